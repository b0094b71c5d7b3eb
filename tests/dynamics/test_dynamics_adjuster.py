"""The hydraulic lash adjuster as a state of the dynamics (valvetrain.dynamics.models.Adjuster and the kernels'
plunger extension carried from revolution to revolution), each against an independent reference: the train without
the adjuster (no leak: it reduces to a rigid element), the laminar leakage of an annular clearance integrated by hand
over the simulated force, the adjuster's push by hand, the float of the train without it (pump-up), the onset of
pump-up against the kinetostatic closed form of the separation speed, and the plunger's sink over the lift event
against scipy solve_ivp of the valve-and-plunger model at rtol 1e-10."""

from dataclasses import replace

import numpy as np
import pytest

from reference_dynamics import RPM, spec12
from valvetrain.design.lash_adjuster import float_speed, plunger_motion
from valvetrain.dynamics.models import Adjuster, one_mass_train
from valvetrain.dynamics.events import lift_event
from valvetrain.dynamics.sweep import sweep

RATIO = 0.6
"""Motion ratio of an end-pivot finger of lever ratio 1.6 (valve motion per plunger motion i - 1)."""
AREA = np.pi * 0.009**2 / 4.0
"""Plunger area of a 9 mm plunger, 6.3617e-5 m^2."""
LEAK = np.pi * 0.009 * (4e-6)**3 / (12.0 * 0.010 * 0.008)
"""pi d c^3 / (12 mu L) of d = 9 mm, c = 4 um, mu = 10 mPa s, L = 8 mm: 1.8850e-15 m^3/(s Pa)."""
PUSH = (15.0 + 0.3e6 * AREA) / RATIO
"""The adjuster's push at the valve, (F_s + p_s A) / i_a = (15 + 0.3e6 x 6.3617e-5) / 0.6 = 56.809 N by hand."""


def trains():
    """spec12's law and one-mass train (c = 15 N/um at the valve, k = 1.5) without clearance, and the same with a
    leak-free adjuster (F_s = 15 N, p_s = 0.3 MPa, refill 0.9 m/s)."""
    law, _ = spec12()
    train = one_mass_train(0.25, 15e6, 67.5e3, 400.0, 1.5, 0.0, damping_ratio=0.05)
    return law, train, replace(train, adjuster=Adjuster(RATIO, 15.0, AREA, 0.3e6, 0.0, 0.9))


def test_a_leak_free_adjuster_is_a_rigid_element_that_takes_up_the_lash():
    """No leak: the plunger extends on the base circle until the contact carries the adjuster's push (56.809 N by
    hand; the train without it, 27.9 N of seat compression), then holds: the valve lift equals the train's without
    the adjuster within the push's deflection of the contact, 56.8 N / 15 N/um = 3.8 um, plus what a transient on the
    base circle pumps (no leak returns it), under 5 um in all."""
    law, rigid, hydraulic = trains()
    speeds = np.array([100.0, 300.0, 1500.0]) * RPM
    a, b = sweep(law, rigid, speeds, revolutions=4), sweep(law, hydraulic, speeds, revolutions=4)
    base = b.contact_force[:, 0] / 1.5
    assert np.all(np.abs(base - PUSH) < 0.02 * PUSH) and np.all(a.contact_force[:, 0] / 1.5 < 0.6 * PUSH)
    assert np.abs(a.lift - b.lift).max() < 5e-6
    assert b.converged.all() and np.all(b.adjuster_extension > 0.0)
    assert a.adjuster_extension is None          # the rigid train has no adjuster (sweep: None without one)


def test_leak_down_per_cycle_is_the_annular_leakage_integrated_by_hand():
    """With the leak: over a revolution at 100 and 300 cam rpm the plunger sinks by the integral of the laminar
    leakage Q = pi d c^3 (p - p_s) / (12 mu L) over A, p = (i_a F - F_s) / A from the simulated contact force F at the
    valve, by the trapezoid rule over the recorded angles; the check valve refills it on the base circle (the state
    repeats)."""
    law, _, hydraulic = trains()
    speeds = np.array([100.0, 300.0]) * RPM
    r = sweep(law, replace(hydraulic, adjuster=replace(hydraulic.adjuster, leak=LEAK)), speeds, revolutions=4)
    z = r.adjuster_extension
    pressure = np.clip((r.contact_force / 1.5 * RATIO - 15.0) / AREA - 0.3e6, 0.0, None)
    by_hand = np.trapezoid(LEAK * pressure / AREA, r.theta / speeds[:, None], axis=1)
    assert np.allclose(z.max(axis=1) - z.min(axis=1), by_hand, rtol=1e-3)
    assert by_hand[0] > 2.0 * by_hand[1] and r.converged.all()


