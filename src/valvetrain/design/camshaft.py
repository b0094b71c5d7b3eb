"""The camshaft stage: the drive torque of every lobe of the named valves on every cylinder in firing order, its
harmonic orders and power, the shaft's twist, torsional natural frequencies and bending at the lobes, and the load
on the timing drive (``[camshaft]``).

Each lobe's torque is its valve's drive torque at the rated speed as the valve's stages made it: the dynamics
stage's simulated contact force where it ran (else the quasi-static force of the strength stage's load map), times
dh/dtheta, plus the friction torque of the lubrication stage where the valve has one.  Camshaft angles are measured
from cylinder 1's gas-exchange TDC (crank angle 0 is camshaft angle 0; the camshaft turns at half the crank speed
of a four-stroke).
"""

from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

import numpy as np

from .. import camshaft as shaft
from ..bibliography import cite
from ..checks import Check, check
from ..units import to_display
from ..layouts import finger_mass_change
from .crank import firing_angles
from .drive import contact_loads, event_load_maps
from .lubrication import contact_map
from .results import quantity, record

ANGLES = 7200
"""Camshaft angles of the torque over a revolution, evenly spaced (0.05 cam deg)."""

ORDERS = 60
"""Orders of the camshaft speed reported (0 ... ORDERS)."""

MODES = 3
"""Torsional natural frequencies reported (the lowest)."""

WORKS = f"{cite('shigley2011', 'chapter 3 (torsion), table A-9')}; {cite('denhartog1956')}; {cite('vt_works', 'eq. (7.3)')}"
"""The works of the chapter, for the report."""


@dataclass(frozen=True)
class LobeSet:
    """The lobes of one valve on the shaft: one lobe's torque over its own angles and where the lobes sit (SI)."""

    valve: str
    count: int                  # lobes of the valve per cylinder (the valve's count), at the cylinder's station
    theta: np.ndarray           # the lobe's angles [rad from the nose]
    torque: np.ndarray          # one lobe's drive torque at the rated speed [N m]
    noses: np.ndarray           # (C,) camshaft angle of the nose on each cylinder of the shaft [rad]
    force_max: float            # largest cam force of one lobe over the speed range [N] (the strength stage)
    train_inertia: float        # the valve train's mass reduced to the camshaft, m_t mean(h'^2) [kg m^2]
    load: str                   # "dynamic" or "quasi-static", "with friction" where the lubrication stage ran


