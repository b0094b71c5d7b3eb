"""The lost-motion stage of a valve design (``[valves.NAME.hydraulic.lost_motion]``): the MultiAir/UniAir intake.

The valve's cam drives a pump piston whose oil holds the valve open through the hydraulic drive of
:mod:`valvetrain.hydraulic_actuation`; a solenoid valve from the pump chamber to an accumulator, opened during the
cam's lift, lets the oil out, and the valve closes on its spring before the cam does, landing on the hydraulic brake
of its actuator piston (Bernard et al. (2009)).  The hydraulic chapter is the drive with the solenoid valve shut (the
valve follows the whole cam, the full lift); this stage simulates one camshaft revolution at the hydraulic chapter's
speed for each solenoid timing of the specification and reports the valve's lift and closing, its landing (seating)
velocity on the brake, the oil pressures and the oil let out to the accumulator.
"""

from dataclasses import dataclass, field, replace
import math
from typing import Any, Optional

import numpy as np

from ..bibliography import cite
from ..checks import Check, check
from ..dynamics.events import BOUNCE_TOLERANCE
from ..errors import InputError
from ..hydraulic_actuation import DriveResult, simulate
from ..locale import NoteText, cited, note
from ..specification.messages import Problem
from ..units import DEG, MM, cam_per_crank, to_display
from .dynamics_checks import SEATING_VELOCITY_MAX
from .dynamics_records import finite_or_none
from .hydraulic_actuation import MAX_NODE_STEPS, SEATING_SOURCE, cycle_angle, gas_force, hydraulic_drive, speed_plan
from .results import quantity

SOURCES = cited(note("source.lost_motion_drive", work=cite("bernard2009")),
                note("source.orifice_equation", work=cite("merritt1967")),
                note("source.wave_speed", work=cite("wylie1978")))
"""The works the lost-motion stage follows, as the report cites them."""

KEY = "solenoid_opens_crank_deg"
"""The key of the solenoid timings in ``[valves.NAME.hydraulic.lost_motion]``."""


@dataclass(frozen=True)
class Closing:
    """The drive at one solenoid timing: one camshaft revolution (SI)."""

    solenoid_opens: float = quantity("solenoid_opens_crank_deg", "crank deg", "where the solenoid valve opens, cycle "
                                     "angle from the gas-exchange TDC")
    solenoid_opens_cam: float = quantity("solenoid_opens_cam_deg", "cam deg", "the same, camshaft angle from the cam "
                                         "nose")
    valve_lift: float = quantity("valve_lift_mm", "mm", "largest valve lift")
    valve_closes: Optional[float] = quantity("valve_closes_crank_deg", "crank deg", "where the valve meets its seat, "
                                             "cycle angle from the gas-exchange TDC (null: not within the revolution)")
    seating_velocity: Optional[float] = quantity("seating_velocity_m_s", "m/s", "valve velocity as it meets its seat, "
                                                 "the brake's landing (negative: closing; null: it does not)")
    max_pressure: float = quantity("max_pressure_MPa", "MPa", "largest absolute pressure at either end of the passage")
    brake_pressure: float = quantity("max_brake_pressure_MPa", "MPa", "largest absolute pressure under the actuator "
                                     "piston (the brake's)")
    min_pressure: float = quantity("min_pressure_MPa", "MPa", "smallest absolute pressure at either end of the "
                                   "passage")
    bypassed: float = quantity("bypassed_oil_cm3", "cm3", "largest oil volume the solenoid valve has let out to the "
                               "accumulator (the lost motion; the pump piston draws it back as it descends)")
    cavitation: bool = quantity("cavitation", label="the pressure fell to the vapour pressure somewhere")
    residual_lift: float = quantity("residual_lift_mm", "mm", "valve lift left when the pump piston is about to lift "
                                    "again (above 0: not closed before the next opening)")


