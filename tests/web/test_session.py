"""The designer's session without a browser (web/session.py): edits, drags, baseline, TOML."""

import copy
from pathlib import Path
import tomllib

import numpy as np
import pytest
import tomli_w

pytest.importorskip("bokeh")

from valvetrain.specification import parse_spec  # noqa: E402
from valvetrain.web.session import Session, document_key  # noqa: E402

from appendix import appendix_text  # noqa: E402


EXAMPLES = sorted((Path(__file__).parents[2] / "examples").rglob("*.toml"))
"""Every example shipped."""


def test_bad_value_keeps_the_last_good_design():
    s = Session.start()
    good = s.good
    assert not s.edit({"engine.bore_mm": 3.0})
    assert s.good is good and s.document["engine"]["bore_mm"] == 80.0
    assert [p["path"] for p in s.problems] == ["engine.bore_mm"] and s.refused == {"engine.bore_mm": 3.0}
    assert s.edit({"engine.bore_mm": 81.0}) and s.problems == [] and s.refused == {}


def test_refused_edits_leave_nothing_behind():
    # issue 40: after three refused edits no drag designed again (each edit applied to the refused document), and
    # when one did, the design drawn carried the refused values the panel no longer showed
    s = Session.start()
    before = document_key(s.document)
    assert not s.edit({"valves.intake.max_lift_mm": 0.001})             # allowed [0.3, 500] mm
    # phi1 + phi2 = 80 + 6 > phi_p0 = 71 cam deg: no room for phi3
    assert not s.edit({"valves.intake.cam.phi1_deg": 80.0})
    assert not s.edit({"valves.intake.cam.phi3_deg": 60.0})            # the angles no longer add up to phi_p0
    assert s.problems and document_key(s.document) == before and s.undone == []
    assert s.drag("intake", "nose", 0.0, 10.0)
    # the design drawn is the last good one with the drag: 10 mm, and the example's phi1, phi2, phi3
    cam = s.document["valves"]["intake"]["cam"]
    assert (s.document["valves"]["intake"]["max_lift_mm"], cam["phi1_deg"], cam["phi2_deg"], cam["phi3_deg"]) == \
        (10.0, 27.0, 6.0, 38.0)
    assert max(s.good["series"]["intake"]["valve_lift_mm"]) == pytest.approx(10.0, rel=1e-9)
    assert s.problems == [] and len(s.undone) == 1


def test_undo_and_redo_every_edit():
    s = Session.start()
    first = document_key(s.document)
    assert s.edit({"engine.rated_speed_rpm": 6500.0})
    assert s.drag("intake", "nose", 0.0, 9.5)
    third = document_key(s.document)
    assert not s.edit({"engine.bore_mm": 3.0})                        # refused: nothing to undo
    assert s.undo() and s.document["valves"]["intake"]["max_lift_mm"] == 9.0
    assert s.document["engine"]["rated_speed_rpm"] == 6500.0
    assert s.undo() and document_key(s.document) == first
    assert not s.undo()
    # the design undone is the one designed before (kept by its document), not designed again
    assert s.good is s.designs[first]
    assert s.redo() and s.redo() and document_key(s.document) == third and not s.redo()
    assert s.undo() and s.edit({"engine.bore_mm": 81.0})             # a new edit: nothing left to redo
    assert not s.redo()


def test_every_example_opens_with_handles_inside_their_limits():
    # issue 40: examples/measured-lobe.toml (a lift table in a file) answered HTTP 500 (its handles needed opens_deg)
    from bokeh.document import Document
    from valvetrain.web.app import Designer

    for path in EXAMPLES:
        d = Designer(Document(), Session.start(path.read_text(encoding="utf-8"), path.parent))
        for valve in d.session.document.get("valves", {}):
            for h in d.session.handles(valve):
                assert h.x_limits[0] <= h.x <= h.x_limits[1] and h.y_limits[0] <= h.y <= h.y_limits[1], (path, h)
    assert {p.name for p in EXAMPLES} >= {"measured-lobe.toml", "two-stroke-ports.toml", "v8-crank.toml"}


