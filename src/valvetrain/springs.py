"""Valve spring characteristic and spring design (Valve-train practical works (n.d.), works 5 and 6).

SI units inside: N, m, Pa, kg, rad/s.  The characteristic is written against the valve
lift y: P(y) = P_min + C y (eq. 5.6).

The design searches a grid of springs at once (numpy arrays over the candidates): the
straight lines above the required force with the deflection ratios of the manual, the
wire grades of :mod:`valvetrain.spring_materials`, the mean diameters D = (0.7...0.9) d_g
and the wire diameters 2.0...7.0 mm; bounds that need no spring designed screen out the
candidates that cannot pass first (:func:`_may_pass`).  The lightest spring that passes
every check is chosen; when none passes, :func:`diagnose` names the requirements in conflict and
computes what would make a spring pass.

Conical (beehive) and progressive-rate springs are not designed: the sources give no
formulas for them.
"""

from dataclasses import dataclass, field, replace
from functools import cached_property

import numpy as np

from .checks import _TOL, check
from .masses import spring_mass
from .spring_materials import GRADES, grade
from .units import to_display

SPRING_RESERVE_RANGE = (1.5, 2.25)
"""Spring reserve factor K_z (Valve-train practical works (n.d.), eq. 5.3)."""

DEFLECTION_RATIO_RANGE = (1.6, 3.2)
"""f_max / f_min (Valve-train practical works (n.d.), work 5; 2 is the optimum)."""

DEFLECTION_RATIO_STEP = 0.1
"""Step of the deflection ratios of the straight lines the search tries."""

INNER_SHARE_RANGE = (0.35, 0.45)
"""Share of the force taken by the inner spring of a nested pair (Valve-train practical works (n.d.), work 5)."""

WIRE_RANGE_MM = (2.0, 7.0)
WIRE_STEP_MM = 0.1
"""Wire diameters searched [mm]: every 0.1 mm from 2.0 to 7.0 mm.  Wider than the manual's series
2.8, 3.0, 3.5, 3.8, 4.0, 4.2, 4.5, 4.8, 5.0, 5.5, 6.0 mm (Valve-train practical works (n.d.), work 6); valve-spring wire is drawn to
any size in this range (EN 10270-2 makes the VD grades from 0.5 to 10 mm)."""

SHAPE_FACTOR_TABLE = (np.array([3, 4, 5, 6, 7, 8, 9, 10, 11, 12], dtype=float),
                      np.array([1.5, 1.38, 1.3, 1.23, 1.2, 1.17, 1.15, 1.13, 1.11, 1.1]))
"""Spring index D/d and shape factor chi (Valve-train practical works (n.d.), work 6, table of eq. 6.1)."""

MEAN_DIAMETER_RANGE = (0.7, 0.9)
"""Spring mean diameter / valve throat diameter (Valve-train practical works (n.d.), work 6)."""

MEAN_DIAMETER_STEP = 0.1e-3
"""Step of the mean diameters tried [m]."""

INNER_DIAMETER_RATIO_LOW = 0.3
"""Smallest mean diameter of the inner spring of a pair / throat diameter (it must fit inside the outer one)."""

RESONANCE_RATIO_MIN = 10.0
"""omega_c1 / omega_cam (Valve-train practical works (n.d.), eq. 6.14)."""

INSTALLED_TO_LIFT_MAX = 6.0
"""Default upper limit of the installed length l_0 / valve lift h where no ``installed_length_mm`` is
given.  A stated default of this package, not from the sources, which set no length: it keeps the search
to springs that fit a cylinder head and leaves out, for example, the 120 mm long outer spring (l_0 = 10 h)
that the search without a limit proposed for the nested pair of the polydyne example; the springs
chosen for the shipped examples stand at 4.3-4.8 h."""

SEAT_ACCELERATION = 100.0 * 9.80665
"""Default seat load per unit reduced mass [m/s^2]: the closed valve is held on its seat with at least
m_v x 100 g.  A stated default of this package, not from the sources (they ask only P_min > P_gas,
eqs. 5.4-5.5): without it a slow engine gets a spring of a few newtons.  A valve that leaves its seat at
0.5 m/s is returned by it within v^2 / (2 a) = 0.13 mm, less than the usual clearance at the valve."""


class NoSpringFits(ValueError):
    """No spring of the wire range can be wound within the given diameters."""


def wire_series(wire_range_mm=WIRE_RANGE_MM, step_mm=WIRE_STEP_MM):
    """Wire diameters [m] from ``wire_range_mm[0]`` to ``wire_range_mm[1]`` every ``step_mm``.

    >>> [round(float(d) * 1e3, 1) for d in wire_series((2.8, 3.2))]
    [2.8, 2.9, 3.0, 3.1, 3.2]
    """
    low, high = wire_range_mm
    count = int(np.floor((high - low) / step_mm + 1e-9))
    return np.round(low + step_mm * np.arange(count + 1), 9) * 1e-3


def feasible_mean_diameters(wire_range_mm=WIRE_RANGE_MM):
    """Mean diameters D [m] some wire of the range can make: D/d within the shape-factor table (3...12)."""
    index = SHAPE_FACTOR_TABLE[0]
    return index[0] * min(wire_range_mm) * 1e-3, index[-1] * max(wire_range_mm) * 1e-3


def deflection_ratios(ratio_range=DEFLECTION_RATIO_RANGE, step=DEFLECTION_RATIO_STEP):
    """The deflection ratios f_max / f_min the search tries: ``ratio_range`` every ``step`` and its upper end.

    >>> [round(float(r), 2) for r in deflection_ratios((1.6, 2.0), 0.15)]
    [1.6, 1.75, 1.9, 2.0]
    """
    low, high = ratio_range
    return np.unique(np.append(low + step * np.arange(int(np.floor((high - low) / step + 1e-9)) + 1), high))


def seat_load(mass_at_valve, acceleration=SEAT_ACCELERATION):
    """Smallest preload that holds the closed valve on its seat, m_v a [N] (a stated default, see
    :data:`SEAT_ACCELERATION`).

    >>> round(seat_load(0.15), 2)
    147.1
    """
    return mass_at_valve * acceleration


def required_spring_force(mass_at_valve, valve_acceleration, reserve):
    """Spring force that keeps the train on the cam, K_z m_v |j_v| where j_v < 0, else 0 [N].

    Parameters
    ----------
    mass_at_valve : float
        Reduced mass at the valve m_v [kg].
    valve_acceleration : ndarray
        Valve acceleration j_v = i_k j_T [m/s^2].
    reserve : float
        Spring reserve factor K_z.

    Notes
    -----
    :math:`P_j = m_v j_v` (5.1), :math:`P_{spr} = K_z P_j` (5.3) over the negative-acceleration part.

    References
    ----------
    Valve-train practical works (n.d.), work 5, eqs. (5.1), (5.3).
    """
    return reserve * mass_at_valve * np.clip(-np.asarray(valve_acceleration, dtype=float), 0.0, None)


def enveloping_line(lift, required, ratio_range=DEFLECTION_RATIO_RANGE, min_preload=0.0):
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
    p_max = max(float(np.max(r1 * p / (1.0 + (r1 - 1.0) * u))), r1 * gas)
    if p_max <= 0.0:
        return 0.0, 0.0
    excess = p - p_max * u
    bounds = [r2, *(p_max * (1.0 - u[excess > 0.0]) / excess[excess > 0.0])] + ([p_max / gas] if gas > 0.0 else [])
    ratio = max(min(bounds), r1)
    preload = p_max / ratio
    return float(preload), float((ratio - 1.0) * preload / h)


