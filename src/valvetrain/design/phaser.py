"""Phaser stage: a cam phaser on the camshaft of a valve (``[valves.NAME.phaser]``): the valve's events moved by the
phase, the breathing over a map of phase x speed and the best phase at each speed, the valve-to-piston gap at the
ends of the range, and the torque the phaser holds.

A phase is an advance in crank degrees, positive earlier: the phased valve's lift at crank angle theta is the designed
lift at theta + advance, so it opens and closes ``advance`` crank degrees sooner (``advance / 2`` camshaft degrees
of a four-stroke).  The phaser turns the camshaft against its drive and changes nothing else: the lift law about
the camshaft, the camshaft's speed and so the valve train's dynamics at a given speed are those of phase 0; what
changes is where the events fall in the engine's cycle: the gas exchange and the piston's position under the open
valve.
"""

from dataclasses import dataclass, field, replace
from functools import cached_property
from typing import Any, Optional

import numpy as np
from scipy.optimize import minimize_scalar

from .. import camshaft as shaft
from ..breathing import BreathingError, ValveFlow
from ..breathing.cycle import MAX_WORK, work
from ..checks import Check, check
from ..locale import NoteText, cited, note, note_of
from ..specification.messages import Problem, SpecError, said
from ..units import to_display
from .breathing import (BreathingResults, breathe_conditions, breathing_conditions, breathing_records, cycle_check,
                        gas_opening_load)
from .camshaft import ANGLES, camshaft_torque, lobe_set
from .crank import firing_angles
from .drive_strength import strength_stage
from .results import quantity, record
from .valve import clearance_stage
from .valve_checks import PISTON_CLEARANCE_MIN, PISTON_CLEARANCE_SOURCE

OBJECTIVES = {"fired": "torque", "motored": "volumetric_efficiency"}
"""The figure the best phase maximises, by [breathing] mode: the indicated torque of a fired engine, the volumetric
efficiency of a motored one (no torque)."""

GAS_LOAD_OVER_MAP = {"motored": "phaser.gas_load_over_map_motored", "fired": "phaser.gas_load_over_map_fired"}
"""The ``[notes]`` code of the largest closed-valve gas load over the phaser's map, by the breathing's mode: the
phase's advance and the numbers of the breathing's own note (:func:`.breathing.gas_opening_load`)."""


GOLDEN = (1.0 + np.sqrt(5.0)) / 2.0
"""The golden ratio: a bounded Brent search's golden-section steps narrow its interval by this factor each."""

SEARCH_EVALUATIONS = 3
"""The evaluations of a bounded Brent search counted beyond those of golden-section steps from its interval (twice the
map's step) to its tolerance, for the work a map asks for: 13 in all for the shipped example's 20 deg at 0.5 deg,
which takes 5 to 8 (its parabolic steps converge faster)."""


def phased_flow(flow, advance) -> ValveFlow:
    """The effective areas of ``flow`` (a side's :class:`~valvetrain.breathing.ValveFlow`) with every event
    ``advance`` crank radians earlier: A_phased(theta) = A(theta + advance), the same areas at the angles less the
    advance (phase 0 is ``flow``'s own angles, unchanged).

    >>> f = phased_flow(ValveFlow(np.array([0.0, 1.0, 2.0]), np.array([0.0, 1.0, 0.0]), np.zeros(3)), 0.5)
    >>> [float(a) for a in f.areas(np.array([0.5, 1.0]))[0]]
    [1.0, 0.5]
    """
    return ValveFlow(flow.angle - advance, flow.forward, flow.reverse)


def advances(phaser) -> np.ndarray:
    """The map's phases [crank rad]: evenly from the range's low to its high end at most ``step`` apart, and 0 (a
    phase of the grid within round-off of 0 is 0, not a second point beside it)."""
    low, high = phaser.advance_range
    n = int(np.ceil((high - low) / phaser.step * (1.0 - 1e-12))) + 1
    grid = np.linspace(low, high, n)
    return np.unique(np.concatenate([np.where(np.abs(grid) <= 1e-9 * (high - low), 0.0, grid), [0.0]]))


