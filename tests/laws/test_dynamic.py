"""The multi-term dynamic cam (laws/dynamic.py; Shang Hanji (1988), section 4.1; Stoddart (1953)): the cam that gives
the design valve motion through an elastic drive."""

import numpy as np
import pytest

from valvetrain.checks import failed
from valvetrain.laws.dynamic import DynamicLaw

DEG = np.pi / 180


def _dynamic():
    """Shang Hanji (1988), section 4.1, and Stoddart (1953), worked example (spec sections 2 and 8): c = 15000 N/mm, F0
    = 400 N, k = 1.5, x0 = 0.30 mm, design seating velocity 0.3 m/s at 3000 rpm (camshaft); K = 67.5 N/mm and a
    constant-acceleration ramp (f = 0.5) reproduce the spec's ramp of 26.03 deg at 11.16 um/deg."""
    omega = 3000 * np.pi / 30
    return DynamicLaw(8e-3, np.radians(55), [2, 10, 18, 26, 34], 0.3 / omega, 15e6, 0.25, 67.5e3, 400.0, omega,
                      1.5, 0.3e-3, "constant_acceleration", 0.5), omega


def test_dynamic_cam_ramp():
    law, _ = _dynamic()
    # ramp height (x0 + F0/c)/k = (0.30 + 400/15000)/1.5 = 0.21778 mm (spec section 2, worked example)
    assert law.ramp_height * 1e3 == pytest.approx(0.21778, abs=1e-5)
    assert law.ramp.end_velocity * 1e6 * DEG == pytest.approx(11.16, abs=0.01)
    assert np.degrees(law.ramp_angle) == pytest.approx(26.03, abs=0.02)
    j = law.start + law.ramp_angle
    d = law.derivatives(np.array([j - 1e-12, j + 1e-12]))
    assert np.allclose(d[:3, 0], d[:3, 1], rtol=1e-6, atol=1e-9)


def test_dynamic_cam_needs_a_stiff_enough_drive():
    """k h = x0 + y + (M omega^2 y'' + K y + F0)/c (Stoddart (1953); spec section 8): the spec's drive gives a cam that
    rises to the nose; with c 100 times softer the negative y'' near the nose makes the cam dip (a warning); with c 10^4
    times softer the nose falls below the ramp's end (no cam: an error naming the remedy)."""
    law, omega = _dynamic()
    assert law.fall_before_nose() == 0.0 and failed(law.checks()) == []
    args = (8e-3, np.radians(55), [2, 10, 18, 26, 34], 0.3 / omega)
    soft = DynamicLaw(*args, 15e4, 0.25, 67.5e3, 400.0, omega, 1.5, 0.3e-3)
    # independent: the lift along a fine grid from the ramp's end to the nose, its largest drop below a running maximum
    h = soft.lift(np.linspace(soft.start + soft.ramp_angle, 0.0, 20001))
    drop = np.max(np.maximum.accumulate(h) - h)
    assert drop > 1e-5 and soft.fall_before_nose() == pytest.approx(drop, rel=1e-3)
    assert failed(soft.checks())[0].quantity == "dynamic cam: fall of the lift before the nose"
    with pytest.raises(ValueError, match="would not rise above its ramp"):
        DynamicLaw(*args, 1.5e3, 0.25, 67.5e3, 400.0, omega, 1.5, 0.3e-3)


def test_dynamic_cam_gives_the_design_valve_motion():
    """Simulated one-mass elastic train, M y'' = c(k h - x0 - y) - (F0 + K y), integrated with scipy's LSODA from the
    valve's opening at the design speed: the valve follows the design polynomial (Stoddart (1953); spec section 8)."""
    from scipy.integrate import solve_ivp

    law, omega = _dynamic()
    t0 = law.start + law.ramp_angle

    def rhs(t, s):
        theta = t0 + omega * t
        u = law.ratio * float(law.lift(np.array([theta]))[0]) - law.x0
        return [s[1], (law.c * (u - s[0]) - (law.F0 + law.K * s[0])) / law.m]

    t_end = 2 * law.main_half_angle / omega
    sol = solve_ivp(rhs, (0, t_end), [0.0, law.v_y * omega], method="LSODA", rtol=1e-11, atol=1e-13,
                    dense_output=True, max_step=t_end / 2000)
    t = np.linspace(0, t_end, 201)
    design = law.valve_motion(t0 + omega * t)[0]
    assert np.abs(sol.sol(t)[0] - design).max() < 1e-7  # 0.1 um on 8 mm
