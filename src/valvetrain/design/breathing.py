"""Breathing stage: the gas exchange of the engine's cylinders through the designed (or measured) valves, converged
over cycles at each condition of ``[breathing]`` (:mod:`valvetrain.breathing`)."""

from dataclasses import dataclass, replace
from functools import cached_property
from typing import Any, Optional

import numpy as np

from ..breathing import (BreathingError, CdTable, Condition, Cylinder, Engine, Firing, Plenum, Runner, ValveFlow,
                         breathe)
from ..breathing.cycle import CYCLE, MAX_WORK, BreathingRecord, BreathingResult, work
from ..breathing.valves import DEFAULT_CD, default_areas, effective_areas
from ..springs import gas_opening_force
from ..checks import Check, check
from ..locale import NoteText, cited, note
from ..units import MM, to_display
from .dynamics import valve_motion
from .hydraulic_actuation import CylinderPressure, cycle_angle
from .results import quantity, record
from .valve import CYCLE_CRANK

KELVIN = 273.15
"""0 degC in K (the specification's temperatures are in degC)."""

GRID = np.radians(np.arange(0.0, 720.0, 0.25))
"""Crank angles [rad, 0...4 pi from the gas-exchange TDC] of the valves' effective areas, a quarter degree apart."""


@dataclass(frozen=True)
class BreathingSummary:
    """The breathing chapter's record: where the valves' lift and discharge come from, and each condition's figures."""

    mode: str = quantity("mode", label="motored or fired")
    intake_lift: str = quantity("intake_lift", label="the intake valves' lift")
    exhaust_lift: str = quantity("exhaust_lift", label="the exhaust valves' lift")
    intake_discharge: str = quantity("intake_discharge", label="the intake valves' discharge coefficients")
    exhaust_discharge: str = quantity("exhaust_discharge", label="the exhaust valves' discharge coefficients")
    conditions: tuple[BreathingRecord, ...] = quantity("conditions", label="the conditions of [[breathing.conditions]]")
    curve: tuple[BreathingRecord, ...] = quantity("curve", label="the speeds of [breathing.curve]")


@dataclass(frozen=True, repr=False)
class BreathingResults:
    """The breathing chapter: the engine as the physics sees it, each condition's and each curve point's result."""

    engines: tuple[Engine, ...]     # one a condition, then one a curve speed (:func:`breathing_engine`)
    conditions: tuple[BreathingResult, ...]
    curve: tuple[BreathingResult, ...]
    figures: BreathingSummary
    checks: tuple[Check, ...]

    @cached_property
    def summary(self) -> dict[str, Any]:
        """The chapter's record in results.json (engineering units), made once: read it, don't change it."""
        return record(self.figures)

    def __repr__(self):
        return (f"BreathingResults({self.figures.mode}: {len(self.conditions)} conditions, {len(self.curve)} curve "
                "speeds)")


def _on_grid(angles_deg, lift_mm):
    """A measured lift on :data:`GRID` [m]: linear between the rows, zero outside them (the valve shut)."""
    start = angles_deg[0]
    rel = np.mod(np.degrees(GRID) - start, 720.0)
    inside = rel <= angles_deg[-1] - start
    return np.where(inside, np.interp(start + rel, angles_deg, lift_mm), 0.0) * MM


def designed_lift(valve) -> np.ndarray:
    """A designed valve's lift on :data:`GRID` [m] (its timing diagram's, :attr:`ValveDesign.cycle_lift`)."""
    order = np.argsort(np.mod(CYCLE_CRANK, 4.0 * np.pi), kind="stable")
    angle = np.mod(CYCLE_CRANK, 4.0 * np.pi)[order]
    keep = np.concatenate([[True], np.diff(angle) > 0.0])
    return np.interp(GRID, angle[keep], valve.cycle_lift[order][keep], period=4.0 * np.pi)


