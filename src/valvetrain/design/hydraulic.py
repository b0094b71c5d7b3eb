"""The hydraulic stage of a valve design: the valve driven through a liquid column ([valves.NAME.hydraulic]).

The valve's cam drives a plunger; the stage simulates one camshaft revolution of the drive of
:mod:`valvetrain.hydraulic` at the given engine speed and reports the pressures at both ends of the pipe, the
valve lift against the rigid drive (plunger lift times the area ratio), the delays and lift loss, the largest
pressure, the cavitation (a pressure held at the vapour pressure, a warning), the seating velocity (a warning
above the dynamics stage's limit) and the bounce; then it sweeps the engine speed (one revolution per speed) and
reports the same numbers at each speed.
"""

from dataclasses import dataclass, field
import math
from typing import Optional

import numpy as np

from ..checks import check
from ..hydraulic import (Actuator, DriveResult, Fluid, HydraulicDrive, Pipe, Pump, SpeedSweep, Valve, simulate,
                         speed_sweep)
from ..units import DEG, MM, cam_per_crank, rpm_to_rad_s
from .dynamics import SEATING_VELOCITY_MAX, finite_or_none
from .results import quantity, record

SOURCES = ("Shang Hanji (1988), ch. 7 (hydraulic valve actuation); Wylie and Streeter (1978) (wave speed, "
           "method of characteristics)")
"""The works the hydraulic stage follows, as the report cites them."""

MAX_NODE_STEPS = 2e8
"""Largest number of node updates (time steps x grid nodes) the stage runs, the simulated speed and the sweep
together (about two seconds)."""

DELAY_LEVEL = 0.05
"""Lift level of the delays, a fraction of the largest rigid lift."""

SPEED_RANGE = (0.5, 1.1)
"""Default speed sweep as fractions of the rated speed."""

SEATING_QUANTITY = "hydraulic drive: valve seating velocity at the simulated speed"
"""The quantity of the seating-velocity check."""

SEATING_SOURCE = "Shang Hanji (1988), ch. 3 and ch. 7; 0.3-0.5 m/s usual"
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
    speed_range: tuple[float, ...] = quantity("speed_range_rpm", "rpm", "engine speeds swept, from and to")
    speeds: int = quantity("speeds", label="speeds swept")
    per_speed: HydraulicSweep = quantity("per_speed")
    notes: tuple[str, ...] = quantity("notes", label="how each value the specification does not give was obtained")
    table_file: str = quantity("table", label="the pressures and lifts against camshaft angle in the output folder")
    sweep_table: str = quantity("sweep_table", label="CSV with one row per speed, relative to the output folder")
    response: Optional[DriveResult] = field(default=None, repr=False)
    sweep: Optional[SpeedSweep] = field(default=None, repr=False)


def _drive(h):
    """The :class:`~valvetrain.hydraulic.HydraulicDrive` of the SI view of a hydraulic section."""
    area = lambda d: math.pi * d**2 / 4.0  # noqa: E731
    wall = math.inf if h.pipe_wall is None else h.pipe_wall
    fill = (h.fill_pressure, h.fill_conductance) if h.fill_pressure is not None else (0.0, 0.0)
    relief = (h.relief_pressure, h.relief_conductance) if h.relief_pressure is not None else (math.inf, 0.0)
    return HydraulicDrive(
        Fluid(h.density_kg_m3, h.bulk_modulus, h.vapour_pressure),
        Pipe(h.pipe_length, h.pipe_diameter, wall, h.pipe_wall_modulus, h.friction_factor, h.reaches),
        Pump(area(h.plunger_diameter), h.pump_volume, h.leakage, *fill, *relief),
        Actuator(area(h.actuator_diameter), h.actuator_volume, h.leakage),
        Valve(h.valve_mass_kg, h.spring_rate, h.spring_preload_N, h.damping_N_s_per_m),
        h.initial_pressure, h.back_pressure)


