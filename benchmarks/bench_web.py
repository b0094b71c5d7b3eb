"""The designer's speed in the browser (issues 25 and 40), measured by the page itself: the release of a drag
(pointerup) to the painted frame of the redrawn curves (``window.vtTimes``; a tree before the two answers of a
release drew its checks and panel with them), to the painted frame of the redrawn checks, card and panel
(``window.vtChecksTimes``, the design's second answer) and to the painted frame of the redrawn sweep panel
(``window.vtSweepTimes``); while the pointer moves, a move sent to the painted frame
of the curves it brought (``window.vtMoveTimes``).  "Painted" is the end of the frame that shows the update (the page's
probe, ``valvetrain.web.draw.STAMP_JS``: the first frame after the update arrived in which the plots it changed were
painted, its main thread's work done); the script also times, in every tree's page alike, the second animation frame
after the curves' stamp came (the probe of the trees before 2026-12-02, a frame later than the one that shows it).

Run on demand: ``python benchmarks/bench_web.py [drags]`` (default 20) with `valvetrain serve` started by the script
on a free port of 127.0.0.1 and Debian's chromium (headless) driven by Playwright in a 1400 x 900 window, both on this
machine.  Each drag takes the nose handle of the built-in example's intake by about 1 mm (towards 9.5 mm, where the
spring passes) in 8 moves, the curves following, and releases it; then it waits for the redraw of the release and
for the sweep panel.  Printed: the medians (and the largest) beside the issue's targets (<= 100 ms, <= 500 ms), the
split of the wait after the release (the way up, the server's callback, the way down, the page's drawing), the
server's design without and with the sweeps in this process, and the load average before and after (a loaded
machine's figures mean little: measure it idle).

``--baseline SRC`` serves the package from another tree too (e.g. ``/work/main/src``, the tree before a change) and
drags its page and this tree's in turn, so that both are measured in the same minutes (a page without the live
drag, issue 25's, is dragged as it was: one release, its probe from Bokeh's pan end).  Then each tree's page is
dragged 3 more times with chromium's timeline recording the release: the processor time of the page's main thread
from the release to the curves painted, the page's own work whatever the load (on a loaded machine the wall times
are mostly the wait for a core).
"""

from functools import partial
import argparse
import json
import os
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
from valvetrain.web.session import Session

BROWSER_ARGS = ["--no-sandbox", "--disable-gpu", "--disable-background-networking", "--disable-component-update",
                "--disable-sync", "--no-first-run"]

PIXELS = """() => {
    const m = Bokeh.documents[0].get_model_by_name('plot-lift');
    const v = Bokeh.index.find_one(m);
    const r = v.canvas_view.el.getBoundingClientRect();
    const src = Bokeh.documents[0].get_model_by_name('handles-lift').data;
    const y = Array.from(src instanceof Map ? src.get('y') : src.y)[0];
    return [r.left + v.frame.x_scale.compute(0), r.top + v.frame.y_scale.compute(y), y,
            Math.abs(v.frame.y_scale.compute(1) - v.frame.y_scale.compute(0))];
}"""

COUNTS = "() => [(window.vtTimes || []).length, (window.vtSweepTimes || []).length]"

TWO_FRAMES = """() => {
    const stamp = Bokeh.documents[0].get_model_by_name('kinematic-stamp');
    window.benchTwoFrames = [];
    stamp.connect(stamp.properties.data.change, () => {
        const data = stamp.data instanceof Map ? Object.fromEntries(stamp.data) : stamp.data;
        if (window.vt && window.vtRelease !== undefined && data.seq[0] === window.vt.release) {
            const release = window.vtRelease;
            requestAnimationFrame(() => requestAnimationFrame(() => {
                window.benchTwoFrames.push(performance.now() - release);
            }));
        }
    });
}"""
"""The same measure in every tree's page: the release to the second animation frame after the curves' stamp came."""

TRACED = 3
"""Drags per tree traced after the timed ones (chromium's timeline): the page's processor time of a release."""


