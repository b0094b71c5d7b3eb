"""The cam phaser (valvetrain.design.phaser, issue 42) on the built-in example's engine with an intake phaser from
-10 to 40 crank deg and a motored or fired breathing: the events moved by exactly the phase, the breathing at phase 0
the breathing chapter's own, the best phase against an independent fine scan, the torque the phaser holds against
the camshaft's drive torque, the gap at the range's ends by hand, bad input refused naming the key."""

from dataclasses import replace
import json
import re
from types import SimpleNamespace

import jsonschema
import numpy as np
import pytest

from valvetrain.breathing import ValveFlow, breathe
from valvetrain.design import breathing_view, results_schema, run
from valvetrain.export import results_json
from valvetrain.design.breathing import GRID, breathe_conditions, breathing_conditions, gas_opening_load
from valvetrain.design.phaser import advances, phased_flow
from valvetrain.locale import note_text
from valvetrain.specification import SpecError, example_spec, spec_document, validate

PHASER = {"advance_range_crank_deg": [-10.0, 40.0], "step_crank_deg": 10.0, "tolerance_crank_deg": 0.5}

CAMSHAFT = {"valves": ["intake"], "cylinder_positions_mm": [60.0, 150.0, 240.0, 330.0],
            "section_lengths_mm": [390.0], "section_diameters_mm": [30.0],
            "journal_positions_mm": [20.0, 105.0, 195.0, 285.0, 375.0], "drive_pitch_radius_mm": 45.0,
            "drive_allowable_force_N": 4000.0}
"""An intake camshaft for the built-in example's four cylinders (its dimensions assumed, as the phaser example's)."""


def _document(mode="fired", camshaft=True, **phaser):
    doc = spec_document(example_spec())
    for v in doc["valves"].values():
        v["dynamics"] = None                    # the phase changes no dynamics: the test needs none
    doc["engine"]["rod_length_mm"] = 135.0
    doc["valves"]["intake"]["piston_gap_tdc_mm"] = 8.0
    doc["valves"]["intake"]["phaser"] = {**PHASER, **phaser}
    doc["breathing"] = {"mode": mode, "wall_temperature_C": 150.0, "cycle_tolerance": 1e-5,
                        "conditions": [{"speed_rpm": 2500.0, "intake_pressure_kPa": 60.0, "intake_temperature_C": 25.0,
                                        "exhaust_pressure_kPa": 103.0}],
                        "curve": {"speed_range_rpm": [2000.0, 6000.0], "points": 2, "intake_pressure_kPa": 100.0,
                                  "intake_temperature_C": 25.0, "exhaust_pressure_kPa": 105.0}}
    if camshaft:
        doc["camshaft"] = dict(CAMSHAFT)
    return doc


@pytest.fixture(scope="module")
def fired():
    return run(validate(_document()))


def test_the_events_move_by_the_phase_exactly(fired):
    """The phased effective areas at the crank angle theta are the designed ones at theta + advance (to round-off):
    at an advance of k quarter degrees (the areas' grid) the area grid is the unphased one rolled by k nodes, so the
    valve leaves and meets its seat k nodes earlier; the record's events are the design's less the advance."""
    flow = fired.breathing.engines[0].intake                # a designed lift: the same at every condition
    for k in (-40, 1, 37, 160):                       # -10, 0.25, 9.25, 40 crank deg
        advance = np.radians(0.25 * k)
        phased = phased_flow(flow, advance).areas(GRID)[0]
        assert np.allclose(phased, np.roll(flow.forward, -k), rtol=0, atol=1e-12 * flow.forward.max())
        lifted = [a > 1e-9 * flow.forward.max() for a in (flow.forward, phased)]      # open, beyond round-off
        open_, moved = (np.flatnonzero(a & ~np.roll(a, 1)) for a in lifted)
        assert ((open_ - moved) % GRID.size == k % GRID.size).all()
    cam = fired.valves["intake"].cam
    for e in fired.phasers["intake"].figures.events:
        assert e.opens == pytest.approx(cam.valve_opens - e.advance, abs=1e-15)
        assert e.closes == pytest.approx(cam.valve_closes - e.advance, abs=1e-15)
    assert [np.degrees(e.advance) for e in fired.phasers["intake"].figures.events] == pytest.approx([-10, 0, 40])


