"""The designer in a real browser: Debian's chromium driven by Playwright against `valvetrain serve`.

The browser is the system's (``executable_path``): a downloaded browser build cannot be had here.  Without one the
tests are skipped, except in CI (``CI=true``), where a missing browser fails them.
"""

from pathlib import Path
import re
import subprocess
import sys
import tomllib

import pytest

pytest.importorskip("bokeh")
pytest.importorskip("playwright")

from playwright.sync_api import TimeoutError as PlaywrightTimeout, expect  # noqa: E402

from appendix import PATH as APPENDIX  # noqa: E402


def _served(*files):
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


@pytest.fixture(scope="module")
def url():
    """The designer on the appendix example (whose V' fails at 7000 rpm)."""
    yield from _served(str(APPENDIX))


@pytest.fixture(scope="module")
def diesel_url():
    """The designer on the power-polynomial cam of examples/ukrsurt2019-diesel.toml."""
    yield from _served(str(Path(__file__).parents[2] / "examples" / "ukrsurt2019-diesel.toml"))


@pytest.fixture(scope="module")
def table_url(tmp_path_factory):
    """The designer on the measured-lobe example with every sixth row of its table inline (31 control points)."""
    from measured_lobe import EXAMPLE_TABLE, inline_text
    from valvetrain.files import read_lift_table

    angle, lift = read_lift_table(EXAMPLE_TABLE)
    path = tmp_path_factory.mktemp("table") / "inline.toml"
    path.write_text(inline_text(angle[::6], lift[::6]), encoding="utf-8")
    yield from _served(str(path))


@pytest.fixture
def designer(page, url):
    """A tab on the designer, loaded (the checks drawn), with its console errors and requests recorded."""
    return opened(page, url)


def opened(page, url):
    """``page`` on the designer at ``url``, loaded (the checks drawn), with its console errors and requests
    recorded."""
    page.errors, page.requests = [], []
    page.on("console", lambda m: page.errors.append(m.text) if m.type == "error" else None)
    page.on("pageerror", lambda e: page.errors.append(str(e)))
    page.on("request", lambda r: page.requests.append(r.url))
    page.set_viewport_size({"width": 1700, "height": 1300})
    page.goto(url, wait_until="commit")        # then the page's state, not the load event's 30 s
    page.wait_for_function("() => window.Bokeh && Bokeh.documents.length > 0 && "
                           "Bokeh.documents[0].get_model_by_name('checks').source.get_length() > 0", timeout=WAIT_MS)
    return page


def model_data(page, name):
    """The data of a named Bokeh model's source (the checks table, a handle's points) as the page holds it."""
    return page.evaluate("""name => {
        const m = Bokeh.documents[0].get_model_by_name(name);
        const data = (m.source || m).data;
        const out = {};
        for (const [k, v] of (data instanceof Map ? data.entries() : Object.entries(data))) { out[k] = Array.from(v); }
        return out;
    }""", name)


def check_passes(page, quantity):
    """Whether the check named ``quantity`` (its English text) passes, as the checks table colours it."""
    from valvetrain.web.app import SEVERITY_COLOURS

    data = model_data(page, "checks")
    i = data["key"].index(quantity)
    return data["colour"][i] == SEVERITY_COLOURS["pass"]


WAIT_MS = 60_000
"""How long a test waits for the page to show a change (a design on a loaded machine, the first with the numba
kernels compiled, takes seconds): each wait ends as soon as its condition holds, none is a fixed sleep.  A page is
opened (and reloaded) without waiting for its load event, whose limit is Playwright's 30 s (a reload on a machine
with a load average of 9 took longer): the test waits for the page's state, the Bokeh document with its checks."""


