"""The lash-adjuster stage: the stiffness the oil column adds to the drive, and over the speed range the leak-down per
camshaft revolution and its refill on the base circle, the pump-up of the plunger while the valve is off its seat,
accumulated revolution by revolution up to the plunger's stop, and the lift at which the valve it holds off its seat
settles, from the plunger extension the dynamics carries from revolution to revolution (Merritt (1967))."""

from dataclasses import dataclass
from typing import Optional

import numpy as np

from .. import lash_adjuster as hla
from ..bibliography import cite
from ..checks import Check, check
from ..locale import cited, note
from ..dynamics.events import lift_event, zero_crossing
from ..dynamics.sweep import sweep, sweep_size
from ..units import DEG, to_display
from .drive_strength import event_load_maps
from .dynamics import MAX_SWEEP_WORK, adjuster_element, adjuster_load, build_train
from .results import quantity

SOURCES = cite("merritt1967")
"""The work of the chapter, for the report."""

PUMP_UP_TOLERANCE = 0.1e-6
"""Plunger extension gained over a camshaft revolution while the valve is off its seat that counts as pump-up [m, at
the adjuster]: a tenth of the dynamics' 1 um lift accuracy (:mod:`valvetrain.dynamics.kernels`); in a train that does
not float the plunger only sinks while the valve is open, by leakage."""

PUMP_REVOLUTIONS = 400
"""Most camshaft revolutions of the integration that follows a plunger pumping up to where it settles
(:func:`lash_adjuster_stage`).  The plunger is the train's slow state: once the valve is held off its seat, the
spring's force on the base circle leaks it back down, and the leak-down grows with the held lift until it balances the
pump-up of a revolution, a geometric approach by about 0.98-0.99 a revolution (the polydyne example preloaded to 150 N:
238 and 342 revolutions at 5419 and 5974 rpm to settle within :data:`SETTLED`); a plunger that reaches its stop
settles within a few revolutions of it."""

SETTLED = 1e-7
"""A pumped-up motion is settled when its state at the end of a revolution differs from the start by no more than
0.1 um at the valve (its plunger's extension times the motion ratio, and every position of the train) [m]: the held
lift is then within about 6 um of its limit on the polydyne example's geometric approach (1e-8 moves it by 1.1 and
5.8 um there), against the hundreds of um of a valve held open."""


@dataclass(frozen=True)
class LashAdjusterPerSpeed:
    """The lash adjuster at each engine speed of the strength checks (SI)."""

    speed: tuple[float, ...] = quantity("speed_rpm", "rpm", "engine speed")
    load: tuple[str, ...] = quantity("load", label="the cam force at that speed: quasi-static or dynamic (the "
                                     "plunger's motion simulated with the train)")
    leak_down: tuple[float, ...] = quantity("leak_down_um", "um", "plunger sink by leakage over one revolution")
    valve_lash: tuple[float, ...] = quantity("valve_lash_um", "um", "the lash it leaves at the valve at closing")
    refill_share: tuple[float, ...] = quantity("refill_share", label="time to refill it through the check valve / "
                                               "time on the base circle")
    stiffness_at_valve: tuple[Optional[float], ...] = quantity(
        "oil_stiffness_at_valve_N_per_mm", "N/mm", "secant stiffness of the oil column under the largest force at that "
        "speed, reduced to the valve (null: the force does not exceed the plunger's push)")
    pump_up: tuple[Optional[float], ...] = quantity("pump_up_um", "um", "plunger extension gained over one "
                                                    "revolution while the valve is off its seat, in the settled "
                                                    "motion (null: no simulated motion at that speed)")
    pumped_up: tuple[Optional[float], ...] = quantity("pumped_up_um", "um", "the plunger's largest extension from its "
                                                      "working position in the settled motion, no more than its "
                                                      "travel to the stop (null: no simulated motion at that speed)")
    held_open: tuple[Optional[float], ...] = quantity("held_open_um", "um", "smallest valve lift on the base circle in "
                                                      "the settled motion: the lift at which the valve held off its "
                                                      "seat settles (null: no simulated motion at that speed)")
    revolutions: tuple[Optional[int], ...] = quantity("revolutions", label="camshaft revolutions from rest to the "
                                                      "settled motion (null: no simulated motion at that speed)")
    settled: tuple[Optional[bool], ...] = quantity("settled", label="the motion settled within its revolutions "
                                                   "(null: no simulated motion at that speed)")


