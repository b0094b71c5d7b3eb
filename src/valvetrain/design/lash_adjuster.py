"""The lash-adjuster stage: the stiffness the oil column adds to the drive, the leak-down per camshaft revolution and
its refill on the base circle over the speed range, and the pump-up of a float with the valve it holds off its seat
(Merritt (1967))."""

from dataclasses import dataclass
from typing import Optional

import numpy as np

from .. import lash_adjuster as hla
from ..bibliography import cite
from ..checks import Check, check
from .drive import event_load_maps
from .dynamics import adjuster_load
from .results import quantity

SOURCES = cite("merritt1967")
"""The work of the chapter, for the report."""


@dataclass(frozen=True)
class LashAdjusterPerSpeed:
    """The lash adjuster at each engine speed of the strength checks (SI)."""

    speed: tuple[float, ...] = quantity("speed_rpm", "rpm", "engine speed")
    load: tuple[str, ...] = quantity("load", label="the cam force at that speed: quasi-static or dynamic")
    leak_down: tuple[float, ...] = quantity("leak_down_um", "um", "plunger sink by leakage over one revolution")
    valve_lash: tuple[float, ...] = quantity("valve_lash_um", "um", "the lash it leaves at the valve at closing")
    refill_share: tuple[float, ...] = quantity("refill_share", label="time to refill it through the check valve / "
                                               "time on the base circle")
    pump_up: tuple[Optional[float], ...] = quantity("pump_up_um", "um", "plunger extension kept after a float "
                                                    "(null: no simulated force at that speed)")
    held_open: tuple[Optional[float], ...] = quantity("held_open_um", "um", "valve lift it holds at the next opening "
                                                      "(null: no simulated force at that speed)")


@dataclass(frozen=True)
class LashAdjusterResult:
    """The hydraulic lash adjuster of a valve (SI)."""

    location: str = quantity("location", label="pivot of an end-pivot finger, or in the tappet")
    motion_ratio: float = quantity("motion_ratio", label="valve motion / adjuster motion (pivot i - 1, tappet i)")
    reference_force: float = quantity("reference_force_N", "N", "largest quasi-static force on the adjuster at the "
                                      "rated speed")
    chamber_pressure: float = quantity("chamber_pressure_MPa", "MPa", "chamber pressure under it")
    compression: float = quantity("compression_um", "um", "plunger sink by the oil's compression under it")
    stiffness: float = quantity("stiffness_N_per_mm", "N/mm", "secant stiffness of the oil column at the adjuster")
    stiffness_at_valve: float = quantity("stiffness_at_valve_N_per_mm", "N/mm", "reduced to the valve, in series "
                                         "with the drive")
    drive_stiffness: Optional[float] = quantity("drive_stiffness_with_adjuster_N_per_mm", "N/mm", "drive stiffness "
                                                "of the dynamics with it", omit_none=True)
    rated_leak_down: float = quantity("rated_leak_down_um", "um", "leak-down per revolution at the rated speed")
    rated_valve_lash: float = quantity("rated_valve_lash_um", "um", "lash at the valve at closing, rated speed")
    max_refill_share: float = quantity("max_refill_share", label="largest refill time / base-circle time")
    max_pump_up: Optional[float] = quantity("max_pump_up_um", "um", "largest pump-up of a float up to the over-speed",
                                            omit_none=True)
    max_held_open: Optional[float] = quantity("max_held_open_um", "um", "largest valve lift held on the base circle "
                                              "after a float, up to the over-speed", omit_none=True)
    per_speed: LashAdjusterPerSpeed = quantity("per_speed", label="the lash adjuster at each speed")


def _leak_rate(la, force, area) -> np.ndarray:
    """Plunger sink velocity [m/s] under ``force`` on the adjuster [N]."""
    pressure = (force - la.plunger_spring_N) / area - la.supply_pressure
    return hla.annular_leakage(pressure, la.plunger_diameter, la.radial_clearance, la.leak_length,
                               la.oil_viscosity) / area