@dataclass(frozen=True)
class PhasedEvents:
    """The valve's events at one phase (crank angles from the gas-exchange TDC)."""

    advance: float = quantity("advance_crank_deg", "crank deg", "the phase, an advance positive (the events earlier)")
    opens: float = quantity("valve_opens_crank_deg", "crank deg", "where the valve leaves its seat")
    closes: float = quantity("valve_closes_crank_deg", "crank deg", "where the valve meets its seat")
    min_gap: Optional[float] = quantity("min_piston_clearance_mm", "mm", "smallest valve-to-piston gap over the open "
                                        "event (with piston_gap_tdc_mm)", omit_none=True)
    min_gap_angle: Optional[float] = quantity("min_piston_clearance_crank_deg", "crank deg", "where",
                                              omit_none=True)


@dataclass(frozen=True)
class OpeningLoad:
    """An exhaust valve's opening at one phase of the range (its ends and 0): the cylinder and port pressures as it
    leaves its seat (the breathing's cycles at that phase, the condition where their difference is largest), the gas
    force on its head, and the strength chapter's largest cam force and cam contact stress with that force."""

    advance: float = quantity("advance_crank_deg", "crank deg", "the phase, an advance positive")
    speed: float = quantity("speed_rpm", "rpm", "the condition's speed where the pressure difference is largest")
    cylinder_pressure: float = quantity("cylinder_pressure_at_opening_MPa", "MPa", "the cylinder's pressure where the "
                                        "valve leaves its seat")
    port_pressure: float = quantity("port_pressure_at_opening_MPa", "MPa", "the exhaust port's there")
    gas_force: float = quantity("gas_force_at_opening_N", "N", "the gas force on the valve head as it opens "
                                "(eq. 7.1)")
    cam_force: float = quantity("cam_force_max_N", "N", "the largest cam force with that gas force (the strength "
                                "chapter's method)")
    contact_stress: Optional[float] = quantity("cam_contact_stress_max_MPa", "MPa", "the largest cam contact stress "
                                               "with it (with parts.cam_width_mm)", omit_none=True, default=None)


@dataclass(frozen=True)
class PhaserPoint:
    """The breathing at one phase and one condition of [breathing] (a point of the map)."""

    advance: float = quantity("advance_crank_deg", "crank deg", "the phase, an advance positive")
    speed: float = quantity("speed_rpm", "rpm", "crank speed")
    intake_pressure: float = quantity("intake_pressure_kPa", "kPa", "intake plenum pressure")
    volumetric_efficiency: float = quantity("volumetric_efficiency", label="air delivered per cycle over the swept "
                                            "volume's mass at the intake plenum's density")
    residual_gas_fraction: float = quantity("residual_gas_fraction", label="share of the trapped mass that was not "
                                            "fresh charge")
    pmep: float = quantity("pmep_kPa", "kPa", "pumping mean effective pressure")
    torque: Optional[float] = quantity("torque_Nm", "N m", "indicated torque of the engine (fired)", omit_none=True)


@dataclass(frozen=True)
class BestPhase:
    """The phase that maximises the objective at one condition of [breathing], and the breathing there."""

    speed: float = quantity("speed_rpm", "rpm", "crank speed")
    intake_pressure: float = quantity("intake_pressure_kPa", "kPa", "intake plenum pressure")
    advance: float = quantity("advance_crank_deg", "crank deg", "the best phase, an advance positive")
    volumetric_efficiency: float = quantity("volumetric_efficiency", label="volumetric efficiency there")
    residual_gas_fraction: float = quantity("residual_gas_fraction", label="residual gas fraction there")
    pmep: float = quantity("pmep_kPa", "kPa", "pumping mean effective pressure there")
    torque: Optional[float] = quantity("torque_Nm", "N m", "indicated torque there (fired)", omit_none=True)
    gain: float = quantity("gain_percent", "%", "the objective there less its value at phase 0, over the magnitude of "
                           "that value")
    evaluations: int = quantity("evaluations", label="cycles converged by the search beyond the map")