def dynamic_lift(name, design, view, engine, speeds, kind) -> np.ndarray:
    """The lift [m] on :data:`GRID` of the valve ``name`` moved by its ``[dynamics]`` train at each engine speed of
    ``speeds`` [rad/s] (one row a speed): :func:`~valvetrain.design.dynamics.valve_motion`'s steady revolution, the
    camshaft angle theta from the nose at the crank angle nose + theta / (camshaft revolutions per crank revolution),
    a valve pressed into its seat shut (lift 0).

    Parameters
    ----------
    name : str
    design : ValveDesign
        The designed valve (its cam, nose and drive).
    view : SI view of ``[valves.NAME]`` with its ``dynamics`` section
    engine : SI view of ``[engine]``
    speeds : array_like
        Engine speeds [rad/s].
    kind : {"intake", "exhaust"}
        Its side (``breathing.KIND.lift`` is named where the sweep is too large).

    Returns
    -------
    ndarray (len(speeds), GRID.size)

    Notes
    -----
    The train is the valve's as designed before the breathing: its spring that of ``[gas]``'s closed-valve gas
    load.  ``run`` then gives the spring the breathing's gas load (:func:`gas_opening_load`); the lift and that load
    are not iterated (one pass), which changes the lift only where the breathing's load changes the spring.
    """
    motion = valve_motion(view.dynamics, view, engine, design.law, design.drive, speeds, f"valves.{name}",
                          f"breathing.{kind}.lift")
    crank = cycle_angle(design.nose_crank, motion.theta, engine.strokes)
    order = np.argsort(crank, kind="stable")
    return np.array([np.interp(GRID, crank[order], np.clip(y[order], 0.0, None), period=CYCLE) for y in motion.lift])


def cd_table(side) -> Optional[CdTable]:
    """The measured C_D(L/D) table of a side of [breathing] (its SI view), None without one."""
    if side.cd is None:
        return None
    x, fwd, rev = side.cd
    return CdTable(x, fwd, rev, side.cd_diameter, side.cd_reference, side.section.cd_file)


def lift_areas(lift, table, valve) -> tuple[np.ndarray, np.ndarray]:
    """The forward and reverse effective areas [m^2] of one valve at the lifts ``lift`` [m]: the side's measured
    ``table`` (:func:`~valvetrain.breathing.valves.effective_areas`), else the default discharge on the flow section of
    the valve's SI view (:func:`~valvetrain.breathing.valves.default_areas`)."""
    if table is not None:
        return effective_areas(lift, table)
    f = default_areas(lift, valve.throat_diameter, valve.seat_angle)
    return f, f


def valve_flow(side, kind, valves, views, engine=None, speeds=()) -> tuple[tuple[ValveFlow, ...], str, str]:
    """One side's effective areas over the cycle and the words of where its lift and discharge come from.

    Parameters
    ----------
    side : SI view of [breathing.intake] or [breathing.exhaust]
    kind : {"intake", "exhaust"}
    valves : dict
        The designed valves (``name -> ValveDesign``).
    views : dict
        Their SI views (``name -> view``: the throat and the seat of the flow section, the ``[dynamics]``).
    engine : SI view of [engine], optional
        Needed with ``lift = "dynamics"``.
    speeds : sequence of float
        The engine speeds [rad/s] of the conditions, in order (``lift = "dynamics"``: a flow at each).

    Returns
    -------
    (tuple of ValveFlow, str, str)
        One flow, the same at every speed (a designed or measured lift), or one at each of ``speeds``
        (``lift = "dynamics"``).
    """
    table = cd_table(side)
    if table is not None:
        discharge = (f"C_D(L/D) of {side.section.cd_file}, referred to the {side.cd_reference} area of D = "
                     f"{side.cd_diameter / MM:g} mm")
    else:
        discharge = f"C_D = {DEFAULT_CD:g} on the flow section, at most the throat (assumed, no measured table)"

    def counted(v):
        return f"{v.count} valve{'s' if v.count > 1 else ''}"

    these = [(name, v) for name, v in valves.items() if v.kind == kind]
    if side.measured_lift is not None:
        lifts = [(_on_grid(*side.measured_lift), side.valves, None)]
        source = f"measured, {side.section.lift_file}, {side.valves} valve{'s' if side.valves > 1 else ''}"
    elif side.lift == "dynamics":
        lifts = [(dynamic_lift(name, v, views[name], engine, speeds, kind), v.count, views[name]) for name, v in these]
        source = "dynamic: " + ", ".join(f"{name} ({v.law.name}, {counted(v)}), the valve's motion of its [dynamics] "
                                         f"{views[name].dynamics.model} train at each speed" for name, v in these)
    else:
        lifts = [(designed_lift(v), v.count, views[name]) for name, v in these]
        source = "designed: " + ", ".join(f"{name} ({v.law.name}, {counted(v)})" for name, v in these)
    forward = reverse = 0.0
    for lift, count, valve in lifts:
        f, r = lift_areas(lift, table, valve)
        forward, reverse = forward + count * f, reverse + count * r
    forward, reverse = np.atleast_2d(forward), np.atleast_2d(reverse)
    return tuple(ValveFlow(GRID, f, r) for f, r in zip(forward, reverse, strict=True)), source, discharge


