"""Breathing stage: the gas exchange of the engine's cylinders through the designed (or measured) valves, converged
over cycles at each condition of ``[breathing]`` (:mod:`valvetrain.breathing`)."""

from dataclasses import dataclass
from functools import cached_property
from typing import Any

import numpy as np

from ..breathing import (BreathingError, CdTable, Condition, Cylinder, Engine, Firing, Plenum, Runner, ValveFlow,
                         breathe)
from ..breathing.cycle import MAX_WORK, BreathingRecord, BreathingResult, work
from ..breathing.valves import DEFAULT_CD, default_areas, effective_areas
from ..checks import Check, check
from ..units import MM, to_display
from .hydraulic_actuation import CylinderPressure
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

    engine: Engine
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


def _designed_lift(valve):
    """A designed valve's lift on :data:`GRID` [m] (its timing diagram's, :attr:`ValveDesign.cycle_lift`)."""
    order = np.argsort(np.mod(CYCLE_CRANK, 4.0 * np.pi), kind="stable")
    angle = np.mod(CYCLE_CRANK, 4.0 * np.pi)[order]
    keep = np.concatenate([[True], np.diff(angle) > 0.0])
    return np.interp(GRID, angle[keep], valve.cycle_lift[order][keep], period=4.0 * np.pi)


def valve_flow(side, kind, valves, views) -> tuple[ValveFlow, str, str]:
    """One side's effective areas over the cycle and the words of where its lift and discharge come from.

    Parameters
    ----------
    side : SI view of [breathing.intake] or [breathing.exhaust]
    kind : {"intake", "exhaust"}
    valves : dict
        The designed valves (``name -> ValveDesign``).
    views : dict
        Their SI views (``name -> view``: the throat and the seat of the flow section).

    Returns
    -------
    (ValveFlow, str, str)
    """
    table = None
    if side.cd is not None:
        x, fwd, rev = side.cd
        table = CdTable(x, fwd, rev, side.cd_diameter, side.cd_reference, side.section.cd_file)
        discharge = (f"C_D(L/D) of {side.section.cd_file}, referred to the {side.cd_reference} area of D = "
                     f"{side.cd_diameter / MM:g} mm")
    else:
        discharge = f"C_D = {DEFAULT_CD:g} on the flow section, at most the throat (assumed, no measured table)"
    if side.lift is not None:
        lifts = [(_on_grid(*side.lift), side.valves, None)]
        source = f"measured, {side.section.lift_file}, {side.valves} valve{'s' if side.valves > 1 else ''}"
    else:
        these = [(name, v) for name, v in valves.items() if v.kind == kind]
        lifts = [(_designed_lift(v), v.count, views[name]) for name, v in these]
        source = "designed: " + ", ".join(f"{name} ({v.law.name}, {v.count} valve{'s' if v.count > 1 else ''})"
                                          for name, v in these)
    forward, reverse = np.zeros_like(GRID), np.zeros_like(GRID)
    for lift, count, valve in lifts:
        if table is not None:
            f, r = effective_areas(lift, table)
        else:
            f = r = default_areas(lift, valve.throat_diameter, valve.seat_angle)
        forward += count * f
        reverse += count * r
    return ValveFlow(GRID, forward, reverse), source, discharge


def breathing_engine(b, engine, crank, valves, views) -> tuple[Engine, tuple[str, str, str, str]]:
    """The engine as the breathing sees it, from the SI views of [breathing], [engine] and [crank] (None) and the
    designed valves with their SI views; and the words of each side's lift and discharge.

    Returns
    -------
    (valvetrain.breathing.Engine, tuple of str)
    """
    rod = crank.rod_length if crank is not None and crank.rod_length is not None else engine.rod_length
    ratio = b.compression_ratio if b.compression_ratio is not None else crank.compression_ratio
    offset = crank.offset if crank is not None else 0.0
    cylinder = Cylinder(engine.bore, engine.stroke, rod, ratio, offset)
    (intake, in_lift, in_cd), (exhaust, ex_lift, ex_cd) = (valve_flow(getattr(b, kind), kind, valves, views)
                                                           for kind in ("intake", "exhaust"))
    runners = [None if s.runner_length is None else Runner(s.runner_length, s.runner_diameter, b.cell)
               for s in (b.intake, b.exhaust)]
    firing = None
    if b.mode == "fired":
        cy = crank.cycle
        firing = Firing(b.fuel, b.equivalence_ratio, cy.combustion_start, cy.combustion_duration, cy.wiebe_a,
                        cy.wiebe_m, b.combustion_efficiency)
    described = Engine(cylinder, intake, exhaust, *runners, b.heat_transfer == "woschni", firing, engine.cylinders)
    return described, (in_lift, ex_lift, in_cd, ex_cd)