def gas_opening_force(throat_diameter, port_pressure, cylinder_pressure):
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
    def max_force(self):
        """P_max = P_min + C h [N] (5.7)."""
        return self.preload + self.rate * self.lift

    @property
    def preload_deflection(self):
        """f_min = P_min / C [m] (5.8)."""
        return self.preload / self.rate

    @property
    def max_deflection(self):
        """f_max = P_max / C = f_min + h [m] (5.9)."""
        return self.max_force / self.rate

    def force(self, y):
        """Spring force at valve lift y [N]."""
        return self.preload + self.rate * np.asarray(y)

    def split(self, share):
        """(outer, inner) characteristics of a nested pair, the inner taking ``share`` of the force (5.10)-(5.14)."""
        inner = Characteristic(share * self.preload, share * self.rate, self.lift)
        outer = Characteristic(self.preload - inner.preload, self.rate - inner.rate, self.lift)
        return outer, inner


def shape_factor_table(index):
    """Shape factor chi from the manual's table, linear interpolation in D/d (Valve-train practical works (n.d.), work 6, eq. 6.1).

    >>> round(float(shape_factor_table(5.5)), 6)
    1.265
    """
    return np.interp(index, *SHAPE_FACTOR_TABLE, left=np.nan, right=np.nan)


def wahl_factor(index):
    """Wahl's curvature and direct-shear factor, (4c - 1)/(4c - 4) + 0.615/c.

    Engineering literature (Wahl (1944)); printed beside the
    manual's table, which lies below it by 5 % at D/d = 3 and by under 2 % from 4 to 12.

    >>> round(float(wahl_factor(6.0)), 4)
    1.2525
    """
    c = np.asarray(index, dtype=float)
    return (4.0 * c - 1.0) / (4.0 * c - 4.0) + 0.615 / c


def shear_stress(force, mean_diameter, wire_diameter, factor):
    """Maximum shear stress in the wire, tau = 8 chi P D / (pi d^3) [Pa] (Valve-train practical works (n.d.), eq. 6.1)."""
    return 8.0 * factor * force * mean_diameter / (np.pi * wire_diameter**3)


def active_coils(shear_modulus, wire_diameter, max_deflection, max_force, mean_diameter):
    """Working coils i_p = G d^4 f_max / (8 P_max D^3) (Valve-train practical works (n.d.), eq. 6.2).

    Examples
    --------
    V. B. Bhandari, Design of Machine Elements, Example 11.1 (G = 81370 MPa, d = 7 mm,
    deflection 30 mm at 1250 N, D = 42 mm): 7.91 coils.

    >>> round(active_coils(81370e6, 7e-3, 30e-3, 1250.0, 42e-3), 2)
    7.91
    """
    return shear_modulus * wire_diameter**4 * max_deflection / (8.0 * max_force * mean_diameter**3)


def spring_rate(shear_modulus, wire_diameter, mean_diameter, coils):
    """Rate of a helical spring, C = G d^4 / (8 D^3 i_p) [N/m] (inverse of eq. 6.2)."""
    return shear_modulus * wire_diameter**4 / (8.0 * mean_diameter**3 * coils)


def natural_frequency(wire_diameter, mean_diameter, coils, shear_modulus, density):
    """First natural (surge) frequency of a spring fixed at both ends, omega_c1 [rad/s].

    Notes
    -----
    .. math:: \\omega_{c1} = \\frac{d}{D^2 i_p}\\sqrt{\\frac{G}{2\\rho}}

    which is the manual's 10^6 d/(D^2 i_p) sqrt(G/(2 rho)) with d, D in mm and G in MPa.

    References
    ----------
    Valve-train practical works (n.d.), work 6, eq. (6.13), as read in corrections note 47
    (the alternative reading is 4.44 times smaller); agrees within 1.2 % with Kolchin and Demidov (1980),
    n_c = 2.17e7 d/(i_p D^2) min^-1.
    """
    return wire_diameter / (mean_diameter**2 * coils) * np.sqrt(shear_modulus / (2.0 * density))


def fatigue_safety(tau_max, tau_min, endurance, mean_stress_factor):
    """Fatigue safety factor n = tau_-1 / (tau_a + psi_tau tau_m) (Valve-train practical works (n.d.), eqs. 6.9-6.12).

    The manual defines no mean-stress coefficient psi_tau (corrections note 24); 0.1-0.2 is usual in the
    engineering literature, and the design takes it from the specification.
    """
    tau_m = 0.5 * (tau_max + tau_min)
    tau_a = 0.5 * (tau_max - tau_min)
    return endurance / (tau_a + mean_stress_factor * tau_m)


def spring_lengths(wire_diameter, coils, lift, preload_deflection, gap_factor, end_coils=2, installed_length=None):
    """Pitches and lengths of a valve spring (Valve-train practical works (n.d.), eqs. 6.3-6.8).

    Parameters
    ----------
    installed_length : float, optional
        Imposed installed length l_0 [m] (the inner spring of a nested pair sits between
        the same seat and retainer as the outer one); l_min = l_0 - h then, and t_min
        follows from (6.4).

    Returns
    -------
    dict
        ``min_pitch`` t_min = d + Delta_min (6.3); ``min_length`` (valve fully open)
        l_min = t_min (i_p + 2) + d (i_0 - 1) (6.4, as read in corrections note 46); ``installed_length``
        l_0 = l_min + h (6.5); ``installed_pitch`` t_0 (6.6); ``free_length``
        l_free = l_0 + f_min (6.7); ``free_pitch`` t_free (6.8) [m].
    """
    d = wire_diameter
    if installed_length is None:
        t_min = d * (1.0 + gap_factor)
        l_min = t_min * (coils + 2.0) + d * (end_coils - 1.0)
    else:
        l_min = installed_length - lift
        t_min = (l_min - d * (end_coils - 1.0)) / (coils + 2.0)
    l_0 = l_min + lift
    l_free = l_0 + preload_deflection
    return {"min_pitch": t_min, "min_length": l_min, "installed_length": l_0,
            "installed_pitch": (l_0 - d * (end_coils - 1.0)) / (coils + 2.0), "free_length": l_free,
            "free_pitch": (l_free - d * (end_coils - 1.0)) / (coils + 2.0)}


@dataclass(frozen=True)
class SpringMaterial:
    """A wire grade and the design limits of a valve spring (SI).

    ``grade`` names a grade of :data:`valvetrain.spring_materials.GRADES`; a property given
    here (not None) replaces the grade's value for every wire diameter.  After construction
    ``shear_modulus`` and ``density`` hold the values in use.
    """

    grade: str = "60S2A"
    shear_modulus: float = None          # G [Pa]
    density: float = None                # rho [kg/m^3]
    allowable_stress: float = None       # [tau] [Pa]
    endurance_limit: float = None        # tau_-1 [Pa]
    mean_stress_factor: float = None     # psi_tau of eq. (6.12)
    min_safety: float = 1.3              # n >= 1.2-1.4
    min_resonance_ratio: float = RESONANCE_RATIO_MIN
    gap_factor: float = 0.12             # Delta_min / d, 0.10-0.15
    end_coils: float = 2.0               # i_0

    def __post_init__(self):
        found = grade(self.grade)
        object.__setattr__(self, "grade", found.name)
        if self.shear_modulus is None:
            object.__setattr__(self, "shear_modulus", found.shear_modulus)
        if self.density is None:
            object.__setattr__(self, "density", found.density)

    def limits(self, wire_diameter):
        """([tau], tau_-1, psi_tau) for wires of diameter d [m], arrays of d's shape."""
        found = GRADES[self.grade]
        d = np.asarray(wire_diameter, dtype=float)
        allowable = found.allowable_stress(d) if self.allowable_stress is None else np.full(d.shape,
                                                                                            self.allowable_stress)
        endurance = found.endurance_limit(d) if self.endurance_limit is None else np.full(d.shape,
                                                                                          self.endurance_limit)
        psi = found.mean_stress(d) if self.mean_stress_factor is None else np.full(d.shape, self.mean_stress_factor)
        return allowable, endurance, psi

    @property
    def source(self):
        """Where the grade's figures come from."""
        return GRADES[self.grade].source


