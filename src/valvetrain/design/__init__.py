"""Orchestration: ``run(spec) -> DesignResults``, the chain of stages of a design.

This package is the one place where the specification's engineering units (mm, deg,
rpm) are converted to SI for the physics functions.  Stages:

* per valve (:mod:`.valve`, :mod:`.drive`, :mod:`.drive_strength`): flow sections and conditional velocities
  (Valve-train practical works (n.d.) work 1), the lift law (works 2-3), time-area and fullness (work 4, Shang Hanji (1988)),
  the cam contour (Shang Hanji (1988) section 2.1), masses and springs (works 5-6), strength (work 7):
  ``law_stage``, ``flow_stage``, ``profile_stage``, ``clearance_stage``, ``drive_stage`` (masses, springs),
  ``dynamics_stage``, ``strength_stage`` (the drive parts over the speed range, on the dynamics stage's contact force
  where it ran), ``lubrication_stage`` (the cam contact's film and friction on the same load maps),
  ``lash_adjuster_stage`` (leak-down, refill, stiffness, pump-up; its oil column joins the dynamics' drive stiffness
  and its plunger the train), ``valve_checks``, composed by ``design_valve`` in two parts: ``valve_geometry`` (the
  law, flow, profile and clearance stages, which no load on the drive changes, kept on ``ValveDesign.geometry``)
  and ``driven_design`` (the drive and what follows it);
* the crank mechanism (:mod:`.crank`): kinematics, forces and torque, multi-cylinder torque (Power units manual (n.d.));
* two-stroke ports (:mod:`.twostroke`): timing, areas, time-area (Valve-train practical works (n.d.) work 8);
* the whole camshaft (:mod:`.camshaft`, after the valves), the cam card (:mod:`.camcard`), the breathing
  (:mod:`.breathing`: the valves' effective areas from the designed lifts, a measured table or, with
  ``lift = "dynamics"``, each valve's ``[dynamics]`` train at each condition's speed; the engine as
  ``breathing.Engine``, the records per condition); with ``[breathing]``, ``run`` gives each spring the breathing's
  closed-valve gas load (``with_gas_load``: the drive stage again, and ``driven_design`` from the kept geometry only
  where the springs change);
* a cam phaser (:mod:`.phaser`, ``[valves.NAME.phaser]``, after the camshaft and the breathing): the events moved by
  the phase, the valve-to-piston gap at the range's ends, the breathing at every phase of the map with the phased
  side's effective areas shifted, the best phase per speed, the torque the phaser holds from the camshaft's drive
  torque;
* a switching roller finger (:mod:`.switching`, ``[valves.NAME.switching]``, after the phasers): the lost-motion
  spring, the unlatched arm's dynamics and the latch; a two-step finger's low lobe, both modes' events and time-area
  and, with ``[breathing]``, each mode's breathing (:mod:`.two_step`);
* a valve with a ``[hydraulic]`` section (:mod:`.hydraulic_actuation`) opens against the cylinder pressure of the
  engine's cycle: ``run`` designs the valve without it, runs the breathing and the crank stage (whose Wiebe cycle
  needs every valve's timing) and adds the hydraulic stage after them (``with_hydraulic``: the breathing's cylinder
  pressure at the hydraulic stage's speed with the port's pressure behind the valve head where it runs, else the
  crank's);
* recommended-range checks of every stage (warnings, never exceptions), ranked by severity and margin, with
  the acceptances of the specification (``[[accepted]]``) applied.

Every result is frozen and typed (``DesignResults``, ``ValveDesign`` and the chapters; the acceptances are applied
by ``replace``); results.json's dictionary is made once (``DesignResults.projection``).  The report, its figures and
the tables read the typed results by attribute, never a ``record()`` dictionary: ``results.shown(result, *fields)``
gives a result's rows as results.json shows them (key and display value from the field metadata).  Per-angle arrays
are typed records too (``CrankColumns``, ``PortCurves``, ``SpringLines``).
"""

from dataclasses import dataclass, field, replace
import difflib
from functools import cached_property
from typing import Any, Optional


