"""The hydraulic stage of a valve design: the valve driven through a liquid column ([valves.NAME.hydraulic]).

The valve's cam drives a plunger; the stage simulates one camshaft revolution of the drive of
:mod:`valvetrain.hydraulic_actuation` at the given engine speed and reports the pressures at both ends of the pipe, the
valve lift against the rigid drive (plunger lift times the area ratio), the delays and lift loss, the largest
pressure, the cavitation (a pressure held at the vapour pressure, a warning), the seating velocity (a warning
above the dynamics stage's limit) and the bounce; then it sweeps the engine speed (one revolution per speed) and
reports the same numbers at each speed.

The valve opens against the cylinder pressure on its head when the engine's cycle is known (the ``[crank]``
section's indicator diagram or Wiebe cycle, :class:`CylinderPressure`): the force (p_cyl - p_port) A_head holds
it on its seat, at the crank angle nose + camshaft angle x 2 (four-stroke); the stage reports what that force
costs (the opening delay, the lift and the pressure peak against the same drive without it).  The valve's travel
ends at a stop (the rigid drive's largest lift plus a margin): a valve that does not open (lifts less than 5 % of
the rigid drive's lift), that reaches the stop (over-travel) or that is not back on its seat when the plunger is
about to lift again (not closed before the next opening) is a failure at any speed of the sweep up to the
over-speed, as is a fill (supply) pressure that lifts the valve off its seat.
"""

from dataclasses import dataclass, field, replace
import math
from typing import Any, Callable, Optional

import numpy as np

from ..checks import Check, check
from ..locale import NoteText, cited, note
from ..crank.pressure import on_grid
from ..dynamics.events import BOUNCE_TOLERANCE
from ..errors import InputError
from ..flow import circle_area
from ..hydraulic_actuation import (Actuator, Brake, DriveResult, Fluid, HydraulicDrive, Pipe, Pump, Solenoid, SpeedSweep,
                                   Valve, simulate, speed_sweep)
from ..specification.messages import Problem
from ..units import DEG, MM, cam_per_crank, rpm_to_rad_s, to_display
from .dynamics_checks import SEATING_VELOCITY_MAX
from .dynamics_records import finite_or_none
from .results import quantity, shown, shown_value

SOURCES = cited(note("source.hydraulic_actuation", work="Shang Hanji (1988), ch. 7"),
                note("source.wave_speed", work="Wylie and Streeter (1978)"))
"""The works the hydraulic stage follows, as the report cites them."""

MAX_NODE_STEPS = 2e8
"""Largest number of node updates (time steps x grid nodes) the stage runs, the simulated speed and the sweep
together (about two seconds)."""

MAX_REVOLUTION_STEPS = 5e5
"""Most time steps of one simulated revolution, each of whose about 25 values the result keeps (100 MB a
revolution; a lost-motion stage keeps up to 13 of them): a hundred times the examples' (about 6000)."""

DELAY_LEVEL = 0.05
"""Lift level of the delays, a fraction of the largest rigid lift."""

LOWEST_SPEED = 0.5
"""Lowest speed of the default sweep, a fraction of the rated speed; the sweep ends at the over-speed
(``[engine] over_speed_ratio`` x the rated speed)."""

STOP_MARGIN = 0.1
"""Default margin of the valve's stop above the rigid drive's largest lift, a fraction of that lift."""

FAILURE_SOURCE = "Shang Hanji (1988), ch. 7"
"""Source of the failure checks of the drive (the valve's stroke, its closing and its rest)."""

SEATING_SOURCE = cited("Shang Hanji (1988), ch. 3 and ch. 7", note("source.usual_seating"))
"""Source of the seating-velocity check (the dynamics stage's limit)."""