def table_shows_its_source(page):
    """Wait until the checks table's first rendered rows show the first values of its source (a grid that kept the
    old rows after new data came was a bug); False if they do not within :data:`WAIT_MS`."""
    try:
        page.wait_for_function("""() => {
            const m = Bokeh.documents[0].get_model_by_name('checks');
            const data = m.source.data;
            const values = Array.from(data instanceof Map ? data.get('value') : data.value).slice(0, 4);
            const rows = Array.from(Bokeh.index.find_one(m).shadow_el.querySelectorAll('.slick-row')).slice(0, 4);
            return rows.length === values.length && rows.every((r, i) => r.innerText.split('\\n')[1] === values[i]);
        }""", timeout=WAIT_MS)
    except PlaywrightTimeout:
        return False
    return True


def wait_redrawn(page, done):
    page.wait_for_function(f"() => (window.vtTimesDone || 0) > {done}", timeout=WAIT_MS)


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


def redrawn_count(page):
    return page.evaluate("() => window.vtTimesDone || 0")


def drag(page, start, end):
    """Press at ``start`` (page pixels), move 6 px towards ``end`` at once, then to ``end`` in 4 steps, release; wait
    for the redraw.  The first 6 px at once: a pointer that stays within 5 px of where it was pressed for 300 ms is a
    press to Bokeh, not a drag (its UIGestures thresholds), and on a loaded machine small steps take that long."""
    done = redrawn_count(page)
    (x0, y0), (x1, y1) = start, end
    length = max(((x1 - x0) ** 2 + (y1 - y0) ** 2) ** 0.5, 6.0)
    page.mouse.move(x0, y0)
    page.mouse.down()
    page.mouse.move(x0 + 6.0 * (x1 - x0) / length, y0 + 6.0 * (y1 - y0) / length)
    page.mouse.move(x1, y1, steps=4)
    page.mouse.up()
    wait_redrawn(page, done)


def fill(page, key, text):
    """Type into the input whose title starts with ``key`` and commit it (Enter)."""
    box = page.get_by_label(re.compile(rf"^{re.escape(key)}\b"))
    box.fill(text)
    box.press("Enter")


def test_page_loads_without_errors_and_stays_on_this_machine(designer):
    assert designer.errors == []
    outside = [u for u in designer.requests
               if not re.match(r"^(https?|wss?)://127\.0\.0\.1:\d+/", u) and not u.startswith(("data:", "blob:"))]
    assert outside == []


def test_a_style_sheet_set_to_the_text_it_holds_is_left_as_it_is(designer):
    # Bokeh sets each renderer's position in a style sheet of its own at each paint, the same text mostly; the browser
    # took each setting for a change of the styles (a mutation of the sheet's text), and the next look-up of a colour
    # in the styles worked all of them out again: the page keeps a sheet whose text is the same
    mutations = designer.evaluate("""async () => {
        const sheet = new (Bokeh.require("core/dom").InlineStyleSheet)(":host { left: 1px; }");
        let seen = 0;
        new MutationObserver((m) => { seen += m.length; }).observe(
            sheet.el, {childList: true, characterData: true, subtree: true});
        sheet.replace(":host { left: 1px; }");
        await new Promise((resolve) => setTimeout(resolve, 0));
        const same = seen;
        sheet.replace(":host { left: 2px; }");
        await new Promise((resolve) => setTimeout(resolve, 0));
        return [same, seen];
    }""")
    assert mutations == [0, 1]


def test_a_redraw_comes_to_the_page_in_one_message(designer):
    # Bokeh's server sent a message per changed model, four or more frames of the web socket each: the curves (the
    # velocity at the rated speed), the checks and the stamp of a redraw come in one (the stamp is its last change)
    contents = []
    designer.on("websocket", lambda ws: ws.on("framereceived", lambda frame: contents.append(frame)))
    designer.reload(wait_until="commit")       # the page's state, not the load event's 30 s: opened() waits for it
    opened(designer, designer.url)
    ids = designer.evaluate("""() => ['curves', 'checks', 'kinematic-stamp'].map((name) => {
        const m = Bokeh.documents[0].get_model_by_name(name);
        return (m.source || m).id;
    })""")
    done = redrawn_count(designer)
    fill(designer, "rated_speed_rpm", "6000")
    wait_redrawn(designer, done)
    stamped = [c for c in contents if isinstance(c, str) and f'"id":"{ids[-1]}"' in c and '"events"' in c]
    assert stamped and all(f'"id":"{i}"' in stamped[-1] for i in ids)