@dataclass(frozen=True)
class SweptClosing:
    """One solenoid timing at one engine speed of the [hydraulic] chapter's sweep (``sweep = true``)."""

    speed: float = quantity("speed_rpm", "rpm", "engine speed")
    closing: Closing = quantity("closing", flatten=True)


@dataclass(frozen=True)
class ClosingBreath:
    """The breathing at one condition of ``[[breathing.conditions]]`` with the valve's lift of one solenoid timing
    (or of the full lift)."""

    solenoid_opens: Optional[float] = quantity("solenoid_opens_crank_deg", "crank deg", "where the solenoid valve "
                                               "opens (null: the full lift, the solenoid valve shut)")
    valve_closes: Optional[float] = quantity("valve_closes_crank_deg", "crank deg", "where the valve meets its seat")
    speed: float = quantity("speed_rpm", "rpm", "crank speed of the condition")
    intake_pressure: float = quantity("intake_pressure_kPa", "kPa", "intake plenum pressure")
    trapped_mass: float = quantity("trapped_mass_mg", "mg", "mass in the cylinder at the intake valve's closing")
    volumetric_efficiency: float = quantity("volumetric_efficiency", label="air delivered per cycle over the swept "
                                            "volume's mass at the intake plenum's density")
    residual_gas_fraction: float = quantity("residual_gas_fraction", label="share of the trapped mass that was not "
                                            "fresh charge")
    pmep: float = quantity("pmep_kPa", "kPa", "pumping mean effective pressure: work on the gas over the exhaust and "
                           "intake strokes per swept volume")
    imep: float = quantity("imep_kPa", "kPa", "net indicated mean effective pressure")
    converged: bool = quantity("converged", label="the cycles repeat within the breathing's tolerance")


@dataclass(frozen=True)
class LostMotionResult:
    """The lost-motion stage: the full lift (the solenoid valve shut, the hydraulic chapter's) and each solenoid
    timing (SI)."""

    speed: float = quantity("speed_rpm", "rpm", "engine speed of the simulations (the hydraulic chapter's)")
    accumulator_pressure: float = quantity("accumulator_pressure_MPa", "MPa", "absolute pressure of the accumulator")
    solenoid_closes: Optional[float] = quantity("solenoid_closes_crank_deg", "crank deg", "where the solenoid valve "
                                                "shuts (null: before the cam lifts)")
    brake_travel: float = quantity("brake_travel_mm", "mm", "the valve's last travel over which the brake acts (0: no "
                                   "brake)")
    full_lift: float = quantity("full_lift_valve_lift_mm", "mm", "largest valve lift with the solenoid valve shut")
    full_lift_closes: Optional[float] = quantity("full_lift_valve_closes_crank_deg", "crank deg", "where that valve "
                                                 "meets its seat (null: not within the revolution)")
    full_lift_seating_velocity: Optional[float] = quantity("full_lift_seating_velocity_m_s", "m/s", "its velocity "
                                                           "there")
    closings: tuple[Closing, ...] = quantity("closings", label="one entry per solenoid timing, in the order given")
    table_file: str = quantity("table", label="the valve lifts and pressures against camshaft angle in the output "
                               "folder")
    breathing: tuple[ClosingBreath, ...] = quantity("breathing", label="with [breathing]: the full lift and each "
                                                    "timing breathed at each of its conditions", default=())
    sweep: Optional[tuple[SweptClosing, ...]] = quantity(
        "sweep", label="with sweep = true: each timing at each speed of the [hydraulic] chapter's sweep, timing by "
        "timing", omit_none=True, default=None)
    responses: tuple[DriveResult, ...] = field(default=(), repr=False)
    full: Optional[DriveResult] = field(default=None, repr=False)
    nose: float = field(default=0.0, repr=False)      # crank angle of the cam nose from the gas-exchange TDC [rad]
    strokes: int = field(default=4, repr=False)