@dataclass
class SpringDesign:
    """One helical spring: geometry, loads and every check (SI)."""

    mean_diameter: float
    wire_diameter: float
    coils: float
    characteristic: Characteristic       # the actual line with the rounded coils
    shape_factor: float                  # chi from the table
    wahl: float                          # Wahl factor, for comparison
    tau_max: float
    tau_min: float
    safety: float
    natural_frequency: float             # omega_c1 [rad/s]
    resonance_ratio: float
    lengths: dict
    mass: float
    checks: dict = field(default_factory=dict)   # name -> valvetrain.checks.Check
    material: str = "60S2A"
    target_ratio: float = None           # f_max / f_min of the line the spring was designed for

    @property
    def margins(self):
        """Relative margin of each check: >= 0 passes (value/limit - 1 for a minimum, 1 - value/limit for a
        maximum; +inf for a check switched off by a zero minimum)."""
        return {k: c.margin for k, c in self.checks.items()}

    @property
    def passes(self):
        return all(c.passed for c in self.checks.values())

    @property
    def binding_check(self):
        """The check with the smallest margin."""
        return min(self.margins, key=self.margins.get)


@dataclass(frozen=True)
class _ArrayCheck:
    """A check of many candidates at once: the arguments of :func:`valvetrain.checks.check` with array
    values and bounds; ``passed`` and ``margin`` follow :class:`valvetrain.checks.Check` element by element."""

    code: str
    value: np.ndarray
    low: object = None
    high: object = None
    unit: str = ""
    source: str = ""
    severity: str = "warning"

    @property
    def passed(self):
        v = self.value
        ok = np.isfinite(v)
        if self.low is not None:
            ok &= ~(v < self.low - _TOL * np.maximum(1.0, np.abs(self.low)))
        if self.high is not None:
            ok &= ~(v > self.high + _TOL * np.maximum(1.0, np.abs(self.high)))
        return ok

    @property
    def margin(self):
        v = self.value
        sides = []
        if self.low is not None:
            sides.append((v - self.low) / np.where(self.low == 0.0, 1.0, np.abs(self.low)))
        if self.high is not None:
            sides.append((self.high - v) / np.where(self.high == 0.0, 1.0, np.abs(self.high)))
        margin = np.minimum.reduce(sides) if sides else np.full(v.shape, np.inf)
        return np.where(np.isfinite(v), margin, -np.inf)

    def at(self, i):
        """The :class:`valvetrain.checks.Check` of candidate ``i``."""
        def pick(x):
            return None if x is None else float(np.broadcast_to(x, self.value.shape)[i])

        return check(self.code, float(self.value[i]), pick(self.low), pick(self.high), unit=self.unit,
                     source=self.source, severity=self.severity)


def _minimum(limit):
    """A lower bound of a check, or None where a zero minimum switches the check off."""
    return limit if limit > 0.0 else None


@dataclass
class Candidates:
    """Springs of one wire grade evaluated at once: flat arrays of one length (SI) and their checks."""

    material: SpringMaterial
    mean_diameter: np.ndarray
    wire_diameter: np.ndarray
    coils: np.ndarray
    preload: np.ndarray
    rate: np.ndarray                     # actual rate with the rounded coils
    lift: float
    target_ratio: np.ndarray
    shape_factor: np.ndarray
    tau_max: np.ndarray
    tau_min: np.ndarray
    safety: np.ndarray
    natural_frequency: np.ndarray
    resonance_ratio: np.ndarray
    lengths: dict
    mass: np.ndarray
    checks: dict                         # name -> _ArrayCheck
    line: np.ndarray = None              # index of the line of each candidate (set by the search)

    def __len__(self):
        return len(self.mass)

    @cached_property
    def passed(self):
        """Candidates passing every check."""
        ok = np.ones(len(self), dtype=bool)
        for c in self.checks.values():
            ok &= c.passed
        return ok

    @cached_property
    def worst_margin(self):
        """The smallest margin of each candidate."""
        return np.minimum.reduce([c.margin for c in self.checks.values()])

    def design(self, i):
        """Candidate ``i`` as a :class:`SpringDesign` with its :class:`valvetrain.checks.Check` records."""
        index = self.mean_diameter[i] / self.wire_diameter[i]
        line = Characteristic(float(self.preload[i]), float(self.rate[i]), self.lift)
        return SpringDesign(float(self.mean_diameter[i]), float(self.wire_diameter[i]), float(self.coils[i]), line,
                            float(self.shape_factor[i]), float(wahl_factor(index)), float(self.tau_max[i]),
                            float(self.tau_min[i]), float(self.safety[i]), float(self.natural_frequency[i]),
                            float(self.resonance_ratio[i]), {k: float(v[i]) for k, v in self.lengths.items()},
                            float(self.mass[i]), {k: c.at(i) for k, c in self.checks.items()}, self.material.grade,
                            float(self.target_ratio[i]))