@dataclass(frozen=True)
class HydraulicSweep:
    """One entry per engine speed of the sweep (SI), as in ``tables/NAME_hydraulic_sweep.csv``."""

    speed: tuple[float, ...] = quantity("speed_rpm", "rpm", "engine speed")
    max_pressure: tuple[float, ...] = quantity("max_pressure_MPa", "MPa", "largest absolute pressure at either end "
                                               "of the pipe")
    valve_lift: tuple[float, ...] = quantity("valve_lift_mm", "mm", "largest valve lift")
    lift_loss: tuple[float, ...] = quantity("lift_loss_mm", "mm", "rigid lift less valve lift (largest values)")
    opening_delay: tuple[Optional[float], ...] = quantity("opening_delay_cam_deg", "cam deg", "opening delay "
                                                          "(null: the valve stays shut)")
    closing_delay: tuple[Optional[float], ...] = quantity("closing_delay_cam_deg", "cam deg", "closing delay "
                                                          "(null: the valve stays shut or open)")
    cavitation: tuple[bool, ...] = quantity("cavitation", label="the pressure fell to the vapour pressure")
    seating_velocity: tuple[Optional[float], ...] = quantity("seating_velocity_m_s", "m/s", "valve velocity at the "
                                                             "first seating (null: it does not return)")
    bounce: tuple[float, ...] = quantity("bounce_mm", "mm", "largest valve lift after the first seating")
    residual_lift: tuple[float, ...] = quantity("residual_lift_mm", "mm", "valve lift left when the plunger is about "
                                                "to lift again (0: closed before the next opening)")
    stop_reached: tuple[bool, ...] = quantity("stop_reached", label="the valve reached its stop (over-travel)")


@dataclass(frozen=True)
class CylinderPressure:
    """The cylinder pressure over the engine's cycle (SI), as the crank chapter computes it.

    Attributes
    ----------
    angle : ndarray
        Cycle crank angle [rad], increasing within one cycle; 0 is the TDC that starts the intake stroke (the
        gas-exchange TDC), the firing TDC is at pi (two-stroke: 0) or 2 pi (four-stroke).
    pressure : ndarray
        Absolute cylinder pressure [Pa].
    source : str
        Where the pressure comes from (an indicator diagram, the Wiebe model, the breathing).
    port : ndarray, optional
        Absolute pressure behind the valve head over the same angles [Pa] (the breathing's port at the valve); None:
        ``[gas]``'s constant port pressure (:func:`head_load`).
    """

    angle: np.ndarray
    pressure: np.ndarray
    source: str
    port: Optional[np.ndarray] = None

    def head_force(self, phi, diameter, port, strokes) -> np.ndarray:
        """The gas force on a valve head of ``diameter`` [m] towards its seat at cycle angles ``phi`` [rad]: (p_cyl -
        p_port) pi d^2 / 4 [N], p_port this cycle's :attr:`port` or else the constant ``port`` [Pa]."""
        return (on_grid(self.angle, self.pressure, phi, strokes) - self.port_pressure(phi, port, strokes)) * \
            circle_area(diameter)

    def port_pressure(self, phi, port, strokes) -> np.ndarray:
        """The pressure behind the valve head at cycle angles ``phi`` [rad]: :attr:`port` there, else ``port`` [Pa]."""
        return port if self.port is None else on_grid(self.angle, self.port, phi, strokes)


@dataclass(frozen=True)
class GasForceRecord:
    """The cylinder pressure on the valve head and what it costs the drive at the simulated speed (SI)."""

    source: str = quantity("pressure_source", label="where the cylinder pressure comes from")
    head_diameter: float = quantity("head_diameter_mm", "mm", "diameter the pressure acts on")
    port_pressure: float = quantity("port_pressure_MPa", "MPa", "absolute pressure behind the valve head (the port's)")
    lift_off: Optional[float] = quantity("lift_off_crank_deg", "crank deg", "where the valve leaves its seat, cycle "
                                         "angle from the gas-exchange TDC 0...720 (null: it does not)")
    cylinder_pressure: Optional[float] = quantity("cylinder_pressure_at_lift_off_MPa", "MPa", "absolute cylinder "
                                                  "pressure there")
    force: Optional[float] = quantity("gas_force_at_lift_off_N", "N", "(p_cyl - p_port) x head area there, towards "
                                      "the seat")
    lift_off_pressure: Optional[float] = quantity("lift_off_pressure_MPa", "MPa", "actuator pressure that holds the "
                                                  "spring preload and the gas force there, p_back + (F_0 + F_gas) / "
                                                  "A_a")
    opening_delay: Optional[float] = quantity("opening_delay_cam_deg", "cam deg", "opening delay the gas force adds "
                                              "(against the same drive without it)")
    lift_loss: float = quantity("lift_loss_mm", "mm", "lift the gas force costs (largest lift without it less with "
                                "it)")
    pressure_rise: float = quantity("pressure_rise_MPa", "MPa", "largest pressure with the gas force less without it")


