"""The hydraulic valve drive (valvetrain.hydraulic_actuation.drive; Shang Hanji (1988), ch. 7): the drive against its
rigid, incompressible limit, the volume (mass) balance of the chambers and the pipe, cavitation, the relief valve, the
speed sweep, the gas force and the stop (the pipe alone: tests/hydraulic_actuation/test_moc.py)."""

import math
from dataclasses import replace

import numpy as np
import pytest
from scipy.optimize import brentq

from valvetrain.hydraulic_actuation import Actuator, Fluid, HydraulicDrive, Pipe, Pump, Valve, simulate, speed_sweep
from valvetrain.laws import KurzLaw

OMEGA = 2 * math.pi * 300 / 60
"""Camshaft speed of the cases [rad/s] (600 rpm crankshaft, four-stroke)."""


@pytest.fixture(scope="module")
def law():
    """A Kurz law of 6.25 mm lift as the plunger lift (any lift law will do)."""
    return KurzLaw(6.25e-3, 0.25e-3, 0.02e-3 * 180 / np.pi, *np.deg2rad([27.0, 6.0, 38.0]), 0.625)


def drive(bulk_modulus=1.5e9, length=2.0, reaches=20, friction=0.03, leakage=1e-13, fill=1e-9, spring=2e5,
          preload=1500.0, relief=math.inf, wall=210e9):
    """An assumed drive: 40 mm plunger, 20 mm steel pipe (3 mm wall), 50 mm actuator, 5 kg valve."""
    pipe = Pipe(length, 0.02, 0.003, wall, friction, reaches)
    pump = Pump(math.pi * 0.04**2 / 4, 2e-4, leakage, 0.3e6, fill, relief, 1e-9 if relief < math.inf else 0.0)
    return HydraulicDrive(Fluid(bulk_modulus=bulk_modulus), pipe, pump, Actuator(math.pi * 0.05**2 / 4, 2e-4, leakage),
                          Valve(5.0, spring, preload, 200.0))


def test_rigid_incompressible_limit_follows_the_cam_scaled_by_the_area_ratio(law):
    """Analytic limit: a stiff liquid (K = 1e13 Pa) in a short pipe moves the valve as the plunger times
    A_p / A_a, opening and closing with the cam."""
    d = drive(bulk_modulus=1e13, length=0.05, reaches=2, leakage=0.0, fill=0.0, wall=math.inf)
    r = simulate(law, d, OMEGA, start=law.start - 0.05, span=law.end - law.start + 0.1)
    assert d.area_ratio == pytest.approx(0.64)
    assert r.rigid_lift == pytest.approx(r.plunger_lift * 0.64)
    assert np.abs(r.valve_lift - r.rigid_lift).max() < 1e-4 * r.rigid_lift.max()
    assert abs(r.lift_loss) < 1e-4 * r.rigid_lift.max()
    assert np.abs(r.delays()).max() < 1e-4
    assert not r.cavitation.any()


def test_rigid_drive_seats_the_valve_at_the_cam_velocity(law):
    """Analytic limit: the stiff drive seats the valve with the rigid drive's velocity A_p / A_a omega dh/dtheta at
    the seating angle (to the O(dt) of the rigid seat's step), without a bounce."""
    d = drive(bulk_modulus=1e13, length=0.05, reaches=2, leakage=0.0, fill=0.0, wall=math.inf)
    angle, velocity, bounce = simulate(law, d, OMEGA).seating()
    rigid = 0.64 * OMEGA * law.derivatives(np.array([angle]))[1][0]
    assert rigid < 0 and velocity == pytest.approx(rigid, rel=1e-2) and bounce == 0.0


def test_compressible_drive_is_late_and_loses_lift(law):
    """The real drive: the liquid's compliance delays the opening and loses lift against the rigid drive."""
    r = simulate(law, drive(), OMEGA)
    opening, closing = r.delays()
    assert opening > 0 and closing < 0
    assert 0 < r.lift_loss < 0.2 * r.rigid_lift.max()
    assert r.max_pressure > d_open_pressure()
    assert r.max_pressure_angle == pytest.approx(r.angle[np.argmax(np.maximum(r.pump_pressure, r.actuator_pressure))])
    assert not r.cavitation.any()


def d_open_pressure():
    """Absolute pressure that lifts the assumed valve off its seat [Pa]: F_0 / A_a + p_back."""
    return 1500.0 / (math.pi * 0.05**2 / 4) + 0.1e6


