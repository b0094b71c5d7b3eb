"""Error control of a speed sweep's headlines: step halving at the speeds that decide them.

A sweep (:func:`.sweep.sweep`) integrates every speed at one step, but few speeds decide its headlines: the jump
speed is the zero of the smallest contact force through the speeds about it, the bounce onset the crossing of the
bounce tolerance by the bounce height between two speeds, the largest seating velocity that of one speed.
:func:`refine` simulates those speeds again at half the step, and again (:func:`.sweep.sweep`'s ``halvings``), until
each headline changes by less than its accuracy (:data:`JUMP_ACCURACY`, :data:`SEATING_ACCURACY`,
:data:`BOUNCE_ACCURACY`, :data:`ONSET_ACCURACY`) or after :data:`MAX_HALVINGS`, and returns the headlines at the finest
step with their estimated errors:

* the time-step error: the change of the headline from the last step but one to the finest, through the same speeds
  (Richardson's estimate of the coarser value's error, so an upper estimate of the finer value's wherever the error
  falls with the step);
* the speed-grid error of a crossing (the jump speed, the bounce onset), which is interpolated between the speeds
  swept: one more speed is simulated where the crossing is found (for the jump halfway to it from the last speed
  below: the contact force is clamped at zero once the follower separates, so only the speeds below the jump tell
  where it is, and a force near zero carries the clipping error below), and the change of the crossing it brings is
  its error; a jump that the new speed shows to lie below it is bracketed instead, and the bracket is its error.

Why the base step is not enough: the stages of an RK4 step evaluate the contact laws at intermediate states that are
accurate to the first and the second order only.  A stiff contact turns their error, of the order of h^2 times the
acceleration, into a force error of the order of M (omega_n h)^2 a (omega_n = sqrt(c / M)), and near the jump, where
the contact force approaches zero, a stage that finds it negative clips it.  At 0.1 cam deg this moves the jump speed
of a one-mass train of 1 kg on a harmonic cam by 0.3 % at c = 1e8 N/m and 0.73 % at 1e9 N/m, far above the
interpolation between the speeds; refined, both are within 1e-6 of the closed form (tests/dynamics/test_accuracy.py).
A refinement costs most where the speeds that decide a headline are slow (many sub-steps) or the headline keeps moving
with the step; :data:`MAX_WORK` bounds it.

References: Hairer, Nørsett and Wanner (1993), section II.4 (the error of a step estimated by doing it again in two
halves, Richardson's extrapolation).
"""

from dataclasses import dataclass, field, fields
from typing import Optional

import numpy as np

from .kernels import BLOCK_SPEEDS
from .events import SweepEvents, force_reached_zero, level_crossing, zero_crossing
from .sweep import STATE_TOLERANCE, substeps, sweep

JUMP_ACCURACY = 5e-4
"""Relative error of the jump speed the refinement aims at (0.05 %: its time-step and speed-grid parts at most half
of it each)."""

SEATING_ACCURACY = 5e-3
"""Relative error of a seating velocity the refinement aims at (0.5 %)."""

BOUNCE_ACCURACY = 0.02
"""Error of a bounce height the refinement aims at, relative to the larger of the height and the bounce tolerance
(2 %: below the tolerance the valve rocks on its seat, and 2 % of it is 20 nm)."""

ONSET_ACCURACY = 1e-3
"""Relative error of the bounce onset speed the refinement aims at (0.1 %, 8 rpm at 8000 rpm; its time-step and
speed-grid parts at most half of it each)."""

MAX_HALVINGS = 4
"""Most halvings of the step (0.1 cam deg: to 0.00625); a headline that has not settled by then keeps its last
change as its error (the time step then costs 16 times the base step's at those speeds)."""

GRID_CHECKS = 6
"""Most speeds simulated to check the interpolation of a crossing between the speeds swept."""