def renderer_cpu(trace, wall):
    """The processor time [ms] of the page's main thread (its tasks' thread time in chromium's timeline ``trace``,
    JSON bytes) from the pointerup to ``wall`` ms after it (the painted curves): what the page's drawing of a
    release costs, loaded or not (its wall time on a loaded machine is mostly the wait for a core)."""
    events = json.loads(trace)["traceEvents"]
    names = {(e["pid"], e["tid"]): e["args"]["name"] for e in events
             if e.get("ph") == "M" and e.get("name") == "thread_name"}
    main = next(k for k, v in names.items() if v == "CrRendererMain")
    start = next(e["ts"] for e in events if e.get("name") == "EventDispatch"
                 and e.get("args", {}).get("data", {}).get("type") == "pointerup" and (e["pid"], e["tid"]) == main)
    return sum(e.get("tdur", 0) for e in events if e.get("ph") == "X" and (e["pid"], e["tid"]) == main
               and e["name"] == "ThreadControllerImpl::RunTask" and start <= e["ts"] <= start + 1e3 * wall) / 1e3


def server_share(repeats=10):
    """The server's part of each redraw [ms, median]: the kinematics of the valve dragged alone (the first answer
    to a release and the answer to a move), the design without the speed sweeps (the kinematics and the checks) of
    a drag of the nose (the lift 9.5 or 9.6 mm in turn, the exhaust kept in the memo as the session keeps
    it) and the whole design with them (the sweep panel and the checks of the dynamics)."""
    documents = [set_keys(tomllib.loads(example_text()), {"valves.intake.max_lift_mm": lift}) for lift in (9.5, 9.6)]
    Session.settle(documents[0])
    out = []
    for call in (partial(api.kinematics, name="intake"), partial(api.design, dynamics=False, diagnose=False,
                                                                  memo={}), Session.settle):
        times = []
        for i in range(repeats):
            t = time.perf_counter()
            call(documents[i % 2])
            times.append(1e3 * (time.perf_counter() - t))
        out.append(statistics.median(times))
    return out


def served(src=None):
    """`valvetrain serve` on a free port of 127.0.0.1 (from the tree ``src`` when given, e.g. main's checkout, to
    measure a baseline beside this tree in the same minutes), its process and address."""
    env = dict(os.environ, **({"PYTHONPATH": str(src)} if src else {}))
    proc = subprocess.Popen([sys.executable, "-u", "-m", "valvetrain", "serve", "--port", "0", "--no-show"],
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True, env=env)
    return proc, re.search(r"http://127\.0\.0\.1:\d+/", proc.stdout.readline())[0]


def opened(browser, url):
    """A tab on the designer at ``url`` in a 1400 x 900 window, loaded, the checks and the first sweep drawn."""
    page = browser.new_page(viewport={"width": 1400, "height": 900})
    page.goto(url)
    page.wait_for_function("() => window.Bokeh && Bokeh.documents.length > 0 && Bokeh.documents[0]"
                           ".get_model_by_name('checks').source.get_length() > 0", timeout=120_000)
    live = page.evaluate("() => window.vt !== undefined")
    if live:
        page.wait_for_function("() => (window.vtSweepTimesDone || 0) > 0", timeout=120_000)
    page.evaluate(TWO_FRAMES)
    return page, live


def drag(page, live, number, browser=None):
    """Drag the nose handle by about 1 mm towards 9.5 mm and wait for the redraw of the release and the sweep panel;
    with the ``browser``, the release traced (after the moves' redraws) and the page's processor time of it
    returned (:func:`renderer_cpu`)."""
    x, y, lift, per_mm = page.evaluate(PIXELS)
    done = page.evaluate(COUNTS)
    step = (1 if lift < 9.5 else -1) * per_mm
    page.mouse.move(x, y)
    page.mouse.down()
    if not live:                              # issue 25's page: 300 ms within 5 px was a press to Bokeh
        page.mouse.move(x, y - 6.0 * (1 if step > 0 else -1))
    page.mouse.move(x, y - step, steps=8 if live else 4)
    if browser is not None:
        page.wait_for_timeout(500)
        browser.start_tracing(page=page, categories=["devtools.timeline", "toplevel"])
    page.mouse.up()
    if browser is not None:
        page.wait_for_function(f"() => (window.vtTimes || []).length > {done[0]}", timeout=60_000)
        cpu = renderer_cpu(browser.stop_tracing(), page.evaluate("() => window.vtTimes.at(-1)"))
    try:
        page.wait_for_function(f"() => (window.vtTimes || []).length > {done[0]} && "
                               f"(window.vtSweepTimes || []).length > {done[1]}", timeout=60_000)
    except PlaywrightTimeout:
        sys.exit(f"no redraw within 60 s of drag {number}: (releases, sweeps) redrawn {done} before, "
                 f"{page.evaluate(COUNTS)} after; the nose at {lift:.3f} mm, {per_mm:.1f} px/mm")
    return cpu if browser is not None else None