@dataclass(frozen=True)
class CamshaftRecord:
    """The whole camshaft at the rated speed: drive torque, orders, torsion, bending and the timing drive."""

    valves: tuple[str, ...] = quantity("valves", label="valves whose lobes the camshaft carries")
    cylinders: tuple[int, ...] = quantity("cylinders", label="cylinders of the camshaft, from the drive end")
    lobes: int = quantity("lobes", label="lobes")
    ratio: float = quantity("camshaft_per_crank_revolution", label="camshaft revolutions per crank revolution")
    load: tuple[str, ...] = quantity("lobe_torque_load", label="each valve's lobe torque: its cam force and friction")
    peak: float = quantity("peak_torque_Nm", "N m", "largest drive torque over a camshaft revolution")
    peak_angle: float = quantity("peak_torque_cam_deg", "cam deg", "where, from cylinder 1's gas-exchange TDC")
    lowest: float = quantity("lowest_torque_Nm", "N m", "smallest drive torque (negative: the lobes drive the shaft)")
    mean: float = quantity("mean_torque_Nm", "N m", "mean drive torque (the friction and damping losses)")
    fluctuation: float = quantity("fluctuating_torque_Nm", "N m", "peak - lowest")
    rms_fluctuation: float = quantity("rms_fluctuating_torque_Nm", "N m", "root mean square of torque - mean")
    power: float = quantity("power_W", "W", "power taken at the rated speed, mean torque x omega_cam")
    orders: tuple[float, ...] = quantity("order_amplitudes_Nm", "N m", "amplitude of orders 0, 1, 2 ... of the "
                                         "camshaft speed")
    significant_orders: tuple[int, ...] = quantity("significant_orders", label="orders of at least "
                                                   "significant_order_share x the largest")
    natural_frequencies: tuple[float, ...] = quantity("natural_frequencies_Hz", "Hz", "lowest torsional natural "
                                                      "frequencies, through the timing drive's stiffness (absent: "
                                                      "the drive end held)")
    frequency_ratio: float = quantity("frequency_ratio", label="first natural frequency / highest significant order x "
                                      "omega_cam at the over-speed")
    resonance_speeds: tuple[float, ...] = quantity("resonance_speeds_rpm", "rpm", "engine speed at which each "
                                                   "significant order meets the first natural frequency")
    positions: tuple[float, ...] = quantity("station_positions_mm", "mm", "lobe stations from the drive end")
    station_inertia: tuple[float, ...] = quantity("station_inertias_kg_mm2", "kg mm2", "inertia of each station: "
                                                  "lobes, reduced train, shaft")
    max_twist: tuple[float, ...] = quantity("max_twist_cam_deg", "cam deg", "largest lag of each station behind the "
                                            "crankshaft at the rated speed: the shaft's twist and the timing "
                                            "drive's stretch")
    twist_max: float = quantity("largest_twist_cam_deg", "cam deg", "largest lag of any station")
    twist_crank: float = quantity("largest_twist_crank_deg", "crank deg", "the same in crank degrees")
    deflection: tuple[float, ...] = quantity("deflection_mm", "mm", "bending deflection at each station under its "
                                             "largest cam force")
    deflection_max: float = quantity("largest_deflection_mm", "mm", "largest bending deflection")
    drive: str = quantity("drive", label="timing drive: chain, belt or gears")
    drive_force: float = quantity("drive_force_max_N", "N", "largest tangential force of the timing drive, "
                                  "peak torque / pitch radius")
    drive_force_mean: float = quantity("drive_force_mean_N", "N", "mean tangential force")
    drive_allowable: float = quantity("drive_allowable_force_N", "N", "allowable force of the timing drive")
    drive_windup: float = quantity("drive_windup_cam_deg", "cam deg", "largest lag of the drive end behind the "
                                   "crankshaft, the drive's stretch under the torque (0: a rigid drive)")
    drive_end_inertia: float = quantity("drive_end_inertia_kg_mm2", "kg mm2", "inertia at the drive end: the "
                                        "sprocket, pulley or gear and its share of the shaft")


@dataclass(frozen=True, repr=False)
class CamshaftResults:
    """The camshaft chapter: the torque over a revolution, the twist of each station and the record (SI)."""

    psi: np.ndarray = field(repr=False)          # camshaft angles over a revolution [rad]
    torque: np.ndarray = field(repr=False)       # total drive torque [N m]
    twist: np.ndarray = field(repr=False)        # (L, n) lag of each station [rad]
    figures: CamshaftRecord
    checks: tuple[Check, ...]                    # the chapter's checks

    @cached_property
    def summary(self) -> dict[str, Any]:
        """The chapter's record in results.json (engineering units), made once."""
        return record(self.figures)


def lobe_set(name, valve, engine, design, firing) -> LobeSet:
    """The lobes of one valve on the shaft from its design (SI views of the valve and [engine]).

    Parameters
    ----------
    name : str
    valve, engine : SI views.
    design : ValveDesign
    firing : ndarray (C,)
        Firing angles after cylinder 1 of the shaft's cylinders [rad].

    Notes
    -----
    T(theta) = P_T(theta) dh/dtheta (+ T_f): the cam force at the rated speed from the strength stage's load maps
    (:func:`valvetrain.design.drive.event_load_maps`: the dynamics' simulated force where it ran), the friction torque
    from :func:`valvetrain.design.lubrication.contact_map` under the cam's normal force
    (:func:`valvetrain.design.drive.contact_loads`) where the valve has a lubrication section.  For a finger the law
    is the valve's and P_T the force at the valve: P_T dv/dtheta is the torque of the cam's normal force N =
    P_T G / (L_r cos beta) about the cam centre (the virtual work of the linkage; Norton (2009)).  The train's inertia
    reduced to the camshaft J = (1/2 pi) int m_t(theta) h'^2 dtheta (its kinetic energy m_t (omega h')^2 / 2 averaged
    over the revolution), m_t with a finger's J / G(psi)^2 at each angle
    (:func:`valvetrain.layouts.finger_mass_change`).
    """
    cam, drive = design.cam, design.drive
    maps = event_load_maps(valve, engine, cam, drive, design.dynamics)[1]
    m = min(maps, key=lambda m: float(np.min(np.abs(m.speeds - engine.rated_speed))))
    row = int(np.argmin(np.abs(m.speeds - engine.rated_speed)))
    force, theta = m.force[row], m.theta
    dh = cam.law.derivatives(theta)[1]
    load = m.kind
    if design.lubrication is not None:
        omega = np.array([[cam.cam_speed]])
        normal = contact_loads(cam, [m])[0].force[row]
        torque = contact_map(valve.lubrication, cam, valve.parts.cam_width, valve.parts.contact_modulus, theta,
                             normal[None, :], omega)["drive_torque"][0]
        load += ", with friction"
    else:
        torque = np.where(force > 0.0, force, 0.0) * dh
    inertia = (drive.masses.at_tappet * float(np.trapezoid(dh**2, theta))
               + float(np.trapezoid(finger_mass_change(valve, cam.law, theta) * dh**2, theta))) / (2.0 * np.pi)
    return LobeSet(name, valve.count, theta, torque, shaft.lobe_noses(cam.nose, firing, engine.strokes),
                   drive.strength.cam_force_max, inertia, load)


