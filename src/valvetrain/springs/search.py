"""The vectorised search for the lightest valve spring or nested pair (Valve-train practical works (n.d.), work 6).

The search tries a grid of springs at once (numpy arrays over the candidates): the straight lines above the
required force with the deflection ratios of the manual (:meth:`~valvetrain.springs.requirement.Requirement.lines`),
the wire grades of :mod:`valvetrain.spring_materials`, the mean diameters D = (0.7...0.9) d_g and the wire
diameters 2.0...7.0 mm; bounds that need no spring designed screen out the candidates that cannot pass first
(:func:`_may_pass`).  The lightest spring that passes every check is chosen; when none passes, the best worst
margin is, and :func:`valvetrain.springs.diagnosis.diagnose` names the requirements in conflict.

SI units: N, m, Pa, kg, rad/s; the wire series is a catalogue grid in mm.
"""

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from ..errors import InputError
from .candidates import INSTALLED_TO_LIFT_MAX, SpringDesign, SpringMaterial, evaluate_spring, evaluate_springs
from .formulas import SHAPE_FACTOR_TABLE, natural_frequency, shape_factor_table
from .requirement import DEFLECTION_RATIO_RANGE, Characteristic

WIRE_RANGE_MM = (2.0, 7.0)
WIRE_STEP_MM = 0.1
"""Wire diameters searched [mm]: every 0.1 mm from 2.0 to 7.0 mm.  Wider than the manual's series
2.8, 3.0, 3.5, 3.8, 4.0, 4.2, 4.5, 4.8, 5.0, 5.5, 6.0 mm (Valve-train practical works (n.d.), work 6); valve-spring wire is drawn to
any size in this range (EN 10270-2 makes the VD grades from 0.5 to 10 mm)."""

MEAN_DIAMETER_RANGE = (0.7, 0.9)
"""Spring mean diameter / valve throat diameter (Valve-train practical works (n.d.), work 6)."""

MEAN_DIAMETER_STEP = 0.1e-3
"""Step of the mean diameters tried [m]."""

INNER_DIAMETER_RATIO_LOW = 0.3
"""Smallest mean diameter of the inner spring of a pair / throat diameter (it must fit inside the outer one)."""


class NoSpringFits(InputError):
    """No spring of the wire range can be wound within the given diameters.

    Parameters
    ----------
    wire_range_mm : (float, float)
        The wire range searched [mm] (a catalogue grid, as in the specification).
    mean_diameters : (float, float)
        The mean diameters searched, D from ``diameter_range`` x d_g [m].
    max_outer : float, optional
        Largest outside diameter D + d of an inner spring [m]: the room inside the outer one.

    Attributes
    ----------
    feasible : (float, float)
        The mean diameters the wire range can make, index D/d 3...12 (:func:`feasible_mean_diameters`) [m].
    """

    def __init__(self, wire_range_mm, mean_diameters, max_outer=None):
        self.wire_range_mm, self.mean_diameters, self.max_outer = tuple(wire_range_mm), tuple(mean_diameters), max_outer
        self.feasible = feasible_mean_diameters(wire_range_mm)
        super().__init__(str(self))

    def __str__(self):
        (w1, w2), (lo, hi), (low, high) = self.wire_range_mm, self.mean_diameters, self.feasible
        inside = (f" inside the outer spring (outside diameter <= {self.max_outer * 1e3:.1f} mm)" if self.max_outer
                  else "")
        return (f"no spring of the wire range {w1:g}...{w2:g} mm fits{inside} with D in {lo * 1e3:.1f}...{hi * 1e3:.1f} "
                f"mm; the range makes D = {low * 1e3:g}...{high * 1e3:g} mm (index 3...12)")


def wire_series(wire_range_mm=WIRE_RANGE_MM, step_mm=WIRE_STEP_MM) -> np.ndarray:
    """Wire diameters [m] from ``wire_range_mm[0]`` to ``wire_range_mm[1]`` every ``step_mm``.

    >>> [round(float(d) * 1e3, 1) for d in wire_series((2.8, 3.2))]
    [2.8, 2.9, 3.0, 3.1, 3.2]
    """
    low, high = wire_range_mm
    count = int(np.floor((high - low) / step_mm + 1e-9))
    return np.round(low + step_mm * np.arange(count + 1), 9) * 1e-3


