"""Valve-train dynamics: one-mass train, integrator accuracy, sweeps, perturbation (spec section 12)."""

from dataclasses import replace
from types import SimpleNamespace

import numpy as np
import pytest

from valvetrain.dynamics.perturbation import (kinetostatic_force, outer_lift, outer_solution, perturbation_parameter,
                                              quasi_static_lift)
from valvetrain.dynamics.sweep import runs, simulate, sweep
from valvetrain.laws import KurzLaw

from reference_dynamics import RPM, spec12

def test_quasi_static_limit():
    """Stiff, slow limit (spec section 12 check): at 10 cam rpm (epsilon = 1.8e-8) the valve follows
    G = (c (k h - x0) - F0)/(c + K), the rigid lift less the static deflection, within 0.01 um away from the
    opening and closing transients."""
    law, train = spec12()
    r = simulate(law, train, 10 * RPM, revolutions=1)
    g = quasi_static_lift(law.derivatives(r.theta)[:1], train)[0]
    inner = np.abs(r.theta) < np.radians(45)
    assert np.abs(r.lift - g)[inner].max() < 1e-8
    # the static deflection itself is far above the tolerance: the test sees it
    assert np.abs(r.lift - r.kinematic_lift)[inner].min() > 1e-5


def test_free_vibration_frequency_and_decay():
    """A mass on a damped spring released from rest: y = A e^(-zeta wn t)(cos wd t + zeta/sqrt(1 - zeta^2)
    sin wd t) about its equilibrium (analytic solution), wn = sqrt(K/M), wd = wn sqrt(1 - zeta^2)."""
    _, train = spec12()
    net = train.network()
    m, k, zeta, y_eq, amp = net.mass[0], 67.5e3, 0.03, 2e-3, 1e-3
    spring = net.elements.index("spring at valve")
    damping = net.damping.copy()
    damping[spring] = 2 * zeta * np.sqrt(k * m)
    gap = net.gap.copy()
    gap[net.cam_element] = 1.0                        # the cam never reaches the valve
    free = replace(net, damping=damping, gap=gap, preload=np.where(np.arange(3) == spring, -k * y_eq, 0.0),
                   x_init=np.array([y_eq + amp]))
    omega = 50 * RPM
    r = sweep(KurzLaw(6.25e-3, 0.25e-3, 1.146e-3, *np.radians([27.0, 6.0, 38.0])),
              SimpleNamespace(network=lambda: free), [omega], revolutions=1)
    t = (r.theta + np.pi) / omega
    wn = np.sqrt(k / m)
    wd = wn * np.sqrt(1 - zeta**2)
    exact = y_eq + amp * np.exp(-zeta * wn * t) * (np.cos(wd * t) + zeta / np.sqrt(1 - zeta**2) * np.sin(wd * t))
    assert np.abs(r.lift[0] - exact).max() < 1e-6 * amp
    assert r.lift[0].max() > y_eq + 0.9 * amp and r.lift[0][-100:].max() < y_eq + 0.01 * amp


def test_energy_balance_without_damping():
    """Without damping every element is conservative, so the train's energy (kinetic, spring F0 y + K y^2/2,
    drive c delta^2/2, seat c_s y^2/2) changes by the work of the cam, the integral of F du (first law)."""
    law, train = spec12()
    train = replace(train, damping=0.0, seat_damping=0.0)
    omega = 1500 * RPM
    r = sweep(law, train, [omega], revolutions=1)
    y, v, f = r.lift[0], r.velocity[0], r.contact_force[0] / train.rocker_ratio
    u = train.rocker_ratio * law.lift(r.theta)
    delta = np.maximum(u - train.lash - y, 0.0)
    energy = (0.5 * train.mass * v**2 + train.preload * y + 0.5 * train.spring_rate * y**2
              + 0.5 * train.stiffness * delta**2 + 0.5 * train.seat_stiffness * np.minimum(y, 0.0) ** 2)
    work = np.concatenate([[0.0], np.cumsum(0.5 * (f[1:] + f[:-1]) * np.diff(u))])
    swing = np.ptp(energy)
    assert swing > 1.0                                   # the valve opens: joules go in and come back
    assert np.abs(energy - energy[0] - work).max() < 1e-4 * swing