def cam_angle(phi, nose, strokes) -> float:
    """The camshaft angle [rad from the nose, in (-pi, pi]] of the cycle crank angle ``phi`` [rad from the gas-exchange
    TDC]: the inverse of :func:`~valvetrain.design.hydraulic_actuation.cycle_angle` within one camshaft revolution.

    >>> round(cam_angle(math.radians(400.0), math.radians(460.0), 4), 6) == round(math.radians(-30.0), 6)
    True
    """
    return float(math.remainder((phi - nose) * cam_per_crank(strokes), 2.0 * math.pi))


def _closing(r, opens, opens_cam, nose, strokes) -> Closing:
    angle, velocity, _ = r.seating()
    ends = np.concatenate([r.pump_pressure, r.actuator_pressure])
    closes = None if math.isnan(angle) else float(cycle_angle(nose, angle, strokes))
    return Closing(opens, opens_cam, float(r.valve_lift.max()), closes, finite_or_none(velocity), r.max_pressure,
                   float(r.brake_pressure.max()), float(ends.min()), float(r.bypassed_volume.max()),
                   bool(r.cavitation.any()), r.residual_lift)


def lost_motion_stage(valve, law, engine, gas, name, nose, hydraulic, cylinder=None) -> tuple[LostMotionResult,
                                                                                                list[Check]]:
    """One camshaft revolution of the lost-motion drive per solenoid timing.

    Parameters
    ----------
    valve : SI view of ``[valves.NAME]`` with ``hydraulic.lost_motion``
    law : valvetrain.laws.LiftLaw
        The valve's cam law, the pump piston's lift.
    engine, gas : SI views of ``[engine]`` and ``[gas]``.
    name : str
        The valve's name (the table's file name).
    nose : float
        Crank angle of the cam nose from the gas-exchange TDC [rad].
    hydraulic : HydraulicResult
        The hydraulic chapter: the full lift (the solenoid valve shut), its speed and the valve's stop.
    cylinder : CylinderPressure, optional
        The engine's cycle (the gas force on the valve head, as in the hydraulic chapter).

    Returns
    -------
    LostMotionResult, list of Check

    Raises
    ------
    InputError
        A solenoid timing outside the cam's lift or simulations that ask for more than
        :data:`~valvetrain.design.hydraulic_actuation.MAX_NODE_STEPS` node updates (its
        :class:`~valvetrain.specification.messages.Problem` names the key).

    Notes
    -----
    The solenoid valve opens at the camshaft angle theta = (phi - phi_nose) / 2 of the timing's cycle angle phi
    (four-stroke) and its area opens over its stroke time; the drive is
    :func:`valvetrain.hydraulic_actuation.simulate`'s with the solenoid valve's orifice to the accumulator and the
    brake.  Checks: the landing velocity against the seating limit of the dynamics (a warning), the valve back on its
    seat before the pump piston lifts again (a failure) and the pressure above the vapour pressure (a warning).

    References
    ----------
    Bernard et al. (2009); Merritt (1967), the orifice equation; Wylie and Streeter (1978).
    """
    lm = valve.hydraulic.lost_motion
    key = f"lost_motion.{KEY}"
    low, high = (float(cycle_angle(nose, a, engine.strokes)) for a in (law.start, law.end))
    thetas = []
    for phi in lm.solenoid_opens:
        theta = cam_angle(phi, nose, engine.strokes)
        if not law.start < theta < law.end:
            raise InputError(Problem(key, NoteText(note(
                "spec.solenoid_opens", opens=to_display(phi, "crank deg"), low=to_display(low, "crank deg"),
                high=to_display(high, "crank deg"))), f"{to_display(phi, 'crank deg'):g}"))
        thetas.append(theta)
    closes = -math.inf if lm.solenoid_closes is None else cam_angle(lm.solenoid_closes, nose, engine.strokes)
    if lm.solenoid_closes is not None and not (law.start - 0.1 < closes < min(thetas)):
        raise InputError(Problem("lost_motion.solenoid_closes_crank_deg", NoteText(note(
            "spec.solenoid_shuts", shuts=to_display(lm.solenoid_closes, "crank deg"),
            first=to_display(float(cycle_angle(nose, law.start - 0.1, engine.strokes)), "crank deg"))),
                                 f"{to_display(lm.solenoid_closes, 'crank deg'):g}"))
    drive = hydraulic_drive(valve.hydraulic)
    drive = replace(drive, valve=replace(drive.valve, stop=hydraulic.stop),
                    solenoid=replace(drive.solenoid, closes=closes))
    to_cam = cam_per_crank(engine.strokes)
    omega = hydraulic.speed * to_cam
    swept = speed_plan(valve.hydraulic, engine)[1] if lm.sweep else np.zeros(0)
    revolutions = 1.0 / omega + np.sum(1.0 / (swept * to_cam))     # [s/rad] of one timing
    work = len(thetas) * 2.0 * math.pi * revolutions / drive.time_step * (drive.pipe.reaches + 1)
    if work > MAX_NODE_STEPS:
        code = "spec.swept_timings_work" if lm.sweep else "spec.timings_node_work"
        raise InputError(Problem(key, NoteText(note(code, timings=len(thetas), speeds=swept.size, work=work,
                                                    most=MAX_NODE_STEPS)), f"{len(thetas)}"))
    force = gas_force(valve, gas, engine, nose, cylinder)
    responses = tuple(simulate(law, replace(drive, solenoid=replace(drive.solenoid, opens=theta)), omega,
                               gas_force=force) for theta in thetas)
    closings = tuple(_closing(r, phi, theta, nose, engine.strokes)
                     for r, phi, theta in zip(responses, lm.solenoid_opens, thetas, strict=True))
    sweep = None
    if lm.sweep:
        sweep = tuple(SweptClosing(float(n), _closing(simulate(law, replace(drive, solenoid=replace(
            drive.solenoid, opens=theta)), n * to_cam, gas_force=force), phi, theta, nose, engine.strokes))
                      for phi, theta in zip(lm.solenoid_opens, thetas, strict=True) for n in swept)
    full = hydraulic.response
    full_angle = full.seating()[0]
    result = LostMotionResult(
        hydraulic.speed, drive.solenoid.accumulator_pressure, lm.solenoid_closes, lm.brake_travel,
        float(full.valve_lift.max()), None if math.isnan(full_angle) else float(cycle_angle(nose, full_angle,
                                                                                             engine.strokes)),
        hydraulic.seating_velocity, closings, f"tables/{name}_lost_motion.csv", sweep=sweep, responses=responses,
        full=full, nose=nose, strokes=engine.strokes)
    return result, _checks(closings, valve.hydraulic.vapour_pressure) + _sweep_checks(
        sweep or (), engine.over_speed_ratio * engine.rated_speed)


