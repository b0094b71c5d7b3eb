"""Why no spring of a search passes, by how much, and what would make one pass: data, in SI.

:func:`diagnose` returns a frozen :class:`Diagnosis`: the failing checks of the best candidate
(:class:`Conflict`), the room the resonance check leaves between stress limits (:class:`StressWindow`) and the
kind of conflict it proves, and the remedies, each tried by a new search (:class:`Remedy`: the specification key
it changes and the value suggested).  The words are the report's (:mod:`valvetrain.locale.wording`).
"""

from dataclasses import dataclass, replace
from typing import Optional

import numpy as np

from ..spring_materials import GRADES
from .formulas import SHAPE_FACTOR_TABLE, fatigue_stress_limit, resonance_stress
from .requirement import DEFLECTION_RATIO_RANGE, deflection_ratios
from .search import WIRE_RANGE_MM, NoSpringFits, design_springs

RESONANCE_STRESS = "resonance_stress"
"""Conflict kind: the resonance ratio needs more stress than the grade allows, for every wire and diameter."""

PAIR_FREQUENCIES = "pair_frequencies"
"""Conflict kind: the two springs of a pair cannot both reach the resonance ratio with frequencies apart."""

MATERIAL, COUNT, INSTALLED_LENGTH, RATED_SPEED, REDUCED_MASS = (
    "material", "count", "max_installed_length", "rated_speed_factor", "reduced_mass_factor")
"""The changes a remedy makes (:attr:`Remedy.change`)."""

SPEED_FLOOR, MASS_FLOOR = 0.3, 0.1
"""Lowest rated-speed and reduced-mass factors a remedy tries."""


@dataclass(frozen=True)
class Conflict:
    """A failing check of the best candidate of a search (SI)."""

    spring: str         # "spring", or "outer" / "inner" of a pair
    check: str          # the check's key in SpringDesign.checks ("tau_max", "resonance_ratio", ...)
    quantity: str       # the check's quantity
    value: float        # the candidate's value [SI]
    limit: float        # the bound it misses [SI]
    unit: str           # the display unit of value and limit
    shortfall: float    # relative distance beyond the bound, -margin


@dataclass(frozen=True)
class StressWindow:
    """The room the resonance check leaves between stress limits at the best deflection ratio (SI)."""

    material: str                 # the grade
    resonance_ratio: float        # the required omega_c1 / omega_cam
    deflection_ratio: float       # f_max / f_min where the room is largest
    max_deflection: float         # f_max = h r / (r - 1) [m]
    needed: float                 # tau_max the resonance ratio needs at D/d = 12 [Pa]
    allowed: float                # the largest tau_max the grade allows at the thinnest wire [Pa]


@dataclass(frozen=True)
class Remedy:
    """A change tried by a new search (SI).

    ``value``: the grade (:data:`MATERIAL`), the count (:data:`COUNT`), the longest installed length of the passing
    springs [m] or None for no limit (:data:`INSTALLED_LENGTH`), the factor on the rated speed (:data:`RATED_SPEED`)
    or on the reduced mass (:data:`REDUCED_MASS`); where it did not help, the furthest value tried.
    """

    change: str                           # MATERIAL, COUNT, INSTALLED_LENGTH, RATED_SPEED or REDUCED_MASS
    value: object
    passes: bool                          # a spring passes with it
    key: Optional[str] = None             # the key it changes: of [valves.NAME.spring] (material, count,
                                          # installed_length_mm: its upper end) or [engine] (rated_speed_rpm); None
                                          # for the part masses
    spring_mass: Optional[float] = None   # of the passing spring(s) [kg], where the masses are kept
    rated_speed: Optional[float] = None   # the lowered rated crank speed [rad/s] of RATED_SPEED


@dataclass(frozen=True)
class Diagnosis:
    """Why no spring of a search passes and what would make one pass (:func:`diagnose`)."""

    pair: bool                            # a nested pair was searched
    frequency_difference: float           # the pair's least relative difference of the natural frequencies
    conflicts: tuple                      # Conflict of every failing check of the best candidate
    window: Optional[StressWindow]        # where the resonance check is on
    kind: Optional[str]                   # RESONANCE_STRESS, PAIR_FREQUENCIES, or None: the checks conflict only
    remedies: tuple                       # Remedy, in the order tried

    @property
    def helped(self) -> tuple:
        """The remedies with which a spring passes."""
        return tuple(r for r in self.remedies if r.passes)

    @property
    def tried(self) -> tuple:
        """The remedies tried in vain."""
        return tuple(r for r in self.remedies if not r.passes)


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


