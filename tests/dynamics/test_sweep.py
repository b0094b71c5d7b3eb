"""Simulating the valve train over speeds (valvetrain.dynamics.sweep): the one-mass train against closed forms (the
quasi-static limit, a free vibration, the energy balance), its jumps, the sweep table of spec section 12, the
headline numbers, the seating and the events."""

from dataclasses import replace
import pickle
import sys
from types import SimpleNamespace

import numpy as np
import pytest

from valvetrain.dynamics.coils import CoilSpring
from valvetrain.dynamics.models import Adjuster, one_mass_train, rocker_train
from valvetrain.dynamics.perturbation import kinetostatic_force, perturbation_parameter, quasi_static_lift
from valvetrain.dynamics.events import seating, sweep_events, zero_crossing
from valvetrain.dynamics.sweep import (MAP_FIELDS, PER_SPEED_FIELDS, headline_sweep, merged, one_node, simulate,
                                      sweep)
from valvetrain.laws import KurzLaw

from reference_dynamics import RPM, appendix_train, harmonic_cam, reference_events, seat_crossings, spec12


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
    tests/laws/test_dynamic.py gives a kinetostatic minimum of 143 N at 3000 rpm against the table's 163 N), so
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




def test_jump_speed_of_a_harmonic_cam_closed_form():
    """A flat follower on a harmonic cam with a stiff drive (c = 3e8 N/m, zeta = 0.1) and an undamped seat.

    Closed form (rigid drive): the contact force is F = F0 + K h + M h'' omega^2, with h = L/2 (1 + cos x),
    h'' = -L/2 (pi/phi)^2 cos x.  Its least value is at the nose (x = 0) once M omega^2 (pi/phi)^2 > K:
    F_min = F0 + K L - M omega^2 L/2 (pi/phi)^2, zero at omega_j = sqrt(2 (F0 + K L) / (M L (pi/phi)^2)).
    With L = 8 mm, phi = 1 rad, M = 0.2 kg, K = 50 N/mm, F0 = 300 N: omega_j = sqrt(1400 / 0.01579) = 297.8 rad/s.
    The drive's compliance shifts it by about (omega / omega_n)^2 = 6e-5 (omega_n = sqrt(c / M) = 38700 rad/s); the
    vibration the acceleration steps of the cam excite at its start has decayed by exp(-zeta omega_n phi / omega)
    = 2e-6 at the nose.  The sweep's speeds are 0.5 % apart; the jump speed must be within 0.1 % (the first speed
    with a separation alone is up to 0.5 % off)."""
    lift, phi, mass, rate, preload = 8e-3, 1.0, 0.2, 50e3, 300.0
    exact = np.sqrt(2 * (preload + rate * lift) / (mass * lift * (np.pi / phi) ** 2))
    train = one_mass_train(mass, 3e8, rate, preload, damping_ratio=0.1, seat_damping_ratio=0.0)
    speeds = np.linspace(0.8, 1.2, 81) * exact * 1.0013           # the grid does not fall on the exact speed
    r = sweep(harmonic_cam(lift, phi), train, speeds)
    jump = r.headline()["jump_speed"]
    assert abs(jump / exact - 1) < 1e-3
    first = speeds[[s.jump_intervals.size > 0 for s in r.per_speed()]][0]
    assert abs(first / exact - 1) > 1e-3                            # the grid alone misses it: the test can fail
    below = r.speed(int(np.searchsorted(speeds, 0.99 * exact)) - 1)
    assert below.jump_intervals.size == 0 and below.min_contact_force > 0.0   # undamped seat: a bounce, no jump


def eccentric(lift):
    """A cam without a base circle: an eccentric disc under a flat follower, h = L/2 (1 + cos theta) (0 at -pi)."""
    def derivatives(theta):
        return np.array([0.5 * lift * (1 + np.cos(theta)), -0.5 * lift * np.sin(theta), -0.5 * lift * np.cos(theta)])
    return SimpleNamespace(derivatives=derivatives)


