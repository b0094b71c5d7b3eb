"""Cam synthesis by optimisation: the parameters of a valve's parametric lift law that maximise its fullness or
its time-area under the design's limits, the dynamics among them.

The variables are keys of the valve's specification (:class:`Variable`, a path under ``[valves.NAME]``): the
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
start in its first population and the margins as an exact penalty (:data:`PENALTY`), then a local polish with SLSQP,
the margins as constraints, from its best point, as the method's article does (UkrSURT Proceedings (2019); Shang
Hanji (1988), section 4.3).  The result is the best point evaluated that meets every limit in full: the points that
met every margin of the search are designed in full (their own spring, a dynamics sweep), best first, until one meets
every constraint (:func:`final_checks`); the start is one of them, so the optimum is never worse than a start that
meets every limit.  Where no point does, the result says so (:attr:`Result.feasible`) with the limits that fail.
"""

import copy
from dataclasses import dataclass, field, replace
import difflib
import math
import time
import tomllib

import numpy as np
from pydantic import BaseModel, ValidationError
from scipy import optimize

from .. import flow, springs
from ..breathing import BreathingError
from ..checks import Check
from ..design import breathing_view, run as run_design
from ..design.breathing import breathe_conditions, breathing_conditions, breathing_engine, speed_mean
from ..design.drive import spring_options
from ..design.dynamics import SPEED_RANGE, build_train, dynamics_stage
from ..design.valve import MAX_LIFT_TO_THROAT, follower_travel_acceleration
from ..dynamics.models import one_mass_train
from ..dynamics.sweep import sweep
from ..errors import InputError
from ..locale import record_text
from ..laws import PolydyneLaw
from ..laws.base import batch_derivatives, member_values, valve_lift_of
from ..laws.kurz import RAMP_VELOCITY_RANGE_MM_PER_DEG
from ..specification import SpecError
from ..layouts import finger_inertia_force, train_mass
from ..specification.models import Dynamics, Valve
from ..specification.si import si
from ..units import DEG, cam_per_crank, to_display
from .constraints import Limits, constraints, spring_reserve, worst_cam_force

OBJECTIVES = {
    "fullness": ("fullness", "", "fullness of the valve lift diagram (Shang Hanji (1988), eq. 2.3)"),
    "time_area": ("time_area_open", "mm2 s", "time-area of the valve's whole opening"),
    "volumetric_efficiency": ("volumetric_efficiency", "", "volumetric efficiency, the mean over the breathing's "
                              "conditions and curve speeds"),
    "torque": ("torque", "N m", "indicated torque of the fired engine, the mean over the breathing's conditions and "
               "curve speeds"),
}
"""Objective name -> (field of the flow stage's result, or of the breathing's records for :data:`BREATHING`,
display unit, what it is)."""

BREATHING = ("volumetric_efficiency", "torque")
"""The objectives of the breathing (:mod:`valvetrain.design.breathing`): the mean of a figure of its converged cycles
over every condition and curve speed of ``[breathing]``, each weighing the same."""


def objective_value(results, valve, objective) -> float:
    """An objective of :data:`OBJECTIVES` as ``valvetrain run`` computes it (``results``, a
    :class:`~valvetrain.design.DesignResults`), for the valve named ``valve``."""
    if objective in BREATHING:
        return speed_mean(results.breathing.conditions + results.breathing.curve, OBJECTIVES[objective][0])
    return float(getattr(results.valves[valve].flow, OBJECTIVES[objective][0]))


@dataclass(frozen=True)
class BreathingObjective:
    """What a cam synthesis by the breathing holds fixed: the SI views of ``[breathing]`` (its files read), of
    ``[engine]`` and ``[crank]`` (or None), the starting design's valves and their SI views, and the conditions and
    curve speeds (:func:`~valvetrain.design.breathing.breathing_conditions`)."""

    view: object
    engine: object
    crank: object
    valves: dict
    views: dict
    conditions: tuple

    def value(self, name, figure, law, valve) -> float:
        """The mean of the breathing's ``figure`` over the conditions with the valve ``name`` lifted by ``law`` (its
        SI view ``valve``), every other valve the start's: the valve's design with that law and nose in its cam
        stage gives the breathing its lift (:attr:`~valvetrain.design.valve.ValveDesign.cycle_lift`), as ``run``
        does; 0 where the cycle leaves the physical range (:class:`~valvetrain.breathing.BreathingError`)."""
        start = self.valves[name]
        cam = replace(start.cam, law=law, nose=valve.cam.section.nose_crank(valve, law),
                      rocker_ratio=valve.rocker_ratio)
        engines = breathing_engine(self.view, self.engine, self.crank, {**self.valves, name: replace(start, cam=cam)},
                                   {**self.views, name: valve}, [c for part in self.conditions for c in part])[0]
        try:
            conditions, curve = breathe_conditions(engines, self.view, *self.conditions)
        except BreathingError:
            return 0.0
        return speed_mean(conditions + curve, figure)


