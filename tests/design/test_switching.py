"""The switching stage (valvetrain.design.switching, issue 42) on examples/switching-finger.toml's intake valve: the
latched valve is the plain finger's (the same design without [switching]), the unlatched valve's lift is 0, the
lost-motion spring's quasi-static jump speed is sqrt(reserve) x the over-speed (the tightest line touches the
requirement), the sweep's jump lies just below it (the contact's compliance), the frequency, valve force and latch
stress by hand from the record's own inputs (results.json against its schema: tests/specification/test_schema.py,
every example)."""

from pathlib import Path

import numpy as np
import pytest

from valvetrain.design import run
from valvetrain.specification import SpecError, load_spec, spec_document, validate

EXAMPLE = Path(__file__).parents[2] / "examples" / "switching-finger.toml"


def _document():
    doc = spec_document(load_spec(EXAMPLE))
    del doc["valves"]["exhaust"]
    doc["valves"]["intake"]["lash_adjuster"] = None       # the lash adjuster's stage is not the switching's
    return doc


@pytest.fixture(scope="module")
def designs():
    doc = _document()
    switched = run(validate(doc))
    doc["valves"]["intake"]["switching"] = None
    return switched, run(validate(doc))


def test_latched_valve_is_the_fingers_and_unlatched_is_shut(designs):
    switched, plain = designs
    a, b = switched.valves["intake"], plain.valves["intake"]
    assert np.array_equal(a.cycle_lift, b.cycle_lift)
    assert a.summary == b.summary
    rec = switched.to_dict()["switching"]["intake"]
    assert rec["latched_valve_lift_mm"] == pytest.approx(9.0)       # the example's max_lift_mm
    assert rec["unlatched_valve_lift_mm"] == 0.0


def test_lost_motion_spring_jump_speeds(designs):
    rec = designs[0].to_dict()["switching"]["intake"]
    # the line T_0 + k phi touches K J omega_os^2 (-phi'') somewhere: there omega_j^2 = K omega_os^2 exactly
    assert rec["jump_speed_quasi_static_rpm"] == pytest.approx(np.sqrt(rec["reserve"]) * rec["over_speed_rpm"],
                                                               rel=1e-6)
    # the elastic arm leaves a little earlier (its contact's compliance): within 5 %, above the over-speed
    assert 0.95 < rec["jump_speed_rpm"] / rec["jump_speed_quasi_static_rpm"] < 1.0
    assert rec["jump_speed_rpm"] > rec["over_speed_rpm"]
    speeds, force = np.array(rec["sweep_speeds_rpm"]), np.array(rec["arm_contact_force_min_N"])
    assert np.all(force[speeds > rec["jump_speed_rpm"] * 1.02] == 0.0) and np.all(force[speeds < 8000.0] > 0.0)


def test_record_by_hand(designs):
    rec = designs[0].to_dict()["switching"]["intake"]
    j, k = 3.6e-6, rec["spring_rate_Nm_per_rad"]               # inner_arm_inertia_kg_mm2 = 3.6
    assert rec["arm_frequency_Hz"] == pytest.approx(np.sqrt(k / j) / (2.0 * np.pi), rel=1e-9)
    # the camshaft turns at half the engine's speed: f / (n / 120)
    assert rec["arm_frequency_orders"] == pytest.approx(rec["arm_frequency_Hz"] / (rec["over_speed_rpm"] / 120.0))
    # Wahl (1944): N = E d^4 / (64 D k), d = 2.5 mm, D = 12 mm, E = 210 GPa
    assert rec["spring_active_coils"] == pytest.approx(2.1e11 * 2.5e-3 ** 4 / (64.0 * 12e-3 * k), rel=1e-9)
    # the latch: P = N L_i / L_l = N x 13.5 / 30, p0 = sqrt(P E* / (pi R b)), R = 2 mm, b = 4 mm (Johnson (1985))
    p = rec["cam_force_max_N"] * 13.5 / 30.0
    assert rec["latch_force_max_N"] == pytest.approx(p)
    p0 = np.sqrt(p * 2.1e11 / (2.0 * (1.0 - 0.09)) / (np.pi * 2e-3 * 4e-3))
    assert rec["latch_stress_max_MPa"] == pytest.approx(p0 / 1e6, rel=6e-4)
    # the force left at the shut valve: N L_r / G_0; G_0 = L_b cos chi_0 of the finger at rest
    finger = designs[0].valves["intake"].follower_model
    g0 = finger.valve_arm(np.array(finger.base_angle(designs[0].valves["intake"].heel_radius)))
    assert rec["valve_force_unlatched_N"] == pytest.approx(rec["arm_contact_force_max_N"] * 0.0225 / g0)
    codes = {c.code: c.passed for c in designs[0].checks if c.code.startswith("switching.")}
    assert codes == {"switching.jump_speed": True, "switching.valve_held": True, "switching.spring_stress": True,
                     "switching.latch_stress": True, "switching.latch_time": True}