@dataclass(frozen=True)
class LashAdjusterResult:
    """The hydraulic lash adjuster of a valve (SI)."""

    location: str = quantity("location", label="pivot of an end-pivot finger, or in the tappet")
    motion_ratio: float = quantity("motion_ratio", label="valve motion / adjuster motion (pivot i - 1, of a "
                                   "finger its linkage along the adjuster's axis; tappet i)")
    eccentricity: float = quantity("plunger_eccentricity", label="the plunger's eccentricity e / c in its bore, "
                                   "[lash_adjuster] plunger_eccentricity (0: concentric)")
    leak_factor: float = quantity("leak_factor", label="its leakage over the concentric plunger's, 1 + 1.5 (e / c)^2 "
                                  "(Merritt (1967); 2.5 fully eccentric)")
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
    travel: float = quantity("plunger_travel_mm", "mm", "the plunger's travel from its working position to its stop")
    max_pump_up: Optional[float] = quantity("max_pump_up_um", "um", "largest pump-up per revolution up to the "
                                            "over-speed", omit_none=True)
    max_pumped_up: Optional[float] = quantity("max_pumped_up_um", "um", "largest extension the plunger pumps up to, "
                                              "up to the over-speed", omit_none=True)
    max_held_open: Optional[float] = quantity("max_held_open_um", "um", "largest lift at which a valve held on the "
                                              "base circle settles, up to the over-speed", omit_none=True)
    held_open_speed: Optional[float] = quantity("held_open_speed_rpm", "rpm", "where", omit_none=True)
    push_at_valve: float = quantity("push_at_valve_N", "N", "the adjuster's own push (F_s + p_s A) / i_a at the valve: "
                                    "the follower's force at which the check valve opens")
    float_speed: Optional[float] = quantity("float_speed_rpm", "rpm", "lowest engine speed where the follower's "
                                            "force falls to that push while the cam lifts the open valve (a float the "
                                            "plunger follows), interpolated; null: none in the range swept",
                                            omit_none=True)
    per_speed: LashAdjusterPerSpeed = quantity("per_speed", label="the lash adjuster at each speed")


def _stiffness_at_valve(la, force, ratio, area) -> Optional[float]:
    """Secant stiffness of the oil column under ``force`` on the adjuster [N], reduced to the valve [N/m]; None where
    the force does not compress it (no more than the plunger's push)."""
    stiffness = hla.secant_stiffness(force, la.plunger_spring_N, area, la.supply_pressure, la.chamber_volume,
                                     la.bulk_modulus, la.air_content)[0]
    return float(stiffness / ratio**2) if np.isfinite(stiffness) else None


def float_speed(speeds, lifting_force, push) -> float:
    """The lowest speed where the follower floats with a lash adjuster, interpolated between the speeds of a sweep.

    Parameters
    ----------
    speeds : ndarray (S,)
        Ascending speeds (any unit; the result is in it).
    lifting_force : ndarray (S,)
        Smallest contact force at the valve while the cam lifts the open valve in its lift event [N]
        (:func:`valvetrain.dynamics.events.lowest_lifting_force`; nan: the valve does not open).
    push : float
        The adjuster's own push at the valve, (F_s + p_s A) / i_a [N].

    Returns
    -------
    float
        :func:`valvetrain.dynamics.events.zero_crossing` of the force less the push (nan: no float).

    Notes
    -----
    A mechanical train separates where its contact force falls to 0 while the cam lifts the open valve
    (:func:`valvetrain.dynamics.events.separation_mask`).  With a hydraulic lash adjuster the contact need not open:
    where the follower's force falls to the adjuster's push (F_s + p_s A) / i_a the chamber pressure falls to the
    supply, the check valve opens and the plunger extends after the follower (:func:`valvetrain.dynamics.kernels`'
    ``_adjust``), holding the contact at that push, and the valve leaves the cam law by the plunger's extension.  The
    engineering definition of the float used here: the cam no longer holds the valve against its spring, the oil
    does, i.e. the follower's force at or below the push while the cam lifts the open valve (the check valve's opening
    condition, Merritt (1967)); the same as a separation of the train without the adjuster whose spring preload is
    less by the push.

    >>> float(float_speed(np.array([1.0, 2.0, 3.0]), np.array([90.0, 70.0, 50.0]), 50.0))
    3.0
    >>> float(float_speed(np.array([1.0, 2.0]), np.array([90.0, 70.0]), 50.0))
    nan
    """
    margin = np.asarray(lifting_force, dtype=float) - push
    return zero_crossing(np.asarray(speeds, dtype=float), margin, margin <= 1e-9 * push)