def check_breathing_objective(spec, valve, objective) -> None:
    """Refuse an objective of :data:`BREATHING` that the specification cannot give for the valve named ``valve``.

    Raises
    ------
    ValueError
        No ``[breathing]`` section; ``torque`` of a motored breathing; the valve's side lifted by a measured
        ``lift_file`` (the cam would not move the breathing): the message names the key.
    """
    if spec.breathing is None:
        raise InputError(f"optimize: --objective {objective} needs a [breathing] section (its conditions or curve "
                         "give the speeds); allowed without it: fullness, time_area")
    if objective == "torque" and spec.breathing.mode != "fired":
        raise InputError(f"optimize: --objective torque needs breathing.mode = 'fired' (the file's is "
                         f"{spec.breathing.mode!r}: a motored engine gives no torque); allowed volumetric_efficiency")
    kind = spec.valves[valve].kind
    if getattr(spec.breathing, kind).lift_file is not None:
        raise InputError(f"optimize: --objective {objective}: breathing.{kind}.lift_file lifts the {kind} valves by a "
                         f"measured table, so valve {valve!r}'s cam does not move the breathing; allowed without "
                         "lift_file (the designed valves' lift)")


def breathing_objective(spec, results) -> BreathingObjective:
    """The :class:`BreathingObjective` of a specification and its starting design ``results``."""
    view = breathing_view(spec)
    views = {name: si(section, spec) for name, section in spec.valves.items()}
    crank = None if spec.crank is None else si(spec.crank, spec)
    return BreathingObjective(view, si(spec.engine), crank, dict(results.valves), views,
                              breathing_conditions(view))


def shown_objective(objective, value) -> float:
    """An objective's value (SI) in its display unit (:data:`OBJECTIVES`)."""
    return to_display(value, OBJECTIVES[objective][1])


GRID = 1201
"""Camshaft angles of the opening flank (of the whole event for a cam with a closing flank of its own) on which one
evaluation samples the law."""

REFINE = 65
"""Camshaft angles of each window, between the neighbours of a sampled extreme, on which one evaluation samples the
law again: the extremes are those of the contour to 1/32 of the grid's step."""

POLISH_RESERVE = 1e-5
"""Relative margin the local polish keeps from every limit (the full design's extremes, refined to round-off, may lie
that far beyond the search's)."""

RELAXED = 1e-6
"""Relative room a limit relaxed to the start's value leaves beyond it (the search's extremes and the full design's
agree to about this, so that the start itself meets the limit in both)."""

FINAL_CANDIDATES = 4
"""Points that met every margin of the search designed in full at most, best first, before the start is taken."""

NEAR = 0.01
"""Summed relative violations of the other limits up to which a point's follower separation is simulated (beyond,
its penalty of :data:`PENALTY` times them already ranks it below any candidate of the search)."""

SPRING_SLACK = 0.1
"""How far below 0 the spring design's margin of the search (a conservative closed form) may lie for a point to be
designed in full: the final spring search decides."""

CAM_WIDTH_TO_BASE_RADIUS = 0.5
"""The cam width of the Hertz stress where ``parts.cam_width_mm`` is not given, as a fraction of the base radius r0:
a narrow cam, so that the stress is not understated (a configurable default; no primary source states it)."""

SPEEDS = (1.0,)
"""Engine speeds, fractions of the rated speed, at which one evaluation simulates the train (with the limit's own
multiple of the rated speed); the final check sweeps the whole range."""

FINAL_SPEEDS = 60
"""Speeds of the final check's dynamics sweep."""

PENALTY = 10.0
"""Weight of the summed constraint violations (relative margins below 0) against the objective over its starting
value in the global search (an exact penalty: a feasible point always beats a point that violates a limit by more
than a tenth of the objective's range)."""

FRONTIER_RANGE = (0.5, 3.0)
"""Factors on the starting design's required spring force between which the spring frontier is searched."""

FRONTIER_TOLERANCE = 2e-3
"""Width of the bisection bracket of the spring frontier (its lower end is used: on the side where a spring passes)."""

SPRING_ITERATIONS = 4
"""Spring searches of one evaluation at most while the reduced mass settles on the found spring's mass."""

START_SPRING = "with the starting design's spring"
"""The note of the spring reserve checked with the spring the search held."""

POLISH_ITERATIONS = 60
"""Iterations of the SLSQP polish at most (from a feasible point it converges in about 20)."""

BINDING = 1e-3
"""A constraint whose relative margin at the optimum is below this binds."""


@dataclass(frozen=True)
class Variable:
    """One design variable: a numeric key under ``[valves.NAME]`` and its bounds (the key's own unit).

    ``path`` is dotted, list entries by their 1-based position: ``cam.phi1_deg``, ``drive.spring_reserve``,
    ``cam.ratios.2.value``.
    """

    path: str
    low: float
    high: float
    written: tuple = field(default=None, compare=False)
    """LOW and HIGH as the user wrote them (for messages)."""

    def put(self, data, value) -> None:
        """Set the variable in a valve section's data (dict, changed in place)."""
        *parents, last = self.path.split(".")
        node = data
        for part in parents:
            node = node[int(part) - 1] if isinstance(node, list) else node.setdefault(part, {})
        if isinstance(node, list):
            node[int(last) - 1] = value
        else:
            node[last] = value


