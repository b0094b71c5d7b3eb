"""The lift-law protocol shared by every cam law.

Angle convention
----------------
A lift law is a function of the **camshaft** angle ``theta`` [rad] measured from the
cam nose (the axis of the lobe): ``theta < 0`` on the opening flank, ``theta > 0`` on
the closing flank.  Outside ``[start, end]`` the follower rests on the base circle and
every quantity is zero.  The lift ``h`` is the follower (tappet) lift above the base
circle including the ramp, as in Valve-train practical works (n.d.) eqs. (2.5)-(2.8); the valve moves once the
ramp height (the clearance) is taken up.

Derivatives are analytic.  ``derivatives(theta)`` returns the geometric derivatives
``h, dh/dtheta, d2h/dtheta2, d3h/dtheta3`` [m, m/rad, m/rad^2, m/rad^3]; the time
derivatives at a constant camshaft speed omega [rad/s] are ``v = omega h'``,
``a = omega^2 h''`` and ``jerk = omega^3 h'''``.
"""

from abc import ABC, abstractmethod
from dataclasses import dataclass
from functools import cached_property

import numpy as np
from numba import njit

from ..followers import FLAT
from ..numerics import bracketed_roots, first_largest, invert_angle, level_span
from ..units import si_name


@dataclass(frozen=True)
class Segment:
    """A piece of a lift law between two camshaft angles [rad from the nose]."""

    name: str
    start: float
    end: float


@dataclass(frozen=True)
class Extremes:
    """Extreme follower kinematics of a law at a camshaft speed (SI, follower side).

    Attributes
    ----------
    max_velocity : float
        Largest follower velocity [m/s] (opening flank).
    max_acceleration, min_acceleration : float
        Largest and smallest follower acceleration [m/s^2].
    max_velocity_angle, max_acceleration_angle, min_acceleration_angle : float
        Camshaft angles of those extremes [rad from the nose].
    """

    max_velocity: float
    max_acceleration: float
    min_acceleration: float
    max_velocity_angle: float
    max_acceleration_angle: float
    min_acceleration_angle: float


@dataclass(frozen=True)
class AccelerationStep:
    """A step of the follower acceleration at a segment boundary of a law (its jerk is an impulse there).

    Attributes
    ----------
    angle : float
        Camshaft angle of the boundary [rad from the nose].
    before, after : float
        d2h/dtheta2 just before and just after it, the one-sided limits [m/rad^2].
    """

    angle: float
    before: float
    after: float

    @property
    def size(self) -> float:
        """after - before [m/rad^2]; times omega^2 the step of the acceleration [m/s^2]."""
        return self.after - self.before


STEP_TOLERANCE = 1e-6
"""A jump of d2h/dtheta2 at a boundary is a step when it exceeds this fraction of the largest |d2h/dtheta2| of the
law: far above the residual of a law whose continuity is solved numerically, far below any step a designer sees."""