def test_the_map_holds_phase_zero_once():
    """[-60, 5] crank deg at 5 deg: np.linspace's 13th point is -2.2e-16 rad, which was a second phase beside 0 (a
    map column of its own, the best phase's gain referred to either); the grid's phases are at most the step apart."""
    phases = advances(SimpleNamespace(advance_range=(np.radians(-60.0), np.radians(5.0)), step=np.radians(5.0)))
    assert np.degrees(phases) == pytest.approx(np.arange(-60.0, 5.1, 5.0), abs=1e-12)
    assert np.count_nonzero(np.abs(phases) < 1e-9) == 1 and 0.0 in phases


def test_phase_zero_is_the_breathing_chapter(fired):
    """The map's points at phase 0 are the breathing chapter's results, exactly (the same model, the same areas): the
    map takes them from the chapter, and the phased engines at an advance of 0, breathed again here, give them too."""
    f = fired.phasers["intake"].figures
    zero = [p for p in f.map if p.advance == 0.0]
    chapter = [r.figures for r in (*fired.breathing.conditions, *fired.breathing.curve)]
    assert len(zero) == len(chapter) == 3
    b = breathing_view(fired.spec)
    given, swept = breathing_conditions(b)
    engines = [replace(e, intake=phased_flow(e.intake, 0.0)) for e in fired.breathing.engines]
    again = [r.figures for part in breathe_conditions(engines, b, given, swept) for r in part]
    assert [(r.speed, r.volumetric_efficiency, r.torque) for r in again] == [
        (r.speed, r.volumetric_efficiency, r.torque) for r in chapter]
    for p, r in zip(zero, chapter, strict=True):
        assert (p.speed, p.volumetric_efficiency, p.residual_gas_fraction, p.pmep, p.torque) == (
            r.speed, r.volumetric_efficiency, r.residual_gas_fraction, r.pmep, r.torque)


def test_the_best_phase_is_the_argmax_of_a_fine_scan(fired):
    """At 2000 rpm (the curve's first speed) an independent scan of the indicated torque over the whole range, every
    crank degree and then every 0.1 deg about its best, with the phased areas made here and the breathing's own
    `breathe`: its best phase is the search's within the search's tolerance and the scan's step."""
    engine, b = fired.breathing.engines[1], fired.spec.breathing      # the engine of best[1]'s condition
    best = fired.phasers["intake"].figures.best[1]
    assert best.speed == pytest.approx(np.pi * 2000.0 / 30.0)
    condition = breathing_conditions(breathing_view(fired.spec))[1][0]

    def torque(advance_deg):
        a = np.radians(advance_deg)
        phased = replace(engine, intake=ValveFlow(engine.intake.angle - a, engine.intake.forward, engine.intake.reverse))
        return breathe(phased, condition, b.cycle_tolerance, b.max_cycles).figures.torque

    coarse = np.arange(-10.0, 40.0 + 0.5, 1.0)
    top = coarse[int(np.argmax([torque(a) for a in coarse]))]
    fine = np.arange(max(top - 1.0, -10.0), min(top + 1.0, 40.0) + 1e-9, 0.1)
    scan = fine[int(np.argmax([torque(a) for a in fine]))]
    assert np.degrees(best.advance) == pytest.approx(scan, abs=0.5 + 0.1)
    assert best.torque >= torque(scan) * (1.0 - 1e-4)


def test_the_phaser_holds_the_camshaft_drive_torque(fired):
    """With [camshaft] carrying the intake the phaser holds the extrema and mean of the camshaft chapter's drive
    torque over a revolution; without it, the same torque of the intake lobes on every cylinder (the same lobes)."""
    f, torque = fired.phasers["intake"].figures, fired.camshaft.torque
    assert (f.torque_peak, f.torque_lowest) == (torque.max(), torque.min())
    assert f.torque_mean == pytest.approx(torque.mean(), rel=1e-12, abs=1e-12 * np.abs(torque).max())
    alone = run(validate(_document("motored", camshaft=False, advance_range_crank_deg=[0.0, 20.0]))).phasers["intake"]
    assert (alone.figures.torque_peak, alone.figures.torque_lowest) == pytest.approx((torque.max(), torque.min()),
                                                                                     rel=1e-12)
    assert alone.figures.objective == "volumetric_efficiency"
    assert all(p.torque is None for p in alone.figures.map)


