"""The designer's page (web/app.py) without a browser: its handlers on a Bokeh document, the check table's colours, the
sweeps it starts, and `valvetrain serve` refusing a specification that does not validate."""

import re
import tomllib

import numpy as np
import pytest

pytest.importorskip("bokeh")

from bokeh.document import Document  # noqa: E402

from valvetrain.web.app import SEVERITY_COLOURS, Designer, _now, kept_range, thinned  # noqa: E402
from valvetrain.web.session import Session, form  # noqa: E402

from appendix import appendix_text  # noqa: E402


def _colour(designer, quantity):
    data = designer.checks.data
    return data["colour"][data["key"].index(quantity)]


def test_page_callbacks():
    doc = Document()
    d = Designer(doc, Session.start(appendix_text()))
    quantity = "intake: V' (throat velocity)"
    # the appendix example: V' = 85.07 m/s at 7000 rpm, above 80; 72.9 m/s at 6000 rpm (c_p S n / 30 scaled by 6/7)
    assert _colour(d, quantity) != SEVERITY_COLOURS["pass"]
    f = next(f for _, group in form(d.session.document) for f in group if f.path == "engine.rated_speed_rpm")
    d.on_field(f, "value", 7000, 6000)
    assert _colour(d, quantity) == SEVERITY_COLOURS["pass"]
    d.on_pin()
    assert d.checks.data["baseline"][d.checks.data["key"].index(quantity)].startswith("72.9")
    bore = next(f for _, group in form(d.session.document) for f in group if f.path == "engine.bore_mm")
    d.on_field(bore, "value", 80, 3)
    assert d.errors["engine.bore_mm"].text == "allowed [5, 2000] mm"
    assert _colour(d, quantity) == SEVERITY_COLOURS["pass"]       # the last good design stays
    d.on_field(bore, "value", 3, 80)
    assert d.errors["engine.bore_mm"].text == ""
    lift = dict(d.handles["lift"].data)
    d.on_handles("lift", "data", lift, {**lift, "y": [10.5]})
    assert d.session.document["valves"]["intake"]["max_lift_mm"] == 10.5
    assert d.fields["valves.intake.max_lift_mm"].value == 10.5
    d.on_language("value", "en", "ru")
    assert d.check_columns[0].title == "Величина"
    d.on_units("value", "rated", "deg")
    # per cam degree: the velocity is the slope of the valve lift in mm/deg; central differences of the lift series
    # (0.5 cam deg apart) agree to 1 % of the peak where the valve is off its seat
    curves = d.curves.data
    x, v, lift = (np.array(curves[k])[np.isfinite(curves["x"])] for k in ("x", "velocity", "lift"))
    slope = np.gradient(lift, x)
    off = lift > 0.5
    assert np.max(np.abs(v[off] - slope[off])) < 0.01 * np.max(np.abs(slope))
    d.on_report()
    assert d.report_text.text.startswith("<!DOCTYPE html>") and 'lang="ru"' in d.report_text.text
    # the figures of `valvetrain run --figures main` (README: the cam contour among them) embedded, drawn in memory
    assert re.search(r'<img src="data:image/png;base64,[^"]+" alt="профиль кулачка">', d.report_text.text)
    d.on_toml()
    assert tomllib.loads(d.toml_text.text)["valves"]["intake"]["max_lift_mm"] == 10.5


def test_serve_refuses_a_specification_that_does_not_validate(refused):
    from valvetrain.specification import example_text

    text = example_text().replace("bore_mm = 80.0", "bore_mm = 3.0")
    assert "error: engine.bore_mm = 3.0: allowed [5, 2000] mm" in refused(text, "serve")


def test_serve_refuses_a_specification_without_valves(refused):
    """Issue 36's fuzzer: `valvetrain serve examples/v8-crank.toml` (an engine without valves) started, then answered
    its page with HTTP 500 (a KeyError: the designer edits valves); refused at the start, exit status 2."""
    from pathlib import Path

    text = (Path(__file__).parents[2] / "examples" / "v8-crank.toml").read_text(encoding="utf-8")
    assert "error: valves: the designer edits the valves' cams; the file defines none" in refused(text, "serve")


