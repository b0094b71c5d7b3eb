"""The designer's speed-sweep panel (web/sweep.py) without a browser: when it starts, what it draws, the checks
pending until the whole design comes, each valve swept once."""

import copy
import tomllib

import numpy as np
import pytest
import tomli_w

pytest.importorskip("bokeh")

from valvetrain.web.draw import SEVERITY_COLOURS, WORDS, _now  # noqa: E402
from valvetrain.web.session import Session  # noqa: E402

from designer_page import _designer, _field, _request, _run_callbacks, _swept  # noqa: E402


@pytest.fixture(scope="module")
def swept():
    """The built-in example's designer with its sweep drawn, made once (a designer and a whole design with its sweeps
    are seconds) for the tests below in their order: the panel read, the speed of the dynamics at speed chosen, then
    an edit and the other valve shown."""
    return _swept(_designer())


def test_sweep_starts_when_the_page_has_drawn_the_newest_kinematics():
    d = _designer()
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
    # the first design's sweep is due before any edit (the page says when it has drawn it: the panel is not empty
    # until the first edit)
    first = _designer()
    first.start_sweep = lambda: started.append("first")
    first.on_drawn("data", None, {"n": [first.kinematic_stamp.data["n"][0]]})
    assert started[-1] == "first"


def test_checks_of_the_sweeps_are_pending_until_the_whole_design_comes():
    d = _designer()

    # the built-in example: both valves with a [dynamics] section, two checks each (seating velocity, jump speed)
    def dynamic():
        return [k for k in d.checks.data["key"] if "dynamic seating velocity" in k or "(jump)" in k]

    assert dynamic() == []
    _swept(d)
    found = dynamic()
    assert len(found) == 4
    d.on_field(_field(d, "engine.rated_speed_rpm"), "value", 7000, 6500)
    data = d.checks.data
    rows = [i for i, k in enumerate(data["key"]) if k in found]
    assert len(rows) == 4
    assert {data["value"][i] for i in rows} == {"…"}
    assert {data["colour"][i] for i in rows} == {SEVERITY_COLOURS["pending"]}
    assert {data["status"][i] for i in rows} == {"pending"}
    _swept(d)
    assert "…" not in d.checks.data["value"]


def test_the_sweep_plots_have_their_own_axes_and_the_map_its_colour_bar(swept):
    # issue 40: the seating velocity plot took the force plot's axis (0-800 N) through the shared marks of the jump
    # and bounce speeds, and showed a flat line; the lift-error map had no colour bar
    d = swept
    seating = np.abs(np.array(d.sweep_sources["seating"].data["y"], dtype=float))
    seating = seating[np.isfinite(seating)]
    rng = d.figures["sweep_seating"].y_range
    assert rng.start <= seating.min() and seating.max() <= rng.end < 2.0 * seating.max()
    marks = d.sweep_marks["seating"].data
    assert len(marks["x"]) and max(marks["y1"]) == pytest.approx(seating.max())
    force = d.sweep_sources["force"].data["y"]
    assert d.figures["sweep_force"].y_range.end >= np.nanmax(force)
    assert d.colour_bar in d.figures["sweep_map"].right and d.colour_bar.color_mapper is d.mapper
    assert d.mapper.high == pytest.approx(np.nanmax(np.abs(d.map_source.data["image"][0])))


def test_the_dynamics_against_the_angle_at_a_chosen_speed(swept):
    d = swept
    sweep = d.sweeps["intake"]
    # at first the swept speed nearest the rated one (7000 rpm)
    speeds = np.array(sweep["speed_rpm"])
    i = int(np.argmin(np.abs(speeds - 7000.0)))
    assert d.speed.value == pytest.approx(speeds[i])
    d.speed.value = float(speeds[5])
    d.on_speed("value_throttled", None, float(speeds[5]))
    force = np.array(d.at_speed.data["force"], dtype=float)
    # the speed's row of the sweep's maps
    assert np.array_equal(force, np.array(sweep["map_contact_force_N"][5], dtype=float), equal_nan=True)
    # the cam contact force against the angle: its least where the valve is well open is not below the sweep's
    # smallest contact force while the cam lifts at that speed (the per-speed table, over every angle of the sweep)
    series = d.session.good["series"]["intake"]
    open_ = np.interp(d.at_speed.data["x"], series["cam_deg"], series["valve_lift_mm"]) > 0.5
    assert np.min(force[open_]) >= sweep["min_contact_force_N"][5] - 1e-6
    assert d.figures["at_speed"].title.text == f"at {speeds[5]:.0f} rpm"
    # the rigid train's acceleration at that speed is the rated speed's scaled by the square of the speed ratio
    rigid = np.array(d.at_speed.data["rigid"], dtype=float)
    assert np.nanmax(rigid) == pytest.approx(np.interp(d.at_speed.data["x"], series["cam_deg"],
                                                       series["valve_acceleration_m_s2"]).max()
                                             * (speeds[5] / 7000.0) ** 2, rel=1e-9)