def test_an_eccentric_jumps_only_where_its_follower_leaves_it():
    """A cam with no base circle (issue 35): an eccentric on a one-mass train without clearance, a stiff drive
    (c = 1e8 N/m, zeta = 0.1) and an undamped seat.  Closed form (rigid drive): F = F0 + K h + M h'' omega^2 with
    h'' = -L/2 cos theta is least at the nose once M omega^2 > K, zero at omega_j = sqrt(2 (F0 + K L) / (M L)) = 836.7
    rad/s (L = 8 mm, M = 0.25 kg, K = 50 N/mm, F0 = 300 N); the drive's compliance shifts it by (omega / omega_n)^2 =
    0.2 %.  The valve seats near the eccentric's lowest point, where the cam lifts again at once, and rocks on the
    seat's elasticity (under 1 um) while the cam's lift is a few nanometres: no separation, the valve is not off its
    seat; and a bounce that runs over the record's start is no jump (the lift event is the revolution's, from the cam
    lifting the valve after its lowest point to the valve's return to its seat).  Main reported a jump from -180 cam
    deg at every speed from 0.5 omega_j.  Now no speed from 0.3 to 0.98 omega_j separates, the jump speed is within
    0.5 % of omega_j, the first separation about the nose."""
    lift, mass, rate, preload = 8e-3, 0.25, 50e3, 300.0
    exact = np.sqrt(2 * (preload + rate * lift) / (mass * lift))
    train = one_mass_train(mass, 1e8, rate, preload, damping_ratio=0.1, seat_damping_ratio=0.0)
    speeds = np.concatenate([np.linspace(0.3, 0.9, 7), np.linspace(0.95, 1.05, 21) * 1.0013]) * exact
    r = sweep(eccentric(lift), train, speeds)
    jumped = r.events.jumped
    assert not jumped[speeds < 0.98 * exact].any() and jumped[-1]
    assert abs(r.headline()["jump_speed"] / exact - 1) < 5e-3
    assert abs(np.degrees(r.events.jump_from[np.argmax(jumped)])) < 30.0




def test_headline_sweep_has_the_full_sweeps_headlines():
    """The speeds a tolerance study simulates (headline_sweep, every 10th speed then the speeds about the events) give
    the jump speed of the harmonic cam above: within 0.1 % of the closed form omega_j = 297.8 rad/s, and equal to the
    full sweep's, whose interpolation it reproduces; the largest seating velocity, and the largest cam force inside a
    load range that stops below the jump between two coarse speeds, equal the full sweep's; with under half of its
    speeds simulated."""
    lift, phi, mass, rate, preload = 8e-3, 1.0, 0.2, 50e3, 300.0
    exact = np.sqrt(2 * (preload + rate * lift) / (mass * lift * (np.pi / phi) ** 2))
    train = one_mass_train(mass, 3e8, rate, preload, damping_ratio=0.1, seat_damping_ratio=0.0)
    speeds = np.linspace(0.5, 1.2, 141) * exact * 1.0013
    load_range = (speeds[0], 0.9 * exact)
    full = sweep(harmonic_cam(lift, phi), train, speeds)
    extra = [0.8 * exact]
    part, alone = headline_sweep(harmonic_cam(lift, phi), train, speeds, load_range=load_range, extra=extra)
    assert part.cam_speeds.size < speeds.size / 2 and np.all(np.diff(part.cam_speeds) > 0)
    # the events joined from the two sweeps' are those found afresh from the joined rows; the extra speed, simulated
    # with the coarse grid, has the rows and the events of its own sweep
    for got, rows, own in ((part.events, part, None), (alone.events, alone, sweep(harmonic_cam(lift, phi), train,
                                                                                        extra))):
        for name, value in vars(sweep_events(rows)).items():
            np.testing.assert_array_equal(getattr(got, name), value, err_msg=name)
        if own is not None:
            np.testing.assert_array_equal(rows.lift, own.lift)
            np.testing.assert_array_equal(rows.contact_force, own.contact_force)
    head, expected = part.headline(), full.headline()
    assert abs(head["jump_speed"] / exact - 1) < 1e-3
    assert head["jump_speed"] == expected["jump_speed"]
    assert head["max_seating_velocity"] == expected["max_seating_velocity"]

    def largest_force(r):
        inside = (r.cam_speeds >= load_range[0]) & (r.cam_speeds <= load_range[1])
        return r.contact_force[inside].max()

    assert largest_force(part) == largest_force(full)
    top = np.flatnonzero(speeds <= load_range[1])[-1]
    assert top % 10 != 0 and speeds[top] in part.cam_speeds        # the range's last speed, not a coarse one