def _ramp_and_spring(cam):
    """The ramp end velocity within its band (Valve-train practical works (n.d.), eq. 2.1) and the spring reserve
    K_z within its band (eq. 5.3)."""
    out = [Variable("drive.spring_reserve", *springs.SPRING_RESERVE_RANGE)]
    if getattr(cam, "ramp_end_velocity_mm_per_deg", None) is not None:
        out.insert(0, Variable("cam.ramp_end_velocity_mm_per_deg", *RAMP_VELOCITY_RANGE_MM_PER_DEG))
    return out


def default_variables(valve, engine) -> list[Variable]:
    """The default design variables of a valve's cam law (a list of :class:`Variable`).

    Parameters
    ----------
    valve, engine : the specification's ``[valves.NAME]`` and ``[engine]`` sections.

    Returns
    -------
    list of Variable
        Kurz: phi1, phi2, shape factor Z; constant acceleration: phi1, phi2, kappa; polydyne: the exponents the
        cam gives; combined: the ratios' values; each with the ramp end velocity (0.008-0.022 mm/deg) and the
        spring reserve K_z (1.5-2.25).  The power polynomial: a_qd, phi_1, x_d, x_g (its article holds the spring
        and the ramp).

    Raises
    ------
    ValueError
        A law without parameters to vary (a measured table, three arcs), or an asymmetric cam.

    Notes
    -----
    Each cam model gives its law's own (:meth:`search_variables` of :mod:`valvetrain.specification.cams`).
    """
    cam = valve.cam
    if getattr(cam, "closing", None) is not None:
        raise InputError("optimize: the cam has a [cam.closing] flank of its own; name the variables with --vary")
    own = cam.search_variables(valve, engine)
    if own is None:
        raise InputError(f"optimize: law = {cam.law!r} has no default variables; name them with --vary KEY=LOW,HIGH "
                         "(e.g. --vary cam.nose_radius_mm=5,12)")
    out = [Variable(*v) for v in own]
    return out + _ramp_and_spring(cam) if cam.varies_ramp_and_spring else out


def parse_variables(items) -> list[Variable]:
    """Variables from ``KEY=LOW,HIGH`` texts (``cam.phi1_deg=20,35``).

    Raises
    ------
    ValueError
        A text that is not of that form, LOW >= HIGH, or a key named twice; the message names the text.
    """
    out = []
    for item in items:
        key, sep, bounds = item.partition("=")
        parts = bounds.split(",")
        try:
            low, high = (float(p) for p in parts) if sep and len(parts) == 2 else (None, None)
        except ValueError:
            low = high = None
        if not key.strip() or low is None or not (math.isfinite(low) and math.isfinite(high) and low < high):
            raise InputError(f"--vary {item[:80]!r}: allowed KEY=LOW,HIGH with finite LOW < HIGH, KEY a path under "
                             "[valves.NAME] such as cam.phi1_deg")
        out.append(Variable(key.strip(), low, high, tuple(p.strip() for p in parts)))
    return unique_variables(out)


def unique_variables(variables) -> list[Variable]:
    """``variables`` (a list of :class:`Variable`) with each key once.

    Raises
    ------
    ValueError
        A key named twice.
    """
    seen = set()
    for v in variables:
        if v.path in seen:
            raise InputError(f"--vary {v.path}: the key is named twice; allowed once, with one LOW,HIGH")
        seen.add(v.path)
    return list(variables)


def numeric_keys(section) -> list[str]:
    """The dotted paths of the numbers of a valve's section (``cam.phi1_deg``, ``drive.spring_reserve``), given or
    defaults, list entries by their 1-based position: what ``--vary`` may name."""
    out = []

    def walk(node, prefix):
        if isinstance(node, BaseModel):
            node = {k: getattr(node, k) for k in type(node).model_fields}
        if isinstance(node, dict):
            for k, v in node.items():
                walk(v, f"{prefix}{k}.")
        elif isinstance(node, list):
            for i, v in enumerate(node, start=1):
                walk(v, f"{prefix}{i}.")
        elif isinstance(node, (int, float)) and not isinstance(node, bool):
            out.append(prefix[:-1])

    walk(section, "")
    return out


def unknown_key(path, name, section) -> str:
    """The message of a ``--vary`` key that the valve's section does not have, with the nearest of its numbers."""
    keys = numeric_keys(section)
    near = difflib.get_close_matches(path, keys, n=2, cutoff=0.6) or [k for k in keys if k.endswith(f".{path}")][:2]
    return (f"--vary {path}: valves.{name}.{path} is no key of the valve (unknown key)"
            + (f"; did you mean {' or '.join(near)}?" if near else "; name a number under [valves.NAME], such as "
               "cam.phi1_deg or drive.spring_reserve"))


