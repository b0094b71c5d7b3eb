"""The designer's speed in the browser (issue 25): release of a drag -> redrawn kinematic plots and checks, and ->
redrawn sweep panel, measured by the page itself (``window.vtTimes``, ``window.vtSweepTimes``: performance.now()
at the plot's pan end to the second animation frame after the update arrived).

Run on demand: ``python benchmarks/bench_web.py [drags]`` (default 20) with `valvetrain serve` started by the script
on a free port of 127.0.0.1 and Debian's chromium (headless) driven by Playwright, both on this machine.  Each
drag moves the nose handle of the built-in example by about 1 mm towards 9.5 mm (below the 10 mm of the example,
where the spring passes, as in the figures measured before) and waits for both redraws.  Printed beside
each median: the target of the issue, the server's share measured in the same run (``valvetrain.api.design`` without
the speed sweeps, and the whole design with them, of the same specification in this process), the server's design
of a drag of an inline lift table's point beside the same with the springs' diagnosis, and the load average.
"""

from functools import partial
import os
import argparse
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
from valvetrain.specification import example_text
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
    checks) and the whole design with them (the sweep panel and the checks of the dynamics)."""
    document = tomllib.loads(example_text())
    Session.settle(document)
    out = []
    for call in (partial(api.design, dynamics=False, diagnose=False), Session.settle):
        times = []
        for _ in range(repeats):
            t = time.perf_counter()
            call(document)
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


def summary(name, times):
    """The medians of one tree's redraws: release -> kinematics, the arrival, the way up, the server, the way down,
    the page's drawing, the sweep panel."""
    kinematic, sweep, arrived, server = times
    up, callback, down = (statistics.median(s) for s in zip(*server))
    return (f"{name}: release -> kinematic plots and checks redrawn: median {statistics.median(kinematic):.0f} ms "
            f"(max {max(kinematic):.0f}); the update arrived after {statistics.median(arrived):.0f}; "
            f"way up / server's callback / way down / drawing: {up:.0f} / {callback:.0f} / {down:.0f} / "
            f"{statistics.median(k - a for k, a in zip(kinematic, arrived)):.0f} ms; "
            f"sweep panel redrawn: median {statistics.median(sweep):.0f} ms (max {max(sweep):.0f})")


def main(drags=20, baseline=None):
    trees = {"this tree": None, **({f"baseline {baseline}": baseline} if baseline else {})}
    servers = {name: served(src) for name, src in trees.items()}
    try:
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=shutil.which("chromium"), args=["--no-sandbox"])
            pages = {name: opened(browser, url) for name, (_, url) in servers.items()}
            pages[next(iter(pages))].wait_for_timeout(3000)
            for number in range(drags):
                for page in pages.values():          # alternating: each tree's drags in the same minutes
                    drag(page, number + 1)
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
    for name, t in times.items():
        print(summary(name, t))
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
    args = parser.parse_args()
    main(args.drags, args.baseline)
