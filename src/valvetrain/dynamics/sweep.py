"""Valve motion at speed: one simulation or a whole speed sweep of an elastic train on a lift law.

Camshaft speeds are camshaft rad/s inside; camshaft angles are rad from the cam nose (the
law's convention, :mod:`valvetrain.laws.base`).  Every speed starts at rest on the seat at
the angle opposite the nose, runs ``revolutions`` camshaft revolutions so that the residual
vibration of the previous event is included, and the last revolution is recorded.

Events (Shang Hanji (1988), sections 3.1-3.2):

* follower separation (jump, 飞脱): the cam contact force is zero while the rigid valve
  lift k h - x0 is positive and the valve is off its seat, before the first seating;
* first seating: the first downward crossing of y = 0 after the valve's largest lift; the
  seating velocity is dy/dt there;
* bounce (落座反跳): every return of the valve above ``bounce_tolerance`` after the first
  seating; its height is the largest lift after the first seating;
* spring surge: the largest deviation of each coil mass from its quasi-static share of the
  valve motion, and the coil clash margin (closing gap minus the compression of a coil
  segment; negative: adjacent coils meet).
"""

from dataclasses import dataclass

import numpy as np
from numba import parallel_chunksize

from .kernels import integrate_network

STEP_LIMIT = 1.0
"""Largest |lambda| dt of the explicit integrator (|lambda|: spectral radius of the train's state matrix,
:meth:`~.models.Network.highest_frequency`); RK4 is stable to 2.83 on the imaginary axis and damps an undamped
mode at omega dt = 1 by 0.7 % a step (Hairer, Nørsett and Wanner (1993), section IV.2)."""

BOUNCE_TOLERANCE = 1e-6
"""Lift above the seat that counts as a bounce [m] (1 um: below it the valve rocks on the seat's elasticity)."""


def substeps(highest_frequency, cam_speeds, step):
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


def cam_excitation(law, rocker_ratio, steps_per_rev, per_step, start=-np.pi):
    """Cam displacement and its slope at the valve on one camshaft revolution.

    Returns
    -------
    theta, u, du : ndarray
        Camshaft angle [rad from the nose] every 2 pi / (steps_per_rev per_step) from ``start``; k h [m];
        k dh/dtheta [m/rad].
    """
    theta = start + 2.0 * np.pi * np.arange(steps_per_rev * per_step) / (steps_per_rev * per_step)
    d = law.derivatives(theta)
    return theta, rocker_ratio * d[0], rocker_ratio * d[1]


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
        Largest lift after the first seating [m] (0 without bounce).
    bounce_count : int
        Returns of the valve above the bounce tolerance after the first seating.
    surge_amplitude : ndarray (N,)
        Largest deviation of each coil mass from its quasi-static share of the valve motion [m].
    clash_margin : float
        Smallest coil closing margin [m] (inf: not monitored; negative: coil clash).
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

    @property
    def lift_error(self):
        """Valve lift minus the rigid lift where either is open [m]."""
        return lift_error(self.lift, self.kinematic_lift)


def lift_error(lift, kinematic_lift):
    """Valve lift y minus the rigid lift max(k h - x0, 0) where either is open, else 0 [m].

    >>> (lift_error(np.array([-1e-6, 2e-3, 0.0]), np.array([-1e-4, 2.1e-3, 1e-5])) * 1e6).round(6).tolist()
    [0.0, -100.0, -10.0]
    """
    rigid = np.maximum(kinematic_lift, 0.0)
    return np.where((lift > 0) | (rigid > 0), lift - rigid, 0.0)


def runs(mask):
    """Start and end (exclusive) indices of the runs of True in a boolean array, shape (m, 2).

    >>> runs(np.array([0, 1, 1, 0, 1], dtype=bool)).tolist()
    [[1, 3], [4, 5]]
    """
    edges = np.diff(np.concatenate([[0], mask.astype(np.int8), [0]]))
    return np.column_stack([np.flatnonzero(edges == 1), np.flatnonzero(edges == -1)])


def seating(theta, lift, velocity):
    """First downward crossing of y = 0 after the largest lift: (index, angle [rad], velocity [m/s]).

    The angle and velocity are interpolated linearly between the samples; (n, nan, nan) if the valve does not
    open or does not return within the record.
    """
    top = int(np.argmax(lift))
    if lift[top] <= 0.0:
        return lift.size, np.nan, np.nan
    below = np.flatnonzero(lift[top:] <= 0.0)
    if below.size == 0:
        return lift.size, np.nan, np.nan
    i = top + int(below[0])
    w = lift[i - 1] / (lift[i - 1] - lift[i])
    return i, float(theta[i - 1] + w * (theta[i] - theta[i - 1])), float(velocity[i - 1] + w * (velocity[i] -
                                                                                             velocity[i - 1]))