class LiftLaw(ABC):
    """Base class of cam lift laws (see the module docstring for the conventions)."""

    #: identifier used in specification files and results (``law = "..."``)
    name: str = ""

    #: where the method and its formulas come from (work, equations; a citation of valvetrain.bibliography), shown in results and report
    source: str = ""

    #: highest derivative of the lift that is continuous at the junctions (2: acceleration continuous)
    continuity: int = 2

    @classmethod
    def from_mm_deg(cls, **keywords) -> "LiftLaw":
        """The law from keywords in the units of a specification file: a keyword ending in a unit (``lift_mm``,
        ``phi1_deg``, ``ramp_velocity_mm_per_deg``; :data:`valvetrain.units.SUFFIXES`) is the constructor's SI
        parameter without the unit (``lift`` [m], ``phi1`` [rad], ``ramp_velocity`` [m/rad]); the others pass as
        they are.  The angles are the law's own: camshaft degrees.

        Examples
        --------
        >>> from valvetrain.laws import KurzLaw
        >>> a = KurzLaw.from_mm_deg(lift_mm=10.0, clearance_mm=0.3, ramp_velocity_mm_per_deg=0.015, phi1_deg=27.0,
        ...                         phi2_deg=9.0, phi3_deg=48.0)
        >>> b = KurzLaw(lift=0.01, clearance=0.0003, ramp_velocity=0.015e-3 * 180 / np.pi, phi1=np.radians(27.0),
        ...             phi2=np.radians(9.0), phi3=np.radians(48.0))
        >>> bool(np.allclose(a.lift(np.linspace(-1.5, 1.5, 7)), b.lift(np.linspace(-1.5, 1.5, 7)), rtol=1e-13))
        True
        """
        converted = {}
        for key, value in keywords.items():
            name, factor = si_name(key)
            converted[name] = value if factor == 1.0 else np.multiply(value, factor)
        return cls(**converted)

    #: the law has no ramp and its flanks take up the valve clearance (the valve meets its seat at speed)
    clearance_on_flank: bool = False

    @property
    @abstractmethod
    def segments(self) -> list[Segment]:
        """Ordered list of :class:`Segment` covering ``[start, end]``."""

    @property
    @abstractmethod
    def lift_max(self) -> float:
        """Follower lift above the ramp at the nose, h_T max [m]."""

    @property
    @abstractmethod
    def ramp_height(self) -> float:
        """Ramp height, the clearance taken up before the valve moves [m] (0: no ramp)."""

    @property
    @abstractmethod
    def ramp_angle(self) -> float:
        """Ramp length Phi_0 on one side [rad camshaft] (0: no ramp)."""

    @abstractmethod
    def derivatives(self, theta) -> np.ndarray:
        """Lift and its first three derivatives, shape (4, n) [m, m/rad, m/rad^2, m/rad^3]."""

    def batch_key(self) -> tuple | None:
        """Laws of one class with equal keys (not None) are sampled together by the class's
        :meth:`_batch_derivatives` (:func:`batch_derivatives`); None (the default): each on its own."""
        return None

    @classmethod
    def _batch_derivatives(cls, laws, theta, member):
        """The derivatives of ``laws[member[k]]`` at ``theta[k]``, shape (4, n): each law at its own angles."""
        out = np.empty((4, theta.size))
        for law, at in zip(laws, _members(member, len(laws)), strict=True):
            out[:, at] = law.derivatives(theta[at])
        return out

    @abstractmethod
    def coefficients(self) -> dict:
        """The law's coefficients as a dict in the units of its source (for results and reports)."""

    def checks(self) -> list:
        """The law's own recommended-range checks, a list of :class:`~valvetrain.checks.Check`, passed or not."""
        return []

    def train_checks(self, natural_frequency, cam_speed) -> list:
        """The law's checks against the elastic train that drives it (natural frequency omega_n and camshaft speed
        omega [rad/s]), a list of :class:`~valvetrain.checks.Check`."""
        return []

    @property
    def start(self) -> float:
        """Camshaft angle where the follower leaves the base circle [rad from the nose]."""
        return self.segments[0].start

    @property
    def end(self) -> float:
        """Camshaft angle where the follower returns to the base circle [rad from the nose]."""
        return self.segments[-1].end

    @property
    def valve_opens(self) -> float:
        """Camshaft angle where the ramp ends on the opening flank and the valve starts to move [rad]."""
        return self.start + self.ramp_angle

    @property
    def valve_closes(self) -> float:
        """Camshaft angle where the valve seats (start of the closing ramp) [rad]."""
        return self.end - self.ramp_angle

    @property
    def breakpoints(self) -> np.ndarray:
        """Angles where the law or the valve lift is not smooth: segment junctions, ends included [rad]."""
        return np.array([s.start for s in self.segments] + [self.end])

    def segment_names(self, theta) -> np.ndarray:
        """Name of the segment of each angle (``"base circle"`` outside the event)."""
        theta = np.asarray(theta, dtype=float)
        names = np.array(["base circle"] + [s.name for s in self.segments], dtype=object)
        edges = np.array([s.start for s in self.segments] + [self.end])
        idx = np.searchsorted(edges, theta, side="right")
        idx[theta == self.end] = len(self.segments)
        idx[(theta < self.start) | (theta > self.end)] = 0
        return names[idx]

    def acceleration_steps(self) -> tuple[AccelerationStep, ...]:
        """The steps of the acceleration at the law's boundaries, a tuple of :class:`AccelerationStep`.

        Notes
        -----
        At every breakpoint (segment junctions, and the start and end of the event, where the base circle has
        d2h/dtheta2 = 0) the one-sided limits are each side's own formula taken :data:`EDGE_INSET` of the event
        from the boundary (the law's analytic segments, not differenced samples).  A jump larger than
        :data:`STEP_TOLERANCE` of the largest |d2h/dtheta2| is a step: the jerk is a Dirac impulse of that size
        times omega^2 there, and a train driven by the cam feels a shock.
        """
        edges = self.breakpoints
        inset = EDGE_INSET * (self.end - self.start)
        before, after = self.derivatives(edges - inset)[2], self.derivatives(edges + inset)[2]
        ext = self.extremes(1.0)
        scale = max(ext.max_acceleration, -ext.min_acceleration)
        jumps = np.abs(after - before) > STEP_TOLERANCE * scale
        return tuple(AccelerationStep(float(a), float(b), float(c))
                     for a, b, c in zip(edges[jumps], before[jumps], after[jumps], strict=True))

    def lift(self, theta) -> float | np.ndarray:
        """Follower lift h [m]."""
        return self.derivatives(theta)[0]

    def velocity(self, theta, omega) -> float | np.ndarray:
        """Follower velocity omega dh/dtheta [m/s] at camshaft speed omega [rad/s]."""
        return omega * self.derivatives(theta)[1]

    def acceleration(self, theta, omega) -> float | np.ndarray:
        """Follower acceleration omega^2 d2h/dtheta2 [m/s^2]."""
        return omega**2 * self.derivatives(theta)[2]

    def jerk(self, theta, omega) -> float | np.ndarray:
        """Follower jerk omega^3 d3h/dtheta3 [m/s^3]."""
        return omega**3 * self.derivatives(theta)[3]

    def valve_lift(self, theta, rocker_ratio=1.0, follower=FLAT) -> float | np.ndarray:
        """Valve lift i_k i_f(h) (h - h0) for h > h0, else 0 [m] (Valve-train practical works (n.d.), work 2: valve =
        tappet x l_v/l_t), with i_f the follower's own lever ratio (:meth:`valvetrain.followers.Follower.ratio`, 1 for
        a translating follower)."""
        return valve_lift_of(self.lift(theta), self.ramp_height, rocker_ratio, follower)

    def crossings(self, height) -> tuple[float, float]:
        """Camshaft angles [rad from the nose] where the lift first rises above and last falls below ``height``
        [m], by root finding on the law; ``(nan, nan)`` where the lift never reaches it."""
        return level_span(self.lift, self.start, self.end, height)

    def duration(self, height) -> float:
        """Camshaft angle [rad] over which the lift exceeds ``height`` [m] (nan if it never reaches it)."""
        rise, fall = self.crossings(height)
        return fall - rise

    def profile(self, theta, heel_radius, follower=FLAT) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """The cam profile at camshaft angles ``theta`` [rad from the nose].

        Parameters
        ----------
        heel_radius : float
            Radius of the circle the law's lift starts from [m] (r0 - h0 with a ramp).
        follower : valvetrain.followers.Follower
            The follower the cam drives (default flat).

        Returns
        -------
        (ndarray, ndarray, ndarray, ndarray)
            Contour points shape (2, n) [m] (cam frame, nose on +y), profile radius of curvature
            [m], pressure angle [rad] (zero for a flat follower) and contact offset from the
            follower axis [m] (h' for a flat follower, zero for a roller).

        References
        ----------
        Shang Hanji (1988), section 2.1, eqs. (2.6)-(2.7), (2.15)-(2.16) (:mod:`valvetrain.geometry`).
        """
        theta = np.asarray(theta, dtype=float)
        h, dh, d2h, _ = self.derivatives(theta)
        return (follower.contour(theta, heel_radius, h, dh), follower.curvature(heel_radius, h, dh, d2h),
                follower.pressure_angle(heel_radius, h, dh), follower.contact_offset(dh))

    def curvature(self, theta, heel_radius, follower=FLAT) -> float | np.ndarray:
        """The profile's radius of curvature [m] at camshaft angles ``theta`` [rad from the nose], that of
        :meth:`profile` without the contour (the arguments of :meth:`profile`)."""
        h, dh, d2h, _ = self.derivatives(np.asarray(theta, dtype=float))
        return follower.curvature(heel_radius, h, dh, d2h)

    def polar_radius(self, polar_angle, heel_radius, follower=FLAT, samples=7201) -> float | np.ndarray:
        """Radius of the cam contour at polar angles from the nose direction (+y towards +x) [m].

        Each radius is found on the analytic contour: the contour point's polar angle is
        bracketed on ``samples`` camshaft angles and the bracket bisected, all angles at once,
        to the round-off of the angle (not interpolated), so a table of any step is exact.

        Where the law's velocity jumps (a measured law at the ends of its event) the contact point jumps, and the
        polar angles in between belong to no camshaft angle: there the cam is the follower's own surface at the
        angle of the jump (the flat the face grinds, the roller's circle), met at the target by a second inversion
        over the velocity between its values on the two sides of the jump (the contact point of a velocity in
        between lies on that surface).  Otherwise such a target gets the radius of one side or the other, by
        round-off.
        """
        def contour(t, derivs=None):
            h, dh = self.derivatives(t)[:2] if derivs is None else derivs
            return follower.contour(t, heel_radius, h, dh)

        def miss(p, goal):
            return np.angle(np.exp(1j * (np.arctan2(*p) - goal)))

        goal = np.asarray(polar_angle, dtype=float)
        found = invert_angle(lambda t: np.arctan2(*contour(t)), goal, samples, brackets=True)
        theta, lo, hi, goal = (x.ravel() for x in (*found, goal))
        point = contour(theta)
        gap = np.abs(miss(point, goal)) > CONTOUR_GAP
        if gap.any():
            a, b, g = lo[gap], hi[gap], goal[gap]
            d_a, d_b = self.derivatives(a)[:2], self.derivatives(b)[:2]

            def between(s):     # the jump's two sides a, b and a lift and velocity in between, s = 0 at a, 1 at b
                return contour((1.0 - s) * a + s * b, (1.0 - s) * d_a + s * d_b)

            ends = np.zeros(g.size), np.ones(g.size)
            s = bracketed_roots(lambda s: miss(between(s), g), *ends, *(miss(between(e), g) for e in ends))
            point[:, gap] = between(s)
        return np.hypot(*point).reshape(np.shape(polar_angle))[()]

    def extremes(self, omega) -> Extremes:
        """Extreme velocity and accelerations at camshaft speed omega [rad/s], found on the analytic law.

        Notes
        -----
        The search does not depend on omega: it runs once per law (:meth:`_extreme_points`), and each call scales
        its dh/dtheta and d2h/dtheta2 by omega and omega^2.
        A velocity extreme lies where d2h/dtheta2 = 0 or at a segment end, an acceleration
        extreme where d3h/dtheta3 = 0 or at a segment end (a kink, or the jump of a law with
        continuity 1, where either side may hold the extreme).  Every segment is sampled at
        :data:`EXTREME_SAMPLES` angles from :data:`EDGE_INSET` inside its ends (its own formula
        there, the one-sided limits to that inset); every change of sign of the next derivative
        between two samples that makes a maximum (minimum) is refined to its root, all at once
        (:func:`~valvetrain.numerics.bracketed_roots`).  The extreme is the best of the
        breakpoints, the samples and the roots.  The largest velocity is searched on the opening
        flank, up to the nose (theta = 0, a breakpoint of every law).
        """
        (xv, v), (xa, amax), (xn, amin) = self._extreme_points
        return Extremes(omega * v, omega**2 * amax, omega**2 * amin, xv, xa, xn)

    @cached_property
    def _extreme_points(self):
        """``((theta, dh/dtheta), (theta, d2h/dtheta2), (theta, d2h/dtheta2))`` at the largest velocity, the largest
        and the smallest acceleration [rad, m/rad, m/rad^2] (:meth:`extremes`)."""
        edges = self.breakpoints
        t = np.linspace(0.0, 1.0, EXTREME_SAMPLES)
        t[[0, -1]] = EDGE_INSET, 1.0 - EDGE_INSET
        x = edges[:-1, None] + np.diff(edges)[:, None] * t
        d = self.derivatives(np.concatenate([edges, x.ravel()]))
        at_edges, d = d[:, :edges.size], d[:, edges.size:].reshape((4,) + x.shape)
        everywhere = np.ones(x.shape[0], dtype=bool)
        searches = [(1, 1.0, edges[1:] <= 0.0), (2, 1.0, everywhere), (2, -1.0, everywhere)]
        brackets = [_peak_brackets(x[m], sign * d[row + 1][m]) for row, sign, m in searches]
        which = np.concatenate([np.full(b[0].size, n) for n, b in enumerate(brackets)])
        rows = np.array([row + 1 for row, _, _ in searches])[which]
        signs = np.array([sign for _, sign, _ in searches])[which]
        roots = bracketed_roots(lambda t: signs * self.derivatives(t)[rows, np.arange(t.size)],
                                *(np.concatenate(parts) for parts in zip(*brackets, strict=True)))
        at_roots = self.derivatives(roots)
        found = []
        for n, (row, sign, m) in enumerate(searches):
            ends = edges <= edges[1:][m].max()
            xs = np.concatenate([edges[ends], x[m].ravel(), roots[which == n]])
            ys = np.concatenate([at_edges[row][ends], d[row][m].ravel(), at_roots[row][which == n]])
            order = np.argsort(xs, kind="stable")     # of extremes equal to round-off, the one at the smallest angle
            i = order[first_largest(sign * ys[order])]
            found.append((float(xs[i]), float(ys[i])))
        return tuple(found)