def feasible_mean_diameters(wire_range_mm=WIRE_RANGE_MM) -> tuple[float, float]:
    """Mean diameters D [m] some wire of the range can make: D/d within the shape-factor table (3...12)."""
    index = SHAPE_FACTOR_TABLE[0]
    return index[0] * min(wire_range_mm) * 1e-3, index[-1] * max(wire_range_mm) * 1e-3

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

    def installed_limits(self, lift) -> tuple:
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
    def passes(self) -> bool:
        return all(s.passes for s in self.designs.values())

    @property
    def mass(self) -> float:
        return sum(s.mass for s in self.designs.values())


@dataclass(frozen=True, eq=False)
class _Grid:
    """The candidates' diameters of a search (:func:`_grid`) and what the screen's bounds (:func:`_may_pass`) need of
    each grid point alone, for one grade (SI; read-only arrays where :func:`_grid_of` shares them between searches)."""

    mean_diameter: np.ndarray
    wire_diameter: np.ndarray
    shape_factor: np.ndarray       # chi of D/d
    one_coil: np.ndarray           # G d^4 / (8 D^3), the rate of one working coil [N/m]
    allowable: np.ndarray          # [tau] [Pa]
    endurance: np.ndarray          # tau_-1 [Pa]
    psi: np.ndarray                # psi_tau
    stress_per_force: np.ndarray   # 8 chi D / (pi d^3) [1/m^2]
    surge_per_coil: np.ndarray     # omega_c1 of one working coil [rad/s]

    @classmethod
    def of(cls, big_d, d, material):
        g, rho = material.shear_modulus, material.density
        chi = shape_factor_table(big_d / d)
        return cls(big_d, d, chi, g * d**4 / (8.0 * big_d**3), *material.limits(d), 8.0 * chi * big_d / (np.pi * d**3),
                   natural_frequency(d, big_d, 1.0, g, rho))


