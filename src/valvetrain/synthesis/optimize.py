"""Cam synthesis by optimisation: the parameters of a valve's parametric lift law that maximise its fullness or
its time-area under the design's limits, the dynamics among them.

The variables are keys of the valve's specification (:class:`~valvetrain.synthesis.variables.Variable`, a path under ``[valves.NAME]``): the
cam's (``cam.phi1_deg``, ``cam.shape_factor``, ``cam.p``, ``cam.ratios.1.value``) and the spring reserve
``drive.spring_reserve``.  Every law with parameters has a default set (:func:`default_variables`: Kurz,
constant acceleration, polydyne exponents, combined-function ratios, the piecewise power polynomial); any other
numeric key may be named, within the key's own allowed range.  The lift, the timing and the follower stay as the
specification gives them.

One evaluation (:class:`Problem`) builds the law of a point through the cam section of the specification and
samples it once on a grid of the flank (the whole event for a cam with a closing flank of its own), then once more
on short windows around each extreme of the sampled quantities (so the extremes are those of the contour between
the samples, not of the grid): the objective (the flow module's fullness or time-area, exact quadrature) and the
margins of the limits (:class:`~.constraints.Limits`): spring reserve, pressure angle and concave radius against
the grinding wheel of a roller follower, the smallest convex radius of the contour and the Hertz stress with the cam
width from standstill to the over-speed (either follower), the acceleration band, the seating velocity, the spring
design, and, with ``no_jump_factor``, the follower separation of the one-mass elastic train at the rated speed and at
that multiple of it.  The separation is simulated only for a point that meets every other limit (elsewhere its
margin is NaN: not needed, the point is outside already).  During the search the train and its spring are the
starting design's (the spring scaled by K_z / K_z,0 when the spring reserve is a variable, as the spring design sizes
it); the spring design's margin is the closed form of the spring's required force line against the start's
(:meth:`Problem.spring_design`), the discrete spring search runs only for the final design.

Search: :func:`scipy.optimize.differential_evolution` over the bounds, the whole population evaluated at once, the
start in its first population and the margins as an exact penalty (:data:`~valvetrain.synthesis.problem.PENALTY`), then a local polish with SLSQP,
the margins as constraints, from its best point, as the method's article does (UkrSURT Proceedings (2019); Shang
Hanji (1988), section 4.3).  The result is the best point evaluated that meets every limit in full: the points that
met every margin of the search are designed in full (their own spring, a dynamics sweep), best first, until one meets
every constraint (:func:`final_checks`); the start is one of them, so the optimum is never worse than a start that
meets every limit.  Where no point does, the result says so (:attr:`Result.feasible`) with the limits that fail.
"""

from dataclasses import dataclass, field, replace
import math
import time
import tomllib

import numpy as np
from scipy import optimize

from ..checks import Check
from ..design import run as run_design
from ..design.dynamics import SPEED_RANGE, dynamics_stage
from ..errors import InputError
from ..locale import note, note_text, record_text
from ..specification import SpecError
from ..specification.models import Dynamics
from ..specification.si import si
from ..units import to_display
from .constraints import Limits, constraints, spring_reserve
from .objectives import (BREATHING, OBJECTIVES, breathing_objective, check_breathing_objective, objective_value,
                         polydyne_fullness)
from .problem import Problem
from .variables import check_bounds, default_variables, unique_variables


POLISH_RESERVE = 1e-5
"""Relative margin the local polish keeps from every limit (the full design's extremes, refined to round-off, may lie
that far beyond the search's)."""

RELAXED = 1e-6
"""Relative room a limit relaxed to the start's value leaves beyond it (the search's extremes and the full design's
agree to about this, so that the start itself meets the limit in both)."""

FINAL_CANDIDATES = 4
"""Points that met every margin of the search designed in full at most, best first, before the start is taken."""