def speed_plan(hydraulic, engine):
    """The engine speeds of the stage [rad/s]: (simulated speed, swept speeds, notes on the defaults taken)."""
    rpm = rpm_to_rad_s(1.0)
    notes = []
    speed = engine.rated_speed if hydraulic.speed is None else hydraulic.speed
    if hydraulic.speed is None:
        notes.append(f"engine speed of the simulation {speed / rpm:.0f} rpm: the rated speed")
    if hydraulic.speed_range is None:
        low, high = (f * engine.rated_speed for f in SPEED_RANGE)
        notes.append(f"speed range {low / rpm:.0f}-{high / rpm:.0f} rpm: {SPEED_RANGE[0]:.0%} to {SPEED_RANGE[1]:.0%} "
                     "of the rated speed")
    else:
        low, high = hydraulic.speed_range
    return speed, np.linspace(low, high, hydraulic.speeds), notes


def hydraulic_stage(hydraulic, law, engine, name):
    """One camshaft revolution of one valve's hydraulic drive, and one at each speed of a sweep.

    Parameters
    ----------
    hydraulic : SI view of ``[valves.NAME.hydraulic]``
    law : valvetrain.laws.LiftLaw
        The valve's cam law, the plunger lift.
    engine : SI view of ``[engine]``
        Rated speed and strokes.
    name : str
        The valve's name (the tables' file names).

    Returns
    -------
    HydraulicResult, list of Check

    Raises
    ------
    ValueError
        The grid and the speeds ask for more than :data:`MAX_NODE_STEPS` node updates (the message starts with the
        key ``reaches``).

    References
    ----------
    Shang Hanji (1988), ch. 7 (the drive) and ch. 3 (seating velocity and bounce); :mod:`valvetrain.hydraulic`.
    """
    drive = _drive(hydraulic)
    speed, speeds, notes = speed_plan(hydraulic, engine)
    to_cam = cam_per_crank(engine.strokes)
    revolutions = np.append(speeds, speed) * to_cam
    work = float(np.sum(2.0 * math.pi / revolutions)) / drive.time_step * (drive.pipe.reaches + 1)
    if work > MAX_NODE_STEPS:
        raise ValueError(f"reaches = {drive.pipe.reaches}: the simulation and the {speeds.size} speeds of the sweep "
                         f"take {work:.3g} node updates of the pipe grid (time step {drive.time_step * 1e6:.3g} us); "
                         f"allowed <= {MAX_NODE_STEPS:.0e}: use fewer reaches, a longer pipe, fewer speeds or higher "
                         "ones")
    r = simulate(law, drive, speed * to_cam)
    sw = speed_sweep(law, drive, speeds * to_cam, DELAY_LEVEL)
    opening, closing = r.delays(DELAY_LEVEL)
    _, seat_velocity, bounce = r.seating()
    ends = np.concatenate([r.pump_pressure, r.actuator_pressure])
    per_speed = HydraulicSweep(
        tuple(float(x) for x in speeds), tuple(sw.max_pressure.tolist()), tuple(sw.valve_lift.tolist()),
        tuple(sw.lift_loss.tolist()), tuple(map(finite_or_none, sw.opening_delay)),
        tuple(map(finite_or_none, sw.closing_delay)), tuple(sw.cavitation.tolist()),
        tuple(map(finite_or_none, sw.seating_velocity)), tuple(sw.bounce.tolist()))
    result = HydraulicResult(
        speed=speed, wave_speed=r.wave_speed, time_step=r.time_step, area_ratio=drive.area_ratio,
        rigid_lift=float(r.rigid_lift.max()), valve_lift=float(r.valve_lift.max()), lift_loss=r.lift_loss,
        opening_delay=finite_or_none(opening), closing_delay=finite_or_none(closing),
        max_pressure=r.max_pressure, max_pressure_angle=r.max_pressure_angle, min_pressure=float(ends.min()),
        vapour_pressure=hydraulic.vapour_pressure, cavitation=bool(r.cavitation.any()),
        seating_velocity=finite_or_none(seat_velocity), bounce=bounce,
        speed_range=(float(speeds[0]), float(speeds[-1])), speeds=int(speeds.size), per_speed=per_speed,
        notes=tuple(notes), table_file=f"tables/{name}_hydraulic.csv",
        sweep_table=f"tables/{name}_hydraulic_sweep.csv", response=r, sweep=sw)
    found = [check("hydraulic drive: smallest pressure above the vapour pressure", result.min_pressure,
                   low=hydraulic.vapour_pressure, strict_low=True, source=SOURCES, unit="MPa",
                   note="the liquid column separates (cavitation) where the pressure falls to the vapour pressure")]
    if result.seating_velocity is not None:
        found.append(check(SEATING_QUANTITY, abs(result.seating_velocity), high=SEATING_VELOCITY_MAX, unit="m/s",
                           source=SEATING_SOURCE))
    return result, found