@dataclass(frozen=True)
class HydraulicResult:
    """The hydraulic stage: one camshaft revolution of the drive (SI)."""

    speed: float = quantity("speed_rpm", "rpm", "engine speed of the simulation")
    wave_speed: float = quantity("wave_speed_m_s", "m/s", "wave speed a in the pipe (Korteweg)")
    time_step: float = quantity("time_step_us", "us", "time step L / (N a)")
    area_ratio: float = quantity("area_ratio", label="plunger area / actuator area A_p / A_a")
    rigid_lift: float = quantity("rigid_lift_mm", "mm", "largest valve lift of the rigid drive h A_p / A_a")
    valve_lift: float = quantity("valve_lift_mm", "mm", "largest valve lift")
    lift_loss: float = quantity("lift_loss_mm", "mm", "rigid lift less valve lift (largest values)")
    opening_delay: Optional[float] = quantity("opening_delay_cam_deg", "cam deg", "valve opening later than the "
                                              "rigid drive's, at 5 % of the rigid lift (null: the valve stays shut)")
    closing_delay: Optional[float] = quantity("closing_delay_cam_deg", "cam deg", "valve closing later than the "
                                              "rigid drive's, at 5 % of the rigid lift (null: the valve stays shut)")
    max_pressure: float = quantity("max_pressure_MPa", "MPa", "largest absolute pressure at either end of the pipe")
    max_pressure_angle: float = quantity("max_pressure_cam_deg", "cam deg", "where it is largest")
    min_pressure: float = quantity("min_pressure_MPa", "MPa", "smallest absolute pressure at either end of the pipe")
    vapour_pressure: float = quantity("vapour_pressure_MPa", "MPa", "vapour pressure of the liquid (absolute)")
    cavitation: bool = quantity("cavitation", label="the pressure fell to the vapour pressure somewhere (held there, "
                                "a column-separation model that does not track the cavity volume)")
    seating_velocity: Optional[float] = quantity("seating_velocity_m_s", "m/s", "valve velocity when it first "
                                                 "returns to its seat (negative: closing; null: it does not return "
                                                 "within the revolution)")
    bounce: float = quantity("bounce_mm", "mm", "largest valve lift after the first seating (0: no bounce)")
    stop: float = quantity("stop_mm", "mm", "lift at which the valve meets its stop (the end of its stroke)")
    stop_reached: bool = quantity("stop_reached", label="the valve reached its stop (over-travel, a failure)")
    residual_lift: float = quantity("residual_lift_mm", "mm", "valve lift left when the plunger is about to lift "
                                    "again (above 0: not closed before the next opening, a failure)")
    gas_force: Optional[GasForceRecord] = quantity("gas_force", label="the cylinder pressure on the valve head "
                                                   "(with the engine's cycle)", omit_none=True)
    speed_range: tuple[float, ...] = quantity("speed_range_rpm", "rpm", "engine speeds swept, from and to")
    speeds: int = quantity("speeds", label="speeds swept")
    per_speed: HydraulicSweep = quantity("per_speed")
    notes: tuple[str, ...] = quantity("notes", label="how each value the specification does not give was obtained")
    table_file: str = quantity("table", label="the pressures and lifts against camshaft angle in the output folder")
    sweep_table: str = quantity("sweep_table", label="CSV with one row per speed, relative to the output folder")
    response: Optional[DriveResult] = field(default=None, repr=False)
    sweep: Optional[SpeedSweep] = field(default=None, repr=False)
    nose: float = field(default=0.0, repr=False)      # crank angle of the cam nose from the gas-exchange TDC [rad]
    strokes: int = field(default=4, repr=False)