def check_bounds(section, name, variables) -> None:
    """Refuse bounds of a variable outside the allowed range of its key.

    Parameters
    ----------
    section : valvetrain.specification.models.Valve
        The valve's section.
    name : str
        The valve's name.
    variables : list of Variable

    Raises
    ------
    ValueError
        A bound that the key's own validation refuses, naming the bound as written and the key's allowed range.
    """
    data = section.model_dump(mode="json", exclude_unset=True, exclude_none=True)
    for v in variables:
        for i, (which, value) in enumerate((("LOW", v.low), ("HIGH", v.high))):
            trial = copy.deepcopy(data)
            try:
                v.put(trial, value)
                Valve.model_validate(trial)
            except (IndexError, TypeError):
                break  # not a key of the section: Problem names it
            except ValidationError as exc:
                for e in exc.errors():
                    at = ".".join(str(part + 1) if isinstance(part, int) else str(part) for part in e["loc"])
                    if at == v.path and e["type"] == "extra_forbidden":
                        raise InputError(unknown_key(v.path, name, section)) from None
                    if at == v.path:
                        written = v.written or (f"{v.low:g}", f"{v.high:g}")
                        reason = e["msg"].removeprefix("Value error, ")
                        raise InputError(f"--vary {v.path}={','.join(written)}: {which} = {written[i]} is outside "
                                         f"the range of valves.{name}.{v.path}: {reason}") from None


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