def _checks(closings, vapour) -> list[Check]:
    """Per timing: the landing velocity (a warning above the dynamics' limit), the valve back on its seat before the
    next opening (a failure), the pressure above the vapour pressure (a warning)."""
    found = []
    for c in closings:
        params = {"opens": f"{to_display(c.solenoid_opens, 'crank deg'):g}"}
        if c.seating_velocity is not None:
            found.append(check("lost_motion.seating_velocity", abs(c.seating_velocity), high=SEATING_VELOCITY_MAX,
                               unit="m/s", source=cited(SEATING_SOURCE, cite("bernard2009")),
                               params=params))
        found.append(check("lost_motion.residual_lift", c.residual_lift, high=BOUNCE_TOLERANCE, unit="mm",
                           severity="failure", source=cite("bernard2009"), params=params,
                           note=note("lost_motion.not_seated") if c.residual_lift > BOUNCE_TOLERANCE else ""))
        found.append(check("lost_motion.min_pressure", c.min_pressure, low=vapour, strict_low=True, unit="MPa",
                           source=cite("wylie1978"), params=params,
                           note=note("hydraulic.cavitation")))
    return found


def _sweep_checks(sweep, top) -> list[Check]:
    """Per timing over the sweep's speeds up to ``top`` [rad/s] (the over-speed): the largest landing velocity (a
    warning above the dynamics' limit) and the largest lift left before the next opening (a failure), each with the
    speed where it is; and, once for the sweep, its lowest speed over ``top`` (a warning above 1: a sweep wholly above
    the over-speed grades no timing)."""
    found = [check("lost_motion.sweep_range", min(s.speed for s in sweep) / top, high=1.0,
                   source=cited(note("source.follower_dynamics", work=cite("norton2009"))))] if sweep else []
    for opens in dict.fromkeys(s.closing.solenoid_opens for s in sweep):
        rows = [s for s in sweep if s.closing.solenoid_opens == opens and s.speed <= top * (1.0 + 1e-9)]
        params = {"opens": f"{to_display(opens, 'crank deg'):g}"}
        landed = [s for s in rows if s.closing.seating_velocity is not None]
        if landed:
            w = max(landed, key=lambda s: abs(s.closing.seating_velocity))
            found.append(check("lost_motion.sweep_seating_velocity", abs(w.closing.seating_velocity),
                               high=SEATING_VELOCITY_MAX, unit="m/s", source=cited(SEATING_SOURCE, cite("bernard2009")),
                               params=params, note=note("hydraulic.largest_at", speed_rpm=to_display(w.speed, "rpm"))))
        if rows:
            w = max(rows, key=lambda s: s.closing.residual_lift)
            found.append(check("lost_motion.sweep_residual_lift", w.closing.residual_lift, high=BOUNCE_TOLERANCE,
                               unit="mm", severity="failure", source=cite("bernard2009"), params=params,
                               note=note("hydraulic.not_reseated", speed_rpm=to_display(w.speed, "rpm"))
                               if w.closing.residual_lift > BOUNCE_TOLERANCE else ""))
    return found