@dataclass(frozen=True)
class PhaserRecord:
    """A valve's cam phaser: its range, the events at its ends, the torque it holds and the breathing's map."""

    valve: str = quantity("valve", label="the phased valve (its camshaft's lobes)")
    advance_range: tuple[float, float] = quantity("advance_range_crank_deg", "crank deg", "the phaser's range, an "
                                                  "advance positive (the events earlier)")
    cam_range: tuple[float, float] = quantity("advance_range_cam_deg", "cam deg", "the same in camshaft degrees "
                                              "(half the crank's of a four-stroke)")
    events: tuple[PhasedEvents, ...] = quantity("events", label="the events at the range's low end, at phase 0 and at "
                                                "its high end (once where an end is 0)")
    dynamics: str = quantity("dynamics", label="the valve train's dynamics over the range")
    torque_source: str = quantity("holding_torque_source", label="the camshaft whose drive torque the phaser holds")
    torque_peak: float = quantity("holding_torque_peak_Nm", "N m", "largest drive torque of the camshaft over a "
                                  "revolution at the rated speed: the phaser holds it")
    torque_lowest: float = quantity("holding_torque_lowest_Nm", "N m", "smallest (negative: the lobes drive the "
                                    "shaft, the phaser holds it the other way)")
    torque_mean: float = quantity("holding_torque_mean_Nm", "N m", "mean drive torque, the steady torque the phaser "
                                  "holds against its drift")
    gas_load: Optional[float] = quantity("gas_load_max_N", "N", "largest gas force that tends to open the shut valve "
                                         "over the map (with [breathing]): the spring's preload must hold it",
                                         omit_none=True, default=None)
    gas_load_advance: Optional[float] = quantity("gas_load_max_advance_crank_deg", "crank deg", "at which phase",
                                                 omit_none=True, default=None)
    objective: Optional[str] = quantity("objective", label="the figure the best phase maximises: the indicated torque "
                                        "(fired) or the volumetric efficiency (motored)", omit_none=True,
                                        default=None)
    search: Optional[str] = quantity("search", label="how the best phase is found", omit_none=True, default=None)
    map: tuple[PhaserPoint, ...] = quantity("map", label="the breathing at every phase and condition of [breathing]",
                                            default=())
    best: tuple[BestPhase, ...] = quantity("best", label="the best phase at each condition", default=())
    opening: Optional[tuple[OpeningLoad, ...]] = quantity(
        "opening", label="an exhaust valve with [breathing]: its opening's gas force and the cam's strength at the "
        "range's ends and at 0", omit_none=True, default=None)


@dataclass(frozen=True, repr=False)
class PhaserResults:
    """The phaser chapter of a valve: the record, the map's phases [crank rad] and the checks (the map's converged
    cycles are not kept: their figures are the record's)."""

    figures: PhaserRecord
    advances: np.ndarray = field(repr=False)       # (P,) the map's phases [crank rad]
    checks: tuple[Check, ...] = ()

    @cached_property
    def summary(self) -> dict[str, Any]:
        """The chapter's record in results.json (engineering units), made once: read it, don't change it."""
        return record(self.figures)

    def __repr__(self):
        low, high = (to_display(a, "crank deg") for a in self.figures.advance_range)
        return f"PhaserResults({self.figures.valve}: {low:g} to {high:g} crank deg, {len(self.figures.best)} best phases)"


def _key(name, leaf="advance_range_crank_deg"):
    return f"valves.{name}.phaser.{leaf}"


def phased_events(name, cam, valve, engine, advance) -> PhasedEvents:
    """The events of the valve (its :class:`~valvetrain.design.valve.CamResult`, SI views) at ``advance`` [crank
    rad], and the smallest valve-to-piston gap then (:func:`~valvetrain.design.valve.clearance_stage` with the
    phase); a gap of zero or less refused naming the phaser's range."""
    try:
        gap = clearance_stage(cam, valve, engine, advance)
    except ValueError as exc:
        raise SpecError([Problem(_key(name), NoteText(note("spec.at_advance", advance=to_display(advance, "crank deg"),
                                                           error=note_of(said(exc)))))]) from None
    return PhasedEvents(advance, cam.valve_opens - advance, cam.valve_closes - advance,
                        None if gap is None else gap.min_gap, None if gap is None else gap.angle)