def test_rated_speed_flips_a_check(designer):
    # V' = c_p (D / d)^2 / i with c_p = S n / 30: at 7000 rpm 18 m/s x (80 / 36.8)^2 = 85.07 m/s > 80 (fails); at
    # 6000 rpm 15.43 m/s x 4.726 = 72.9 m/s, inside 50...80 (Valve-train practical works, work 1)
    quantity = "intake: V' (throat velocity)"
    assert not check_passes(designer, quantity)
    done = redrawn_count(designer)
    fill(designer, "rated_speed_rpm", "6000")
    wait_redrawn(designer, done)
    assert check_passes(designer, quantity)
    assert table_shows_its_source(designer)


def test_drag_of_the_nose_changes_the_lift_and_a_check(designer):
    # V'' = c_p F_p / f_curtain; the curtain at full lift grows with the lift (pi d h cos a + ...): 97.4 m/s at
    # 10 mm is above 95; at 11 mm the curtain is about 10 % larger and V'' falls inside 80...95
    quantity = "intake: V'' (curtain velocity at full lift)"
    assert not check_passes(designer, quantity)
    start = designer.evaluate("""() => {
        const m = Bokeh.documents[0].get_model_by_name('plot-lift');
        const v = Bokeh.index.find_one(m);
        const r = v.canvas_view.el.getBoundingClientRect();
        const px = (x, y) => [r.left + v.frame.x_scale.compute(x), r.top + v.frame.y_scale.compute(y)];
        return [px(0, 10), px(0, 11)];
    }""")
    drag(designer, *start)
    lift = model_data(designer, "handles-lift")
    # the pointer went to 11 mm, above the curve's highest point: the plot leaves room there (an edit tool drops the
    # moves outside the plot's frame; with a range fitted tight to the curve the handle stopped at its first step)
    assert lift["y"][0] == pytest.approx(11.0, abs=0.05)
    assert check_passes(designer, quantity)
    # the panel's input follows the drag (its change comes after the redraw's)
    expect(designer.get_by_label(re.compile(r"^max_lift_mm\b"))).to_have_value(
        re.compile("^" + re.escape(str(lift["y"][0])[:4])), timeout=WAIT_MS)


def test_bad_value_shows_its_message_and_keeps_the_design(designer):
    before = model_data(designer, "checks")
    fill(designer, "bore_mm", "3")
    # the bounds of [engine] bore_mm in the specification's model: 5 ... 2000 mm
    designer.get_by_text("allowed [5, 2000] mm").wait_for(timeout=WAIT_MS)
    assert model_data(designer, "checks") == before


def test_switch_to_russian(designer):
    designer.get_by_label("Language").select_option(label="Русский")
    designer.get_by_text("Скачать TOML").wait_for(timeout=WAIT_MS)
    # the checks come in Russian after the words of the buttons
    wait_checks(designer, "data.quantity.some((q) => q.startsWith('intake: V′ (условная'))")