def median(values, unit="ms"):
    return f"median {statistics.median(values):.0f} {unit} (max {max(values):.0f})" if values else "none"


def summary(name, times):
    """The medians of one tree's redraws: release -> redrawn, the arrival, the split, the sweep panel, the moves."""
    kinematic, sweep, arrived, server, moves, checks, two_frames = times
    up, callback, down, *processor = (statistics.median(s) for s in zip(*server))
    drawing = statistics.median(k - a for k, a in zip(kinematic, arrived))
    return (f"{name}:\n"
            f"  release -> curves painted: {median(kinematic)} (target <= 100 ms); the update "
            f"arrived after {statistics.median(arrived):.0f}; way up / server's callback / way down / drawing: "
            f"{up:.0f} / {callback:.0f} / {down:.0f} / {drawing:.0f} ms; the server's processor time "
            f"{' '.join(f'{v:.0f} ms' for v in processor) or 'not sent'}\n"
            f"  release -> the second animation frame after the curves came (every tree alike): {median(two_frames)}\n"
            f"  release -> checks, card and panel painted: "
            f"{median(checks) if checks else 'with the curves (one answer)'}\n"
            f"  release -> sweep panel painted: {median(sweep)} (target <= 500 ms)\n"
            f"  while the pointer moves, a move -> its curves painted: {median(moves or [])} "
            f"({len(moves or [])} moves drawn)")


def main(drags=20, baseline=None):
    load_before = os.getloadavg()
    trees = {"this tree": None, **({f"baseline {baseline}": baseline} if baseline else {})}
    servers = {name: served(src) for name, src in trees.items()}
    try:
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=shutil.which("chromium"), args=BROWSER_ARGS)
            pages = {name: opened(browser, url) for name, (_, url) in servers.items()}
            for number in range(drags):
                for page, live in pages.values():          # alternating: each tree's drags in the same minutes
                    drag(page, live, number + 1)
            times = {name: page.evaluate("() => [window.vtTimes, window.vtSweepTimes, window.vtTimesArrived, "
                                         "window.vtTimesServer, window.vtMoveTimes, window.vtChecksTimes, "
                                         "window.benchTwoFrames]")
                     for name, (page, _) in pages.items()}
            cpu = {name: [drag(page, live, drags + k + 1, browser) for k in range(TRACED)]
                   for name, (page, live) in pages.items()}
            browser.close()
    finally:
        for proc, _ in servers.values():
            proc.terminate()
            proc.wait(timeout=20)
    kinematics_ms, design_ms, sweep_ms = server_share()
    print(f"drags: {drags} per tree, in a 1400 x 900 window")
    for name, t in times.items():
        print(summary(name, t))
        print(f"  the page's processor time from the release to the curves painted (main thread, {TRACED} traced "
              f"drags): {median(cpu[name])}")
    print(f"in this process: the valve's kinematics {kinematics_ms:.0f} ms, the design without the sweeps {design_ms:.0f} ms, the whole design with the sweeps "
          f"{sweep_ms:.0f} ms")
    print("load average (1, 5, 15 min) before: " + ", ".join(f"{v:.1f}" for v in load_before)
          + "; after: " + ", ".join(f"{v:.1f}" for v in os.getloadavg()) + f" ({os.cpu_count()} cores)")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("drags", nargs="?", type=int, default=20, help="drags of the nose handle (default 20)")
    parser.add_argument("--baseline", metavar="SRC", help="also serve the package from the tree SRC (e.g. "
                        "/work/main/src) and drag its page and this tree's in turn: both measured in the same minutes")
    args = parser.parse_args()
    main(args.drags, args.baseline)
