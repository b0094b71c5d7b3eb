"""The designer in a real browser on the shipped examples and on specifications written for the tests: Debian's
chromium driven by Playwright against servers of the designer in this process (:class:`browser_page.Servers`, as
``valvetrain serve FILE`` makes them; tests/web/test_web_browser.py drives ``valvetrain serve`` itself on the built-in
example).  Every test opens a tab of its own (a session of its own) on a server of its specification; every wait is
on the page's state.  Without a browser the tests are skipped, except in CI (``CI=true``), where a missing browser
fails them.
"""

from pathlib import Path
import re
import tomllib

import pytest

from appendix import PATH as APPENDIX
from browser_page import (WAIT_MS, Servers, answered, at_pixels, drag, expect, fill, model_data, opened, pixels,
                          plot_range, redrawn_count, value, wait_checks, wait_redrawn)

EXAMPLES = Path(__file__).parents[2] / "examples"


@pytest.fixture(scope="module")
def servers():
    """The servers of this file's specifications, in this process."""
    here = Servers()
    yield here
    here.close()


@pytest.fixture(scope="module")
def appendix_url(servers):
    """The designer on the appendix example (whose V' fails at 7000 rpm)."""
    return servers.url(APPENDIX)


@pytest.fixture(scope="module")
def diesel_url(servers):
    """The designer on the power-polynomial cam of examples/ukrsurt2019-diesel.toml."""
    return servers.url(EXAMPLES / "ukrsurt2019-diesel.toml")


@pytest.fixture(scope="module")
def table_url(servers, tmp_path_factory):
    """The designer on the measured-lobe example with every sixth row of its table inline (31 control points)."""
    from measured_lobe import EXAMPLE_TABLE, inline_text
    from valvetrain.files import read_lift_table

    angle, lift = read_lift_table(EXAMPLE_TABLE)
    path = tmp_path_factory.mktemp("table") / "inline.toml"
    path.write_text(inline_text(angle[::6], lift[::6]), encoding="utf-8")
    return servers.url(path)


@pytest.fixture(scope="module")
def breathing_url(servers, tmp_path_factory):
    """The designer on the built-in example with a [breathing] section through its designed valves."""
    from breathing_example import breathing_text

    path = tmp_path_factory.mktemp("breathing") / "breathing.toml"
    path.write_text(breathing_text(), encoding="utf-8")
    return servers.url(path)


def test_rated_speed_flips_a_check(page, appendix_url):
    # V' = c_p (D / d)^2 / i with c_p = S n / 30: at 7000 rpm 18 m/s x (80 / 36.8)^2 = 85.07 m/s > 80 (fails); at
    # 6000 rpm 15.43 m/s x 4.726 = 72.9 m/s, inside 50...80 (Valve-train practical works, work 1)
    page = opened(page, appendix_url)
    quantity = "intake: V' (throat velocity)"
    wait_checks(page, f"data.status[data.key.indexOf({quantity!r})] !== 'passes'")
    fill(page, "rated speed n, rpm", "6000")
    wait_checks(page, f"data.status[data.key.indexOf({quantity!r})] === 'passes'")
    # the grid's rows show their source's values (a grid that kept the old rows after new data came was a bug)
    page.wait_for_function("""() => {
        const m = Bokeh.documents[0].get_model_by_name('checks');
        const data = m.source.data;
        const values = Array.from(data instanceof Map ? data.get('value') : data.value).slice(0, 4);
        const rows = Array.from(Bokeh.index.find_one(m).shadow_el.querySelectorAll('.slick-row')).slice(0, 4);
        return rows.length === values.length && rows.every((r, i) => r.innerText.split('\\n')[2] === values[i]);
    }""", timeout=WAIT_MS)


def test_the_measured_lobe_example_opens(page, servers):
    # issue 40: examples/measured-lobe.toml (a lift table in a file) answered HTTP 500 on every load
    answered(page, servers.url(EXAMPLES / "measured-lobe.toml"))
    assert model_data(page, "handles-lift")["name"] == []         # the file's points are the file's
    assert value(page, "valves.intake.cam.table_file") == "data/measured-intake-lobe.csv"


