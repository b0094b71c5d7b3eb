"""Two-step lift of the switching finger (valvetrain.design.two_step, issue 42) on examples/two-step-finger.toml's
intake against independent references: the low lobe's law built here from its events (a polydyne of its own half
event and lift), its time-area integrated by hand, the arm's lost motion and the valve's jump speed on the low lobe
through the finger built by hand (tests/finger_linkage.py: rotation matrices and brentq) with derivatives by finite
differences, and the unlatched breathing against the physics breathed here with areas made from that lift."""

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from finger_linkage import hand_finger
from valvetrain.design import breathing_view, run
from valvetrain.laws.polydyne import PolydyneLaw
from valvetrain.specification import SpecError, load_spec, spec_document, validate

EXAMPLE = Path(__file__).parents[2] / "examples" / "two-step-finger.toml"

LOW = PolydyneLaw(main_half_angle=np.radians((0.0 + 180.0 - 10.0) / 4.0), lift=3e-3, p=8)
"""The low lobe by hand: opens 0, closes -10 crank deg (10 before BDC), 3 mm, the cam section's p = 8: its event
170 crank deg = 85 camshaft deg, half of it each flank; its nose at (180 - 10 - 0) / 2 = 85 crank deg."""

NOSES = (np.radians((180.0 + 50.0 - 8.0) / 2.0), np.radians(85.0))
"""The main lobe's nose (opens 8 before TDC, closes 50 after BDC) and the low lobe's [crank rad]."""


@pytest.fixture(scope="module")
def spec():
    return load_spec(EXAMPLE)


@pytest.fixture(scope="module")
def design(spec):
    return run(spec)


def _doc(**low):
    doc = spec_document(load_spec(EXAMPLE))
    doc["breathing"] = None
    doc["valves"]["intake"]["switching"]["low_lobe"].update(low)
    return doc


def test_events_and_time_area_of_both_modes_by_hand(design):
    rec = design.to_dict()["switching"]["intake"]
    modes = rec["two_step"]
    assert rec["unlatched_valve_lift_mm"] == pytest.approx(3.0) and rec["latched_valve_lift_mm"] == pytest.approx(9.0)
    assert (modes["valve_opens_latched_crank_deg"], modes["valve_closes_latched_crank_deg"]) == pytest.approx((-8, 230))
    assert (modes["valve_opens_unlatched_crank_deg"], modes["valve_closes_unlatched_crank_deg"]) == pytest.approx(
        (0.0, 170.0))
    # time-area: the curtain area f = pi y (d cos a + y sin a cos^2 a) (work 1, eq. (1.3)), d = 30 mm, a = 45 deg, over
    # the low lobe's opening by the trapezoidal rule in time, the camshaft at 6500 / 2 rpm
    theta = np.linspace(-LOW.main_half_angle, LOW.main_half_angle, 40001)
    y = LOW.derivatives(theta)[0]
    a, d = np.radians(45.0), 0.030
    f = np.pi * y * (d * np.cos(a) + y * np.sin(a) * np.cos(a) ** 2)
    omega = 6500.0 * np.pi / 60.0
    assert modes["time_area_unlatched_mm2_s"] == pytest.approx(np.trapezoid(f, theta / omega) * 1e6, rel=1e-6)
    assert modes["time_area_latched_mm2_s"] == pytest.approx(
        design.to_dict()["valves"]["intake"]["flow"]["time_area_open_mm2_s"])


def test_lost_motion_and_the_valves_jump_speed_through_the_hand_built_finger(design):
    """The arm turns in the body by (u - u_b) / L_i, u and u_b the roller's travels L_r (psi - psi_0) on the main and
    the low lobe, psi from the valve lift by the hand-built linkage; the valve leaves the low lobe where
    P_0 + C h - (T_0 + k phi) / L_i L_r / G(psi) = m_v (-h'') omega^2, h'' and G = dv/dpsi by finite differences."""
    v = design.valves["intake"]
    rec = design.to_dict()["switching"]["intake"]
    hand = hand_finger(v.cam)
    arm, inner = v.follower_model.roller_arm, 13.5e-3
    step = 5e-4
    theta = np.arange(-1.05, 1.05, step)            # camshaft rad from the main lobe's nose, over its event
    low = theta + (NOSES[0] - NOSES[1]) / 2.0
    h = LOW.derivatives(low)[0]
    psi = np.array([hand.angle(x) for x in v.law.derivatives(theta)[0]])
    psi_b = np.array([hand.angle(x) for x in h])
    phi = arm * (psi - psi_b) / inner
    assert np.degrees(phi.max()) == pytest.approx(rec["arm_swing_deg"], rel=1e-5)
    # the valve on the low lobe
    torque = rec["spring_preload_Nm"] + rec["spring_rate_Nm_per_rad"] * phi
    g = (np.array([(hand.pad(p + 1e-7) - hand.pad(p - 1e-7)) @ hand.a for p in psi_b]) / 2e-7)
    load = torque / inner * arm / g
    spring = v.drive.spring
    d2h = np.gradient(np.gradient(h, step), step)
    down = d2h < -1e-9
    omega2 = (spring.preload + spring.rate * h[down] - load[down]) / (v.drive.masses.at_valve * -d2h[down])
    assert np.sqrt(omega2.min()) * 60.0 / np.pi == pytest.approx(rec["two_step"]["valve_jump_speed_unlatched_rpm"],
                                                                 rel=1e-3)
    # the rigid arm's: the spring's line touches K J omega_os^2 (-u'' / L_i) somewhere, so omega_j = sqrt(K) omega_os
    assert rec["jump_speed_quasi_static_rpm"] == pytest.approx(np.sqrt(rec["reserve"]) * rec["over_speed_rpm"],
                                                               rel=1e-6)
    assert "jump_speed_rpm" not in rec and rec["sweep_speeds_rpm"] == []