CAM_WIDTH_TO_BASE_RADIUS = 0.5
"""The cam width of the Hertz stress where ``parts.cam_width_mm`` is not given, as a fraction of the base radius r0:
a narrow cam, so that the stress is not understated (a configurable default; no primary source states it)."""

FINAL_SPEEDS = 60
"""Speeds of the final check's dynamics sweep."""

POLISH_ITERATIONS = 60
"""Iterations of the SLSQP polish at most (from a feasible point it converges in about 20)."""

BINDING = 1e-3
"""A constraint whose relative margin at the optimum is below this binds."""


def _relaxed(c, notes):
    """The band of a start check, widened to the start's value where the start lies outside it (noted)."""
    if c is None:
        return None, None
    low, high = c.low, c.high
    if not c.passed:
        notes.append({"quantity": record_text(c.code), "code": c.code, "value": c.shown_value, "unit": c.unit, "range": c.range})
        low = None if low is None else min(low, c.value - RELAXED * abs(c.value))
        high = None if high is None else max(high, c.value + RELAXED * abs(c.value))
    return low, high


def design_limits(design, wheel_radius=None, no_jump_factor=None, ramp_varied=True, cam_width=None,
                  seating_velocity=None, top_speed=1.0, valve=None) -> tuple[Limits, list[str]]:
    """The limits of a design's own checks and of the synthesis, and notes on how they were set.

    Parameters
    ----------
    design : ValveDesign
        The starting design.
    wheel_radius : float, optional
        Grinding wheel radius [m]; default the ``[grinding]`` section's, else no concave-radius limit.
    no_jump_factor : float, optional
        No follower separation up to this multiple of the rated speed.
    ramp_varied : bool
        Whether the ramp end velocity is a variable (else it has no limit: it cannot change).
    cam_width : float, optional
        Cam width of the Hertz stress [m]; default :data:`CAM_WIDTH_TO_BASE_RADIUS` x the base radius.
    seating_velocity : float, optional
        Largest valve seating (and opening) velocity [m/s]; default none.
    top_speed : float
        Highest engine speed over the rated speed up to which the contact stress is checked.
    valve : SI view of the valve, optional
        A finger's inertia by its variable ratio in the start's contact stress (:func:`~.constraints.constraints`).

    Returns
    -------
    (Limits, list of dict)
        The spring reserve of ``drive.spring_reserve``; the tappet acceleration bands of the design's checks
        (Valve-train practical works (n.d.), work 2), each widened to the starting design's value where that lies
        outside; the smallest convex contour radius >= 2 mm (Shang Hanji (1988), section 2.1); the Hertz stress
        <= 1200 MPa (Valve-train practical works (n.d.), eqs. 7.4-7.5), widened to the start's where it lies above;
        pressure angle <= 30 deg (UkrSURT Proceedings (2019)); the ramp end velocity band of
        :class:`~.constraints.Limits`, widened the same way (it bounds the kinematic seating velocity,
        i_k omega times it).
    """
    notes = []
    by_code = {c.code: c for c in design.checks}
    high, low = (_relaxed(by_code.get(code), notes)[i] for code, i in (("tappet_acceleration.max", 1),
                                                                        ("tappet_acceleration.min", 0)))
    if wheel_radius is None and design.grinding is not None:
        wheel_radius = design.grinding.wheel_radius
    limits = Limits(max_acceleration=high, min_acceleration=low, grinding_wheel_radius=wheel_radius,
                    min_spring_reserve=design.drive.spring.spring_reserve, no_jump_factor=no_jump_factor,
                    cam_width=cam_width or CAM_WIDTH_TO_BASE_RADIUS * design.cam.base_radius, top_speed=top_speed,
                    seating_velocity=None if seating_velocity is None else (0.0, seating_velocity))
    start = {c.code: c for c in constraints(design, replace(limits, no_jump_factor=None), valve)}
    limits = replace(limits, max_contact_stress=_relaxed(start["synthesis.contact_stress"], notes)[1])
    c = start.get("ramp.end_velocity")
    if not ramp_varied:
        limits = replace(limits, ramp_velocity=None)
    elif c is not None:
        limits = replace(limits, ramp_velocity=_relaxed(c, notes))
    return limits, notes