def evaluate_springs(preload, rate, lift, mean_diameter, wire_diameter, material, camshaft_speed, *,
                     ratio_range=DEFLECTION_RATIO_RANGE, installed_length=None, min_installed_length=None,
                     max_installed_length=None, max_free_length=None, partner_frequency=None,
                     min_frequency_difference=0.0):
    """Design many springs at once, each for its own straight characteristic (Valve-train practical works (n.d.), work 6).

    Parameters
    ----------
    preload, rate : ndarray
        The line each spring is designed for, P(y) = P_min + C y [N, N/m].
    lift : float
        Valve lift h [m].
    mean_diameter, wire_diameter : ndarray
        D and d [m]; every argument array broadcasts to one shape.
    material : SpringMaterial
    camshaft_speed : float
        omega_cam [rad/s] for the resonance ratio (6.14).
    ratio_range : (float, float)
        Allowed f_max / f_min of the spring's actual line (Valve-train practical works (n.d.), work 5).
    installed_length : ndarray, optional
        Imposed installed length l_0 [m] (the inner spring of a pair: the outer one's); the
        coils must then keep their minimum gap at full lift.
    min_installed_length : float, optional
        A spring shorter than this is installed at this length (on a taller seat).
    max_installed_length, max_free_length : float, optional
        Upper limits of l_0 and of the free length [m], checked.
    partner_frequency : ndarray, optional
        omega_c1 of the outer spring, for the inner spring of a pair: the two must differ by
        ``min_frequency_difference`` (eq. 6.14).

    Returns
    -------
    Candidates
        Flat arrays.  The working coils from (6.2) are rounded **down** to a multiple of 0.5
        (at least 1): the spring gets slightly stiffer and, with the preload kept, the actual
        line stays above the one it was designed for.  A spring index D/d outside the manual's
        table (3...12) gives a NaN shape factor, and the candidate fails.
    """
    p0, c0 = np.asarray(preload, dtype=float), np.asarray(rate, dtype=float)
    big_d, d = np.asarray(mean_diameter, dtype=float), np.asarray(wire_diameter, dtype=float)
    g, rho = material.shear_modulus, material.density
    chi = shape_factor_table(big_d / d)
    allowable, endurance, psi = material.limits(d)
    p_max = p0 + c0 * lift
    exact = active_coils(g, d, p_max / c0, p_max, big_d)
    coils = np.maximum(np.floor(exact * 2.0) / 2.0, 1.0)
    actual = spring_rate(g, d, big_d, coils)
    tau_max = shear_stress(p0 + actual * lift, big_d, d, chi)
    tau_min = shear_stress(p0, big_d, d, chi)
    safety = fatigue_safety(tau_max, tau_min, endurance, psi)
    omega = natural_frequency(d, big_d, coils, g, rho)
    shape = np.broadcast_shapes(np.shape(p0), np.shape(c0), np.shape(big_d), np.shape(d))

    def flat(x):
        return np.broadcast_to(x, shape).ravel()

    p0, c0, big_d, d, chi, allowable, endurance, psi, exact, coils, actual, tau_max, tau_min, safety, omega = map(
        flat, (p0, c0, big_d, d, chi, allowable, endurance, psi, exact, coils, actual, tau_max, tau_min, safety, omega))
    lengths = spring_lengths(d, coils, lift, p0 / actual, material.gap_factor, material.end_coils)
    imposed = None if installed_length is None else flat(installed_length)
    if imposed is None and min_installed_length is not None:
        imposed = np.maximum(lengths["installed_length"], min_installed_length)
    if imposed is not None:
        lengths = spring_lengths(d, coils, lift, p0 / actual, material.gap_factor, material.end_coils, imposed)
    mass = spring_mass(big_d, d, coils + material.end_coils, rho)
    grade_note = f"{material.grade}: {material.source}"
    checks = {
        "tau_max": _ArrayCheck("spring.tau_max", tau_max, high=allowable, unit="MPa", severity="failure",
                               source=f"Valve-train practical works (n.d.), eq. (6.1) with [tau] of {grade_note}"),
        "fatigue_safety": _ArrayCheck("spring.fatigue_safety", safety, low=_minimum(material.min_safety),
                                      severity="failure", source=f"Valve-train practical works (n.d.), eq. (6.12): n >= 1.2-1.4; tau_-1 "
                                                                 f"and psi_tau of {grade_note}"),
        "resonance_ratio": _ArrayCheck("spring.resonance_ratio", omega / camshaft_speed,
                                       low=_minimum(material.min_resonance_ratio),
                                       source="Valve-train practical works (n.d.), eq. (6.14): >= 10 (hard to meet at high speed, corrections note 27)"),
        "working_coils": _ArrayCheck("spring.working_coils", exact, low=2.0, source="Valve-train practical works (n.d.), eq. (6.2)"),
        "deflection_ratio": _ArrayCheck("spring.deflection_ratio", (p0 + actual * lift) / p0, *ratio_range,
                                        source="Valve-train practical works (n.d.), work 5 (with the rounded coils)"),
    }
    if max_installed_length is not None:
        checks["installed_length"] = _ArrayCheck("spring.installed_length", lengths["installed_length"],
                                                 high=max_installed_length, unit="mm",
                                                 source="installed_length_mm of the specification, or "
                                                        f"{INSTALLED_TO_LIFT_MAX:g} x lift (a stated default)")
    if max_free_length is not None:
        checks["free_length"] = _ArrayCheck("spring.free_length", lengths["free_length"], high=max_free_length, unit="mm",
                                            source="max_free_length_mm of the specification")
    if imposed is not None:
        checks["coil_gap_at_full_lift"] = _ArrayCheck("spring.coil_gap_at_full_lift",
                                                      lengths["min_pitch"] / d - 1.0, low=material.gap_factor,
                                                      source="Valve-train practical works (n.d.), eq. (6.3): Delta_min = 0.10-0.15 d")
    if partner_frequency is not None:
        difference = np.abs(omega - partner_frequency) / partner_frequency
        checks["frequency_difference"] = _ArrayCheck("spring.frequency_difference", difference,
                                                     low=_minimum(min_frequency_difference),
                                                     source="Valve-train practical works (n.d.), eq. (6.14): the two ratios must differ "
                                                            f"({min_frequency_difference:.0%} assumed)")
    target = (p0 + c0 * lift) / p0
    return Candidates(material, big_d, d, coils, p0, actual, lift, target, chi, tau_max, tau_min, safety,
                      omega, omega / camshaft_speed, lengths, mass, checks)


def evaluate_spring(required, mean_diameter, wire_diameter, material, camshaft_speed, **limits):
    """Design one spring of given diameters for a line (:func:`evaluate_springs` of one candidate).

    Returns
    -------
    SpringDesign or None
        None when the spring index D/d is outside the manual's table (3...12).
    """
    found = evaluate_springs(required.preload, required.rate, required.lift, mean_diameter, wire_diameter, material,
                             camshaft_speed, **limits)
    return found.design(0) if np.isfinite(found.shape_factor[0]) else None


def enveloping_lines(lift, required, ratios, min_preload=0.0):
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
    slope = (r[:, None] - 1.0) * y[None, loaded] / h
    preload = np.maximum(np.max(p[None, loaded] / (1.0 + slope), axis=1, initial=0.0), max(min_preload, 0.0))
    return preload, (r - 1.0) * preload / h


@dataclass(frozen=True)
class Requirement:
    """The spring force a valve needs (SI): the required force against lift and the smallest preload."""

    lift: np.ndarray            # valve lift y at the points [m]
    force: np.ndarray           # K_z m_v |j_v| (5.3) [N]
    min_preload: float = 0.0    # gas force (5.4)-(5.5) or seat load [N]

    @property
    def max_lift(self):
        return float(np.max(self.lift))

    def line(self, ratio_range=DEFLECTION_RATIO_RANGE):
        """The required line of the manual's construction (:func:`enveloping_line`)."""
        return Characteristic(*enveloping_line(self.lift, self.force, ratio_range, self.min_preload), self.max_lift)

    def lines(self, ratio_range=DEFLECTION_RATIO_RANGE, step=DEFLECTION_RATIO_STEP, line=None):
        """(preloads, rates) of the lines of the deflection ratios ``ratio_range`` every ``step``, its upper end
        and the ratio of the required line ``line`` (:meth:`line` when not given)."""
        required = self.line(ratio_range) if line is None else line
        ratios = np.append(deflection_ratios(ratio_range, step), required.max_force / required.preload)
        return enveloping_lines(self.lift, self.force, np.unique(np.clip(ratios, *ratio_range)), self.min_preload)

    def scaled(self, factor):
        """The requirement with every required force times ``factor`` (the preload minimum kept)."""
        return replace(self, force=self.force * factor)