def plunger_motion(extension, lift, event, base) -> tuple[float, float, float]:
    """Leak-down, pump-up [m, at the adjuster] and the valve held off its seat [m] over one simulated revolution.

    Parameters
    ----------
    extension : ndarray (n,)
        Plunger extension over the revolution, in time order [m, at the adjuster]
        (:attr:`valvetrain.dynamics.sweep.SpeedResult.adjuster_extension`).
    lift : ndarray (n,)
        Valve lift at the same instants [m] (> 0: off its seat).
    event : ndarray (n,) of bool
        The cam's lift event up to the valve's first return to its seat
        (:func:`valvetrain.dynamics.events.lift_event`).
    base : ndarray (n,) of bool
        The cam's base circle (no cam lift).

    Returns
    -------
    (leak_down, pump_up, held_open)
        The plunger's sink summed over the revolution; its extension gained while the valve is off its seat in the
        lift event (the check valve opens only where the follower's force falls to the adjuster's own push, which a
        valve carried by the cam never lets it: the follower floats; after the valve's first return the plunger
        refills its leak-down, also while the valve bounces); the smallest valve lift on the base circle (0: the valve
        seats).

    Examples
    --------
    The plunger sinks 2 um with the valve open, extends 3 um while it floats, and refills 1 um after the valve's
    return, in a bounce:

    >>> z = np.array([5.0, 4.0, 3.0, 6.0, 6.0, 7.0, 7.0]) * 1e-6
    >>> y = np.array([0.0, 1.0, 2.0, 1.0, -1e-3, 2e-3, -1e-3]) * 1e-3
    >>> event = np.array([0, 1, 1, 1, 0, 0, 0], dtype=bool)
    >>> [round(v * 1e6, 9) for v in plunger_motion(z, y, event, np.array([1, 0, 0, 0, 0, 0, 1], dtype=bool))]
    [2.0, 3.0, 0.0]
    """
    step = np.diff(extension)
    floating = event[1:] & (lift[1:] > 0.0)
    return (float(-step[step < 0.0].sum()), float(step[(step > 0.0) & floating].sum()),
            max(float(lift[base].min()), 0.0))