def stress_window(material, lift, camshaft_speed, ratio_range=DEFLECTION_RATIO_RANGE, wire_range_mm=WIRE_RANGE_MM) -> StressWindow:
    """The room the resonance check leaves between stress limits, at the best deflection ratio (SI).

    For each ratio r of ``ratio_range`` (every :data:`~valvetrain.springs.requirement.DEFLECTION_RATIO_STEP`): the
    stress the resonance ratio needs at f_max = h r / (r - 1) with the smallest shape factor of the
    table (D/d = 12, :func:`~valvetrain.springs.formulas.resonance_stress`), and the largest stress the grade allows
    at the thinnest wire ([tau] and :func:`~valvetrain.springs.formulas.fatigue_stress_limit` with
    tau_min = tau_max / r).  No spring of the grade can pass when the needed stress exceeds the allowed one at
    every r.

    Returns
    -------
    StressWindow
        At the ratio of the largest allowed / needed.
    """
    r = deflection_ratios(ratio_range)
    f_max = lift * r / (r - 1.0)
    needed = resonance_stress(material.min_resonance_ratio, camshaft_speed, f_max, SHAPE_FACTOR_TABLE[1][-1],
                              material.shear_modulus, material.density)
    allowable, endurance, psi = material.limits(np.array([wire_range_mm[0] * 1e-3]))
    allowed = np.minimum(allowable, fatigue_stress_limit(endurance, psi, r, material.min_safety))
    k = int(np.argmax(allowed / needed))
    return StressWindow(material.grade, material.min_resonance_ratio, float(r[k]), float(f_max[k]),
                        float(needed[k]), float(allowed[k]))


def _conflicts(search):
    """Every failing check of the springs of a search: value and the bound it misses (SI), relative shortfall."""
    out = []
    for tag, spring in search.designs.items():
        for key, c in spring.checks.items():
            if not c.passed:
                limit = c.high if c.high is not None and (c.low is None or c.value > c.high) else c.low
                out.append(Conflict(tag, key, c.quantity, c.value, limit, c.unit, -c.margin))
    return tuple(out)


def _remedies(requirement, throat_diameter, camshaft_speed, options, conflicts, engine_speed):
    """The remedies tried, in order, each computed by a new search."""
    def passing(req=requirement, speed=camshaft_speed, **changes):
        try:
            found = design_springs(req, throat_diameter, speed, replace(options, **changes))
        except NoSpringFits:
            return None
        return found if found.passes else None

    def mass(found):
        return found.mass if found else None

    out = []
    base = options.materials[0]
    for name in (n for n in GRADES if n not in {m.grade for m in options.materials}):
        own = replace(base, grade=name, shear_modulus=None, density=None, allowable_stress=None, endurance_limit=None,
                      mean_stress_factor=None)
        found = passing(materials=(own,))
        out.append(Remedy(MATERIAL, name, bool(found), "material", mass(found)))
    found = passing(count=3 - options.count)
    out.append(Remedy(COUNT, 3 - options.count, bool(found), "count", mass(found)))
    if any(x.check == "installed_length" for x in conflicts):
        found = passing(installed_length_range=(None, None))
        longest = max(s.lengths["installed_length"] for s in found.designs.values()) if found else None
        out.append(Remedy(INSTALLED_LENGTH, longest, bool(found), "installed_length_mm", mass(found)))
    speed = _passing_factor(lambda f: passing(requirement.scaled(f**2), camshaft_speed * f) is not None, SPEED_FLOOR)
    out.append(Remedy(RATED_SPEED, SPEED_FLOOR if speed is None else speed, speed is not None, "rated_speed_rpm",
                      rated_speed=None if speed is None or engine_speed is None else speed * engine_speed))
    factor = _passing_factor(lambda f: passing(requirement.scaled(f)) is not None, MASS_FLOOR)
    out.append(Remedy(REDUCED_MASS, MASS_FLOOR if factor is None else factor, factor is not None))
    return tuple(out)


def diagnose(requirement, throat_diameter, camshaft_speed, options, search, engine_speed=None) -> Diagnosis:
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
        Rated crank speed [rad/s], for the lowered rated speed of the speed remedy.

    Returns
    -------
    Diagnosis
        ``conflicts``: every failing check of the best candidate with its value, limit and relative shortfall;
        ``window`` (where the resonance check is on): :func:`stress_window` of the best candidate's grade, and
        ``kind``: :data:`RESONANCE_STRESS` where the resonance ratio needs more stress than the grade allows
        whatever the wire and diameter, :data:`PAIR_FREQUENCIES` where a pair's two springs, sharing f_max, cannot
        both reach it with their frequencies ``options.min_frequency_difference`` apart (their frequencies stand
        as tau_max / chi); ``remedies``: the changes tried by a new search (another grade of
        :data:`valvetrain.spring_materials.GRADES`, a nested pair or one spring, a longer installed length, a
        lower rated speed -- forces ~ omega^2, resonance ratio ~ 1/omega --, a lower reduced mass -- forces ~ m),
        whether a spring passes with each and its mass where it applies.
    """
    conflicts = _conflicts(search)
    pair = len(search.designs) > 1
    grade_name = next(iter(search.designs.values())).material
    material = next(m for m in options.materials if m.grade == grade_name)
    window, kind = None, None
    if material.min_resonance_ratio > 0.0:
        window = stress_window(material, requirement.max_lift, camshaft_speed, options.ratio_range,
                               options.wire_range_mm)
        if window.needed > window.allowed:
            kind = RESONANCE_STRESS
        elif pair and window.needed * (1.0 + options.min_frequency_difference) > window.allowed:
            kind = PAIR_FREQUENCIES
    remedies = _remedies(requirement, throat_diameter, camshaft_speed, options, conflicts, engine_speed)
    return Diagnosis(pair, options.min_frequency_difference, conflicts, window, kind, remedies)