CONTOUR_GAP = 1e-10
"""Miss of a polar angle [rad] beyond which :meth:`LiftLaw.polar_radius` takes the target for one in a jump of the
contour: far above the round-off of a contour point's angle at its root (some 1e-15 rad), far below a jump of the
velocity of the order of a measurement's noise (a jump of 0.1 mm/rad moves the contact point by 5e-3 rad on a
20 mm base circle); a target so close to a jump's side that it is not told from it has that side's radius to
1e-12 relative."""


EXTREME_SAMPLES = 65
"""Samples per segment in :meth:`LiftLaw.extremes`."""

EDGE_INSET = 1e-12
"""Inset of the first and last sample of a segment from its ends, a fraction of its length: far above the
round-off of a law's own segment search, so the sample takes the segment's formula."""


def _peak_brackets(x, slope):
    """Brackets ``(a, b, slope(a), slope(b))`` between consecutive samples (along the last axis) where the slope
    falls from positive to negative: each holds a maximum of the function."""
    falls = (slope[..., :-1] > 0.0) & (slope[..., 1:] < 0.0)
    return x[..., :-1][falls], x[..., 1:][falls], slope[..., :-1][falls], slope[..., 1:][falls]


class RampedLaw(LiftLaw):
    """Lift above the ramp ``self._lift`` and an optional ramp ``self.ramp`` (a :class:`~.ramps.Ramp` or None)."""

    ramp = None

    @property
    def lift_max(self) -> float:
        return self._lift

    @property
    def ramp_height(self) -> float:
        return self.ramp.height if self.ramp is not None else 0.0

    @property
    def ramp_angle(self) -> float:
        return self.ramp.length if self.ramp is not None else 0.0


