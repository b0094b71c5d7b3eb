"""Two-step lift of a switching roller finger (``mode = "two_step"`` of ``[valves.NAME.switching]``, its
``low_lobe``): the second, low-lift lobe's law, events, flow time-area and profile, the arm's lost motion between the
two lobes and, with ``[breathing]``, each mode's breathing.

Latched, the valve is the finger's of the valve's own chapters (the main lobe).  Unlatched, the finger's body follows
the low lobe and lifts the valve by its law, and the inner arm follows the main lobe against the lost-motion spring:
the arm turns in the body by phi = (u - u_b) / L_i, u and u_b the roller centre's travels on the two lobes
(:func:`valvetrain.switching.roller_travel`; the body's contact on the low lobe taken at the roller's place, of the
roller's radius).  The stage that uses it is :func:`valvetrain.design.switching.switching_stage`.
"""

from dataclasses import dataclass, replace

import numpy as np

from ..breathing import ValveFlow
from ..locale import NoteText, note
from ..specification.messages import Problem, SpecError, said
from .breathing import GRID, breathing_conditions, breathing_records, cd_table, cycle_check, designed_lift
from .lost_motion_breathing import count_areas
from .results import quantity
from .valve import CamResult, FlowResult, ProfileResult, flow_stage, law_stage, profile_stage

KEY = "switching.low_lobe"
"""The key of the second lobe within ``[valves.NAME]``."""

ABOVE = 1e-7
"""How far [m] the low lobe's roller travel may rise above the main lobe's (round-off) before it is refused."""


@dataclass(frozen=True)
class LowLobe:
    """The second lobe of a two-step finger: its law stage, flow and profile (SI), and its nose's shift from the main
    lobe's [camshaft rad]."""

    cam: CamResult
    flow: FlowResult
    profile: ProfileResult
    shift: float

    def derivatives(self, theta) -> np.ndarray:
        """The low lobe's valve lift h [m] and its derivatives by the camshaft angle, at ``theta`` [camshaft rad from
        the main lobe's nose], shape (4, n)."""
        return self.cam.law.derivatives(np.asarray(theta) + self.shift)


@dataclass(frozen=True)
class ModeBreath:
    """The breathing at one condition of ``[[breathing.conditions]]`` in one mode of a two-step finger."""

    mode: str = quantity("mode", label="latched (the main lobe) or unlatched (the low lobe)")
    speed: float = quantity("speed_rpm", "rpm", "crank speed of the condition")
    trapped_mass: float = quantity("trapped_mass_mg", "mg", "mass in the cylinder at the intake valve's closing")
    volumetric_efficiency: float = quantity("volumetric_efficiency", label="air delivered per cycle over the swept "
                                            "volume's mass at the intake plenum's density")
    residual_gas_fraction: float = quantity("residual_gas_fraction", label="share of the trapped mass that was not "
                                            "fresh charge")
    pmep: float = quantity("pmep_kPa", "kPa", "pumping mean effective pressure")
    imep: float = quantity("imep_kPa", "kPa", "net indicated mean effective pressure")
    converged: bool = quantity("converged", label="the cycles repeat within the tolerance")


def low_lobe(name, lobe, valve, engine, output, main) -> LowLobe:
    """The second lobe of the valve ``name``: the valve's own cam section's law with the lobe's largest lift and
    events (:func:`~valvetrain.design.valve.law_stage`, :func:`~valvetrain.design.valve.flow_stage`,
    :func:`~valvetrain.design.valve.profile_stage` on the valve's SI view with ``max_lift``, ``opens`` and
    ``closes`` replaced).

    Parameters
    ----------
    name : str
    lobe : SI view of ``[valves.NAME.switching.low_lobe]``
    valve, engine, output : SI views of the valve, [engine] and [output]
    main : CamResult
        The valve's own (main) lobe.

    Raises
    ------
    SpecError
        A lobe its law cannot make or whose profile is undercut, naming ``switching.low_lobe``.
    """
    view = replace(valve, max_lift=lobe.max_lift, opens=lobe.opens, closes=lobe.closes)
    at = f"valves.{name}.{KEY}"
    try:
        cam = law_stage(view, engine)
    except ValueError as exc:
        problem = exc.args[0] if exc.args and isinstance(exc.args[0], Problem) else Problem("", said(exc))
        raise SpecError([Problem(at, NoteText(note("spec.second_lobe", problem=problem.note())))]) from None
    profile = profile_stage(cam, view, output)
    if profile.undercut:
        raise SpecError([Problem(at, NoteText(note("spec.second_lobe_undercut")))])
    return LowLobe(cam, flow_stage(cam, view, engine), profile, (main.nose - cam.nose) / 2.0)