def test_serve_on_a_port_in_use_is_one_line():
    """Issue 36: `valvetrain serve` on a port another program listens on printed an OSError traceback; it says so in one
    line naming the port, exit status 2."""
    import socket

    from click.testing import CliRunner

    from valvetrain.cli import main

    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen()
        port = taken.getsockname()[1]
        result = CliRunner().invoke(main, ["serve", "--no-show", "--port", str(port)])
    assert result.exit_code == 2, result.output
    assert result.output.splitlines() == [f"error: --host 127.0.0.1 --port {port}: cannot listen there (Address already "
                                          "in use); give another --port (0: any free port) or --host"]


def test_sweep_starts_when_the_page_has_drawn_the_newest_kinematics():
    d = Designer(Document(), Session.start())
    started = []
    d.start_sweep = lambda: started.append(d.kinematic_stamp.data["n"][0])
    d.redraw()
    newest = d.kinematic_stamp.data["n"][0]
    d.on_drawn("data", None, {"n": [newest - 1]})         # an older redraw drawn: its sweep would be stale
    assert started == []
    d.on_drawn("data", None, {"n": [newest]})
    d.on_drawn("data", None, {"n": [newest]})             # once per redraw
    assert started == [newest]
    d.redraw(sweep=False)                                 # a language or unit switch: no new sweep
    d.on_drawn("data", None, {"n": [newest + 1]})
    assert started == [newest]


def test_checks_of_the_sweeps_are_pending_until_the_whole_design_comes():

    d = Designer(Document(), Session.start())
    # the built-in example: both valves with a [dynamics] section, two checks each (seating velocity, jump speed)
    def dynamic():
        return [k for k in d.checks.data["key"] if "dynamic seating velocity" in k or "(jump)" in k]

    assert dynamic() == []
    d.draw_sweep(d.generation, Session.settle(d.session.good_document), _now())
    found = dynamic()
    assert len(found) == 4
    f = next(f for _, group in form(d.session.document) for f in group if f.path == "engine.rated_speed_rpm")
    d.on_field(f, "value", 7000, 6500)
    data = d.checks.data
    rows = [i for i, k in enumerate(data["key"]) if k in found]
    assert len(rows) == 4
    assert {data["value"][i] for i in rows} == {"…"}
    assert {data["colour"][i] for i in rows} == {SEVERITY_COLOURS["pending"]}
    d.draw_sweep(d.generation, Session.settle(d.session.good_document), _now())
    assert "…" not in d.checks.data["value"]


def test_plot_ranges_are_kept_while_the_curves_keep_half_their_room():
    # a lift from 0 to 10 mm with a quarter of its span as room: (-2.5, 12.5) mm.  Raised to 11 mm it still has
    # 12.5 - 11 = 1.5 mm >= 2.75 / 2 above it: kept (no new ticks, no new layout).  Raised to 12 mm, 0.5 mm < 3 / 2:
    # refitted to (-3, 15).  Cut to 2 mm the range 18 mm wide is more than twice the 2 + 2 x 0.5 = 3 mm it wants:
    # refitted to (-0.5, 2.5)
    assert kept_range(0.0, 1.0, 0.0, 10.0, 0.25) == (-2.5, 12.5)
    assert kept_range(-2.5, 12.5, 0.0, 11.0, 0.25) == (-2.5, 12.5)
    assert kept_range(-2.5, 12.5, 0.0, 12.0, 0.25) == (-3.0, 15.0)
    assert kept_range(-3.0, 15.0, 0.0, 2.0, 0.25) == (-0.5, 2.5)
    # the redraws of a drag change a range only when it moves: the nose 0.1 mm higher leaves the lift plot's
    d = Designer(Document(), Session.start())
    lift = d.figures["lift"].y_range
    before = (lift.start, lift.end)
    handles = dict(d.handles["lift"].data)
    d.on_handles("lift", "data", handles, {**handles, "y": [handles["y"][0] + 0.1]})
    assert d.session.document["valves"]["intake"]["max_lift_mm"] == pytest.approx(handles["y"][0] + 0.1, abs=1e-3)
    assert (lift.start, lift.end) == before


