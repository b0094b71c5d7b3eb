"""The force line a valve spring must exceed (Valve-train practical works (n.d.), work 5): the required force
K_z m_v |j_v| against the valve lift, the gas force and the seat load that bound the preload, and the straight
characteristics above the requirement, in closed form.

SI units: N, m, Pa, kg.  The characteristic is written against the valve lift y: P(y) = P_min + C y (eq. 5.6).
"""

from dataclasses import dataclass, replace

import numpy as np

SPRING_RESERVE_RANGE = (1.5, 2.25)
"""Spring reserve factor K_z (Valve-train practical works (n.d.), eq. 5.3)."""

DEFLECTION_RATIO_RANGE = (1.6, 3.2)
"""f_max / f_min (Valve-train practical works (n.d.), work 5; 2 is the optimum)."""

DEFLECTION_RATIO_STEP = 0.1
"""Step of the deflection ratios of the straight lines the search tries."""

INNER_SHARE_RANGE = (0.35, 0.45)
"""Share of the force taken by the inner spring of a nested pair (Valve-train practical works (n.d.), work 5)."""

SEAT_ACCELERATION = 100.0 * 9.80665
"""Default seat load per unit reduced mass [m/s^2]: the closed valve is held on its seat with at least
m_v x 100 g.  A stated default of this package, not from the sources (they ask only P_min > P_gas,
eqs. 5.4-5.5): without it a slow engine gets a spring of a few newtons.  A valve that leaves its seat at
0.5 m/s is returned by it within v^2 / (2 a) = 0.13 mm, less than the usual clearance at the valve."""

RATIO_ROUNDOFF = 1e-12
"""Relative difference within which two deflection ratios are one (:meth:`Requirement.lines`): far above the round-off
of a ratio recomputed from a line's preload and rate (a few units in the last place), far below the step."""


def deflection_ratios(ratio_range=DEFLECTION_RATIO_RANGE, step=DEFLECTION_RATIO_STEP) -> np.ndarray:
    """The deflection ratios f_max / f_min the search tries: ``ratio_range`` every ``step`` and its upper end.

    >>> [round(float(r), 2) for r in deflection_ratios((1.6, 2.0), 0.15)]
    [1.6, 1.75, 1.9, 2.0]
    """
    low, high = ratio_range
    return np.unique(np.append(low + step * np.arange(int(np.floor((high - low) / step + 1e-9)) + 1), high))


def seat_load(mass_at_valve, acceleration=SEAT_ACCELERATION) -> float:
    """Smallest preload that holds the closed valve on its seat, m_v a [N] (a stated default, see
    :data:`SEAT_ACCELERATION`).

    >>> round(seat_load(0.15), 2)
    147.1
    """
    return mass_at_valve * acceleration


def required_spring_force(mass_at_valve, valve_acceleration, reserve) -> np.ndarray:
    """Spring force that keeps the train on the cam, K_z m_v |j_v| where j_v < 0, else 0 [N].

    Parameters
    ----------
    mass_at_valve : float
        Reduced mass at the valve m_v [kg].
    valve_acceleration : ndarray
        Valve acceleration j_v = i_k j_T [m/s^2]; for a finger follower the equivalent acceleration P_j / m_v of its
        train's inertia force by the variable ratio (:func:`valvetrain.layouts.finger_inertia`).
    reserve : float
        Spring reserve factor K_z.

    Notes
    -----
    :math:`P_j = m_v j_v` (5.1), :math:`P_{spr} = K_z P_j` (5.3) over the negative-acceleration part.  A linkage of
    variable ratio (a finger of inertia J about its pivot, effective arm G(psi) = dv/dpsi) has a reduced mass
    m(v) = m_0 + J / G^2 that changes with the lift, and Lagrange's equation gives
    :math:`P_j = m(v)\\ddot v + \\tfrac12\\,m'(v)\\,\\dot v^2` (Norton (2009); Wang (2007)).

    References
    ----------
    Valve-train practical works (n.d.), work 5, eqs. (5.1), (5.3); Norton (2009), the chapter on the dynamics of
    follower trains; Wang (2007), the chapter on valvetrain dynamics.
    """
    return reserve * mass_at_valve * np.clip(-np.asarray(valve_acceleration, dtype=float), 0.0, None)