def lobe_grid(main, lobe, samples=2001) -> np.ndarray:
    """Camshaft angles [rad from the main lobe's nose] over both lobes' events, their breakpoints included."""
    law, low = main.law, lobe.cam.law
    start, end = min(law.start, low.start - lobe.shift), max(law.end, low.end - lobe.shift)
    return np.unique(np.concatenate([np.linspace(start, end, samples), law.breakpoints,
                                     low.breakpoints - lobe.shift]))


def below_main(name, theta, u_main, u_low) -> None:
    """Refuse a low lobe whose roller travel ``u_low`` rises above the main lobe's ``u_main`` [m] at any of the
    camshaft angles ``theta`` [rad]: latched, the body would ride it and the arm leave the main lobe."""
    over = u_low - u_main
    if over.max() > ABOVE:
        at = int(np.argmax(over))
        raise SpecError([Problem(f"valves.{name}.{KEY}", NoteText(note(
            "spec.second_lobe_above", above=over[at] * 1e3, angle=np.degrees(theta[at]))))])


def lift_on_grid(cam) -> np.ndarray:
    """The valve lift of the law stage ``cam`` on the breathing's crank-angle grid
    (:data:`~valvetrain.design.breathing.GRID`) [m]: the camshaft angle (c - nose) / 2 wrapped into one revolution."""
    theta = np.mod((GRID - cam.nose) / 2.0 + np.pi, 2.0 * np.pi) - np.pi
    return np.asarray(cam.valve_lift(theta))


def mode_breathing(name, design, view, lobe, breathing, b) -> tuple[tuple[ModeBreath, ...], list]:
    """Each mode's breathing at each condition of ``[[breathing.conditions]]``: latched the breathing chapter's own,
    unlatched the chapter's engines with this valve's designed lift replaced by the low lobe's (its ``count`` valves'
    effective areas, :func:`~valvetrain.design.breathing.lift_areas`).

    Parameters
    ----------
    name : str
    design : ValveDesign
        The designed valve (latched).
    view : SI view of ``[valves.NAME]``
    lobe : LowLobe
    breathing : BreathingResults
    b : SI view of ``[breathing]``

    Returns
    -------
    (tuple of ModeBreath, list of Check)
        The rows, latched then unlatched, each in the conditions' order; the checks that the unlatched cycles repeat
        (:func:`~valvetrain.design.breathing.cycle_check`, those that do not).

    Raises
    ------
    SpecError
        A side whose lift is not the designed one (``lift = "dynamics"`` or a measured lift), naming
        ``switching.low_lobe``: the unlatched mode replaces the designed lift.
    """
    kind = design.kind
    side = getattr(b, kind)
    if side.measured_lift is not None or side.lift == "dynamics":
        raise SpecError([Problem(f"valves.{name}.{KEY}", NoteText(note("spec.unlatched_breathing", kind=kind)))])
    table = cd_table(side)
    given, _ = breathing_conditions(b)
    engines = breathing.engines[:len(given)]
    own_forward, own_reverse = count_areas(designed_lift(design), table, view, design.count)
    forward, reverse = count_areas(lift_on_grid(lobe.cam), table, view, design.count)
    low = [replace(e, **{kind: ValveFlow(GRID, getattr(e, kind).forward - own_forward + forward,
                                         getattr(e, kind).reverse - own_reverse + reverse)}) for e in engines]
    unlatched = breathing_records(low, given, b.cycle_tolerance, b.max_cycles)
    rows = tuple(_row(mode, out) for mode, runs in (("latched", breathing.conditions), ("unlatched", unlatched))
                 for out in runs)
    return rows, [cycle_check(out.figures, b.cycle_tolerance) for out in unlatched if not out.converged]


def _row(mode, out) -> ModeBreath:
    g = out.figures
    return ModeBreath(mode, g.speed, g.trapped_mass, g.volumetric_efficiency, g.residual_gas_fraction, g.pmep, g.imep,
                      out.converged)