def test_drag_of_a_segment_boundary_keeps_the_others():
    s = Session.start()
    # half-angle phi_p0 = (26 + 180 + 78) / 2 crank deg / 2 = 71 cam deg; phi1 = 27 puts the first boundary at
    # -71 + 27 = -44 cam deg, the second at -44 + 6 = -38
    h = {x.name: x for x in s.handles("intake")}
    assert (h["phi1"].x, h["phi2"].x) == (pytest.approx(-44.0), pytest.approx(-38.0))
    assert s.drag("intake", "phi1", -46.0, 0.0)
    cam = s.document["valves"]["intake"]["cam"]
    # phi1 = 71 - 46 = 25, phi2 = 27 + 6 - 25 = 8 (the second boundary stays), phi3 = 38 as given
    assert (cam["phi1_deg"], cam["phi2_deg"], cam["phi3_deg"]) == (25.0, 8.0, 38.0)


def test_a_handle_the_valve_does_not_have_is_refused_by_its_name():
    """Issue 36 (fuzz): a three-arc cam has the nose alone; a drag of another handle (a Handle passed for its name, a
    page drawn before the law changed) raised KeyError 'phi1_deg', the keys of a cam of segment angles; now a
    ValueError naming the handle and the valve's handles, and the page's request redraws the good design."""
    from bokeh.document import Document
    from valvetrain.web.app import Designer

    doc = tomllib.loads(appendix_text())
    cam = doc["valves"]["intake"]["cam"]
    doc["valves"]["intake"]["cam"] = {"law": "three_arc", "flank_angle_deg": 25.0, "follower": "flat",
                                      "base_radius_mm": cam["base_radius_mm"]}
    s = Session.start(tomli_w.dumps(doc))
    assert [h.name for h in s.handles("intake")] == ["nose"]
    with pytest.raises(ValueError, match=r"valves.intake has no handle 'phi1' \(its handles: nose\)"):
        s.drag("intake", "phi1", -40.0, 0.0)
    before = copy.deepcopy(s.document)
    d = Designer(Document(), s)
    d.on_request("data", {}, {"kind": ["end"], "seq": [1], "plot": ["acceleration"], "name": ["phi1"], "x": [-40.0],
                              "y": [0.0], "text": [""]})
    assert d.session.document == before
    assert s.drag("intake", "nose", 0.0, 9.0)


def test_drag_of_the_nose_sets_the_valve_lift():
    s = Session.start()
    assert s.drag("intake", "nose", 0.0, 10.8)
    assert max(s.good["series"]["intake"]["valve_lift_mm"]) == pytest.approx(10.8, rel=1e-9)


def test_toml_reads_back_to_the_edited_design():
    s = Session.start()
    s.edit({"engine.rated_speed_rpm": 6500.0})
    assert parse_spec(s.toml()).engine.rated_speed_rpm == 6500.0


def test_a_measured_table_from_its_file_has_no_shape_handles():
    """Issue 36's fuzzer: `valvetrain serve examples/measured-lobe.toml` answered the page with HTTP 500 (a TypeError:
    the table sets its own timing, so the valve has no opens_deg for the shape handles).  A table read from its file
    has no handle to drag (its lift is the measurement's); the session starts and the page's handles are none."""
    from pathlib import Path

    path = Path(__file__).parents[2] / "examples" / "measured-lobe.toml"
    s = Session.start(path.read_text(encoding="utf-8"), path.parent)
    assert s.handles("intake") == []


def test_sessions_are_separate():
    a, b = Session.start(), Session.start()
    a.edit({"engine.rated_speed_rpm": 6000.0})
    assert b.document["engine"]["rated_speed_rpm"] == 7000
    assert b.good["results"]["engine"]["rated_speed_rpm"] == 7000