@pytest.mark.parametrize("kind", ["one mass", "lash adjuster", "rocker"])
def test_merged_joins_each_map_when_it_is_read(kind):
    """merged's sweep of three sweeps' speeds (sweep.merged, its maps joined when first read): every per-speed field,
    the maps among them (the plunger's extension of a train with a lash adjuster, the follower's lift of a rocker
    train), equal to the bit the parts' rows put in the order of their speeds, each map joined only once read; a
    changed copy (dataclasses.replace) and a pickled one with every map; a sweep of one part is that part."""
    law = harmonic_cam(8e-3, 1.0)
    train = {"one mass": one_mass_train(0.2, 3e8, 50e3, 300.0, damping_ratio=0.1),
             "lash adjuster": replace(one_mass_train(0.2, 3e8, 50e3, 300.0, damping_ratio=0.1),
                                      adjuster=Adjuster(1.0, 20.0, 1e-4, 3e5, 1e-13, 0.05)),
             "rocker": rocker_train(3e-5, 0.12, 0.04, 1.5, 1e8, 3e7, 2e8, [CoilSpring(45e3, 400.0, 0.05, coils=0)],
                                    lash=0.3e-3)}[kind]
    speeds = np.array([200.0, 250.0, 270.0, 300.0, 320.0, 330.0])
    parts = [sweep(law, train, speeds[[1, 4]]), sweep(law, train, speeds[[0, 5]]), sweep(law, train, speeds[[2, 3]])]
    order = np.argsort(np.concatenate([p.cam_speeds for p in parts]))
    whole = SimpleNamespace(**{name: None if getattr(parts[0], name) is None else
                               np.concatenate([getattr(p, name) for p in parts])[order] for name in PER_SPEED_FIELDS})
    assert np.array_equal(whole.cam_speeds, speeds)
    assert (whole.adjuster_extension is not None) == (kind == "lash adjuster")
    assert (whole.follower_lift is not None) == (kind == "rocker")
    joined = merged(parts)
    assert not set(MAP_FIELDS) & set(vars(joined))
    for name in PER_SPEED_FIELDS:
        np.testing.assert_array_equal(getattr(joined, name), getattr(whole, name), err_msg=name)
    assert set(MAP_FIELDS) <= set(vars(joined))
    for copy in (replace(merged(parts), bounce_tolerance=2e-6), pickle.loads(pickle.dumps(merged(parts)))):
        for name in MAP_FIELDS:
            assert name in vars(copy)
            np.testing.assert_array_equal(getattr(copy, name), getattr(whole, name), err_msg=name)
    assert merged(parts[:1]) is parts[0]


def test_the_one_node_kernel_takes_only_the_one_mass_trains_order():
    """sweep.one_node sends the one-mass train (cam contact, spring, seat) to its kernel, and no network of other
    elements or another order (the springs first, as a one-node multi-mass train has them; the kernel refuses
    it)."""
    net = one_mass_train(0.2, 3e8, 50e3, 300.0).network()
    assert one_node(net)
    order = [1, 0, 2]
    swapped = replace(net, elements=tuple(net.elements[i] for i in order),
                      **{f: getattr(net, f)[order] for f in ("a", "b", "stiffness", "damping", "gap", "preload",
                                                               "unilateral", "clash_gap")})
    assert not one_node(swapped)