from .. import flow
from ..breathing import BreathingError
from ..checks import SEVERITIES, Check, apply_acceptances, check, failed, ranked, tally
from ..crank.pressure import PressureFileError
from ..files import BreathingFileError, TableFileError
from ..laws.records import LawRecord
from ..locale import cited, note, verdict
from ..specification import Spec, SpecError, crank_geometry, si, spec_document, validate
from ..specification.messages import Problem, said
from ..specification.models import Dynamics
from ..units import MM, to_display
from .breathing import (BreathingResults, BreathingSummary, breathing_stage, cylinder_pressure,
                        gas_opening_load)
from .camcard import CamCard, CamCardValve, cam_card_stage
from .camshaft import CamshaftRecord, CamshaftResults, camshaft_stage
from .crank import (LAMBDA_RANGE, CrankResults, CrankSummary, crank_geometry as crank_geometry_of, crank_stage,
                    valve_timing)
from .drive import MassResult, SpringResult
from .drive_strength import StrengthResult
from .dynamics_records import DynamicsResult
from .grinding import GrindingResult
from .hydraulic_actuation import CylinderPressure, HydraulicResult, speed_plan
from .lost_motion import LostMotionResult
from .lost_motion_breathing import with_breathing
from .lash_adjuster import LashAdjusterResult
from .lubrication import LubricationResult
from .phaser import PhaserRecord, PhaserResults, phaser_stage
from .switching import SwitchingRecord, SwitchingResult, switching_stage
from .results import json_schema, quantity, record, shown_value
from .twostroke import TwoStrokeResults, TwoStrokeSummary, two_stroke_stage
from .valve import (CamResult, ClearanceResult, FlowResult, ProfileResult, ValveDesign, clearance_stage, design_valve,
                    flow_stage, kinematic_stages, law_stage, profile_stage, with_gas_load, with_hydraulic)
from .valve_checks import THROAT_AREA_SHARE_RANGE, overlap_clearance_checks, valve_checks

__all__ = ["DesignResults", "ValveDesign", "breathing_view", "clearance_stage", "design_valve", "flow_stage", "law_stage",
           "profile_stage", "run", "sweep_designs", "valve_checks", "valve_kinematics"]


@dataclass(frozen=True)
class EngineRecord:
    """The engine's data and derived figures."""

    name: str = quantity("name", label="engine name")
    bore: float = quantity("bore_mm", "mm", "bore D")
    stroke: float = quantity("stroke_mm", "mm", "stroke S")
    rated_speed: float = quantity("rated_speed_rpm", "rpm", "rated speed")
    cylinders: int = quantity("cylinders", label="cylinders")
    strokes: int = quantity("strokes", label="strokes per cycle")
    mean_piston_speed: float = quantity("mean_piston_speed_m_s", "m/s", "mean piston speed c_p = S n / 30")
    swept_volume: float = quantity("swept_volume_cm3", "cm3", "swept volume of one cylinder V_h")
    displacement: float = quantity("displacement_cm3", "cm3", "engine displacement")
    piston_area: float = quantity("piston_area_mm2", "mm2", "piston area F_p")