def hydraulic_drive(h) -> HydraulicDrive:
    """The :class:`~valvetrain.hydraulic_actuation.HydraulicDrive` of the SI view of a hydraulic section (the valve's stop not yet
    placed); with a ``lost_motion`` section its brake and its solenoid valve, shut the whole revolution (the valve
    follows the whole cam)."""
    area = lambda d: math.pi * d**2 / 4.0  # noqa: E731
    wall = math.inf if h.pipe_wall is None else h.pipe_wall
    fill = (h.fill_pressure, h.fill_conductance) if h.fill_pressure is not None else (0.0, 0.0)
    relief = (h.relief_pressure, h.relief_conductance) if h.relief_pressure is not None else (math.inf, 0.0)
    return HydraulicDrive(
        Fluid(h.density_kg_m3, h.bulk_modulus, h.vapour_pressure),
        Pipe(h.pipe_length, h.pipe_diameter, wall, h.pipe_wall_modulus, h.friction_factor, h.reaches),
        Pump(area(h.plunger_diameter), h.pump_volume, h.leakage, *fill, *relief),
        Actuator(area(h.actuator_diameter), h.actuator_volume, h.leakage),
        Valve(h.valve_mass_kg, h.spring_rate, h.spring_preload_N, h.damping_N_s_per_m, math.inf, h.stop_stiffness),
        h.initial_pressure, h.back_pressure, *_lost_motion_parts(h))


def _lost_motion_parts(h):
    """The solenoid valve (shut) and the brake of a hydraulic section's ``lost_motion`` (None, None without one)."""
    lm = h.lost_motion
    if lm is None:
        return None, None
    accumulator = h.initial_pressure if lm.accumulator_pressure is None else lm.accumulator_pressure
    brake = None if lm.brake_travel == 0.0 else Brake(lm.brake_travel, lm.brake_end_area, lm.brake_open_area,
                                                      lm.discharge_coefficient)
    return Solenoid(lm.solenoid_area, accumulator, lm.discharge_coefficient, stroke_time=lm.solenoid_stroke), brake


def lift_off_pressure(drive, gas_force=0.0) -> float:
    """Absolute actuator pressure that lifts the valve off its seat [Pa].

    Parameters
    ----------
    drive : valvetrain.hydraulic_actuation.HydraulicDrive
    gas_force : float
        Force of the cylinder pressure that holds the valve on its seat [N].

    Notes
    -----
    The valve's equation at rest on its seat: (p_a - p_back) A_a = F_0 + F_gas.

    References
    ----------
    Shang Hanji (1988), ch. 7.
    """
    return drive.back_pressure + (drive.valve.preload + gas_force) / drive.actuator.piston_area


def cycle_angle(nose, cam_angle, strokes) -> np.ndarray:
    """Cycle crank angle [rad from the gas-exchange TDC, 0...pi strokes] of camshaft angles [rad from the nose], the
    nose at the crank angle ``nose`` [rad]: crank = nose + camshaft angle / (camshaft revolutions per crank
    revolution), twice the camshaft angle for a four-stroke."""
    return np.mod(nose + np.asarray(cam_angle) / cam_per_crank(strokes), math.pi * strokes)


def head_load(valve, gas) -> tuple[float, float]:
    """The diameter the cylinder pressure acts on [m] (``parts.head_diameter_mm``, else the throat's, which is
    smaller) and the absolute pressure behind the valve head [Pa] (``[gas]``: the exhaust back pressure of an exhaust
    valve, the intake port pressure of an intake valve)."""
    head = valve.parts.head_diameter
    port = gas.exhaust_back_pressure if valve.kind == "exhaust" else gas.intake_port_pressure
    return (valve.throat_diameter if head is None else head), port


