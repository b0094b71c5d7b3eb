"""The events of a valve's motion over a recorded revolution (Shang Hanji (1988), sections 3.1-3.2): the first
seating and its velocity, the bounces after it, the follower's separation (jump) and the smallest contact force while
the cam lifts, of one speed or of every speed of a sweep at once (:class:`SweepEvents`), and the speeds where a sweep's
events start (:func:`zero_crossing`, :func:`level_crossing`).  The definitions are in :mod:`.sweep`'s docstring; the
simulation that records the revolutions is :func:`.sweep.sweep`.
"""

from dataclasses import dataclass

import numpy as np
from numba import njit

from ..errors import InputError

BOUNCE_TOLERANCE = 1e-6
"""Lift above the seat that counts as a bounce [m] (1 um: below it the valve rocks on the seat's elasticity)."""


def lift_error(lift, kinematic_lift) -> np.ndarray:
    """Valve lift y minus the rigid lift max(k h - x0, 0) where either is open, else 0 [m].

    >>> (lift_error(np.array([-1e-6, 2e-3, 0.0]), np.array([-1e-4, 2.1e-3, 1e-5])) * 1e6).round(6).tolist()
    [0.0, -100.0, -10.0]
    """
    rigid = np.maximum(kinematic_lift, 0.0)
    return np.where((lift > 0) | (rigid > 0), lift - rigid, 0.0)


def largest_lift_errors(lift, kinematic_lift) -> np.ndarray:
    """The largest |:func:`lift_error`| of each row of ``lift`` (S, n) [m] against the rigid lift (n,) [m], as
    ``np.abs(lift_error(lift, kinematic_lift)).max(axis=1)`` (nan where one is), without the map of the errors.

    >>> largest_lift_errors(np.array([[-1e-6, 2e-3, 0.0], [0.0, 2.1e-3, 3e-5]]), np.array([-1e-4, 2.1e-3, 1e-5])
    ...                     ).round(9).tolist()
    [0.0001, 2e-05]
    """
    rows = np.ascontiguousarray(lift, dtype=float)
    rigid = np.ascontiguousarray(kinematic_lift, dtype=float)
    if rigid.ndim != 1 or rows.shape[-1:] != rigid.shape:
        raise InputError(f"largest_lift_errors: a rigid lift of {rigid.shape} samples for records of {rows.shape}")
    return _largest_lift_errors(rows.reshape(-1, rigid.size), rigid)