def test_the_spring_source_names_its_range(designs):
    """The record's source of the lost-motion spring: the valve spring's force ratio 1.6 ... 3.2 as every range is
    written (fuzz6: '1.6....3.2', four dots; fails before)."""
    source = designs[0].to_dict()["switching"]["intake"]["spring_source"]
    assert "the force ratio's range 1.6...3.2 the valve spring's" in source and "...." not in source


def test_a_too_weak_spring_wire_fails_its_check():
    doc = _document()
    doc["valves"]["intake"]["switching"]["spring_wire_diameter_mm"] = 1.6
    doc["valves"]["intake"]["switching"]["spring_mean_diameter_mm"] = 10.0
    stress = [c for c in run(validate(doc)).checks if c.code == "switching.spring_stress"][0]
    assert not stress.passed and stress.severity == "failure"


def test_deactivated_cylinders_loss(designs):
    """The trapped charge (100 kPa, 60 degC at BDC, epsilon = 10.5, walls at 120 degC) loses work to its walls: a
    positive loss per cycle, twice a revolution's; its peak below the adiabatic p epsilon^1.4 (the walls cool it)."""
    rec = designs[0].to_dict()["switching"]["intake"]
    assert rec["deactivated_loss_kPa"] > 0.0
    swept = np.pi * 0.086 ** 3 / 4.0
    assert rec["deactivated_work_J"] == pytest.approx(-rec["deactivated_loss_kPa"] * 1e3 * swept)
    assert rec["deactivated_peak_pressure_kPa"] < 100.0 * 10.5 ** 1.4


def test_a_sweep_too_large_is_refused_naming_the_stiffness():
    """A contact of 1e7 N/mm on an arm of 0.01 kg mm^2 at 200 mm (0.25 mg at the roller) rings at 2e8 rad/s: its 200
    speeds would take about 1e10 integrator steps x elements, hours; refused before it runs."""
    doc = _document()
    doc["valves"]["intake"]["switching"].update(contact_stiffness_N_per_mm=1e7, inner_arm_inertia_kg_mm2=0.01,
                                                inner_arm_mm=200.0, speeds=200)
    with pytest.raises(SpecError, match=r"valves\.intake\.switching\.contact_stiffness_N_per_mm = 1e\+07: with "
                                        r"speeds = 200 the unlatched arm's sweep is about"):
        run(validate(doc))


def test_the_latchs_switching_window_by_hand(designs):
    """The window is the camshaft's turn outside the lobe's event: the intake's 8 + 180 + 50 = 238 crank deg is
    119 camshaft deg, so 241 deg, at 6500 / 2 rpm (19500 camshaft deg/s) 12.359 ms; the pin's two travels (its
    physics: tests/test_switching.py) over it."""
    latch = designs[0].to_dict()["switching"]["intake"]["latch_switching"]
    assert latch["switching_window_cam_deg"] == pytest.approx(241.0)
    assert latch["switching_window_ms"] == pytest.approx(241.0 / 19500.0 * 1e3)
    assert latch["latch_time_share"] == pytest.approx(max(latch["latch_engage_time_ms"], latch["latch_return_time_ms"])
                                                      / latch["switching_window_ms"])
    check = [c for c in designs[0].checks if c.code == "switching.latch_time"][0]
    assert check.passed and check.value == pytest.approx(latch["latch_time_share"])


def test_a_latch_too_slow_for_its_window_fails_its_check():
    """A 0.1 mm passage lets a hundredth of the oil through: the pin takes about 0.2 s, longer than the window."""
    doc = _document()
    doc["valves"]["intake"]["switching"]["oil_passage_diameter_mm"] = 0.1
    latch = [c for c in run(validate(doc)).checks if c.code == "switching.latch_time"][0]
    assert not latch.passed and latch.severity == "failure" and latch.value > 10.0