def speed_plan(hydraulic, engine) -> tuple[float, np.ndarray, list[str]]:
    """The engine speeds of the stage [rad/s]: (simulated speed, swept speeds, notes on the defaults taken, each a
    :class:`~valvetrain.locale.NoteText`)."""
    rpm = rpm_to_rad_s(1.0)
    notes = []
    speed = engine.rated_speed if hydraulic.speed is None else hydraulic.speed
    if hydraulic.speed is None:
        notes.append(NoteText(note("hydraulic.rated_speed", speed_rpm=speed / rpm)))
    if hydraulic.speed_range is None:
        top = engine.over_speed_ratio
        low, high = LOWEST_SPEED * engine.rated_speed, top * engine.rated_speed
        notes.append(NoteText(note("hydraulic.speed_range", low_rpm=low / rpm, high_rpm=high / rpm,
                                   low_share=LOWEST_SPEED, high_share=top)))
    else:
        low, high = hydraulic.speed_range
    return speed, np.linspace(low, high, hydraulic.speeds), notes


def hydraulic_stage(valve, law, engine, gas, name, nose, cylinder=None) -> tuple[HydraulicResult, list[Check]]:
    """One camshaft revolution of one valve's hydraulic drive, and one at each speed of a sweep.

    Parameters
    ----------
    valve : SI view of ``[valves.NAME]`` with its ``hydraulic`` section
    law : valvetrain.laws.LiftLaw
        The valve's cam law, the plunger lift.
    engine : SI view of ``[engine]``
        Rated speed, over-speed ratio and strokes.
    gas : SI view of ``[gas]``
        The pressure behind the valve head.
    name : str
        The valve's name (the tables' file names).
    nose : float
        Crank angle of the cam nose from the gas-exchange TDC [rad].
    cylinder : CylinderPressure, optional
        The engine's cycle; without it no gas force acts on the valve head (a note says so).

    Returns
    -------
    HydraulicResult, list of Check

    Raises
    ------
    ValueError
        The grid and the speeds ask for more than :data:`MAX_NODE_STEPS` node updates (its
        :class:`~valvetrain.specification.messages.Problem` names the key ``reaches``), or a revolution for more than
        :data:`MAX_REVOLUTION_STEPS` time steps (naming ``speed_rpm`` or ``speed_range_rpm``).

    Notes
    -----
    The gas force on the valve head is F = (p_cyl(phi) - p_port) pi d^2 / 4 at the cycle angle phi = nose + 2 theta
    (four-stroke), towards the seat, p_port the port's of ``[gas]`` or, where the breathing gives the cycle, the
    breathing's at the valve at that angle (:meth:`CylinderPressure.head_force`); the pressure of an open valve's head
    is taken as that of the cylinder (no flow forces).  The stop lies at the rigid drive's largest lift plus
    ``stop_margin_mm`` (default :data:`STOP_MARGIN` of that lift).  Failures, at the simulated speed and every swept
    speed up to the over-speed: the valve's largest lift below :data:`DELAY_LEVEL` of the rigid drive's (it does not
    open); the valve reaches its stop; the valve is more than the bounce tolerance (1 um) above its seat at the end
    of the revolution, where the plunger is about to lift again; a fill pressure above :func:`lift_off_pressure`.

    References
    ----------
    Shang Hanji (1988), ch. 7 (the drive) and ch. 3 (seating velocity and bounce); :mod:`valvetrain.hydraulic_actuation`.
    """
    hydraulic = valve.hydraulic
    drive = hydraulic_drive(hydraulic)
    speed, speeds, notes = speed_plan(hydraulic, engine)
    rigid = float(np.max(law.lift(np.linspace(law.start, law.end, 2001)))) * drive.area_ratio
    margin = STOP_MARGIN * rigid if hydraulic.stop_margin is None else hydraulic.stop_margin
    if hydraulic.stop_margin is None:
        notes.append(NoteText(note("hydraulic.valve_stop", stop_mm=to_display(rigid + margin, "mm"),
                                   margin=STOP_MARGIN)))
    drive = replace(drive, valve=replace(drive.valve, stop=rigid + margin))
    to_cam = cam_per_crank(engine.strokes)
    revolutions = np.concatenate([speeds, [speed] * (1 if cylinder is None else 2)]) * to_cam
    work = float(np.sum(2.0 * math.pi / revolutions)) / drive.time_step * (drive.pipe.reaches + 1)
    if work > MAX_NODE_STEPS:
        raise InputError(Problem("reaches", NoteText(note(
            "spec.pipe_work", speeds=speeds.size, work=work, step_us=drive.time_step * 1e6, most=MAX_NODE_STEPS)),
            f"{drive.pipe.reaches}"))
    slowest = float(revolutions.min())
    if 2.0 * math.pi / slowest / drive.time_step > MAX_REVOLUTION_STEPS:
        key = "speed_rpm" if slowest == speed * to_cam else "speed_range_rpm"
        raise InputError(Problem(key, NoteText(note(
            "spec.revolution_steps", speed_rpm=to_display(slowest / to_cam, "rpm"),
            steps=2.0 * math.pi / slowest / drive.time_step, step_us=drive.time_step * 1e6, most=MAX_REVOLUTION_STEPS)),
            f"{to_display(slowest / to_cam, 'rpm'):.4g}"))
    diameter, port = head_load(valve, gas)
    force = gas_force(valve, gas, engine, nose, cylinder)
    if cylinder is None:
        notes.append(NoteText(note("hydraulic.no_gas_force")))
    r = simulate(law, drive, speed * to_cam, gas_force=force)
    sw = speed_sweep(law, drive, speeds * to_cam, DELAY_LEVEL, gas_force=force)
    opening, closing = r.delays(DELAY_LEVEL)
    _, seat_velocity, bounce = r.seating()
    ends = np.concatenate([r.pump_pressure, r.actuator_pressure])
    per_speed = HydraulicSweep(
        tuple(float(x) for x in speeds), tuple(sw.max_pressure.tolist()), tuple(sw.valve_lift.tolist()),
        tuple(sw.lift_loss.tolist()), tuple(map(finite_or_none, sw.opening_delay)),
        tuple(map(finite_or_none, sw.closing_delay)), tuple(sw.cavitation.tolist()),
        tuple(map(finite_or_none, sw.seating_velocity)), tuple(sw.bounce.tolist()), tuple(sw.residual_lift.tolist()),
        tuple(sw.stop_reached.tolist()))
    gas_record = None if cylinder is None else _gas_record(r, simulate(law, drive, speed * to_cam), drive, cylinder,
                                                           diameter, port, nose, engine.strokes)
    result = HydraulicResult(
        speed=speed, wave_speed=r.wave_speed, time_step=r.time_step, area_ratio=drive.area_ratio,
        rigid_lift=float(r.rigid_lift.max()), valve_lift=float(r.valve_lift.max()), lift_loss=r.lift_loss,
        opening_delay=finite_or_none(opening), closing_delay=finite_or_none(closing),
        max_pressure=r.max_pressure, max_pressure_angle=r.max_pressure_angle, min_pressure=float(ends.min()),
        vapour_pressure=hydraulic.vapour_pressure, cavitation=bool(r.cavitation.any()),
        seating_velocity=finite_or_none(seat_velocity), bounce=bounce, stop=drive.valve.stop,
        stop_reached=r.stop_reached, residual_lift=r.residual_lift, gas_force=gas_record,
        speed_range=(float(speeds[0]), float(speeds[-1])), speeds=int(speeds.size), per_speed=per_speed,
        notes=tuple(notes), table_file=f"tables/{name}_hydraulic.csv",
        sweep_table=f"tables/{name}_hydraulic_sweep.csv", response=r, sweep=sw, nose=nose, strokes=engine.strokes)
    found = [check("hydraulic.min_pressure", result.min_pressure,
                   low=hydraulic.vapour_pressure, strict_low=True, source=SOURCES, unit="MPa",
                   note=note("hydraulic.cavitation"))]
    found += _failure_checks(r, sw, speed, speeds, engine, drive, hydraulic)
    if result.seating_velocity is not None:
        found.append(check("hydraulic.seating_velocity", abs(result.seating_velocity), high=SEATING_VELOCITY_MAX, unit="m/s",
                           source=SEATING_SOURCE))
    return result, found