def holding_torque(name, valve, engine, design, camshaft) -> tuple[float, float, float, str]:
    """The peak, lowest and mean drive torque of the phased camshaft at the rated speed [N m] and its words: the
    camshaft chapter's where [camshaft] carries the valve (every lobe it carries turns with the phaser), else the
    valve's lobes on every cylinder in firing order (:func:`valvetrain.design.camshaft.lobe_set`, the camshaft
    chapter's torque)."""
    if camshaft is not None and name in camshaft.figures.valves:
        f = camshaft.figures
        return f.peak, f.lowest, f.mean, f"[camshaft]: the lobes of {', '.join(f.valves)}"
    lobes = [lobe_set(name, valve, engine, design, firing_angles(engine)[0])]
    t = shaft.torque_figures(camshaft_torque(2.0 * np.pi * np.arange(ANGLES) / ANGLES, lobes).sum(axis=0))
    return t["peak"], t["lowest"], t["mean"], f"the lobes of {name} on every cylinder in firing order"


CONTACT_STRESS = "strength.cam_contact_stress"
"""The strength chapter's check of the cam contact stress, whose allowable the phases' stress is checked against."""


def opening_loads(name, design, valve, gas, engine, phases, rows, ends
                  ) -> tuple[tuple[OpeningLoad, ...], list[Check]]:
    """The exhaust valve's opening at each phase of ``ends`` (:class:`PhasedEvents`): the cylinder pressure p_c and
    the port's p_p where it leaves its seat, from the converged cycles ``rows`` of the map's ``phases`` (one tuple of
    results a phase, one result a condition), the condition where p_c - p_p is largest; the strength chapter again
    (:func:`~valvetrain.design.drive_strength.strength_stage`) with ``[gas]``'s opening pressures replaced by those;
    and the checks of the cam contact stress at the range's ends against the strength chapter's allowable.

    Notes
    -----
    The exhaust valve opens against the cylinder's pressure, F = A_head (p_c - p_p) (Valve-train practical works
    (n.d.), eq. (7.1)); an advance opens it earlier in the expansion, where p_c is higher.  The lift law about the
    camshaft, and so its inertia force, is that of phase 0 (the phaser turns the whole camshaft): the gas force at the
    opening is what the phase changes in the cam's load.
    """
    out, found = [], []
    for e in ends:
        at = np.mod(e.opens, 4.0 * np.pi)
        row = rows[int(np.flatnonzero(phases == e.advance)[0])]
        pressures = [(float(np.interp(at, r.columns.angle, r.columns.pressure, period=4.0 * np.pi)),
                      float(np.interp(at, r.columns.angle, r.columns.exhaust_port, period=4.0 * np.pi)), r)
                     for r in row]
        cylinder, port, r = max(pressures, key=lambda x: x[0] - x[1])
        strength, checks = strength_stage(replace(valve, hydraulic=None), replace(
            gas, exhaust_opening_pressure=cylinder, exhaust_back_pressure=port), engine, design.cam, design.drive,
            design.dynamics)
        stress = next((c for c in checks if c.code == CONTACT_STRESS), None)
        out.append(OpeningLoad(e.advance, r.figures.speed, cylinder, port, strength.gas_force_at_opening,
                               strength.cam_force_max, None if stress is None else stress.value))
        if stress is not None and e.advance != 0.0:
            found.append(check("phaser.opening_contact_stress", stress.value, high=stress.high, unit="MPa",
                               source=stress.source, severity=stress.severity,
                               params={"advance": f"{to_display(e.advance, 'crank deg'):g}"}).of_valve(name))
    return tuple(out), found


def _point(advance, r) -> PhaserPoint:
    f = r.figures
    return PhaserPoint(advance, f.speed, f.intake_pressure, f.volumetric_efficiency, f.residual_gas_fraction, f.pmep,
                       f.torque)


def _breathe(name, at, run):
    try:
        return run()
    except BreathingError as exc:
        raise SpecError([Problem(_key(name), NoteText(note(
            "spec.advance_breathing", advance=to_display(at, "crank deg"), error=note_of(said(exc)))))]) from None