def test_fast_integrator_agrees_with_solve_ivp():
    """The compiled RK4 at 0.1 cam deg against scipy's DOP853 at rtol 1e-10 on the same equations (spec section
    12) over one revolution at the design speed: the valve lift agrees within 0.2 um."""
    from scipy.integrate import solve_ivp

    law, train = spec12()
    omega = 3000 * RPM

    def rhs(t, s):
        d = law.derivatives(np.array([-np.pi + omega * t]))[:2, 0] * train.rocker_ratio
        y, v = s
        gap = d[0] - train.lash - y
        fc = max(0.0, train.stiffness * gap + train.damping * (omega * d[1] - v)) if gap > 0 else 0.0
        fs = max(0.0, -train.seat_stiffness * y - train.seat_damping * v) if y < 0 else 0.0
        return [v, (fc - train.preload - train.spring_rate * y + fs) / train.mass]

    sol = solve_ivp(rhs, (0, 2 * np.pi / omega), [-train.preload / train.seat_stiffness, 0.0], method="DOP853",
                    rtol=1e-10, atol=1e-13, dense_output=True)
    r = simulate(law, train, omega, revolutions=1)
    reference = sol.sol((r.theta + np.pi) / omega)[0]
    assert reference.max() > 7e-3
    assert np.abs(r.lift - reference).max() < 2e-7


def test_known_jump_case():
    """Spec section 12 at 3600 cam rpm: the kinetostatic force goes negative on the nose, so the follower must
    separate there; at 1500 rpm it stays positive (its minimum is F0 at the opening) and nothing separates."""
    law, train = spec12()
    theta = np.concatenate([[law.valve_opens + 1e-7], np.radians(np.linspace(-80, 80, 3201))])
    slow, fast = (kinetostatic_force(law, train, theta, n * RPM) for n in (1500, 3600))
    assert slow[0] == pytest.approx(400.0, abs=0.5) and np.nanmin(slow) > 399.5 and np.nanmin(fast) < -100.0
    negative = theta[fast < 0]
    r = sweep(law, train, np.array([1500, 3600]) * RPM)
    assert r.speed(0).jump_intervals.size == 0
    (start, end), = r.speed(1).jump_intervals
    assert start < negative.min() and end > negative.max()


def test_spec12_sweep_table():
    """Spec section 12, speed sweep of the section 8 cam (single event from rest, as the reference ran it).

    Reproduced: epsilon (to the printed digits); no jump at 1500 rpm; a dynamic jump at 3000 rpm on the opening
    flank (the table: -36...-18 deg; here -32...-11 deg) although the kinetostatic force is positive; the
    float at 3600 and 4500 rpm starting near -37/-38 deg; seating velocity at 1500-3000 rpm near the design
    -0.3 m/s; no bounce at 3000 rpm; millimetre bounces once the valve floats.  Not reproduced exactly: the
    spec's reference train is not fully given (K and the seat are not stated; K = 67.5 N/mm of
    tests/laws/test_laws_more.py gives a kinetostatic minimum of 143 N at 3000 rpm against the table's 163 N), so
    the angles and the float-regime velocities differ by a few degrees and tens of per cent."""
    law, train = spec12()
    rpm = np.array([1500, 3000, 3600, 4500])
    eps = perturbation_parameter(train.mass, train.stiffness, train.spring_rate, rpm * RPM)
    # the printed digits; 4500 rpm gives 0.003685 against the printed 0.00369 (the reference's K was 24-65 N/mm)
    assert eps == pytest.approx([0.00041, 0.00164, 0.00236, 0.00369], abs=6e-6)
    r = sweep(law, train, rpm * RPM, revolutions=1).per_speed()
    assert r[0].jump_intervals.size == 0
    assert r[1].jump_intervals.size and all(-40 < a < b < -10 for a, b in np.degrees(r[1].jump_intervals))
    for row, start in ((r[2], -37.3), (r[3], -38.4)):
        assert np.degrees(row.jump_intervals[0, 0]) == pytest.approx(start, abs=5.0)
        assert np.degrees(row.jump_intervals[-1, 1]) > 45
    assert -0.30 < r[0].seating_velocity < -0.2 and r[1].seating_velocity == pytest.approx(-0.295, abs=0.015)
    assert r[0].bounce_height < 10e-6 and r[1].bounce_count == 0 and r[1].bounce_height < 1e-6
    assert r[2].seating_velocity < -4 and r[3].seating_velocity < -8
    assert 1e-3 < r[2].bounce_height < 3.5e-3 and 1e-3 < r[3].bounce_height < 3.5e-3