class SymmetricLaw(LiftLaw):
    """A law symmetric about the nose, defined by its rise on the opening side.

    ``phi`` is the camshaft angle from the start of the event (ramp start),
    ``0 <= phi <= half_angle``; the law mirrors it onto the closing flank with
    ``phi = half_angle - |theta|``: ``h`` and ``h''`` are even, ``h'`` and ``h'''`` odd.
    A law gives its rise either vectorised, ``_rise(phi)``, mirrored by :meth:`_mirrored`, or
    in a compiled kernel that overrides :meth:`_mirrored` and mirrors each angle with
    :func:`mirror` as it goes (one pass over the angles, no masks).
    """

    @property
    @abstractmethod
    def half_angle(self) -> float:
        """Half of the whole event, ramp included [rad camshaft]."""

    @abstractmethod
    def _rise_segments(self):
        """``[(name, phi_start, phi_end), ...]`` on the opening side, in rise coordinates."""

    def _rise(self, phi):
        """Rise and its derivatives with respect to phi, shape (4, n) (for :meth:`_mirrored`)."""
        raise NotImplementedError

    @cached_property
    def segments(self) -> list[Segment]:
        """The opening flank's segments and their mirror images, made once per law (a law is not changed once
        made)."""
        T = self.half_angle
        rise = self._rise_segments()
        opening = [Segment(f"{n} opening", a - T, b - T) for n, a, b in rise]
        closing = [Segment(f"{n} closing", T - b, T - a) for n, a, b in reversed(rise)]
        return opening + closing

    def derivatives(self, theta) -> np.ndarray:
        theta = np.asarray(theta, dtype=float)
        out = np.zeros((4, theta.size))
        self._mirrored(np.ascontiguousarray(theta).ravel(), out)
        return out.reshape((4,) + theta.shape)

    def _mirrored(self, theta, out):
        """Write the law at the angles ``theta`` (1-D) into ``out`` (zeros, shape (4, n)) by mirroring :meth:`_rise`:
        the batch of one law (:meth:`_mirror`)."""
        self._mirror([self], theta, None, out)

    @classmethod
    def _batch_derivatives(cls, laws, theta, member):
        if laws[0].batch_key() is None:  # no batch of its own (a compiled kernel): each law on its own
            return super()._batch_derivatives(laws, theta, member)
        out = np.zeros((4, theta.size))
        cls._mirror(laws, theta, member, out)
        return out

    @classmethod
    def _mirror(cls, laws, theta, member, out):
        """Write ``laws[member[k]]`` at ``theta[k]`` (``member`` None: the one law at every angle) into ``out`` (zeros,
        shape (4, n)) by mirroring :meth:`_batch_rise`."""
        half = member_values([law.half_angle for law in laws], member)
        inside = np.abs(theta) <= half
        t = theta[inside]
        if member is not None:
            half, member = half[inside], member[inside]
        r = cls._batch_rise(laws, half - np.abs(t), member)
        r[1::2] *= -np.sign(t)
        out[:, inside] = r

    @classmethod
    def _batch_rise(cls, laws, phi, member):
        """The rise of ``laws[member[k]]`` at ``phi[k]`` (``member`` None: the one law), shape (4, n): each law's
        :meth:`_rise` (a law with a batch of its own overrides this)."""
        if member is None:
            return laws[0]._rise(phi)
        out = np.empty((4, phi.size))
        for law, at in zip(laws, _members(member, len(laws)), strict=True):
            out[:, at] = law._rise(phi[at])
        return out