def lash_adjuster_stage(la, valve, engine, cam, drive, dynamics=None,
                        name="valve") -> tuple[LashAdjusterResult, list[Check]]:
    """The lash adjuster over the speed range (leak-down, refill, stiffness, pump-up), with its checks.

    Parameters
    ----------
    la : SI view of ``[valves.NAME.lash_adjuster]``.
    valve, engine : SI views of the valve and the engine.
    cam : CamResult
    drive : DriveResult
    dynamics : DynamicsResult, optional
        Its simulated motion, the plunger's extension a state of it (none evaluated without it).
    name : str
        The valve's name (the messages' keys).

    Returns
    -------
    (LashAdjusterResult, list of Check)

    Notes
    -----
    The oil column enters the dynamics as its secant stiffness in series with the drive
    (:func:`valvetrain.design.dynamics.adjuster_link`) and its plunger as a state of the integration
    (:func:`valvetrain.design.dynamics.adjuster_element`): it leaks down through the annular clearance under the
    force it carries (:func:`valvetrain.lash_adjuster.annular_leakage`) and refills through the check valve where
    that force falls to its own push, no further than its stop.  At the simulated speeds the leak-down, the pump-up and
    the valve held off its seat are read from that state (:func:`plunger_motion`).  Where the sweep's motion did not
    repeat because the plunger still pumps up (it gained more than :data:`PUMP_UP_TOLERANCE` while the valve was off
    its seat), the same train is integrated again at those speeds for up to :data:`PUMP_REVOLUTIONS` revolutions
    until its motion settles within :data:`SETTLED` a revolution: the pump-up accumulates revolution by revolution,
    until the leak-down of the valve it holds off its seat balances it or the plunger reaches its stop, and the
    figures are those of the settled revolution.  At a speed of the strength range the dynamics does not sweep, the
    leak-down is the laminar leakage integrated over the quasi-static force.  The time to refill the leak-down through
    the check valve is compared with the time on the base circle.
    """
    at = f"valves.{name}"
    law, k = cam.law, valve.rocker_ratio
    ratio, ref = adjuster_load(valve, law, drive, cam.cam_speed, at)
    element = adjuster_element(la, ratio)
    area = element.area
    stiffness, sink, pressure = hla.secant_stiffness(ref, la.plunger_spring_N, area, la.supply_pressure,
                                                     la.chamber_volume, la.bulk_modulus, la.air_content)
    _, maps, (low, high, _) = event_load_maps(valve, engine, cam, drive, dynamics)
    to_cam = cam.cam_speed / engine.rated_speed
    base = 2.0 * np.pi - (law.valve_closes - law.valve_opens)
    rows = []
    for speed, r in _settled(_motions(dynamics, low, high), valve, law, drive, cam.cam_speed, at):
        leak, pump, held = plunger_motion(r.adjuster_extension, r.lift, lift_event(r.kinematic_lift, r.lift),
                                          law.lift(r.theta) <= 0.0)
        force = float(r.contact_force.max()) / k * ratio
        rows.append((speed, "dynamic", leak, force, pump, float(r.adjuster_extension.max()), held, int(r.revolutions),
                     bool(r.converged)))
    for m in maps:
        if m.kind == "dynamic":
            continue
        step = np.gradient(m.theta)
        for i, speed in enumerate(m.speeds):
            force = np.clip(m.force[i], 0.0, None) / k * ratio
            pressure_drop = np.clip((force - la.plunger_spring_N) / area - la.supply_pressure, 0.0, None)
            sinking = element.leak * pressure_drop / area
            rows.append((float(speed), m.kind, float(np.sum(sinking * step)) / (speed * to_cam), float(force.max()),
                         None, None, None, None, None))
    rows = [(speed, kind, leak, leak * ratio, leak / element.refill / (base / (speed * to_cam)),
             _stiffness_at_valve(la, force, ratio, area), pump, pumped, held, revs, settled)
            for speed, kind, leak, force, pump, pumped, held, revs, settled in sorted(rows, key=lambda row: row[0])]
    per = LashAdjusterPerSpeed(*(tuple(col) for col in zip(*rows, strict=True)))
    rated = int(np.argmin(np.abs(np.asarray(per.speed) - engine.rated_speed)))
    pumps = [p for p in per.pump_up if p is not None]
    helds = [(h, i) for i, h in enumerate(per.held_open) if h is not None]
    worst = max(helds)[1] if helds else None
    push = element.push
    floats = np.nan
    if dynamics is not None:
        floats = float_speed(dynamics.per_speed.speed, np.asarray(dynamics.per_speed.min_contact_force) / k, push)
    result = LashAdjusterResult(
        la.location, ratio, la.plunger_eccentricity, float(hla.eccentricity_factor(la.plunger_eccentricity)), ref,
        pressure, sink, stiffness, stiffness / ratio**2,
        None if dynamics is None else dynamics.parameters.drive_stiffness, per.leak_down[rated],
        per.valve_lash[rated], max(per.refill_share), la.plunger_travel, max(pumps) if pumps else None,
        max((p for p in per.pumped_up if p is not None), default=None), None if worst is None else per.held_open[worst],
        None if worst is None else per.speed[worst], push, floats if np.isfinite(floats) else None, per)
    where = f"{at}.lash_adjuster"
    found = [check("lash_adjuster.refill", result.max_refill_share,
                   high=1.0, source=cited(note("source.refill", work=cite("merritt1967")), where), note=note("lash_adjuster.largest_over_speeds"))]
    if pumps:
        found.append(check("lash_adjuster.pump_up", result.max_pump_up, high=PUMP_UP_TOLERANCE, unit="um",
                           severity="failure", source=cited(note("source.pump_up", work=cite("merritt1967")), where)))
        top = dynamics.speed_range[1]
        said = "" if np.isfinite(floats) else note("lash_adjuster.no_float", speed_rpm=to_display(top, "rpm"))
        found.append(check("lash_adjuster.float", (floats if np.isfinite(floats) else top) / engine.rated_speed,
                           low=engine.over_speed_ratio, severity="failure", note=said,
                           source=cited(note("source.adjuster_float", push_N=push, work=cite("merritt1967")), where)))
        found.append(check("lash_adjuster.held_open",
                           result.max_held_open, high=0.0, unit="um", severity="failure",
                           note=held_note(per, worst, la.plunger_travel),
                           source=cited(note("source.held_open", work=cite("merritt1967"),
                                             stop=cite("enginebuilder2011")), where)))
    return result, found