def best_phase(name, objective, engine, kind, condition, b, bracket, start) -> tuple[float, Any, int]:
    """The phase [crank rad] in ``bracket`` that maximises ``objective`` of the breathing at ``condition``, the
    breathing there and the number of phases the search converged: a bounded one-dimensional search
    (:func:`scipy.optimize.minimize_scalar`, ``method="bounded"``) over ``bracket`` (low, high, tolerance [crank
    rad]: the map's neighbours of its best point), each phase's breathing with the tolerance and cycles of [breathing]
    ``b``; ``start`` is the map's best (phase, result), kept where the search finds nothing better."""
    side = getattr(engine, kind)
    seen = {}

    def value(a):
        if a not in seen:
            phased = _engine_with(engine, kind, phased_flow(side, a))
            seen[a] = _breathe(name, a, lambda: breathing_records(phased, [condition], b.cycle_tolerance,
                                                                  b.max_cycles)[0])
        return -getattr(seen[a].figures, objective)

    low, high, tolerance = bracket
    found = minimize_scalar(value, bounds=(low, high), method="bounded", options={"xatol": tolerance})
    a, r = start
    if -found.fun > getattr(r.figures, objective):
        a, r = float(found.x), seen[float(found.x)]
    return a, r, len(seen)


def _engine_with(engine, kind, flow):
    """The breathing's engine with the ``kind`` side's effective areas ``flow``."""
    return replace(engine, **{kind: flow})