TABLE_COLUMNS = [
    ("cam_deg", "camshaft angle from the cam nose [deg]"),
    ("crank_deg", "cycle crank angle from the gas-exchange TDC, 0...720 [deg]"),
    ("pump_lift_mm", "pump piston (cam follower) lift [mm]"),
    ("full_lift_mm", "valve lift with the solenoid valve shut [mm]"),
]
"""The leading columns of ``tables/NAME_lost_motion.csv``; then per timing (its solenoid opening in crank deg, ``at``)
``valve_lift_mm_at``, ``pump_pressure_MPa_at``, ``brake_pressure_MPa_at``."""


def table_columns(result, step=0.5 * DEG) -> dict[str, Any]:
    """The lost-motion table: every k-th time step, k the whole number of steps nearest to ``step`` [rad] of camshaft
    angle (at least 1), the timings' runs on the full lift's grid (the same time step and start)."""
    full = result.full
    stride = max(1, round(step / (full.angle[1] - full.angle[0])))
    rows = np.arange(0, full.angle.size, stride)
    out = {"cam_deg": np.degrees(full.angle[rows]),
           "crank_deg": np.degrees(cycle_angle(result.nose, full.angle[rows], result.strokes)),
           "pump_lift_mm": full.plunger_lift[rows] / MM, "full_lift_mm": full.valve_lift[rows] / MM}
    for c, r in zip(result.closings, result.responses, strict=True):
        at = f"{to_display(c.solenoid_opens, 'crank deg'):g}"
        out[f"valve_lift_mm_{at}"] = r.valve_lift[rows] / MM
        out[f"pump_pressure_MPa_{at}"] = r.pump_pressure[rows] / 1e6
        out[f"brake_pressure_MPa_{at}"] = r.brake_pressure[rows] / 1e6
    return out


__all__ = ["Closing", "ClosingBreath", "SweptClosing", "KEY", "LostMotionResult", "SOURCES", "TABLE_COLUMNS", "cam_angle",
           "lost_motion_stage", "table_columns"]
