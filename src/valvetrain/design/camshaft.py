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
from scipy.interpolate import interp1d

from .. import camshaft as shaft
from ..bibliography import cite
from ..checks import Check, check
from ..locale import cited, note
from ..numerics import first_largest
from ..units import to_display
from ..layouts import finger_mass_change
from .crank import firing_angles
from .drive_strength import contact_loads, event_load_maps
from .lubrication import contact_map
from .results import quantity, record

ANGLES = 7200
"""Camshaft angles of the torque over a revolution, evenly spaced (0.05 cam deg)."""

ORDERS = 60
"""Orders of the camshaft speed reported (0 ... ORDERS)."""

MODES = 3
"""Torsional natural frequencies reported (the lowest)."""

TORSION_TABLE = "tables/camshaft_torsion.csv"
"""The file of the torsional response at every speed of the running range."""

RESPONSE_SPEEDS = 400
"""Evenly spaced engine speeds of the torsional response over the running range; the speeds at which a significant
order meets one of the :data:`MODES` lowest natural frequencies are added, where the response peaks."""

SERIES_ANGLES = 720
"""Camshaft angles of a revolution at which the response's lag and drive force are summed from their orders (0.5 cam
deg, more than twice :data:`ORDERS`)."""

LISTED_RESONANCES = 4
"""Resonances of the running range a check's note names (the largest timing fluctuations first)."""

WORKS = cited(note("source.torsion_table", work=cite("shigley2011", "chapter 3"), table="A-9"), cite("denhartog1956"),
              cite("vt_works", "eq. (7.3)"), cite("chrysler2002"))
"""The works of the chapter, for the report."""

DRIVE_ALLOWABLES = {"chain": "source.chain_allowable", "belt": "source.belt_allowable", "gears": "source.gears_allowable"}
"""The source of a timing drive's allowable force by the drive's kind (``camshaft.drive``): the maker's."""


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
    speeds: np.ndarray          # (S,) engine speeds of the running range the torque is known at, ascending [rad/s]
    phasors: np.ndarray         # (S, ORDERS + 1) one lobe's torque orders there, its nose at 0 [N m, complex]


@dataclass(frozen=True)
class TorsionalResonance:
    """A natural frequency met by a significant order of the camshaft speed inside the running range, and the
    response there (SI)."""

    mode: int = quantity("mode", label="the mode, lowest first")
    frequency: float = quantity("natural_frequency_Hz", "Hz", "its natural frequency")
    order: int = quantity("order", label="the significant order of the camshaft speed that meets it")
    speed: float = quantity("speed_rpm", "rpm", "the engine speed where they meet")
    fluctuation: float = quantity("timing_fluctuation_cam_deg", "cam deg", "the largest fluctuation of a lobe's "
                                  "timing there: its largest less its smallest lag behind the crankshaft over a "
                                  "revolution")
    drive_force: float = quantity("drive_force_N", "N", "the largest force of the timing drive there")


@dataclass(frozen=True)
class TorsionalResponse:
    """The steady torsional response of the camshaft and its timing drive to the lobes' torque over the running
    range, by modal superposition (SI)."""

    damping_ratio: float = quantity("damping_ratio", label="modal damping ratio of every torsional mode, [camshaft] "
                                    "torsional_damping_ratio")
    speed_range: tuple[float, float] = quantity("speed_range_rpm", "rpm", "the running range: the lowest speed of "
                                                "the strength checks to the over-speed")
    allowable: float = quantity("timing_fluctuation_allowable_cam_deg", "cam deg", "allowable fluctuation of a "
                                "lobe's timing: [camshaft] max_timing_play_mm over the pitch radius")
    fluctuation: float = quantity("largest_timing_fluctuation_cam_deg", "cam deg", "the largest fluctuation of a "
                                  "lobe's timing over the running range")
    fluctuation_speed: float = quantity("largest_timing_fluctuation_speed_rpm", "rpm", "where")
    fluctuation_cylinder: int = quantity("largest_timing_fluctuation_cylinder", label="at which cylinder's lobes")
    drive_force: float = quantity("largest_drive_force_N", "N", "the largest force of the timing drive over the "
                                  "running range")
    drive_force_speed: float = quantity("largest_drive_force_speed_rpm", "rpm", "where")
    resonances: tuple[TorsionalResonance, ...] = quantity("resonances", label="the natural frequencies met by a "
                                                          "significant order inside the running range")
    table: str = quantity("table", label="the response at every speed of the range (CSV)")


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
    response: TorsionalResponse = quantity("torsional_response", label="the steady torsional response over the "
                                           "running range")