@dataclass(frozen=True, repr=False)
class DesignResults:
    """Result of :func:`run`: the engine's derived figures, each valve's design, all warnings."""

    spec: Spec
    engine: EngineRecord
    valves: dict[str, ValveDesign]
    checks: tuple[Check, ...]                  # every check of the design, passed or not
    crank: Optional[CrankResults] = None
    two_stroke: Optional[TwoStrokeResults] = None
    cam_card: Optional[CamCard] = None         # a four-stroke's (valvetrain.camcard)
    camshaft: Optional[CamshaftResults] = None  # with a [camshaft] section
    breathing: Optional[BreathingResults] = None  # with a [breathing] section
    phasers: dict[str, PhaserResults] = field(default_factory=dict)   # the valves with a [phaser] section
    switching: dict[str, SwitchingResult] = field(default_factory=dict)  # the valves with a [switching] section

    @property
    def warnings(self) -> list[Check]:
        """The checks that fail and that the specification does not accept, ranked (:func:`valvetrain.checks.ranked`:
        failures, warnings, info; the farthest outside first)."""
        return ranked(c for c in failed(self.checks) if not c.accepted)

    @property
    def accepted(self) -> list[Check]:
        """The checks that fail and that the specification accepts (``[[accepted]]``, with a reason), ranked."""
        return ranked(c for c in failed(self.checks) if c.accepted)

    def _rows(self):
        """One line of figures per valve: name, law, valve lift, time-area, fullness, spring, open checks."""
        for name, v in self.valves.items():
            spring = v.drive.spring.design
            yield (name, v.law.name, f"{v.flow.valve_lift / MM:.4g}", f"{v.flow.time_area / MM**2:.4g}",
                   f"{v.flow.fullness:.4g}", f"{spring.wire_diameter / MM:g} x {spring.mean_diameter / MM:g}",
                   "{failure}, {warning}, {info} of {checks}".format(**tally(v.checks)))

    _HEADS = ("valve", "law", "lift, mm", "time-area, mm2 s", "fullness", "spring wire x D, mm",
              "open failures, warnings, info")

    def __repr__(self):
        e = self.engine
        bore, stroke, speed = (shown_value(e, k) for k in ("bore", "stroke", "rated_speed"))
        lines = [f"DesignResults: {e.name} ({e.cylinders} cyl., {bore:g} x {stroke:g} mm, {speed:g} rpm)",
                 *("  " + line for line in verdict(tally(self.checks)))]
        lines += ["  " + ", ".join(f"{h} {c}" for h, c in zip(self._HEADS, row, strict=True)) for row in self._rows()]
        if self.crank is not None:
            lines.append(f"  crank: mean torque {self.crank.figures.mean_torque:.4g} N m")
        return "\n".join(lines)

    def _repr_html_(self):
        """A summary table for notebooks: the valves' figures and the checks that fail."""
        from html import escape

        def table(heads, rows):
            head = "".join(f"<th>{escape(h)}</th>" for h in heads)
            body = "".join("<tr>" + "".join(f"<td>{escape(str(c))}</td>" for c in r) + "</tr>" for r in rows)
            return f"<table><tr>{head}</tr>{body}</table>"

        warnings = [(w.severity, w.quantity, w.value_text, w.range, w.source) for w in self.warnings]
        accepted = [(w.severity, w.quantity, w.value_text, w.range, w.reason) for w in self.accepted]
        sentence, counts = verdict(tally(self.checks))
        return (f"<p><b>{escape(self.engine.name)}</b></p><p>{escape(sentence)} {escape(counts)}</p>"
                + table(self._HEADS, self._rows())
                + "<p>Checks that fail</p>" + table(("severity", "quantity", "value", "allowed", "source"), warnings)
                + ("<p>Accepted in the specification</p>" + table(("severity", "quantity", "value", "allowed",
                                                                   "reason"), accepted) if accepted else ""))

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready dictionary (engineering units, named in the keys): the projection of results.json, made once
        (:attr:`projection`); read it, don't change it."""
        return self.projection

    @cached_property
    def projection(self) -> dict[str, Any]:
        """The results.json dictionary, made on first use and kept (the results are frozen)."""
        from .. import __version__

        out = {
            "valvetrain_version": __version__,
            "engine": record(self.engine),
            "valves": {name: v.summary for name, v in self.valves.items()},
        }
        if self.crank is not None:
            out["crank"] = self.crank.summary
        if self.two_stroke is not None:
            out["two_stroke"] = self.two_stroke.summary
        if self.cam_card is not None:
            out["cam_card"] = record(self.cam_card)
        if self.camshaft is not None:
            out["camshaft"] = self.camshaft.summary
        if self.breathing is not None:
            out["breathing"] = self.breathing.summary
        if self.phasers:
            out["phasers"] = {name: p.summary for name, p in self.phasers.items()}
        if self.switching:
            out["switching"] = {name: s.summary for name, s in self.switching.items()}
        out["warnings"] = [w.warning() for w in self.warnings]
        out["accepted"] = [w.warning() for w in self.accepted]
        out["checks"] = [c.as_dict() for c in self.checks]
        return out