def breathing_engine(b, engine, crank, valves, views, conditions
                     ) -> tuple[tuple[Engine, ...], tuple[str, str, str, str]]:
    """The engine as the breathing sees it at each of ``conditions`` (the physics' conditions of [breathing] and the
    speeds of its curve, in order: :func:`breathing_conditions`), from the SI views of [breathing], [engine] and
    [crank] (None) and the designed valves with their SI views; and the words of each side's lift and discharge.

    Returns
    -------
    (tuple of valvetrain.breathing.Engine, tuple of str)
        The engines differ only in a side whose lift is dynamic (``lift = "dynamics"``: its valves' motion at the
        condition's speed).
    """
    rod = crank.rod_length if crank is not None and crank.rod_length is not None else engine.rod_length
    ratio = b.compression_ratio if b.compression_ratio is not None else crank.compression_ratio
    offset = crank.offset if crank is not None else 0.0
    cylinder = Cylinder(engine.bore, engine.stroke, rod, ratio, offset)
    speeds = [c.speed for c in conditions]
    (intake, in_lift, in_cd), (exhaust, ex_lift, ex_cd) = (
        valve_flow(getattr(b, kind), kind, valves, views, engine, speeds) for kind in ("intake", "exhaust"))
    runners = [None if s.runner_length is None else Runner(s.runner_length, s.runner_diameter, b.cell)
               for s in (b.intake, b.exhaust)]
    firing = None
    if b.mode == "fired":
        cy = crank.cycle
        firing = Firing(b.fuel, b.equivalence_ratio, cy.combustion_start, cy.combustion_duration, cy.wiebe_a,
                        cy.wiebe_m, b.combustion_efficiency)
    described = Engine(cylinder, intake[0], exhaust[0], *runners, b.heat_transfer == "woschni", firing,
                       engine.cylinders)
    engines = tuple(replace(described, intake=intake[i % len(intake)], exhaust=exhaust[i % len(exhaust)])
                    for i in range(len(speeds)))
    return engines, (in_lift, ex_lift, in_cd, ex_cd)


def condition_of(state, speed, b) -> Condition:
    """The physics' condition of a plenum state of [breathing] (a condition or the curve) at ``speed`` [rad/s]."""
    wall = state.wall_temperature_C if state.wall_temperature_C is not None else b.wall_temperature_C
    exhaust_t = None if state.exhaust_temperature_C is None else state.exhaust_temperature_C + KELVIN
    return Condition(speed, Plenum(state.intake_pressure, state.intake_temperature_C + KELVIN),
                     Plenum(state.exhaust_pressure, exhaust_t), wall + KELVIN)


def curve_speeds(curve) -> np.ndarray:
    """The speeds of [breathing.curve] [rad/s]: ``points`` evenly over ``speed_range``."""
    return np.linspace(curve.speed_range[0], curve.speed_range[1], curve.points)