def test_headline_sweep_finds_a_force_levels_first_speed_as_the_full_sweep():
    """A contact force level (a lash adjuster's push, whose crossing is its float speed) crossed between two coarse
    speeds well below the jump: the headline sweep given the level simulates the speeds the crossing is interpolated
    from, so the crossing equals the full sweep's (the same speeds, the same zero_crossing); without the level it
    does not simulate them."""
    lift, phi, mass, rate, preload = 8e-3, 1.0, 0.2, 50e3, 300.0
    exact = np.sqrt(2 * (preload + rate * lift) / (mass * lift * (np.pi / phi) ** 2))
    train = one_mass_train(mass, 3e8, rate, preload, damping_ratio=0.1, seat_damping_ratio=0.0)
    speeds = np.linspace(0.5, 1.2, 141) * exact * 1.0013
    full = sweep(harmonic_cam(lift, phi), train, speeds)
    level = 0.6 * full.events.min_contact_force[0]

    def crossing(r):
        force = r.events.min_contact_force
        return zero_crossing(r.cam_speeds, force - level, force <= level)

    first = int(np.argmax(full.events.min_contact_force <= level))
    assert first % 10 > 3 and crossing(full) < 0.9 * exact    # between two coarse speeds, below the jump's window
    part = headline_sweep(harmonic_cam(lift, phi), train, speeds, levels=[level])
    assert crossing(part) == crossing(full)
    assert set(speeds[first - 3:first + 1]) <= set(part.cam_speeds)
    without = headline_sweep(harmonic_cam(lift, phi), train, speeds)
    assert not set(speeds[first - 3:first + 1]) <= set(without.cam_speeds)


def test_seating_velocity_against_a_second_integrator():
    """At the default 0.1 cam deg the seating velocity is within 1 % of scipy's DOP853 (rtol 1e-10, largest step 0.05
    cam deg) at every speed; interpolating between the sample above the seat and the one inside it (the former
    method) is several per cent off at some of them."""
    law, train = spec12()
    worst_linear = 0.0
    for rpm in (1000, 3000):
        omega = rpm * RPM
        r = sweep(law, train, [omega], revolutions=1)
        s = r.speed(0)
        times, states = seat_crossings(law, train, omega, first=True)       # 0.05 cam deg largest step
        exact = states[np.argmin(np.abs(times * omega - np.pi - s.seating_angle)), 1]
        assert exact < -0.1
        assert abs(s.seating_velocity / exact - 1) < 0.01
        linear = seating(r.theta, r.lift[0], r.velocity[0])[2]
        worst_linear = max(worst_linear, abs(linear / exact - 1))
    assert worst_linear > 0.01


def test_a_follower_that_never_touches_the_lifting_cam_has_jumped():
    """A valve hopping on an undamped seat, 25 mm high, with no spring rate and a 15.4 N preload on 0.1 kg (154 m/s^2
    down): it lands first at t1 = sqrt(2 h / a) = 18 ms, before the cam's lift begins (about 22 ms at 100 rad/s),
    and is in its second flight, far above the cam's 12 mm, until after the cam's lift ends.  The cam never touches
    it while it lifts: a jump, although the valve's first seating after its largest lift (the start) came before the
    cam's lift (hand calculation of the free flight; the former definition, separation only before that seating,
    missed it)."""
    law, _ = spec12()
    train = one_mass_train(0.1, 15e6, 0.0, 15.4, 1.5, 0.3e-3, seat_damping_ratio=0.0)
    net = replace(train.network(), x_init=np.array([0.025]))
    omega = 100.0
    r = sweep(law, SimpleNamespace(network=lambda: net), [omega], revolutions=1, tolerance=-1.0).speed(0)
    lifting = r.kinematic_lift > 0.0
    assert lifting.any() and np.all(r.contact_force[lifting] == 0.0)
    assert np.all(r.lift[lifting] > r.kinematic_lift[lifting])
    first_seat = seating(r.theta, r.lift, r.velocity)[0]
    assert first_seat < np.flatnonzero(lifting)[0]
    assert r.jump_intervals.size and r.min_contact_force == 0.0