@pytest.mark.parametrize("example", ["lost-motion-intake.toml", "switching-finger.toml"])
def test_the_variable_valve_actuation_examples_open(page, servers, example):
    # issue 42: the lost-motion intake and the switching finger in the designer, their tab drawn
    url = servers.url(EXAMPLES / example)
    opened(page, url)
    page.locator(".bk-tab", has_text=re.compile("^Lost motion, switching$")).click()
    expect(page.locator(".bk-tab.bk-active", has_text=re.compile("^Lost motion, switching$"))).to_be_visible()
    assert len(model_data(page, "vva-rows")["item"]) > 0 and len(model_data(page, "vva")["label"]) >= 2
    # issue 40's pictures of a finger in the page: the spring plot's ranges hold the chosen spring's line (a finger's
    # was cut), the curvature is drawn as 1/rho with the limit of the smallest convex radius, 1/(2 mm) (the switching
    # finger's rho passes through -21,500 mm at the flanks' inflections: drawn as rho, the spikes flattened the plot)
    curves = model_data(page, "curves")
    for plot, axis, column in (("spring", "x", "spring_line_x"), ("spring", "y", "spring_line_y"),
                               ("curvature", "y", "curvature"), ("curvature", "y", "curvature_limit")):
        drawn = [v for v in curves[column] if v == v]
        start, end = plot_range(page, plot, axis)
        assert drawn and start <= min(drawn) and max(drawn) <= end, column
    assert max(v for v in curves["curvature_limit"] if v == v) == pytest.approx(0.5) and end - start < 1.0
    assert page.errors == []


def test_a_specification_without_valves_is_served(page, servers):
    # issue 36's fuzzer: `valvetrain serve examples/v8-crank.toml` (an engine without valves) answered its page with
    # HTTP 500 (a KeyError); issue 40: every shipped example opens, this one with its engine's keys and checks
    from valvetrain.web.draw import WORDS

    answered(page, servers.url(EXAMPLES / "v8-crank.toml"))
    expect(page.get_by_text(WORDS["en"]["no_valves"])).to_be_visible()


def test_drag_of_a_peak_raises_the_acceleration_and_changes_the_checks(page, diesel_url):
    page = opened(page, diesel_url)
    # issue 40: the spring plot's range hid the diesel's chosen spring's line; the page's ranges hold it
    curves = model_data(page, "curves")
    for axis, column in (("x", "spring_line_x"), ("y", "spring_line_y")):
        line = [v for v in curves[column] if v == v]
        start, end = plot_range(page, "spring", axis)
        assert line and start <= min(line) and max(line) <= end, column
    before = model_data(page, "checks")["value"]
    handles = model_data(page, "handles-acceleration")
    i = handles["name"].index("peak")
    x, y = handles["x"][i], handles["y"][i]
    drag(page, "acceleration", (x, y), (x, 1.2 * y))
    # the valve's peak acceleration is a_qd x i x omega^2 (a flat extremum of the positive part, UkrSURT Proceedings
    # (2019) reconstruction R2): proportional to peak_acceleration_mm_per_rad2 (135.2 in the example), which the
    # drag scales by the new height over the old (the pointer went up to 1.2 times the height, within the room the
    # plot leaves above its highest point, a quarter of its span, and the peak follows it to the pixel)
    after = model_data(page, "handles-acceleration")
    rise = after["y"][after["name"].index("peak")] / y
    assert rise == pytest.approx(1.2, rel=0.01)
    a_qd = value(page, "valves.intake.cam.peak_acceleration_mm_per_rad2")
    assert a_qd / 135.2 == pytest.approx(rise, rel=5e-3)
    assert model_data(page, "checks")["value"] != before