def test_power_polynomial_handles_follow_its_keys():
    from pathlib import Path

    examples = Path(__file__).parents[2] / "examples"
    s = Session.start((examples / "ukrsurt2019-diesel.toml").read_text(encoding="utf-8"), examples)
    h = {x.name: x for x in s.handles("intake")}
    # phi_p0 = (40 + 180 + 55) / 2 crank deg / 2 = 68.75 cam deg: the ramp (12 deg) starts at -80.75, the positive
    # part (phi1 = 19.3) ends at -68.75 + 19.3 = -49.45, its peak at -68.75 + 0.2 x 19.3 = -64.89
    assert (h["ramp"].x, h["peak"].x, h["phi1"].x) == (pytest.approx(-80.75), pytest.approx(-64.89),
                                                        pytest.approx(-49.45))
    # the peak of the valve acceleration: a_qd x i x omega^2 = 0.1352 m/rad² x 1 x (1000 rpm x pi/30 / 2)² = 370.66
    # m/s² (the series is sampled every 0.5 cam deg)
    assert h["peak"].y == pytest.approx(370.66, rel=5e-3)
    assert s.drag("intake", "peak", -62.89, 1.2 * h["peak"].y)
    cam = s.document["valves"]["intake"]["cam"]
    # x_d = (-62.89 + 68.75) / 19.3 = 0.3036 (to 3 digits); a_qd = 1.2 x 135.2 mm/rad²
    assert (cam["peak_position"], cam["peak_acceleration_mm_per_rad2"]) == (0.304, pytest.approx(162.24, rel=5e-3))
    peak = next(x for x in s.handles("intake") if x.name == "peak")
    assert peak.x == pytest.approx(-68.75 + 0.304 * 19.3)
    assert peak.y == pytest.approx(1.2 * 370.66, rel=5e-3)
    assert s.drag("intake", "ramp", -82.0, 0.0)
    assert s.document["valves"]["intake"]["cam"]["ramp_angle_deg"] == 82.0 - 68.75
    assert s.good["series"]["intake"]["segments_cam_deg"][0] == pytest.approx(-82.0)
    assert s.drag("intake", "phi1", -48.0, 0.0)
    assert s.document["valves"]["intake"]["cam"]["phi1_deg"] == 68.75 - 48.0
    assert s.drag("intake", "trough", -30.0, 0.0)
    assert 0.02 <= s.document["valves"]["intake"]["cam"]["trough_position"] <= 0.98


def test_combined_cam_segment_ends_set_lengths_and_ratios():
    s = Session.start(appendix_text())
    doc = copy.deepcopy(s.document)
    doc["valves"]["intake"]["cam"] = {"law": "combined", "base_radius_mm": 20.0, "ramp_end_velocity_mm_per_deg": 0.02,
                                      "segments": [{"shape": "half_sine", "length_deg": 25.0},
                                                   {"shape": "quarter_sine", "length_deg": 8.0},
                                                   {"shape": "parabola_to_nose", "length_deg": 38.0}],
                                      "ratios": [{"segment": 2, "value": 0.625}]}
    assert s.apply(doc), s.problems
    h = {x.name: x for x in s.handles("intake")}
    # phi_p0 = 71 cam deg: segment 1 ends at -71 + 25 = -46, segment 2 at -46 + 8 = -38; the last ends at the nose
    assert sorted(h) == ["end.1", "end.2", "nose"]
    assert (h["end.1"].x, h["end.2"].x) == (pytest.approx(-46.0), pytest.approx(-38.0))
    assert s.drag("intake", "end.1", -48.0, 0.0)
    # segment 1: -48 + 71 = 23 deg, segment 2: 25 + 8 - 23 = 10 deg (segment 2's end stays)
    assert [seg["length_deg"] for seg in s.document["valves"]["intake"]["cam"]["segments"]] == [23.0, 10.0, 38.0]
    series = s.good["series"]["intake"]
    nose = float(np.interp(0.0, series["cam_deg"], series["valve_acceleration_m_s2"]))
    assert s.drag("intake", "end.2", -38.0, 0.5 * nose)
    # the ratio's definition: a(end of segment 2) = value x a(nose), the value 0.5 where the handle was put
    assert s.document["valves"]["intake"]["cam"]["ratios"] == [{"segment": 2, "value": 0.5}]
    series = s.good["series"]["intake"]
    a = np.interp([-38.0, 0.0], series["cam_deg"], series["valve_acceleration_m_s2"])
    assert a[0] / a[1] == pytest.approx(0.5, rel=1e-6)