@dataclass(frozen=True)
class SpringOptions:
    """What the spring search tries (SI): grades, diameters, wire, lengths, one spring or a nested pair."""

    materials: tuple = (SpringMaterial(),)
    count: int = 1
    inner_share: float = 0.4
    diameter_range: tuple = MEAN_DIAMETER_RANGE          # D / d_g
    diameter_step: float = MEAN_DIAMETER_STEP            # [m]
    wire_range_mm: tuple = WIRE_RANGE_MM
    wire_step_mm: float = WIRE_STEP_MM
    ratio_range: tuple = DEFLECTION_RATIO_RANGE
    installed_length_range: tuple = None                 # (low, high) [m], either None; None: (None, 6 h)
    max_free_length: float = None                        # [m]
    radial_gap: float = 1.0e-3                           # between the coils of a pair [m]
    min_frequency_difference: float = 0.1

    def installed_limits(self, lift):
        """(min_installed_length, max_installed_length) [m]."""
        if self.installed_length_range is None:
            return None, INSTALLED_TO_LIFT_MAX * lift
        return self.installed_length_range


def _grid(throat_diameter, diameter_range, diameter_step, wires, max_outer=None):
    """Flat arrays (D, d) of the mean diameters (multiples of the step in the range x d_g) and wires whose index
    lies in the shape-factor table and, for an inner spring, whose outside diameter D + d fits ``max_outer``."""
    lo, hi = diameter_range[0] * throat_diameter, diameter_range[1] * throat_diameter
    diameters = np.arange(np.ceil(lo / diameter_step - 1e-9), np.floor(hi / diameter_step + 1e-9) + 1) * diameter_step
    big_d, d = (a.ravel() for a in np.meshgrid(diameters, wires, indexing="ij"))
    index = big_d / d
    keep = (index >= SHAPE_FACTOR_TABLE[0][0]) & (index <= SHAPE_FACTOR_TABLE[0][-1])
    if max_outer is not None:
        keep &= big_d + d <= max_outer
    return big_d[keep], d[keep]


@dataclass
class Search:
    """Result of a spring search: the chosen springs, how many candidates passed and were tried."""

    designs: dict                # "spring", or "outer" and "inner" -> SpringDesign
    passing: int
    tried: int
    line: Characteristic         # the required line of the manual's construction

    @property
    def passes(self):
        return all(s.passes for s in self.designs.values())

    @property
    def mass(self):
        return sum(s.mass for s in self.designs.values())


SCREEN_SLACK = 1e-6
"""Relative slack of the screen of :func:`_may_pass`: far wider than the tolerance of a check (1e-9) and the
rounding of its arithmetic, so that the screen never drops a candidate that passes."""


def _may_pass(preloads, rates, lift, big_d, d, material, camshaft_speed, max_installed_length):
    """The (line, grid point) pairs that may pass every check: a boolean (lines, grid) array that holds every
    passing candidate of :func:`evaluate_springs` (the screen of :func:`_search`).

    Notes
    -----
    Bounds that need no spring to be designed, each of a line's scalar against a grid point's: with
    :math:`K = G d^4 / (8 D^3)` (the rate of one working coil) a line of rate C needs the exact coils
    :math:`i = K / C` (6.2), rounded down to :math:`i_p \\ge i - 1/2`.  A spring passes only if

    * ``working_coils``: :math:`K / C \\ge 2`;
    * ``tau_max``: :math:`8 \\chi P_{max} D / (\\pi d^3) \\le \\tau_{max} \\le [\\tau]`, P_max of the line: the
      coils rounded down (:math:`i_p \\le i` where i >= 2) make the spring stiffer, its full-lift force at least
      the line's (6.1);
    * ``fatigue_safety``: with :math:`\\tau_{min} = 8 \\chi P_{min} D / (\\pi d^3)` and that bound of
      :math:`\\tau_{max}`, :math:`n = 2 \\tau_{-1} / ((1 + \\psi_\\tau) \\tau_{max} - (1 - \\psi_\\tau) \\tau_{min})
      \\le 2 \\tau_{-1} \\pi d^3 / (8 \\chi D (C h + \\psi_\\tau (2 P_{min} + C h)))` must reach
      :math:`n_{min}` (6.9)-(6.12), where :math:`\\psi_\\tau \\ge 0`;
    * ``resonance_ratio``: :math:`\\omega_{c1} = d \\sqrt{G / 2\\rho} / (D^2 i_p) \\ge R \\omega_{cam}`, so
      :math:`i - 1/2 \\le i_p \\le d \\sqrt{G / 2\\rho} / (D^2 R \\omega_{cam})` (6.13)-(6.14);
    * ``installed_length`` (no imposed length): :math:`l_0 \\ge d (1 + \\Delta/d)(i_p + 2) + d (i_0 - 1) + h \\le
      l_{0,max}` (6.3)-(6.5), another upper bound of :math:`i_p`.

    Each bound is widened by :data:`SCREEN_SLACK`.
    """
    g, rho = material.shear_modulus, material.density
    p = np.asarray(preloads, dtype=float)
    c = np.asarray(rates, dtype=float)
    one_coil = g * d**4 / (8.0 * big_d**3)
    allowable, endurance, psi = material.limits(d)
    stress_per_force = 8.0 * shape_factor_table(big_d / d) * big_d / (np.pi * d**3)
    keep = (p + c * lift)[:, None] <= (allowable * (1.0 + SCREEN_SLACK) / stress_per_force)[None, :]
    if material.min_safety > 0.0:
        fatigue_cap = np.where(psi >= 0.0, 2.0 * endurance / (stress_per_force * material.min_safety
                                                               * (1.0 - SCREEN_SLACK)), np.inf)
        keep &= (c * lift)[:, None] + psi[None, :] * (2.0 * p + c * lift)[:, None] <= fatigue_cap[None, :]
    keep &= c[:, None] <= (one_coil / (2.0 * (1.0 - SCREEN_SLACK)))[None, :]
    coil_cap = np.full(d.shape, np.inf)
    if material.min_resonance_ratio > 0.0:
        coil_cap = natural_frequency(d, big_d, 1.0, g, rho) / (material.min_resonance_ratio * camshaft_speed)
    if max_installed_length is not None:
        fit = (max_installed_length * (1.0 + SCREEN_SLACK) - lift - d * (material.end_coils - 1.0)) / (
            d * (1.0 + material.gap_factor)) - 2.0
        coil_cap = np.minimum(coil_cap, fit)
    coil_cap = coil_cap + SCREEN_SLACK * (np.abs(coil_cap) + 1.0) + 0.5
    min_rate = np.where(coil_cap > 0.0, one_coil / np.where(coil_cap > 0.0, coil_cap, 1.0), np.inf)
    keep &= c[:, None] >= min_rate[None, :]
    return keep