def test_the_gap_at_the_range_ends_by_hand(fired):
    """The smallest valve-to-piston gap at 40 crank deg of advance, by a scan of the open event with the exact
    slider-crank displacement typed here: s = r (1 - cos phi) + L (1 - sqrt(1 - (r/L)^2 sin^2 phi)), D = s + y0 - y
    (Shang Hanji (1988), eqs. 2.13-2.14), the lift y at phi + advance."""
    v = fired.valves["intake"]
    e = fired.phasers["intake"].figures.events[-1]
    r, rod = 0.077142857 / 2.0, 0.135
    phi = np.linspace(v.cam.valve_opens, v.cam.valve_closes, 200001) - e.advance
    s = r * (1 - np.cos(phi)) + rod * (1 - np.sqrt(1 - (r / rod * np.sin(phi)) ** 2))
    gap = s + 0.008 - v.cam.valve_lift((phi + e.advance - v.cam.nose) / 2.0)
    assert e.min_gap == pytest.approx(gap.min(), abs=1e-7)
    assert e.min_gap < fired.phasers["intake"].figures.events[0].min_gap      # advanced: nearer the rising piston
    checks = [c for c in fired.checks if c.code == "phaser.piston_clearance"]
    assert [dict(c.params)["advance"] for c in checks] == ["-10", "40"]


def test_the_spring_holds_the_largest_gas_load_over_the_map(fired):
    """The gas force on the shut intake valve over the map is at least the breathing chapter's (phase 0, whose load
    the spring was designed for; here 0: without a runner the port stays below the cylinder while the valve is
    shut) and is checked against the spring's preload."""
    f, v = fired.phasers["intake"].figures, fired.valves["intake"]
    at_zero = gas_opening_load(fired.breathing, "intake", 0.038)[0]
    assert f.gas_load >= at_zero
    (c,) = [c for c in fired.checks if c.code == "phaser.gas_load"]
    assert (c.value, c.high) == (f.gas_load, v.drive.spring.preload)
    # its note is a code of the catalogue with its numbers: the English as the record says it, the Russian with the
    # decimal comma of every Russian number (locale.number_text) but the source's equation number; the
    # English numbers translated by skeleton had points
    assert c.note.startswith("the largest over the map at an advance of ") and c.note == note_text(c.note_parts)
    ru = note_text(c.note_parts, "ru")
    assert ru.startswith("наибольшая по карте, при опережении ") and re.search(r"\d\.\d", ru.partition("ф. (")[0]) is None, ru


def test_without_breathing_the_events_gap_and_torque_alone():
    """Without [breathing]: the events, the gap at the range's ends and the held torque; no map, no best phase, no
    gas load; results.json keeps to its schema."""
    doc = _document(camshaft=False)
    del doc["breathing"]
    results = run(validate(doc))
    record = results.to_dict()["phasers"]["intake"]
    assert [e["advance_crank_deg"] for e in record["events"]] == [-10.0, 0.0, 40.0]
    assert record["map"] == [] and record["best"] == [] and "objective" not in record and "gas_load_max_N" not in record
    jsonschema.validate(json.loads(results_json(results)), results_schema())


@pytest.mark.parametrize("change, message", [
    ({"advance_range_crank_deg": [10.0, 40.0]},
     r"valves.intake.phaser: advance_range_crank_deg = \[10, 40\]: allowed low <= 0 <= high"),
    ({"advance_range_crank_deg": [0.0, 120.0]},
     r"valves.intake.phaser.advance_range_crank_deg.1 = 120.0: allowed \(-90, 90\] crank deg"),
    ({"step_crank_deg": 0.1}, r"valves.intake.phaser.step_crank_deg = 0.1: allowed \[0.5, 180\] crank deg"),
    ({"tolerance_crank_deg": 0.0}, r"valves.intake.phaser.tolerance_crank_deg = 0.0: allowed \[0.01, 5\] crank deg"),
])
def test_bad_phaser_keys_are_refused_naming_them(change, message):
    with pytest.raises(SpecError, match=message):
        validate(_document(**change))