@dataclass
class Result:
    """An optimisation: the variables and the designs at the start and at the optimum, and the cost.

    ``start`` and ``optimum`` map each variable's path to its value; ``comparison`` holds rows
    ``(quantity, unit, start, optimum)`` of the two full designs; ``checks_start`` and ``checks`` the constraints
    on them (:func:`final_checks`); ``history`` one ``(objective, margins)`` per evaluation, in order (a margin not
    needed, NaN); ``law_samples`` the angles at which the search evaluated the law (the objective's quadrature nodes
    not counted), ``simulations`` the dynamics runs of the search (two speeds each).  Where no point meets every
    limit, ``optimum`` is the point nearest to them (or the start) and ``feasible`` is False.
    """

    valve: str
    objective: str
    start: dict
    optimum: dict
    start_value: float
    value: float
    bounds: list
    margin_names: list
    margins: dict
    evaluations: int
    seconds: float
    seconds_in_evaluations: float
    limit_notes: list = field(default_factory=list)
    comparison: list = field(default_factory=list)
    checks_start: list = field(repr=False, default_factory=list)
    checks: list = field(repr=False, default_factory=list)
    history: list = field(repr=False, default_factory=list)
    polydyne_fullness: float = None
    spec_text: str = field(repr=False, default="")
    law_samples: int = 0
    simulations: int = 0

    @property
    def feasible(self) -> bool:
        """Every constraint of the optimum's full design holds."""
        return all(c.passed for c in self.checks)

    @property
    def binding(self) -> list[Check]:
        """The constraints of the optimum with a relative margin below :data:`BINDING` (they bind)."""
        return [c for c in self.checks if c.passed and c.margin < BINDING]


def breathing_failures(results) -> list[Check]:
    """The breathing's checks of a full design that fail and are not accepted (cycles that did not repeat): an
    objective of :data:`BREATHING` read from them is not the converged cycle's, so they are limits of the optimum."""
    return [c for c in results.checks if c.code.startswith("breathing.") and not c.passed and not c.accepted]


def final_checks(design, spec, limits, scale=1.0, search_spring=None) -> list[Check]:
    """Every constraint of ``limits`` on a full design, and the design's own failures.

    Parameters
    ----------
    design : ValveDesign
    spec : valvetrain.specification.Spec
        The design's specification (its ``[dynamics]`` section, if any, sets the train of the sweep).
    limits : Limits
    scale : float
        K_z / K_z,0 of the design against the starting design.
    search_spring : springs.Characteristic, optional
        The starting design's spring: the reserve is checked with it (scaled) too, as the search held it.

    Returns
    -------
    list of Check
        With ``no_jump_factor``, the follower separation from a dynamics sweep of the design with its own spring
        from 10 % of the rated speed up to the limit or 125 % of it, whichever is higher (the ``[dynamics]``
        section's train and range, the range raised to that top where it ends below).  Then every failure check of
        the design that the specification does not accept, as ``valvetrain run`` grades it (one place for the
        limits: the valve-to-piston clearance of :data:`~valvetrain.design.valve_checks.PISTON_CLEARANCE_MIN`, the
        separation below ``[engine] over_speed_ratio``), but where a constraint above is the same check with the
        same bounds: an optimum passes what ``run`` passes.
    """
    if limits.no_jump_factor is not None:
        section = spec.valves[design.name]
        rated = spec.engine.rated_speed_rpm
        top = max(limits.no_jump_factor, SPEED_RANGE[1]) * rated
        dyn = section.dynamics or Dynamics(speeds=FINAL_SPEEDS)
        low, high = dyn.speed_range_rpm or (SPEED_RANGE[0] * rated, top)
        dyn = dyn.model_copy(update={"speed_range_rpm": [low, max(high, top)]})
        result, _ = dynamics_stage(si(dyn), si(section, spec), si(spec.engine), design.law, design.drive,
                                   design.name, cam=design.cam)
        design = replace(design, dynamics=result)
    out = constraints(design, limits, si(spec.valves[design.name], spec))
    if search_spring is not None:
        held = note("synthesis.start_spring_scaled", scale=scale) if scale != 1.0 else note("synthesis.start_spring")
        out.append(replace(spring_reserve(design, limits.min_spring_reserve * scale, search_spring.preload * scale,
                                          search_spring.rate * scale), note=note_text(held), note_parts=held))
    same = {(c.code, c.params, c.low, c.high) for c in out}
    own = [c for c in design.checks if c.severity == "failure" and not c.accepted
           and (c.code, c.params, c.low, c.high) not in same]
    return out + own