def breathing_records(engines, conditions, tolerance, max_cycles, curve=False) -> tuple[BreathingResult, ...]:
    """The breathing of ``engines`` (one :class:`~valvetrain.breathing.Engine`, or one a condition) at each condition
    (:func:`valvetrain.breathing.breathe`), in order: the pure function from a design's engine to its per-speed
    results (the designer redraws its curve with it).  A ``curve`` (one plenum state at increasing speeds) starts each
    speed from the previous one's converged state."""
    if isinstance(engines, Engine):
        engines = [engines] * len(conditions)
    out, state = [], None
    for engine, c in zip(engines, conditions, strict=True):
        out.append(breathe(engine, c, tolerance, max_cycles, state))
        state = out[-1].state if curve else None
    return tuple(out)


def breathing_conditions(b) -> tuple[list[Condition], list[Condition]]:
    """The physics' conditions of [breathing] ``b`` (its SI view): those of [[breathing.conditions]] and the speeds
    of [breathing.curve], in order."""
    given = [condition_of(c, c.speed, b) for c in b.conditions]
    swept = [] if b.curve is None else [condition_of(b.curve, n, b) for n in curve_speeds(b.curve)]
    return given, swept


def breathe_conditions(engines, b, given, swept) -> tuple[tuple[BreathingResult, ...], tuple[BreathingResult, ...]]:
    """The breathing of ``engines`` (:func:`breathing_engine`: one a condition of ``given``, then one a speed of
    ``swept``) at the conditions ``given`` (each from the plenums' state) and along the curve ``swept`` (each speed
    from the previous one's converged state) with the tolerance and the cycles of [breathing] ``b``: what the chapter
    and a cam synthesis by the breathing compute alike.

    Raises
    ------
    BreathingError
        More work than :data:`~valvetrain.breathing.cycle.MAX_WORK` asked for (refused before it runs).
    """
    asked = sum(work(e, c, b.max_cycles) for e, c in zip(engines, given + swept, strict=True))
    if asked > MAX_WORK:
        raise BreathingError(NoteText(note("breathing.work", conditions=len(given), speeds=len(swept),
                                           cycles=b.max_cycles, cell_mm=b.cell / MM, asked=asked, most=MAX_WORK)))
    return (breathing_records(engines[:len(given)], given, b.cycle_tolerance, b.max_cycles),
            breathing_records(engines[len(given):], swept, b.cycle_tolerance, b.max_cycles, curve=True))


def speed_mean(results, name) -> float:
    """The mean of the figure ``name`` (``volumetric_efficiency``, ``torque``) over the breathing's results (every
    condition and curve speed weighs the same): the objective of a cam synthesis by the breathing."""
    return float(np.mean([getattr(r.figures, name) for r in results]))


def cycle_check(figures, tolerance, code="breathing.cycle_change", **params) -> Check:
    """The check that a condition's cycles repeat: its last cycle's relative change (``figures``, a
    :class:`~valvetrain.breathing.cycle.BreathingRecord`) within ``tolerance``, its speed and ``params`` (display
    texts) the check's parameters; the breathing chapter's, or another stage's ``code`` that breathes again."""
    return check(code, figures.cycle_change, high=tolerance,
                 source=cited(note("source.cycles_repeat", work="Heywood (1988), chapter 14")),
                 params={"speed": f"{to_display(figures.speed, 'rpm'):.5g}", **params})


def breathing_stage(b, engine, crank, valves, views) -> BreathingResults:
    """Run the breathing chapter: ``b``, ``engine`` and ``crank`` are the SI views of [breathing], [engine] and
    [crank] (or None), ``valves`` the designed valves and ``views`` their SI views; returns
    :class:`BreathingResults`."""
    given, swept = breathing_conditions(b)
    engines, words = breathing_engine(b, engine, crank, valves, views, given + swept)
    conditions, curve = breathe_conditions(engines, b, given, swept)
    found = [cycle_check(r.figures, b.cycle_tolerance) for r in conditions + curve if not r.converged]
    found += [check("breathing.air_flow", r.figures.air_mass_flow, low=0.0, unit="g/s",
                    source=cited(note("source.air_delivered", work="Heywood (1988), section 6.2")),
                    params={"speed": f"{to_display(r.figures.speed, 'rpm'):.5g}"})
              for r in conditions + curve if r.figures.air_mass_flow < 0.0]
    figures = BreathingSummary(b.mode, *words, tuple(r.figures for r in conditions), tuple(r.figures for r in curve))
    return BreathingResults(engines, conditions, curve, figures, tuple(found))