@pytest.mark.parametrize("kwargs", [{}, {"friction": 0.0, "fill": 0.0}, {"leakage": 1e-12}])
def test_volume_balance_of_chambers_and_pipe(law, kwargs):
    """Mass conservation (linear compressibility): the plunger's displaced volume A_p h equals the volume
    stored by compression in the two chambers, (V / K) (p - p_0), and in the pipe, plus A_a y and the net
    leaked volume, at every step; the pipe's storage is summed on the grid, so the balance closes to the
    grid's first-order error, which halves when the grid is refined twice."""
    errors = []
    for reaches in (20, 40):
        d = drive(reaches=reaches, **kwargs)
        r = simulate(law, d, OMEGA)
        K, p0 = d.fluid.bulk_modulus, d.initial_pressure
        displaced = d.pump.plunger_area * r.plunger_lift
        stored = (d.pump.volume / K * (r.pump_pressure - p0) + d.actuator.volume / K * (r.actuator_pressure - p0)
                  + r.pipe_stored_volume + d.actuator.piston_area * r.valve_lift + r.leaked_volume)
        assert not r.cavitation.any()
        errors.append(np.abs(displaced - stored).max() / displaced.max())
    assert errors[0] < 5e-4 and errors[1] < 0.6 * errors[0]


def test_leakage_without_fill_lowers_the_lift(law):
    """Leakage lets out volume the plunger would have sent to the valve: less lift with more leakage."""
    tight = simulate(law, drive(leakage=0.0, fill=0.0), OMEGA)
    leaky = simulate(law, drive(leakage=2e-11, fill=0.0), OMEGA)
    assert leaky.valve_lift.max() < tight.valve_lift.max()
    assert leaky.leaked_volume[-1] > 0 and tight.leaked_volume[-1] == 0.0


def test_cavitation_is_flagged_and_clamped(law):
    """A weak spring on a fast cam: the valve overruns the liquid, the pressure falls to the vapour
    pressure, where it is held and flagged."""
    d = drive(spring=2e3, preload=200.0, fill=0.0)
    r = simulate(law, d, 4 * OMEGA)
    assert r.cavitation.any()
    assert min(r.pump_pressure.min(), r.actuator_pressure.min()) == pytest.approx(d.fluid.vapour_pressure)


def test_relief_valve_limits_the_pressure(law):
    free = simulate(law, drive(), OMEGA)
    limited = simulate(law, drive(relief=1.0e6), OMEGA)
    assert free.max_pressure > 1.1e6 and limited.max_pressure < free.max_pressure


def test_speed_sweep_is_the_single_runs_and_the_loss_grows_with_speed(law):
    """Each entry of the sweep is the single revolution at that speed; a faster cam leaves the compressible
    column less time: the opening delay in camshaft angle grows with speed (no leakage)."""
    d = drive(leakage=0.0, fill=0.0)
    speeds = OMEGA * np.array([0.25, 0.5, 1.0])
    s = speed_sweep(law, d, speeds)
    one = simulate(law, d, speeds[1])
    assert s.max_pressure[1] == one.max_pressure and s.lift_loss[1] == one.lift_loss
    assert s.opening_delay[1] == one.delays()[0] and not s.cavitation.any()
    assert (s.seating_velocity[1], s.bounce[1]) == one.seating()[1:]
    assert np.all(np.diff(s.opening_delay) > 0)


def test_slow_cam_loses_the_static_compression_of_the_column(law):
    """Quasi-static limit (analytic): on a slow cam the valve at full lift Y - l holds its spring with the
    pressure p = p_back + (F_0 + k (Y - l)) / A_a, and the lift lost is the liquid compressed by it,
    l = C (p - p_0) / A_a with the compliance C = (V_p + V_a) / K + A L / (rho a^2) of chambers and pipe."""
    d = drive(leakage=0.0, fill=0.0, friction=0.0)
    r = simulate(law, d, 0.02 * OMEGA)
    k, f0, aa = d.valve.spring_rate, d.valve.preload, d.actuator.piston_area
    c = (d.pump.volume + d.actuator.volume) / d.fluid.bulk_modulus + d.pipe.area * d.pipe.length / (
        d.fluid.density * d.wave_speed**2)
    y = r.rigid_lift.max()
    loss = c * (d.back_pressure - d.initial_pressure + (f0 + k * y) / aa) / aa / (1 + c * k / aa**2)
    assert r.lift_loss == pytest.approx(loss, rel=2e-3)


def _compliance(d):
    """Liquid compliance of the drive, chambers and pipe, C = (V_p + V_a) / K + A L / (rho a^2) [m^3/Pa]."""
    return (d.pump.volume + d.actuator.volume) / d.fluid.bulk_modulus + d.pipe.area * d.pipe.length / (
        d.fluid.density * d.wave_speed**2)