def enveloping_line(lift, required, ratio_range=DEFLECTION_RATIO_RANGE, min_preload=0.0) -> tuple[float, float]:
    """The tightest straight spring characteristic above a required spring-force curve.

    Parameters
    ----------
    lift : ndarray
        Valve lift y [m] at the points of the curve.
    required : ndarray
        Required spring force at those lifts [N].
    ratio_range : (float, float)
        Allowed f_max / f_min = P_max / P_min (Valve-train practical works (n.d.), work 5: usually 1.6...3.2).
    min_preload : float
        Smallest preload [N]: the gas force that tends to open the closed valve
        (eqs. 5.4-5.5); the manual raises P_min to meet it.

    Returns
    -------
    (float, float)
        Preload P_min [N] and rate C [N/m] of the line P(y) = P_min + C y.

    Notes
    -----
    The manual replaces the curve a'b'c' of required force against valve lift by a
    straight line a''c'' drawn by hand (Valve-train practical works (n.d.), work 5, Fig. 5.1).  Here the line is
    the one with the smallest maximum force P_max = P_min + C h (the spring's largest
    stress) among the lines that

    * stay on or above the requirement at every point, :math:`P_{min} + C y_i \\ge P_i`;
    * keep the deflection ratio in the usual range, :math:`r_1 P_{min} \\le P_{min} + C h \\le r_2 P_{min}`;
    * hold the valve closed against the gas force, :math:`P_{min} \\ge P_g`.

    This is a linear programme in (P_min, C), solved here in closed form.  Written with
    the ratio r = P_max / P_min and u_i = y_i / h, a line of ratio r above the requirement
    has :math:`P_{max} \\ge \\max_i r P_i / (1 + (r - 1) u_i)` (and :math:`\\ge r P_g`);
    every term grows with r, so the smallest P_max is
    :math:`P^* = \\max(\\max_i r_1 P_i / (1 + (r_1 - 1) u_i), r_1 P_g)`, reached by every
    ratio up to :math:`r^* = \\min(r_2, \\min_{P_i > P^* u_i} P^* (1 - u_i) / (P_i - P^* u_i),
    P^* / P_g)`.  Of these optimal lines the steepest, r*, is taken: where the ratio bound
    is slack it is the steepest line through the full-lift point c' that stays above the
    curve (this package's reading of the graphical construction of
    Valve-train practical works (n.d.), work 5, Fig. 5.1); a polydyne cam, whose requirement is flat at the nose, gets the line of the
    smallest allowed ratio.  The line touches the requirement at least once, or sits on
    the gas force.

    References
    ----------
    Valve-train practical works (n.d.), work 5, eqs. (5.3)-(5.9) and Fig. 5.1.

    Examples
    --------
    A requirement proportional to lift, 10 N/mm up to 2 mm: the ratio bound 3.2 binds,
    P_min = 20/3.2 N and the line touches at full lift.

    >>> p0, c = enveloping_line(np.array([0.0, 1.0, 2.0]), np.array([0.0, 10.0, 20.0]))
    >>> round(p0, 6), round(c, 6)
    (6.25, 6.875)
    """
    y = np.asarray(lift, dtype=float)
    p = np.asarray(required, dtype=float)
    h = float(y.max())
    u = y / h
    r1, r2 = ratio_range
    gas = max(min_preload, 0.0)
    own = r1 * p / (1.0 + (r1 - 1.0) * u)      # each point's P_max at the ratio r1
    p_max = max(float(np.max(own)), r1 * gas)
    if p_max <= 0.0:
        return 0.0, 0.0
    excess = p - p_max * u
    # each point's bound P*(1 - u_i) / (P_i - P* u_i), written r1 + (1 + (r1 - 1) u_i)(P* - P*_i) / (P_i - P* u_i):
    # the point that sets P* bounds the ratio at r1 exactly, not at r1 plus the round-off of the difference
    up = excess > 0.0
    bounds = [r2, *(r1 + (1.0 + (r1 - 1.0) * u[up]) * (p_max - own[up]) / excess[up])]
    ratio = min(bounds + ([r1 + (p_max - r1 * gas) / gas] if gas > 0.0 else []))
    preload = p_max / ratio
    return float(preload), float((ratio - 1.0) * preload / h)


def gas_opening_force(throat_diameter, port_pressure, cylinder_pressure) -> float:
    """Gas force that tends to open a closed valve, f_g (p_port - p_cyl), zero if negative [N].

    Parameters
    ----------
    throat_diameter : float
        Throat diameter of the valve [m].
    port_pressure : float
        Absolute pressure behind the valve head in the port [Pa]: exhaust manifold p_tr
        for an exhaust valve (5.4), boost p_k for an inlet valve (5.5).
    cylinder_pressure : float
        Absolute cylinder pressure at the same time [Pa]: p_a during intake (5.4), p_r
        during the exhaust stroke (5.5, corrections note 19).

    References
    ----------
    Valve-train practical works (n.d.), work 5, eqs. (5.4), (5.5).

    Examples
    --------
    An exhaust valve of 31 mm throat, p_tr = 0.106 MPa, p_a = 0.085 MPa: 15.85 N.

    >>> round(gas_opening_force(0.031, 0.106e6, 0.085e6), 2)
    15.85
    """
    return float(max(np.pi * throat_diameter**2 / 4.0 * (port_pressure - cylinder_pressure), 0.0))