def run(spec, laws=None, progress=None, headlines_only=False, diagnose=True, memo=None) -> DesignResults:
    """Run the whole design of a validated specification.

    Parameters
    ----------
    spec : valvetrain.specification.Spec or dict
        Validated again here: a specification changed with ``model_copy(update=...)``, which validates nothing, is
        refused like a file with the same values (:meth:`Spec.replace` is the validated way to change one); a dict
        is the tables of a specification, as :func:`tomllib.loads` gives them.
    laws : dict, optional
        ``valve name -> LiftLaw``: enter those valves' designs with a law of the caller's own.
    progress : callable, optional
        ``progress(valve name, done, total)`` during the speed sweep of a valve's ``[dynamics]`` section.
    headlines_only : bool
        Each one-mass ``[dynamics]`` sweep simulates only the speeds that decide its jump speed, its largest seating
        velocity and its largest cam force (:func:`valvetrain.dynamics.sweep.headline_sweep`), for a tolerance
        study: its checks and headlines as the full sweep's (within the accuracy that function states), its
        per-speed table sparse; no cam card (it has no checks).
    diagnose : bool
        Where no spring passes, diagnose why (:func:`valvetrain.springs.diagnose`, about a second); False leaves
        the diagnosis out of the springs' failing checks.
    memo : dict, optional
        The valves' designs of an earlier run, kept by the caller between runs (the designer's tab): a valve whose
        inputs (its SI view, the engine's, ``[gas]``, ``[output]`` and the options) equal those of the design kept
        under its name takes that design instead of being designed again; each valve's newest design is kept.

    Returns
    -------
    DesignResults

    Raises
    ------
    SpecError
        A specification that does not validate; inputs that admit no design (a cam the law cannot make, a file
        that cannot be read, no spring that fits), one message per problem of every valve.
    """
    if not isinstance(spec, (Spec, dict)):
        raise SpecError([f"run: a valvetrain.specification.Spec (from load_spec, parse_spec or Spec.replace) or a "
                         f"dict of its tables is needed, not a {type(spec).__name__}"])
    spec = validate(spec if isinstance(spec, dict) else spec_document(spec))
    engine, gas, output = si(spec.engine), si(spec.gas), si(spec.output)
    valves, problems, waiting, views = {}, [], {}, {}
    for name, v in spec.valves.items():
        try:
            valve = views[name] = _valve_view(name, v, spec)
        except SpecError as err:
            problems += err.problems
            continue
        if (spec.crank is not None or spec.breathing is not None) and valve.hydraulic is not None:
            waiting[name], valve = valve, replace(valve, hydraulic=None)   # opens against the cycle: after it
        try:
            tick = None if progress is None else (lambda done, total, name=name: progress(name, done, total))
            valves[name] = _remembered(memo, name, (valve, engine, gas, output, (laws or {}).get(name),
                                                    headlines_only, diagnose), tick)
        except SpecError as err:
            problems += err.problems
    if problems:
        raise SpecError(problems)
    crank_view = None
    if spec.crank is not None:
        try:
            crank_view = si(spec.crank, spec)
        except PressureFileError as exc:
            raise SpecError([Problem("crank.pressure_file", said(exc))]) from None
    breathing = (_breathing(spec, engine, crank_view, valves, views) if spec.breathing is not None else None)
    if breathing is not None:
        for name, valve in views.items():   # the spring's gas load from the breathing's pressures: what it changes
            valves[name] = with_gas_load(valves[name], replace(valve, hydraulic=None), engine, gas, output,
                                         gas_opening_load(breathing, valve.kind, valve.throat_diameter),
                                         headlines_only, diagnose)
    breathed = None
    if breathing is not None and crank_view is not None and engine.strokes == 4:
        breathed = cylinder_pressure(breathing, crank_geometry_of(crank_view, engine)[3])
    crank = crank_stage(crank_view, engine, valve_timing(valves), breathed) if crank_view is not None else None
    for name, valve in waiting.items():     # a hydraulic valve opens against the cylinder pressure
        cylinder = (cylinder_pressure(breathing, speed_plan(valve.hydraulic, engine)[0], valve.kind)
                    if breathing is not None
                    else CylinderPressure(crank.phi, crank.columns.p_abs, crank.pressure_source))
        valves[name] = with_hydraulic(valves[name], valve, engine, gas, cylinder)
        lost = valves[name].lost_motion
        if lost is not None and breathing is not None and views[name].kind == "intake":
            lost, more = with_breathing(lost, name, valves[name], views[name], breathing, breathing_view(spec))
            valves[name] = replace(valves[name], lost_motion=lost,
                                   checks=valves[name].checks + tuple(c.of_valve(name) for c in more))
    found = [c for v in valves.values() for c in v.checks] + overlap_clearance_checks(valves) + engine_checks(spec)
    if {v.kind for v in valves.values()} == {"intake", "exhaust"}:
        share = sum(v.count * v.flow.throat_area for v in valves.values())
        found.append(check("engine.throat_area_share", share / float(flow.circle_area(engine.bore)),
                           *THROAT_AREA_SHARE_RANGE, source="Valve-train practical works (n.d.), work 1"))
    ports = two_stroke_stage(si(spec.two_stroke), crank_view, engine) if spec.two_stroke is not None else None
    shaft = camshaft_stage(si(spec.camshaft), engine, views, valves) if spec.camshaft is not None else None
    for stage, tag in ((crank, "crank"), (ports, "two-stroke"), (shaft, "camshaft"), (breathing, "breathing")):
        if stage is not None:
            found += [c.named(tag) for c in stage.checks]
    phased = [name for name, v in views.items() if v.phaser is not None]
    switched = {name: v for name, v in views.items() if v.switching is not None}
    b = breathing_view(spec) if (phased or switched) and breathing is not None else None
    phasers = {name: phaser_stage(name, views[name].phaser, views[name], engine, valves[name], breathing, b, shaft,
                                  gas) for name in phased}
    found += [c for p in phasers.values() for c in p.checks]
    switching = {name: switching_stage(name, v.switching, v, engine, valves[name], output, breathing, b)
                 for name, v in switched.items()}
    found += [c for s in switching.values() for c in s.checks]
    found, valves = accept(found, spec.accepted, valves)
    card = cam_card_stage(valves) if valves and engine.strokes == 4 and not headlines_only else None
    return DesignResults(spec, engine_record(engine), valves, tuple(found), crank, ports, card, shaft, breathing,
                         phasers, switching)