def test_points_of_an_inline_table_are_handles_moved_added_and_removed():
    from measured_lobe import EXAMPLE, EXAMPLE_TABLE, inline_text
    from valvetrain import api
    from valvetrain.files import read_lift_table

    angle, lift = read_lift_table(EXAMPLE_TABLE)
    s = Session.start(inline_text(angle[::6], lift[::6]), EXAMPLE.parent)
    h = {x.name: x for x in s.handles("intake") if x.plot == "lift"}
    assert sorted(h, key=lambda n: int(n.split(".")[1])) == [f"point.{k}" for k in range(31)]
    # the table is the appendix's lobe with its nose 3 crank deg late, at 116 + 3 = 119 crank deg (tests/laws/
    # test_measured.py): its highest point, 122 crank deg, lies (122 - 119) / 2 = 1.5 cam deg after the nose
    assert (h["point.16"].x, h["point.16"].y) == (pytest.approx(1.5, abs=0.1), pytest.approx(9.991, abs=5e-4))
    assert s.drag("intake", "point.16", h["point.16"].x, 10.5)
    cam = s.document["valves"]["intake"]["cam"]
    assert (cam["table_angles_deg"][16], cam["table_lifts_mm"][16]) == (122.0, 10.5)
    # dragged past its neighbour (134 crank deg) it stops 0.01 deg before it
    assert s.drag("intake", "point.16", 20.0, 10.5)
    assert cam is not s.document["valves"]["intake"]["cam"]
    assert s.document["valves"]["intake"]["cam"]["table_angles_deg"][16:18] == [133.99, 134.0]
    x, y = zip(*[(p.x, p.y) for p in s.handles("intake") if p.plot == "lift"], strict=True)
    # a point added at 1.5 cam deg from the nose, (119 + 2 x 1.5 =) 122 crank deg, and the last one removed
    assert s.set_points("intake", [*x[:-1], h["point.16"].x], [*y[:-1], 10.2])
    cam = s.document["valves"]["intake"]["cam"]
    assert len(cam["table_angles_deg"]) == 31 and cam["table_angles_deg"][-1] == 278.0
    k = cam["table_lifts_mm"].index(10.2)
    assert cam["table_angles_deg"][k] == pytest.approx(122.0, abs=0.2)
    # the TOML saved reads back to the same design
    again = api.design(tomllib.loads(s.toml()), dynamics=False)
    assert again["series"]["intake"]["valve_lift_mm"] == s.good["series"]["intake"]["valve_lift_mm"]


def test_kurz_boundaries_move_one_to_one_and_set_the_shape_factor():
    s = Session.start()
    h = {x.name: x for x in s.handles("intake")}
    # the Kurz law's positive acceleration is a half sine over phi1 (Valve-train practical works (n.d.), work 2): its
    # peak, in the middle of phi1, moves half as far as the phi1 boundary, so it has no handle of its own (a 3 deg
    # drag of one took phi2 from 6 deg to its 0.1 deg least)
    assert sorted(h) == ["nose", "phi1", "phi2"]
    # phi_p0 = 71 cam deg: phi1 may end 0.1 deg after the ramp's end (-71) and 0.1 deg before phi2's end (-38); phi2
    # may end 0.1 deg after phi1's (-44) and 0.1 deg before the nose (phi3 = 38 is given: -38 + 38 = 0)
    assert h["phi1"].x_limits == (pytest.approx(-70.9), pytest.approx(-38.1))
    assert h["phi2"].x_limits == (pytest.approx(-43.9), pytest.approx(-0.1))
    assert h["phi1"].y_limits[0] == h["phi1"].y_limits[1]               # a boundary of phi1 moves sideways only
    assert s.drag("intake", "phi1", -47.0, h["phi1"].y)
    cam = s.document["valves"]["intake"]["cam"]
    # one to one: the boundary 3 deg earlier, phi1 = 71 - 47 = 24, phi2 = 27 + 6 - 24 = 9 (the phi2/phi3 boundary
    # at -38 stays)
    assert (cam["phi1_deg"], cam["phi2_deg"], cam["phi3_deg"]) == (24.0, 9.0, 38.0)
    assert next(x for x in s.handles("intake") if x.name == "phi1").x == pytest.approx(-47.0)
    series = s.good["series"]["intake"]
    nose = float(np.interp(0.0, series["cam_deg"], series["valve_acceleration_m_s2"]))
    # Z = 0.05 ... 0.99 of the nose's acceleration: the handle's height range
    phi2 = next(x for x in s.handles("intake") if x.name == "phi2")
    assert phi2.y_limits == (pytest.approx(0.99 * nose), pytest.approx(0.05 * nose))
    assert s.drag("intake", "phi2", -38.0, 0.5 * nose)
    assert s.document["valves"]["intake"]["cam"]["shape_factor"] == 0.5
    # Z = j_T2K / j_T3K, the accelerations at the phi2/phi3 junction and at the nose (the law's definition, work 2)
    series = s.good["series"]["intake"]
    a = np.interp([-38.0, 0.0], series["cam_deg"], series["valve_acceleration_m_s2"])
    assert a[0] / a[1] == pytest.approx(0.5, rel=1e-3)