def gas_force(valve, gas, engine, nose, cylinder=None) -> Optional[Callable[[np.ndarray], np.ndarray]]:
    """The force of the cylinder pressure on the valve head towards its seat [N] as a function of camshaft angles
    [rad from the nose] (:meth:`CylinderPressure.head_force` at the cycle angle :func:`cycle_angle`, on the head of
    :func:`head_load`); None without the engine's cycle ``cylinder``."""
    if cylinder is None:
        return None
    diameter, port = head_load(valve, gas)

    def force(theta):
        return cylinder.head_force(cycle_angle(nose, theta, engine.strokes), diameter, port, engine.strokes)
    return force


def _gas_record(r, free, drive, cylinder, diameter, port, nose, strokes):
    """The :class:`GasForceRecord` of the response ``r`` with the gas force and ``free`` without it."""
    i = r.lift_off()
    opened = i < r.angle.size
    phi = float(cycle_angle(nose, r.angle[i], strokes)) if opened else None
    force = float(r.gas_force[i]) if opened else None
    if cylinder.port is not None:       # the breathing's port: at the lift-off (its cycle's mean if none)
        port = float(np.mean(cylinder.port) if phi is None else cylinder.port_pressure(phi, port, strokes))
    return GasForceRecord(
        cylinder.source, diameter, port, phi,
        None if phi is None else float(on_grid(cylinder.angle, cylinder.pressure, phi, strokes)), force,
        None if force is None else lift_off_pressure(drive, force),
        finite_or_none(r.delays(DELAY_LEVEL)[0] - free.delays(DELAY_LEVEL)[0]),
        float(free.valve_lift.max() - r.valve_lift.max()), r.max_pressure - free.max_pressure)