def breathing_view(spec) -> Any:
    """The SI view of a specification's [breathing] with its files read (a file that cannot be used is a
    :class:`SpecError` naming its key)."""
    sides = {}
    for side in ("intake", "exhaust"):
        try:
            sides[side] = si(getattr(spec.breathing, side), spec)
        except BreathingFileError as exc:
            raise SpecError([Problem(f"breathing.{side}.{exc.key}", said(exc))]) from None
    return replace(si(spec.breathing.model_copy(update={"intake": None, "exhaust": None}), spec), **sides)


def _breathing(spec, engine, crank_view, valves, views):
    """The breathing stage of a specification with [breathing] (:func:`breathing_view`), the crank's SI view (or
    None) for the rod, offset and Wiebe cycle."""
    try:
        return breathing_stage(breathing_view(spec), engine, crank_view, valves, views)
    except BreathingError as exc:
        raise SpecError([Problem("breathing", said(exc))]) from None


def accept(found: list[Check], acceptances: list, valves: dict[str, ValveDesign]
           ) -> tuple[list[Check], dict[str, ValveDesign]]:
    """The checks with the specification's acceptances applied, and the valves with them applied to each valve's
    own checks.

    Raises
    ------
    SpecError
        An acceptance that names no check of the design (``accepted.N.quantity``), with the nearest quantities.
    """
    found, unmatched = apply_acceptances(found, acceptances, valves)
    if unmatched:
        names = sorted({c.quantity for c in found} | {c.quantity.partition(": ")[2] for c in found if c.valve}
                       | {c.code for c in found})
        problems = []
        for i in unmatched:
            a = acceptances[i]
            near = difflib.get_close_matches(a.quantity, names, n=3, cutoff=0.5)
            where = f" of valve {a.valve!r}" if a.valve is not None else ""
            problems.append(f"accepted.{i}.quantity = {a.quantity!r} names no check{where} of the design"
                            + (f"; did you mean {' or '.join(repr(n) for n in near)}?" if near else
                               " (every check is listed in results.json, checks)"))
        raise SpecError(problems)
    return found, {name: replace(v, checks=tuple(apply_acceptances(v.checks, acceptances, valves)[0]))
                   for name, v in valves.items()}


