"""The designer's speed in the browser (issue 25): release of a drag -> redrawn kinematic plots and checks, and ->
redrawn sweep panel, measured by the page itself (``window.vtTimes``, ``window.vtSweepTimes``: performance.now()
at the plot's pan end to the second animation frame after the update arrived).

Run on demand: ``python benchmarks/bench_web.py [drags]`` (default 20) with `valvetrain serve` started by the script
on a free port of 127.0.0.1 and Debian's chromium (headless) driven by Playwright, both on this machine.  Each
drag moves the nose handle of the built-in example by about 1 mm towards 9.5 mm (below the 10 mm of the example,
where the spring passes, as in the figures measured before) and waits for both redraws.  Printed beside
each median: the target of the issue, the split of the wait (the way up, the server's callback, the way down, the
page's drawing), the server's share measured in the same run (``valvetrain.api.design`` without the speed sweeps, and
the whole design with them, of the same specification in this process), the server's design of a drag of an inline
lift table's point beside the same with the springs' diagnosis, and the load average.

``--baseline SRC`` serves the package from another tree too (e.g. ``/work/main/src``, the tree before a change) and
drags its page and this tree's in turn, so that both are measured in the same minutes of a loaded machine.
"""

from functools import partial
import os
import argparse
import json
from pathlib import Path
import re
import shutil
import statistics
import subprocess
import sys
import time
import tomllib

from playwright.sync_api import TimeoutError as PlaywrightTimeout, sync_playwright

from valvetrain import api
from valvetrain.specification import example_text, set_keys
from valvetrain.web.session import Session, without_nones

PIXELS = """() => {
    const m = Bokeh.documents[0].get_model_by_name('plot-lift');
    const v = Bokeh.index.find_one(m);
    const r = v.canvas_view.el.getBoundingClientRect();
    const src = Bokeh.documents[0].get_model_by_name('handles-lift').data;
    const y = Array.from(src instanceof Map ? src.get('y') : src.y)[0];
    return [r.left + v.frame.x_scale.compute(0), r.top + v.frame.y_scale.compute(y), y,
            Math.abs(v.frame.y_scale.compute(1) - v.frame.y_scale.compute(0))];
}"""


def server_share(repeats=10):
    """The server's part of each redraw [ms, median]: the design without the speed sweeps (the kinematics and the
    checks) of a drag of the nose (the lift 9.5 or 9.6 mm in turn, the exhaust kept in the memo as the session keeps
    it) and the whole design with them (the sweep panel and the checks of the dynamics)."""
    documents = [set_keys(tomllib.loads(example_text()), {"valves.intake.max_lift_mm": lift}) for lift in (9.5, 9.6)]
    Session.settle(documents[0])
    out = []
    for call in (partial(api.design, dynamics=False, diagnose=False, memo={}), Session.settle):
        times = []
        for i in range(repeats):
            t = time.perf_counter()
            call(documents[i % 2])
            times.append(1e3 * (time.perf_counter() - t))
        out.append(statistics.median(times))
    return out


def table_share(repeats=5):
    """The server's design of a drag of an inline lift table's point [ms, median]: the measured-lobe example with
    every sixth row inline and its highest point raised to 10.5 mm (no spring passes), designed as the designer's
    first answer does it (without the sweeps and the springs' diagnosis) and, the baseline, with the diagnosis."""
    sys.path.insert(0, str(Path(__file__).parents[1] / "tests"))
    from measured_lobe import EXAMPLE, EXAMPLE_TABLE, inline_text
    from valvetrain.files import read_lift_table

    angle, lift = read_lift_table(EXAMPLE_TABLE)
    s = Session.start(inline_text(angle[::6], lift[::6]), EXAMPLE.parent)
    s.drag("intake", "point.16", s.handles("intake")[16].x, 10.5)
    document = without_nones(s.good_document)
    out = []
    for diagnose in (False, True):
        times = []
        for _ in range(repeats):
            t = time.perf_counter()
            api.design(document, dynamics=False, diagnose=diagnose)
            times.append(1e3 * (time.perf_counter() - t))
        out.append(statistics.median(times))
    return out


def served(src=None):
    """`valvetrain serve` on a free port of 127.0.0.1 (from the tree ``src`` when given, e.g. main's checkout, to
    measure a baseline beside this tree in the same minutes), its process and address."""
    env = dict(os.environ, **({"PYTHONPATH": str(src)} if src else {}))
    proc = subprocess.Popen([sys.executable, "-u", "-m", "valvetrain", "serve", "--port", "0", "--no-show"],
                            stdout=subprocess.PIPE, text=True, env=env)
    return proc, re.search(r"http://127\.0\.0\.1:\d+/", proc.stdout.readline())[0]


def opened(browser, url):
    """A tab on the designer at ``url``, loaded, the checks drawn."""
    page = browser.new_page(viewport={"width": 1700, "height": 1300})
    page.goto(url)
    page.wait_for_function("() => window.Bokeh && Bokeh.documents.length > 0 && Bokeh.documents[0]"
                           ".get_model_by_name('checks').source.get_length() > 0", timeout=60_000)
    return page