TABLE_COLUMNS = [
    ("cam_deg", "camshaft angle from the cam nose [deg]"),
    ("plunger_lift_mm", "plunger (follower) lift [mm]"),
    ("pump_pressure_MPa", "absolute pressure at the pump end of the pipe [MPa]"),
    ("actuator_pressure_MPa", "absolute pressure at the actuator end of the pipe [MPa]"),
    ("valve_lift_mm", "valve lift [mm]"),
    ("rigid_lift_mm", "valve lift of the rigid drive, plunger lift x A_p / A_a [mm]"),
    ("cavitation", "1 where a pressure is held at the vapour pressure"),
]
"""Columns of ``tables/NAME_hydraulic.csv``."""


def table_columns(result, step=0.5 * DEG):
    """The hydraulic table in the units of :data:`TABLE_COLUMNS`: every k-th time step of the simulation, k the
    whole number of steps nearest to ``step`` [rad] of camshaft angle (at least 1); a cavitation between two rows
    is shown on the next row."""
    r = result.response
    stride = max(1, round(step / (r.angle[1] - r.angle[0])))
    rows = np.arange(0, r.angle.size, stride)
    flags = np.cumsum(r.cavitation)
    seen = np.diff(np.concatenate([[0], flags[rows]])) > 0
    return {"cam_deg": np.degrees(r.angle[rows]), "plunger_lift_mm": r.plunger_lift[rows] / MM,
            "pump_pressure_MPa": r.pump_pressure[rows] / 1e6, "actuator_pressure_MPa": r.actuator_pressure[rows] / 1e6,
            "valve_lift_mm": r.valve_lift[rows] / MM, "rigid_lift_mm": r.rigid_lift[rows] / MM,
            "cavitation": seen.astype(int)}


SWEEP_COLUMNS = [
    ("speed_rpm", "engine speed [rpm]"), ("camshaft_rpm", "camshaft speed [rpm]"),
    ("max_pressure_MPa", "largest absolute pressure at either end of the pipe [MPa]"),
    ("valve_lift_mm", "largest valve lift [mm]"), ("lift_loss_mm", "rigid lift less valve lift [mm]"),
    ("opening_delay_cam_deg", "opening delay against the rigid drive [cam deg]; empty: the valve stays shut"),
    ("closing_delay_cam_deg", "closing delay against the rigid drive [cam deg]; empty: the valve stays shut or open"),
    ("cavitation", "1 where the pressure fell to the vapour pressure, else 0"),
    ("seating_velocity_m_s", "valve velocity at the first seating [m/s]; empty: it does not return"),
    ("bounce_mm", "largest valve lift after the first seating [mm]"),
]
"""Columns of ``tables/NAME_hydraulic_sweep.csv``."""


def sweep_columns(result):
    """The per-speed table of a :class:`HydraulicResult` in the units of :data:`SWEEP_COLUMNS` (None: an empty
    cell)."""
    rec = record(result.per_speed)
    out = {"speed_rpm": rec["speed_rpm"], "camshaft_rpm": (result.sweep.cam_speed / rpm_to_rad_s(1.0)).tolist()}
    out.update((key, rec[key]) for key, _ in SWEEP_COLUMNS[2:])
    out["cavitation"] = [int(c) for c in rec["cavitation"]]
    return out


__all__ = ["HydraulicResult", "HydraulicSweep", "SWEEP_COLUMNS", "TABLE_COLUMNS", "hydraulic_stage", "speed_plan",
           "sweep_columns", "table_columns"]