@dataclass(frozen=True, repr=False)
class CamshaftResults:
    """The camshaft chapter: the torque over a revolution, the twist of each station and the record (SI)."""

    psi: np.ndarray = field(repr=False)          # camshaft angles over a revolution [rad]
    torque: np.ndarray = field(repr=False)       # total drive torque [N m]
    twist: np.ndarray = field(repr=False)        # (L, n) lag of each station [rad]
    chain: np.ndarray = field(repr=False)        # (L,) the torsional chain's spring rates from the crankshaft [N m/rad]
    masses: np.ndarray = field(repr=False)       # (L,) its inertias: the sprocket (a compliant drive), the stations
    speeds: np.ndarray = field(repr=False)       # (G,) engine speeds of the torsional response [rad/s]
    fluctuation: np.ndarray = field(repr=False)  # (G, C) fluctuation of each station's lag there [rad]
    drive_forces: np.ndarray = field(repr=False)   # (G,) largest force of the timing drive there [N]
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
    (:func:`valvetrain.design.drive_strength.event_load_maps`: the dynamics' simulated force where it ran), the friction torque
    from :func:`valvetrain.design.lubrication.contact_map` under the cam's normal force
    (:func:`valvetrain.design.drive_strength.contact_loads`) where the valve has a lubrication section.  For a finger the law
    is the valve's and P_T the force at the valve: P_T dv/dtheta is the torque of the cam's normal force N =
    P_T G / (L_r cos beta) about the cam centre (the virtual work of the linkage; Norton (2009)).  The train's inertia
    reduced to the camshaft J = (1/2 pi) int m_t(theta) h'^2 dtheta (its kinetic energy m_t (omega h')^2 / 2 averaged
    over the revolution), m_t with a finger's J / G(psi)^2 at each angle
    (:func:`valvetrain.layouts.finger_mass_change`).
    """
    cam, drive = design.cam, design.drive
    maps = event_load_maps(valve, engine, cam, drive, design.dynamics)[1]
    torques = [map_torque(valve, cam, design.lubrication is not None, m, engine.rated_speed) for m in maps]
    j = min(range(len(maps)), key=lambda i: float(np.min(np.abs(maps[i].speeds - engine.rated_speed))))
    m = maps[j]
    row = int(np.argmin(np.abs(m.speeds - engine.rated_speed)))
    theta, torque = m.theta, torques[j][row]
    dh = cam.law.derivatives(theta)[1]
    load = m.kind + (", with friction" if design.lubrication is not None else "")
    inertia = (drive.masses.at_tappet * float(np.trapezoid(dh**2, theta))
               + float(np.trapezoid(finger_mass_change(valve, cam.law, theta) * dh**2, theta))) / (2.0 * np.pi)
    lobe = shaft.wrap(2.0 * np.pi * np.arange(ANGLES) / ANGLES)
    speeds = np.concatenate([m.speeds for m in maps])
    phasors = np.concatenate([shaft.order_phasors(interp1d(m.theta, t, axis=1, bounds_error=False, fill_value=0.0)(
        lobe), ORDERS) for m, t in zip(maps, torques, strict=True)])
    order = np.argsort(speeds, kind="stable")
    return LobeSet(name, valve.count, theta, torque, shaft.lobe_noses(cam.nose, firing, engine.strokes),
                   drive.strength.cam_force_max, inertia, load, speeds[order], phasors[order])


def map_torque(valve, cam, friction, m, rated_speed) -> np.ndarray:
    """One lobe's drive torque at every speed of the load map ``m`` [N m], (S, n): P_T dh/dtheta, with the friction
    torque of :func:`valvetrain.design.lubrication.contact_map` where ``friction`` (the valve has a lubrication
    section) under the cam's normal force (:func:`valvetrain.design.drive_strength.contact_loads`); ``rated_speed`` [rad/s]
    turns the map's engine speeds into camshaft speeds (``cam.cam_speed`` at it)."""
    if friction:
        normal = contact_loads(cam, [m])[0].force
        omega = (m.speeds * cam.cam_speed / rated_speed)[:, None]
        return contact_map(valve.lubrication, cam, valve.parts.cam_width, valve.parts.contact_modulus, m.theta,
                           normal, omega)["drive_torque"]
    return np.where(m.force > 0.0, m.force, 0.0) * cam.law.derivatives(m.theta)[1]


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
    chain, masses = shaft.with_drive_end(shaft.station_stiffness(compliance), inertia, drive_k, sprocket)
    omega_n, shapes = shaft.torsional_modes(chain, masses)
    top = max(significant)
    ratio_n = float(omega_n[0] / (top * cam_speed * engine.over_speed_ratio))
    section = shaft.section_at(x, lengths)
    force = sum(s.count * s.force_max for s in lobes) * np.ones_like(x)
    bend = shaft.lobe_deflection(force, x, np.asarray(c.journal_positions), diameters[section], bores[section],
                                 c.modulus)
    drive_force = shaft.drive_force(np.array([figures["peak"], figures["mean"]]), c.drive_pitch_radius)
    twist_max = float(np.max(np.abs(lag)))
    j = first_largest(total)    # of the equal peaks of a camshaft's lobes, the first
    speeds = response_speeds(lobes, omega_n[:MODES], significant, ratio, engine.over_speed_ratio * engine.rated_speed)
    lags = torsional_response(omega_n, shapes, c.torsional_damping_ratio,
                              station_phasors(lobes, speeds), ratio * speeds)
    fluctuation = np.ptp(lags[:, -len(cylinders):, :], axis=-1)
    drive_forces = np.max(chain[0] * lags[:, 0, :], axis=-1) / c.drive_pitch_radius
    response = response_record(c, speeds, fluctuation, drive_forces, omega_n[:MODES], significant, ratio, cylinders)
    record_ = CamshaftRecord(
        tuple(names), tuple(cylinders), lobe_count * len(cylinders), ratio, tuple(f"{s.valve}: {s.load}" for s in lobes),
        figures["peak"], float(psi[j]), figures["lowest"], figures["mean"], figures["fluctuation"],
        figures["rms_fluctuation"], figures["mean"] * cam_speed, tuple(float(a) for a in amplitudes), significant,
        tuple(float(w) / (2.0 * np.pi) for w in omega_n[:MODES]), ratio_n,
        tuple(float(n) for n in shaft.resonance_speeds(omega_n[0], significant, ratio)), tuple(float(p) for p in x),
        tuple(float(i) for i in inertia), tuple(float(t) for t in np.max(np.abs(lag), axis=1)), twist_max,
        twist_max / ratio, tuple(float(f) for f in bend), float(bend.max()), c.drive, float(drive_force[0]),
        float(drive_force[1]), c.drive_allowable_force_N, float(np.max(np.abs(total)) / drive_k), float(sprocket),
        response)
    return CamshaftResults(psi, total, lag, chain, masses, speeds, fluctuation, drive_forces, record_,
                           tuple(camshaft_checks(record_, c, engine)))