def _members(member, count):
    """The positions of each law's samples in a batch, in order (``member[k]`` the law of sample k), for laws 0 to
    ``count`` - 1."""
    order = np.argsort(member, kind="stable")
    return np.split(order, np.searchsorted(member[order], np.arange(1, count)))


def valve_lift_of(h, ramp_height, rocker_ratio=1.0, follower=FLAT) -> float | np.ndarray:
    """Valve lift i_k i_f(h) (h - h0) for h > h0, else 0 [m], of the follower lifts ``h`` [m] (:meth:`LiftLaw.valve_lift`;
    ``ramp_height`` h0 [m] and ``rocker_ratio`` i_k scalars or one an angle)."""
    return rocker_ratio * follower.ratio(h) * np.clip(h - ramp_height, 0.0, None)


def member_values(values, member) -> float | np.ndarray:
    """Per-law ``values`` (a sequence, one a law) at each sample of a batch: ``values[member]``, or the one law's value
    where ``member`` is None (:func:`batch_derivatives`)."""
    return values[0] if member is None else np.asarray(values, dtype=float)[member]


def batch_derivatives(laws, theta, member) -> np.ndarray:
    """Lift and its first three derivatives of several laws, each at its own angles.

    Parameters
    ----------
    laws : sequence of LiftLaw
    theta : array_like
        Camshaft angles [rad from the nose], shape (n,).
    member : array_like of int
        The law of each angle, an index into ``laws``, shape (n,).

    Returns
    -------
    ndarray
        Shape (4, n): h, dh/dtheta, d2h/dtheta2, d3h/dtheta3 of ``laws[member[k]]`` at ``theta[k]`` [m, m/rad, m/rad^2,
        m/rad^3], the numbers of each law's :meth:`LiftLaw.derivatives`.

    Notes
    -----
    Laws of one class with equal :meth:`LiftLaw.batch_key` are sampled together, their coefficients gathered per
    angle, one pass over the pieces for all of them; the others each on its own.
    """
    theta, member = np.asarray(theta, dtype=float), np.asarray(member)
    groups = {}
    for i, law in enumerate(laws):
        key = law.batch_key()
        groups.setdefault(i if key is None else (type(law), key), []).append(i)
    if len(groups) == 1:
        return type(laws[0])._batch_derivatives(laws, theta, member)
    out = np.empty((4, theta.size))
    position = np.empty(len(laws), dtype=int)
    for indices in groups.values():
        position[indices] = np.arange(len(indices))
        at = np.isin(member, indices)
        out[:, at] = type(laws[indices[0]])._batch_derivatives([laws[i] for i in indices], theta[at],
                                                               position[member[at]])
    return out


@njit(cache=True)
def mirror(theta, half) -> tuple[float, float]:
    """The rise coordinate of a symmetric law at one angle (compiled kernels; see :class:`SymmetricLaw`).

    Returns
    -------
    (float, float)
        ``phi = half - |theta|`` [rad] (negative on the base circle) and the factor of the odd
        derivatives: 1 on the opening flank (theta < 0), -1 on the closing flank, 0 at the nose.
    """
    flip = 1.0 if theta < 0.0 else (-1.0 if theta > 0.0 else 0.0)
    return half - abs(theta), flip


def segment_index(x, edges) -> int | np.ndarray:
    """Index of the piece of ``edges`` that holds each ``x`` (ends clipped to the first/last piece)."""
    return np.clip(np.searchsorted(edges, x, side="right") - 1, 0, len(edges) - 2)
