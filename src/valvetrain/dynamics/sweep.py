"""Valve motion at speed: one simulation or a whole speed sweep of an elastic train on a lift law.

Camshaft speeds are camshaft rad/s inside; camshaft angles are rad from the cam nose (the
law's convention, :mod:`valvetrain.laws.base`).  Every speed starts at rest on the seat at
the angle opposite the nose and runs camshaft revolutions until its state at the start of a
revolution repeats (so that the residual vibration of the previous event is included), at most
``revolutions`` of them; the last revolution is recorded.

Events (Shang Hanji (1988), sections 3.1-3.2):

* follower separation (jump, 飞脱): the cam contact force is zero, the follower at or above the
  cam (the contact's gap open) and the valve off its seat while the cam's lift is positive (the rigid
  valve lift k h - x0 > 0), from the start of the cam's lift to the valve's first return to its seat;
  the jump speed of a sweep is the zero of the smallest such contact force, interpolated between the
  speeds;
* first seating: the first downward crossing of y = 0 after the valve's largest lift, located
  inside the step by carrying the last free state to y = 0; the seating velocity is dy/dt there;
* bounce (落座反跳): every return of the valve above ``bounce_tolerance`` after the first
  seating; its height is the largest lift after the first seating; the bounce onset speed of a
  sweep is where that height crosses ``bounce_tolerance``, interpolated between the speeds;
* spring surge: the largest deviation of each coil mass from its quasi-static share of the
  valve motion, and the coil clash margin (closing gap minus the compression of a coil
  segment; negative: adjacent coils meet).
"""

from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, fields, replace
from functools import cached_property
import sys
from typing import Optional
import weakref

import numpy as np
from numba import get_num_threads

from ..errors import InputError
from .kernels import blocks, integrate_block, rows

STEP_LIMIT = 1.0
"""Largest |lambda| dt of the explicit integrator (|lambda|: spectral radius of the train's state matrix,
:meth:`~.models.Network.highest_frequency`); RK4 is stable to 2.83 on the imaginary axis and damps an undamped
mode at omega dt = 1 by 0.7 % a step (Hairer, Nørsett and Wanner (1993), section IV.2)."""

BOUNCE_TOLERANCE = 1e-6
"""Lift above the seat that counts as a bounce [m] (1 um: below it the valve rocks on the seat's elasticity)."""

STATE_TOLERANCE = 1e-9
"""A speed's motion repeats when its state at the end of a camshaft revolution differs from the state at its start
by no more than 1 nm in every position (and 1 nm times the spectral radius of the train in every velocity) [m]: a
thousandth of the 1 um lift accuracy of the integrator, and 0.015 N of force on a 15000 N/mm drive."""


def substeps(highest_frequency, cam_speeds, step) -> np.ndarray:
    """Sub-steps per angle step for each speed, the smallest power of two with |lambda|_max dt <= STEP_LIMIT.

    Parameters
    ----------
    highest_frequency : float
        Spectral radius of the train's state matrix [1/s].
    cam_speeds : ndarray
        Camshaft speeds [rad/s].
    step : float
        Angle step [rad camshaft].

    Examples
    --------
    >>> substeps(1000.0, np.array([100.0, 30.0, 1.0]), np.radians(1.0)).tolist()
    [1, 1, 32]
    """
    need = highest_frequency * step / (STEP_LIMIT * np.asarray(cam_speeds, dtype=float))
    return (2 ** np.ceil(np.log2(np.maximum(need, 1.0)))).astype(np.int64)


