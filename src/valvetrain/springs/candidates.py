"""Many valve springs designed at once (Valve-train practical works (n.d.), work 6): for each candidate line,
wire grade, mean and wire diameter, the working coils, stresses, fatigue safety, surge frequency, lengths, mass
and every check, as numpy arrays over the candidates.

SI units: N, m, Pa, kg, rad/s.
"""

from dataclasses import dataclass, field
from functools import cached_property, lru_cache

import numpy as np

from ..checks import _TOL, check
from ..locale import cited, note
from ..masses import spring_mass
from ..spring_materials import GRADES, grade
from .formulas import (active_coils, fatigue_safety, length_at_pitch, natural_frequency, shape_factor_table,
                       shear_stress, spring_lengths, spring_rate, wahl_factor)
from .requirement import DEFLECTION_RATIO_RANGE, Characteristic

_WORKS = "Valve-train practical works (n.d.)"
"""The work whose chapter 6 the spring design follows, as cited."""

RESONANCE_RATIO_MIN = 10.0
"""omega_c1 / omega_cam (Valve-train practical works (n.d.), eq. 6.14)."""

INSTALLED_TO_LIFT_MAX = 6.0
"""Default upper limit of the installed length l_0 / valve lift h where no ``installed_length_mm`` is
given.  A stated default of this package, not from the sources, which set no length: it keeps the search
to springs that fit a cylinder head and leaves out, for example, the 120 mm long outer spring (l_0 = 10 h)
that the search without a limit proposed for the nested pair of the polydyne example; the springs
chosen for the shipped examples stand at 4.3-4.8 h."""

MIN_WORKING_COILS = 1.0
"""Fewest working coils i_p of a designed spring: those of (6.2) rounded down to half coils, at least one (the
``working_coils`` check asks for two)."""

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
    design_margin: float = 0.0           # sought on n and omega_c1 / omega_cam above their minima, 0.05 = 5 %
    gap_factor: float = 0.12             # Delta_min / d, 0.10-0.15
    end_coils: float = 2.0               # i_0

    def __post_init__(self):
        found = grade(self.grade)
        object.__setattr__(self, "grade", found.name)
        if self.shear_modulus is None:
            object.__setattr__(self, "shear_modulus", found.shear_modulus)
        if self.density is None:
            object.__setattr__(self, "density", found.density)

    def limits(self, wire_diameter) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
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
    def source(self) -> str:
        """Where the grade's figures come from."""
        return GRADES[self.grade].source


def shortest_solid_length(wire_diameter) -> float:
    """Solid length of the shortest spring a search makes of wire ``d`` [m]: :data:`MIN_WORKING_COILS` and the end
    coils i_0 of :class:`SpringMaterial` closed, (6.4) at the pitch t = d (:func:`~.formulas.length_at_pitch`).
    A spring of that wire installed shorter than the valve lift plus this length goes solid before full lift.

    >>> round(shortest_solid_length(2e-3) * 1e3, 9)        # one working coil, two end coils: 3 d + d
    8.0
    """
    return float(length_at_pitch(wire_diameter, wire_diameter, MIN_WORKING_COILS, SpringMaterial.end_coils))


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
    def margins(self) -> dict[str, float]:
        """Relative margin of each check: >= 0 passes (value/limit - 1 for a minimum, 1 - value/limit for a
        maximum; +inf for a check switched off by a zero minimum)."""
        return {k: c.margin for k, c in self.checks.items()}

    @property
    def passes(self) -> bool:
        return all(c.passed for c in self.checks.values())

    @property
    def binding_check(self) -> str:
        """The check with the smallest margin."""
        return min(self.margins, key=self.margins.get)

    @property
    def design_margin(self) -> float:
        """The smaller relative margin of the fatigue safety and the resonance ratio (+inf where both are off)."""
        return min(self.checks["fatigue_safety"].margin, self.checks["resonance_ratio"].margin)


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
            return None if x is None else float(x[i] if np.ndim(x) else x)

        return check(self.code, float(self.value[i]), pick(self.low), pick(self.high), unit=self.unit,
                     source=self.source, severity=self.severity)