def phaser_stage(name, phaser, valve, engine, design, breathing=None, b=None, camshaft=None, gas=None
                 ) -> PhaserResults:
    """The phaser chapter of the valve ``name``.

    Parameters
    ----------
    name : str
    phaser, valve, engine : SI views of [valves.NAME.phaser], the valve and [engine].
    design : ValveDesign
    breathing : BreathingResults, optional
        The breathing chapter (its engines, one a condition): with it the map of phase x condition and the best phases.
    b : SI view of [breathing], optional
    camshaft : CamshaftResults, optional
    gas : SI view of [gas], optional
        An exhaust valve's with ``breathing``: the strength at each end of the range with the cylinder's pressure at
        that phase's opening (:func:`opening_loads`).

    Returns
    -------
    PhaserResults

    Raises
    ------
    SpecError
        A phase at which the valve meets the piston or the breathing cannot run, or a map that asks for more work
        than :data:`~valvetrain.breathing.cycle.MAX_WORK`, naming the phaser's key.

    Notes
    -----
    Phased lift y_phi(theta) = y(theta + phi): opening and closing at theta_o - phi, theta_c - phi crank angle
    (phi/2 camshaft angle of a four-stroke).  The gas exchange at each phase and condition is the breathing chapter's
    model (:func:`valvetrain.design.breathing.breathe_conditions`) with the phased valve's effective areas
    (:func:`phased_flow`); at phase 0 it is the breathing chapter's own result.  The best phase at a condition is the
    map's best point refined by a bounded Brent search (:func:`scipy.optimize.minimize_scalar`) between its
    neighbouring phases of the map, to ``tolerance_crank_deg``.  The drive torque of the camshaft is a function of the
    camshaft's angle at the rated speed, unchanged by the phase (the phaser turns the whole camshaft), so the phaser
    holds its peak, lowest and mean over the range.  An exhaust valve opens against the cylinder's pressure at its
    phased opening, from the map's cycles at each end of the range (:func:`opening_loads`).
    """
    cam = design.cam
    low, high = phaser.advance_range
    events = tuple(phased_events(name, cam, valve, engine, a) for a in sorted({low, 0.0, high}))
    checks = [check("phaser.piston_clearance", e.min_gap, low=PISTON_CLEARANCE_MIN[design.kind], unit="mm",
                    source=PISTON_CLEARANCE_SOURCE, severity="failure",
                    params={"advance": f"{to_display(e.advance, 'crank deg'):g}"},
                    note=note("phaser.smallest_gap_at", crank_deg=to_display(e.min_gap_angle, 'crank deg'))
                    ).of_valve(name)
              for e in (events[0], events[-1]) if e.min_gap is not None]
    peak, lowest, mean, source = holding_torque(name, valve, engine, design, camshaft)
    dynamics = ("unchanged over the range: the phase turns the whole camshaft, its lift law about the camshaft and "
                "its speed stay those of phase 0" + (", as the dynamics chapter simulates them" if design.dynamics
                                                     is not None else ""))
    cam_range = tuple(a / 2.0 for a in phaser.advance_range)
    if breathing is None:
        figures = PhaserRecord(name, phaser.advance_range, cam_range, events, dynamics, source, peak, lowest, mean)
        return PhaserResults(figures, np.zeros(0), tuple(checks))
    phases = advances(phaser)
    given, swept = breathing_conditions(b)
    conditions = given + swept
    engines = [tuple(_engine_with(e, design.kind, phased_flow(getattr(e, design.kind), a)) for e in breathing.engines)
               for a in phases]
    searched = SEARCH_EVALUATIONS + int(np.ceil(np.log(2.0 * phaser.step / phaser.tolerance) / np.log(GOLDEN)))
    asked = (sum(work(e, c, b.max_cycles) for each in engines for e, c in zip(each, conditions, strict=True))
             + searched * sum(work(e, c, b.max_cycles) for e, c in zip(breathing.engines, conditions, strict=True)))
    if asked > MAX_WORK:
        raise SpecError([Problem(_key(name, "step_crank_deg"), NoteText(note(
            "spec.phases_work", phases=len(phases), conditions=len(conditions), asked=asked, most=MAX_WORK)),
                                 f"{to_display(phaser.step, 'crank deg'):g}")])
    pairs = [(breathing.conditions, breathing.curve) if a == 0.0   # phase 0: the breathing chapter's own result
             else _breathe(name, a, lambda e=e: breathe_conditions(e, b, given, swept))
             for a, e in zip(phases, engines, strict=True)]
    rows = tuple(sum(pair, ()) for pair in pairs)
    loads = [gas_opening_load(BreathingResults(e, *pair, breathing.figures, ()), design.kind, valve.throat_diameter)
             for e, pair in zip(engines, pairs, strict=True)]
    k = int(np.argmax([force for force, _ in loads]))
    closed = (float(loads[k][0]), float(phases[k]))
    spring = design.drive.spring
    checks.append(check("phaser.gas_load", closed[0], high=spring.preload, unit="N", severity="failure",
                        source=cited(note("source.preload_holds", work="Valve-train practical works (n.d.), eqs. (5.4), (5.5)")),
                        note=note(GAS_LOAD_OVER_MAP[breathing.figures.mode],
                                  advance_crank_deg=float(to_display(closed[1], "crank deg")),
                                  **dict(loads[k][1][0][1]))).of_valve(name))
    opening = None
    if design.kind == "exhaust" and gas is not None:
        opening, more = opening_loads(name, design, valve, gas, engine, phases, rows, events)
        checks += more
    objective = OBJECTIVES[b.mode]
    zero = int(np.flatnonzero(phases == 0.0)[0])
    best, searched_results = [], []
    for j, c in enumerate(conditions):
        values = np.array([getattr(row[j].figures, objective) for row in rows])
        i = int(np.argmax(values))
        bracket = (phases[max(i - 1, 0)], phases[min(i + 1, phases.size - 1)], phaser.tolerance)
        a, r, n = best_phase(name, objective, breathing.engines[j], design.kind, c, b, bracket,
                             (phases[i], rows[i][j]))
        f = r.figures
        searched_results.append((a, r))
        best.append(BestPhase(f.speed, f.intake_pressure, a, f.volumetric_efficiency, f.residual_gas_fraction, f.pmep,
                              f.torque, (getattr(f, objective) - values[zero]) / abs(values[zero]), n))
    found = [cycle_check(r.figures, b.cycle_tolerance, "phaser.cycle_change",
                         advance=f"{to_display(a, 'crank deg'):g}").of_valve(name)
             for a, r in [(a, r) for a, row in zip(phases, rows, strict=True) for r in row] + searched_results
             if not r.converged]
    search = (f"the map's best phase refined by a bounded Brent search (scipy.optimize.minimize_scalar) between its "
              f"neighbours of the map, to {to_display(phaser.tolerance, 'crank deg'):g} crank deg")
    figures = PhaserRecord(name, phaser.advance_range, cam_range, events, dynamics, source, peak, lowest, mean,
                           *closed, objective, search, tuple(_point(a, r) for a, row in zip(phases, rows, strict=True)
                                                    for r in row), tuple(best), opening)
    return PhaserResults(figures, phases, tuple(checks + found))