MAX_WORK = 8.0
"""Most integrator work of a refinement, in units of the sweep's own (:func:`work`).  It bounds the cost where a
headline does not settle (a slow speed with many sub-steps whose crossing moves with every halving); the errors of the
headlines not settled by then are their last changes.  The stiff one-mass trains of the tests take up to 6 (81
speeds; 4 of 200), the built-in example 0.3."""

BLOCK_COST = 8
"""The fixed cost of a block of the kernels in speeds: a block of one speed takes about as long as eight speeds of a
large block take each (:mod:`.kernels`: the per-step work outside the loops over the speeds)."""


def work(n_sub, halvings=0) -> float:
    """The integrator work of a sweep whose speeds have the sub-steps ``n_sub`` (one per speed) at ``halvings``: for
    each group of equal sub-steps, sub-steps x 2^halvings x (its speeds + BLOCK_COST per block of
    :data:`~.kernels.BLOCK_SPEEDS`).

    Two speeds of 1 sub-step and one of 2, halved once: 1 x 2 x (2 + 8) + 2 x 2 x (1 + 8).

    >>> work(np.array([1, 1, 2]), 1)
    56.0
    """
    values, counts = np.unique(np.asarray(n_sub), return_counts=True)
    return float(sum(int(n) * 2**halvings * (int(k) + BLOCK_COST * -(-int(k) // BLOCK_SPEEDS))
                     for n, k in zip(values, counts, strict=True)))


@dataclass(frozen=True)
class Accuracy:
    """Estimated discretisation errors of a sweep's headlines (:func:`refine`; SI, camshaft speeds); nan where the
    headline is none.

    Attributes
    ----------
    jump_speed_step, jump_speed_grid : float
        Of the jump speed [rad/s]: its time-step part and its speed-grid part.
    bounce_onset_step, bounce_onset_grid : float
        The same of the bounce onset speed [rad/s].
    max_seating_velocity : float
        Of the largest |seating velocity| [m/s] (time step).
    step : float
        The finest step a headline was refined to [rad camshaft].
    """

    jump_speed_step: float
    jump_speed_grid: float
    bounce_onset_step: float
    bounce_onset_grid: float
    max_seating_velocity: float
    step: float

    @property
    def jump_speed(self) -> float:
        """The jump speed's estimated error, both parts [rad/s]."""
        return self.jump_speed_step + self.jump_speed_grid

    @property
    def bounce_onset(self) -> float:
        """The bounce onset speed's estimated error, both parts [rad/s]."""
        return self.bounce_onset_step + self.bounce_onset_grid


@dataclass(frozen=True)
class Refinement:
    """A sweep's headlines at the finest step :func:`refine` took, with their errors.

    Attributes
    ----------
    headline : dict
        :meth:`.sweep.SweepResult.headline`'s keys, each at the finest step.
    accuracy : Accuracy
    events : SweepEvents
        The sweep's events, each speed's at the finest step it was simulated at (the base step for most).
    halvings : ndarray (S,) of int
        Halvings of the step of each speed's events.
    extra : SweepEvents or None
        The events of the ``extra`` speeds, at their finest step.
    extra_seating_error, extra_bounce_error : ndarray
        Their estimated errors (time step) of the seating velocity [m/s] and the bounce height [m].
    """

    headline: dict
    accuracy: Accuracy
    events: SweepEvents
    halvings: np.ndarray
    extra: Optional[SweepEvents] = None
    extra_seating_error: np.ndarray = field(default_factory=lambda: np.zeros(0))
    extra_bounce_error: np.ndarray = field(default_factory=lambda: np.zeros(0))


FIELDS = tuple(f.name for f in fields(SweepEvents))


class _Runs:
    """The events of single camshaft speeds at a step halved a number of times (:func:`.sweep.sweep`'s ``halvings``),
    each (speed, halvings) simulated once."""

    def __init__(self, law, train, revolutions, step_deg, bounce_tolerance, tolerance):
        self.law, self.train, self.revolutions, self.step_deg = law, train, revolutions, step_deg
        self.bounce_tolerance, self.tolerance = bounce_tolerance, tolerance
        self.rows, self.halvings, self.work = {}, {}, 0.0
        self.rate = train.network().highest_frequency()

    def seed(self, speeds, events, halvings=0):
        """Keep the ``events`` of ``speeds`` [rad/s] at ``halvings``."""
        for i, w in enumerate(np.asarray(speeds, dtype=float).tolist()):
            self.rows[halvings, w] = tuple(getattr(events, name)[i] for name in FIELDS)
            self.halvings[w] = max(self.halvings.get(w, 0), halvings)

    def fetch(self, wanted):
        """Simulate the (speed [rad/s], halvings) pairs of ``wanted`` not simulated yet, those of equal halvings together
        (a block of the kernel costs about as much for one speed as for eight, :mod:`.kernels`)."""
        for halvings, group in sorted(self.missing(wanted).items()):
            group = sorted(group)
            self.work += self.cost({halvings: group})
            self.seed(group, sweep(self.law, self.train, group, self.revolutions, self.step_deg,
                                   bounce_tolerance=self.bounce_tolerance, tolerance=self.tolerance,
                                   halvings=halvings).events, halvings)

    def missing(self, wanted) -> dict:
        """The speeds [rad/s] of the (speed, halvings) pairs of ``wanted`` not simulated yet, by halvings."""
        missing = {}
        for w, halvings in wanted:
            if (halvings, float(w)) not in self.rows:
                missing.setdefault(halvings, set()).add(float(w))
        return missing

    def cost(self, missing) -> float:
        """The integrator work (:func:`work`) of simulating ``missing`` ({halvings: speeds}), each halvings' speeds in
        one sweep."""
        step = np.radians(self.step_deg)
        return sum(work(substeps(self.rate, np.array(sorted(group)), step), halvings)
                   for halvings, group in missing.items())

    def events(self, speeds, halvings) -> SweepEvents:
        """The :class:`SweepEvents` of ``speeds`` [rad/s] at ``halvings``, in their order."""
        speeds = [float(w) for w in np.atleast_1d(speeds)]
        self.fetch([(w, halvings) for w in speeds])
        rows = [self.rows[halvings, w] for w in speeds]
        return SweepEvents(*(np.array([row[k] for row in rows]) for k in range(len(FIELDS))))

    def finest(self, speed) -> int:
        """The most halvings ``speed`` [rad/s] has been simulated at."""
        return self.halvings[float(speed)]

    def overlay(self, speeds, events) -> SweepEvents:
        """``events`` of the grid ``speeds`` with each speed's row at the finest step it was simulated at (but the index
        of the first seating, which stays that of the record of ``events``)."""
        rows = {name: np.array(getattr(events, name)) for name in FIELDS}
        for i, w in enumerate(speeds.tolist()):
            finest = self.finest(w)
            if finest:
                for k, name in enumerate(FIELDS):
                    if name != "seating_index":
                        rows[name][i] = self.rows[finest, w][k]
        return SweepEvents(**rows)


def _change(new, old) -> np.ndarray:
    """|new - old|, 0 where both are nan (no seating either time), inf where one is."""
    new, old = np.asarray(new, dtype=float), np.asarray(old, dtype=float)
    both = np.isnan(new) & np.isnan(old)
    with np.errstate(invalid="ignore"):
        return np.where(both, 0.0, np.where(np.isnan(new) | np.isnan(old), np.inf, np.abs(new - old)))


class _Crossing:
    """The jump speed (``kind`` "jump": the zero of the smallest contact force, :func:`.events.zero_crossing`, fitted
    through up to 3 speeds below the first whose force reaches zero) or the bounce onset ("onset": where the bounce
    height crosses the bounce tolerance, :func:`.events.level_crossing`, linear between 2 speeds) of the grid
    ``speeds``, refined to the relative ``accuracy`` in rounds (:meth:`wanted`, then :meth:`advance`): a halving of the
    step at the speeds it is found from, until it changes by no more than half the accuracy, then a speed simulated
    where it is found (:meth:`probe`), until that moves it by no more than half the accuracy; a probe that changes
    the crossing by more than that from the step before (it lies nearer the crossing than the grid's speeds, where a
    time step's error counts for more) halves the step again."""

    def __init__(self, runs, kind, speeds, accuracy, max_halvings):
        self.runs, self.jump, self.speeds, self.accuracy = runs, kind == "jump", speeds, accuracy
        self.max_halvings = max_halvings
        self.below = 3 if self.jump else 1
        self.found, hit = self.at(speeds, 0)
        self.halvings, self.step_error, self.grid_error, self.checks = 0, np.nan, np.nan, 0
        self.settled = bool(np.isnan(self.found)) or max_halvings == 0
        first = int(np.argmax(hit))
        self.lo, self.hi = max(first - self.below, 0), first
        self.extra, self.pending = [], None

    @property
    def points(self) -> list:
        """The speeds the crossing is found from: the grid's window and the probes."""
        return sorted([*self.speeds[self.lo:self.hi + 1].tolist(), *self.extra])

    def at(self, speeds, halvings) -> tuple[float, np.ndarray]:
        """(the crossing, nan if none; which of ``speeds`` have the event) at ``halvings``."""
        e = self.runs.events(speeds, halvings)
        if self.jump:
            hit = force_reached_zero(e)
            return zero_crossing(np.asarray(speeds, dtype=float), e.min_contact_force, hit), hit
        level = self.runs.bounce_tolerance
        return level_crossing(np.asarray(speeds, dtype=float), e.bounce_height, level), e.bounce_height > level

    def tight(self, error) -> bool:
        """Whether an ``error`` [rad/s] is within half the accuracy of the crossing."""
        return bool(error <= 0.5 * self.accuracy * self.found)

    def wanted(self) -> list:
        """The (speed, halvings) pairs of the next round: its speeds at the next halving while the time-step error is
        above half the accuracy, else a probe at this halving and the one before while the speed-grid error is; none
        once settled."""
        if self.settled:
            return []
        if not self.tight(self.step_error) and self.halvings < self.max_halvings:
            self.pending = None
            return [(w, self.halvings + 1) for w in self.points]
        if not self.tight(self.grid_error) and self.checks < GRID_CHECKS:
            self.pending = self.probe()
            if self.pending is not None:
                return [(self.pending, self.halvings), (self.pending, self.halvings - 1)]
        self.settled = True
        return []

    def advance(self):
        """The round :meth:`wanted` asked for."""
        if self.pending is None:
            self.halve()
        else:
            before = self.found
            self.extra.append(self.pending)
            self.found, hit = self.at(self.points, self.halvings)
            low, high = self.bracket(hit)
            self.grid_error = high - low if self.jump and self.found >= high else abs(self.found - before)
            self.checks += 1
            self.compare()
        self.settled = bool(np.isnan(self.found))

    def halve(self):
        """The crossing at the next halving, the grid's window moved (a few speeds at a time) until it holds the first
        speed with the event at this step and the speeds below it that the crossing is fitted through, and no more."""
        self.halvings += 1
        n = self.speeds.size
        while True:
            _, hit = self.at(self.speeds[self.lo:self.hi + 1], self.halvings)
            if not hit.any():
                if self.hi + 1 >= n:
                    break
                self.hi = min(self.hi + self.below + 1, n - 1)
                continue
            first = self.lo + int(np.argmax(hit))
            if first - self.below < self.lo and self.lo > 0:
                self.lo = max(first - self.below, 0)
                continue
            self.lo, self.hi = max(first - self.below, 0), first
            break
        self.found = self.at(self.points, self.halvings)[0]
        self.compare()

    def compare(self):
        """The time-step error: the change of the crossing from the halving before, through the same speeds."""
        if not np.isnan(self.found):
            self.step_error = float(_change(self.found, self.at(self.points, self.halvings - 1)[0]))

    def bracket(self, hit) -> tuple[float, float]:
        """The last speed of :attr:`points` without the event below the first with it, and that first."""
        points = self.points
        first = int(np.argmax(hit))
        return points[max(first - 1, 0)], points[first]

    def probe(self) -> Optional[float]:
        """The speed [rad/s] that checks the interpolation between the speeds: the bounce onset found, or halfway
        from the last speed below the jump to the jump found (the force there is still well above zero, where the
        time step clips it, see the module docstring), the midpoint of the bracket where that lies outside it; None
        where no speed is left between."""
        points = self.points
        low, high = self.bracket(self.at(points, self.halvings)[1])
        probe = 0.5 * (low + self.found) if self.jump else self.found
        if not low < probe < high:
            probe = 0.5 * (low + high)
        return probe if low < probe < high and probe not in points else None


class _Settling:
    """Speeds whose seating velocity (and, with ``bounce``, bounce height) are refined, each halving its step until
    they change by no more than :data:`SEATING_ACCURACY` (:data:`BOUNCE_ACCURACY`)."""

    def __init__(self, runs, bounce):
        self.runs, self.bounce = runs, bounce
        self.halvings, self.errors, self.pending = {}, {}, set()

    def add(self, speeds):
        """Refine ``speeds`` [rad/s] too (those not refined yet)."""
        for w in map(float, speeds):
            if w not in self.halvings:
                self.halvings[w], self.errors[w] = 0, (np.nan, np.nan)
                self.pending.add(w)

    def wanted(self, max_halvings) -> list:
        """The (speed, halvings) pairs of the next halving of the speeds not settled."""
        return [(w, self.halvings[w] + 1) for w in sorted(self.pending) if self.halvings[w] < max_halvings]

    def advance(self, max_halvings):
        """Each speed not settled at its next halving."""
        for w, halvings in self.wanted(max_halvings):
            old, new = self.runs.events([w], halvings - 1), self.runs.events([w], halvings)
            dv = float(_change(new.seating_velocity, old.seating_velocity)[0])
            dh = float(_change(new.bounce_height, old.bounce_height)[0])
            self.halvings[w], self.errors[w] = halvings, (dv, dh)
            settled = not dv > SEATING_ACCURACY * abs(float(new.seating_velocity[0]))
            if self.bounce:
                settled &= dh <= BOUNCE_ACCURACY * max(float(new.bounce_height[0]), self.runs.bounce_tolerance)
            if settled or halvings >= max_halvings:
                self.pending.discard(w)


def refine(law, train, result, revolutions=3, step_deg=0.1, seating_top=np.inf, extra=None,
           max_halvings=MAX_HALVINGS, tolerance=STATE_TOLERANCE, max_work=MAX_WORK, onset=True) -> Refinement:
    """The headlines of a sweep at a step halved at the speeds that decide them, with their estimated errors.

    Parameters
    ----------
    law, train, revolutions, step_deg, tolerance
        Those of the sweep ``result`` (:func:`.sweep.sweep`; ``step_deg`` its step [camshaft deg]).
    result : SweepResult
    seating_top : float
        The highest speed of the graded seating velocity [rad/s camshaft] (the rated speed): the largest seating
        velocity up to it is refined as well as the sweep's largest.
    extra : SweepResult, optional
        More speeds (the rated speed) whose seating velocity and bounce height are refined.
    max_halvings : int
    max_work : float
        Most integrator work of the refinement as a multiple of the sweep's (:data:`MAX_WORK`).
    onset : bool
        Refine the bounce onset speed; False: it is the sweep's (its errors nan), as where the sweep has a few of
        the speeds alone (:func:`.sweep.headline_sweep`, whose bounce onset is not the full sweep's anyway): the
        onset's rounds were most of the refinement of the built-in example's intake (up to 4 of its 7 sweeps).

    Returns
    -------
    Refinement

    Notes
    -----
    Refined, as the module docstring says: the jump speed (the speeds through which the zero of the smallest contact
    force is fitted and the first speed that separates, :data:`JUMP_ACCURACY`), the bounce onset speed (the two
    speeds about it, :data:`ONSET_ACCURACY`), the seating velocity (:data:`SEATING_ACCURACY`) of the speeds whose
    |seating velocity| is within that accuracy of the largest, of all the speeds and of those up to
    ``seating_top``, and the seating velocity and the bounce height (:data:`BOUNCE_ACCURACY`) of the ``extra``
    speeds.  The speeds of a round (a halving, a probe) are simulated together, those of each step in one sweep; the
    rounds stop once the next would take the work of the refinement beyond ``max_work`` times the sweep's.
    """
    runs = _Runs(law, train, revolutions, step_deg, result.bounce_tolerance, tolerance)
    speeds = result.cam_speeds
    runs.seed(speeds, result.events)
    extra_speeds = [] if extra is None else extra.cam_speeds.tolist()
    if extra is not None:
        runs.seed(extra_speeds, extra.events)
    graded = speeds <= seating_top * (1.0 + 1e-12)
    budget = max_work * work(result.substeps)

    def near_top():
        """The speeds whose |seating velocity| is within SEATING_ACCURACY of the largest, of all and up to
        seating_top."""
        seat = np.abs(runs.overlay(speeds, result.events).seating_velocity)
        out = []
        for mask in (np.ones(speeds.size, dtype=bool), graded):
            inside = np.where(mask, seat, np.nan)
            if np.isfinite(inside).any():
                out += speeds[inside >= (1.0 - SEATING_ACCURACY) * np.nanmax(inside)].tolist()
        return out

    crossings = (_Crossing(runs, "jump", speeds, JUMP_ACCURACY, max_halvings),
                 _Crossing(runs, "onset", speeds, ONSET_ACCURACY, max_halvings if onset else 0))
    seats, rated = _Settling(runs, bounce=False), _Settling(runs, bounce=True)
    seats.add(near_top())
    rated.add(extra_speeds)
    while True:
        asks = [(part, part.wanted()) for part in crossings]
        wanted = [pair for _, pairs in asks for pair in pairs] + seats.wanted(max_halvings) + rated.wanted(max_halvings)
        if not wanted or runs.work + runs.cost(runs.missing(wanted)) > budget:
            break
        runs.fetch(wanted)
        for part, pairs in asks:
            if pairs:
                part.advance()
        seats.advance(max_halvings)
        rated.advance(max_halvings)
        seats.add(near_top())
    events = runs.overlay(speeds, result.events)
    seat = np.abs(events.seating_velocity)
    worst = int(np.nanargmax(seat)) if np.isfinite(seat).any() else None
    clash = speeds[result.clash_margin < 0.0]
    jump, onset = crossings
    headline = {"jump_speed": jump.found, "bounce_onset_speed": onset.found,
                "max_seating_velocity": float(seat[worst]) if worst is not None else np.nan,
                "max_seating_velocity_speed": float(speeds[worst]) if worst is not None else np.nan,
                "coil_clash_speed": float(clash.min()) if clash.size else np.nan}
    finest = max(jump.halvings, onset.halvings, *(runs.finest(w) for w in [*speeds.tolist(), *extra_speeds]))
    accuracy = Accuracy(jump.step_error, jump.grid_error, onset.step_error, onset.grid_error,
                        seats.errors.get(float(speeds[worst]), (np.nan,))[0] if worst is not None else np.nan,
                        float(np.radians(step_deg) / 2**finest))
    halvings = np.array([runs.finest(w) for w in speeds.tolist()])
    if extra is None:
        return Refinement(headline, accuracy, events, halvings)
    return Refinement(headline, accuracy, events, halvings, runs.overlay(extra.cam_speeds, extra.events),
                      np.array([rated.errors[w][0] for w in extra_speeds]),
                      np.array([rated.errors[w][1] for w in extra_speeds]))