def test_polydyne_peak_handle_sets_p():
    from pathlib import Path

    examples = Path(__file__).parents[2] / "examples"
    s = Session.start((examples / "seed000-polydyne.toml").read_text(encoding="utf-8"), examples)
    h = {x.name: x for x in s.handles("intake")}
    # h = h_nose (1 + C2 x^2 + Cp x^p + ...), x = theta / phi_p0; p = 8, q, r, s = 14, 20, 26: the closed-form
    # coefficients (3.4)-(3.8) of Valve-train practical works (n.d.), work 3; the acceleration peaks where the third
    # derivative, sum C_k k (k-1) (k-2) x^(k-3), vanishes: x = 0.8088 (its root in (0, 1) but x = 1, the start of
    # lift, where the law makes it vanish; numpy's roots below), on the opening flank at -71 x 0.8088 = -57.43 cam
    # deg (phi_p0 = (26 + 180 + 78) / 4 = 71)
    c = {8: 1.87243, 14: -1.60494, 20: 0.74897, 26: -0.14403}
    third = np.zeros(24)
    for k, ck in c.items():
        third[26 - k] = ck * k * (k - 1) * (k - 2)         # highest power (x^23) first
    roots = np.roots(third)
    x = [r.real for r in roots if abs(r.imag) < 1e-9 and 0.1 < r.real < 0.99]
    assert len(x) == 1 and h["peak"].x == pytest.approx(-71.0 * x[0], abs=71.0 / 2000)
    assert s.drag("intake", "peak", -62.0, h["peak"].y)
    p = s.document["valves"]["intake"]["cam"]["p"]
    assert p > 8                           # a peak nearer the start of lift: a larger p
    # the redrawn acceleration peaks under the pointer (the series every 0.5 cam deg)
    series = s.good["series"]["intake"]
    angle, acc = np.array(series["cam_deg"]), np.array(series["valve_acceleration_m_s2"], dtype=float)
    opening = angle < 0.0
    assert angle[opening][np.nanargmax(acc[opening])] == pytest.approx(-62.0, abs=0.5)


def test_quick_design_leaves_the_spring_diagnosis_to_the_whole_design():
    # the designer's first answer to a drag skips the diagnosis of a spring that does not pass (a new spring search
    # per remedy, about a second: the table law's drags took 1-2 s); the checks fail the same and the whole design
    # (the downloaded report, `valvetrain run`) still diagnoses.  The measured lobe raised at its top row to
    # 10.5 mm: no spring of the search passes (its fatigue safety short of 1.3, Valve-train practical works (n.d.),
    # eq. (6.12))
    from measured_lobe import EXAMPLE, EXAMPLE_TABLE, inline_text
    from valvetrain import api
    from valvetrain.files import read_lift_table

    angle, lift = read_lift_table(EXAMPLE_TABLE)
    s = Session.start(inline_text(angle[::6], lift[::6]), EXAMPLE.parent)
    assert s.drag("intake", "point.16", s.handles("intake")[16].x, 10.5)
    whole = api.design(s.good_document, dynamics=False)["results"]
    quick = s.good["results"]
    assert quick["valves"]["intake"]["spring"].get("diagnosis") is None
    assert whole["valves"]["intake"]["spring"]["diagnosis"]["conflicts"]
    failing = {c["quantity"]: c for c in quick["checks"] if not c["pass"]}
    assert "intake: spring fatigue safety factor" in failing
    assert {c["quantity"]: c["value"] for c in whole["checks"] if not c["pass"]} == \
        {q: c["value"] for q, c in failing.items()}
    notes = {c["quantity"]: c.get("note") for c in whole["checks"]}
    fatigue = "intake: spring fatigue safety factor"
    assert not failing[fatigue].get("note") and notes[fatigue].startswith("No spring passes")