@njit(cache=True, nogil=True)
def _largest_lift_errors(lift, kinematic) -> np.ndarray:
    """:func:`largest_lift_errors`, compiled: the arithmetic of :func:`lift_error` on each sample (numpy's maximum
    keeps a nan of the rigid lift) and numpy's largest (a nan is kept); a map of the errors, made and read again,
    took a fortieth of a tolerance sample."""
    count, n = lift.shape
    rigid = np.empty(n)
    for j in range(n):
        k = kinematic[j]
        rigid[j] = k if (k > 0.0) | (k != k) else 0.0
    out = np.empty(count)
    for r in range(count):
        top, nan = 0.0, False
        for j in range(n):
            y = lift[r, j]
            e = abs(y - rigid[j]) if (y > 0.0) | (rigid[j] > 0.0) else 0.0
            nan |= e != e
            top = e if e > top else top
        out[r] = np.nan if nan else top
    return out


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
    arrays (S,); ``step_time`` [s] a scalar or one per row (the Taylor series' roots of :func:`_seat_states`)."""
    lift = np.ascontiguousarray(lift, dtype=float)
    i = _seat_indices(lift)
    if acceleration is not None:
        h = np.ascontiguousarray(np.broadcast_to(np.asarray(step_time, dtype=float), i.shape))
        angle, vel = _seat_states(np.ascontiguousarray(theta, dtype=float), lift,
                                  np.ascontiguousarray(velocity, dtype=float),
                                  np.ascontiguousarray(acceleration, dtype=float), i, h)
        return i, angle, vel
    k = np.flatnonzero(i < lift.shape[-1])
    index, angle, vel = i, np.full(i.shape, np.nan), np.full(i.shape, np.nan)
    if not k.size:
        return index, angle, vel
    i = i[k]
    y0, y1 = lift[k, i - 1], lift[k, i]
    w = y0 / (y0 - y1)
    t0, t1 = theta[i - 1], theta[i]
    v0 = velocity[k, i - 1]
    angle[k], vel[k] = t0 + w * (t1 - t0), v0 + w * (velocity[k, i] - v0)
    return index, angle, vel


@njit(cache=True, nogil=True)
def _seat_indices(lift) -> np.ndarray:
    """The first sample at or below the seat from the largest lift on (the first of equal ones, the first nan) of each
    row of ``lift`` (S, n) [m], where that lift is positive; else n.  Compiled: the whole-array version (the masks of
    every sample, two first-True searches) took a sixth of a sweep's events."""
    count, n = lift.shape
    out = np.full(count, n, dtype=np.int64)
    for r in range(count):
        y = lift[r]
        top = 0
        for j in range(1, n):
            if y[top] != y[top]:
                break
            if y[j] > y[top] or y[j] != y[j]:
                top = j
        if y[top] > 0.0:
            for j in range(top, n):
                if y[j] <= 0.0:
                    out[r] = j
                    break
    return out


@njit(cache=True, nogil=True, error_model="numpy")
def _seat_states(theta, lift, velocity, acceleration, index, h) -> tuple[np.ndarray, np.ndarray]:
    """The angle [rad] and the velocity [m/s] of each row's first seating (:func:`seating` with the acceleration; nan
    where ``index`` is the row's length): the last free sample's state y, v, a carried by its Taylor series
    y + v t + a t^2/2 + j t^3/6 (the jerk j from the two free samples before the crossing, else 0) to its first root t
    in (0, 2 h] (:func:`_first_root`), else to the linear interpolation's w h; ``h`` (S,) the time between samples
    [s].  Compiled: the roots as the eigenvalues of each row's companion matrix, with the masks and gathers around
    them, took a twentieth of a tolerance sample."""
    count, n = lift.shape
    angle, vel = np.full(count, np.nan), np.full(count, np.nan)
    for r in range(count):
        i = index[r]
        if i >= n:
            continue
        y0, y1 = lift[r, i - 1], lift[r, i]
        w = y0 / (y0 - y1)
        v, a = velocity[r, i - 1], acceleration[r, i - 1]
        back = max(i - 2, 0)
        jerk = (a - acceleration[r, back]) / h[r] if (i >= 2) & (lift[r, back] > 0.0) else 0.0
        t = _first_root(y0, v, a / 2.0, jerk / 6.0, 2.0 * h[r], w * h[r])
        angle[r] = theta[i - 1] + t / h[r] * (theta[i] - theta[i - 1])
        vel[r] = v + a * t + 0.5 * jerk * t * t
    return angle, vel


@njit(cache=True, nogil=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _first_root(c0, c1, c2, c3, top, fallback) -> float:
    """The smallest root in (0, ``top``] of the cubic c0 + c1 t + c2 t^2 + c3 t^3 (c3 = 0: a quadratic) where it
    changes sign or vanishes, else ``fallback``: the interval cut at the cubic's turning points (the roots of its
    derivative, :func:`_quadratic_roots`), where it is monotone, and each piece whose ends differ in sign bisected to
    adjacent floats.  The companion matrix's eigenvalues
    (:func:`numpy.roots`) give the same roots to round-off.  A root where the cubic touches zero without changing
    sign (a pair of complex roots to them, within round-off) is found only where the cubic is exactly 0 at a turning
    point."""
    cuts = [0.0]
    count, low, high = _quadratic_roots(3.0 * c3, 2.0 * c2, c1)      # the derivative's
    if count > 0 and 0.0 < low < top:
        cuts.append(low)
    if count > 1 and 0.0 < high < top:
        cuts.append(high)
    cuts.append(top)
    for j in range(len(cuts) - 1):
        lo, hi = cuts[j], cuts[j + 1]
        p_lo = c0 + lo * (c1 + lo * (c2 + lo * c3))
        p_hi = c0 + hi * (c1 + hi * (c2 + hi * c3))
        if p_hi == 0.0:
            return hi
        if not (p_lo < 0.0) != (p_hi < 0.0) or p_lo != p_lo or p_hi != p_hi:
            continue
        while True:
            mid = 0.5 * (lo + hi)
            if not lo < mid < hi:
                return hi if abs(p_hi) < abs(p_lo) else lo
            p_mid = c0 + mid * (c1 + mid * (c2 + mid * c3))
            if p_mid == 0.0:
                return mid
            if (p_mid < 0.0) == (p_lo < 0.0):
                lo, p_lo = mid, p_mid
            else:
                hi, p_hi = mid, p_mid
    return fallback


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
    first_seating = np.asarray(first_seating, dtype=np.int64)
    largest, top, count = _after_seating(np.ascontiguousarray(lift, dtype=float), first_seating, float(tolerance))
    if velocity is not None:
        largest = np.maximum(largest, peak_between(lift, velocity, top, step_time, first_seating))
    return np.where((first_seating < lift.shape[-1]) & ~(0.0 > largest), largest, 0.0), count


@njit(cache=True, nogil=True)
def _after_seating(lift, first_seating, tolerance) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Of each row of ``lift`` (S, n) [m] from its sample ``first_seating`` (S,) on: the largest lift (nan if one is
    nan, -inf if none), its sample (the first of equal ones, the first nan; 0 if none) and the runs of samples above
    ``tolerance``, compiled (:func:`bounces`: the whole-array masks took a third of a sweep's events)."""
    count, n = lift.shape
    largest, top, runs = np.full(count, -np.inf), np.zeros(count, dtype=np.int64), np.zeros(count, dtype=np.int64)
    for r in range(count):
        y = lift[r]
        above = False
        for j in range(max(first_seating[r], 0), n):
            v = y[j]
            if largest[r] == largest[r] and (v > largest[r] or v != v):
                largest[r], top[r] = v, j
            if v > tolerance and not above:
                runs[r] += 1
            above = v > tolerance
    return largest, top, runs


def peak_between(lift, velocity, top, step_time, first=None) -> np.ndarray:
    """The largest lift next to the sample ``top`` (S,) of each row of (S, n) records [m]: the maximum of the cubic
    Hermite of the lift and the velocity over the sample interval on either side of it where the velocity turns
    from rising to falling (``step_time``: the time between the samples [s], a scalar or one per row); -inf where
    neither does (a largest sample at an end of the record, or at a kink) or an interval's sample lies before the
    row's ``first`` (S,) (default 0: every sample counts).

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
    rows = lift.shape[0]
    h = np.ascontiguousarray(np.broadcast_to(np.asarray(step_time, dtype=float), (rows,)))
    first = np.zeros(rows, dtype=np.int64) if first is None else np.asarray(first, dtype=np.int64)
    return _peaks(np.ascontiguousarray(lift, dtype=float), np.ascontiguousarray(velocity, dtype=float),
                  np.asarray(top, dtype=np.int64), h, first)


@njit(cache=True, nogil=True, error_model="numpy")
def _peaks(lift, velocity, top, h, first) -> np.ndarray:
    """:func:`peak_between` of each row, compiled (written with whole arrays, its fixed cost was half the events of a
    sweep of one speed): the same arithmetic in the same order, numpy's maximum (a nan kept) and its division."""
    rows, n = lift.shape
    best = np.full(rows, -np.inf)
    for r in range(rows):
        for j in (top[r] - 1, top[r]):                          # the interval [j, j + 1]
            if j < 0 or j + 1 >= n or j < first[r]:
                continue
            y0, y1 = lift[r, j], lift[r, j + 1]
            m0, m1 = h[r] * velocity[r, j], h[r] * velocity[r, j + 1]
            if not ((m0 >= 0.0) & (m1 <= 0.0) & (m0 > m1)):
                continue
            a, b = 6.0 * (y0 - y1) + 3.0 * (m0 + m1), 6.0 * (y1 - y0) - 4.0 * m0 - 2.0 * m1
            d = b * b - 4.0 * a * m0
            disc = np.sqrt(d if (d >= 0.0) | (d != d) else 0.0)
            q = -0.5 * (b + (disc if b >= 0.0 else -disc))     # the root in [0, 1] of a s^2 + b s + m0
            r0 = q / a if a != 0.0 else np.inf
            r1 = m0 / q if q != 0.0 else -m0 / b
            r0 = r0 if (r0 >= 0.0) & (r0 <= 1.0) else np.nan
            r1 = r1 if (r1 >= 0.0) & (r1 <= 1.0) else np.nan
            s = r1 if r0 != r0 else r0
            if not np.isfinite(s):
                continue
            s2, s3 = s * s, s * s * s
            p = (2 * s3 - 3 * s2 + 1) * y0 + (s3 - 2 * s2 + s) * m0 + (3 * s2 - 2 * s3) * y1 + (s3 - s2) * m1
            best[r] = best[r] if (best[r] >= p) | (best[r] != best[r]) else p
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
    lift = np.asarray(lift, dtype=float)
    rows = np.ascontiguousarray(lift.reshape(-1, lift.shape[-1]))
    on_cam = rows if follower is None else np.ascontiguousarray(np.asarray(follower, dtype=float).reshape(rows.shape))
    out = _lift_events(np.ascontiguousarray(kinematic, dtype=float), rows, on_cam, float(tolerance))
    return out.reshape(lift.shape)


@njit(cache=True, nogil=True, no_cpython_wrapper=True, no_cfunc_wrapper=True, inline='always')
def _event_span(kinematic, rising, lowest, y, follower, tolerance) -> tuple[int, int]:
    """The lift event of one record (:func:`lift_event`): its first sample and its count of samples, which run
    round the record from it.  ``rising`` is the first sample of positive cam lift (-1: none) and ``lowest`` the cam's
    lowest lift; ``y`` the valve's lift, ``follower`` the node on the cam (n,).  Its steps: the largest lift (the first
    of equal ones); the first sample at or below the seat from it on, round the record (the return); the cam's lowest
    point from the return on; the first catching from that point on; the event from the catching (else the first
    sample of positive cam lift, else the return) up to the return."""
    n = y.size
    peak = 0
    for i in range(1, n):
        if y[i] > y[peak]:
            peak = i
    seat = -1
    for j in range(n):
        i = peak + j if peak + j < n else peak + j - n
        if y[i] <= 0.0:
            seat = i
            break
    if seat < 0 or not y[peak] > 0.0:          # never returns to its seat: every sample while the cam lifts
        return 0, n if rising >= 0 else 0
    bottom = seat
    for j in range(n):
        i = seat + j if seat + j < n else seat + j - n
        if kinematic[i] <= lowest:
            bottom = i
            break
    start = -1
    for j in range(n):
        i = bottom + j if bottom + j < n else bottom + j - n
        if kinematic[i] > 0.0 and y[i] > tolerance and follower[i] < kinematic[i]:
            start = i
            break
    if start < 0:
        start = rising if rising >= 0 else seat
    return start, seat - start if seat >= start else seat - start + n


@njit(cache=True, nogil=True, no_cpython_wrapper=True, no_cfunc_wrapper=True, inline='always')
def _cam_rise(kinematic) -> tuple[int, float]:
    """The first sample of positive cam lift (-1: none) and the cam's lowest lift, of a record (n,)."""
    rising = -1
    lowest = np.inf
    for i in range(kinematic.size):
        if rising < 0 and kinematic[i] > 0.0:
            rising = i
        lowest = min(lowest, kinematic[i])
    return rising, lowest


@njit(cache=True, nogil=True)
def _lift_events(kinematic, lift, follower, tolerance) -> np.ndarray:
    """:func:`lift_event` of each row of ``lift`` and ``follower`` (S, n), compiled (:func:`_event_span`): a few
    passes over each row's samples, where the whole-array version (two first-True searches round the record on every
    row, the masks of every sample) took half the time of a sweep's events."""
    count, n = lift.shape
    out = np.zeros((count, n), dtype=np.bool_)
    rising, lowest = _cam_rise(kinematic)
    for r in range(count):
        start, span = _event_span(kinematic, rising, lowest, lift[r], follower[r], tolerance)
        for j in range(span):
            out[r, start + j if start + j < n else start + j - n] = True
    return out


@njit(cache=True, nogil=True)
def _lifting_contact(kinematic, lift, follower, contact, tolerance):
    """Of each row of (S, n) records, over its lift event (:func:`_event_span`) at once: whether the follower
    separates (:func:`separation_mask`), its first and last sample separated (0 without), the smallest contact force
    while the cam lifts the open valve (:func:`lowest_lifting_force`'s before the separation is accounted; inf where
    none; nan where one is) and whether the cam lifts it at all, compiled: the masks of every sample, made and read
    again, took half the time of a sweep's events."""
    count, n = lift.shape
    jumped, lifting = np.zeros(count, dtype=np.bool_), np.zeros(count, dtype=np.bool_)
    first, last, least = np.zeros(count, dtype=np.int64), np.zeros(count, dtype=np.int64), np.full(count, np.inf)
    rising, lowest = _cam_rise(kinematic)
    for r in range(count):
        y, f, c = lift[r], follower[r], contact[r]
        start, span = _event_span(kinematic, rising, lowest, y, f, tolerance)
        low, high, small = n, -1, np.inf
        for j in range(span):
            i = start + j if start + j < n else start + j - n
            if kinematic[i] > 0.0 and y[i] > tolerance:
                lifting[r] = True
                if small == small and (c[i] < small or c[i] != c[i]):     # np.min's: a nan is kept
                    small = c[i]
                if c[i] <= 0.0 and f[i] >= kinematic[i]:
                    low, high = min(low, i), max(high, i)
        least[r] = small
        if high >= 0:
            jumped[r], first[r], last[r] = True, low, high
    return jumped, first, last, least, lifting


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
    rows = np.ascontiguousarray(lift, dtype=float)
    on_cam = rows if result.follower_lift is None else np.ascontiguousarray(result.follower_lift, dtype=float)
    jumped, first, last, least, lifting = _lifting_contact(np.ascontiguousarray(kinematic, dtype=float), rows, on_cam,
                                                           np.ascontiguousarray(result.contact_force, dtype=float),
                                                           float(result.bounce_tolerance))
    height, count = bounces(lift, index, result.bounce_tolerance, result.velocity, step_time)
    return SweepEvents(index, angle, velocity, height, count, jumped, np.where(jumped, theta[first], np.nan),
                       np.where(jumped, theta[last], np.nan),
                       np.where(jumped, 0.0, np.where(lifting, least, np.nan)))


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
    fit = fit[np.diff(speeds[fit], append=np.inf) > 0.0]     # of equal speeds the last
    if fit.size < 2 or fit[-1] != i - 1:
        return float(speeds[i])
    x0, top = float(speeds[i - 1]), float(speeds[i])
    roots = _trend_roots([float(s) - x0 for s in speeds[fit]], [float(v) for v in values[fit]])
    inside = [r + x0 for r in roots if x0 <= r + x0 <= top]
    return min(inside) if inside else top


def _trend_roots(x, y) -> list[float]:
    """The real roots of the line through two points (``x``, ``y``: lists of two floats, the last x 0) or of the
    parabola through three (the last x 0): Newton's form about the last point, p(x) = y2 + d2 x + a x (x - x1), and
    its roots by :func:`_quadratic_roots`.  The fit of :func:`numpy.polyfit` and the roots of :func:`numpy.roots`
    (a least-squares solve, a companion matrix's eigenvalues) took 0.13 ms a call for these two or three points; the
    roots agree to round-off."""
    if len(x) == 2:
        a, d2 = 0.0, (y[1] - y[0]) / (x[1] - x[0])
    else:
        d1, d2 = (y[1] - y[0]) / (x[1] - x[0]), (y[2] - y[1]) / (x[2] - x[1])
        a = (d2 - d1) / (x[2] - x[0])
    count, low, high = _quadratic_roots(a, d2 - a * x[-2], y[-1])
    return [low, high][:count]


@njit(cache=True, nogil=True)
def _quadratic_roots(a, b, c) -> tuple[int, float, float]:
    """The real roots of a t^2 + b t + c: their count (0, 1 or 2; a = 0: the line's, none where b = 0 too) and the
    smaller and the larger (nan for those not there), by the form that does not cancel, q = -(b + sgn(b)
    sqrt(b^2 - 4 a c)) / 2 (sgn(0) = 1), roots q / a and c / q (Press et al. (2007), section 5.6); q = 0 (b = c = 0):
    the one root 0.

    >>> _quadratic_roots(1.0, -3.0, 2.0), _quadratic_roots(0.0, 2.0, -1.0), _quadratic_roots(1.0, 0.0, 1.0)[0]
    ((2, 1.0, 2.0), (1, 0.5, 0.5), 0)
    """
    if a == 0.0:
        return (1, -c / b, -c / b) if b != 0.0 else (0, np.nan, np.nan)
    disc = b * b - 4.0 * a * c
    if not disc >= 0.0:
        return 0, np.nan, np.nan
    q = -0.5 * (b + (np.sqrt(disc) if b >= 0.0 else -np.sqrt(disc)))
    if q == 0.0:
        return 1, 0.0, 0.0
    return 2, min(q / a, c / q), max(q / a, c / q)


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
