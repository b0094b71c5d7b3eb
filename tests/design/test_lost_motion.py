"""The lost-motion stage (valvetrain.design.lost_motion, issue 42) on examples/lost-motion-intake.toml: the early
closings against the full lift, each run the library's simulation with the solenoid valve at the timing, the record
in results.json against its schema, bad input refused naming the key, the value and the range."""

import json
import math
from dataclasses import replace

import jsonschema
import numpy as np
import pytest

from valvetrain.design import results_schema, run
from valvetrain.design.breathing import cylinder_pressure
from valvetrain.design.hydraulic_actuation import cycle_angle, gas_force, hydraulic_drive
from valvetrain.design.lost_motion import _sweep_checks, cam_angle, table_columns
from valvetrain.export import json_text
from valvetrain.hydraulic_actuation import simulate
from valvetrain.specification import SpecError, spec_document, validate
from valvetrain.specification.si import si

def test_the_earlier_the_solenoid_opens_the_earlier_and_lower_the_valve_closes(design):
    """Each timing closes the valve before the full lift (the solenoid valve shut) does, the earlier the earlier it
    opens, with no more lift than the full lift's; the brake lands each below the seating limit (0.5 m/s)."""
    lm = design.valves["intake"].lost_motion
    closes = [c.valve_closes for c in lm.closings]
    lifts = [c.valve_lift for c in lm.closings]
    assert len(closes) == 4 and np.all(np.diff(closes) > 0) and closes[-1] < lm.full_lift_closes
    assert closes[2] < math.pi                                      # at least three before BDC
    assert np.all(np.diff(lifts) >= 0) and max(lifts) <= lm.full_lift * (1 + 1e-12)
    assert all(0 < -c.seating_velocity < 0.5 for c in lm.closings)
    assert all(c.bypassed > 0 and not c.cavitation for c in lm.closings)


def test_each_timing_is_the_simulation_with_the_solenoid_opening_there(design, spec):
    """Independent of the stage's bookkeeping: the drive of the section's keys simulated with the solenoid valve
    opening at the camshaft angle of the timing's crank angle, (phi - phi_nose) / 2, against the breathing's cylinder
    pressure on the valve head, gives the same closing; the full lift is the hydraulic chapter's own revolution (the
    solenoid valve shut)."""
    v = design.valves["intake"]
    lm, h = v.lost_motion, v.hydraulic
    view = si(spec.valves["intake"])
    drive = hydraulic_drive(view.hydraulic)
    drive = replace(drive, valve=replace(drive.valve, stop=h.stop))
    phi = view.hydraulic.lost_motion.solenoid_opens[1]
    theta = math.remainder((phi - v.cam.nose) / 2.0, 2.0 * math.pi)
    assert cam_angle(phi, v.cam.nose, 4) == pytest.approx(theta, abs=1e-12)
    cylinder = cylinder_pressure(design.breathing, h.speed, "intake")      # the breathing's cycle on the valve head
    force = gas_force(view, si(spec.gas), si(spec.engine), v.cam.nose, cylinder)
    r = simulate(v.cam.law, replace(drive, solenoid=replace(drive.solenoid, opens=theta)), h.speed / 2.0,
                 gas_force=force)
    angle, velocity, _ = r.seating()
    assert lm.closings[1].valve_closes == pytest.approx(float(cycle_angle(v.cam.nose, angle, 4)), abs=1e-12)
    assert lm.closings[1].seating_velocity == velocity
    assert lm.full is h.response and lm.full_lift == h.valve_lift
    table = table_columns(lm)
    assert set(table) >= {"cam_deg", "crank_deg", "valve_lift_mm_90", "brake_pressure_MPa_90"}