class Problem:
    """The fast evaluation of one valve's design variables: the objective and the constraint margins.

    Parameters
    ----------
    spec : valvetrain.specification.Spec
    design : ValveDesign
        The starting design of the valve (its train and spring are those of the search).
    variables : list of Variable
    limits : Limits
    objective : str
        A name of :data:`OBJECTIVES`.
    breathing : BreathingObjective, optional
        Required for the objectives of :data:`BREATHING`.

    Notes
    -----
    One evaluation samples the law twice (:data:`GRID` angles, then :data:`REFINE` around each extreme) and
    integrates the objective by the flow module's quadrature (an objective of the breathing: the cycles converged at
    each of its speeds, :meth:`BreathingObjective.value`); ``evaluations``, ``seconds`` and ``law_samples`` (the
    angles at which the law was evaluated, the quadrature's nodes not counted) measure its cost.  A population is
    evaluated as one batch (:meth:`evaluate_many`): each point's law is built on its own, then all are sampled on
    their own grids in one call (:func:`~valvetrain.laws.base.batch_derivatives`), their quantities and least values
    found together and their objectives integrated in one quadrature; each point's numbers are those of evaluating it
    alone.
    """

    def __init__(self, spec, design, variables, limits, objective="fullness", breathing=None):
        self.name, self.variables, self.limits, self.objective = design.name, list(variables), limits, objective
        self.breathing = breathing
        self.spec, self.engine = spec, si(spec.engine)
        self.section = spec.valves[self.name]
        self.data = self.section.model_dump(mode="json", exclude_unset=True, exclude_none=True)
        self.x0 = np.array([self._value(v) for v in self.variables], dtype=float)
        self.bounds = [(v.low, v.high) for v in self.variables]
        self.reserve0 = self.section.drive.spring_reserve
        self.follower = design.cam.follower_model
        self.heel, self.i_k, self.omega = design.cam.heel_radius, design.cam.rocker_ratio, design.cam.cam_speed
        self.whole_event = getattr(self.section.cam, "closing", None) is not None
        self.mass = design.drive.masses.at_valve
        self.spring = design.drive.lines.chosen
        self.valve = si(self.section, self.spec)
        self.parts = {v.path.split(".")[0] for v in self.variables}
        self.spring_inputs = (self.valve.throat_diameter, spring_options(self.valve.spring),
                              max(design.drive.spring.gas_force, design.drive.spring.seat_load))
        self.law0, self.frontier = design.law, None
        self._train_parameters(design)
        self.names = self.margin_names()
        self.jump = self.names.index("no jump") if "no jump" in self.names else None
        self.evaluations, self.seconds, self.law_samples, self.simulations, self.best = 0, 0.0, 0, 0, -math.inf
        self.history, self.points = [], []
        self._cache, self._grid_kept = {}, (None, None, None)

    def _value(self, v):
        """The variable's value in the specification (given or the key's default).

        Raises
        ------
        ValueError
            The path names no numeric key of the valve's section.
        """
        node = self.section
        try:
            for part in v.path.split("."):
                node = node[int(part) - 1] if isinstance(node, list) else getattr(node, part)
        except (AttributeError, IndexError, ValueError):
            node = None
        if isinstance(node, bool) or not isinstance(node, (int, float)):
            raise InputError(f"optimize: valves.{self.name}.{v.path} is not a numeric key of the valve; allowed the "
                             "numbers of [valves.NAME] and its sections (cam.phi1_deg, drive.spring_reserve, ...)")
        return float(node)

    def _train_parameters(self, design):
        """The one-mass train of the search: the valve's [dynamics] section's (or the defaults'), a finger's mass
        changing with the lift (:func:`~valvetrain.design.dynamics.build_train`)."""
        self.speeds = None
        if self.limits.no_jump_factor is None:
            return
        dyn = self.section.dynamics or Dynamics()
        rated = self.engine.rated_speed * cam_per_crank(self.engine.strokes)
        train, self.train_parameters = build_train(si(dyn.model_copy(update={"model": "1dof"})), self.valve,
                                                   design.law, design.drive, f"valves.{self.name}", rated)
        self.variable_mass = train.variable_mass
        self.speeds = rated * np.unique(np.array(SPEEDS + (self.limits.no_jump_factor,)))

    def margin_names(self) -> list[str]:
        """Names of the entries of :meth:`evaluate`'s margins."""
        L = self.limits
        names = ["spring reserve"]
        if self.follower.rolling:
            names += ["pressure angle"] + (["concave radius"] if L.grinding_wheel_radius else [])
        names += [n for n, lim in (("rho_min", L.min_rho), ("contact stress", L.cam_width),
                                   ("max acceleration", L.max_acceleration), ("min acceleration", L.min_acceleration),
                                   ("seating velocity", L.seating_velocity)) if lim is not None]
        if self.speeds is not None:
            names.append("no jump")
        return names + ["spring design"]

    def point(self, x) -> dict:
        """The valve section's data with the variables ``x`` (the start's data, the parts the variables change
        copied)."""
        data = {**self.data, **{p: _copied(self.data[p]) for p in self.parts if p in self.data}}
        for v, value in zip(self.variables, x, strict=True):
            v.put(data, float(value))
        cam = data["cam"]
        for key, sources in self.section.cam.derived_keys.items():
            if any(v.path in sources for v in self.variables):
                cam.pop(key, None)
        return data

    def law(self, x) -> tuple | None:
        """(law, SI valve, spring scale K_z / K_z,0) of the variables, or None where they admit no law."""
        data = self.point(x)
        try:
            section = Valve.model_validate(data)
        except ValidationError:
            return None
        if section.cam.problems(f"valves.{self.name}", section, self.spec.engine):
            return None
        try:
            valve = self._si(section)
            law = valve.cam.section.build(valve, self.engine)
        except ValueError:
            return None
        if not law.end - law.start < 2.0 * np.pi or law.lift_max * valve.rocker_ratio > (
                MAX_LIFT_TO_THROAT * valve.throat_diameter):
            return None
        return law, valve, section.drive.spring_reserve / self.reserve0

    def _si(self, section):
        """The SI view of a point's valve section: the start's, with the sections that the variables change made
        anew (the whole view where a variable is a key of the valve itself)."""
        if any(not isinstance(getattr(section, p), BaseModel) for p in self.parts):
            return si(section, self.spec)
        return replace(self.valve, section=section, **{p: si(getattr(section, p), self.spec) for p in self.parts})

    def _angles(self, law):
        """The grid of one evaluation and the law's junctions on it [rad from the nose]."""
        end = law.end if self.whole_event else 0.0
        bp = law.breakpoints
        return np.unique(np.concatenate([self._grid(law.start, end), bp[(bp > law.start) & (bp < end)],
                                         [law.valve_opens], [law.valve_closes] if self.whole_event else []]))

    def _grid(self, start, end):
        """:data:`GRID` angles from ``start`` to ``end`` [rad], kept for the next law with the same event (the laws of
        a search share it where no variable changes the event's angles)."""
        if self._grid_kept[:2] != (start, end):
            self._grid_kept = (start, end, np.linspace(start, end, GRID))
        return self._grid_kept[2]

    def _quantities(self, laws, theta, member, scales):
        """Each sampled quantity as one to minimise at the angles ``theta`` of the laws ``laws[member]`` at K_z =
        ``scales[member]`` x K_z,0, and (h, dh, d2h) there."""
        L = self.limits
        h, dh, d2h, _ = batch_derivatives(laws, theta, member)
        self.law_samples += theta.size
        ramp = member_values([law.ramp_height for law in laws], member)
        y = self.i_k * np.clip(h - ramp, 0.0, None)
        spring = scales[member] * self.spring.force(y)
        finger = finger_inertia_force(self.valve, self.heel, h, dh, d2h)
        inertia = np.clip(-(self.mass * self.i_k * self.omega**2 * d2h + self.omega**2 * finger), 0.0, None)
        loaded = (inertia > 0.0) & (y > 0.0)
        nose = member_values([law.lift_max + law.ramp_height for law in laws], member)
        acc = follower_travel_acceleration(self.follower, self.heel, h, dh, d2h)
        q = {"spring reserve": np.where(loaded, spring / np.where(loaded, inertia, 1.0), np.inf),
             "lift": h / nose, "overshoot": -h / nose,
             "max acceleration": -acc, "min acceleration": acc}
        rho = self.follower.curvature(self.heel, h, dh, d2h)
        if self.follower.rolling:
            q["pressure angle"] = -np.abs(self.follower.pressure_angle(self.heel, h, dh))
            q["concave radius"] = np.where(rho < 0.0, 1.0 / np.where(rho < 0.0, rho, -1.0), 0.0)
        q["rho_min"] = self.follower.convex_radius(rho)
        if L.cam_width is not None:
            top = (self.omega * L.top_speed)**2
            force = worst_cam_force(spring, self.mass, self.i_k, top * d2h, top * finger)
            at_cam = force * self.follower.force_ratio(self.heel, h, dh)
            q["contact stress"] = -self.follower.contact_stress(at_cam, rho, L.cam_width, L.contact_modulus)
        return q, h, dh, d2h

    def _extremes(self, laws, scales):
        """Per law of ``laws`` (at K_z = ``scales`` x K_z,0): the least value of each quantity of :meth:`_quantities`
        on the grid refined around its least sample (:data:`REFINE` angles between the neighbours), the grid's
        (theta, h, dh, d2h) and |dh/dtheta| [m/rad] at the valve's opening and closing; all laws sampled together."""
        theta, member, starts = _ragged([self._angles(law) for law in laws])
        q, h, dh, d2h = self._quantities(laws, theta, member, scales)
        least = {k: _least(v, starts) for k, v in q.items()}
        ends = np.append(starts[1:], theta.size)
        windows = []
        for i, (a, b) in enumerate(zip(starts, ends, strict=True)):
            at = a + np.array(sorted({int(first[i]) for _, first in least.values()}))
            windows.append(np.linspace(theta[np.maximum(at - 1, a)], theta[np.minimum(at + 1, b - 1)], REFINE,
                                       axis=1).ravel())
        fine, fine_member, fine_starts = _ragged(windows)
        fine_least = {k: _least(v, fine_starts)[0] for k, v in self._quantities(laws, fine, fine_member,
                                                                                  scales)[0].items()}
        out = []
        for i, (law, a, b) in enumerate(zip(laws, starts, ends, strict=True)):
            t = theta[a:b]
            seat = np.abs(dh[a:b][np.searchsorted(t, [law.valve_opens, law.valve_closes if self.whole_event else
                                                      law.valve_opens])])
            out.append(({k: min(float(least[k][0][i]), float(fine_least[k][i])) for k in q}, t, h[a:b], dh[a:b],
                        d2h[a:b], seat))
        return out

    def _objectives(self, laws, valves):
        """The objective of :data:`OBJECTIVES` of each law as the flow stage computes it, all quadratures at once (an
        objective of the breathing as its stage computes it, law by law)."""
        if self.objective in BREATHING:
            return [self.breathing.value(self.name, OBJECTIVES[self.objective][0], law, valve)
                    for law, valve in zip(laws, valves, strict=True)]
        ramp = np.array([law.ramp_height for law in laws])
        rocker = np.array([valve.rocker_ratio for valve in valves])
        opens, closes = (np.array([getattr(law, k) for law in laws]) for k in ("valve_opens", "valve_closes"))
        bp = [law.breakpoints for law in laws]

        def valve_lift(t, member):
            return valve_lift_of(batch_derivatives(laws, t, member)[0], ramp[member], rocker[member], self.follower)

        if self.objective == "fullness":
            return flow.fullnesses(valve_lift, opens, closes, rocker * np.array([law.lift_max for law in laws]), bp)
        throat, seat = (np.array([getattr(valve, k) for valve in valves]) for k in ("throat_diameter", "seat_angle"))
        return flow.time_areas(lambda t, member: flow.curtain_area(valve_lift(t, member), throat[member], seat[member]),
                               opens, closes, self.omega, bp)

    def evaluate(self, x, dynamics=None) -> tuple[float, np.ndarray]:
        """(objective, margins) of the variables; a point that admits no design has objective 0 and margins -1.

        The follower separation is simulated (``dynamics`` None) only where it can matter: until a candidate is found
        (:meth:`acceptable`) at every point, to rank the infeasible ones; then where the objective beats the best
        candidate's and the other margins are violated by at most :data:`NEAR` in all (a point farther out is ranked
        below every candidate by its penalty alone); with ``dynamics`` True always, with False never.  Where it is
        not simulated its margin is NaN.  The evaluation of one point is the batch of one (:meth:`evaluate_many`).
        """
        return self.evaluate_many([x], dynamics)[0]

    def evaluate_many(self, xs, dynamics=None) -> list[tuple[float, np.ndarray]]:
        """(objective, margins) of each point of ``xs`` (a sequence of variable vectors) as :meth:`evaluate` gives it,
        in order: the points not evaluated before have their laws built one by one and sampled, checked and integrated
        together (:meth:`_entries`); the separation is then decided point by point, in order."""
        t0 = time.perf_counter()
        keys = [tuple(float(v) for v in x) for x in xs]
        new = list(dict.fromkeys(key for key in keys if key not in self._cache))
        for key, entry in zip(new, self._entries([self.law(np.array(key)) for key in new]), strict=True):
            self.evaluations += 1
            self._cache[key] = entry
            self.history.append((entry[0], entry[1]))
            self.points.append(np.array(key))
        out = []
        for key in keys:
            objective, margins, kept = self._cache[key]
            if self.jump is not None and kept is not None and np.isnan(margins[self.jump]) and (
                    dynamics or (dynamics is None and objective > self.best and (
                        self.best == -math.inf or self.violation(margins) <= NEAR))):
                margins[self.jump] = self._separation(*kept)
                self.simulations += 1
            if self.acceptable(margins):
                self.best = max(self.best, objective)
            out.append((objective, margins))
        self.seconds += time.perf_counter() - t0
        return out

    def _entries(self, found):
        """[objective, margins, (law, scale) or None] of each of :meth:`law`'s results ``found``: objective 0 and
        margins -1 where there is no law or no cam."""
        out = [[0.0, -np.ones(len(self.names)), None] for _ in found]
        built = [(i, f) for i, f in enumerate(found) if f is not None]
        if not built:
            return out
        index, (laws, valves, scales) = [i for i, _ in built], zip(*(f for _, f in built), strict=True)
        margins = self._margins(laws, valves, np.array(scales))
        cams = [k for k, m in enumerate(margins) if m is not None]
        if cams:
            objectives = self._objectives([laws[k] for k in cams], [valves[k] for k in cams])
            for k, objective in zip(cams, objectives, strict=True):
                out[index[k]] = [float(objective), margins[k], (laws[k], scales[k])]
        return out

    def penalised_many(self, xs, scale) -> np.ndarray:
        """The objective over ``scale``, negated, plus :data:`PENALTY` times the summed violations, of each point of
        ``xs``, evaluated together (:meth:`evaluate_many`)."""
        return np.array([-objective / scale + PENALTY * float(np.nansum(np.clip(-margins, 0.0, None)))
                         for objective, margins in self.evaluate_many(xs)])

    def _margins(self, laws, valves, scales):
        """The margins of the limits of each law, or None where its lift leaves 0...the nose lift (no cam)."""
        return [self._margins_of(law, valve, scale, extremes)
                for law, valve, scale, extremes in zip(laws, valves, scales, self._extremes(laws, scales),
                                                       strict=True)]

    def _margins_of(self, law, valve, scale, extremes):
        """The margins of one law from its :meth:`_extremes`, or None where the lift leaves 0...the nose lift."""
        L = self.limits
        least, theta, h, dh, d2h, seat = extremes
        if least["lift"] < -1e-6 or least["overshoot"] < -1.0 - 1e-6:
            return None
        reserve = least["spring reserve"] if np.isfinite(least["spring reserve"]) else 10.0
        target = L.min_spring_reserve * scale
        out = [(reserve - target) / target]
        if self.follower.rolling:
            out.append((L.max_pressure_angle + least["pressure angle"]) / L.max_pressure_angle)
            if L.grinding_wheel_radius:
                out.append(1.0 - L.grinding_wheel_radius * max(-least["concave radius"], 0.0))
        if L.min_rho is not None:
            out.append((min(least["rho_min"], self.heel) - L.min_rho) / L.min_rho)
        if L.cam_width is not None:
            out.append((L.max_contact_stress + least["contact stress"]) / L.max_contact_stress)
        if L.max_acceleration is not None:
            out.append((L.max_acceleration + self.omega**2 * least["max acceleration"]) / abs(L.max_acceleration))
        if L.min_acceleration is not None:
            out.append((self.omega**2 * least["min acceleration"] - L.min_acceleration) / abs(L.min_acceleration))
        if L.seating_velocity is not None:
            velocity = valve.rocker_ratio * self.omega * float(np.max(seat))
            out.append((L.seating_velocity[1] - velocity) / L.seating_velocity[1])
        if self.speeds is not None:
            out.append(math.nan)
        out.append(self.spring_design(law, theta, h, dh, d2h, scale))
        return np.array(out, dtype=float)

    def _requirement(self, law, theta, h, dh, d2h, scale):
        """The required spring force (:class:`valvetrain.springs.Requirement`) of a cam at K_z = scale x K_z,0 on the
        starting design's reduced mass, from the samples of the open event (a finger's inertia by its variable ratio
        as an acceleration of that mass, as the drive stage takes it)."""
        open_ = (theta >= law.valve_opens) & (theta <= law.valve_closes)
        y = self.i_k * np.clip(h[open_] - law.ramp_height, 0.0, None)
        finger = finger_inertia_force(self.valve, self.heel, h[open_], dh[open_], d2h[open_])
        force = springs.required_spring_force(self.mass, self.i_k * self.omega**2 * d2h[open_]
                                              + self.omega**2 * finger / self.mass, self.reserve0 * scale)
        return springs.Requirement(y, force, self.spring_inputs[2])

    def _spring_passes(self, requirement):
        """Whether the design's spring search finds a spring for ``requirement`` (times a factor), the reduced mass
        iterated on the found spring's mass as the drive stage does: ``passes(factor)``."""
        throat, options, _ = self.spring_inputs
        masses = self.valve.drive.masses

        def passes(factor):
            required, mass = requirement.scaled(factor), self.mass
            for _ in range(SPRING_ITERATIONS):
                search = springs.design_springs(required, throat, self.omega, options)
                if masses is None or masses.spring_kg is not None:
                    break
                settled = train_mass(self.valve, sum(d.mass for d in search.designs.values()))[0]
                if abs(settled - mass) < 1e-7:
                    break
                required, mass = requirement.scaled(factor * settled / self.mass), settled
            return search.passes
        return passes

    def _spring_frontier(self):
        """The largest factor on the starting design's required spring force for which a spring passes every spring
        check (bisection to :data:`FRONTIER_TOLERANCE`, at most :data:`FRONTIER_RANGE`), and that required line."""
        law = self.law0
        theta = self._angles(law)
        h, dh, d2h, _ = law.derivatives(theta)
        requirement = self._requirement(law, theta, h, dh, d2h, 1.0)
        line = requirement.line(self.spring_inputs[1].ratio_range)
        passes = self._spring_passes(requirement)
        low, high = FRONTIER_RANGE
        if not passes(low):
            return 0.0, line
        if passes(high):
            return high, line
        while high - low > FRONTIER_TOLERANCE:
            mid = 0.5 * (low + high)
            low, high = (mid, high) if passes(mid) else (low, mid)
        return low, line

    def spring_design(self, law, theta, h, dh, d2h, scale) -> float:
        """Margin of the spring design: the largest of the candidate's required preload and largest force over the
        starting design's, against the factor up to which a spring passes (:meth:`_spring_frontier`, found once);
        >= 0 when a spring of the specification's options is expected to pass.

        Notes
        -----
        The required force line of a cam is a closed form of its samples (:class:`valvetrain.springs.Requirement`);
        the discrete spring search runs once, for the start's frontier, and for the final design
        (:func:`final_checks`), which checks the optimum's own spring exactly.
        """
        if self.frontier is None:
            self.frontier = self._spring_frontier()
        factor, line0 = self.frontier
        line = self._requirement(law, theta, h, dh, d2h, scale).line(self.spring_inputs[1].ratio_range)
        ratio = max(line.preload / line0.preload, line.max_force / line0.max_force)
        return (factor - ratio) / max(factor, FRONTIER_RANGE[0])

    def _separation(self, law, scale):
        """Margin of the follower separation: the smallest contact force while the cam lifts the valve over the
        spring preload (> 0), or minus the separated camshaft angle [rad] (< 0); 0 on the border."""
        p = self.train_parameters
        train = replace(one_mass_train(p.mass, p.drive_stiffness, p.spring_rate * scale, p.preload * scale,
                                       p.rocker_ratio, p.lash, damping_ratio=p.damping_ratio,
                                       seat_stiffness=p.seat_stiffness, seat_damping_ratio=p.seat_damping_ratio),
                        variable_mass=self.variable_mass)
        worst = math.inf
        for r in sweep(law, train, self.speeds, p.revolutions, p.step / DEG).per_speed():
            if len(r.jump_intervals):
                worst = min(worst, -float(np.sum(np.diff(r.jump_intervals, axis=1))))
            else:
                lifting = (r.kinematic_lift > 0.0) & (r.lift > 0.0)
                force = float(r.contact_force[lifting].min()) if lifting.any() else p.preload * scale
                worst = min(worst, force / (p.preload * scale))
        return worst

    def _slack(self, margins):
        """The margins with the spring design's raised by :data:`SPRING_SLACK`."""
        return margins + np.where(np.arange(margins.size) == margins.size - 1, SPRING_SLACK, 0.0)

    def acceptable(self, margins) -> bool:
        """Whether a point is a candidate for the full design: every margin holds (a NaN one does not), the spring
        design's within :data:`SPRING_SLACK`."""
        return bool(np.all(self._slack(margins) >= 0.0))

    def violation(self, margins) -> float:
        """The summed violations of the margins but a NaN one, the spring design's beyond :data:`SPRING_SLACK`."""
        return float(np.nansum(np.clip(-self._slack(margins), 0.0, None)))

    def candidates(self) -> list[tuple[float, np.ndarray, float]]:
        """The points evaluated that are :meth:`acceptable`, best objective first: (objective, x, worst margin)."""
        found = [(o, x, float(np.nanmin(m))) for (o, m), x in zip(self.history, self.points, strict=True)
                 if self.acceptable(m)]
        return sorted(found, key=lambda p: -p[0])


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