def test_a_drag_sends_only_the_sources_that_change():
    # the page gets a message per changed source (and paints its plots again): after the sweep panel is drawn, a drag
    # of the nose changes the curves and the handles, never the sweep panel of the last whole design (its new sweep
    # comes later) nor the heel circle (the same base circle); counted on the document's change events
    d = Designer(Document(), Session.start())
    d.draw_sweep(d.generation, Session.settle(d.session.good_document), _now())
    changed = []
    d.doc.on_change(lambda event: changed.append(getattr(event, "model", None)))
    lift = dict(d.handles["lift"].data)
    d.on_handles("lift", "data", lift, {**lift, "y": [lift["y"][0] - 0.1]})
    assert d.curves in changed
    unchanged = [d.heel, d.map_source, d.sweep_marks, *d.sweep_sources.values()]
    assert [s for s in unchanged if s in changed] == []
    # a pinned baseline's curves (NaN-padded to one length) are the same at the next drag: not sent again
    d.on_pin()
    changed.clear()
    lift = dict(d.handles["lift"].data)
    d.on_handles("lift", "data", lift, {**lift, "y": [lift["y"][0] - 0.1]})
    assert d.curves in changed and d.base_curves not in changed


def test_thinned_curve_keeps_what_a_plot_shows():
    # sin x on [0, 2 pi] in 2001 samples with one sample raised by 5 (a spike a plot must show): every-k-th sampling
    # drops it; the thinned curve keeps it, the ends, and the extremes of sin x (1 at pi/2, -1 at 3 pi/2, samples
    # pi/1000 apart: within 1 - cos(pi/2000) = 1.2e-6 of the closed form's)
    x = np.linspace(0.0, 2.0 * np.pi, 2001)
    y = np.sin(x)
    y[777] += 5.0
    tx, ty = thinned(x, y, buckets=100)
    assert len(tx) <= 202 and np.all(np.diff(tx) > 0.0)
    assert (tx[0], ty[0], tx[-1], ty[-1]) == (x[0], y[0], x[-1], y[-1])
    assert (x[777], y[777]) in set(zip(tx, ty, strict=True))
    spikeless = np.delete(np.arange(len(tx)), np.flatnonzero(tx == x[777]))
    assert ty[spikeless].max() == pytest.approx(1.0, abs=1.3e-6)
    assert ty.min() == pytest.approx(-1.0, abs=1.3e-6)
    # every sample between two kept points lies within their span of a bucket: no sample above the kept maximum or
    # below the kept minimum of its bucket (the line covers the pixels the whole curve covers)
    bucket = np.minimum((x / (2.0 * np.pi) * 100).astype(int), 99)
    kept_bucket = np.minimum((tx / (2.0 * np.pi) * 100).astype(int), 99)
    for b in range(100):
        assert y[bucket == b].max() == ty[kept_bucket == b].max()
        assert y[bucket == b].min() == ty[kept_bucket == b].min()
    # a short curve and one with a gap as they are
    assert thinned(x[:150], y[:150], buckets=100)[0].size == 150
    gap = y.copy()
    gap[10] = np.nan
    assert thinned(x, gap, buckets=100)[1].size == 2001


def test_curves_sent_to_the_page_are_thinned_to_what_the_plots_show():
    d = Designer(Document(), Session.start())
    series = d.session.good["series"]["intake"]
    curves = d.curves.data
    # the spring's required force: about 2000 points against the lift, sent with at most 402; its largest force
    # (the spring plot's range) kept exactly (to 32-bit floats)
    assert len(series["required_force_N"]) > 1000
    spring = curves["spring_y"][np.isfinite(curves["spring_y"])]
    assert spring.size <= 402
    assert spring.max() == pytest.approx(max(series["required_force_N"]), rel=1e-6)
    # every column as long as the longest curve sent, 32-bit
    assert {len(v) for v in curves.values()} == {max(len(series["cam_deg"]), spring.size,
                                                     np.isfinite(curves["contour_x"]).sum())}
    assert {v.dtype for v in curves.values()} == {np.dtype(np.float32)}
    # the contour closed, its points on the design's contour
    cx, cy = (curves[k][np.isfinite(curves[k])] for k in ("contour_x", "contour_y"))
    assert (cx[0], cy[0]) == (cx[-1], cy[-1])
    assert set(zip(cx, cy, strict=True)) <= set(zip(np.float32(series["contour_x_mm"]), np.float32(series["contour_y_mm"]),
                                                    strict=True))
