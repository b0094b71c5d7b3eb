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
from .events import (BOUNCE_TOLERANCE, SweepEvents, bounces, force_reached_zero, level_crossing, lift_error, lift_event,
                     lowest_lifting_force, runs, seating, separation_mask, sweep_events, zero_crossing)
from .kernels import CAM, GROUND, blocks, integrate_block, integrate_node, rows
from .models import _kept

STEP_LIMIT = 1.0
"""Largest |lambda| dt of the explicit integrator (|lambda|: spectral radius of the train's state matrix,
:meth:`~.models.Network.highest_frequency`); RK4 is stable to 2.83 on the imaginary axis and damps an undamped
mode at omega dt = 1 by 0.7 % a step (Hairer, Nørsett and Wanner (1993), section IV.2)."""

STATE_TOLERANCE = 1e-9
"""A speed's motion repeats when its state at the end of a camshaft revolution differs from the state at its start
by no more than 1 nm in every position (and 1 nm times the spectral radius of the train in every velocity) [m]: a
thousandth of the 1 um lift accuracy of the integrator, and 0.015 N of force on a 15000 N/mm drive."""

REST_AMPLITUDE = 1e-12
"""A one-mass valve on its seat while the cam's base circle passes is held at rest once its motion about its rest
position is within 1 pm (:func:`.kernels.integrate_node`): a thousandth of :data:`STATE_TOLERANCE`; its velocity is
then within 1e-12 m times the seated train's natural frequency (0.04 um/s on the built-in example's 2e8 N/m seat) and
its seat force within 1e-12 m times the seat's stiffness (0.2 mN)."""


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
    share them.  A grid is kept by its samples a revolution: the samples of a coarser one are every 2^j-th of a finer
    one kept (the same angles to the bit, and the law's derivatives are those of each angle alone), so the
    one-mass design's grids (the sub-stepped first sweep's, the second's and the refinement's halved step) are made
    once.  The arrays are shared: read them, don't change them.

    Returns
    -------
    theta, u, du : ndarray
        Camshaft angle [rad from the nose] every 2 pi / (steps_per_rev per_step) from ``start``; k h [m];
        k dh/dtheta [m/rad].
    """
    count = int(steps_per_rev) * int(per_step)
    try:
        kept = _EXCITATIONS.setdefault(law, {}).setdefault((float(rocker_ratio), float(start)), {})
    except TypeError:         # a law that is not hashable or cannot be referred to weakly: made every time
        kept = {}
    if count not in kept:
        finer = [n for n in kept if n % count == 0 and (n // count) & (n // count - 1) == 0]
        if finer:             # every 2^j-th sample of a finer grid: the same angles, to the bit
            m = min(finer) // count
            kept[count] = tuple(np.ascontiguousarray(a[::m]) for a in kept[min(finer)])
        else:
            theta = start + 2.0 * np.pi * np.arange(count) / count
            d = law.derivatives(theta)
            kept[count] = theta, rocker_ratio * d[0], rocker_ratio * d[1]
    return kept[count]


_EXCITATIONS = weakref.WeakKeyDictionary()
"""The excitation samples of each live law (:func:`cam_excitation`), law -> {(k, start): {samples a revolution:
arrays}}."""


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
        Plunger extension of the train's hydraulic lash adjuster [m, at the adjuster] (None without one).
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
        (None without one).
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


def kernels_cached() -> bool:
    """Whether numba's cache holds the sweep's kernel compiled from this source (its index names the source's
    modification time and size: a kernel of an older source is not counted)."""
    try:
        return bool(integrate_block._cache._cache_file._load_index())   # numba's cache index of this kernel
    except (AttributeError, OSError):
        return False


def _notify_compile():
    """Say once on stderr that the kernels are being compiled, when no compiled or cached kernel is at hand and
    stderr is a terminal (like the commands' progress: a command whose output is read says only its results and
    errors, and a refusal found after the first sweep came after this line)."""
    global _COMPILE_NOTIFIED
    if _COMPILE_NOTIFIED or integrate_block.signatures or not sys.stderr.isatty():
        return
    _COMPILE_NOTIFIED = True
    if not kernels_cached():
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


def one_node(net) -> bool:
    """Whether a train's network is integrated by :func:`.kernels.integrate_node` (the one-mass train: one node
    without a lash adjuster, a node of variable mass or coils, its elements a unilateral contact from the cam, a spring
    from the node to the head and a unilateral seat from the head, in this order, :meth:`.models.OneMassTrain.network`;
    the same records as :func:`.kernels.integrate_block`, to the bit, faster) rather than by the general block
    kernel."""
    layout = [(CAM, 0, True), (0, GROUND, False), (GROUND, 0, True)]
    return (net.mass.size == 1 and net.adjuster[0] == 0.0 and net.variable_node < 0 and not np.any(net.clash_gap > 0.0)
            and not np.any(net.surge_weight > 0.0) and net.a.size == len(layout)
            and all((int(a), int(b), bool(u)) == kind
                    for a, b, u, kind in zip(net.a, net.b, net.unilateral, layout, strict=True)))


@_kept
def _layout(net) -> tuple:
    """What :func:`sweep` passes to the kernels of a network besides its arrays, found once per network (kept on it,
    as its :meth:`~.models.Network.highest_frequency`): its element ends' rows (:func:`.kernels.rows`), its spring
    elements, :func:`recorded_nodes`, its seat and cam elements and its lash [m].  Found again for each sweep, they
    took a quarter of the time of a sweep of one speed outside its kernel."""
    return (*rows(net.a, net.b, net.mass.size), np.asarray(net.spring_elements, dtype=np.int64), recorded_nodes(net),
            int(net.seat_element), int(net.cam_element), net.lash)


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
    if not abs(steps * step_deg - 360.0) <= 1e-9:
        raise InputError(f"the step {step_deg} deg does not divide the camshaft revolution")
    if revolutions < 1 or np.any(speeds <= 0.0) or halvings < 0:
        raise InputError("sweep: at least one revolution, positive camshaft speeds and no negative halvings are needed")
    rate = net.highest_frequency()
    n_sub = substeps(rate, speeds, 2.0 * np.pi / steps)
    steps *= 2**halvings
    dtheta = 2.0 * np.pi / steps
    per_step = 2 * int(n_sub.max())
    theta, u, du = cam_excitation(law, net.rocker_ratio, steps, per_step)
    ra, rb, springs, rec_nodes, seat_element, cam_element, lash = _layout(net)
    s_count, n_nodes, n_elems = speeds.size, net.mass.size, net.a.size
    # the six maps in one allocation: numpy asks Linux for huge pages for an array of 4 MB and more, so that the
    # kernel's writes to the maps' rows take fewer page faults and TLB misses (the 200-speed one-mass sweep on one
    # thread 17-21 against 23-24 ms, alternately)
    lift, velocity, acceleration, contact, seat, spring = np.empty((6, s_count, steps))
    follower = np.empty((s_count if rec_nodes.size > 1 else 0, steps))
    out_clash = np.empty((s_count, n_elems))
    out_surge = np.empty((s_count, n_nodes))
    out_revs = np.zeros(s_count, dtype=np.int64)
    adjusted = net.adjuster[0] > 0.0                # a hydraulic lash adjuster: its plunger's extension recorded
    out_z = np.zeros((s_count if adjusted else 0, steps))
    workers = get_num_threads()
    order, start, seq = blocks(n_sub, workers)
    inv_mass = 1.0 / net.mass
    single = one_node(net)

    def run(j):
        idx = order[start[j]:start[j + 1]]
        if single:
            integrate_node(idx, speeds, int(n_sub[idx[0]]), dtheta, u, du, per_step, steps, int(revolutions),
                           float(tolerance), float(rate), REST_AMPLITUDE, inv_mass, net.x_init, ra, rb, net.stiffness,
                           net.damping, net.gap, net.preload, net.unilateral, seat_element, springs,
                           float(net.rocker_ratio), cam_element, int(net.variable_node), net.variable_mass,
                           lift, velocity, acceleration, contact, seat, spring, out_clash, out_surge, out_revs)
            return idx.size
        integrate_block(idx, speeds, int(n_sub[idx[0]]), dtheta, u, du, per_step, steps, int(revolutions),
                        float(tolerance), float(rate), inv_mass, net.x_init, ra, rb, net.stiffness, net.damping,
                        net.gap, net.preload, net.unilateral, seat_element, int(rec_nodes[-1]) if
                        rec_nodes.size > 1 else -1, springs, float(net.rocker_ratio), net.clash_gap, int(net.valve),
                        net.surge_weight, net.adjuster, cam_element, int(net.variable_node),
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
    return SweepResult(speeds, theta[::per_step], u[::per_step] - lash, lift, velocity, acceleration, contact, seat,
                       spring, du[::per_step] / net.rocker_ratio, out_surge[:, coils], out_clash.min(axis=1), n_sub,
                       np.where(out_revs > 0, out_revs, int(revolutions)), out_revs > 0, bounce_tolerance,
                       out_z if adjusted else None,
                       follower if rec_nodes.size > 1 else None)


HEADLINE_STRIDE = 10
"""Every how many speeds of a sweep :func:`headline_sweep` simulates first (the coarse grid)."""

PER_SPEED_FIELDS = ("cam_speeds", "lift", "velocity", "acceleration", "contact_force", "seat_force", "spring_force",
                    "surge_amplitude", "clash_margin", "substeps", "revolutions", "converged", "adjuster_extension",
                    "follower_lift")
"""The fields of a :class:`SweepResult` with one row per speed."""

MAP_FIELDS = ("lift", "velocity", "acceleration", "contact_force", "seat_force", "spring_force", "adjuster_extension",
              "follower_lift")
"""The fields of a :class:`SweepResult` with a row of every recorded angle per speed (its maps)."""


def merged(parts) -> SweepResult:
    """One :class:`SweepResult` of the speeds of several sweeps of the same train on the same law, by ascending speed,
    with the parts' :attr:`~SweepResult.events` joined where every part has found its own (the events of a speed are
    found from its rows alone, :func:`sweep_events`).  Its maps (:data:`MAP_FIELDS`) are joined when they are first
    read (:class:`_JoinedSweep`).

    Each speed of a sweep is an independent problem integrated on the same excitation samples (:mod:`.kernels`), so a
    speed's rows do not depend on the sweep it was simulated in, but for the revolutions it runs: a block of speeds
    runs until all of them repeat, so its last revolution may differ by up to :data:`STATE_TOLERANCE`."""
    if len(parts) == 1:
        return parts[0]
    rank = np.argsort(np.argsort(np.concatenate([p.cam_speeds for p in parts]), kind="stable"))
    at = tuple(np.split(rank, np.cumsum([p.cam_speeds.size for p in parts])[:-1]))
    out = object.__new__(_JoinedSweep)
    state = vars(out)
    state.update((f.name, getattr(parts[0], f.name)) for f in fields(SweepResult) if f.name not in MAP_FIELDS)
    state.update((f, _joined([getattr(p, f) for p in parts], at)) for f in PER_SPEED_FIELDS
                 if f not in MAP_FIELDS and state[f] is not None)
    state["_parts"], state["_at"] = tuple(parts), at
    if all("events" in vars(p) for p in parts):
        state["events"] = SweepEvents(*(_joined([getattr(p.events, f.name) for p in parts], at)
                                        for f in fields(SweepEvents)))
    return out


def _joined(rows, at) -> np.ndarray:
    """The rows of each part (``rows``, one array a part) at its places ``at`` (one index array a part) of one array."""
    first = rows[0]
    out = np.empty((sum(r.shape[0] for r in rows), *first.shape[1:]), dtype=first.dtype)
    for part, where in zip(rows, at, strict=True):
        out[where] = part
    return out


class _JoinedMap:
    """A map of :class:`_JoinedSweep`, joined from the parts' rows when first read and kept on the instance (a value
    the instance holds, one set by its ``__init__``, comes first: this descriptor has no ``__set__``)."""

    def __set_name__(self, owner, name):
        self.name = name

    def __get__(self, result, owner=None):
        if result is None:
            return self
        state = vars(result)
        rows = [getattr(p, self.name) for p in state["_parts"]]
        value = state[self.name] = None if rows[0] is None else _joined(rows, state["_at"])
        return value


class _JoinedSweep(SweepResult):
    """The :class:`SweepResult` of :func:`merged`: each map is joined from the parts' rows when it is first read
    (:class:`_JoinedMap`), and kept (a tolerance sample reads two of the six of its headline sweep, whose joining took
    a twentieth of the sample's time).  A changed copy (:func:`dataclasses.replace`) has every map joined; pickled (a
    report's figures drawn in another process), it is a :class:`SweepResult` with every map joined, not its parts."""

    lift = _JoinedMap()
    velocity = _JoinedMap()
    acceleration = _JoinedMap()
    contact_force = _JoinedMap()
    seat_force = _JoinedMap()
    spring_force = _JoinedMap()
    adjuster_extension = _JoinedMap()
    follower_lift = _JoinedMap()

    def __reduce__(self):
        return SweepResult, tuple(getattr(self, f.name) for f in fields(SweepResult))


def speeds_of(result, index) -> SweepResult:
    """The :class:`SweepResult` of the speeds ``index`` (an integer array, or a slice: views of ``result``'s rows, no
    copy) of ``result``, with their events where ``result`` has found its own."""
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


def _window(centre, stride, n, keep, every) -> np.ndarray:
    """The indices of a grid of ``n`` speeds less than ``stride`` from ``centre``, every ``every``-th from it, those
    of the mask ``keep`` (None: all)."""
    offsets = np.arange(1 - stride, stride)
    out = np.clip(centre + offsets[offsets % every == 0], 0, n - 1)
    return np.unique(out if keep is None else out[keep[out]])


def _peak_neighbours(index, values, window) -> np.ndarray:
    """The speeds of ``window`` (indices) next to a local maximum of ``values`` (of the speeds ``index`` simulated)
    among its speeds simulated (nan: the lowest)."""
    at = np.searchsorted(index, window)
    done = window[(at < index.size) & (index[np.minimum(at, index.size - 1)] == window)]
    v = np.nan_to_num(values[np.searchsorted(index, done)], nan=-np.inf)
    top = (v >= np.append(-np.inf, v[:-1])) & (v >= np.append(v[1:], -np.inf))
    return window[np.isin(window, np.concatenate([done[top] - 1, done[top] + 1]))]


def headline_sweep(law, train, cam_speeds, revolutions=3, step_deg=0.1, bounce_tolerance=BOUNCE_TOLERANCE,
                   load_range=(0.0, np.inf), stride=HEADLINE_STRIDE, seating_top=np.inf,
                   extra=None, levels=()) -> SweepResult | tuple[SweepResult, SweepResult]:
    """The speeds of a sweep that decide its jump speed, its largest seating velocity and its largest loads, without
    the others.

    Parameters are those of :func:`sweep`; ``load_range`` is the speed range [rad/s camshaft] whose cam force loads
    the parts (the strength stage's), ``stride`` spaces the coarse grid, ``seating_top`` is the highest speed
    [rad/s camshaft] of the seating velocity graded (the rated speed), ``extra`` more camshaft speeds [rad/s] to
    simulate with the coarse grid (the rated speed: one kernel call fewer), returned apart; ``levels`` contact forces
    [N] whose first speed with the smallest contact force while the cam lifts at or below them is found as the jump
    speed's (a lash adjuster's push, :attr:`.models.Adjuster.push`: where its follower floats).

    Returns
    -------
    SweepResult, or (SweepResult, SweepResult) with ``extra``
        The speeds simulated, a subset of ``cam_speeds``, by ascending speed (and those of ``extra``, in their
        order), each with its :attr:`~SweepResult.events` found.

    Notes
    -----
    Simulated, in three sweeps:

    1. the coarse grid: every ``stride``-th speed, the lowest and the highest, the first and the last speed
       inside ``load_range``, and the last speed up to ``seating_top``;
    2. the speeds between the last coarse speed without a separation and the first with one, and the two below
       them: the first speed of the full grid with a separation and the speeds :func:`zero_crossing` fits below it;
       the same below the first coarse speed whose contact force falls to zero while the cam lifts (a separation
       that comes and goes with the speed starts near it) and to each of ``levels``; every other speed within
       ``stride`` of the coarse speed with the largest seating velocity, of those up to ``seating_top`` whose
       seating velocity is within :data:`SEATING_NEAR` of their largest (the seating velocity has a peak at each
       harmonic of the cam the train meets: the built-in example's exhaust peaks at 6161 rpm between two coarse
       speeds lower than one 600 rpm above; of these speeds only those up to ``seating_top``), and of the coarse
       speed inside ``load_range`` with the largest contact force (only those inside ``load_range``);
    3. in each of those windows, the two neighbours of every speed simulated whose value (the seating velocity, the
       largest contact force) is at least that of the speeds simulated on either side of it
       (:func:`_peak_neighbours`): where the value has one peak between two speeds two apart, its largest speed.

    So :meth:`SweepResult.headline` gives the full sweep's jump speed unless a separation starts and ends between two
    coarse speeds below the first coarse speed that separates or loses its contact force; the largest seating
    velocity (of all the speeds, and of those up to ``seating_top``) and the largest contact force (in
    ``load_range``) are the full sweep's where they lie within ``stride`` speeds of the coarse grid's largest (or at
    an end of ``load_range``) and no two peaks of the value lie within two speeds.  The sweep's other headlines (the
    bounce onset, the coil clash) and its maps have the simulated speeds only.
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
            parts.append(speeds_of(both, slice(0, idx.size)) if also.size else both)
            done[idx] = True
            return np.flatnonzero(done), speeds_of(both, slice(idx.size, None))
        return np.flatnonzero(done), None

    ends = np.flatnonzero(inside)[[0, -1]] if inside.any() else []
    graded = speeds <= seating_top * (1.0 + 1e-12)
    index, extra_result = simulated(np.concatenate([np.arange(0, n, stride), [n - 1], ends,
                                                    np.flatnonzero(graded)[-1:]]), more_speeds)
    result = parts[0]
    jumped, force, seat = seating_events(result)
    below = np.where(graded[index], seat, np.nan)
    near = index[below >= SEATING_NEAR * np.nanmax(below)] if np.isfinite(below).any() else []
    windows = [(c, None, "seat") for c in ([index[np.nanargmax(seat)]] if np.isfinite(seat).any() else [])]
    windows += [(c, graded, "seat") for c in near]
    if inside.any():
        c = index[inside[index]][np.argmax(result.contact_force[inside[index]].max(axis=1))]
        windows.append((c, inside, "force"))
    more = [_window(c, stride, n, keep, 2) for c, keep, _ in windows]
    for hit in (jumped, jumped | (force <= 0.0), *(force <= level for level in levels)):
        if hit.any() and hit.argmax() > 0:
            more.append(np.arange(index[hit.argmax() - 1] - 2, index[hit.argmax()]))
    index = simulated(np.concatenate(more or [[]]))[0]
    order = np.argsort(np.concatenate([part.cam_speeds for part in parts]))   # the speeds' rows, not joined
    values = {"seat": np.concatenate([seating_events(part)[2] for part in parts])[order],
              "force": np.concatenate([part.contact_force.max(axis=1) for part in parts])[order]}
    last = [_peak_neighbours(index, values[kind], _window(c, stride, n, keep, 1)) for c, keep, kind in windows]
    simulated(np.concatenate(last or [[]]))
    result = merged(parts)
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