def _copied(node):
    """A copy of specification data (dicts and lists of numbers, texts and booleans), each dict and list new."""
    if isinstance(node, dict):
        return {k: _copied(v) for k, v in node.items()}
    return [_copied(v) for v in node] if isinstance(node, list) else node


def _ragged(arrays):
    """(concatenation, index of the array of each entry, start of each array in it) of 1-D arrays."""
    sizes = [a.size for a in arrays]
    return (np.concatenate(arrays), np.repeat(np.arange(len(arrays)), sizes),
            np.concatenate([[0], np.cumsum(sizes)[:-1]]).astype(int))


def _least(values, starts):
    """(least value, index of its first occurrence from the start) of each run of ``values`` beginning at ``starts``
    (``np.min`` and ``np.argmin`` of each run: a run holding NaN gives NaN at its first NaN)."""
    least = np.minimum.reduceat(values, starts)
    sizes = np.diff(np.append(starts, values.size))
    hits = np.flatnonzero((values == np.repeat(least, sizes)) | np.isnan(values))
    return least, hits[np.searchsorted(hits, starts)] - starts


def polydyne_fullness(law, exponents=(10, 18, 26, 34)) -> float:
    """Fullness of the polydyne (2, p, q, r, s) with the same lift, cosine ramp of the same height and end velocity
    and the same main angle as a power-polynomial ``law``, on the same definition (tappet lift over the valve-open
    part): the serial-type reference of the comparison.

    References
    ----------
    Valve-train practical works (n.d.), work 3 (the polydyne); UkrSURT Proceedings (2019) (the comparison).
    """
    poly = PolydyneLaw(law.lift_max, law.main_half_angle, *exponents, ramp_height=law.ramp_height,
                       ramp_velocity=law.v_qb)
    return flow.fullness(poly.lift, poly.valve_opens, poly.valve_closes, poly.lift_max + poly.ramp_height,
                         poly.breakpoints)


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
        limits: the valve-to-piston clearance of :data:`~valvetrain.design.valve.PISTON_CLEARANCE_MIN`, the
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
        out.append(replace(spring_reserve(design, limits.min_spring_reserve * scale, search_spring.preload * scale,
                                          search_spring.rate * scale),
                           note=START_SPRING + (f" x {scale:.4g}" if scale != 1.0 else "")))
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