def engine_record(eng) -> EngineRecord:
    """The engine's figures (SI view of [engine]): its data, the mean piston speed, swept volume and piston area."""
    swept = float(flow.swept_volume(eng.bore, eng.stroke))
    return EngineRecord(eng.name, eng.bore, eng.stroke, eng.rated_speed, eng.cylinders, eng.strokes,
                        flow.mean_piston_speed(eng.stroke, to_display(eng.rated_speed, "rpm")), swept,
                        swept * eng.cylinders, float(flow.circle_area(eng.bore)))


UNIT_SLIP_FACTOR = 3.0
"""How far beyond a typical range of engines a figure of the engine's keys is a failure: a factor of 3 either way.
A unit slip (a stroke in cm, x10; inches, x25.4; a speed in rev/s, x60) takes a typical value far outside, a real
engine stays inside."""

MEAN_PISTON_SPEED_RANGE = (8.0, 15.0)
"""Typical mean piston speed at the rated speed [m/s] (Heywood (1988), section 2.2)."""

STROKE_BORE_RANGE = (1.0 / 1.2, 2.0)
"""Typical stroke / bore ratio: bore / stroke 0.8-1.2 for small and medium engines, down to about 0.5 for large
slow-speed diesels (Heywood (1988), section 2.2)."""


def engine_checks(spec) -> list[Check]:
    """Plausibility of the engine's keys: the stroke / bore ratio, the mean piston speed and the crank-rod ratio
    lambda, failures a factor of :data:`UNIT_SLIP_FACTOR` beyond their typical ranges (a unit slip, not an engine).

    Parameters
    ----------
    spec : valvetrain.specification.Spec

    Returns
    -------
    list of Check
        Severity failure, the quantities naming the keys they come from.

    Notes
    -----
    S/D = stroke / bore; c_p = S n / 30 [m/s] with S in m and n in rpm; lambda = R / L = S / (2 L).

    References
    ----------
    Heywood (1988), section 2.2 (mean piston speed 8-15 m/s; bore / stroke 0.8-1.2, about 0.5 for large slow-speed
    diesels); Power units manual (n.d.), eq. (1.1) (lambda = 0.24-0.31).
    """
    bore, stroke, rod, speed = crank_geometry(spec)
    k = UNIT_SLIP_FACTOR
    found = [check("engine.stroke_to_bore", stroke / bore, STROKE_BORE_RANGE[0] / k,
                   STROKE_BORE_RANGE[1] * k, source=cited(note("source.factor_beyond", factor=k, work="Heywood (1988), section 2.2")),
                   severity="failure").named("engine"),
             check("engine.mean_piston_speed",
                   flow.mean_piston_speed(stroke * MM, speed), MEAN_PISTON_SPEED_RANGE[0] / k,
                   MEAN_PISTON_SPEED_RANGE[1] * k, unit="m/s",
                   source=cited(note("source.factor_beyond", factor=k, work="Heywood (1988), section 2.2")),
                   severity="failure").named("engine")]
    if rod is not None:
        found.append(check("engine.rod_ratio", stroke / 2.0 / rod, LAMBDA_RANGE[0] / k,
                           min(LAMBDA_RANGE[1] * k, 1.0), source=cited(note("source.factor_beyond", factor=k, work="Power units manual (n.d.), eq. (1.1)")),
                           severity="failure").named("engine"))
    return found


def _remembered(memo, name, inputs, tick) -> ValveDesign:
    """:func:`~valvetrain.design.valve.design_valve` of ``inputs`` (the valve's, the engine's, ``[gas]``'s and
    ``[output]``'s SI views, the law, ``headlines_only``, ``diagnose``), or the design ``memo`` keeps under ``name``
    for equal inputs (a speed sweep's too: a valve swept once is not swept again); the design made is kept there."""
    kept = (memo or {}).get(name)
    if kept is not None and _same(kept[0], inputs):
        return kept[1]
    designed = design_valve(name, *inputs[:5], tick, headlines_only=inputs[5], diagnose=inputs[6])
    if memo is not None:
        memo[name] = (inputs, designed)
    return designed


