"""The designer's page in Debian's chromium driven by Playwright, for the browser tests of web/: its servers
(``valvetrain serve`` in a process of its own, or :func:`valvetrain.web.server` in this one), a tab opened on one and
the page's state read and waited for (every wait is on the page's state, none a fixed sleep)."""

import asyncio
import re
import subprocess
import sys
import threading

import pytest

pytest.importorskip("bokeh")
pytest.importorskip("playwright")       # the test files importing this module skipped without them

from playwright.sync_api import expect  # noqa: E402,F401  (the tests' assertions on the page)


def served(*files):
    """`valvetrain serve [FILE]` on a free port of 127.0.0.1, its page's address."""
    proc = subprocess.Popen([sys.executable, "-u", "-m", "valvetrain", "serve", *files, "--port", "0", "--no-show"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    line = proc.stdout.readline()
    found = re.search(r"http://127\.0\.0\.1:\d+/", line)
    try:
        assert found, line + proc.stderr.read() if proc.poll() is not None else line
        yield found[0]
    finally:
        proc.terminate()
        proc.wait(timeout=20)


WAIT_MS = 60_000
"""How long a test waits for the page to show a change (a design on a loaded machine, the first with the numba
kernels compiled, takes seconds): each wait ends as soon as its condition holds, none is a fixed sleep.  A page is
opened (and reloaded) without waiting for its load event, whose limit is Playwright's 30 s (a reload on a machine
with a load average of 9 took longer): the test waits for the page's state, loaded (a drag at once after the first
bytes came pressed beside a handle laid out later) and the Bokeh document with its checks."""

VIEWPORT = {"width": 1400, "height": 900}
"""The window the designer is made for (issue 40)."""


class Servers:
    """Servers of the designer in this process, each :func:`valvetrain.web.server` on a specification as ``valvetrain
    serve FILE`` makes it, on one event loop in a thread of its own: a server costs its specification's design, not a
    Python process importing the package (10-30 s each in a loaded CI).  The tests of ``valvetrain serve`` itself
    start it (:func:`served`)."""

    def __init__(self):
        self.loop = asyncio.new_event_loop()
        self.thread = threading.Thread(target=self.loop.run_forever, name="designer-servers", daemon=True)
        self.thread.start()
        self.servers = []

    def url(self, path=None):
        """The page's address of a new server of the specification at ``path`` (the built-in example without it)."""
        from valvetrain.web import server

        async def start():
            text, folder = (None, None) if path is None else (path.read_text(encoding="utf-8"), path.resolve().parent)
            app = server(text, folder, port=0)
            app.start()
            self.servers.append(app)
            return f"http://127.0.0.1:{app.port}/"

        return asyncio.run_coroutine_threadsafe(start(), self.loop).result(timeout=WAIT_MS / 1000)

    def close(self):
        async def stop():
            for app in self.servers:
                app.stop()

        asyncio.run_coroutine_threadsafe(stop(), self.loop).result(timeout=WAIT_MS / 1000)
        self.loop.call_soon_threadsafe(self.loop.stop)
        self.thread.join(timeout=WAIT_MS / 1000)


def opened(page, url):
    """``page`` on the designer at ``url`` in a 1400 x 900 window, loaded (the checks drawn, the page's script
    running), with its console errors and requests recorded."""
    page.errors, page.requests = [], []
    page.on("console", lambda m: page.errors.append(m.text) if m.type == "error" else None)
    page.on("pageerror", lambda e: page.errors.append(str(e)))
    page.on("request", lambda r: page.requests.append(r.url))
    page.set_viewport_size(VIEWPORT)
    page.goto(url, wait_until="commit")        # then the page's state, not the load event's 30 s
    page.wait_for_function("() => document.readyState === 'complete' && window.Bokeh && Bokeh.documents.length > 0"
                           " && window.vt !== undefined"
                           " && Bokeh.documents[0].get_model_by_name('checks').source.get_length() > 0", timeout=WAIT_MS)
    return page


def answered(page, url):
    """``page`` opened on ``url`` (:func:`opened`) after checking that the server answered it (HTTP 200: a page that
    fails to build answers 500) and that the page logged no error."""
    assert page.goto(url, wait_until="commit").status == 200
    opened(page, url)
    assert page.errors == []
    return page


def plot_range(page, plot, axis):
    """``[start, end]`` of the ``axis`` ("x", "y") range of plot ``plot`` as the page holds it."""
    return page.evaluate(f"() => {{ const r = Bokeh.documents[0].get_model_by_name('plot-{plot}').{axis}_range;"
                         " return [r.start, r.end]; }")


def model_data(page, name):
    """The data of a named Bokeh model's source (the checks table, a handle's points) as the page holds it."""
    return page.evaluate("""name => {
        const m = Bokeh.documents[0].get_model_by_name(name);
        const data = (m.source || m).data;
        const out = {};
        for (const [k, v] of (data instanceof Map ? data.entries() : Object.entries(data))) { out[k] = Array.from(v); }
        return out;
    }""", name)


def value(page, path):
    """The value of the panel's input of a dotted key as the page holds it."""
    return page.evaluate("path => Bokeh.documents[0].get_model_by_name(path).value", path)


def pixels(page, plot, x, y):
    """Page pixels of the point (x, y) of a plot."""
    return page.evaluate("""([plot, x, y]) => {
        const v = Bokeh.index.find_one(Bokeh.documents[0].get_model_by_name('plot-' + plot));
        const r = v.canvas_view.el.getBoundingClientRect();
        return [r.left + v.frame.x_scale.compute(x), r.top + v.frame.y_scale.compute(y)];
    }""", [plot, x, y])


def at_pixels(page, plot, px, py):
    """The point (x, y) of a plot at page pixels."""
    return page.evaluate("""([plot, px, py]) => {
        const v = Bokeh.index.find_one(Bokeh.documents[0].get_model_by_name('plot-' + plot));
        const r = v.canvas_view.el.getBoundingClientRect();
        return [v.frame.x_scale.invert(px - r.left), v.frame.y_scale.invert(py - r.top)];
    }""", [plot, px, py])


def redrawn_count(page):
    return page.evaluate("() => window.vtTimesDone || 0")


def wait_redrawn(page, done):
    """Wait for the redraw that answers the last release (a drag, a key, an undo): the page's probe counts it."""
    page.wait_for_function(f"() => (window.vtTimesDone || 0) > {done} && window.vtTimes && "
                           "window.vtTimes.length > 0 && window.vt.inflight === 0", timeout=WAIT_MS)
    # a drag's curves come first (counted above), its checks and panel after them
    page.wait_for_function("() => { const s = Bokeh.documents[0].get_model_by_name('checks-stamp').data;"
                           " const seq = (s instanceof Map ? s.get('seq') : s.seq)[0];"
                           " return seq >= window.vt.release; }", timeout=WAIT_MS)


def drag(page, plot, start, end, steps=4, wait=True):
    """Press on the handle at ``start`` (a point of ``plot``), move to ``end`` in ``steps``, release; wait for the
    redraw of the release."""
    done = redrawn_count(page)
    (x0, y0), (x1, y1) = pixels(page, plot, *start), pixels(page, plot, *end)
    page.mouse.move(x0, y0)
    page.mouse.down()
    page.mouse.move(x1, y1, steps=steps)
    page.mouse.up()
    if wait:
        wait_redrawn(page, done)


def fill(page, label, text):
    """Type into the panel's input whose name starts with ``label`` and commit it (Enter)."""
    box = page.get_by_label(re.compile(rf"^{re.escape(label)}"))
    box.fill(text)
    box.press("Enter")


def choose(page, option):
    """Choose ``option`` in the select of the command bar that offers it."""
    page.locator("select").filter(has=page.locator("option", has_text=re.compile(f"^{re.escape(option)}$"))).first \
        .select_option(label=option)


def wait_checks(page, predicate):
    """Wait until the checks table's data (as :func:`model_data` gives it) satisfy a JavaScript ``predicate`` of
    them: the page may show other changes of the same update first."""
    page.wait_for_function("""predicate => {
        const m = Bokeh.documents[0].get_model_by_name('checks');
        const data = m.source.data;
        const out = {};
        for (const [k, v] of (data instanceof Map ? data.entries() : Object.entries(data))) { out[k] = Array.from(v); }
        return new Function('data', 'return ' + predicate)(out);
    }""", arg=predicate, timeout=WAIT_MS)