def response_speeds(lobes, omega_n, orders, ratio, top) -> np.ndarray:
    """The engine speeds of the torsional response [rad/s]: :data:`RESPONSE_SPEEDS` evenly over the running range
    where every lobe's torque is known (from the highest of the lobes' lowest speeds to ``top``, the over-speed), and
    the speeds in it where an order of ``orders`` meets a natural frequency of ``omega_n`` [rad/s]
    (:func:`valvetrain.camshaft.resonance_speeds`, ``ratio`` camshaft revolutions per crank revolution)."""
    low, high = max(s.speeds[0] for s in lobes), min(min(s.speeds[-1] for s in lobes), top)
    met = np.concatenate([shaft.resonance_speeds(w, np.asarray(orders), ratio) for w in omega_n])
    return np.unique(np.concatenate([np.linspace(low, high, RESPONSE_SPEEDS), met[(met >= low) & (met <= high)]]))


def station_phasors(lobes, speeds) -> np.ndarray:
    """The orders of each station's torque at the engine speeds ``speeds`` [rad/s] [N m, complex], (G, ORDERS + 1,
    C): the sum over the valves of count x one lobe's orders, interpolated linearly between the speeds its torque is
    known at, each turned to its nose's camshaft angle psi_c, c_k exp(-i k psi_c) (T(psi - psi_c))."""
    k = np.arange(ORDERS + 1)
    return sum(s.count * interp1d(s.speeds, s.phasors, axis=0)(speeds)[:, :, None]
               * np.exp(-1j * k[None, :, None] * s.noses[None, None, :]) for s in lobes)


