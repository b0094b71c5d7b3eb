"""The breathing of a lost-motion intake's early closings (``[valves.NAME.hydraulic.lost_motion]`` with
``[breathing]``): the trapped air and the pumping loss of the full lift and of each solenoid timing, the breathing
chapter's engines with the valve's lift replaced by the drive's (:mod:`valvetrain.design.lost_motion`)."""

from dataclasses import replace

import numpy as np

from ..breathing import ValveFlow
from ..breathing.cycle import CYCLE, MAX_WORK, BreathingError, work
from ..checks import Check
from ..locale import NoteText, note, note_of
from ..specification.messages import Problem, SpecError, said
from ..units import to_display
from .breathing import GRID, breathing_conditions, breathing_records, cd_table, cycle_check, designed_lift, lift_areas
from .hydraulic_actuation import cycle_angle
from .lost_motion import KEY, ClosingBreath, LostMotionResult


def lift_on_grid(r, nose, strokes) -> np.ndarray:
    """The valve lift of the drive's response ``r`` on the breathing's crank-angle grid
    (:data:`~valvetrain.design.breathing.GRID`) [m], the camshaft angle theta at the cycle angle of
    :func:`~valvetrain.design.hydraulic_actuation.cycle_angle`, periodic over the cycle."""
    crank = cycle_angle(nose, r.angle, strokes)
    order = np.argsort(crank, kind="stable")
    return np.interp(GRID, crank[order], np.clip(r.valve_lift[order], 0.0, None), period=CYCLE)


def with_breathing(result, name, design, view, breathing, b) -> tuple[LostMotionResult, list[Check]]:
    """The lost-motion result with the breathing of the full lift and of each solenoid timing at each condition of
    ``[[breathing.conditions]]`` (the chapter's engines with this valve's lift replaced), and the checks that the
    cycles repeat.

    Parameters
    ----------
    result : LostMotionResult
    name : str
    design : ValveDesign
        The designed valve (its kind, count and designed lift).
    view : SI view of ``[valves.NAME]``
    breathing : BreathingResults
        The breathing chapter (its engines, one a condition).
    b : SI view of ``[breathing]``

    Raises
    ------
    SpecError
        More work than :data:`~valvetrain.breathing.cycle.MAX_WORK` asked for, naming the timings' key; a lift
        the breathing cannot run (a drive that never opens the valve or never lets it close), naming the drive or the
        timings.

    Notes
    -----
    The side's effective areas are the chapter's less this valve's designed lift's and plus the drive's lift's, each
    count x A(lift) (:func:`~valvetrain.design.breathing.lift_areas`), so that the full lift breathes as the drive
    lifts the valve (its compressed oil's lift, not the cam's) and each timing as its early closing does.  The lift
    is the drive's at the hydraulic chapter's speed, whatever the condition's speed.
    """
    kind = design.kind
    side = getattr(b, kind)
    table = cd_table(side)
    given, _ = breathing_conditions(b)
    engines = breathing.engines[:len(given)]
    own_forward, own_reverse = count_areas(designed_lift(design), table, view, design.count)
    runs = [(None, result.full_lift_closes, result.full)] + [
        (c.solenoid_opens, c.valve_closes, r) for c, r in zip(result.closings, result.responses, strict=True)]
    asked = len(runs) * sum(work(e, c, b.max_cycles) for e, c in zip(engines, given, strict=True))
    if asked > MAX_WORK:
        raise SpecError([Problem(f"valves.{name}.hydraulic.lost_motion.{KEY}", NoteText(note(
            "spec.timings_work", timings=len(runs) - 1, conditions=len(given), asked=asked, most=MAX_WORK)),
                                 f"{[to_display(a, 'crank deg') for a in view.hydraulic.lost_motion.solenoid_opens]}")])
    rows, found = [], []
    for opens, closes, r in runs:
        f, rev = count_areas(lift_on_grid(r, result.nose, result.strokes), table, view, design.count)
        flows = [getattr(e, kind) for e in engines]
        lifted = [replace(e, **{kind: ValveFlow(GRID, flow.forward - own_forward + f,
                                                flow.reverse - own_reverse + rev)})
                  for e, flow in zip(engines, flows, strict=True)]
        try:
            records = breathing_records(lifted, given, b.cycle_tolerance, b.max_cycles)
        except BreathingError as exc:
            which = (note("spec.full_lift") if opens is None else
                     note("spec.solenoid_timing", opens=to_display(opens, "crank deg")))
            raise SpecError([Problem(f"valves.{name}.hydraulic" + ("" if opens is None else f".lost_motion.{KEY}"),
                                     NoteText(note("spec.breathing_of", which=which,
                                                   lift=to_display(float(r.valve_lift.max()), "mm"),
                                                   error=note_of(said(exc)))))]) from None
        for c, out in zip(given, records, strict=True):
            g = out.figures
            rows.append(ClosingBreath(opens, closes, g.speed, g.intake_pressure, g.trapped_mass,
                                      g.volumetric_efficiency, g.residual_gas_fraction, g.pmep, g.imep, out.converged))
            if not out.converged:
                found.append(cycle_check(g, b.cycle_tolerance))
    return replace(result, breathing=tuple(rows)), found


def count_areas(lift, table, view, count) -> tuple[np.ndarray, np.ndarray]:
    """``count`` valves' forward and reverse effective areas at the lifts ``lift`` [m^2]
    (:func:`~valvetrain.design.breathing.lift_areas`)."""
    f, r = lift_areas(lift, table, view)
    return count * f, count * r


__all__ = ["count_areas", "lift_on_grid", "with_breathing"]