def test_a_float_pumps_the_adjuster_up_and_holds_the_valve_open():
    """spec12 at 3600 cam rpm floats (its test_known_jump_case): the plunger follows the opened gap, the oil trapped
    by the check valve holds it, and without leak the valve stays off its seat on the base circle; at 1500 rpm, no
    float, it seats."""
    law, rigid, hydraulic = trains()
    speeds = np.array([1500.0, 3600.0]) * RPM
    a, b = sweep(law, rigid, speeds, revolutions=6), sweep(law, hydraulic, speeds, revolutions=6)
    assert a.speed(1).jump_intervals.size > 0 and a.speed(0).jump_intervals.size == 0
    base = np.abs(b.theta) > np.radians(120.0)
    assert b.lift[1, base].min() > 1e-4 and b.adjuster_extension[1].max() > 100.0 * b.adjuster_extension[0].max()
    assert b.lift[0, base].max() < 1e-6


def test_the_check_valve_only_refills():
    """Leak-free, the plunger can only extend: where the force falls to the push the check valve opens and oil flows
    in, never out (it leaves by the clearance alone, here shut).  At 3800 cam rpm spec12 floats and its contact
    unloads faster than its spring relaxes (the damping force pulls the unilateral force to 0 while it is still
    compressed); the plunger's extension over the recorded revolution never falls (it fell by 7.3 um in one step
    when the kernel set it to the extension that would carry the push there, shorter than the one it had)."""
    law, _, hydraulic = trains()
    r = sweep(law, hydraulic, np.array([1500.0, 3800.0]) * RPM, revolutions=8)
    assert np.all(np.diff(r.adjuster_extension, axis=1) >= 0.0)
    assert r.adjuster_extension[1, -1] > 100e-6


def test_the_plunger_stops_at_its_travel_and_holds_the_valve_as_an_interference_would():
    """Leak-free with a stop 0.3 mm out: where spec12 floats (3300-3450 cam rpm) the plunger pumps up to its stop and
    no further, and the train is then the train without the adjuster whose cam contact is compressed by i_a s =
    0.6 x 0.3 = 0.18 mm on the base circle (a negative lash): both integrations agree to 1e-8 m.  That train holds
    its valve off its seat at low speed at the static balance c (i_a s - y) = F0 + K y, y = (15e6 x 0.18e-3 - 400) /
    (15e6 + 67.5e3) = 0.15265 mm, by hand."""
    law, rigid, hydraulic = trains()
    stop = 0.3e-3
    speeds = np.array([3300.0, 3400.0, 3450.0]) * RPM
    a = sweep(law, replace(hydraulic, adjuster=replace(hydraulic.adjuster, stop=stop)), speeds, revolutions=20)
    b = sweep(law, replace(rigid, lash=-RATIO * stop), speeds, revolutions=20)
    assert a.converged.all() and np.all(a.adjuster_extension == stop)
    assert np.abs(a.lift - b.lift).max() < 1e-8
    low = sweep(law, replace(rigid, lash=-RATIO * stop), [300.0 * RPM], revolutions=5)
    base = np.abs(low.theta) > np.radians(120.0)
    assert low.lift[0, base] == pytest.approx(0.15265e-3, rel=1e-4)