def test_gas_force_holds_the_valve_until_the_actuator_force_exceeds_it(law):
    """Quasi-static limit (hand calculation): on a slow cam a constant gas force F = p_cyl A_head holds the valve on
    its seat until (p_a - p_back) A_a = F_0 + F; until then the valve stands and the plunger only compresses the
    liquid, A_p h = C (p - p_0), so the valve leaves its seat where the plunger lift is
    h* = C (p_back + (F_0 + F) / A_a - p_0) / A_p.  At the nose (plunger lift H) the valve lift is
    y = (A_p H - C (p_back - p_0) - C (F_0 + F) / A_a) / (A_a + C k / A_a)."""
    d = drive(leakage=0.0, fill=0.0, friction=0.0)
    p_cyl, head = 0.8e6, math.pi * 0.04**2 / 4                  # 0.8 MPa over the port on a 40 mm head: 1005 N
    force = p_cyl * head
    r = simulate(law, d, 0.02 * OMEGA, gas_force=lambda angle: np.full(angle.shape, force))
    c, aa, ap, f0, k = _compliance(d), d.actuator.piston_area, d.pump.plunger_area, d.valve.preload, d.valve.spring_rate
    p_lift = d.back_pressure + (f0 + force) / aa
    h_star = c * (p_lift - d.initial_pressure) / ap
    theta_star = brentq(lambda t: law.lift(np.array([t]))[0] - h_star, law.start, 0.0)
    i = r.lift_off()
    assert r.angle[i] == pytest.approx(theta_star, abs=1e-4)     # two time steps, 0.006 cam deg
    assert r.actuator_pressure[i] == pytest.approx(p_lift, rel=5e-4)
    assert np.all(r.gas_force == force)
    y = (ap * law.lift(np.array([0.0]))[0] - c * (d.back_pressure - d.initial_pressure) - c * (f0 + force) / aa) / (
        aa + c * k / aa)
    assert r.valve_lift.max() == pytest.approx(y, rel=1e-4)
    # without the gas force the same drive opens earlier and lifts further
    free = simulate(law, d, 0.02 * OMEGA)
    assert free.lift_off() < i and free.valve_lift.max() > r.valve_lift.max()


def test_the_stop_ends_the_stroke_quasi_statically(law):
    """Closed form of a stop contact on a slow cam: with the stop at y_s below the drive's lift, at the nose the valve
    presses on it; the liquid balance A_p H = C (p - p_0) + A_a (y_s + d) and the valve's
    (p - p_back) A_a = F_0 + k (y_s + d) + K_stop d give the stop's deflection d and the pressure p."""
    d = drive(leakage=0.0, fill=0.0, friction=0.0)
    free = simulate(law, d, 0.02 * OMEGA)
    y_s, k_stop = 0.8 * free.valve_lift.max(), 2e7
    d = replace(d, valve=replace(d.valve, stop=y_s, stop_rate=k_stop))
    r = simulate(law, d, 0.02 * OMEGA)
    c, aa, ap, f0, k = _compliance(d), d.actuator.piston_area, d.pump.plunger_area, d.valve.preload, d.valve.spring_rate
    big_h = law.lift(np.array([0.0]))[0]
    # two linear equations in (p, d):  C p + A_a d = A_p H + C p_0 - A_a y_s;  A_a p - (k + K_stop) d = ...
    a = np.array([[c, aa], [aa, -(k + k_stop)]])
    b = np.array([ap * big_h + c * d.initial_pressure - aa * y_s, d.back_pressure * aa + f0 + k * y_s])
    p, deflection = np.linalg.solve(a, b)
    assert deflection > 0 and r.stop_reached and not free.stop_reached
    assert r.valve_lift.max() == pytest.approx(y_s + deflection, rel=1e-4)
    assert r.actuator_pressure.max() == pytest.approx(p, rel=1e-4)
    assert r.actuator_pressure.max() > free.actuator_pressure.max()   # the stop takes the lift the liquid would give


def test_a_valve_that_does_not_close_is_open_at_the_end_of_the_revolution(law):
    """A valve whose spring cannot push the liquid back before the plunger lifts again: the lift left at the end of
    the revolution (where the plunger is about to lift again) is the valve's, and it has no seating (nan)."""
    d = drive(leakage=0.0, fill=0.0)
    heavy = replace(d, valve=replace(d.valve, mass=500.0))
    r = simulate(law, heavy, OMEGA)
    assert r.residual_lift == r.valve_lift[-1] > 1e-3
    assert math.isnan(r.seating()[1])
    assert simulate(law, d, OMEGA).residual_lift == 0.0             # the assumed drive closes