def torsional_response(omega_n, shapes, damping_ratio, stations, cam_speeds) -> np.ndarray:
    """The lag of every mass of the torsional chain behind the crankshaft over a camshaft revolution [rad], (G, L,
    SERIES_ANGLES): the steady response to each order of the stations' torque ``stations`` (G, K, C) at the camshaft
    speeds ``cam_speeds`` (G,) [rad/s] by :func:`valvetrain.camshaft.forced_response` (the stations the last C masses
    of the chain, the sprocket unloaded), summed over the orders (:func:`valvetrain.camshaft.order_series`) at
    camshaft angles 2 pi j / SERIES_ANGLES from cylinder 1's gas-exchange TDC."""
    g, k, c = stations.shape
    torques = np.zeros((g, k, shapes.shape[0]), dtype=complex)
    torques[:, :, -c:] = stations
    phi = shaft.forced_response(omega_n, shapes, damping_ratio, torques, np.arange(k)[None, :] * cam_speeds[:, None])
    return shaft.order_series(np.swapaxes(phi, 1, 2), SERIES_ANGLES)


def response_record(c, speeds, fluctuation, drive_forces, omega_n, orders, ratio, cylinders) -> TorsionalResponse:
    """The :class:`TorsionalResponse` of the fluctuation of each station's lag (G, C) [rad] and the largest drive
    force (G,) [N] at the engine speeds ``speeds`` [rad/s], with the resonances: each order of ``orders`` meeting a
    natural frequency of ``omega_n`` [rad/s] inside them (``ratio`` camshaft revolutions per crank revolution)."""
    found = []
    for mode, w in enumerate(omega_n, start=1):
        for k in orders:
            n = float(shaft.resonance_speeds(w, np.array([k]), ratio)[0])
            i = int(np.argmin(np.abs(speeds - n)))
            if abs(speeds[i] - n) <= 1e-9 * n:
                found.append(TorsionalResonance(mode, float(w / (2.0 * np.pi)), int(k), n,
                                                float(fluctuation[i].max()), float(drive_forces[i])))
    i, station = np.unravel_index(int(np.argmax(fluctuation)), fluctuation.shape)
    j = int(np.argmax(drive_forces))
    return TorsionalResponse(c.torsional_damping_ratio, (float(speeds[0]), float(speeds[-1])),
                             c.max_timing_play / c.drive_pitch_radius, float(fluctuation[i, station]), float(speeds[i]),
                             int(cylinders[station]), float(drive_forces[j]), float(speeds[j]),
                             tuple(sorted(found, key=lambda r: -r.fluctuation)), TORSION_TABLE)


TWIST_FAILURE = np.radians(10.0)
"""A camshaft twist beyond which its check is a failure, not a warning [rad, camshaft]: 10 cam deg (20 crank deg), the
largest ``max_twist_cam_deg`` allows, an engineering limit: valve events that far from their timing are no longer
the engine's (and a shaft that twists so far elastically is far past its yield)."""