def _ports(columns, kind) -> np.ndarray:
    """The pressure at the ``kind`` side's valves over the converged cycle [Pa]: the runner's last cell (the plenum's
    without a runner)."""
    return columns.intake_port if kind == "intake" else columns.exhaust_port


CYCLE_SOURCE_NOTES = {"motored": "breathing.cycle_source_motored", "fired": "breathing.cycle_source_fired"}
"""The ``[notes]`` code of the cylinder pressure's source of :func:`cylinder_pressure`, by the breathing's mode."""


def cylinder_pressure(results, speed, kind=None) -> CylinderPressure:
    """The cylinder pressure of the breathing's converged cycle whose speed is nearest ``speed`` [rad/s] (the
    conditions first, then the curve), for the chapters that read the cylinder pressure (the crank's torque, the
    hydraulic valve's gas force), with the words of its source; with ``kind`` ("intake" or "exhaust") also the
    pressure at that side's valves (the port behind the valve head)."""
    chosen = min((*results.conditions, *results.curve), key=lambda r: abs(r.figures.speed - speed))
    f, c = chosen.figures, chosen.columns
    said = note(CYCLE_SOURCE_NOTES[results.figures.mode], speed_rpm=to_display(f.speed, "rpm"),
                plenum_kPa=f.intake_pressure / 1e3)
    return CylinderPressure(c.angle, c.pressure, NoteText(said),
                            None if kind is None else _ports(c, kind))


GAS_LOAD_NOTES = {"motored": "breathing.gas_load_motored", "fired": "breathing.gas_load_fired"}
"""The ``[notes]`` code of the closed-valve gas load of :func:`gas_opening_load`, by the breathing's mode."""


def gas_opening_load(results, kind, diameter) -> tuple[float, str]:
    """The largest gas force that tends to open the closed valve of ``kind`` over the breathing's converged cycles,
    and the words of where it comes from.

    Parameters
    ----------
    results : BreathingResults
    kind : {"intake", "exhaust"}
    diameter : float
        Throat diameter of the valve [m] (the area of :func:`valvetrain.springs.gas_opening_force`).

    Returns
    -------
    (float, Note)
        f_g max(p_port - p_cyl, 0) [N] over every condition and curve speed and every crank angle at which the
        side's valves are shut (their effective areas zero), p_port the pressure at that side's valves (the runner's
        last cell, the plenum's without a runner), and the speed and crank angle where it is largest
        (:func:`valvetrain.locale.note`, a code of :data:`GAS_LOAD_NOTES`).

    Notes
    -----
    The sources' closed-valve gas load (5.4) and (5.5) with the breathing's own pressures: the spring holds the
    valve shut at every condition, so the largest of them is the load.

    References
    ----------
    Valve-train practical works (n.d.), work 5, eqs. (5.4), (5.5).
    """
    best = None
    for engine, r in zip(results.engines, (*results.conditions, *results.curve), strict=True):
        c = r.columns
        forward, reverse = getattr(engine, kind).areas(c.angle)
        port = _ports(c, kind)
        difference = np.where((forward == 0.0) & (reverse == 0.0), port - c.pressure, -np.inf)
        i = int(np.argmax(difference))
        if best is None or difference[i] > best[0]:
            best = (difference[i], r, i)
    _, r, i = best
    c = r.columns
    port = _ports(c, kind)[i]
    force = gas_opening_force(diameter, port, c.pressure[i])
    return force, note(GAS_LOAD_NOTES[results.figures.mode], port_kPa=float(port / 1e3),
                       cylinder_kPa=float(c.pressure[i] / 1e3), speed_rpm=float(to_display(r.figures.speed, "rpm")),
                       crank_deg=float(np.degrees(c.angle[i])), equation="5.5" if kind == "intake" else "5.4")