def test_the_speed_sweep_is_the_simulation_at_each_speed_and_closes_in_about_the_same_time(design, spec):
    """With sweep = true each timing runs at the hydraulic chapter's 12 swept speeds: one point against the drive
    simulated here at that speed with the solenoid opening at the timing's camshaft angle (as above); and the physics
    of a spring-closed valve: it closes a nearly constant time after the solenoid valve opens, (closes - opens) / (6 n)
    within 10 % of its mean over the speeds at every timing (measured: 2.9-3.3 ms), and lands on the brake at nearly
    the same velocity, 0.2-0.35 m/s (two points read 0.02-0.03 m/s before DriveResult.seating took a sample within
    SEATED of the seat as on it: the impact step's round-off above the seat)."""
    v = design.valves["intake"]
    lm, h = v.lost_motion, v.hydraulic
    assert len(lm.sweep) == 4 * 12 and [s.speed for s in lm.sweep[:12]] == pytest.approx(
        np.linspace(0.5, 1.1, 12) * 5500.0 * math.pi / 30.0)
    view = si(spec.valves["intake"])
    drive = hydraulic_drive(view.hydraulic)
    drive = replace(drive, valve=replace(drive.valve, stop=h.stop))
    point = lm.sweep[12 + 7]                                  # the second timing (90 crank deg) at the 8th speed
    theta = math.remainder((point.closing.solenoid_opens - v.cam.nose) / 2.0, 2.0 * math.pi)
    force = gas_force(view, si(spec.gas), si(spec.engine), v.cam.nose,
                      cylinder_pressure(design.breathing, h.speed, "intake"))
    r = simulate(v.cam.law, replace(drive, solenoid=replace(drive.solenoid, opens=theta)), point.speed / 2.0,
                 gas_force=force)
    angle, velocity, _ = r.seating()
    assert point.closing.valve_closes == pytest.approx(float(cycle_angle(v.cam.nose, angle, 4)), abs=1e-12)
    assert point.closing.seating_velocity == velocity
    for k in range(4):
        rows = lm.sweep[12 * k:12 * (k + 1)]
        times = np.array([(s.closing.valve_closes - s.closing.solenoid_opens) / s.speed for s in rows])
        assert np.all(np.abs(times / times.mean() - 1.0) < 0.10)
        assert all(0.2 < -s.closing.seating_velocity < 0.35 and s.closing.residual_lift == 0.0 for s in rows)


def test_a_sweep_wholly_above_the_over_speed_says_so(design):
    """The sweep's lowest speed over the over-speed is a check: the example's sweep from 50 % of the rated speed,
    over-speed 1.1 x rated (the default), gives 0.5 / 1.1; the same rows graded against an over-speed below all of
    them grade no timing and the check fails (before it, such a sweep checked nothing and said nothing: fuzz)."""
    found = [c for c in design.checks if c.code == "lost_motion.sweep_range"]
    assert len(found) == 1 and found[0].value == pytest.approx(0.5 / 1.1, rel=1e-12) and found[0].passed
    sweep = design.valves["intake"].lost_motion.sweep
    top = 0.9 * min(s.speed for s in sweep)
    checks = _sweep_checks(sweep, top)
    assert [c.code for c in checks] == ["lost_motion.sweep_range"] and not checks[0].passed
    assert checks[0].value == pytest.approx(1.0 / 0.9, rel=1e-12)


def test_the_record_follows_the_schema(design):
    record = json.loads(json_text(design.valves["intake"].summary))["lost_motion"]
    assert [c["solenoid_opens_crank_deg"] for c in record["closings"]] == [60.0, 90.0, 120.0, 150.0]
    jsonschema.validate(record, results_schema()["properties"]["valves"]["additionalProperties"]["properties"]
                        ["lost_motion"])


@pytest.mark.parametrize("change, message", [
    ({"solenoid_opens_crank_deg": [60.0, 300.0]},
     r"valves.intake.hydraulic.lost_motion.solenoid_opens_crank_deg = 300: the solenoid valve opens at 300 crank deg, "
     r"outside the cam's lift: allowed within \(-?\d.*, \d.*\) crank deg"),
    ({"solenoid_opens_crank_deg": [60.0, 720.0]},
     r"valves.intake.hydraulic.lost_motion.solenoid_opens_crank_deg.1 = 720.0: allowed \[0, 720\) crank deg"),
    ({"solenoid_opens_crank_deg": []}, r"valves.intake.hydraulic.lost_motion.solenoid_opens_crank_deg"),
    ({"solenoid_area_mm2": 0.0}, r"valves.intake.hydraulic.lost_motion.solenoid_area_mm2 = 0.0: allowed \[0.01, 1000\]"),
    ({"brake_end_area_mm2": 30.0}, r"brake_end_area_mm2 = 30: allowed at most brake_open_area_mm2 = 20"),
    ({"accumulator_pressure_MPa": 3.0}, r"lost_motion.accumulator_pressure_MPa = 3: allowed above vapour_pressure_MPa "
                                        r"= 0.002 and at most back_pressure_MPa \+ F_0 / A_a = 2.049 MPa"),
])
def test_bad_lost_motion_keys_are_refused_naming_them(spec, change, message):
    doc = spec_document(spec)
    doc["valves"]["intake"]["hydraulic"]["lost_motion"].update(change)
    with pytest.raises(SpecError, match=message):
        run(validate(doc))