def test_downloaded_toml_validates(designer, tmp_path):
    with designer.expect_download() as info:
        designer.get_by_text("Download TOML").click()
    path = tmp_path / "designer.toml"
    info.value.save_as(path)
    done = subprocess.run([sys.executable, "-m", "valvetrain", "validate", str(path)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert "valid (1 valve(s): intake)" in done.stdout
    with designer.expect_download() as info:
        designer.get_by_text("Download report").click()
    report = tmp_path / "report.html"
    info.value.save_as(report)
    text = report.read_text(encoding="utf-8")
    assert text.startswith("<!DOCTYPE html>")
    # the figures of `valvetrain run` (--figures main) embedded, among them the cam contour
    assert re.search(r'<img src="data:image/png;base64,[^"]+" alt="cam contour">', text)


def test_drag_of_a_peak_raises_the_acceleration_and_changes_the_checks(page, diesel_url):
    page = opened(page, diesel_url)
    before = model_data(page, "checks")["value"]
    handles = model_data(page, "handles-acceleration")
    i = handles["name"].index("peak")
    x, y = handles["x"][i], handles["y"][i]
    px, py0, py1 = page.evaluate("""([x, y0, y1]) => {
        const v = Bokeh.index.find_one(Bokeh.documents[0].get_model_by_name('plot-acceleration'));
        const r = v.canvas_view.el.getBoundingClientRect();
        return [r.left + v.frame.x_scale.compute(x), r.top + v.frame.y_scale.compute(y0),
                r.top + v.frame.y_scale.compute(y1)];
    }""", [x, y, 1.2 * y])
    drag(page, (px, py0), (px, py1))
    # the valve's peak acceleration is a_qd x i x omega^2 (a flat extremum of the positive part, UkrSURT Proceedings
    # (2019) reconstruction R2): proportional to peak_acceleration_mm_per_rad2 (135.2 in the example), which the
    # drag scales by the new height over the old (the pointer went up to 1.2 times the height, within the room the
    # plot leaves above its highest point, a quarter of its span, and the peak follows it to the pixel)
    after = model_data(page, "handles-acceleration")
    rise = after["y"][after["name"].index("peak")] / y
    assert rise == pytest.approx(1.2, rel=0.01)
    box = page.get_by_label(re.compile(r"^peak_acceleration_mm_per_rad2\b"))
    expect(box).not_to_have_value(re.compile(r"^135\.2$"), timeout=WAIT_MS)   # it follows the drag after the redraw
    a_qd = float(box.input_value())
    assert a_qd / 135.2 == pytest.approx(rise, rel=5e-3)
    assert model_data(page, "checks")["value"] != before


def test_drag_of_an_acceleration_point_moves_the_lift_of_its_table_point(page, table_url):
    page = opened(page, table_url)
    box = page.get_by_label(re.compile(r"^table_lifts_mm\b"))
    text = box.input_value()
    old = tomllib.loads("v = " + text)["v"]
    handles = model_data(page, "handles-acceleration")
    i = handles["name"].index("acceleration.10")
    x, y = handles["x"][i], handles["y"][i]
    px, py0, py1, dropped = page.evaluate("""([x, y0, y1]) => {
        const v = Bokeh.index.find_one(Bokeh.documents[0].get_model_by_name('plot-acceleration'));
        const r = v.canvas_view.el.getBoundingClientRect();
        const py1 = Math.round(v.frame.y_scale.compute(y1));
        return [r.left + v.frame.x_scale.compute(x), r.top + v.frame.y_scale.compute(y0), r.top + py1,
                v.frame.y_scale.invert(py1)];
    }""", [x, y, y + 2000.0])
    drag(page, (px, py0), (px, py1))
    expect(box).not_to_have_value(text, timeout=WAIT_MS)   # the panel follows the drag after the redraw
    new = tomllib.loads("v = " + box.input_value())["v"]
    # the point's lift moves by -(a rise) d^2 / (2 omega^2) (twice the second divided difference is h'', Burden and
    # Faires, Numerical Analysis (2011), section 3.3), d = 12 crank deg = 0.104720 rad, omega = 7000 rpm / 2 =
    # 366.519 rad/s: 4.0817e-5 mm per m/s^2 of the rise from the handle's height to where the pointer left it
    assert new[10] == pytest.approx(old[10] - 4.0817e-5 * (dropped - y), abs=1.5e-3)
    after = model_data(page, "handles-acceleration")
    assert after["y"][after["name"].index("acceleration.10")] > y + 1000.0