def bounce(lift, first_seating, tolerance=BOUNCE_TOLERANCE):
    """The bounce after the first seating: (largest lift after it [m], returns above ``tolerance``); (0, 0) without one.

    ``first_seating`` is the index :func:`seating` returns (the record's length: no seating, no bounce).

    >>> bounce(np.array([0.0, 2e-3, 0.0, 5e-6, 0.0, 3e-6, 0.0]), 2)
    (5e-06, 2)
    """
    after = lift[first_seating:]
    returns = runs(after > tolerance)
    return (float(max(after.max(), 0.0)) if returns.size else 0.0), len(returns)


def speed_result(cam_speed, theta, lift, velocity, kinematic, contact, seat, spring, slope, surge, clash,
                 bounce_tolerance=BOUNCE_TOLERANCE):
    """Events of one speed from its recorded revolution (see the module docstring for the definitions)."""
    i_seat, seat_angle, seat_velocity = seating(theta, lift, velocity)
    before = np.arange(theta.size) < i_seat
    separation = (contact <= 0.0) & (kinematic > 0.0) & (lift > 0.0) & before
    intervals = runs(separation)
    jumps = np.column_stack([theta[intervals[:, 0]], theta[intervals[:, 1] - 1]]) if intervals.size else \
        np.zeros((0, 2))
    height, count = bounce(lift, i_seat, bounce_tolerance)
    return SpeedResult(float(cam_speed), theta, lift, velocity, kinematic, contact, seat, spring, contact * slope,
                       separation, jumps, seat_angle, seat_velocity, height, count, surge, clash)


@dataclass(frozen=True)
class SweepResult:
    """A speed sweep: maps over (speed, camshaft angle) and the headline numbers.

    Attributes
    ----------
    cam_speeds : ndarray (S,)
        [rad/s].
    theta : ndarray (n,)
        Camshaft angle of the last revolution [rad from the nose].
    kinematic_lift : ndarray (n,)
        Rigid valve lift k h - x0 [m].
    lift, velocity, contact_force, seat_force, spring_force : ndarray (S, n)
        As in :class:`SpeedResult`.
    slope : ndarray (n,)
        dh/dtheta of the law [m/rad] (for the torque).
    surge_amplitude : ndarray (S, N)
        Coil deviations [m] (N = coil masses of the train).
    clash_margin : ndarray (S,)
        Smallest coil closing margin [m].
    substeps : ndarray (S,)
        Integrator sub-steps per angle step used for each speed.
    """

    cam_speeds: np.ndarray
    theta: np.ndarray
    kinematic_lift: np.ndarray
    lift: np.ndarray
    velocity: np.ndarray
    contact_force: np.ndarray
    seat_force: np.ndarray
    spring_force: np.ndarray
    slope: np.ndarray
    surge_amplitude: np.ndarray
    clash_margin: np.ndarray
    substeps: np.ndarray
    bounce_tolerance: float = BOUNCE_TOLERANCE

    def speed(self, i):
        """The :class:`SpeedResult` of the i-th speed."""
        return speed_result(self.cam_speeds[i], self.theta, self.lift[i], self.velocity[i], self.kinematic_lift,
                            self.contact_force[i], self.seat_force[i], self.spring_force[i], self.slope,
                            self.surge_amplitude[i], float(self.clash_margin[i]), self.bounce_tolerance)

    def per_speed(self):
        """Every :class:`SpeedResult` of the sweep."""
        return [self.speed(i) for i in range(self.cam_speeds.size)]

    @property
    def lift_error(self):
        """Map of valve lift minus rigid lift where either is open [m], shape (S, n)."""
        return lift_error(self.lift, self.kinematic_lift)

    @property
    def torque(self):
        """Map of the camshaft drive torque F dh/dtheta [N m], shape (S, n)."""
        return self.contact_force * self.slope

    def headline(self):
        """Jump speed, bounce onset speed and the largest seating speed of the sweep.

        Returns
        -------
        dict
            ``jump_speed`` and ``bounce_onset_speed``: the lowest camshaft speed [rad/s] with a follower
            separation / a bounce (nan if none); ``max_seating_velocity``: the largest |dy/dt| at seating
            [m/s] and ``max_seating_velocity_speed`` where it occurs; ``coil_clash_speed``: the lowest speed
            whose coils meet (nan if none).
        """
        results = self.per_speed()
        jump = [r.cam_speed for r in results if r.jump_intervals.size]
        bounce = [r.cam_speed for r in results if r.bounce_count]
        seat = np.array([abs(r.seating_velocity) for r in results])
        clash = self.cam_speeds[self.clash_margin < 0.0]
        worst = int(np.nanargmax(seat)) if np.isfinite(seat).any() else None
        return {"jump_speed": min(jump, default=np.nan), "bounce_onset_speed": min(bounce, default=np.nan),
                "max_seating_velocity": float(seat[worst]) if worst is not None else np.nan,
                "max_seating_velocity_speed": float(self.cam_speeds[worst]) if worst is not None else np.nan,
                "coil_clash_speed": float(clash.min()) if clash.size else np.nan}