def _same(a, b):
    """Whether two tuples of SI views are equal (views holding arrays, a lift table's, are not compared: False)."""
    try:
        return bool(a == b)
    except ValueError:
        return False


def _valve_view(name, valve, spec):
    """The SI view of ``spec.valves[name]``, its lift table read; a file that cannot be read is a
    :class:`SpecError` naming the key."""
    try:
        return si(valve, spec)
    except (TableFileError, PressureFileError) as exc:
        raise SpecError([Problem(f"valves.{name}.cam.table_file", said(exc))]) from None


def valve_kinematics(spec, name) -> tuple[CamResult, FlowResult, ProfileResult]:
    """The kinematic stages of valve ``name`` of a validated specification alone
    (:func:`~valvetrain.design.valve.kinematic_stages`): its lift curves and contour, without its drive, springs
    and checks and without the other valves (the designer's answer while a handle is dragged).

    Raises
    ------
    SpecError
        No such valve; a lift table that cannot be read or a cam the law cannot make, naming the key.
    """
    if name not in spec.valves:
        raise SpecError([f"no valve {name!r}; allowed: {', '.join(spec.valves)}"])
    return kinematic_stages(name, _valve_view(name, spec.valves[name], spec), si(spec.engine), si(spec.output))


def sweep_designs(spec, names=None, progress=None, memo=None) -> dict[str, ValveDesign]:
    """The speed sweep alone: the named valves of a specification (default: those with a ``[dynamics]`` section, or
    every valve if none has one) designed with their section, or the default one where they have none.

    Parameters
    ----------
    spec : valvetrain.specification.Spec
    names : sequence of str, optional
    progress : callable, optional
        ``progress(valve name, done, total)``.
    memo : dict, optional
        As for :func:`run`: a valve swept with equal inputs before is not swept again, and the valves swept here
        are kept (a :func:`run` of the same specification with this memo takes them).

    Returns
    -------
    dict
        ``name -> ValveDesign`` whose ``dynamics`` is set.

    Raises
    ------
    SpecError
        An unknown valve name, or inputs that admit no design.
    """
    if not names:
        names = [n for n, v in spec.valves.items() if v.dynamics is not None] or list(spec.valves)
    unknown = [n for n in names if n not in spec.valves]
    if unknown:
        raise SpecError([f"--valve {n}: no such valve; allowed: {', '.join(spec.valves)}" for n in unknown])
    engine, gas, output = si(spec.engine), si(spec.gas), si(spec.output)
    out, problems = {}, []
    for name in names:
        v = spec.valves[name]
        if v.dynamics is None:
            v = v.model_copy(update={"dynamics": Dynamics()})
        tick = None if progress is None else (lambda done, total, name=name: progress(name, done, total))
        try:
            out[name] = _remembered(memo, name, (_valve_view(name, v, spec), engine, gas, output, None, False, True),
                                    tick)
        except SpecError as err:
            problems += err.problems
    if problems:
        raise SpecError(problems)
    return out