def _comparison(start, end, objective, start_value, value):
    """Rows (quantity, unit, start, optimum) of two full designs, in the display units; an objective of
    :data:`BREATHING` first, ``start_value`` and ``value`` (SI)."""
    def rows(d):
        c, f = d.cam, d.flow
        out = [("fullness", "", f.fullness), ("time-area of the whole opening", "mm2 s", f.time_area_open),
               ("time-area over the valve's stroke", "mm2 s", f.time_area),
               ("max tappet acceleration", "m/s2", c.max_acceleration),
               ("min tappet acceleration", "m/s2", c.min_acceleration),
               ("max tappet velocity", "m/s", c.max_velocity),
               ("spring preload", "N", d.drive.spring.preload), ("spring rate", "N/mm", d.drive.spring.rate),
               ("spring reserve K_z", "", d.drive.spring.spring_reserve)]
        if d.profile.rho_min is not None:
            out.append(("rho_min", "mm", d.profile.rho_min))
        if d.records.power_polynomial is not None:
            out.insert(1, ("tappet fullness (UkrSURT Proceedings (2019))", "", d.records.power_polynomial.tappet_fullness))
        return out
    head = [(OBJECTIVES[objective][2], OBJECTIVES[objective][1], start_value, value)] if objective in BREATHING else []
    return [(q, u, to_display(a, u), to_display(b, u)) for q, u, a, b in head] + [
        (q, u, to_display(a, u), to_display(b, u)) for (q, u, a), (_, _, b) in zip(rows(start), rows(end), strict=True)]


def _inside(x, bounds):
    """``x`` moved into the bounds, a hair inside them (the optimiser's own scaling must find it within)."""
    low, high = (np.array(b, dtype=float) for b in zip(*bounds, strict=True))
    return low + (high - low) * np.clip((np.asarray(x, dtype=float) - low) / (high - low), 1e-9, 1.0 - 1e-9)