def _search(preloads, rates, lift, throat_diameter, camshaft_speed, options, *, diameter_range=None, max_outer=None,
            installed_length=None, partner_frequency=None, free_lengths=False):
    """Every line x grade x D x d: a list of :class:`Candidates` (one per grade) and the number of candidates
    tried.  ``free_lengths``: no limit on the lengths (the inner springs of a pair, installed at the outer one's
    length).

    Only the candidates that may pass (:func:`_may_pass`) are designed, in the order of the grid (line by line);
    when none of them passes, every candidate is, so that the best worst margin is found among all.  The
    lightest passing spring, the passing count and the margins of every spring designed are those of the
    exhaustive search."""
    wires = wire_series(options.wire_range_mm, options.wire_step_mm)
    big_d, d = _grid(throat_diameter, diameter_range or options.diameter_range, options.diameter_step, wires,
                     max_outer)
    low, high = (None, None) if free_lengths else options.installed_limits(lift)
    preloads, rates = np.asarray(preloads, dtype=float), np.asarray(rates, dtype=float)
    lines = np.arange(len(preloads))

    def designed(material, line, grid):
        found = evaluate_springs(
            preloads[line], rates[line], lift, big_d[grid], d[grid], material, camshaft_speed,
            ratio_range=options.ratio_range, installed_length=installed_length,
            min_installed_length=low if installed_length is None else None, max_installed_length=high,
            max_free_length=None if free_lengths else options.max_free_length, partner_frequency=partner_frequency,
            min_frequency_difference=options.min_frequency_difference)
        found.line = line
        return found

    found = [designed(m, *divmod(np.flatnonzero(_may_pass(preloads, rates, lift, big_d, d, m, camshaft_speed,
                                                         high if installed_length is None else None)), len(d)))
             for m in options.materials]
    if not any(c.passed.any() for c in found):
        line, grid = (a.ravel() for a in np.meshgrid(lines, np.arange(len(d)), indexing="ij"))
        found = [designed(m, line, grid) for m in options.materials]
    return found, len(options.materials) * len(lines) * len(d)


def _best(found):
    """(candidates, index, passing count): the lightest passing candidate, else the best worst margin."""
    passing = sum(int(np.count_nonzero(c.passed)) for c in found)
    if passing:
        key = [np.where(c.passed, c.mass, np.inf) for c in found]
        k = int(np.argmin([np.min(m, initial=np.inf) for m in key]))
        return found[k], int(np.argmin(key[k])), passing
    key = [c.worst_margin for c in found]
    k = int(np.argmax([np.max(m) for m in key]))
    return found[k], int(np.argmax(key[k])), 0


def design_spring(required, throat_diameter, camshaft_speed, options=SpringOptions(), **limits):
    """The lightest spring that passes every check for the lines ``required``.

    Parameters
    ----------
    required : Characteristic or (ndarray, ndarray)
        One line, or the preloads and rates of several (:meth:`Requirement.lines`), whose
        valve lift is then ``limits["lift"]``.
    throat_diameter : float
        Valve throat diameter d_g [m]; mean diameters from ``options.diameter_range`` x d_g.
    camshaft_speed : float
        omega_cam [rad/s] for the resonance ratio (6.14).
    options : SpringOptions
    limits
        ``lift`` [m]; for the inner spring of a pair: ``diameter_range`` (D / d_g),
        ``max_outer`` (largest D + d [m]), and ``installed_length``, ``partner_frequency`` of
        :func:`evaluate_springs`.

    Returns
    -------
    (SpringDesign, int, int)
        The lightest spring passing every check or, when none does, the one whose worst
        margin is best; the number of candidates that passed and that were tried.

    Raises
    ------
    NoSpringFits
        When no wire of the range makes a spring of the mean diameters (index 3...12) that fits.

    References
    ----------
    Valve-train practical works (n.d.), work 6 (D = 0.7-0.9 d_g, checks (6.1), (6.12), (6.14)).
    """
    if isinstance(required, Characteristic):
        preloads, rates, lift = [required.preload], [required.rate], required.lift
    else:
        (preloads, rates), lift = required, limits.pop("lift")
    found, tried = _search(preloads, rates, lift, throat_diameter, camshaft_speed, options, **limits)
    if not tried:
        low, high = feasible_mean_diameters(options.wire_range_mm)
        ratio = limits.get("diameter_range") or options.diameter_range
        lo, hi = ratio[0] * throat_diameter, ratio[1] * throat_diameter
        max_outer = limits.get("max_outer")
        inside = f" inside the outer spring (outside diameter <= {max_outer * 1e3:.1f} mm)" if max_outer else ""
        raise NoSpringFits(f"no spring of the wire range {options.wire_range_mm[0]:g}...{options.wire_range_mm[1]:g} "
                           f"mm fits{inside} with D in {lo * 1e3:.1f}...{hi * 1e3:.1f} mm; the range makes D = "
                           f"{low * 1e3:g}...{high * 1e3:g} mm (index 3...12)")
    best, i, passing = _best(found)
    return best.design(i), passing, tried


PAIR_CANDIDATES = 300
"""Passing outer and inner springs per line, lightest first, joined into nested pairs."""


def _inner_design(outer, inner_found, i, camshaft_speed, options):
    """Inner candidate ``i`` designed at the outer spring's installed length, against its frequency."""
    c = inner_found
    preload = float(c.preload[i])
    line = Characteristic(preload, (float(c.target_ratio[i]) - 1.0) * preload / c.lift, c.lift)
    return evaluate_spring(line, c.mean_diameter[i], c.wire_diameter[i], c.material, camshaft_speed,
                           ratio_range=options.ratio_range, installed_length=outer.lengths["installed_length"],
                           max_free_length=options.max_free_length, partner_frequency=outer.natural_frequency,
                           min_frequency_difference=options.min_frequency_difference)


def _joined(outer, inner, options, lift):
    """(outer index, inner index, count) of the lightest compatible pair of two grades' candidates, or None.

    Per line: the :data:`PAIR_CANDIDATES` lightest passing springs of each kind, compatible when the inner
    one fits inside the outer one with ``options.radial_gap``, its own length at full lift is not longer
    than the outer one's (the coil gap at the common installed length), its natural frequency differs by
    ``options.min_frequency_difference`` and its free length at that installed length is allowed."""
    best, count = None, 0
    for line in np.unique(outer.line):
        o = np.flatnonzero(outer.passed & (outer.line == line))
        n = np.flatnonzero(inner.passed & (inner.line == line))
        o, n = o[np.argsort(outer.mass[o])][:PAIR_CANDIDATES], n[np.argsort(inner.mass[n])][:PAIR_CANDIDATES]
        if not len(o) or not len(n):
            continue
        room = outer.mean_diameter[o] - outer.wire_diameter[o] - 2.0 * options.radial_gap
        ok = (inner.mean_diameter[n] + inner.wire_diameter[n])[None, :] <= room[:, None]
        ok &= inner.lengths["min_length"][n][None, :] <= outer.lengths["min_length"][o][:, None] * (1.0 + 1e-9)
        w_o = outer.natural_frequency[o][:, None]
        ok &= np.abs(inner.natural_frequency[n][None, :] - w_o) / w_o >= options.min_frequency_difference
        if options.max_free_length is not None:
            free = outer.lengths["installed_length"][o][:, None] + (inner.preload[n] / inner.rate[n])[None, :]
            ok &= free <= options.max_free_length
        count += int(np.count_nonzero(ok))
        if ok.any():
            total = np.where(ok, outer.mass[o][:, None] + inner.mass[n][None, :], np.inf)
            a, b = np.unravel_index(int(np.argmin(total)), total.shape)
            if best is None or total[a, b] < best[0]:
                best = (total[a, b], int(o[a]), int(n[b]))
    return None if best is None else (best[1], best[2], count)