def drag(page, number):
    """Drag the nose handle by about 1 mm towards 9.5 mm and wait for both redraws."""
    x, y, lift, per_mm = page.evaluate(PIXELS)
    done = page.evaluate("() => [window.vtTimesDone || 0, window.vtSweepTimesDone || 0]")
    step = (1 if lift < 9.5 else -1) * per_mm
    page.mouse.move(x, y)
    page.mouse.down()
    page.mouse.move(x, y - 6.0 * (1 if step > 0 else -1))   # at once: 300 ms within 5 px is a press
    page.mouse.move(x, y - step, steps=4)
    page.mouse.up()
    try:
        page.wait_for_function(f"() => (window.vtTimesDone || 0) > {done[0]} && "
                               f"(window.vtSweepTimesDone || 0) > {done[1]}", timeout=60_000)
    except PlaywrightTimeout:
        now = page.evaluate("() => [window.vtTimesDone || 0, window.vtSweepTimesDone || 0]")
        sys.exit(f"no redraw within 60 s of drag {number}: redraws (kinematics, sweep) {done} before, "
                 f"{now} after; the nose at {lift:.3f} mm, {per_mm:.1f} px/mm")


def page_cpu(path, counts):
    """The processor time of each page's main thread from each release of a drag to its redrawn kinematics [ms], from
    a Chrome trace at ``path`` of the drags: the thread time of the main thread's tasks that began in the window (a
    figure that the other processes of a loaded machine leave as it is, unlike the wall times).  ``counts``: per
    page, in the order of their first drags, the release -> redraw times (``window.vtTimes``) of the traced drags."""
    events = json.loads(Path(path).read_text())
    events = events["traceEvents"] if isinstance(events, dict) else events
    main = {(e["pid"], e["tid"]) for e in events if e.get("name") == "thread_name"
            and e.get("args", {}).get("name") == "CrRendererMain"}
    ups = {}
    for e in events:
        if ((e.get("pid"), e.get("tid")) in main and e.get("name") == "EventDispatch"
                and e.get("args", {}).get("data", {}).get("type") == "pointerup"):
            ups.setdefault((e["pid"], e["tid"]), []).append(e["ts"])
    out = []
    for thread, times in zip(sorted(ups, key=lambda k: min(ups[k])), counts):
        tasks = [e for e in events if (e.get("pid"), e.get("tid")) == thread and e.get("name") == "RunTask"
                 and "tdur" in e]
        out.append([sum(e["tdur"] for e in tasks if up <= e["ts"] <= up + 1e3 * t) / 1e3
                    for up, t in zip(sorted(ups[thread]), times, strict=True)])
    return out


def summary(name, times, cpu=None):
    """The medians of one tree's redraws: release -> kinematics, the arrival, the way up, the server, the way down,
    the page's drawing, the sweep panel; the processor times of the server's callback and (``cpu``) of the page."""
    kinematic, sweep, arrived, server = times
    up, callback, down, *processor = (statistics.median(s) for s in zip(*server))   # a tree before it: 3 parts
    return (f"{name}: release -> kinematic plots and checks redrawn: median {statistics.median(kinematic):.0f} ms "
            f"(max {max(kinematic):.0f}); the update arrived after {statistics.median(arrived):.0f}; "
            f"way up / server's callback / way down / drawing: {up:.0f} / {callback:.0f} / {down:.0f} / "
            f"{statistics.median(k - a for k, a in zip(kinematic, arrived)):.0f} ms; "
            f"sweep panel redrawn: median {statistics.median(sweep):.0f} ms (max {max(sweep):.0f}); "
            f"processor time: the server's callback {' '.join(f'{v:.0f} ms' for v in processor) or 'not sent'}"
            + ("" if cpu is None else f", the page from release to redraw {statistics.median(cpu):.0f} ms"))


def main(drags=20, baseline=None, trace=None):
    trees = {"this tree": None, **({f"baseline {baseline}": baseline} if baseline else {})}
    servers = {name: served(src) for name, src in trees.items()}
    try:
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=shutil.which("chromium"), args=["--no-sandbox"])
            pages = {name: opened(browser, url) for name, (_, url) in servers.items()}
            pages[next(iter(pages))].wait_for_timeout(3000)
            if trace:
                browser.start_tracing(path=trace, categories=["devtools.timeline", "disabled-by-default-devtools.timeline"])
            for number in range(drags):
                for page in pages.values():          # alternating: each tree's drags in the same minutes
                    drag(page, number + 1)
            if trace:
                browser.stop_tracing()
            times = {name: page.evaluate("() => [window.vtTimes, window.vtSweepTimes, window.vtTimesArrived, "
                                         "window.vtTimesServer]") for name, page in pages.items()}
            browser.close()
    finally:
        for proc, _ in servers.values():
            proc.terminate()
            proc.wait(timeout=20)
    design_ms, sweep_ms = server_share()
    table_ms, diagnosed_ms = table_share()
    print(f"drags: {drags} per tree; target <= 150 ms (kinematics), <= 1000 ms (sweep panel)")
    cpu = page_cpu(trace, [t[0] for t in times.values()]) if trace else [None] * len(times)
    for (name, t), c in zip(times.items(), cpu, strict=True):
        print(summary(name, t, c))
    print(f"in this process: the design without the sweeps {design_ms:.0f} ms, the whole design with the sweeps "
          f"{sweep_ms:.0f} ms")
    print(f"a drag of an inline table's point, the server's design (a spring failing): {table_ms:.0f} ms as the designer "
          f"answers first, {diagnosed_ms:.0f} ms with the springs' diagnosis")
    print("load average (1, 5, 15 min): " + ", ".join(f"{v:.1f}" for v in os.getloadavg()))


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("drags", nargs="?", type=int, default=20, help="drags of the nose handle (default 20)")
    parser.add_argument("--baseline", metavar="SRC", help="also serve the package from the tree SRC (e.g. "
                        "/work/main/src) and drag its page and this tree's in turn: both measured in the same minutes")
    parser.add_argument("--trace", metavar="FILE", help="record a Chrome trace of the drags to FILE and print the "
                        "processor time of the page from release to redraw")
    args = parser.parse_args()
    main(args.drags, args.baseline, args.trace)