def test_unlatched_breathing_against_the_physics_with_the_low_lift(design, spec):
    """The breathing chapter's engine with the intake side's effective areas made here from the low lobe's lift (two
    valves, default discharge) breathes to the unlatched row; the latched row is the chapter's; the early closing
    traps less air, no more than the plenum's ideal gas in the cylinder at the closing (hand calculation)."""
    from valvetrain.breathing import ValveFlow, breathe
    from valvetrain.breathing.valves import default_areas
    from valvetrain.design.breathing import GRID, breathing_conditions
    rows = design.switching["intake"].figures.two_step.breathing
    latched, unlatched = rows
    assert (latched.mode, unlatched.mode) == ("latched", "unlatched")
    chapter = design.breathing.conditions[0].figures
    assert latched.trapped_mass == chapter.trapped_mass and latched.imep == chapter.imep
    b = breathing_view(spec)
    theta = np.mod((GRID - NOSES[1]) / 2.0 + np.pi, 2.0 * np.pi) - np.pi
    area = 2 * default_areas(LOW.derivatives(theta)[0], 0.030, np.radians(45.0))
    engine = design.breathing.engines[0]
    out = breathe(replace(engine, intake=ValveFlow(GRID, area, area)), breathing_conditions(b)[0][0],
                  b.cycle_tolerance, b.max_cycles)
    assert unlatched.trapped_mass == pytest.approx(out.figures.trapped_mass, rel=1e-9)
    assert unlatched.trapped_mass < latched.trapped_mass and unlatched.converged
    bore, stroke, rod, ratio, closes = 0.086, 0.086, 0.145, 10.5, np.radians(170.0)
    r = stroke / 2
    x = r * (1 - np.cos(closes)) + rod - np.sqrt(rod ** 2 - (r * np.sin(closes)) ** 2)
    assert unlatched.trapped_mass < 100e3 * np.pi * bore ** 2 / 4 * (stroke / (ratio - 1) + x) / (287.05 * 303.15)


def test_a_low_lobe_above_the_main_one_is_refused():
    """Opening 20 deg before TDC, before the main lobe (8 deg), the low lobe lifts the roller where the main one
    does not."""
    with pytest.raises(SpecError, match=r"valves\.intake\.switching\.low_lobe: the second lobe lifts the roller .* "
                                        r"above the main lobe"):
        run(validate(_doc(opens_deg=20.0)))


@pytest.mark.parametrize("change, words", [
    ({"low_lobe": {"max_lift_mm": 9.0, "opens_deg": 0.0, "closes_deg": -10.0}},
     "switching.low_lobe.max_lift_mm = 9: allowed below the valve's max_lift_mm = 9"),
    ({"low_lobe": None}, "mode = 'two_step': needs a low_lobe section"),
    ({"mode": "deactivation"}, "mode = 'deactivation': allowed a low_lobe section only with mode = 'two_step'"),
    ({"compression_ratio": 10.0, "trapped_pressure_kPa": 100.0, "trapped_temperature_C": 60.0,
      "wall_temperature_C": 120.0}, "given with mode = 'two_step': allowed only with mode = 'deactivation'"),
    ({"low_lobe": {"max_lift_mm": 3.0, "opens_deg": -100.0, "closes_deg": -90.0}},
     "opens_deg + 180 + closes_deg > 0"),
])
def test_bad_two_step_input_is_refused_naming_the_key(change, words):
    doc = _doc()
    doc["valves"]["intake"]["switching"].update(change)
    with pytest.raises(SpecError, match="switching") as err:
        validate(doc)
    assert words in str(err.value)