def design_pair(preloads, rates, lift, throat_diameter, camshaft_speed, options):
    """The lightest nested pair: the outer spring takes 1 - s of each line, the inner spring s (eqs. 5.10-5.14).

    Both kinds are searched over the whole grid (the inner one over D = 0.3...0.9 d_g), each
    with its own checks; the passing ones of the same line are joined (:func:`_joined`): one
    seat and one retainer, so the inner spring is installed at the outer one's length, fits
    inside it and has a natural frequency apart from it (6.14).  The pair of the smallest
    total mass wins.  When no pair passes, the best outer spring (lightest passing, else best
    worst margin) gets its best inner spring.

    Returns
    -------
    (dict, int, int)
        ``{"outer": SpringDesign, "inner": SpringDesign}``, the number of passing pairs found
        (0 when none) and the number of candidates tried.

    Raises
    ------
    NoSpringFits
        When no spring of the wire range can be wound (outer), or none fits inside the outer one.
    """
    share = options.inner_share
    p, c = np.asarray(preloads, dtype=float), np.asarray(rates, dtype=float)
    outer_found, outer_tried = _search(p * (1.0 - share), c * (1.0 - share), lift, throat_diameter, camshaft_speed,
                                       options)
    if not outer_tried:
        design_spring((p, c), throat_diameter, camshaft_speed, options, lift=lift)    # raises NoSpringFits
    inner_range = (INNER_DIAMETER_RATIO_LOW, options.diameter_range[1])
    inner_found, inner_tried = _search(p * share, c * share, lift, throat_diameter, camshaft_speed, options,
                                       diameter_range=inner_range, free_lengths=True)
    tried = outer_tried + inner_tried
    best, passing = None, 0
    for outer in outer_found:
        for inner in inner_found:
            joined = _joined(outer, inner, options, lift)
            if joined is None:
                continue
            a, b, count = joined
            passing += count
            total = outer.mass[a] + inner.mass[b]
            if best is None or total < best[0]:
                best = (total, outer, a, inner, b)
    if best is not None:
        _, outer, a, inner, b = best
        chosen = outer.design(a)
        return {"outer": chosen, "inner": _inner_design(chosen, inner, b, camshaft_speed, options)}, passing, tried
    found, a, _ = _best(outer_found)
    chosen = found.design(a)
    line = int(found.line[a])
    room = chosen.mean_diameter - chosen.wire_diameter - 2.0 * options.radial_gap
    inner, _, n_tried = design_spring(([p[line] * share], [c[line] * share]), throat_diameter, camshaft_speed, options,
                                      lift=lift, diameter_range=inner_range, max_outer=room,
                                      installed_length=chosen.lengths["installed_length"],
                                      partner_frequency=chosen.natural_frequency)
    return {"outer": chosen, "inner": inner}, 0, tried + n_tried


def design_springs(requirement, throat_diameter, camshaft_speed, options=SpringOptions()):
    """The lightest spring (or nested pair) of ``options`` for a requirement, over the lines of every allowed
    deflection ratio (:meth:`Requirement.lines`).

    Returns
    -------
    Search
    """
    line = requirement.line(options.ratio_range)
    preloads, rates = requirement.lines(options.ratio_range, line=line)
    lift = requirement.max_lift
    if options.count == 1:
        spring, passing, tried = design_spring((preloads, rates), throat_diameter, camshaft_speed, options, lift=lift)
        designs = {"spring": spring}
    else:
        designs, passing, tried = design_pair(preloads, rates, lift, throat_diameter, camshaft_speed, options)
    return Search(designs, passing, tried, line)


def resonance_stress(ratio, camshaft_speed, max_deflection, shape_factor, shear_modulus, density):
    """Shear stress at full lift of a spring whose surge frequency is ``ratio`` x omega_cam [Pa].

    Notes
    -----
    Eliminating d, D and i_p between (6.1), (6.2) and (6.13):

    .. math:: \\omega_{c1} = \\frac{\\pi \\tau_{max}}{\\chi f_{max} \\sqrt{2 \\rho G}}

    so that a resonance ratio R needs
    :math:`\\tau_{max} = R \\omega_{cam} \\chi f_{max} \\sqrt{2 \\rho G} / \\pi`, whatever the
    wire and mean diameters: at a given f_max (fixed by the line, f_max = h r / (r - 1))
    the frequency can only be bought with stress.

    References
    ----------
    Valve-train practical works (n.d.), eqs. (6.1), (6.2), (6.13) (as read in corrections note 47).

    Examples
    --------
    the appendix of Valve-train practical works (n.d.) speed and lift, f_max/f_min = 3.2 (f_max = 14.545 mm), chi = 1.1 (D/d = 12),
    60S2A: 10 x omega_cam needs 661.5 MPa.

    >>> round(float(resonance_stress(10.0, np.pi * 3500 / 30, 0.010 * 3.2 / 2.2, 1.1, 8e10, 7850.0)) / 1e6, 1)
    661.5
    """
    return ratio * camshaft_speed * shape_factor * max_deflection * np.sqrt(2.0 * density * shear_modulus) / np.pi


def fatigue_stress_limit(endurance, mean_stress_factor, ratio, min_safety):
    """Largest tau_max with a fatigue safety of ``min_safety`` when tau_min = tau_max / ratio [Pa].

    Notes
    -----
    From (6.10)-(6.12) with :math:`\\tau_{min} = \\tau_{max} / r` (r = f_max / f_min):

    .. math:: \\tau_{max} = \\frac{2 \\tau_{-1}}{n [(1 - 1/r) + \\psi_\\tau (1 + 1/r)]}

    Examples
    --------
    >>> tau = fatigue_stress_limit(370e6, 0.2, 3.2, 1.3)
    >>> round(float(fatigue_safety(tau, tau / 3.2, 370e6, 0.2)), 12)
    1.3
    """
    return 2.0 * endurance / (min_safety * ((1.0 - 1.0 / ratio) + mean_stress_factor * (1.0 + 1.0 / ratio)))


def _passing_factor(trial, floor, tolerance=0.01):
    """A factor in [floor, 1) for which ``trial(factor)`` passes, found by bisection to ``tolerance`` between
    ``floor`` (which must pass) and 1 (which failed); None when ``floor`` fails.  The factor returned always
    passed; with the discrete wire sizes a slightly larger one may pass too."""
    if not trial(floor):
        return None
    good, bad = floor, 1.0
    while bad - good > tolerance:
        middle = 0.5 * (good + bad)
        if trial(middle):
            good = middle
        else:
            bad = middle
    return float(good)


def stress_window(material, lift, camshaft_speed, ratio_range=DEFLECTION_RATIO_RANGE, wire_range_mm=WIRE_RANGE_MM):
    """The room the resonance check leaves between stress limits, at the best deflection ratio (SI).

    For each ratio r of ``ratio_range`` (every :data:`DEFLECTION_RATIO_STEP`): the stress the
    resonance ratio needs at f_max = h r / (r - 1) with the smallest shape factor of the
    table (D/d = 12, :func:`resonance_stress`), and the largest stress the grade allows at
    the thinnest wire ([tau] and :func:`fatigue_stress_limit` with tau_min = tau_max / r).
    No spring of the grade can pass when the needed stress exceeds the allowed one at every r.

    Returns
    -------
    dict
        ``ratio``, ``max_deflection`` [m], ``needed`` and ``allowed`` [Pa] at the ratio of the
        largest allowed / needed.
    """
    r = deflection_ratios(ratio_range)
    f_max = lift * r / (r - 1.0)
    needed = resonance_stress(material.min_resonance_ratio, camshaft_speed, f_max, SHAPE_FACTOR_TABLE[1][-1],
                              material.shear_modulus, material.density)
    allowable, endurance, psi = material.limits(np.array([wire_range_mm[0] * 1e-3]))
    allowed = np.minimum(allowable, fatigue_stress_limit(endurance, psi, r, material.min_safety))
    k = int(np.argmax(allowed / needed))
    return {"ratio": float(r[k]), "max_deflection": float(f_max[k]), "needed": float(needed[k]),
            "allowed": float(allowed[k])}