@lru_cache(maxsize=32)
def _grid_of(throat_diameter, diameter_range, diameter_step, wire_range_mm, wire_step_mm, max_outer, material) -> _Grid:
    """The :class:`_Grid` of a search, made once for its diameters and grade: the searches of one design (the drive
    stage repeats its search until the spring's mass settles) and of an optimisation or a drag share it."""
    big_d, d = _grid(throat_diameter, diameter_range, diameter_step, wire_series(wire_range_mm, wire_step_mm),
                     max_outer)
    grid = _Grid.of(big_d, d, material)
    for a in vars(grid).values():
        a.flags.writeable = False
    return grid


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

    Each bound is widened by :data:`SCREEN_SLACK`.  The grid points that no line may pass (each bound against the
    lines' most lenient value: the rounding of a sum or product never decreases as its terms grow) are left out
    before the bounds are taken line by line.
    """
    return _screen(preloads, rates, lift, _Grid.of(big_d, d, material), material, camshaft_speed,
                   max_installed_length)


@dataclass(frozen=True)
class _Caps:
    """The screen's bounds (:func:`_may_pass`) of each grid point alone for a lift, a camshaft speed and a longest
    installed length (SI): the same for every search of one design, whose lines alone change."""

    force_cap: np.ndarray      # largest P_max of tau_max <= [tau] [N]
    max_rate: np.ndarray       # largest C of two working coils [N/m]
    min_rate: np.ndarray       # smallest C of the coils the resonance ratio and the length allow [N/m]
    fatigue_cap: np.ndarray    # largest C h + psi_tau (2 P_min + C h) of the fatigue safety [N], None where it is off

    @classmethod
    def of(cls, grid, material, lift, camshaft_speed, max_installed_length):
        d = grid.wire_diameter
        force_cap = grid.allowable * (1.0 + SCREEN_SLACK) / grid.stress_per_force
        max_rate = grid.one_coil / (2.0 * (1.0 - SCREEN_SLACK))
        coil_cap = np.full(d.shape, np.inf)
        if material.min_resonance_ratio > 0.0:
            coil_cap = grid.surge_per_coil / (material.min_resonance_ratio * camshaft_speed)
        if max_installed_length is not None:
            fit = (max_installed_length * (1.0 + SCREEN_SLACK) - lift - d * (material.end_coils - 1.0)) / (
                d * (1.0 + material.gap_factor)) - 2.0
            coil_cap = np.minimum(coil_cap, fit)
        coil_cap = coil_cap + SCREEN_SLACK * (np.abs(coil_cap) + 1.0) + 0.5
        min_rate = np.where(coil_cap > 0.0, grid.one_coil / np.where(coil_cap > 0.0, coil_cap, 1.0), np.inf)
        fatigue_cap = None
        if material.min_safety > 0.0:
            fatigue_cap = np.where(grid.psi >= 0.0, 2.0 * grid.endurance / (
                grid.stress_per_force * material.min_safety * (1.0 - SCREEN_SLACK)), np.inf)
        return cls(force_cap, max_rate, min_rate, fatigue_cap)


@lru_cache(maxsize=32)
def _caps_of(grid, material, lift, camshaft_speed, max_installed_length) -> _Caps:
    """:meth:`_Caps.of` made once for a grid of :func:`_grid_of` (held by identity) and the rest: the searches of
    one design's spring-mass fixed point (:func:`valvetrain.design.drive.drive_stage`) share it."""
    return _Caps.of(grid, material, lift, camshaft_speed, max_installed_length)


def _screen(preloads, rates, lift, grid, material, camshaft_speed, max_installed_length, caps=None):
    """:func:`_may_pass` on a :class:`_Grid`, with its :class:`_Caps` where the caller holds them."""
    d = grid.wire_diameter
    p = np.asarray(preloads, dtype=float)
    c = np.asarray(rates, dtype=float)
    p_max, travel = p + c * lift, c * lift
    if caps is None:
        caps = _Caps.of(grid, material, lift, camshaft_speed, max_installed_length)
    force_cap, max_rate, min_rate, fatigue_cap = caps.force_cap, caps.max_rate, caps.min_rate, caps.fatigue_cap
    mean = 2.0 * p + travel
    columns = (p_max.min() <= force_cap) & (c.min() <= max_rate) & (c.max() >= min_rate)
    if fatigue_cap is not None:   # psi >= 0 wherever the cap is finite
        columns &= travel.min() + grid.psi * mean.min() <= fatigue_cap
    kept = np.flatnonzero(columns)
    inside = (p_max[:, None] <= force_cap[kept]) & (c[:, None] <= max_rate[kept]) & (c[:, None] >= min_rate[kept])
    if fatigue_cap is not None:
        inside &= travel[:, None] + grid.psi[kept] * mean[:, None] <= fatigue_cap[kept]
    keep = np.zeros((p.size, d.size), dtype=bool)
    keep[:, kept] = inside
    return keep


def _search(preloads, rates, lift, throat_diameter, camshaft_speed, options, *, diameter_range=None, max_outer=None,
            installed_length=None, partner_frequency=None, free_lengths=False):
    """Every line x grade x D x d: a list of :class:`Candidates` (one per grade) and the number of candidates
    tried.  ``free_lengths``: no limit on the lengths (the inner springs of a pair, installed at the outer one's
    length).

    Only the candidates that may pass (:func:`_may_pass`) are designed, in the order of the grid (line by line);
    when none of them passes, every candidate is, so that the best worst margin is found among all.  The
    lightest passing spring (with the design margin or without), the passing count and the margins of every spring
    designed are those of the exhaustive search: a spring with the margin passes."""
    grids = [_grid_of(throat_diameter, tuple(diameter_range or options.diameter_range), options.diameter_step,
                      tuple(options.wire_range_mm), options.wire_step_mm, max_outer, m) for m in options.materials]
    big_d, d = grids[0].mean_diameter, grids[0].wire_diameter
    low, high = (None, None) if free_lengths else options.installed_limits(lift)
    preloads, rates = np.asarray(preloads, dtype=float), np.asarray(rates, dtype=float)
    lines = np.arange(len(preloads))

    def designed(material, line, grid, of):
        found = evaluate_springs(
            preloads[line], rates[line], lift, big_d[grid], d[grid], material, camshaft_speed,
            ratio_range=options.ratio_range, installed_length=installed_length,
            min_installed_length=low if installed_length is None else None, max_installed_length=high,
            max_free_length=None if free_lengths else options.max_free_length, partner_frequency=partner_frequency,
            min_frequency_difference=options.min_frequency_difference, shape_factor=of.shape_factor[grid],
            limits=(of.allowable[grid], of.endurance[grid], of.psi[grid]))
        found.line = line
        return found

    longest = high if installed_length is None else None
    found = [designed(m, *divmod(np.flatnonzero(_screen(preloads, rates, lift, grid, m, camshaft_speed, longest,
                                                       _caps_of(grid, m, lift, camshaft_speed, longest))), len(d)),
                      grid)
             for m, grid in zip(options.materials, grids, strict=True)]
    if not any(c.passed.any() for c in found):
        line, grid = (a.ravel() for a in np.meshgrid(lines, np.arange(len(d)), indexing="ij"))
        found = [designed(m, line, grid, of) for m, of in zip(options.materials, grids, strict=True)]
    return found, len(options.materials) * len(lines) * len(d)


def _best(found):
    """(candidates, index, passing count): the lightest candidate meeting the design margin, else the passing one
    of the largest design margin, else the best worst margin."""
    passing = sum(int(np.count_nonzero(c.passed)) for c in found)
    if any(c.margin_met.any() for c in found):
        key = [np.where(c.margin_met, c.mass, np.inf) for c in found]
        k = int(np.argmin([np.min(m, initial=np.inf) for m in key]))
        return found[k], int(np.argmin(key[k])), passing
    if passing:
        key = [np.where(c.passed, c.design_margin, -np.inf) for c in found]
        k = int(np.argmax([np.max(m) for m in key]))
        return found[k], int(np.argmax(key[k])), passing
    key = [c.worst_margin for c in found]
    k = int(np.argmax([np.max(m) for m in key]))
    return found[k], int(np.argmax(key[k])), 0


def design_spring(required, throat_diameter, camshaft_speed, options=SpringOptions(), **limits) -> tuple[SpringDesign, int, int]:
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
        ratio = limits.get("diameter_range") or options.diameter_range
        raise NoSpringFits(options.wire_range_mm, (ratio[0] * throat_diameter, ratio[1] * throat_diameter),
                           limits.get("max_outer"))
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


def _joined(outer, inner, options, lift, chosen="passed"):
    """(outer index, inner index, count) of the lightest compatible pair of two grades' candidates, or None.

    Per line: the :data:`PAIR_CANDIDATES` lightest springs of each kind that pass (``chosen = "passed"``) or also
    meet the design margin (``"margin_met"``), compatible when the inner
    one fits inside the outer one with ``options.radial_gap``, its own length at full lift is not longer
    than the outer one's (the coil gap at the common installed length), its natural frequency differs by
    ``options.min_frequency_difference`` and its free length at that installed length is allowed."""
    best, count = None, 0
    for line in np.unique(outer.line):
        o = np.flatnonzero(getattr(outer, chosen) & (outer.line == line))
        n = np.flatnonzero(getattr(inner, chosen) & (inner.line == line))
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


def design_pair(preloads, rates, lift, throat_diameter, camshaft_speed, options) -> tuple[dict[str, SpringDesign], int, int]:
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
    joined = {chosen: [(o, n, _joined(o, n, options, lift, chosen)) for o in outer_found for n in inner_found]
              for chosen in ("margin_met", "passed")}
    passing = sum(j[2] for _, _, j in joined["passed"] if j is not None)
    pairs = ([(o.mass[j[0]] + n.mass[j[1]], k, o, j[0], n, j[1]) for k, (o, n, j) in enumerate(found) if j is not None]
             for found in joined.values())
    best = next((min(found) for found in pairs if found), None)
    if best is not None:
        _, _, outer, a, inner, b = best
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


def design_springs(requirement, throat_diameter, camshaft_speed, options=SpringOptions()) -> Search:
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