def camshaft_checks(r, c, engine) -> list[Check]:
    """The camshaft's checks: the timing error of the twist, the torsional resonance margin, the bending deflection
    at the lobes and the timing drive's load, at the rated speed; the torsional response over the running range.

    Notes
    -----
    The limits of the quasi-static twist (``max_twist_cam_deg``) and of the frequency ratio (``min_frequency_ratio``)
    are engineering assumptions, keys with bounded defaults: no published camshaft limit was found; a twist beyond
    :data:`TWIST_FAILURE` is a failure. The frequency ratio is information: a resonance inside the running range is
    graded by its response, the fluctuation of each lobe's timing (against the movement of the cam sprocket against
    the crankshaft a maker accepts in service, ``max_timing_play_mm`` along the pitch circle: 3.175 mm, Chrysler
    (2002)) and the largest force of the timing drive, each a failure above its allowable. The allowable of the
    timing drive is the maker's (``drive_allowable_force_N``); for a roller chain the working load is commonly at
    most 1/6 of its tensile strength (Diamond Chain (n.d.)).
    """
    over = to_display(engine.over_speed_ratio * engine.rated_speed, "rpm")
    held = "camshaft.twist_held" if c.drive_stiffness is None else "camshaft.twist_through_drive"
    t = r.response
    allowable = note(DRIVE_ALLOWABLES[c.drive], more=f"; {cite('diamondchain')}" if c.drive == "chain" else "")
    return [
        check("camshaft.twist_timing_error", r.twist_max, high=c.max_twist, unit="cam deg",
              severity="failure" if r.twist_max > TWIST_FAILURE else "warning",
              source=cited(note("source.torsion", work=cite("shigley2011", "chapter 3")),
                           note("source.twist_assumption", limit_cam_deg=np.degrees(TWIST_FAILURE))),
              note=note(held, twist_crank_deg=to_display(r.twist_crank, 'crank deg'))),
        check("camshaft.torsional_resonance", r.frequency_ratio, low=c.min_frequency_ratio, severity="info",
              source=cited(cite("denhartog1956"), note("source.assumption", key="camshaft.min_frequency_ratio")),
              note=note("camshaft.first_resonance", frequency_Hz=r.natural_frequencies[0],
                        order=max(r.significant_orders), speed_rpm=over)),
        check("camshaft.bending_deflection", r.deflection_max, high=c.max_deflection, unit="mm", severity="failure",
              source=cited(note("source.usual_deflection", work=cite("vt_works", "eq. (7.3)")),
                           cite("shigley2011", "table A-9")),
              note=note("camshaft.lobe_span")),
        check("camshaft.timing_drive_force", r.drive_force, high=c.drive_allowable_force_N, unit="N",
              severity="failure", source=cited(allowable),
              note=note("camshaft.peak_torque", torque_Nm=r.peak, radius_mm=to_display(c.drive_pitch_radius, 'mm'))),
        check("camshaft.dynamic_timing_error", t.fluctuation, high=t.allowable, unit="cam deg", severity="failure",
              source=cited(note("source.timing_play", work=cite("chrysler2002"), play_mm=to_display(c.max_timing_play, "mm"),
                                radius_mm=to_display(c.drive_pitch_radius, "mm")), cite("denhartog1956")),
              note=note("camshaft.lag", cylinder=t.fluctuation_cylinder,
                        speed_rpm=to_display(t.fluctuation_speed, "rpm"), low_rpm=to_display(t.speed_range[0], "rpm"), high_rpm=to_display(t.speed_range[1], "rpm"),
                        damping=t.damping_ratio) + resonance_note(t)),
        check("camshaft.dynamic_drive_force", t.drive_force, high=c.drive_allowable_force_N, unit="N",
              severity="failure", source=cited(allowable, cite("denhartog1956")),
              note=note("camshaft.steady_drive_force", speed_rpm=to_display(t.drive_force_speed, 'rpm'),
                        damping=t.damping_ratio)),
    ]


def resonance_note(t) -> tuple:
    """The resonances of the running range with their figures, the largest timing fluctuations first (at most
    :data:`LISTED_RESONANCES`), or that there is none."""
    if not t.resonances:
        return note("camshaft.no_resonance")
    listed = sum((note("camshaft.resonance" if k else "camshaft.first_resonance_met", order=r.order, mode=r.mode,
                       frequency_Hz=r.frequency, speed_rpm=to_display(r.speed, "rpm"),
                       cam_deg=to_display(r.fluctuation, "cam deg"), force_N=r.drive_force)
                  for k, r in enumerate(t.resonances[:LISTED_RESONANCES])), ())
    more = len(t.resonances) - LISTED_RESONANCES
    return listed + (note("camshaft.more_resonances", count=more) if more > 0 else ())