def test_bounce_onset_does_not_move_with_the_step():
    """The bounce onset speed is where the bounce height, continuous in the speed, crosses 1 um; the seat's closing is
    located inside the step, so the height converges with the step and halving the step moves the onset by much
    less than the 40 cam rpm between the speeds of the sweep (the first speed with a counted bounce moves by whole
    speed steps).  Reference: the same sweep at half the step, 0.05 cam deg."""
    law, train = spec12()
    speeds = np.linspace(600, 1600, 26) * RPM
    coarse, fine = (sweep(law, train, speeds, revolutions=2, step_deg=step).headline()["bounce_onset_speed"]
                    for step in (0.1, 0.05))
    assert np.isfinite(coarse) and speeds[0] < coarse < speeds[-1]
    assert abs(coarse - fine) < 0.1 * (speeds[1] - speeds[0])




def test_a_halving_halves_the_time_step_where_a_halved_step_alone_would_not():
    """A slow speed integrates with sub-steps (16 at 5 rad/s on a 1e8 N/m drive), so sweep(step_deg=0.05) takes its
    sub-steps from 0.05 (8) and repeats the 0.1 deg sweep's arithmetic to the bit: the same time step.
    sweep(halvings=1) records every 0.05 deg too but keeps the 16 sub-steps: its time step halves and its lift moves.
    At a fast speed, without sub-steps, the two are the same sweep to the bit."""
    train = one_mass_train(0.2, 1e8, 50e3, 300.0, damping_ratio=0.1)
    law = harmonic_cam(8e-3, 1.0)
    base, half = (sweep(law, train, [5.0, 250.0], revolutions=1, halvings=h) for h in (0, 1))
    plain = sweep(law, train, [5.0, 250.0], revolutions=1, step_deg=0.05)
    assert base.substeps.tolist() == half.substeps.tolist() == [16, 1] and plain.substeps.tolist() == [8, 1]
    assert np.array_equal(half.theta[::2], base.theta) and np.array_equal(half.theta, plain.theta)
    assert np.array_equal(plain.lift[0, ::2], base.lift[0]) and not np.array_equal(half.lift[0], plain.lift[0])
    assert np.array_equal(half.lift[1], plain.lift[1])


def test_the_excitation_kept_is_each_laws_own():
    """The cam's samples are kept per law and grid (sweep.cam_excitation): a second law's sweep of the same grid, and
    a second grid of the same law, get their own samples (the law's derivatives on their own angles, the independent
    reference), not those kept first; a coarser grid after a finer one (every second or fourth of its samples) too."""
    from valvetrain.dynamics.sweep import cam_excitation

    law, train = spec12()
    other = harmonic_cam(8e-3, np.radians(50.0))   # unhashable (a SimpleNamespace): made every time
    for f in (law, other):
        for steps, per_step in ((360, 2), (720, 4), (360, 4), (720, 2), (360, 1), (180, 2)):
            theta, u, du = cam_excitation(f, 1.5, steps, per_step)
            assert theta.size == steps * per_step
            d = f.derivatives(theta)
            np.testing.assert_array_equal(u, 1.5 * d[0])
            np.testing.assert_array_equal(du, 1.5 * d[1])


def test_the_compile_notice_is_for_a_terminal_only(monkeypatch, capsys):
    """fuzz8: on a first run (no kernel compiled or cached) "compiling the dynamics kernels ..." went to stderr
    before a refusal found after the first sweep; like the commands' progress it is said on a terminal only."""
    from valvetrain.dynamics import sweep as sweep_module

    monkeypatch.setattr(sweep_module, "integrate_block", SimpleNamespace(signatures=[]))
    monkeypatch.setattr(sweep_module, "kernels_cached", lambda: False)
    said = []
    for tty in (False, True):
        monkeypatch.setattr(sweep_module, "_COMPILE_NOTIFIED", False)
        monkeypatch.setattr(sys.stderr, "isatty", lambda tty=tty: tty)
        sweep_module._notify_compile()
        said.append(capsys.readouterr().err)
    assert said[0] == "" and said[1].startswith("compiling the dynamics kernels")