@lru_cache(maxsize=256)
def _cited(source):
    """The words of a check's source note (:func:`valvetrain.locale.cited`), said once: a spring design cites the
    same few sources in every search of its spring-mass fixed point (five for the built-in example's intake)."""
    return cited(source)


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
    def passed(self) -> np.ndarray:
        """Candidates passing every check."""
        ok = np.ones(len(self), dtype=bool)
        for c in self.checks.values():
            ok &= c.passed
        return ok

    @cached_property
    def design_margin(self) -> np.ndarray:
        """The smaller relative margin of each candidate's fatigue safety and resonance ratio."""
        return np.minimum(self.checks["fatigue_safety"].margin, self.checks["resonance_ratio"].margin)

    @cached_property
    def margin_met(self) -> np.ndarray:
        """Candidates passing every check with :attr:`SpringMaterial.design_margin` on the fatigue safety and the
        resonance ratio."""
        return self.passed & (self.design_margin >= self.material.design_margin - _TOL)

    @cached_property
    def worst_margin(self) -> np.ndarray:
        """The smallest margin of each candidate."""
        return np.minimum.reduce([c.margin for c in self.checks.values()])

    def design(self, i) -> SpringDesign:
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
                     min_frequency_difference=0.0, shape_factor=None, limits=None) -> Candidates:
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
    shape_factor : ndarray, optional
        chi of the candidates (:func:`~valvetrain.springs.formulas.shape_factor_table` of D/d), where the caller
        holds it already (the search's grid); computed when not given.
    limits : (ndarray, ndarray, ndarray), optional
        ([tau], tau_-1, psi_tau) of the candidates' wires (:meth:`SpringMaterial.limits`), likewise.

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
    chi = shape_factor_table(big_d / d) if shape_factor is None else shape_factor
    allowable, endurance, psi = material.limits(d) if limits is None else limits
    p_max = p0 + c0 * lift
    exact = active_coils(g, d, p_max / c0, p_max, big_d)
    coils = np.maximum(np.floor(exact * 2.0) / 2.0, MIN_WORKING_COILS)
    actual = spring_rate(g, d, big_d, coils)
    tau_max = shear_stress(p0 + actual * lift, big_d, d, chi)
    tau_min = shear_stress(p0, big_d, d, chi)
    safety = fatigue_safety(tau_max, tau_min, endurance, psi)
    omega = natural_frequency(d, big_d, coils, g, rho)
    shape = np.broadcast_shapes(np.shape(p0), np.shape(c0), np.shape(big_d), np.shape(d))

    def flat(x):   # the search's candidates come flat already: broadcast only what is not
        return np.ravel(x) if np.shape(x) == shape else np.broadcast_to(x, shape).ravel()

    p0, c0, big_d, d, chi, allowable, endurance, psi, exact, coils, actual, tau_max, tau_min, safety, omega = map(
        flat, (p0, c0, big_d, d, chi, allowable, endurance, psi, exact, coils, actual, tau_max, tau_min, safety, omega))
    lengths = spring_lengths(d, coils, lift, p0 / actual, material.gap_factor, material.end_coils)
    imposed = None if installed_length is None else flat(installed_length)
    if imposed is None and min_installed_length is not None:
        imposed = np.maximum(lengths["installed_length"], min_installed_length)
    if imposed is not None:
        lengths = spring_lengths(d, coils, lift, p0 / actual, material.gap_factor, material.end_coils, imposed)
    mass = spring_mass(big_d, d, coils + material.end_coils, rho)
    grade = {"grade": material.grade, "material": material.source.parts}
    checks = {
        "tau_max": _ArrayCheck("spring.tau_max", tau_max, high=allowable, unit="MPa", severity="failure",
                               source=_cited(note("source.spring_allowable", work=f"{_WORKS}, eq. (6.1)",
                                                  **grade))),
        "fatigue_safety": _ArrayCheck("spring.fatigue_safety", safety, low=_minimum(material.min_safety),
                                      severity="failure",
                                      source=_cited(note("source.spring_fatigue", work=f"{_WORKS}, eq. (6.12)",
                                                         **grade))),
        "resonance_ratio": _ArrayCheck("spring.resonance_ratio", omega / camshaft_speed,
                                       low=_minimum(material.min_resonance_ratio),
                                       source=_cited(note("source.spring_resonance", work=f"{_WORKS}, eq. (6.14)"))),
        # the coils of the spring as made (rounded down): the number its table shows; the rounding keeps the
        # verdict, floor(2 n) / 2 >= 2 exactly where n >= 2
        "working_coils": _ArrayCheck("spring.working_coils", coils, low=2.0,
                                     source=_cited(note("source.half_coils", work=f"{_WORKS}, eq. (6.2)"))),
        "deflection_ratio": _ArrayCheck("spring.deflection_ratio", (p0 + actual * lift) / p0, *ratio_range,
                                        source=_cited(note("source.rounded_coils", work=f"{_WORKS}, work 5"))),
    }
    if max_installed_length is not None:
        checks["installed_length"] = _ArrayCheck("spring.installed_length", lengths["installed_length"],
                                                 high=max_installed_length, unit="mm",
                                                 source=_cited(note("source.installed_length",
                                                                    factor=INSTALLED_TO_LIFT_MAX)))
    if max_free_length is not None:
        checks["free_length"] = _ArrayCheck("spring.free_length", lengths["free_length"], high=max_free_length, unit="mm",
                                            source=_cited(note("source.free_length")))
    if imposed is not None:
        checks["coil_gap_at_full_lift"] = _ArrayCheck("spring.coil_gap_at_full_lift",
                                                      lengths["min_pitch"] / d - 1.0, low=material.gap_factor,
                                                      source="Valve-train practical works (n.d.), eq. (6.3): Delta_min = 0.10-0.15 d")
    if partner_frequency is not None:
        difference = np.abs(omega - partner_frequency) / partner_frequency
        checks["frequency_difference"] = _ArrayCheck("spring.frequency_difference", difference,
                                                     low=_minimum(min_frequency_difference),
                                                     source=_cited(note("source.ratios_differ",
                                                                        work=f"{_WORKS}, eq. (6.14)",
                                                                        difference=min_frequency_difference)))
    target = (p0 + c0 * lift) / p0
    return Candidates(material, big_d, d, coils, p0, actual, lift, target, chi, tau_max, tau_min, safety,
                      omega, omega / camshaft_speed, lengths, mass, checks)


def evaluate_spring(required, mean_diameter, wire_diameter, material, camshaft_speed, **limits) -> SpringDesign | None:
    """Design one spring of given diameters for a line (:func:`evaluate_springs` of one candidate).

    Returns
    -------
    SpringDesign or None
        None when the spring index D/d is outside the manual's table (3...12).
    """
    found = evaluate_springs(required.preload, required.rate, required.lift, mean_diameter, wire_diameter, material,
                             camshaft_speed, **limits)
    return found.design(0) if np.isfinite(found.shape_factor[0]) else None