def camshaft_torque(psi, lobes) -> np.ndarray:
    """Drive torque of each cylinder's lobes at camshaft angles ``psi`` [N m], (C, n): the sum over the valves of
    count x one lobe's torque (:func:`valvetrain.camshaft.lobe_torques`)."""
    return sum(s.count * shaft.lobe_torques(psi, s.theta, s.torque, s.noses) for s in lobes)


def camshaft_stage(c, engine, valves, designs) -> CamshaftResults:
    """The camshaft chapter: ``c``, ``engine`` and ``valves`` are the SI views of [camshaft], [engine] and the
    valves, ``designs`` the valves' designs.

    Returns
    -------
    CamshaftResults
    """
    names = list(c.valves) if c.valves is not None else list(designs)
    cylinders = list(c.cylinders) if c.cylinders is not None else list(range(1, engine.cylinders + 1))
    firing = firing_angles(engine)[0][np.asarray(cylinders) - 1]
    lobes = [lobe_set(n, valves[n], engine, designs[n], firing) for n in names]
    ratio = shaft.camshaft_ratio(engine.strokes)
    psi = 2.0 * np.pi * np.arange(ANGLES) / ANGLES
    stations = camshaft_torque(psi, lobes)
    total = stations.sum(axis=0)
    figures = shaft.torque_figures(total)
    amplitudes = shaft.harmonic_orders(total, ORDERS)
    fluctuating = amplitudes[1:]
    significant = tuple(int(k) for k in np.nonzero(fluctuating >= c.significant_order_share * fluctuating.max())[0] + 1)
    cam_speed = ratio * engine.rated_speed

    x = np.asarray(c.cylinder_positions, dtype=float)
    lengths, diameters = np.asarray(c.section_lengths), np.asarray(c.section_diameters)
    bores = np.asarray(c.section_bores) if c.section_bores is not None else np.zeros_like(diameters)
    compliance = shaft.shaft_compliance(x, lengths, diameters, bores, c.shear_modulus)
    drive_k = np.inf if c.drive_stiffness is None else \
        shaft.drive_torsional_stiffness(c.drive_stiffness, c.drive_pitch_radius)
    lag = shaft.twist(compliance + 1.0 / drive_k, stations)
    lobe_count = sum(s.count for s in lobes)
    lumped = shaft.lumped_shaft_inertia(np.concatenate([[0.0], x]), lengths, diameters, bores, c.density_kg_m3)
    inertia = lobe_count * c.lobe_inertia + sum(s.count * s.train_inertia for s in lobes) + lumped[1:]
    sprocket = c.sprocket_inertia + lumped[0]
    omega_n = shaft.torsional_frequencies(*shaft.with_drive_end(shaft.station_stiffness(compliance), inertia,
                                                                drive_k, sprocket))
    top = max(significant)
    ratio_n = float(omega_n[0] / (top * cam_speed * engine.over_speed_ratio))
    section = shaft.section_at(x, lengths)
    force = sum(s.count * s.force_max for s in lobes) * np.ones_like(x)
    bend = shaft.lobe_deflection(force, x, np.asarray(c.journal_positions), diameters[section], bores[section],
                                 c.modulus)
    drive_force = shaft.drive_force(np.array([figures["peak"], figures["mean"]]), c.drive_pitch_radius)
    twist_max = float(np.max(np.abs(lag)))
    j = int(np.argmax(total))
    record_ = CamshaftRecord(
        tuple(names), tuple(cylinders), lobe_count * len(cylinders), ratio, tuple(f"{s.valve}: {s.load}" for s in lobes),
        figures["peak"], float(psi[j]), figures["lowest"], figures["mean"], figures["fluctuation"],
        figures["rms_fluctuation"], figures["mean"] * cam_speed, tuple(float(a) for a in amplitudes), significant,
        tuple(float(w) / (2.0 * np.pi) for w in omega_n[:MODES]), ratio_n,
        tuple(float(n) for n in shaft.resonance_speeds(omega_n[0], significant, ratio)), tuple(float(p) for p in x),
        tuple(float(i) for i in inertia), tuple(float(t) for t in np.max(np.abs(lag), axis=1)), twist_max,
        twist_max / ratio, tuple(float(f) for f in bend), float(bend.max()), c.drive, float(drive_force[0]),
        float(drive_force[1]), c.drive_allowable_force_N, float(np.max(np.abs(total)) / drive_k), float(sprocket))
    return CamshaftResults(psi, total, lag, record_, tuple(camshaft_checks(record_, c, engine)))