def _failure_checks(r, sw, speed, speeds, engine, drive, hydraulic):
    """The drive's failures at the simulated speed and the swept speeds up to the over-speed: a valve that does not
    open (its largest lift below :data:`DELAY_LEVEL` of the rigid drive's, where the delays are measured), over-travel
    (the valve reaches its stop), a valve not closed before its next opening, a fill pressure that lifts the valve."""
    rpm = rpm_to_rad_s(1.0)
    judged = speeds <= engine.over_speed_ratio * engine.rated_speed * (1.0 + 1e-9)
    at = np.append(speeds[judged], speed)
    lift = np.append(sw.valve_lift[judged], r.valve_lift.max())
    left = np.append(sw.residual_lift[judged], r.residual_lift)
    k, m, n = int(np.argmax(lift)), int(np.argmax(left)), int(np.argmin(lift))
    stop = drive.valve.stop
    reached = lift[k] >= stop
    opening = DELAY_LEVEL * float(r.rigid_lift.max())
    found = [
        check("hydraulic.opening", lift[n], low=opening, unit="mm", severity="failure",
              source=cited(FAILURE_SOURCE, note("source.delay_level", percent=DELAY_LEVEL * 100)),
              note=(note("hydraulic.not_opened", speed_rpm=at[n] / rpm, lift_mm=lift[n] / MM,
                         rigid_mm=opening / DELAY_LEVEL / MM)
                    if lift[n] < opening else note("hydraulic.least_at", speed_rpm=at[n] / rpm))),
        check("hydraulic.max_lift", lift[k], high=stop, unit="mm",
              severity="failure", source=FAILURE_SOURCE,
              note=note("hydraulic.stop_reached" if reached else "hydraulic.largest_at", speed_rpm=at[k] / rpm)),
        check("hydraulic.residual_lift", left[m], high=BOUNCE_TOLERANCE, unit="mm",
              severity="failure", source=FAILURE_SOURCE,
              note=note("hydraulic.not_reseated", speed_rpm=at[m] / rpm) if left[m] > BOUNCE_TOLERANCE else "")]
    if hydraulic.fill_pressure is not None:
        found.append(check("hydraulic.fill_pressure",
                           hydraulic.fill_pressure, high=lift_off_pressure(drive), unit="MPa", severity="failure",
                           source=FAILURE_SOURCE,
                           note=note("hydraulic.lift_off")))
    return found