def test_net_extension_per_revolution_is_the_refill_less_the_leak_down_by_hand():
    """spec12 with the leaking adjuster and a 1 mm stop at 3300 and 3400 cam rpm, where it floats: the plunger's sink
    over a revolution is the laminar leakage integrated by hand over the recorded force (trapezoid rule, Q = pi d c^3
    (p - p_s) / (12 mu L), p = (i_a F - F_s) / A), and its net extension is the check valve's refill (the steps it
    extends) less that integral: in its second revolution it still pumps up by more than 50 um; once its
    motion settles (the plunger at its stop, within 0.1 um a revolution at the valve) the refill balances the hand
    integral within that.  The hand integral and the kernel's explicit steps agree to 1e-3 (the existing test at low
    speed)."""
    law, _, hydraulic = trains()
    train = replace(hydraulic, adjuster=replace(hydraulic.adjuster, leak=LEAK, stop=1e-3))
    speeds = np.array([3300.0, 3400.0]) * RPM
    for revolutions, tolerance in ((2, -1.0), (400, 1e-7)):
        r = sweep(law, train, speeds, revolutions=revolutions, tolerance=tolerance)
        z = r.adjuster_extension
        pressure = np.clip((r.contact_force / 1.5 * RATIO - 15.0) / AREA - 0.3e6, 0.0, None)
        leak = np.trapezoid(LEAK * pressure / AREA, r.theta / speeds[:, None], axis=1)
        step = np.diff(z, axis=1)
        assert -np.where(step < 0.0, step, 0.0).sum(axis=1) == pytest.approx(leak, rel=1e-3)
        refill = np.where(step > 0.0, step, 0.0).sum(axis=1)
        assert z[:, -1] - z[:, 0] == pytest.approx(refill - leak, abs=1e-3 * leak.max())
        if revolutions == 2:
            assert np.all(refill - leak > 50e-6)
        else:
            assert r.converged.all() and np.all(z.max(axis=1) == 1e-3)
            assert np.all(np.abs(refill - leak) < 1e-7 / RATIO)


def test_pump_up_starts_where_the_follower_leaves_the_cam():
    """The rigid follower leaves the cam where the inertia force exceeds the spring's, M |y''| w^2 > F0 + K y on the
    nose (y = k h, y'' = k h'' per rad^2 < 0): w_j^2 = min (F0 + K y) / (M |y''|) over the law's angles, by hand here
    (the kinetostatic closed form, 352.2 rad/s, 3363 cam rpm).  The elastic train separates a little earlier (its
    vibration, spec12's dynamic jump); the train without the adjuster is the second reference.  With a leaking
    adjuster: at 0.8 w_j neither the closed form nor the train without it separates, and the plunger gains nothing
    while the valve is off its seat, which seats on the base circle (:func:`plunger_motion`); at 0.9 w_j the train
    without it separates and the plunger pumps up; above w_j (the closed form separates) it pumps up by more than
    1 um a revolution and holds the valve off its seat."""
    law, rigid, hydraulic = trains()
    hydraulic = replace(hydraulic, adjuster=replace(hydraulic.adjuster, leak=LEAK))
    theta = np.linspace(law.valve_opens, law.valve_closes, 20001)
    h, _, h2 = law.derivatives(theta)[:3]
    nose = h2 < 0.0
    w_j = np.sqrt(np.min((400.0 + 67.5e3 * 1.5 * h[nose]) / (0.25 * 1.5 * -h2[nose])))
    assert w_j / RPM == pytest.approx(3363.1, abs=0.5)
    speeds = w_j * np.array([0.8, 0.9, 1.05, 1.2])
    a, b = sweep(law, rigid, speeds, revolutions=6), sweep(law, hydraulic, speeds, revolutions=6)
    separated = [a.speed(i).jump_intervals.size > 0 for i in range(speeds.size)]
    assert separated == [False, True, True, True]
    motion = [plunger_motion(r.adjuster_extension, r.lift, lift_event(r.kinematic_lift, r.lift),
                             law.lift(r.theta) <= 0.0) for r in b.per_speed()]
    assert motion[0][1:] == (0.0, 0.0) and motion[1][1] > 0.0
    assert all(pump > 1e-6 and held > 0.0 for _, pump, held in motion[2:])