@dataclass(frozen=True)
class Characteristic:
    """A straight spring characteristic at the valve, P(y) = preload + rate y (Valve-train practical works (n.d.), eqs. 5.6-5.9)."""

    preload: float     # P_min [N]
    rate: float        # C [N/m]
    lift: float        # valve lift h [m]

    @property
    def max_force(self) -> float:
        """P_max = P_min + C h [N] (5.7)."""
        return self.preload + self.rate * self.lift

    @property
    def preload_deflection(self) -> float:
        """f_min = P_min / C [m] (5.8)."""
        return self.preload / self.rate

    @property
    def max_deflection(self) -> float:
        """f_max = P_max / C = f_min + h [m] (5.9)."""
        return self.max_force / self.rate

    def force(self, y) -> float | np.ndarray:
        """Spring force at valve lift y [N]."""
        return self.preload + self.rate * np.asarray(y)

    def split(self, share) -> tuple["Characteristic", "Characteristic"]:
        """(outer, inner) characteristics of a nested pair, the inner taking ``share`` of the force (5.10)-(5.14)."""
        inner = Characteristic(share * self.preload, share * self.rate, self.lift)
        outer = Characteristic(self.preload - inner.preload, self.rate - inner.rate, self.lift)
        return outer, inner

def enveloping_lines(lift, required, ratios, min_preload=0.0) -> tuple[np.ndarray, np.ndarray]:
    """For each deflection ratio r = f_max / f_min the lowest straight line of that ratio above a requirement.

    Parameters
    ----------
    lift, required : ndarray
        Valve lift y [m] and required spring force [N] at the points of the curve.
    ratios : ndarray
        Deflection ratios r.
    min_preload : float
        Smallest preload [N] (gas force, eqs. 5.4-5.5, or seat load).

    Returns
    -------
    (ndarray, ndarray)
        Preloads P_min [N] and rates C [N/m] of the lines, one per ratio.

    Notes
    -----
    A line of ratio r is :math:`P(y) = P_{min}(1 + (r - 1) y / h)`; it stays on or above the
    requirement when :math:`P_{min} = \\max(\\max_i P_i / (1 + (r - 1) y_i / h), P_g)`, and
    :math:`C = (r - 1) P_{min} / h`.  The line of :func:`enveloping_line` (smallest P_max)
    is the one of its own ratio; a steeper line has a shorter f_max = h r / (r - 1) and so a
    higher surge frequency at a given stress (see :func:`resonance_stress`).

    References
    ----------
    Valve-train practical works (n.d.), work 5, eqs. (5.6)-(5.9), Fig. 5.1.

    Examples
    --------
    The requirement 10 N/mm up to 2 mm with r = 3.2: P_min = 20/3.2 N, as in :func:`enveloping_line`.

    >>> p0, c = enveloping_lines(np.array([0.0, 1.0, 2.0]), np.array([0.0, 10.0, 20.0]), np.array([3.2]))
    >>> round(float(p0[0]), 6), round(float(c[0]), 6)
    (6.25, 6.875)
    """
    y = np.asarray(lift, dtype=float)
    p = np.asarray(required, dtype=float)
    r = np.asarray(ratios, dtype=float)
    h = float(y.max())
    loaded = p > 0.0     # the points of no required force bound no line
    # in place: ratios x points is large enough that a new array per operation has its pages faulted in afresh
    share = (r[:, None] - 1.0) * y[None, loaded]
    share /= h
    share += 1.0
    np.divide(p[None, loaded], share, out=share)    # each point's P_min of each ratio
    preload = np.maximum(np.max(share, axis=1, initial=0.0), max(min_preload, 0.0))
    return preload, (r - 1.0) * preload / h


@dataclass(frozen=True)
class Requirement:
    """The spring force a valve needs (SI): the required force against lift and the smallest preload."""

    lift: np.ndarray            # valve lift y at the points [m]
    force: np.ndarray           # K_z m_v |j_v| (5.3) [N]
    min_preload: float = 0.0    # gas force (5.4)-(5.5) or seat load [N]

    @property
    def max_lift(self) -> float:
        return float(np.max(self.lift))

    def line(self, ratio_range=DEFLECTION_RATIO_RANGE) -> Characteristic:
        """The required line of the manual's construction (:func:`enveloping_line`)."""
        return Characteristic(*enveloping_line(self.lift, self.force, ratio_range, self.min_preload), self.max_lift)

    def lines(self, ratio_range=DEFLECTION_RATIO_RANGE, step=DEFLECTION_RATIO_STEP, line=None) -> tuple[np.ndarray, np.ndarray]:
        """(preloads, rates) of the lines of the deflection ratios ``ratio_range`` every ``step``, its upper end
        and the ratio of the required line ``line`` (:meth:`line` when not given)."""
        required = self.line(ratio_range) if line is None else line
        ratios = deflection_ratios(ratio_range, step)
        own = np.clip(required.max_force / required.preload, *ratio_range)
        # the required line's ratio, recomputed from its preload and rate, carries their round-off: within a few
        # units in the last place of a ratio of the grid it is that ratio, and its line that ratio's line
        if not np.any(np.abs(ratios - own) <= RATIO_ROUNDOFF * ratios):
            ratios = np.unique(np.append(ratios, own))
        return enveloping_lines(self.lift, self.force, ratios, self.min_preload)

    def scaled(self, factor) -> "Requirement":
        """The requirement with every required force times ``factor`` (the preload minimum kept)."""
        return replace(self, force=self.force * factor)