def test_a_map_that_asks_too_much_work_is_refused_before_it_runs():
    """81 phases 1 deg apart at 3 conditions ask for more cell-steps than the breathing allows (about half a
    minute): refused naming the step, before a cycle of the map runs."""
    doc = _document(camshaft=False, advance_range_crank_deg=[-40.0, 40.0], step_crank_deg=1.0)
    with pytest.raises(SpecError, match=r"valves.intake.phaser.step_crank_deg = 1: 81 phases of 3 conditions and the "
                                        r"search of the best phase at each ask for .* cell-steps; allowed at most 1e\+08"):
        run(validate(doc))


def test_a_camshaft_with_a_phased_and_an_unphased_valve_is_refused():
    doc = _document()
    doc["camshaft"]["valves"] = ["intake", "exhaust"]
    with pytest.raises(SpecError, match=r"camshaft.valves = \['intake', 'exhaust'\]: a phaser turns the whole "
                                        r"camshaft.*phased: intake"):
        validate(doc)


def test_a_phase_at_which_the_valve_meets_the_piston_is_refused_naming_the_range():
    """A gap of 1.5 mm at TDC: the designed timing clears the piston, 40 crank deg of advance does not."""
    doc = _document(camshaft=False)
    doc["valves"]["intake"]["piston_gap_tdc_mm"] = 1.5
    del doc["breathing"]
    with pytest.raises(SpecError, match=r"valves.intake.phaser.advance_range_crank_deg: at an advance of 40 crank deg "
                                        r"the valve hits the piston"):
        run(validate(doc))


def test_an_exhaust_phaser_opens_against_the_cylinders_pressure_at_each_phase():
    """An exhaust phaser of -20...20 crank deg at full load, fired: at each end of the range and at 0 the cylinder's
    and the port's pressure where the valve leaves its seat equal those of the cycle breathed here with the exhaust
    areas moved by hand, A(theta + advance), read at the phased opening; the gas force on the 37 mm head is
    pi/4 d^2 (p_c - p_p) (eq. (7.1)) and is what the strength chapter's load takes; an earlier opening meets a higher
    pressure of the expansion."""
    doc = _document(camshaft=False)
    doc["valves"]["intake"]["phaser"] = None
    doc["valves"]["exhaust"]["phaser"] = {"advance_range_crank_deg": [-20.0, 20.0], "step_crank_deg": 20.0,
                                          "tolerance_crank_deg": 5.0}
    doc["breathing"]["curve"] = None
    doc["breathing"]["conditions"][0]["intake_pressure_kPa"] = 100.0
    spec = validate(doc)
    results = run(spec)
    rows = results.phasers["exhaust"].figures.opening
    b = breathing_view(spec)
    engine, condition = results.breathing.engines[0], breathing_conditions(b)[0][0]
    side, cycle = engine.exhaust, 4.0 * np.pi
    for o in rows:
        out = breathe(replace(engine, exhaust=ValveFlow(side.angle - o.advance, side.forward, side.reverse)),
                      condition, b.cycle_tolerance, b.max_cycles).columns
        at = np.mod(results.valves["exhaust"].cam.valve_opens - o.advance, cycle)
        p, port = (np.interp(at, out.angle, x, period=cycle) for x in (out.pressure, out.exhaust_port))
        assert (o.cylinder_pressure, o.port_pressure) == pytest.approx((p, port), rel=1e-9)
        assert o.gas_force == pytest.approx(np.pi / 4 * 0.037 ** 2 * (p - port), rel=1e-9)
    assert [o.advance for o in rows] == pytest.approx(np.radians([-20.0, 0.0, 20.0]))
    assert rows[0].cylinder_pressure < rows[1].cylinder_pressure < rows[2].cylinder_pressure
    stress = [c for c in results.checks if c.code == "phaser.opening_contact_stress"]
    assert len(stress) == 2 and all(c.passed for c in stress)