def test_the_plunger_s_leak_down_over_the_event_agrees_with_solve_ivp():
    """A second solver of the 2-DOF model, valve and plunger: M y'' = F - F0 - K y with the contact force
    F = max(0, c d + C (w k h' - y')) while d = k h + i_a z - y > 0, and the plunger sinking by the laminar leakage,
    z' = -Q (p - p_s) / A^2 for p = (i_a F - F_s) / A > p_s (the check valve shut), by scipy's DOP853 at rtol 1e-10 from
    the kernels' state where the valve is 10 um open to where it closes to 10 um, at 1500 cam rpm with ten times the
    leak coefficient (26 um of sink): the sink agrees to 1e-4 of itself, the plunger and the valve within 0.05 um."""
    from scipy.integrate import solve_ivp

    law, _, hydraulic = trains()
    leak, k, omega = 10.0 * LEAK, 1.5, 1500 * RPM
    r = sweep(law, replace(hydraulic, adjuster=replace(hydraulic.adjuster, leak=leak)), [omega], revolutions=6).speed(0)
    y, z, theta = r.lift, r.adjuster_extension, r.theta
    i0, i1 = np.flatnonzero(y > 1e-5)[[0, -1]]

    def rhs(t, s):
        lift, velocity, extension = s
        h, dh = law.derivatives(np.array([theta[i0] + omega * t]))[:2, 0]
        delta = k * h + RATIO * extension - lift
        force = max(hydraulic.stiffness * delta + hydraulic.damping * (omega * k * dh - velocity), 0.0) \
            if delta > 0.0 else 0.0
        pressure = (RATIO * force - 15.0) / AREA
        sink = leak * (pressure - 0.3e6) / AREA if pressure > 0.3e6 else 0.0
        return [velocity, (force - 400.0 - 67.5e3 * lift) / 0.25, -sink]

    sol = solve_ivp(rhs, (0.0, (theta[i1] - theta[i0]) / omega), [y[i0], r.velocity[i0], z[i0]], method="DOP853",
                    rtol=1e-10, atol=1e-14, dense_output=True)
    reference = sol.sol((theta[i0:i1 + 1] - theta[i0]) / omega)
    sink = reference[2, 0] - reference[2, -1]
    assert sink > 2e-5 and r.converged
    assert z[i0] - z[i1] == pytest.approx(sink, rel=1e-4)
    assert np.abs(z[i0:i1 + 1] - reference[2]).max() < 5e-8 and np.abs(y[i0:i1 + 1] - reference[0]).max() < 5e-8


def test_a_float_the_plunger_follows_is_the_separation_of_the_train_preloaded_less_the_push():
    """Where the follower's force falls to the adjuster's push (56.809 N at the valve by hand) the plunger extends
    after it and the contact does not open: the dynamics' jump (contact force 0) sees no separation up to 1.1 x the
    kinetostatic float speed, where the train without the adjuster separates.  The float speed
    (:func:`float_speed`) is the separation speed of the train without the adjuster whose spring preload is less by
    the push, 400 - 56.809 N (the same criterion on a mechanical train), within 0.5 %; both float below the
    kinetostatic closed form w_f^2 = min (F0 - P + K y) / (M |y''|) over the nose (by hand here, 3243 cam rpm; the
    elastic train's vibration floats it earlier, by 10 % at most) and below the separation of the train without the
    adjuster at its full preload (the push unloads the spring)."""
    law, rigid, hydraulic = trains()
    hydraulic = replace(hydraulic, adjuster=replace(hydraulic.adjuster, leak=LEAK))
    theta = np.linspace(law.valve_opens, law.valve_closes, 20001)
    h, _, h2 = law.derivatives(theta)[:3]
    nose = h2 < 0.0
    w_f = np.sqrt(np.min((400.0 - PUSH + 67.5e3 * 1.5 * h[nose]) / (0.25 * 1.5 * -h2[nose])))
    assert w_f / RPM == pytest.approx(3243.4, abs=0.5)
    speeds = np.linspace(0.78, 1.1, 17) * w_f
    b = sweep(law, hydraulic, speeds, revolutions=20)
    less = sweep(law, one_mass_train(0.25, 15e6, 67.5e3, 400.0 - PUSH, 1.5, 0.0, damping_ratio=0.05), speeds,
                 revolutions=20).headline()["jump_speed"]
    full = sweep(law, rigid, speeds, revolutions=6).headline()["jump_speed"]
    assert np.isnan(b.headline()["jump_speed"]) and b.contact_force.min() > 0.0
    found = float_speed(speeds, np.array([r.min_contact_force for r in b.per_speed()]) / 1.5, PUSH)
    assert found == pytest.approx(less, rel=5e-3)
    assert 0.9 * w_f < found < min(w_f, full)