def sweep(law, train, cam_speeds, revolutions=3, step_deg=0.1, progress=None, chunk=25,
          bounce_tolerance=BOUNCE_TOLERANCE):
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
        Camshaft revolutions per speed; the last is recorded (the earlier ones settle the residual vibration).
    step_deg : float
        Recording and base integration step [camshaft deg]; it must divide 360.  Slow speeds integrate with
        sub-steps (:func:`substeps`).
    progress : callable, optional
        ``progress(done, total)`` after each chunk of speeds (the compiled kernel itself never calls Python).
    chunk : int
        Speeds per kernel call when ``progress`` is given (without it, one call integrates every speed: the
        kernel groups the speeds into SIMD blocks and deals them to the threads itself).
    bounce_tolerance : float
        Lift that counts as a bounce [m].

    Returns
    -------
    SweepResult
    """
    net = train.network()
    speeds = np.atleast_1d(np.asarray(cam_speeds, dtype=float))
    steps = int(round(360.0 / step_deg))
    if not np.isclose(steps * step_deg, 360.0, rtol=0, atol=1e-9):
        raise ValueError(f"the step {step_deg} deg does not divide the camshaft revolution")
    if revolutions < 1 or np.any(speeds <= 0.0):
        raise ValueError("sweep: at least one revolution and positive camshaft speeds are needed")
    dtheta = 2.0 * np.pi / steps
    n_sub = substeps(net.highest_frequency(), speeds, dtheta)
    per_step = 2 * int(n_sub.max())
    theta, u, du = cam_excitation(law, net.rocker_ratio, steps, per_step)
    rec_nodes = np.array([net.valve], dtype=np.int64)
    rec_elems = np.concatenate([[net.cam_element, net.seat_element], net.spring_elements]).astype(np.int64)
    s_count, n_nodes, n_elems = speeds.size, net.mass.size, net.a.size
    out_x = np.empty((s_count, 1, steps))
    out_v = np.empty((s_count, 1, steps))
    out_f = np.empty((s_count, rec_elems.size, steps))
    out_clash = np.empty((s_count, n_elems))
    out_surge = np.empty((s_count, n_nodes))
    chunk = chunk if progress is not None else s_count
    for lo in range(0, s_count, chunk):
        hi = min(lo + chunk, s_count)
        with parallel_chunksize(1):                   # the threads take the blocks one by one, costliest first
            integrate_network(speeds[lo:hi], n_sub[lo:hi], dtheta, u, du, per_step, steps, int(revolutions),
                              1.0 / net.mass, net.x_init, net.a, net.b, net.stiffness, net.damping, net.gap,
                              net.preload, net.unilateral, rec_nodes, rec_elems, net.clash_gap, net.valve,
                              net.surge_weight, out_x[lo:hi], out_v[lo:hi], out_f[lo:hi], out_clash[lo:hi],
                              out_surge[lo:hi])
        if progress is not None:
            progress(hi, s_count)
    coils = net.surge_weight > 0.0
    return SweepResult(speeds, theta[::per_step], u[::per_step] - net.lash, out_x[:, 0], out_v[:, 0],
                       net.rocker_ratio * out_f[:, 0], out_f[:, 1], -out_f[:, 2:].sum(axis=1),
                       du[::per_step] / net.rocker_ratio, out_surge[:, coils], out_clash.min(axis=1), n_sub,
                       bounce_tolerance)


def simulate(law, train, cam_speed, revolutions=3, step_deg=0.1, bounce_tolerance=BOUNCE_TOLERANCE):
    """Simulate one camshaft speed [rad/s]; a :class:`SpeedResult` of the last revolution (see :func:`sweep`)."""
    return sweep(law, train, [cam_speed], revolutions, step_deg, bounce_tolerance=bounce_tolerance).speed(0)


def speed_range(low, high, count=200):
    """``count`` camshaft speeds evenly spaced from ``low`` (idle) to ``high`` (over-speed) [rad/s].

    The issue's default sweep is 200 speeds; an engine speed n [rpm] of a four-stroke turns the camshaft at
    pi n / 60 rad/s.

    >>> speed_range(np.pi * 800 / 60, np.pi * 7000 / 60).size
    200
    """
    return np.linspace(low, high, count)