def test_outer_solution_identity():
    """For the dynamic cam, G = y + epsilon y'' exactly (k h = x0 + y + (M w^2 y'' + K y + F0)/c at its design
    speed), so the first-order outer solution G - epsilon G'' is y - epsilon^2 y'''' (analytic identity)."""
    law, train = spec12()
    theta = np.radians(np.linspace(-50, 50, 201))
    y = law.valve_motion(theta)
    eps = perturbation_parameter(train.mass, train.stiffness, train.spring_rate, law.omega)
    g = quasi_static_lift(law.derivatives(theta)[:3], train)
    assert np.abs(g[0] - (y[0] + eps * y[2])).max() < 1e-12
    assert np.abs(outer_solution([g[0], g[2]], eps) - (y[0] - eps**2 * y[4])).max() < 1e-12


def test_simulation_is_closer_to_the_outer_solution_than_to_g():
    """Spec section 12: inside the event the simulated lift is nearer the outer solution than the quasi-static G
    (the spec's reference: 23.3 um against 60.1 um)."""
    law, train = spec12()
    r = simulate(law, train, law.omega)
    inner = np.abs(r.theta) < np.radians(45)
    g = np.maximum(quasi_static_lift(law.derivatives(r.theta)[:1], train)[0], 0.0)
    outer = outer_lift(law, train, r.theta, law.omega)
    assert np.abs(r.lift - outer)[inner].max() < 0.6 * np.abs(r.lift - g)[inner].max()


def test_sweep_progress_and_blocks():
    """The progress hook counts up to every speed; the blocking and the threads do not change the results (speeds are
    independent: each speed alone gives the same lift to the bit)."""
    law, train = spec12()
    calls = []
    speeds = np.linspace(1000, 3000, 20) * RPM
    a = sweep(law, train, speeds, revolutions=1, progress=lambda done, total: calls.append((done, total)))
    assert calls[-1] == (20, 20) and all(x[0] < y[0] for x, y in zip(calls, calls[1:]))
    for i in (0, 7, 19):
        assert np.array_equal(a.lift[i], sweep(law, train, speeds[i:i + 1], revolutions=1).lift[0])


def test_headline_numbers():
    """Jump speed and bounce onset are the lowest speeds showing them; the largest seating velocity is the
    largest |dy/dt| at seating among the speeds."""
    law, train = spec12()
    speeds = np.array([1500, 3000, 3600, 4500]) * RPM
    r = sweep(law, train, speeds, revolutions=1)
    head = r.headline()
    per = r.per_speed()
    assert head["jump_speed"] == speeds[1]
    assert head["bounce_onset_speed"] == speeds[0]
    assert head["max_seating_velocity"] == pytest.approx(max(abs(p.seating_velocity) for p in per))
    assert np.isnan(head["coil_clash_speed"])


def test_torque_is_force_times_slope():
    """Camshaft torque from the power balance F v_tappet = T omega: T = F dh/dtheta; over a revolution the
    undamped train returns the energy, so the mean torque is small against its peak."""
    law, train = spec12()
    r = simulate(law, train, 1500 * RPM)
    slope = law.derivatives(r.theta)[1]
    assert np.allclose(r.torque, r.contact_force * slope)
    assert abs(r.torque.mean()) < 0.05 * np.abs(r.torque).max()


def test_runs():
    """Runs of a mask: none, one at each end, the whole array."""
    assert runs(np.zeros(4, dtype=bool)).shape == (0, 2)
    assert runs(np.array([1, 0, 0, 1], dtype=bool)).tolist() == [[0, 1], [3, 4]]
    assert runs(np.ones(3, dtype=bool)).tolist() == [[0, 3]]


def test_dynamic_contact_stress_and_lubrication():
    """Shang Hanji (1988), (2.5) with the dynamic force (section 3.4): at the nose sigma = 0.418 sqrt(F E / (b rho)) with
    rho = R0 + h + h'' (2.6).  The lubrication characteristic (2.12) gamma = rho / (R0 + h) is 1 on the base
    circle.  Hand computations on a simulated force."""
    from valvetrain.dynamics.contact import dynamic_contact_stress, lubrication_characteristic

    law, train = spec12()
    r = simulate(law, train, 2000 * RPM)
    r0, width, modulus = 20e-3, 15e-3, 2.1e11
    sigma = dynamic_contact_stress(law, r.theta, r.contact_force, r0, width, modulus)
    nose = int(np.argmin(np.abs(r.theta)))
    h, _, d2h = law.derivatives(r.theta[nose])[:3]
    assert sigma[nose] == pytest.approx(0.418 * np.sqrt(r.contact_force[nose] * modulus / (width * (r0 + h + d2h))))
    assert r.contact_force[nose] > 100.0
    base = 0
    assert law.lift(r.theta[base]) == 0.0
    gamma = lubrication_characteristic(law, r.theta[[base, nose]], r0)
    assert gamma[0] == 1.0 and gamma[1] == pytest.approx((r0 + h + d2h) / (r0 + h))