TABLE_COLUMNS = [
    ("cam_deg", "camshaft angle from the cam nose [deg]"),
    ("crank_deg", "cycle crank angle from the gas-exchange TDC, 0...720 [deg]"),
    ("plunger_lift_mm", "plunger (follower) lift [mm]"),
    ("pump_pressure_MPa", "absolute pressure at the pump end of the pipe [MPa]"),
    ("actuator_pressure_MPa", "absolute pressure at the actuator end of the pipe [MPa]"),
    ("valve_lift_mm", "valve lift [mm]"),
    ("rigid_lift_mm", "valve lift of the rigid drive, plunger lift x A_p / A_a [mm]"),
    ("gas_force_N", "force of the cylinder pressure on the valve head, towards the seat [N] (0: no engine cycle)"),
    ("cavitation", "1 where a pressure is held at the vapour pressure"),
]
"""Columns of ``tables/NAME_hydraulic.csv``."""


def table_columns(result, step=0.5 * DEG) -> dict[str, np.ndarray]:
    """The hydraulic table in the units of :data:`TABLE_COLUMNS`: every k-th time step of the simulation, k the
    whole number of steps nearest to ``step`` [rad] of camshaft angle (at least 1); a cavitation between two rows
    is shown on the next row."""
    r = result.response
    stride = max(1, round(step / (r.angle[1] - r.angle[0])))
    rows = np.arange(0, r.angle.size, stride)
    flags = np.cumsum(r.cavitation)
    seen = np.diff(np.concatenate([[0], flags[rows]])) > 0
    return {"cam_deg": np.degrees(r.angle[rows]),
            "crank_deg": np.degrees(cycle_angle(result.nose, r.angle[rows], result.strokes)),
            "plunger_lift_mm": r.plunger_lift[rows] / MM,
            "pump_pressure_MPa": r.pump_pressure[rows] / 1e6, "actuator_pressure_MPa": r.actuator_pressure[rows] / 1e6,
            "valve_lift_mm": r.valve_lift[rows] / MM, "rigid_lift_mm": r.rigid_lift[rows] / MM,
            "gas_force_N": r.gas_force[rows], "cavitation": seen.astype(int)}


SWEEP_COLUMNS = [
    ("speed_rpm", "engine speed [rpm]"), ("camshaft_rpm", "camshaft speed [rpm]"),
    ("max_pressure_MPa", "largest absolute pressure at either end of the pipe [MPa]"),
    ("valve_lift_mm", "largest valve lift [mm]"), ("lift_loss_mm", "rigid lift less valve lift [mm]"),
    ("opening_delay_cam_deg", "opening delay against the rigid drive [cam deg]; empty: the valve stays shut"),
    ("closing_delay_cam_deg", "closing delay against the rigid drive [cam deg]; empty: the valve stays shut or open"),
    ("cavitation", "1 where the pressure fell to the vapour pressure, else 0"),
    ("seating_velocity_m_s", "valve velocity at the first seating [m/s]; empty: it does not return"),
    ("bounce_mm", "largest valve lift after the first seating [mm]"),
    ("residual_lift_mm", "valve lift left when the plunger is about to lift again [mm]; above 0: not closed"),
    ("stop_reached", "1 where the valve reached its stop (over-travel), else 0"),
]
"""Columns of ``tables/NAME_hydraulic_sweep.csv``."""


def sweep_columns(result) -> dict[str, Any]:
    """The per-speed table of a :class:`HydraulicResult` in the units of :data:`SWEEP_COLUMNS` (None: an empty
    cell)."""
    p = result.per_speed
    out = {"speed_rpm": shown_value(p, "speed"), "camshaft_rpm": (result.sweep.cam_speed / rpm_to_rad_s(1.0)).tolist()}
    out.update(shown(p, "max_pressure", "valve_lift", "lift_loss", "opening_delay", "closing_delay"))
    out["cavitation"] = [int(c) for c in p.cavitation]
    out.update(shown(p, "seating_velocity", "bounce", "residual_lift"))
    out["stop_reached"] = [int(c) for c in p.stop_reached]
    return out


__all__ = ["CylinderPressure", "GasForceRecord", "HydraulicResult", "HydraulicSweep", "SWEEP_COLUMNS", "TABLE_COLUMNS",
           "cycle_angle", "gas_force", "head_load", "hydraulic_drive", "hydraulic_stage", "lift_off_pressure", "speed_plan", "sweep_columns",
           "table_columns"]