def optimize_valve(spec, valve=None, variables=None, objective="fullness", wheel_radius=None, no_jump_factor=None,
                   seed=1, maxiter=60, popsize=12, progress=None, cam_width=None, seating_velocity=None) -> Result:
    """Maximise the fullness or the time-area of one valve's cam under its limits.

    Parameters
    ----------
    spec : valvetrain.specification.Spec
    valve : str, optional
        The valve's name (default: the first).
    variables : list of Variable, optional
        Default :func:`default_variables` of the valve's law.
    objective : str
        A name of :data:`OBJECTIVES`: the fullness, the time-area, or the breathing's volumetric efficiency or
        torque (fired), each the mean over the conditions and the curve speeds of ``[breathing]``
        (:data:`BREATHING`; no local polish then: the converged cycles' objective has no useful finite-difference
        gradient).
    wheel_radius : float, optional
        Grinding wheel radius [m] for the concave radius of a roller follower's cam (default: the valve's
        ``[grinding]`` section's, else none).
    no_jump_factor : float, optional
        No follower separation up to this multiple of the rated speed (None: no dynamics in the search).
    seed, maxiter, popsize : int
        Of :func:`scipy.optimize.differential_evolution` (deterministic for a seed).
    progress : callable, optional
        ``progress(generation, best objective)`` after each generation.
    cam_width : float, optional
        Cam width of the Hertz stress [m]; default ``parts.cam_width_mm``, else :data:`CAM_WIDTH_TO_BASE_RADIUS` x
        the base radius.
    seating_velocity : float, optional
        Largest valve seating velocity [m/s] (kinematic in the search; the dynamics sweep's too in the final check).

    Returns
    -------
    Result
        With ``spec_text``, the specification with the optimum's keys (TOML).  The optimum is the best point
        evaluated whose full design meets every limit, the start included; where none does, ``feasible`` is False
        and ``checks`` name what fails at the point nearest to the limits.

    Raises
    ------
    ValueError
        A specification without valves, an unknown valve or objective, a law without variables, a variable that is
        not a key of the valve, a key named twice, bounds outside the key's allowed range.
    """
    if objective not in OBJECTIVES:
        raise InputError(f"optimize: objective = {objective!r}; allowed {', '.join(OBJECTIVES)}")
    if not spec.valves:
        raise InputError("optimize: the specification has no [valves.NAME] section: no cam to optimise; allowed a "
                         "file with at least one valve")
    if valve is None:
        valve = next(iter(spec.valves))
    if valve not in spec.valves:
        raise InputError(f"optimize: --valve {valve!r}; allowed {', '.join(spec.valves)}")
    if objective in BREATHING:
        check_breathing_objective(spec, valve, objective)
    section = spec.valves[valve]
    variables = unique_variables(default_variables(section, spec.engine) if variables is None else variables)
    check_bounds(section, valve, variables)
    t0 = time.perf_counter()
    results = run_design(spec)
    design = results.valves[valve]
    ramp = any(v.path.startswith("cam.ramp_end_velocity") for v in variables)
    limits, notes = design_limits(design, wheel_radius, no_jump_factor, ramp,
                                  cam_width or si(section, spec).parts.cam_width, seating_velocity,
                                  spec.engine.over_speed_ratio, si(section, spec))
    problem = Problem(spec, design, variables, limits, objective,
                      breathing_objective(spec, results) if objective in BREATHING else None)
    start_value = problem.evaluate(problem.x0, dynamics=True)[0]
    scale0 = start_value or 1.0
    generation = [0]

    def population(xs):
        return problem.penalised_many(np.asarray(xs).T, scale0)

    def callback(xk, convergence=None):
        generation[0] += 1
        if progress is not None:
            progress(generation[0], problem.evaluate(xk)[0])

    found = optimize.differential_evolution(population, problem.bounds, seed=seed, maxiter=maxiter, popsize=popsize,
                                            tol=1e-7, polish=False, callback=callback, vectorized=True,
                                            updating="deferred", x0=_inside(problem.x0, problem.bounds))
    candidates = problem.candidates()
    if candidates and objective not in BREATHING:   # the breathing's cycles converge to a tolerance: no gradient
        origin = candidates[0][1]
        held = problem.evaluate(origin, dynamics=True)[1]

        def polish_margins(x):
            """The margins less :data:`POLISH_RESERVE`, the separation's held at the polish's origin (the final
            design's sweep checks it)."""
            margins = problem.evaluate(x, dynamics=False)[1]
            return np.where(np.isnan(margins), held, margins) - POLISH_RESERVE

        local = optimize.minimize(lambda x: -problem.evaluate(x, dynamics=False)[0] / scale0, origin,
                                  method="SLSQP", bounds=problem.bounds,
                                  constraints=({"type": "ineq", "fun": polish_margins},),
                                  options={"maxiter": POLISH_ITERATIONS, "ftol": 1e-10})
        problem.evaluate(local.x)
    spring = None if any(v.path == "drive.spring_reserve" for v in problem.variables) else design.drive.lines.chosen
    checks_start = final_checks(design, spec, limits, 1.0, spring) + (
        breathing_failures(results) if objective in BREATHING else [])
    start = (problem.x0, spec, design, checks_start,
             optimum_spec_text(spec, valve, problem.data, dict(zip((v.path for v in variables), problem.x0))),
             objective_value(results, valve, objective))
    chosen, nearest = _best_designed(problem, spec, valve, limits, spring,
                                     start_value if _passed(checks_start) else None)
    if chosen is None:
        chosen = start if _passed(checks_start) else (
            nearest or _designed(problem, spec, valve, limits, spring, found.x) or start)
    x, optimum_spec, checked, checks, text, value = chosen
    margins = problem.evaluate(x, dynamics=True)[1]
    values = {v.path: float(value) for v, value in zip(problem.variables, x, strict=True)}
    reference = polydyne_fullness(checked.law) if checked.law.name == "power_polynomial" else None
    return Result(
        valve, objective, {v.path: float(value) for v, value in zip(problem.variables, problem.x0, strict=True)},
        values, start_value, value, problem.bounds, problem.names,
        dict(zip(problem.names, map(float, margins), strict=True)), problem.evaluations, time.perf_counter() - t0,
        problem.seconds, notes, _comparison(design, checked, objective, start[5], value), checks_start, checks, list(problem.history), reference,
        text, problem.law_samples, problem.simulations)