HELD_NOTES = {(True, False): "lash_adjuster.held_settled", (True, True): "lash_adjuster.held_settled_at_stop",
              (False, False): "lash_adjuster.held_unsettled", (False, True): "lash_adjuster.held_unsettled_at_stop"}
"""The note of a valve held open by whether its motion settled and whether the plunger reached its stop."""


def held_note(per, worst, travel) -> tuple | str:
    """The note of the check of the valve held open: where the largest held lift settles, the plunger's extension
    there and whether it reached its stop, after how many revolutions (or that it had not settled); empty where the
    valve seats at every simulated speed."""
    if per.held_open[worst] <= 0.0:
        return ""
    extension = per.pumped_up[worst]
    code = HELD_NOTES[bool(per.settled[worst]), bool(extension >= travel * (1.0 - 1e-9))]
    return note(code, held_um=to_display(per.held_open[worst], "um"), speed_rpm=to_display(per.speed[worst], "rpm"),
                extension_um=to_display(extension, "um"), revolutions=per.revolutions[worst])


def _settled(motions, valve, law, drive, cam_speed, at) -> list:
    """The simulated motions ``motions`` ((speed, SpeedResult) pairs), each replaced by its settled motion where the
    sweep left its plunger pumping up: it did not repeat and its plunger gained more than :data:`PUMP_UP_TOLERANCE`
    while the valve was off its seat.  Those speeds are integrated again, from rest, for up to
    :data:`PUMP_REVOLUTIONS` revolutions until they repeat within :data:`SETTLED` (the train of
    :func:`valvetrain.design.dynamics.build_train`, ``cam_speed`` the rated camshaft speed [rad/s]); fewer where
    that would exceed the sweep's limit of work :data:`~valvetrain.design.dynamics.MAX_SWEEP_WORK` (unless ``[dynamics]
    allow_large_sweep``), their motions then flagged unsettled."""
    pumping = [j for j, (_, r) in enumerate(motions) if not r.converged and plunger_motion(
        r.adjuster_extension, r.lift, lift_event(r.kinematic_lift, r.lift), law.lift(r.theta) <= 0.0)[1]
        > PUMP_UP_TOLERANCE]
    if not pumping:
        return motions
    train = build_train(valve.dynamics, valve, law, drive, at, cam_speed)[0]
    speeds, step = [motions[j][1].cam_speed for j in pumping], valve.dynamics.step / DEG
    revolutions = PUMP_REVOLUTIONS
    if not valve.dynamics.allow_large_sweep:
        work = sweep_size(train.network(), speeds, 1, step)[0]
        revolutions = max(min(revolutions, int(MAX_SWEEP_WORK // work)), 1)
    again = sweep(law, train, speeds, revolutions, step, tolerance=SETTLED)
    out = list(motions)
    for i, j in enumerate(pumping):
        out[j] = (motions[j][0], again.speed(i))
    return out


def _motions(dynamics, low, high) -> list:
    """The simulated motions at the engine speeds in [low, high] [rad/s]: (speed, SpeedResult), the sweep's and the
    rated speed's (none without the dynamics)."""
    if dynamics is None:
        return []
    motions = [(float(s), dynamics.sweep.speed(i)) for i, s in enumerate(dynamics.per_speed.speed)]
    motions.append((float(dynamics.at_rated_speed.speed), dynamics.rated))
    return [(s, r) for s, r in motions if low * (1.0 - 1e-12) <= s <= high * (1.0 + 1e-12)]