TWIST_FAILURE = np.radians(10.0)
"""A camshaft twist beyond which its check is a failure, not a warning [rad, camshaft]: 10 cam deg (20 crank deg), the
largest ``max_twist_cam_deg`` allows, an engineering limit: valve events that far from their timing are no longer
the engine's (and a shaft that twists so far elastically is far past its yield)."""


def camshaft_checks(r, c, engine) -> list[Check]:
    """The camshaft's checks: the timing error of the twist, the torsional resonance margin, the bending deflection
    at the lobes and the timing drive's load.

    Notes
    -----
    The limits of the twist (``max_twist_cam_deg``) and of the frequency ratio (``min_frequency_ratio``) are
    engineering assumptions, keys with bounded defaults: no published camshaft limit was found; a twist beyond
    :data:`TWIST_FAILURE` is a failure.  The allowable of the
    timing drive is the maker's (``drive_allowable_force_N``); for a roller chain the working load is commonly at most
    1/6 of its tensile strength (Diamond Chain (n.d.)).
    """
    over = to_display(engine.over_speed_ratio * engine.rated_speed, "rpm")
    held = "the drive end held" if c.drive_stiffness is None else "through the timing drive's stiffness"
    return [
        check("camshaft.twist_timing_error", r.twist_max, high=c.max_twist, unit="cam deg",
              severity="failure" if r.twist_max > TWIST_FAILURE else "warning",
              source=f"{cite('shigley2011', 'chapter 3 (torsion)')}; camshaft.max_twist_cam_deg (an engineering "
                     f"assumption; beyond {np.degrees(TWIST_FAILURE):g} cam deg a failure)",
              note=f"{to_display(r.twist_crank, 'crank deg'):.3g} crank deg; quasi-static, {held}"),
        check("camshaft.torsional_resonance", r.frequency_ratio, low=c.min_frequency_ratio, severity="warning",
              source=f"{cite('denhartog1956')}; camshaft.min_frequency_ratio (an engineering assumption)",
              note=f"first natural frequency {r.natural_frequencies[0]:.4g} Hz against order {max(r.significant_orders)} "
                   f"at the over-speed {over:.0f} rpm"),
        check("camshaft.bending_deflection", r.deflection_max, high=c.max_deflection, unit="mm", severity="failure",
              source=f"{cite('vt_works', 'eq. (7.3)')}: 0.02-0.05 mm; {cite('shigley2011', 'table A-9')}",
              note="each lobe alone on a simply supported span between its journals"),
        check("camshaft.timing_drive_force", r.drive_force, high=c.drive_allowable_force_N, unit="N",
              severity="failure", source="camshaft.drive_allowable_force_N (the maker's allowable of the "
                                         f"{c.drive}{'; ' + cite('diamondchain') if c.drive == 'chain' else ''})",
              note=f"peak torque {r.peak:.4g} N m at the pitch radius {to_display(c.drive_pitch_radius, 'mm'):g} mm"),
    ]
