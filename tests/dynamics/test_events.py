"""The events of a recorded revolution (valvetrain.dynamics.events): runs of a mask, a sweep's events at once against
each speed's own, the bounce height between the samples against a second integrator (DOP853)."""

import itertools

import numpy as np
import pytest

from valvetrain.dynamics.events import bounces, largest_lift_errors, lift_error, runs, seatings, zero_crossing
from valvetrain.dynamics.models import one_mass_train
from valvetrain.dynamics.sweep import sweep

from reference_dynamics import appendix_train, harmonic_cam, reference_events


def test_runs():
    """Runs of a mask: none, one at each end, the whole array."""
    assert runs(np.zeros(4, dtype=bool)).shape == (0, 2)
    assert runs(np.array([1, 0, 0, 1], dtype=bool)).tolist() == [[0, 1], [3, 4]]
    assert runs(np.ones(3, dtype=bool)).tolist() == [[0, 3]]


def test_the_compiled_scans_of_bounces_and_seatings_against_their_definitions():
    """bounces' largest lift and returns after the first seating, and seatings' first sample at or below the seat
    after the largest lift (compiled scans over each row) against their definitions in plain Python, over random rows
    with nan samples, rows that never rise above the seat, and first seatings before, inside and beyond the row."""
    rng = np.random.default_rng(7)
    lift = rng.normal(size=(60, 12))
    lift[rng.random(lift.shape) < 0.05] = np.nan
    lift[:3] = [[-1.0], [0.0], [2.0]]
    first = rng.integers(-2, 15, lift.shape[0])
    height, count = bounces(lift, first, 0.3)
    index = seatings(np.arange(12.0), lift, np.zeros_like(lift))[0]
    for y, f, h, c, i in zip(lift, first, height, count, index, strict=True):
        after = y[max(f, 0):]
        largest = np.nan if np.isnan(after).any() else max(after, default=0.0)
        assert h == pytest.approx(max(largest, 0.0), nan_ok=True)
        assert c == sum(up for up, _ in itertools.groupby(after > 0.3))
        top = int(np.flatnonzero(np.isnan(y))[0]) if np.isnan(y).any() else int(np.flatnonzero(y == y.max())[0])
        assert i == (next((j for j in range(top, 12) if y[j] <= 0.0), 12) if y[top] > 0.0 else 12)


def test_the_compiled_largest_lift_error_is_that_of_the_map_of_errors():
    """largest_lift_errors (a compiled scan of each row) against the map of lift_error's definition, its absolute
    value and numpy's largest of each row, equal to the bit: random rows with nan, zero and negative zero samples in
    the lift and in the rigid lift (numpy's maximum keeps a nan of the rigid lift, its where drops a nan lift where
    the cam is closed)."""
    rng = np.random.default_rng(11)
    lift, rigid = rng.normal(size=(40, 15)) * 1e-3, rng.normal(size=15) * 1e-3
    for values in (lift.reshape(-1), rigid):
        draw = rng.random(values.size)
        values[draw < 0.08] = np.nan
        values[(draw >= 0.08) & (draw < 0.16)] = 0.0
        values[(draw >= 0.16) & (draw < 0.2)] = -0.0
    expected = np.abs(lift_error(lift, rigid)).max(axis=1)
    assert np.isnan(expected).any() and not np.isnan(expected).all()
    assert np.array_equal(largest_lift_errors(lift, rigid), expected, equal_nan=True)
    with pytest.raises(ValueError, match="rigid lift"):      # a rigid lift of other angles than the records'
        largest_lift_errors(lift, rigid[:-1])