def lash_adjuster_stage(la, valve, engine, cam, drive, dynamics=None,
                        name="valve") -> tuple[LashAdjusterResult, list[Check]]:
    """The lash adjuster over the speed range (leak-down, refill, pump-up), with its checks.

    Parameters
    ----------
    la : SI view of ``[valves.NAME.lash_adjuster]``.
    valve, engine : SI views of the valve and the engine.
    cam : CamResult
    drive : DriveResult
    dynamics : DynamicsResult, optional
        Its simulated motion gives the floats that pump the adjuster up (none evaluated without it).
    name : str
        The valve's name (the messages' keys).

    Returns
    -------
    (LashAdjusterResult, list of Check)

    Notes
    -----
    The oil column enters the dynamics as its secant stiffness in series with the drive
    (:func:`valvetrain.design.dynamics.adjuster_link`); the
    hydraulic state changes too slowly to matter within a revolution and is followed from one revolution to the
    next: the leak-down under the force on the adjuster (:func:`valvetrain.lash_adjuster.annular_leakage`), the
    time to refill it on the base circle through the check valve, and for a float of the simulated motion the
    extension the plunger keeps (:func:`valvetrain.lash_adjuster.pump_up`) less the leak-down under the valve
    spring's preload over one base circle: what remains holds the valve off its seat.
    """
    at = f"valves.{name}"
    law, k = cam.law, valve.rocker_ratio
    ratio, ref = adjuster_load(valve, law, drive, cam.cam_speed, at)
    area = hla.plunger_area(la.plunger_diameter)
    refill = hla.check_valve_flow(hla.refill_pressure(la.supply_pressure, la.plunger_spring_N, area),
                                  la.check_valve_diameter) / area
    stiffness, sink, pressure = hla.secant_stiffness(ref, la.plunger_spring_N, area, la.supply_pressure,
                                                     la.chamber_volume, la.bulk_modulus, la.air_content)
    _, maps, (low, high, _) = event_load_maps(valve, engine, cam, drive, dynamics)
    to_cam = cam.cam_speed / engine.rated_speed
    base = 2.0 * np.pi - (law.valve_closes - law.valve_opens)
    pumped = _pump_up(la, dynamics, ratio, refill, area, drive.lines.chosen.preload, base, low, high)
    rows = []
    for m in maps:
        step = np.gradient(m.theta)
        for i, speed in enumerate(m.speeds):
            omega = speed * to_cam
            leak = float(np.sum(_leak_rate(la, np.clip(m.force[i], 0.0, None) / k * ratio, area) * step) / omega)
            pump = pumped.get(float(speed), (None, None)) if m.kind == "dynamic" else (None, None)
            rows.append((float(speed), m.kind, leak, leak * ratio, leak / refill / (base / omega), *pump))
    rows.sort(key=lambda row: row[0])
    per = LashAdjusterPerSpeed(*(tuple(col) for col in zip(*rows, strict=True)))
    rated = int(np.argmin(np.abs(np.asarray(per.speed) - engine.rated_speed)))
    pumps = [p for p in per.pump_up if p is not None]
    helds = [p for p in per.held_open if p is not None]
    result = LashAdjusterResult(
        la.location, ratio, ref, pressure, sink, stiffness, stiffness / ratio**2,
        None if dynamics is None else dynamics.parameters.drive_stiffness, per.leak_down[rated],
        per.valve_lash[rated], max(per.refill_share), max(pumps) if pumps else None, max(helds) if helds else None,
        per)
    where = f"{at}.lash_adjuster"
    found = [check("lash_adjuster.refill", result.max_refill_share,
                   high=1.0, source=f"{cite('merritt1967')}: annular leakage and the check valve's orifice flow; "
                   f"{where}", note="largest over the speeds up to the over-speed")]
    if pumps:
        found.append(check("lash_adjuster.pump_up", result.max_pump_up,
                           high=0.0, unit="um", source=f"{cite('merritt1967')}: the check valve's orifice flow; {where}"))
        found.append(check("lash_adjuster.held_open",
                           result.max_held_open, high=0.0, unit="um", severity="failure",
                           source=f"{cite('merritt1967')}: leak-down under the valve spring's preload over one base "
                                  f"circle; {where}"))
    return result, found


def _pump_up(la, dynamics, ratio, refill, area, preload, base, low,
             high) -> dict[float, tuple[float, float]]:
    """Pump-up [m] and valve held open [m] at each simulated speed in [low, high] [rad/s]: {speed: (pump, held)}."""
    if dynamics is None:
        return {}
    motions = [(float(s), dynamics.sweep.speed(i)) for i, s in enumerate(dynamics.per_speed.speed)]
    motions.append((float(dynamics.at_rated_speed.speed), dynamics.rated))
    out = {}
    for speed, r in motions:
        if not low * (1.0 - 1e-12) <= speed <= high * (1.0 + 1e-12):
            continue
        gap = np.where(r.separation, np.clip(r.lift - r.kinematic_lift, 0.0, None), 0.0) / ratio
        dt = float(r.theta[1] - r.theta[0]) / r.cam_speed
        pump = hla.pump_up(gap, dt, refill)
        relief = float(_leak_rate(la, preload * ratio, area)) * base / r.cam_speed
        out[speed] = (pump, max(pump - relief, 0.0) * ratio)
    return out