def _conflicts(search):
    """Every failing check of the springs of a search: value, limit (display units) and relative shortfall."""
    out = []
    for tag, spring in search.designs.items():
        for key, c in spring.checks.items():
            if not c.passed:
                limit = c.high if c.high is not None and (c.low is None or c.value > c.high) else c.low
                out.append({"spring": tag, "check": key, "quantity": c.quantity, "value": c.shown_value,
                            "limit": to_display(limit, c.unit), "unit": c.unit, "shortfall": -c.margin})
    return out


def _remedies(requirement, throat_diameter, camshaft_speed, options, conflicts, engine_speed):
    """(remedies that make a spring pass, remedies tried in vain), each computed by a new search."""
    def passing(req=requirement, speed=camshaft_speed, **changes):
        try:
            found = design_springs(req, throat_diameter, speed, replace(options, **changes))
        except NoSpringFits:
            return None
        return found if found.passes else None

    helped, tried = [], []
    base = options.materials[0]
    for name in (n for n in GRADES if n not in {m.grade for m in options.materials}):
        own = replace(base, grade=name, shear_modulus=None, density=None, allowable_stress=None, endurance_limit=None,
                      mean_stress_factor=None)
        found = passing(materials=(own,))
        (helped if found else tried).append({"change": "material", "to": name,
                                             **({"spring_mass_kg": found.mass} if found else {})})
    found = passing(count=3 - options.count)
    (helped if found else tried).append({"change": "count", "to": 3 - options.count,
                                         **({"spring_mass_kg": found.mass} if found else {})})
    if any(x["check"] == "installed_length" for x in conflicts):
        found = passing(installed_length_range=(None, None))
        if found:
            longest = max(s.lengths["installed_length"] for s in found.designs.values())
            helped.append({"change": "max_installed_length_mm", "to": longest * 1e3, "spring_mass_kg": found.mass})
        else:
            tried.append({"change": "max_installed_length_mm"})
    speed = _passing_factor(lambda f: passing(requirement.scaled(f**2), camshaft_speed * f) is not None, 0.3)
    if speed is None:
        tried.append({"change": "rated_speed_factor", "to": 0.3})
    else:
        helped.append({"change": "rated_speed_factor", "to": speed,
                       **({} if engine_speed is None else {"rated_speed_rpm": to_display(speed * engine_speed, "rpm")})})
    mass = _passing_factor(lambda f: passing(requirement.scaled(f)) is not None, 0.1)
    (tried if mass is None else helped).append({"change": "reduced_mass_factor", "to": 0.1 if mass is None else mass})
    return helped, tried


def _remedy_text(x, helped):
    """One remedy in words."""
    grams = f" ({x['spring_mass_kg'] * 1e3:.0f} g)" if helped and "spring_mass_kg" in x else ""
    if x["change"] == "material":
        return f"material = \"{x['to']}\"{grams}"
    if x["change"] == "count":
        return ("a nested pair (count = 2)" if x["to"] == 2 else "one spring (count = 1)") + grams
    if x["change"] == "max_installed_length_mm":
        return f"an installed length up to {x['to']:.1f} mm" if helped else "no installed length limit"
    if x["change"] == "rated_speed_factor":
        rpm = f" ({x['rated_speed_rpm']:.0f} rpm)" if "rated_speed_rpm" in x else ""
        return f"a rated speed lowered to {x['to']:.1%}{rpm}" if helped else "a rated speed down to 30 %"
    return f"a reduced mass lowered by {1.0 - x['to']:.0%}" if helped else "a reduced mass down to 10 %"


def diagnose(requirement, throat_diameter, camshaft_speed, options, search, engine_speed=None):
    """Why no spring of a search passes, by how much, and what would make one pass (each remedy computed).

    Parameters
    ----------
    requirement : Requirement
    throat_diameter, camshaft_speed : float
        d_g [m] and omega_cam [rad/s].
    options : SpringOptions
        The search that found no passing spring.
    search : Search
        Its result (the best candidate).
    engine_speed : float, optional
        Rated crank speed [rad/s], to state the speed remedy in rpm.

    Returns
    -------
    dict
        ``conflicts``: every failing check of the best candidate with its value, limit and
        relative shortfall; ``resonance`` (where the resonance check is on):
        :func:`stress_window` of the best candidate's grade in MPa and mm; ``remedies``: the
        changes with which a new search finds a passing spring (another grade of
        :data:`valvetrain.spring_materials.GRADES`, a nested pair or one spring, a longer
        installed length, a lower rated speed -- forces ~ omega^2, resonance ratio
        ~ 1/omega --, a lower reduced mass -- forces ~ m), with the spring mass where it
        applies; ``tried``: those that did not help; ``text``: all of it in words.
    """
    conflicts = _conflicts(search)
    pair = len(search.designs) > 1
    unit = {x["check"]: f" {x['unit']}" if x["unit"] else "" for x in conflicts}
    words = [f"{x['spring'] + ' ' if pair else ''}{x['quantity']} {x['value']:.4g}{unit[x['check']]} against "
             f"{x['limit']:.4g}{unit[x['check']]} (short by {x['shortfall']:.1%})" for x in conflicts]
    text = [f"No {'nested pair' if pair else 'spring'} passes; the best {'pair' if pair else 'candidate'}: "
            + "; ".join(words) + "."]
    out = {"conflicts": conflicts}
    grade_name = next(iter(search.designs.values())).material
    material = next(m for m in options.materials if m.grade == grade_name)
    if material.min_resonance_ratio > 0.0:
        w = stress_window(material, requirement.max_lift, camshaft_speed, options.ratio_range, options.wire_range_mm)
        out["resonance"] = {"material": grade_name, "deflection_ratio": w["ratio"],
                            "max_deflection_mm": w["max_deflection"] * 1e3, "stress_needed_MPa": w["needed"] / 1e6,
                            "stress_allowed_MPa": w["allowed"] / 1e6}
        where = (f"at D/d = 12 and f_max/f_min = {w['ratio']:.3g} (f_max = {w['max_deflection'] * 1e3:.3g} mm), "
                 f"while {grade_name} allows at most {w['allowed'] / 1e6:.0f} MPa there ([tau] and the fatigue safety)")
        separation = 1.0 + options.min_frequency_difference
        if w["needed"] > w["allowed"]:
            text.append(f"The resonance ratio {material.min_resonance_ratio:g} needs tau_max >= {w['needed'] / 1e6:.0f} "
                        f"MPa even {where}: no wire and no diameter of this grade can pass at this speed and lift.")
        elif pair and w["needed"] * separation > w["allowed"]:
            text.append(f"The two springs of a pair share f_max, so their frequencies stand as tau_max / chi: "
                        f"frequencies {options.min_frequency_difference:.0%} apart with both resonance ratios >= "
                        f"{material.min_resonance_ratio:g} need tau_max up to {w['needed'] * separation / 1e6:.0f} MPa "
                        f"even {where}: no nested pair of this grade can pass at this speed and lift.")
    helped, tried = _remedies(requirement, throat_diameter, camshaft_speed, options, conflicts, engine_speed)
    out["remedies"], out["tried"] = helped, tried
    if helped:
        text.append("A spring passes with " + "; or ".join(_remedy_text(x, True) for x in helped) + ".")
    if tried:
        text.append("None passes with " + ", ".join(_remedy_text(x, False) for x in tried) + ".")
    out["text"] = " ".join(text)
    return out