def results_schema() -> dict[str, Any]:
    """JSON Schema (draft 2020-12) of results.json, generated from the stage results' field metadata.

    The strength checks are objects described in the README.
    """
    from .. import __version__

    def merged(*schemas, **extra):
        props = {k: v for sch in schemas for k, v in sch["properties"].items()}
        props.update({k: {"type": "object", "description": text} for k, text in extra.items()})
        return {"type": "object", "properties": props, "required": [k for sch in schemas for k in sch["required"]]}

    check_record = {"type": "object", "required": ["quantity", "code", "valve", "params", "value", "range", "source",
                                                   "unit", "severity", "margin"],
                    "properties": {k: {"type": t} for k, t in (("quantity", "string"), ("code", "string"),
                                                                ("valve", ["string", "null"]), ("params", "object"),
                                                                ("range", "string"),
                                                                ("source", "string"), ("unit", "string"),
                                                                ("accepted", "boolean"), ("reason", "string"),
                                                                ("unevaluated", "string"))}
                    | {"value": {"type": ["number", "null"]},
                       "margin": {"type": ["number", "null"], "description": "relative distance of the value to the "
                                  "nearest bound (>= 0 passes); null where there is none: a value that cannot be "
                                  "evaluated (unevaluated says why), a check without bounds (range 'any')"},
                       "severity": {"enum": list(SEVERITIES)}}}
    # a margin is null exactly where there is no distance to a bound: no value, or no bound (a failed check has one)
    no_value = {"required": ["unevaluated"]}
    no_bound = {"properties": {"low": {"type": "null"}, "high": {"type": "null"}}}
    null_margin = {"properties": {"margin": {"type": "null"}}}
    full_record = {**check_record, "required": [*check_record["required"], "low", "high", "pass", "accepted"],
                   "properties": check_record["properties"] | {
                       "low": {"type": ["number", "null"]}, "high": {"type": ["number", "null"]},
                       "pass": {"type": "boolean"}, "note": {"type": "string"}},
                   "allOf": [{"if": null_margin, "then": {"anyOf": [no_value, no_bound]}},
                             {"if": {"anyOf": [no_value, no_bound]}, "then": null_margin}]}
    check_record["allOf"] = [{"if": null_margin, "then": no_value}, {"if": no_value, "then": null_margin}]
    strength = merged(json_schema(StrengthResult), checks="one record per strength check: value, allowed, limit, "
                      "unit, pass, source (and a note)")
    strength["properties"]["not_checked"] = {"type": "array", "items": {"type": "string"},
                                             "description": "the checks whose parts are not given"}
    valve = {"type": "object", "properties": {
        "kind": {"type": "string"}, "count": {"type": "integer"}, "rocker_ratio": {"type": "number"},
        "cam": merged(json_schema(CamResult), json_schema(ProfileResult), json_schema(LawRecord)),
        "flow": json_schema(FlowResult), "piston_clearance": json_schema(ClearanceResult),
        "masses": json_schema(MassResult), "spring": json_schema(SpringResult),
        "strength": strength, "dynamics": json_schema(DynamicsResult),
        "grinding": json_schema(GrindingResult), "hydraulic": json_schema(HydraulicResult),
        "lost_motion": json_schema(LostMotionResult),
        "lubrication": json_schema(LubricationResult), "lash_adjuster": json_schema(LashAdjusterResult)}}
    return {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "$id": f"https://valvetrain.invalid/results-{__version__}.schema.json",
        "title": "valvetrain results.json", "type": "object",
        "required": ["valvetrain_version", "engine", "valves", "warnings", "accepted", "checks"],
        "properties": {
            "valvetrain_version": {"type": "string"}, "engine": json_schema(EngineRecord),
            "valves": {"type": "object", "additionalProperties": valve},
            "crank": json_schema(CrankSummary), "two_stroke": json_schema(TwoStrokeSummary),
            "breathing": json_schema(BreathingSummary),
            "camshaft": json_schema(CamshaftRecord),
            "phasers": {"type": "object", "additionalProperties": json_schema(PhaserRecord),
                        "description": "each phased valve's cam phaser ([valves.NAME.phaser])"},
            "switching": {"type": "object", "additionalProperties": json_schema(SwitchingRecord),
                          "description": "each valve's switching roller finger follower ([valves.NAME.switching])"},
            "cam_card": json_schema(CamCard) | {"properties": json_schema(CamCard)["properties"] | {
                "valves": {"type": "object", "additionalProperties": json_schema(CamCardValve)}}},
            "warnings": {"type": "array", "items": check_record,
                         "description": "the checks that fail and are not accepted, ranked: failures, warnings, info, "
                                        "the farthest outside (smallest margin) first"},
            "accepted": {"type": "array", "items": check_record,
                         "description": "the checks that fail and that the specification accepts ([[accepted]]), "
                                        "ranked, each with accepted = true and the reason"},
            "checks": {"type": "array", "items": full_record,
                       "description": "every check, with low, high, severity, pass, margin and accepted (and the "
                                      "reason of an acceptance)"}}}