def _passed(checks):
    return all(c.passed for c in checks)


def _designed(problem, spec, valve, limits, spring, x):
    """(x, specification, full design, final checks, specification text, objective as ``run`` computes it) of a
    point, or None where the point admits no full design (no spring fits, a law the design refuses)."""
    from ..specification.reading import parse_spec

    values = {v.path: float(value) for v, value in zip(problem.variables, x, strict=True)}
    text = optimum_spec_text(spec, valve, problem.point(x), values)
    try:
        optimum_spec = parse_spec(text)
        results = run_design(optimum_spec)
    except (SpecError, ValueError):
        return None
    checked = results.valves[valve]
    scale = optimum_spec.valves[valve].drive.spring_reserve / problem.reserve0
    checks = final_checks(checked, optimum_spec, limits, scale, spring) + (
        breathing_failures(results) if problem.objective in BREATHING else [])
    return x, optimum_spec, checked, checks, text, objective_value(results, valve, problem.objective)


def _best_designed(problem, spec, valve, limits, spring, floor):
    """The best of the search's candidates (:meth:`Problem.candidates`) whose full design meets every limit, each better
    than ``floor`` (the start's objective where the start meets every limit, else None), trying at most
    :data:`FINAL_CANDIDATES`; after one fails, only a point whose worst margin of the search is larger is tried:
    (found or None, the first point tried that admits a full design or None)."""
    tried, nearest, worst = 0, None, -math.inf
    for value, x, least in problem.candidates():
        if tried == FINAL_CANDIDATES or (floor is not None and value <= floor):
            break
        if least <= worst:
            continue
        tried += 1
        found = _designed(problem, spec, valve, limits, spring, x)
        if found is not None and _passed(found[3]):
            return found, found
        nearest, worst = nearest or found, least
    return None, nearest


def optimum_spec_text(spec, valve, section, values) -> str:
    """The specification file of ``spec`` with the valve section ``section`` (dict) of the optimum (TOML text).

    The specification is written back from its validated keys (those the user gave), so ``valvetrain run``
    reads it as the original with the optimum's keys.
    """
    import tomli_w

    data = spec.model_dump(mode="json", exclude_unset=True, exclude_none=True)
    data["valves"][valve] = section
    shown = ", ".join(f"{k} = {v:.6g}" for k, v in values.items())
    head = (f"# The optimum of valvetrain optimize for valve {valve!r}: {shown}.\n"
            "# Method: differential evolution and a local polish under the design's limits (UkrSURT Proceedings "
            "(2019); Shang Hanji (1988), section 4.3).\n\n")
    text = head + tomli_w.dumps(data)
    tomllib.loads(text)
    return text