def test_points_of_a_table_dragged_added_and_removed(page, table_url):
    page = opened(page, table_url)
    old = tomllib.loads("v = [" + value(page, "valves.intake.cam.table_lifts_mm") + "]")["v"]
    handles = model_data(page, "handles-acceleration")
    i = handles["name"].index("acceleration.10")
    x, y = handles["x"][i], handles["y"][i]
    py1 = round(pixels(page, "acceleration", x, y + 2000.0)[1])
    dropped = at_pixels(page, "acceleration", 0.0, py1)[1]
    drag(page, "acceleration", (x, y), (x, dropped))
    new = tomllib.loads("v = [" + value(page, "valves.intake.cam.table_lifts_mm") + "]")["v"]
    # the point's lift moves by -(a rise) d^2 / (2 omega^2) (twice the second divided difference is h'', Burden and
    # Faires, Numerical Analysis (2011), section 3.3), d = 12 crank deg = 0.104720 rad, omega = 7000 rpm / 2 =
    # 366.519 rad/s: 4.0817e-5 mm per m/s^2 of the rise from the handle's height to where the pointer left it
    assert new[10] == pytest.approx(old[10] - 4.0817e-5 * (dropped - y), abs=1.5e-3)
    after = model_data(page, "handles-acceleration")
    assert after["y"][after["name"].index("acceleration.10")] > y + 1000.0
    # a tap on the lift plot adds a point there (half way between points 12 and 13, on the line between them); the
    # point selected and Delete removes it
    lifts = model_data(page, "handles-lift")
    points = len(lifts["x"])
    x, y = (0.5 * (lifts[c][12] + lifts[c][13]) for c in ("x", "y"))
    done = redrawn_count(page)
    page.mouse.click(*pixels(page, "lift", x, y))
    wait_redrawn(page, done)
    lifts = model_data(page, "handles-lift")
    assert len(lifts["x"]) == points + 1
    k = min(range(len(lifts["x"])), key=lambda j: abs(lifts["x"][j] - x))
    assert (lifts["x"][k], lifts["y"][k]) == (pytest.approx(x, abs=0.3), pytest.approx(y, abs=0.05))
    page.mouse.click(*pixels(page, "lift", lifts["x"][k], lifts["y"][k]))
    done = redrawn_count(page)
    page.keyboard.press("Delete")
    wait_redrawn(page, done)
    assert len(model_data(page, "handles-lift")["x"]) == points


def test_the_breathing_panel_is_redrawn_after_an_edit_of_the_intake_closing(page, breathing_url):
    # issue 40: "once the breathing exists, its VE curve redrawn after an edit"
    designer = opened(page, breathing_url)
    designer.locator(".bk-tab", has_text=re.compile("^Breathing$")).click()
    expect(designer.locator(".bk-tab.bk-active", has_text=re.compile("^Breathing$"))).to_be_visible()
    before = model_data(designer, "breathing-curve")
    assert before["speed"] == [2000.0, 4000.0, 6000.0] and all(0.5 < v < 1.2 for v in before["ve"])
    assert designer.evaluate("() => { const v = Bokeh.index.find_one(Bokeh.documents[0]"
                             ".get_model_by_name('plot-breathing')); return v != null && v.bbox.width > 0; }")
    designer.locator(".bk-tab", has_text=re.compile("^Valve$")).click()
    box = designer.locator('input[name="valves.intake.closes_deg"]')      # the intake's closing lag, crank deg
    box.fill("50")
    box.press("Enter")
    designer.wait_for_function("""ve => {
        const c = Bokeh.documents[0].get_model_by_name('breathing-curve').data;
        return Array.from(c instanceof Map ? c.get('ve') : c.ve)[0] !== ve;
    }""", arg=before["ve"][0], timeout=WAIT_MS)
    assert value(designer, "valves.intake.closes_deg") == 50.0
    # the intake closing earlier: less charge pushed back at low speed (Heywood (1988), chapter 6)
    assert model_data(designer, "breathing-curve")["ve"][0] > before["ve"][0]
    assert designer.errors == []
