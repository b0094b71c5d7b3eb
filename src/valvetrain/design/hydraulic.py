"""The hydraulic stage of a valve design: the valve driven through a liquid column ([valves.NAME.hydraulic]).

The valve's cam drives a plunger; the stage simulates one camshaft revolution of the drive of
:mod:`valvetrain.hydraulic` at the given engine speed and reports the pressures at both ends of the pipe, the
valve lift against the rigid drive (plunger lift times the area ratio), the delays and lift loss, the largest
pressure and the cavitation (a pressure held at the vapour pressure, a warning).
"""

from dataclasses import dataclass, field
import math
from typing import Optional

import numpy as np

from ..checks import check
from ..hydraulic import Actuator, DriveResult, Fluid, HydraulicDrive, Pipe, Pump, Valve, simulate
from ..units import DEG, MM, cam_per_crank
from .results import quantity

SOURCES = ("Shang Hanji (1988), ch. 7 (hydraulic valve actuation); Wylie and Streeter (1978) (wave speed, "
           "method of characteristics)")
"""The works the hydraulic stage follows, as the report cites them."""

MAX_NODE_STEPS = 5e7
"""Largest number of node updates (time steps x grid nodes) of one revolution the stage runs."""

DELAY_LEVEL = 0.05
"""Lift level of the delays, a fraction of the largest rigid lift."""


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
    table_file: str = quantity("table", label="the pressures and lifts against camshaft angle in the output folder")
    response: Optional[DriveResult] = field(default=None, repr=False)


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


def hydraulic_stage(hydraulic, law, engine, name):
    """One camshaft revolution of one valve's hydraulic drive.

    Parameters
    ----------
    hydraulic : SI view of ``[valves.NAME.hydraulic]``
    law : valvetrain.laws.LiftLaw
        The valve's cam law, the plunger lift.
    engine : SI view of ``[engine]``
        Rated speed and strokes.
    name : str
        The valve's name (the table's file name).

    Returns
    -------
    HydraulicResult, list of Check

    References
    ----------
    Shang Hanji (1988), ch. 7; :mod:`valvetrain.hydraulic`.
    """
    drive = _drive(hydraulic)
    speed = engine.rated_speed if hydraulic.speed is None else hydraulic.speed
    cam_speed = speed * cam_per_crank(engine.strokes)
    work = 2.0 * math.pi / cam_speed / drive.time_step * (drive.pipe.reaches + 1)
    if work > MAX_NODE_STEPS:
        raise ValueError(f"reaches = {drive.pipe.reaches}: one revolution takes {work:.3g} node updates of the pipe "
                         f"grid (time step {drive.time_step * 1e6:.3g} us); allowed <= {MAX_NODE_STEPS:.0e}: use "
                         "fewer reaches or a longer pipe")
    r = simulate(law, drive, cam_speed)
    opening, closing = r.delays(DELAY_LEVEL)
    ends = np.concatenate([r.pump_pressure, r.actuator_pressure])
    result = HydraulicResult(
        speed=speed, wave_speed=r.wave_speed, time_step=r.time_step, area_ratio=drive.area_ratio,
        rigid_lift=float(r.rigid_lift.max()), valve_lift=float(r.valve_lift.max()), lift_loss=r.lift_loss,
        opening_delay=None if math.isnan(opening) else opening, closing_delay=None if math.isnan(closing) else closing,
        max_pressure=r.max_pressure, max_pressure_angle=r.max_pressure_angle, min_pressure=float(ends.min()),
        vapour_pressure=hydraulic.vapour_pressure,
        cavitation=bool(r.cavitation.any()), table_file=f"tables/{name}_hydraulic.csv", response=r)
    found = [check("hydraulic drive: smallest pressure above the vapour pressure", result.min_pressure,
                   low=hydraulic.vapour_pressure, strict_low=True, source=SOURCES, unit="MPa",
                   note="the liquid column separates (cavitation) where the pressure falls to the vapour pressure")]
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


__all__ = ["HydraulicResult", "TABLE_COLUMNS", "hydraulic_stage", "table_columns"]