def test_the_jump_speed_fit_finds_the_root_of_its_trend():
    """zero_crossing against the root known by construction: a force -0.004 (w - 237.5)(w + 50) [N] on speeds every
    2.12 rad/s from 200 (its parabola through the last three speeds without the event: the root 237.5 to round-off),
    the same force with a nan at the third-last speed (the line through the last two: its root by hand), and a trend
    without a root between the speeds (the first speed with the event)."""
    w = 200.0 + 2.12 * np.arange(30)
    force = -0.004 * (w - 237.5) * (w + 50.0)
    assert zero_crossing(w, force, force <= 0.0) == pytest.approx(237.5, rel=1e-13)
    i = int(np.flatnonzero(force <= 0.0)[0])
    gap = force.copy()
    gap[i - 3] = np.nan
    line = w[i - 1] - force[i - 1] * (w[i - 1] - w[i - 2]) / (force[i - 1] - force[i - 2])    # the secant's zero
    assert zero_crossing(w, gap, gap <= 0.0) == pytest.approx(line, rel=1e-13)
    rising = 1.0 + (w - 200.0) ** 2
    assert zero_crossing(w, rising, w >= w[10]) == w[10]
    twice = np.insert(w, i - 1, w[i - 1])                       # a speed given twice: the last of the two counts
    again = -0.004 * (twice - 237.5) * (twice + 50.0)
    assert zero_crossing(twice, again, again <= 0.0) == pytest.approx(line, rel=1e-13)
    unknown = np.where(np.arange(w.size) < i, np.nan, force)    # no finite force below the first hit: no trend
    assert zero_crossing(w, unknown, force <= 0.0) == w[i]


def test_the_seating_root_is_numpys_root_of_the_taylor_series():
    """seatings' carried seating (its compiled root of the last free sample's Taylor series) against the series' roots
    by numpy (the eigenvalues of the companion matrix), the smallest real one in (0, 2 h], on valves falling through
    the seat with random velocity, acceleration and jerk; the angle to 1e-12 of a step, the velocity to 1e-12."""
    rng = np.random.default_rng(13)
    h = 1e-5
    t = h * np.arange(40)
    for _ in range(50):
        seat = rng.uniform(10.0, 35.0, 6) * h
        v0, a0, j0 = -rng.uniform(0.05, 1.0, 6), rng.normal(0.0, 3e3, 6), rng.normal(0.0, 1e7, 6)
        tt = t[None, :] - seat[:, None]
        lift = v0[:, None] * tt + a0[:, None] / 2 * tt**2 + j0[:, None] / 6 * tt**3
        lift[:, 0] = 1e-3
        velocity = v0[:, None] + a0[:, None] * tt + j0[:, None] / 2 * tt**2
        acceleration = a0[:, None] + j0[:, None] * tt
        index, angle, vel = seatings(t, lift, velocity, acceleration, h)
        for r, i in enumerate(index):
            y, v, a = lift[r, i - 1], velocity[r, i - 1], acceleration[r, i - 1]
            jerk = (a - acceleration[r, i - 2]) / h if i >= 2 and lift[r, i - 2] > 0.0 else 0.0
            roots = np.roots([jerk / 6.0, a / 2.0, v, y])
            real = np.sort(roots[np.abs(roots.imag) <= 1e-12 * np.abs(roots)].real)
            real = real[(real > 0.0) & (real <= 2.0 * h)]
            root = real[0] if real.size else y / (y - lift[r, i]) * h
            assert angle[r] == pytest.approx(t[i - 1] + root, abs=1e-12 * h)
            assert vel[r] == pytest.approx(v + a * root + 0.5 * jerk * root**2, rel=1e-12)