def test_the_sweep_panel_comes_from_the_valve_alone_before_the_whole_design(swept):
    d = swept
    d.on_field(_field(d, "engine.rated_speed_rpm"), "value", 7000, 6500)
    # the valve's sweep alone is the whole design's sweep of it (the same series from the two designs)
    alone = Session.sweep_one(d.session.document, "intake")
    whole = Session.settle(d.session.document)
    assert alone == whole["sweeps"]["intake"]
    # drawn first, with the page's probe stamped for the release that asked for it; the checks of the dynamics
    # still pending until the whole design comes, which stamps nothing the probe counts
    d.draw_sweep_of(d.generation, "intake", alone, _now(), 7)
    assert d.sweep_stamp.data["seq"] == [7]
    assert len(d.sweep_sources["force"].data["y"]) == len(alone["speed_rpm"])
    assert "pending" in d.checks.data["status"]
    # the other valve shown before the whole design comes: its sweep is to come, not the intake's in its place
    d.on_valve("value", "intake", "exhaust")
    assert d.sweep_status.text == WORDS["en"]["sweeping"]
    d.draw_sweep(d.generation, whole, _now(), 0)
    assert d.sweep_stamp.data["seq"] == [0] and "pending" not in d.checks.data["status"]
    assert list(d.sweep_sources["force"].data["y"]) == whole["sweeps"]["exhaust"]["min_contact_force_N"]
    # a valve the whole design does not sweep: without a [dynamics] section beside one with it
    mixed = copy.deepcopy(d.session.document)
    del mixed["valves"]["exhaust"]["dynamics"]
    assert Session.sweep_one(mixed, "exhaust") is None


def test_an_edit_sweeps_each_valve_once(monkeypatch):
    # issue 40: the sweep of the valve shown (drawn first, alone) was swept again by the whole design after it
    import valvetrain.design.valve as stages
    from valvetrain.specification import example_text
    from valvetrain.web.app import DESIGN_WORKERS
    from valvetrain.web.sweep import SWEEP_WORKERS

    document = tomllib.loads(example_text())
    for valve in document["valves"].values():
        valve["dynamics"]["speeds"] = 12                  # a short sweep: what is counted is the same
    d = _designer(tomli_w.dumps(document))
    swept, real = [], stages.dynamics_stage
    monkeypatch.setattr(stages, "dynamics_stage", lambda *a, **k: swept.append(a[5]) or real(*a, **k))
    # a drag released: its kinematics at once; then its design and, beside it, the valve's sweep (not waiting for
    # the design), then the whole design's sweeps (waiting for it)
    _request(d, "end", "nose", 0.0, 9.5, seq=3, finish=False)
    assert d.kinematic_stamp.data["seq"] == [3] and swept == []
    _run_callbacks(d)
    for workers in (DESIGN_WORKERS, SWEEP_WORKERS):
        workers.submit(lambda: None).result()             # the threads done
    assert swept == ["intake", "exhaust"]                 # the valve shown first, alone; the other by the whole design
    _run_callbacks(d)
    assert d.session.document["valves"]["intake"]["max_lift_mm"] == 9.5 and d.checks_stamp.data["seq"] == [3]
    assert d.sweep_stamp.data["n"] == [2] and "pending" not in d.checks.data["status"]   # the valve's, the whole
    assert len(d.sweep_sources["force"].data["y"]) == 12
    # an edit in the panel: its sweep when the page has drawn it, each valve once again
    d.on_field(_field(d, "engine.rated_speed_rpm"), "value", 7000, 6500)
    d.on_drawn("data", None, {"n": [d.kinematic_stamp.data["n"][0]]})
    SWEEP_WORKERS.submit(lambda: None).result()
    assert swept == ["intake", "exhaust"] * 2