def test_acceleration_points_of_an_inline_table_move_the_lift_of_their_point():
    from measured_lobe import EXAMPLE, EXAMPLE_TABLE, inline_text
    from valvetrain.files import read_lift_table

    angle, lift = read_lift_table(EXAMPLE_TABLE)
    s = Session.start(inline_text(angle[::6], lift[::6]), EXAMPLE.parent)
    old = list(s.document["valves"]["intake"]["cam"]["table_lifts_mm"])
    h = {x.name: x for x in s.handles("intake") if x.plot == "acceleration"}
    # a handle at each point off the base circle but the ends: the table's first four points lie on it (lift 0)
    assert sorted(int(n.split(".")[1]) for n in h) == [k for k in range(1, 30) if old[k] > 0.0] == list(range(4, 28))
    k, rise = 10, 2000.0
    a = h[f"acceleration.{k}"]
    assert s.drag("intake", a.name, a.x, a.y + rise)
    new = s.document["valves"]["intake"]["cam"]["table_lifts_mm"]
    # the point's lift moves by -rise d1 d2 / (2 omega^2), twice the second divided difference being h''
    # (Burden and Faires, Numerical Analysis (2011), section 3.3): d1 = d2 = 12 crank deg = 6 cam deg = 0.104720 rad,
    # omega = 7000 rpm / 2 = 366.519 rad/s: 2000 / 366.519^2 x 0.104720^2 / 2 = 8.163e-5 m = 0.0816 mm
    assert new[k] == pytest.approx(old[k] - 0.0816, abs=6e-4)
    assert max(abs(n - o) for j, (n, o) in enumerate(zip(new, old, strict=True)) if j != k) <= 5e-4  # 0.001 mm steps
    # the table's acceleration at the point, omega^2 h'' from its three points written out, rose by the drag (to
    # the rounding of the lifts to 0.001 mm: 2 x 0.0005 mm / d^2 x omega^2 = 12 m/s^2)
    d, omega = np.deg2rad(6.0), 7000.0 / 60.0 * np.pi

    def table_acceleration(h):
        return omega**2 * (h[k + 1] - 2.0 * h[k] + h[k - 1]) * 1e-3 / d**2

    assert table_acceleration(new) - table_acceleration(old) == pytest.approx(rise, abs=30.0)
    # the law's fit follows the moved point: the design's acceleration there rises by about the drag
    after = {x.name: x for x in s.handles("intake")}[a.name]
    assert 0.5 * rise < after.y - a.y < 2.0 * rise


def test_a_drags_sketch_is_the_kinematics_of_its_valve_kept_for_the_release(monkeypatch):
    from valvetrain import api

    s = Session.start()
    calls, real = [], api.kinematics
    monkeypatch.setattr(api, "kinematics", lambda spec, name: calls.append(name) or real(spec, name))
    document, sketch = s.preview({"valves.intake.max_lift_mm": 9.5}, "intake")
    # the valve's curves are the edited document's, the other valve's the good design's; the spring's, which the
    # drive stage designs, none until the document's design is kept (issue 40: the good design's spring was drawn
    # beside the new lift), then that design's
    assert max(sketch["series"]["intake"]["valve_lift_mm"]) == pytest.approx(9.5)
    assert sketch["series"]["intake"]["required_force_N"] == [] == sketch["series"]["intake"]["spring_line_force_N"]
    assert sketch["series"]["exhaust"] is s.good["series"]["exhaust"]
    assert s.document["valves"]["intake"]["max_lift_mm"] == 9.0          # kept as neither
    # released where the pointer last moved: not sketched again
    assert s.preview({"valves.intake.max_lift_mm": 9.5}, "intake")[1] == sketch and calls == ["intake"]
    designed = s.design(document)["series"]["intake"]
    again = s.preview({"valves.intake.max_lift_mm": 9.5}, "intake")[1]["series"]["intake"]
    assert max(again["spring_lift_mm"]) == pytest.approx(9.5) and calls == ["intake"]
    assert all(again[k] == designed[k] for k in ("spring_lift_mm", "required_force_N", "spring_line_force_N"))
    # a cam the law cannot make: not ok, with why
    refused = s.preview({"valves.intake.max_lift_mm": 0.31}, "intake")[1]
    assert not refused["ok"] and refused["errors"][0]["path"].startswith("valves.intake")