def cam_excitation(law, rocker_ratio, steps_per_rev, per_step, start=-np.pi) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Cam displacement and its slope at the valve on one camshaft revolution.

    They do not depend on the speed (the time step of a speed is the angle step over its speed), so the samples of
    a law are made once for its grid and kept while the law lives (:data:`_EXCITATIONS`): the sweeps of a design (the
    coarse and the fine speeds, the rated speed, the refinement's halved steps) and the repeated sweeps of a study
    share them.  The arrays are shared: read them, don't change them.

    Returns
    -------
    theta, u, du : ndarray
        Camshaft angle [rad from the nose] every 2 pi / (steps_per_rev per_step) from ``start``; k h [m];
        k dh/dtheta [m/rad].
    """
    key = (float(rocker_ratio), int(steps_per_rev), int(per_step), float(start))
    try:
        kept = _EXCITATIONS.setdefault(law, {})
    except TypeError:         # a law that is not hashable or cannot be referred to weakly: made every time
        kept = {}
    if key not in kept:
        theta = start + 2.0 * np.pi * np.arange(steps_per_rev * per_step) / (steps_per_rev * per_step)
        d = law.derivatives(theta)
        kept[key] = theta, rocker_ratio * d[0], rocker_ratio * d[1]
    return kept[key]


_EXCITATIONS = weakref.WeakKeyDictionary()
"""The excitation samples of each live law (:func:`cam_excitation`), law -> {(k, steps, per step, start): arrays}."""


@dataclass(frozen=True)
class SpeedResult:
    """Dynamics of one camshaft speed over the last recorded revolution (SI; angles camshaft rad from the nose).

    Attributes
    ----------
    cam_speed : float
        [rad/s].
    theta : ndarray (n,)
        Camshaft angle.
    lift, velocity : ndarray (n,)
        Valve lift y [m] (negative: pressed into the seat) and dy/dt [m/s].
    kinematic_lift : ndarray (n,)
        Rigid valve lift k h - x0 [m] (negative while the lash is open).
    contact_force : ndarray (n,)
        Force between cam and follower at the cam [N] (k times the valve-side force).
    seat_force, spring_force : ndarray (n,)
        Seat reaction and spring force on the valve [N].
    torque : ndarray (n,)
        Camshaft drive torque of this cam, F dh/dtheta [N m] (power balance of a frictionless follower).
    separation : ndarray (n,) of bool
        Follower separation (jump) mask.
    jump_intervals : ndarray (m, 2)
        Start and end angle of each separation interval [rad].
    seating_angle, seating_velocity : float
        Angle [rad] and dy/dt [m/s] at the first seating (nan if the valve never opens).
    bounce_height : float
        Largest lift after the first seating [m] (0 if the valve stays on its seat; continuous in the speed, also
        below the bounce tolerance).
    bounce_count : int
        Returns of the valve above the bounce tolerance after the first seating.
    surge_amplitude : ndarray (N,)
        Largest deviation of each coil mass from its quasi-static share of the valve motion [m].
    clash_margin : float
        Smallest coil closing margin [m] (inf: not monitored; negative: coil clash).
    min_contact_force : float
        Smallest cam contact force while the cam carries the open valve [N] (:func:`lowest_lifting_force`; 0 with a
        jump).
    revolutions : int
        Camshaft revolutions after which the motion repeated (the cap if it did not).
    converged : bool
        The motion repeated before the cap (:data:`STATE_TOLERANCE`).
    adjuster_extension : ndarray (n,) or None
        Plunger extension of the train's hydraulic lash adjuster [m, at the adjuster] (zeros without one).
    """

    cam_speed: float
    theta: np.ndarray
    lift: np.ndarray
    velocity: np.ndarray
    kinematic_lift: np.ndarray
    contact_force: np.ndarray
    seat_force: np.ndarray
    spring_force: np.ndarray
    torque: np.ndarray
    separation: np.ndarray
    jump_intervals: np.ndarray
    seating_angle: float
    seating_velocity: float
    bounce_height: float
    bounce_count: int
    surge_amplitude: np.ndarray
    clash_margin: float
    min_contact_force: float = np.nan
    revolutions: int = 1
    converged: bool = True
    adjuster_extension: Optional[np.ndarray] = None

    @property
    def lift_error(self) -> np.ndarray:
        """Valve lift minus the rigid lift where either is open [m]."""
        return lift_error(self.lift, self.kinematic_lift)


def lift_error(lift, kinematic_lift) -> np.ndarray:
    """Valve lift y minus the rigid lift max(k h - x0, 0) where either is open, else 0 [m].

    >>> (lift_error(np.array([-1e-6, 2e-3, 0.0]), np.array([-1e-4, 2.1e-3, 1e-5])) * 1e6).round(6).tolist()
    [0.0, -100.0, -10.0]
    """
    rigid = np.maximum(kinematic_lift, 0.0)
    return np.where((lift > 0) | (rigid > 0), lift - rigid, 0.0)


def runs(mask) -> np.ndarray:
    """Start and end (exclusive) indices of the runs of True in a boolean array, shape (m, 2).

    >>> runs(np.array([0, 1, 1, 0, 1], dtype=bool)).tolist()
    [[1, 3], [4, 5]]
    """
    edges = np.diff(np.concatenate([[0], mask.astype(np.int8), [0]]))
    return np.column_stack([np.flatnonzero(edges == 1), np.flatnonzero(edges == -1)])


def seating(theta, lift, velocity, acceleration=None, step_time=None) -> tuple[int, float, float]:
    """First downward crossing of y = 0 after the largest lift: (index, angle [rad], velocity [m/s]).

    ``index`` is the first sample at or below the seat.  With ``acceleration`` [m/s^2] and ``step_time`` (the time
    between samples [s]) the last free state (the sample before, off the seat) is carried to y = 0 by its Taylor
    series y + v t + a t^2/2 + j t^3/6, the jerk j from the two free samples before the crossing; the sample inside
    the stiff seat, already slowed by it, is not used.  Without them the angle and velocity are interpolated
    linearly between the samples.  (n, nan, nan) if the valve does not open or does not return within the record.
    One record of :func:`seatings`.

    Examples
    --------
    A valve closing at a steady 0.3 m/s, sampled every 10 us; the sample inside the seat is already slowed to
    0.1 m/s, which a linear interpolation would mix in:

    >>> y, v = np.array([1e-3, 5e-6, 2e-6, -1e-6]), np.array([0.0, -0.3, -0.3, -0.1])
    >>> i, angle, vel = seating(1e-5 * np.arange(4), y, v, np.zeros(4), 1e-5)
    >>> i, round(angle * 1e5, 9), round(vel, 12)
    (3, 2.666666667, -0.3)
    >>> round(seating(1e-5 * np.arange(4), y, v)[2], 12)
    -0.166666666667
    """
    index, angle, vel = seatings(theta, lift[None], velocity[None], None if acceleration is None else
                                 acceleration[None], step_time)
    return int(index[0]), float(angle[0]), float(vel[0])


def seatings(theta, lift, velocity, acceleration=None, step_time=None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """:func:`seating` of every row of (S, n) records (one a speed) at once: (index, angle [rad], velocity [m/s]),
    arrays (S,); ``step_time`` [s] a scalar or one per row (the Taylor series' roots of :func:`_seat_times`)."""
    n = lift.shape[-1]
    every = np.arange(lift.shape[0])
    top = np.argmax(lift, axis=-1)
    down = (lift <= 0.0) & (np.arange(n) >= top[:, None])
    seated = (lift[every, top] > 0.0) & down.any(axis=-1)
    i = np.where(seated, np.argmax(down, axis=-1), n)
    k = np.flatnonzero(seated)
    index, angle, vel = i, np.full(i.shape, np.nan), np.full(i.shape, np.nan)
    if not k.size:
        return index, angle, vel
    i = i[k]
    y0, y1 = lift[k, i - 1], lift[k, i]
    w = y0 / (y0 - y1)
    t0, t1 = theta[i - 1], theta[i]
    if acceleration is None:
        v0 = velocity[k, i - 1]
        angle[k], vel[k] = t0 + w * (t1 - t0), v0 + w * (velocity[k, i] - v0)
        return index, angle, vel
    h = np.broadcast_to(np.asarray(step_time, dtype=float), index.shape)[k]
    v, a = velocity[k, i - 1], acceleration[k, i - 1]
    free = (i >= 2) & (lift[k, np.maximum(i - 2, 0)] > 0.0)
    jerk = np.where(free, (a - acceleration[k, np.maximum(i - 2, 0)]) / h, 0.0)
    t = _seat_times(y0, v, a, jerk, h, w * h)
    angle[k], vel[k] = t0 + t / h * (t1 - t0), v + a * t + 0.5 * jerk * t * t
    return index, angle, vel


def _seat_times(y, v, a, jerk, h, fallback) -> np.ndarray:
    """For each row the first time in (0, 2 h] [s] at which y + v t + a t^2/2 + jerk t^3/6 [m] reaches 0, else
    ``fallback`` (arrays (K,)): the real roots of the cubic (of the quadratic where jerk = 0) as numpy's ``roots``
    finds them, the eigenvalues of its companion matrix, of every row's matrix in one call."""
    out = np.array(fallback, dtype=float)
    cubic = jerk != 0.0
    for members, p in ((np.flatnonzero(cubic), np.stack([jerk / 6.0, a / 2.0, v, y], axis=1)),
                       (np.flatnonzero(~cubic), np.stack([a / 2.0, v, y], axis=1))):
        p = p[members]
        whole = (p[:, 0] != 0.0) & (p[:, -1] != 0.0) & np.isfinite(p).all(axis=1)   # roots() would trim the others
        for i in members[~whole]:
            out[i] = _first_root(np.roots(p[members == i][0]), h[i], out[i])
        members, p = members[whole], p[whole]
        if not members.size:
            continue
        companion = np.zeros((members.size, p.shape[1] - 1, p.shape[1] - 1))
        companion[:, 0, :] = -p[:, 1:] / p[:, :1]
        companion[:, np.arange(1, p.shape[1] - 1), np.arange(p.shape[1] - 2)] = 1.0
        roots = np.linalg.eigvals(companion)
        inside = (np.imag(roots) == 0.0) & (roots.real > 0.0) & (roots.real <= 2.0 * h[members, None])
        first = np.min(roots.real, axis=1, where=inside, initial=np.inf)
        out[members] = np.where(inside.any(axis=1), first, out[members])
    return out


def _first_root(roots, h, fallback) -> float:
    """The smallest real one of ``roots`` in (0, 2 h], else ``fallback``."""
    real = np.sort(roots[np.isreal(roots)].real)
    real = real[(real > 0.0) & (real <= 2.0 * h)]
    return real[0] if real.size else fallback


def bounce(lift, first_seating, tolerance=BOUNCE_TOLERANCE) -> tuple[float, int]:
    """The bounce after the first seating: (largest lift after it [m], returns above ``tolerance``); (0, 0) without one.

    ``first_seating`` is the index :func:`seating` returns (the record's length: no seating, no bounce).  One record
    of :func:`bounces`.

    >>> bounce(np.array([0.0, 2e-3, 0.0, 5e-6, 0.0, 3e-6, 0.0]), 2)
    (5e-06, 2)
    """
    height, count = bounces(lift[None], np.array([first_seating]), tolerance)
    return float(height[0]) if count[0] else 0.0, int(count[0])


def bounces(lift, first_seating, tolerance=BOUNCE_TOLERANCE, velocity=None, step_time=None
            ) -> tuple[np.ndarray, np.ndarray]:
    """Of every row of (S, n) records after its first seating (index, (S,)): the largest lift, not below 0 (0 where
    the valve does not seat) [m], and the returns above ``tolerance`` (runs of samples above it).

    With the ``velocity`` [m/s] records and ``step_time`` (the time between samples [s], a scalar or one per row) the
    largest lift is the peak between the samples (:func:`peak_between`), else the largest sample."""
    after = np.arange(lift.shape[-1]) >= first_seating[:, None]
    above = (lift > tolerance) & after
    count = np.count_nonzero(above[:, :1], axis=-1) + np.count_nonzero(above[:, 1:] & ~above[:, :-1], axis=-1)
    largest = np.max(lift, axis=-1, where=after, initial=-np.inf)
    if velocity is not None:
        top = np.argmax(np.where(after, lift, -np.inf), axis=-1)
        largest = np.maximum(largest, peak_between(lift, velocity, top, step_time, after))
    return np.where(after.any(axis=-1) & ~(0.0 > largest), largest, 0.0), count


def peak_between(lift, velocity, top, step_time, valid=None) -> np.ndarray:
    """The largest lift next to the sample ``top`` (S,) of each row of (S, n) records [m]: the maximum of the cubic
    Hermite of the lift and the velocity over the sample interval on either side of it where the velocity turns
    from rising to falling (``step_time``: the time between the samples [s], a scalar or one per row); -inf where
    neither does (a largest sample at an end of the record, or at a kink) or an interval's sample is not ``valid``.

    Notes
    -----
    On an interval of length h from y0, v0 to y1, v1 the Hermite p(s) = y0 H00 + h v0 H10 + y1 H01 + h v1 H11,
    s in [0, 1], interpolates a smooth motion with an error of order h^4; its slope is the quadratic
    (6 y0 + 3 m0 - 6 y1 + 3 m1) s^2 + (6 y1 - 6 y0 - 4 m0 - 2 m1) s + m0 (m = h v), whose root in [0, 1] is its
    maximum when m0 >= 0 >= m1 (the velocity's sign change brackets it).  A bounce of a few micrometres spans a few
    tens of samples: the largest sample misses the peak by up to a v^2 / 8 of the step.

    Examples
    --------
    A free flight y = 1 - (t - 0.35)^2 sampled every 0.1: the samples' largest 0.9975, the peak 1.

    >>> t = 0.1 * np.arange(8)
    >>> float(peak_between((1 - (t - 0.35) ** 2)[None], (-2 * (t - 0.35))[None], np.array([3]), 0.1)[0])
    1.0
    """
    rows, n = lift.shape
    every = np.arange(rows)
    h = np.broadcast_to(np.asarray(step_time, dtype=float), (rows,))
    best = np.full(rows, -np.inf)
    for j in (top - 1, top):                                    # the interval [j, j + 1]
        inside = (j >= 0) & (j + 1 < n)
        j0, j1 = np.clip(j, 0, n - 1), np.clip(j + 1, 0, n - 1)
        y0, y1 = lift[every, j0], lift[every, j1]
        m0, m1 = h * velocity[every, j0], h * velocity[every, j1]
        ok = inside & (m0 >= 0.0) & (m1 <= 0.0) & (m0 > m1)
        if valid is not None:
            ok &= valid[every, j0] & valid[every, j1]
        a, b = 6.0 * (y0 - y1) + 3.0 * (m0 + m1), 6.0 * (y1 - y0) - 4.0 * m0 - 2.0 * m1
        disc = np.sqrt(np.maximum(b * b - 4.0 * a * m0, 0.0))
        # the root in [0, 1] of a s^2 + b s + m0, in the form without cancellation
        q = -0.5 * (b + np.where(b >= 0.0, disc, -disc))
        with np.errstate(divide="ignore", invalid="ignore"):
            roots = np.stack([np.where(a != 0.0, q / a, np.inf), np.where(q != 0.0, m0 / q, -m0 / b)])
        roots = np.where((roots >= 0.0) & (roots <= 1.0), roots, np.nan)
        s = np.where(np.isnan(roots[0]), roots[1], roots[0])
        ok &= np.isfinite(s)
        s = np.where(ok, s, 0.0)
        s2, s3 = s * s, s * s * s
        p = (2 * s3 - 3 * s2 + 1) * y0 + (s3 - 2 * s2 + s) * m0 + (3 * s2 - 2 * s3) * y1 + (s3 - s2) * m1
        best = np.where(ok, np.maximum(best, p), best)
    return best


def lift_event(kinematic, lift, follower=None, tolerance=BOUNCE_TOLERANCE) -> np.ndarray:
    """Mask of the cam's lift event as the valve lives it: from the cam's catching the valve (the cam's lift positive,
    the valve off its seat by more than ``tolerance`` [m], the seat's elastic rocking, :data:`BOUNCE_TOLERANCE`, and
    the follower on the cam) to the valve's first return to its seat after its largest
    lift (the first sample at or below the seat), the catching the first after that return and after the cam's
    lowest point, round the revolution.

    The record is one period of the motion, so the event may run over its end: a cam without a base circle (an
    eccentric) lifts again as soon as it has lowered the valve.  A valve that rebounds from its seat bounces, and the
    cam that goes on lowering may touch it, until the cam lifts it again; from that catching to the return, the cam
    should be carrying the valve.  Without a return (a valve that never seats) every sample; without a catching (a
    valve that floats over the cam) from the first sample where the cam's lift is positive to the return.  ``lift`` (and ``follower``, the node on the
    cam where it is not the valve, :func:`separation_mask`) may hold a record per row (S, n), of one rigid lift
    ``kinematic`` (n,).

    >>> lift_event(np.array([-1.0, 1.0, 2.0, 1.0, 0.5, -1.0]), np.array([0.0, 0.5, 1.5, 0.2, -0.1, 0.3])).tolist()
    [False, True, True, True, False, False]

    An eccentric: the valve returns to its seat at sample 3 and rebounds over the end of the record, above the rising
    cam at samples 4 and 0; the cam catches it at sample 1, so the event runs from 1 to 3:

    >>> lift_event(np.array([0.1, 1.0, 2.0, 1.0, 0.2]), np.array([0.4, 0.8, 1.9, -0.1, 0.3])).tolist()
    [False, True, True, False, False]
    """
    lift = np.asarray(lift)
    follower = lift if follower is None else follower
    n = lift.shape[-1]
    index = np.arange(n)
    peak = np.expand_dims(np.argmax(lift, axis=-1), -1)
    after_peak = samples_to(lift <= 0.0, peak)
    returned = (after_peak < n) & (np.take_along_axis(lift, peak, -1) > 0.0)
    seat = (peak + after_peak) % n
    bottom = (seat + samples_to(np.broadcast_to(kinematic <= kinematic.min(), lift.shape), seat)) % n
    caught = (kinematic > 0.0) & (lift > tolerance) & (follower < kinematic)
    after = samples_to(caught, bottom)
    rising = np.flatnonzero(kinematic > 0.0)
    start = np.where(after < n, (bottom + after) % n, rising[0] if rising.size else seat)
    shifted = index - start
    inside = np.where(shifted < 0, shifted + n, shifted) < (seat - start) % n
    return np.where(returned, inside, rising.size > 0)


def samples_to(mask, origin) -> np.ndarray:
    """Samples from ``origin`` forward, round the record, to the first True of ``mask`` in each row of (S, n) (or one
    (n,) record), origin (S, 1) (or (1,)); n where the row has none.

    Two first-True searches (at or after the origin, else from the start), not the distance (index - origin) mod n of
    every sample: the integer division of that took most of the time of :func:`lift_event`, which every sweep's events
    run.

    >>> samples_to(np.array([[1, 0, 0, 1, 0], [0, 0, 0, 0, 0]], dtype=bool), np.array([[4], [1]])).tolist()
    [[1], [5]]
    """
    n = mask.shape[-1]
    ahead = mask & (np.arange(n) >= origin)
    later = np.expand_dims(np.argmax(ahead, axis=-1), -1)
    first = np.expand_dims(np.argmax(mask, axis=-1), -1)
    return np.where(np.take_along_axis(ahead, later, -1), later - origin,
                    np.where(np.take_along_axis(mask, first, -1), first + n - origin, n))


def separation_mask(contact, kinematic, lift, event=None, follower=None, tolerance=BOUNCE_TOLERANCE) -> np.ndarray:
    """Follower separation (jump): no contact force, the follower at or above the cam and the valve off its seat (by
    more than ``tolerance`` [m]: below it the valve rocks on the seat's elasticity, :data:`BOUNCE_TOLERANCE`), while
    the cam's lift is positive during the lift event (:func:`lift_event`).

    Only the cam's lift decides whether the cam should be carrying the valve: a valve thrown above the cam, or one
    that never comes down to it while the cam lifts, has jumped; a valve that rebounds from its seat after the event
    has returned it there bounces, it does not jump.  The follower must be at or above the cam's rigid lift (the
    contact's gap open): a contact whose damping releases it an instant before the gap opens has not separated.
    ``follower`` is the position of the node on the cam [m at the valve] where it is not the valve (the first drive
    part of a multi-mass train: the valve behind an elastic drive lags it).  ``contact``, ``lift`` and ``follower`` may
    hold a record per row (S, n); ``event``: their :func:`lift_event`, if
    found.

    >>> separation_mask(np.array([0.0, 0.0, 5.0, 0.0, 0.0]), np.array([-1e-4, 1e-3, 1e-3, 3e-6, 2e-6]),
    ...                 np.array([1e-4, 2e-3, 1e-3, -1e-7, 4e-6])).tolist()
    [False, True, False, False, False]

    An elastic drive: the valve 0.1 mm below the cam's rigid lift, its follower on the cam (no force: the contact's
    damping releases it) or 1 um above it (separated):

    >>> separation_mask(np.zeros(2), np.full(2, 1e-3), np.full(2, 0.9e-3),
    ...                 follower=np.array([0.999e-3, 1.001e-3])).tolist()
    [False, True]
    """
    event = lift_event(kinematic, lift, follower, tolerance) if event is None else event
    follower = lift if follower is None else follower
    return (contact <= 0.0) & (kinematic > 0.0) & (follower >= kinematic) & (lift > tolerance) & event


def lowest_lifting_force(contact, kinematic, lift, separated, event=None, tolerance=BOUNCE_TOLERANCE) -> np.ndarray:
    """Smallest cam contact force while the cam carries the open valve [N]: 0 with a separation, else the least where
    the cam's lift is positive and the valve is off its seat (by more than ``tolerance`` [m], as
    :func:`separation_mask` has it) during the lift event (:func:`lift_event`; after it
    the cam lowers the seated valve to its base circle and the force falls to 0 without a separation); nan if the
    valve never leaves its seat while the cam lifts.  ``contact`` and ``lift`` may hold a record per row (S, n),
    ``separated`` one flag per row (and ``event``, :func:`lift_event`, if found): one force per row.

    >>> float(lowest_lifting_force(np.array([300.0, 50.0, 80.0, 2.0, 1.0]), np.array([-1e-4, 1e-3, 2e-3, 2e-6, 1e-6]),
    ...                            np.array([0.0, 1e-3, 2e-3, -1e-7, 1e-7]), False))
    50.0
    """
    lifting = (kinematic > 0.0) & (lift > tolerance) & (lift_event(kinematic, lift, tolerance=tolerance) if event
                                                          is None else event)
    least = np.min(contact, axis=-1, where=lifting, initial=np.inf)
    return np.where(separated, 0.0, np.where(lifting.any(axis=-1), least, np.nan))


def speed_result(cam_speed, theta, lift, velocity, kinematic, contact, seat, spring, slope, surge, clash,
                 bounce_tolerance=BOUNCE_TOLERANCE, acceleration=None, revolutions=1, converged=True,
                 adjuster_extension=None, follower=None) -> SpeedResult:
    """Events of one speed from its recorded revolution (see the module docstring for the definitions); ``follower``
    the position of the node on the cam [m at the valve], where it is not the valve (:func:`separation_mask`)."""
    step_time = float(theta[1] - theta[0]) / cam_speed
    i_seat, seat_angle, seat_velocity = seating(theta, lift, velocity, acceleration, step_time)
    event = lift_event(kinematic, lift, follower, bounce_tolerance)
    separation = separation_mask(contact, kinematic, lift, event, follower, bounce_tolerance)
    intervals = runs(separation)
    jumps = np.column_stack([theta[intervals[:, 0]], theta[intervals[:, 1] - 1]]) if intervals.size else \
        np.zeros((0, 2))
    height, count = (float(x[0]) for x in bounces(lift[None], np.array([i_seat]), bounce_tolerance, velocity[None],
                                                   step_time))
    return SpeedResult(float(cam_speed), theta, lift, velocity, kinematic, contact, seat, spring, contact * slope,
                       separation, jumps, seat_angle, seat_velocity, height, int(count), surge, clash,
                       float(lowest_lifting_force(contact, kinematic, lift, intervals.size > 0, event, bounce_tolerance)),
                       int(revolutions), bool(converged), adjuster_extension)


@dataclass(frozen=True)
class SweepEvents:
    """The events of every speed of a :class:`SweepResult` at once, arrays (S,) (:func:`speed_result`'s of each
    speed; angles camshaft rad from the nose).

    Attributes
    ----------
    seating_index : ndarray of int
        First sample at or below the seat after the largest lift (n: no seating).
    seating_angle, seating_velocity : ndarray
        At the first seating [rad], [m/s] (nan: no seating).
    bounce_height : ndarray
        Largest lift after the first seating [m].
    bounce_count : ndarray of int
        Returns above the bounce tolerance after it.
    jumped : ndarray of bool
        Follower separation.
    jump_from, jump_to : ndarray
        Where the first separation starts and the last one ends [rad] (nan: none).
    min_contact_force : ndarray
        :func:`lowest_lifting_force` [N].
    """

    seating_index: np.ndarray
    seating_angle: np.ndarray
    seating_velocity: np.ndarray
    bounce_height: np.ndarray
    bounce_count: np.ndarray
    jumped: np.ndarray
    jump_from: np.ndarray
    jump_to: np.ndarray
    min_contact_force: np.ndarray


def sweep_events(result) -> SweepEvents:
    """The :class:`SweepEvents` of a :class:`SweepResult`: :func:`speed_result`'s events over the speeds at once."""
    theta, kinematic, lift = result.theta, result.kinematic_lift, result.lift
    step_time = float(theta[1] - theta[0]) / result.cam_speeds
    index, angle, velocity = seatings(theta, lift, result.velocity, result.acceleration, step_time)
    event = lift_event(kinematic, lift, result.follower_lift, result.bounce_tolerance)
    separation = separation_mask(result.contact_force, kinematic, lift, event, result.follower_lift,
                                 result.bounce_tolerance)
    jumped = separation.any(axis=-1)
    last = lift.shape[-1] - 1 - np.argmax(separation[:, ::-1], axis=-1)
    height, count = bounces(lift, index, result.bounce_tolerance, result.velocity, step_time)
    return SweepEvents(index, angle, velocity, height, count, jumped,
                       np.where(jumped, theta[np.argmax(separation, axis=-1)], np.nan),
                       np.where(jumped, theta[last], np.nan),
                       lowest_lifting_force(result.contact_force, kinematic, lift, jumped, event, result.bounce_tolerance))


def force_reached_zero(events) -> np.ndarray:
    """Of every speed of :class:`SweepEvents`: whether the smallest contact force while the cam lifts has reached
    zero, with a separation or without (a force that touches zero, which the contact law clamps there, an instant
    before the valve would rise above the cam: the speeds above separate).

    >>> e = SweepEvents(*([np.zeros(3)] * 5), np.array([False, False, True]), *([np.zeros(3)] * 2),
    ...                 np.array([26.7, 0.0, 0.0]))
    >>> force_reached_zero(e).tolist()
    [False, True, True]
    """
    return events.jumped | (events.min_contact_force <= 0.0)


def zero_crossing(speeds, values, hit) -> float:
    """The speed where a quantity reaches its limit, interpolated between the speeds of a sweep.

    Parameters
    ----------
    speeds : ndarray (S,)
        Ascending speeds.
    values : ndarray (S,)
        The quantity less its limit: positive where the limit is not reached.
    hit : ndarray (S,) of bool
        Where the limit is reached (the event happens).

    Returns
    -------
    float
        nan if no speed has the event; the lowest speed if the first has it; else the zero of the smooth trend of
        ``values`` through the last speeds without the event (a parabola through three, a line through two), kept
        between the last speed without the event and the first with it (the trend of the speeds above is not
        smooth: an event clamps the quantity, e.g. a contact force at 0).

    Examples
    --------
    A force 400 - 0.01 w^2 [N] (zero at w = 200) sampled every 15 rad/s:

    >>> w = np.arange(140.0, 260.0, 15.0)
    >>> f = 400.0 - 0.01 * w**2
    >>> round(zero_crossing(w, np.maximum(f, 0.0), f <= 0.0), 9)
    200.0
    """
    first = np.flatnonzero(hit)
    if first.size == 0:
        return np.nan
    i = int(first[0])
    if i == 0:
        return float(speeds[0])
    fit = np.arange(max(0, i - 3), i)
    fit = fit[np.isfinite(values[fit])]
    if fit.size < 2 or fit[-1] != i - 1:
        return float(speeds[i])
    x0 = speeds[i - 1]
    roots = np.roots(np.polyfit(speeds[fit] - x0, values[fit], fit.size - 1))
    real = roots[np.isreal(roots)].real + x0
    inside = real[(real >= x0) & (real <= speeds[i])]
    return float(inside.min()) if inside.size else float(speeds[i])


def level_crossing(speeds, values, level) -> float:
    """The lowest speed where ``values`` rises above ``level``, linear between the two speeds around it (nan: none;
    the lowest speed if it is already above).

    >>> level_crossing(np.array([10.0, 20.0, 30.0]), np.array([0.0, 1e-6, 3e-6]), 2e-6)
    25.0
    """
    above = np.flatnonzero(values > level)
    if above.size == 0:
        return np.nan
    i = int(above[0])
    if i == 0:
        return float(speeds[0])
    w = (level - values[i - 1]) / (values[i] - values[i - 1])
    return float(speeds[i - 1] + w * (speeds[i] - speeds[i - 1]))


@dataclass(frozen=True)
class SweepResult:
    """A speed sweep: maps over (speed, camshaft angle) and the headline numbers.

    Attributes
    ----------
    cam_speeds : ndarray (S,)
        [rad/s].
    theta : ndarray (n,)
        Camshaft angle of the recorded revolution [rad from the nose].
    kinematic_lift : ndarray (n,)
        Rigid valve lift k h - x0 [m].
    lift, velocity, acceleration, contact_force, seat_force, spring_force : ndarray (S, n)
        As in :class:`SpeedResult`; the valve acceleration [m/s^2].
    slope : ndarray (n,)
        dh/dtheta of the law [m/rad] (for the torque).
    surge_amplitude : ndarray (S, N)
        Coil deviations [m] (N = coil masses of the train).
    clash_margin : ndarray (S,)
        Smallest coil closing margin [m].
    substeps : ndarray (S,)
        Integrator sub-steps per angle step used for each speed.
    revolutions : ndarray (S,) of int
        Camshaft revolutions after which each speed repeated (the cap where it did not).
    converged : ndarray (S,) of bool
        The speed repeated within :data:`STATE_TOLERANCE` before the cap.
    adjuster_extension : ndarray (S, n) or None
        Plunger extension of the train's hydraulic lash adjuster over the recorded revolution [m, at the adjuster]
        (zeros without one).
    follower_lift : ndarray (S, n) or None
        Position of the node on the cam [m at the valve] where it is not the valve (the first drive part of a
        multi-mass train); None: the valve is on the cam.
    """

    cam_speeds: np.ndarray
    theta: np.ndarray
    kinematic_lift: np.ndarray
    lift: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray
    contact_force: np.ndarray
    seat_force: np.ndarray
    spring_force: np.ndarray
    slope: np.ndarray
    surge_amplitude: np.ndarray
    clash_margin: np.ndarray
    substeps: np.ndarray
    revolutions: np.ndarray
    converged: np.ndarray
    bounce_tolerance: float = BOUNCE_TOLERANCE
    adjuster_extension: Optional[np.ndarray] = None
    follower_lift: Optional[np.ndarray] = None

    def speed(self, i) -> SpeedResult:
        """The :class:`SpeedResult` of the i-th speed."""
        return speed_result(self.cam_speeds[i], self.theta, self.lift[i], self.velocity[i], self.kinematic_lift,
                            self.contact_force[i], self.seat_force[i], self.spring_force[i], self.slope,
                            self.surge_amplitude[i], float(self.clash_margin[i]), self.bounce_tolerance,
                            self.acceleration[i], self.revolutions[i], self.converged[i],
                            None if self.adjuster_extension is None else self.adjuster_extension[i],
                            None if self.follower_lift is None else self.follower_lift[i])

    def per_speed(self) -> list[SpeedResult]:
        """Every :class:`SpeedResult` of the sweep."""
        return [self.speed(i) for i in range(self.cam_speeds.size)]

    @property
    def lift_error(self) -> np.ndarray:
        """Map of valve lift minus rigid lift where either is open [m], shape (S, n)."""
        return lift_error(self.lift, self.kinematic_lift)

    @property
    def torque(self) -> np.ndarray:
        """Map of the camshaft drive torque F dh/dtheta [N m], shape (S, n)."""
        return self.contact_force * self.slope

    @cached_property
    def events(self) -> SweepEvents:
        """The :class:`SweepEvents` of every speed (:func:`sweep_events`), found once."""
        return sweep_events(self)

    def headline(self) -> dict:
        """Jump speed, bounce onset speed and the largest seating speed of the sweep (from :attr:`events`).

        Returns
        -------
        dict
            ``jump_speed``: the camshaft speed [rad/s] where the smallest contact force while the cam lifts
            (:func:`lowest_lifting_force`) reaches zero, interpolated between the speeds (:func:`zero_crossing`)
            through those below the first whose force has reached it (:func:`force_reached_zero`);
            ``bounce_onset_speed``: where the bounce height (continuous in the speed) first exceeds the bounce
            tolerance, linear between the speeds (nan if none): unlike the first speed with a counted bounce, it
            does not move with the angle step; ``max_seating_velocity``: the largest |dy/dt| at seating [m/s] and
            ``max_seating_velocity_speed`` where it occurs; ``coil_clash_speed``: the lowest speed whose coils
            meet (nan if none).
        """
        events = self.events
        seat = np.abs(events.seating_velocity)
        clash = self.cam_speeds[self.clash_margin < 0.0]
        worst = int(np.nanargmax(seat)) if np.isfinite(seat).any() else None
        return {"jump_speed": zero_crossing(self.cam_speeds, events.min_contact_force, force_reached_zero(events)),
                "bounce_onset_speed": level_crossing(self.cam_speeds, events.bounce_height, self.bounce_tolerance),
                "max_seating_velocity": float(seat[worst]) if worst is not None else np.nan,
                "max_seating_velocity_speed": float(self.cam_speeds[worst]) if worst is not None else np.nan,
                "coil_clash_speed": float(clash.min()) if clash.size else np.nan}


def _notify_compile():
    """Say once on stderr that the kernels are being compiled, when no compiled or cached kernel is at hand."""
    global _COMPILE_NOTIFIED
    if _COMPILE_NOTIFIED or integrate_block.signatures:
        return
    _COMPILE_NOTIFIED = True
    try:
        cached = bool(integrate_block._cache._cache_file._load_index())   # numba's cache index of this kernel
    except (AttributeError, OSError):
        cached = False
    if not cached:
        print("compiling the dynamics kernels (once; later runs load them from the cache) ...", file=sys.stderr,
              flush=True)


_COMPILE_NOTIFIED = False


def sweep_size(network, cam_speeds, revolutions, step_deg) -> tuple[int, int]:
    """Work and memory of a sweep before it runs: (integrator steps x elements, bytes of the recorded maps).

    The work counts every sub-step of every speed for ``revolutions`` (the cap: a speed that repeats stops
    earlier) times the elements of the network; the memory is the recorded revolution of every speed (the valve's
    position, velocity and acceleration, the follower's position where it is another node, the forces of the
    contact, the seat and the springs, 8 bytes each).

    >>> from .models import one_mass_train
    >>> sweep_size(one_mass_train(0.25, 15e6, 67.5e3, 400.0).network(), [300.0, 400.0], 3, 0.1)
    (64800, 345600)
    """
    steps = int(round(360.0 / step_deg))
    n_sub = substeps(network.highest_frequency(), np.atleast_1d(np.asarray(cam_speeds, dtype=float)),
                     np.radians(step_deg))
    recorded = 5 + len(recorded_nodes(network))
    return (int(n_sub.sum()) * steps * int(revolutions) * network.a.size,
            n_sub.size * steps * recorded * 8)


def recorded_nodes(network) -> np.ndarray:
    """The nodes a sweep records: the valve, and the node on the cam where it is another (a multi-mass train's first
    drive part, for the separation of the follower, :func:`separation_mask`)."""
    follower = int(network.b[network.cam_element])
    return np.array([network.valve] + ([follower] if follower != network.valve else []), dtype=np.int64)


def sweep(law, train, cam_speeds, revolutions=3, step_deg=0.1, progress=None, bounce_tolerance=BOUNCE_TOLERANCE,
          tolerance=STATE_TOLERANCE, halvings=0) -> SweepResult:
    """Simulate an elastic train on a lift law at every camshaft speed of a sweep.

    Parameters
    ----------
    law : valvetrain.laws.base.LiftLaw
        The cam (tappet lift h(theta) [m], camshaft angle from the nose).
    train : OneMassTrain or MultiMassTrain
        Anything with a ``network()`` method (:mod:`.models`).
    cam_speeds : array_like
        Camshaft speeds [rad/s] (engine rpm: omega = pi n / 30 / 2 for a four-stroke).
    revolutions : int
        Most camshaft revolutions per speed: a speed stops once its state at the start of a revolution repeats
        within :data:`STATE_TOLERANCE` (``SweepResult.revolutions`` says after how many), else after this many;
        the last revolution is recorded.
    step_deg : float
        Recording and base integration step [camshaft deg]; it must divide 360.  Slow speeds integrate with
        sub-steps (:func:`substeps`).
    progress : callable, optional
        ``progress(done, total)`` after each block of speeds (the compiled kernel itself never calls Python).
    bounce_tolerance : float
        Lift that counts as a bounce [m].
    tolerance : float
        Largest change of the state over a revolution at which a speed repeats [m] (:data:`STATE_TOLERANCE`; a
        negative value runs every speed for ``revolutions``).
    halvings : int
        Halve the step this many times: the recording step is ``step_deg`` / 2^halvings and each speed keeps the
        sub-steps of ``step_deg``, so that its time step halves with each (the error estimates of
        :func:`.accuracy.refine`).

    Returns
    -------
    SweepResult
    """
    net = train.network()
    speeds = np.atleast_1d(np.asarray(cam_speeds, dtype=float))
    steps = int(round(360.0 / step_deg))
    if not np.isclose(steps * step_deg, 360.0, rtol=0, atol=1e-9):
        raise InputError(f"the step {step_deg} deg does not divide the camshaft revolution")
    if revolutions < 1 or np.any(speeds <= 0.0) or halvings < 0:
        raise InputError("sweep: at least one revolution, positive camshaft speeds and no negative halvings are needed")
    rate = net.highest_frequency()
    n_sub = substeps(rate, speeds, 2.0 * np.pi / steps)
    steps *= 2**halvings
    dtheta = 2.0 * np.pi / steps
    per_step = 2 * int(n_sub.max())
    theta, u, du = cam_excitation(law, net.rocker_ratio, steps, per_step)
    rec_nodes = recorded_nodes(net)
    springs = np.asarray(net.spring_elements, dtype=np.int64)
    s_count, n_nodes, n_elems = speeds.size, net.mass.size, net.a.size
    lift, velocity, acceleration, contact, seat, spring = (np.empty((s_count, steps)) for _ in range(6))
    follower = np.empty((s_count if rec_nodes.size > 1 else 0, steps))
    out_clash = np.empty((s_count, n_elems))
    out_surge = np.empty((s_count, n_nodes))
    out_revs = np.zeros(s_count, dtype=np.int64)
    out_z = np.zeros((s_count, steps))
    ra, rb = rows(net.a, net.b, n_nodes)
    workers = get_num_threads()
    order, start, seq = blocks(n_sub, workers)
    inv_mass = 1.0 / net.mass

    def run(j):
        idx = order[start[j]:start[j + 1]]
        integrate_block(idx, speeds, int(n_sub[idx[0]]), dtheta, u, du, per_step, steps, int(revolutions),
                        float(tolerance), float(rate), inv_mass, net.x_init, ra, rb, net.stiffness, net.damping,
                        net.gap, net.preload, net.unilateral, int(net.seat_element), int(rec_nodes[-1]) if
                        rec_nodes.size > 1 else -1, springs, float(net.rocker_ratio), net.clash_gap, int(net.valve),
                        net.surge_weight, net.adjuster, int(net.cam_element), int(net.variable_node),
                        net.variable_mass, lift, velocity, acceleration, contact, seat, spring, follower, out_clash,
                        out_surge, out_revs, out_z)
        return idx.size

    _notify_compile()
    if seq.size == 1 or workers == 1:
        done = 0
        for j in seq:
            done += run(j)
            if progress is not None:
                progress(done, s_count)
    else:
        with ThreadPoolExecutor(min(workers, seq.size)) as pool:
            done = 0
            for size in pool.map(run, seq):
                done += size
                if progress is not None:
                    progress(done, s_count)
    coils = net.surge_weight > 0.0
    return SweepResult(speeds, theta[::per_step], u[::per_step] - net.lash, lift, velocity, acceleration, contact, seat,
                       spring, du[::per_step] / net.rocker_ratio, out_surge[:, coils], out_clash.min(axis=1), n_sub,
                       np.where(out_revs > 0, out_revs, int(revolutions)), out_revs > 0, bounce_tolerance, out_z,
                       follower if rec_nodes.size > 1 else None)


HEADLINE_STRIDE = 10
"""Every how many speeds of a sweep :func:`headline_sweep` simulates first (the coarse grid)."""

PER_SPEED_FIELDS = ("cam_speeds", "lift", "velocity", "acceleration", "contact_force", "seat_force", "spring_force",
                    "surge_amplitude", "clash_margin", "substeps", "revolutions", "converged", "adjuster_extension",
                    "follower_lift")
"""The fields of a :class:`SweepResult` with one row per speed."""


def merged(parts) -> SweepResult:
    """One :class:`SweepResult` of the speeds of several sweeps of the same train on the same law, by ascending speed,
    with the parts' :attr:`~SweepResult.events` joined where every part has found its own (the events of a speed are
    found from its rows alone, :func:`sweep_events`).

    Each speed of a sweep is an independent problem integrated on the same excitation samples (:mod:`.kernels`), so a
    speed's rows do not depend on the sweep it was simulated in, but for the revolutions it runs: a block of speeds
    runs until all of them repeat, so its last revolution may differ by up to :data:`STATE_TOLERANCE`."""
    if len(parts) == 1:
        return parts[0]
    rank = np.argsort(np.argsort(np.concatenate([p.cam_speeds for p in parts]), kind="stable"))
    at = np.split(rank, np.cumsum([p.cam_speeds.size for p in parts])[:-1])

    def joined(rows):
        first = rows[0]
        out = np.empty((rank.size, *first.shape[1:]), dtype=first.dtype)
        for part, where in zip(rows, at, strict=True):
            out[where] = part
        return out

    out = replace(parts[0], **{f: joined([getattr(p, f) for p in parts]) for f in PER_SPEED_FIELDS
                               if getattr(parts[0], f) is not None})
    if all("events" in vars(p) for p in parts):
        vars(out)["events"] = SweepEvents(*(joined([getattr(p.events, f.name) for p in parts])
                                            for f in fields(SweepEvents)))
    return out


def speeds_of(result, index) -> SweepResult:
    """The :class:`SweepResult` of the speeds ``index`` (an integer array) of ``result``, with their events where
    ``result`` has found its own."""
    out = replace(result, **{f: getattr(result, f)[index] for f in PER_SPEED_FIELDS if getattr(result, f) is not None})
    if "events" in vars(result):
        vars(out)["events"] = SweepEvents(*(getattr(result.events, f.name)[index] for f in fields(SweepEvents)))
    return out


def seating_events(result) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Per speed of a :class:`SweepResult`: whether the follower separates, the smallest contact force while the cam
    lifts [N] (:func:`lowest_lifting_force`) and |dy/dt| at the first seating [m/s] (nan: no seating); the events of
    :func:`speed_result` that decide the sweep's jump speed and its largest seating velocity."""
    events = result.events
    return events.jumped, events.min_contact_force, np.abs(events.seating_velocity)


SEATING_NEAR = 0.95
"""The coarse speeds up to the rated one whose seating velocity is at least this share of their largest are refined
by :func:`headline_sweep`."""


def headline_sweep(law, train, cam_speeds, revolutions=3, step_deg=0.1, bounce_tolerance=BOUNCE_TOLERANCE,
                   load_range=(0.0, np.inf), stride=HEADLINE_STRIDE, seating_top=np.inf,
                   extra=None) -> SweepResult | tuple[SweepResult, SweepResult]:
    """The speeds of a sweep that decide its jump speed, its largest seating velocity and its largest loads, without
    the others.

    Parameters are those of :func:`sweep`; ``load_range`` is the speed range [rad/s camshaft] whose cam force loads
    the parts (the strength stage's), ``stride`` spaces the coarse grid, ``seating_top`` is the highest speed
    [rad/s camshaft] of the seating velocity graded (the rated speed), ``extra`` more camshaft speeds [rad/s] to
    simulate with the coarse grid (the rated speed: one kernel call fewer), returned apart.

    Returns
    -------
    SweepResult, or (SweepResult, SweepResult) with ``extra``
        The speeds simulated, a subset of ``cam_speeds``, by ascending speed (and those of ``extra``, in their
        order), each with its :attr:`~SweepResult.events` found.

    Notes
    -----
    Simulated, in two sweeps:

    1. the coarse grid: every ``stride``-th speed, the lowest and the highest, the first and the last speed
       inside ``load_range``, and the last speed up to ``seating_top``;
    2. the speeds between the last coarse speed without a separation and the first with one, and the two below
       them: the first speed of the full grid with a separation and the speeds :func:`zero_crossing` fits below it;
       the same below the first coarse speed whose contact force falls to zero while the cam lifts (a separation
       that comes and goes with the speed starts near it); the speeds within ``stride`` of the coarse speed with the
       largest seating velocity, of those up to ``seating_top`` whose seating velocity is within
       :data:`SEATING_NEAR` of their largest (the seating velocity has a peak at each harmonic of the cam the train
       meets: the built-in example's exhaust peaks at 6161 rpm between two coarse speeds lower than one 600 rpm
       above; of these speeds only those up to ``seating_top``), and of the coarse speed inside ``load_range`` with
       the largest contact force (only those inside ``load_range``).

    So :meth:`SweepResult.headline` gives the full sweep's jump speed unless a separation starts and ends between two
    coarse speeds below the first coarse speed that separates or loses its contact force; the largest seating
    velocity (of all the speeds, and of those up to ``seating_top``) and the largest contact force (in
    ``load_range``) are the full sweep's where they lie within ``stride`` speeds of the coarse grid's largest (or at
    an end of ``load_range``).  The sweep's other headlines (the bounce
    onset, the coil clash) and its maps have the simulated speeds only.
    """
    speeds = np.atleast_1d(np.asarray(cam_speeds, dtype=float))
    n = speeds.size
    done = np.zeros(n, dtype=bool)
    parts = []
    inside = (speeds >= load_range[0] * (1.0 - 1e-12)) & (speeds <= load_range[1] * (1.0 + 1e-12))
    more_speeds = np.zeros(0) if extra is None else np.atleast_1d(np.asarray(extra, dtype=float))

    def simulated(indices, also=np.zeros(0)):
        idx = np.unique(np.clip(np.asarray(indices, dtype=np.int64), 0, n - 1))
        idx = idx[~done[idx]]
        if idx.size or also.size:
            both = sweep(law, train, np.concatenate([speeds[idx], also]), revolutions, step_deg,
                         bounce_tolerance=bounce_tolerance)
            both.events     # noqa: B018 - found once here; merged() joins the parts' events
            parts.append(speeds_of(both, np.arange(idx.size)) if also.size else both)
            done[idx] = True
            return np.flatnonzero(done), merged(parts), speeds_of(both, idx.size + np.arange(also.size))
        return np.flatnonzero(done), merged(parts), None

    ends = np.flatnonzero(inside)[[0, -1]] if inside.any() else []
    graded = speeds <= seating_top * (1.0 + 1e-12)
    index, result, extra_result = simulated(np.concatenate([np.arange(0, n, stride), [n - 1], ends,
                                                            np.flatnonzero(graded)[-1:]]), more_speeds)
    jumped, force, seat = seating_events(result)
    below = np.where(graded[index], seat, np.nan)
    near = index[below >= SEATING_NEAR * np.nanmax(below)] if np.isfinite(below).any() else []
    window = np.arange(1 - stride, stride)
    more = [c + window for c in ([index[np.nanargmax(seat)]] if np.isfinite(seat).any() else [])]
    more += [c + window[graded[np.clip(c + window, 0, n - 1)]] for c in near]
    if inside.any():
        c = index[inside[index]][np.argmax(result.contact_force[inside[index]].max(axis=1))]
        more.append(c + window[inside[np.clip(c + window, 0, n - 1)]])
    for hit in (jumped, jumped | (force <= 0.0)):
        if hit.any() and hit.argmax() > 0:
            more.append(np.arange(index[hit.argmax() - 1] - 2, index[hit.argmax()]))
    result = simulated(np.concatenate(more or [[]]))[1]
    return result if extra is None else (result, extra_result)


def simulate(law, train, cam_speed, revolutions=3, step_deg=0.1, bounce_tolerance=BOUNCE_TOLERANCE) -> SpeedResult:
    """Simulate one camshaft speed [rad/s]; a :class:`SpeedResult` of the last revolution (see :func:`sweep`)."""
    return sweep(law, train, [cam_speed], revolutions, step_deg, bounce_tolerance=bounce_tolerance).speed(0)


def speed_range(low, high, count=200) -> np.ndarray:
    """``count`` camshaft speeds evenly spaced from ``low`` (idle) to ``high`` (over-speed) [rad/s].

    The issue's default sweep is 200 speeds; an engine speed n [rpm] of a four-stroke turns the camshaft at
    pi n / 60 rad/s.

    >>> speed_range(np.pi * 800 / 60, np.pi * 7000 / 60).size
    200
    """
    return np.linspace(low, high, count)