@pytest.mark.parametrize("first, second", [(0.4, 1.5), (0.05, 1.95), (0.9, 1.02)])
def test_the_seating_is_the_first_of_two_roots_in_the_interval(first, second):
    """A Taylor series k (t - r1)(t - r2)(t - r3) with roots r1 = first h and r2 = second h after the last free sample
    (a valve that seats and turns back up within two steps) and r3 = -5 h: the seating is at r1, to 1e-12 of a step,
    its velocity the series' slope there, k (r1 - r2)(r1 - r3)."""
    h, k, i = 1e-5, 1e12, 10
    r1, r2, r3 = first * h, second * h, -5.0 * h
    c0, c1, c2, c3 = -k * r1 * r2 * r3, k * (r1 * r2 + r1 * r3 + r2 * r3), -k * (r1 + r2 + r3), k
    t = h * np.arange(20)
    lift, velocity, acceleration = np.full((1, 20), 1e-4), np.zeros((1, 20)), np.zeros((1, 20))
    lift[0, 0], lift[0, i - 1], lift[0, i] = 1e-3, c0, c0 + c1 * h + c2 * h**2 + c3 * h**3
    velocity[0, i - 1], acceleration[0, i - 1] = c1, 2.0 * c2
    acceleration[0, i - 2] = 2.0 * c2 - 6.0 * c3 * h
    assert lift[0, i] < 0.0
    index, angle, vel = seatings(t, lift, velocity, acceleration, h)
    assert index[0] == i
    assert angle[0] == pytest.approx(t[i - 1] + r1, abs=1e-12 * h)
    assert vel[0] == pytest.approx(k * (r1 - r2) * (r1 - r3), rel=1e-9)


def test_the_events_of_a_sweep_at_once_are_each_speeds_own():
    """SweepResult.events finds every speed's events over the speeds at once (compiled passes over each row's lift
    event, events._lifting_contact, as the design's per-speed table reads them): the same numbers, bit for bit, as
    speed_result's of each speed alone (the record of one speed, SweepResult.speed: the masks of every sample,
    separation_mask and lowest_lifting_force), over speeds that separate, bounce on an undamped seat and neither (the
    harmonic cam above, 0.6-1.2 x its jump speed)."""
    lift, phi, mass, rate, preload = 8e-3, 1.0, 0.2, 50e3, 300.0
    exact = np.sqrt(2 * (preload + rate * lift) / (mass * lift * (np.pi / phi) ** 2))
    train = one_mass_train(mass, 3e8, rate, preload, damping_ratio=0.1, seat_damping_ratio=0.0)
    r = sweep(harmonic_cam(lift, phi), train, np.linspace(0.6, 1.2, 25) * exact)
    each = r.per_speed()
    e = r.events
    assert e.jumped.any() and not e.jumped.all() and (e.bounce_count > 0).any() and np.isfinite(e.seating_angle).all()
    pairs = {"seating_angle": [s.seating_angle for s in each], "seating_velocity": [s.seating_velocity for s in each],
             "bounce_height": [s.bounce_height for s in each], "bounce_count": [s.bounce_count for s in each],
             "min_contact_force": [s.min_contact_force for s in each],
             "jumped": [s.jump_intervals.size > 0 for s in each],
             "jump_from": [s.jump_intervals[0, 0] if s.jump_intervals.size else np.nan for s in each],
             "jump_to": [s.jump_intervals[-1, 1] if s.jump_intervals.size else np.nan for s in each]}
    for name, expected in pairs.items():
        np.testing.assert_array_equal(getattr(e, name), expected, err_msg=name)


def test_the_bounce_height_is_the_peak_between_the_samples():
    """The appendix train of tests/reference_dynamics.py at 5554 engine rpm, recorded every 1 cam deg (integrated as at
    0.5: the sub-steps keep the time step): its bounce of 1.58 um is within 3 % of DOP853's (its largest lift after
    the first seating, located by the event finder, reference_dynamics.reference_events) as the peak of the cubic
    Hermite of the lift and the velocity between the samples; the largest sample, the former bounce height, misses
    it by 39 %."""
    law, train = appendix_train()
    omega = 5554 * np.pi / 60
    reference = reference_events(law, train, omega)["bounce_height"]
    r = sweep(law, train, [omega], step_deg=1.0)
    assert r.events.bounce_height[0] == pytest.approx(reference, rel=0.03)
    assert bounces(r.lift, r.events.seating_index, r.bounce_tolerance)[0][0] < 0.7 * reference