def condition_of(state, speed, b) -> Condition:
    """The physics' condition of a plenum state of [breathing] (a condition or the curve) at ``speed`` [rad/s]."""
    wall = state.wall_temperature_C if state.wall_temperature_C is not None else b.wall_temperature_C
    exhaust_t = None if state.exhaust_temperature_C is None else state.exhaust_temperature_C + KELVIN
    return Condition(speed, Plenum(state.intake_pressure, state.intake_temperature_C + KELVIN),
                     Plenum(state.exhaust_pressure, exhaust_t), wall + KELVIN)


def curve_speeds(curve) -> np.ndarray:
    """The speeds of [breathing.curve] [rad/s]: ``points`` evenly over ``speed_range``."""
    return np.linspace(curve.speed_range[0], curve.speed_range[1], curve.points)


def breathing_records(engine, conditions, tolerance, max_cycles, curve=False) -> tuple[BreathingResult, ...]:
    """The breathing of ``engine`` at each condition (:func:`valvetrain.breathing.breathe`), in order: the pure
    function from a design's engine to its per-speed results (the designer redraws its curve with it).  A ``curve``
    (one plenum state at increasing speeds) starts each speed from the previous one's converged state."""
    out, state = [], None
    for c in conditions:
        out.append(breathe(engine, c, tolerance, max_cycles, state))
        state = out[-1].state if curve else None
    return tuple(out)


def breathing_stage(b, engine, crank, valves, views) -> BreathingResults:
    """Run the breathing chapter: ``b``, ``engine`` and ``crank`` are the SI views of [breathing], [engine] and
    [crank] (or None), ``valves`` the designed valves and ``views`` their SI views; returns
    :class:`BreathingResults`."""
    described, words = breathing_engine(b, engine, crank, valves, views)
    given = [condition_of(c, c.speed, b) for c in b.conditions]
    swept = [] if b.curve is None else [condition_of(b.curve, n, b) for n in curve_speeds(b.curve)]
    asked = sum(work(described, c, b.max_cycles) for c in given + swept)
    if asked > MAX_WORK:
        raise BreathingError(f"{len(given)} conditions and {len(swept)} curve speeds at up to {b.max_cycles} cycles "
                             f"of the runners' cells (cell_mm = {b.cell / MM:g}) ask for {asked:.3g} cell-steps; "
                             f"allowed at most {MAX_WORK:.3g} (about half a minute): fewer conditions or curve points, "
                             "a coarser cell_mm, fewer max_cycles or higher speeds")
    results = (breathing_records(described, given, b.cycle_tolerance, b.max_cycles)
               + breathing_records(described, swept, b.cycle_tolerance, b.max_cycles, curve=True))
    found = [check("breathing.cycle_change", r.figures.cycle_change, high=b.cycle_tolerance,
                   source="the cycles repeat (Heywood (1988), chapter 14: a cycle simulation runs until its state "
                          "repeats)", params={"speed": f"{to_display(r.figures.speed, 'rpm'):.5g}"})
             for r in results if not r.converged]
    figures = BreathingSummary(b.mode, *words, tuple(r.figures for r in results[:len(given)]),
                               tuple(r.figures for r in results[len(given):]))
    return BreathingResults(described, results[:len(given)], results[len(given):], figures, tuple(found))



def cylinder_pressure(results, speed) -> CylinderPressure:
    """The cylinder pressure of the breathing's converged cycle whose speed is nearest ``speed`` [rad/s] (the
    conditions first, then the curve), for the chapters that read the cylinder pressure (the crank's torque, the
    hydraulic valve's gas force), with the words of its source."""
    chosen = min((*results.conditions, *results.curve), key=lambda r: abs(r.figures.speed - speed))
    f = chosen.figures
    return CylinderPressure(chosen.columns.angle, chosen.columns.pressure,
                            f"the breathing's converged {results.figures.mode} cycle at {to_display(f.speed, 'rpm'):.5g} "
                            f"rpm, intake plenum {f.intake_pressure / 1e3:.5g} kPa")
