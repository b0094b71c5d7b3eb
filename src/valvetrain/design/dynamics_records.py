"""The records of a valve's dynamics stage (:mod:`valvetrain.design.dynamics`): the train simulated, each speed's
events, the rated speed's, the resonance, the natural modes, the accuracy of the headlines, the stage's result, and
the per-speed table of ``tables/NAME_dynamics.csv``.

Speeds in the records are engine (crank) speeds; the camshaft of a four-stroke turns at half.
"""

from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from ..dynamics.accuracy import MAX_HALVINGS, Refinement
from ..dynamics.events import largest_lift_errors
from ..dynamics.sweep import SpeedResult, SweepResult
from ..units import rpm_to_rad_s
from .results import quantity, shown

@dataclass(frozen=True)
class DynamicsParameters:
    """The train that was simulated, every value at the valve (SI), and how each was obtained."""

    model: str = quantity("model", label="1dof: one mass; multi: drive masses and coil masses")
    drive_layout: str = quantity("layout", label="drive layout")
    mass: float = quantity("mass_kg", "kg", "M, the train's mass reduced to the valve")
    drive_stiffness: float = quantity("drive_stiffness_N_per_mm", "N/mm", "c, drive stiffness from cam to valve, at "
                                      "the valve (the links in series)")
    damping_ratio: float = quantity("damping_ratio", label="zeta of the drive, C = 2 zeta sqrt(c M)")
    spring_rate: float = quantity("spring_rate_N_per_mm", "N/mm", "K, valve spring(s) rate")
    preload: float = quantity("spring_preload_N", "N", "F0, installed spring force")
    rocker_ratio: float = quantity("rocker_ratio", label="k, valve arm / tappet arm")
    lash: float = quantity("lash_mm", "mm", "valve clearance at the valve, k h0")
    seat_stiffness: float = quantity("seat_stiffness_N_per_mm", "N/mm", "c_s, valve seat contact")
    seat_damping_ratio: float = quantity("seat_damping_ratio", label="zeta_s of the seat, C_s = 2 zeta_s sqrt(c_s M)")
    revolutions: int = quantity("revolutions", label="most camshaft revolutions per speed (a speed stops once its "
                                "motion repeats), the last one recorded")
    step: float = quantity("step_cam_deg", "cam deg", "recording and base integration step")
    coils_per_spring: int = quantity("coils_per_spring", label="coil masses per spring (multi)")
    links: tuple[float, ...] = quantity("link_stiffnesses_N_per_mm", "N/mm", "drive links from the cam to the valve, "
                                        "at the valve")
    link_names: tuple[str, ...] = quantity("link_names", label="what each link is")
    node_masses: Optional[dict[str, float]] = quantity("node_masses_kg", "kg", "multi: masses of the nodes at the valve",
                                           omit_none=True)
    estimates: tuple[str, ...] = quantity("estimates", label="how each value the specification does not give was "
                                          "obtained")


@dataclass(frozen=True)
class SpeedRecord:
    """The train at one engine speed (SI)."""

    speed: float = quantity("speed_rpm", "rpm", "engine speed")
    epsilon: float = quantity("epsilon", label="perturbation parameter M omega_cam^2 / (c + K)")
    min_contact_force: float = quantity("min_contact_force_N", "N", "smallest cam contact force while the cam lifts "
                                        "the open valve, before it seats (at the cam; 0: separation; null: the valve "
                                        "never leaves its seat)")
    max_contact_force: float = quantity("max_contact_force_N", "N", "largest cam contact force (at the cam)")
    seating_velocity: float = quantity("seating_velocity_m_s", "m/s", "valve velocity at the first seating "
                                       "(negative: closing; null: no seating)")
    bounce: float = quantity("bounce_mm", "mm", "largest valve lift after the first seating")
    bounce_count: int = quantity("bounce_count", label="returns above 1 um after the first seating")
    max_lift_error: float = quantity("max_lift_error_mm", "mm", "largest |valve lift - rigid lift|")
    jump_intervals: tuple[tuple[float, ...], ...] = quantity("jump_intervals_cam_deg", "cam deg",
                                                              "follower separation, from and to (from the nose)")
    max_surge: Optional[float] = quantity("max_surge_mm", "mm", "multi: largest coil deviation from its share of "
                                          "the valve motion", omit_none=True)
    clash_margin: Optional[float] = quantity("coil_clash_margin_mm", "mm", "multi: smallest gap between coils "
                                             "(negative: clash)", omit_none=True)
    revolutions: int = quantity("revolutions", label="camshaft revolutions integrated until the motion repeated "
                                "(the cap where it did not)", default=1)
    max_contact_stress: Optional[float] = quantity("max_contact_stress_MPa", "MPa", "rated speed: largest Hertz "
                                                   "stress of the cam contact under the simulated force (needs "
                                                   "parts.cam_width_mm)", default=None, omit_none=True)
    max_contact_stress_angle: Optional[float] = quantity("max_contact_stress_angle_cam_deg", "cam deg", "where it "
                                                         "occurs, from the nose", default=None, omit_none=True)
    lubrication_gamma_nose: Optional[float] = quantity("lubrication_gamma_nose", label="rated speed, flat follower: "
                                                       "gamma = rho / (R0 + h) at the nose (0.15-0.25 recommended)",
                                                       default=None, omit_none=True)
    lubrication_gamma_at_max_stress: Optional[float] = quantity("lubrication_gamma_at_max_stress", label="gamma "
                                                                "where the dynamic stress is largest", default=None, omit_none=True)
    lubrication_near_half: Optional[float] = quantity("lubrication_poor_film_cam_deg", "cam deg", "cam angle over "
                                                      "which the loaded contact has 0.4 <= gamma <= 0.6 (poor film "
                                                      "near gamma = 0.5; keep it short)", default=None, omit_none=True)
    max_drive_torque: Optional[float] = quantity("max_drive_torque_N_m", "N m", "rated speed: largest camshaft "
                                                 "drive torque of this cam, F dh/dtheta", default=None, omit_none=True)
    min_drive_torque: Optional[float] = quantity("min_drive_torque_N_m", "N m", "smallest (negative: the closing "
                                                 "flank drives the camshaft)", default=None, omit_none=True)
    mean_drive_torque: Optional[float] = quantity("mean_drive_torque_N_m", "N m", "mean over the revolution (the "
                                                  "damping losses)", default=None, omit_none=True)


def _like(name):
    """A field of :class:`SpeedRecord`'s key, unit and label."""
    return field(metadata=SpeedRecord.__dataclass_fields__[name].metadata)


@dataclass(frozen=True)
class SpeedRecords:
    """Every speed of the sweep at once: the fields of :class:`SpeedRecord`, arrays (S,) (SI), as the CSV table
    shows them; a speed without a separation has nan where the first separation starts and the last one ends, and a
    spring whose closing is not monitored a nan clash margin."""

    speed: np.ndarray = _like("speed")
    epsilon: np.ndarray = _like("epsilon")
    min_contact_force: np.ndarray = _like("min_contact_force")
    max_contact_force: np.ndarray = _like("max_contact_force")
    seating_velocity: np.ndarray = _like("seating_velocity")
    bounce: np.ndarray = _like("bounce")
    bounce_count: np.ndarray = _like("bounce_count")
    jump: np.ndarray = quantity("jump", label="follower separation")
    jump_from: np.ndarray = quantity("jump_from_cam_deg", "cam deg", "first separation starts (from the nose)")
    jump_to: np.ndarray = quantity("jump_to_cam_deg", "cam deg", "last separation ends (from the nose)")
    max_lift_error: np.ndarray = _like("max_lift_error")
    max_surge: Optional[np.ndarray] = _like("max_surge")      # None: no coil masses
    clash_margin: np.ndarray = _like("clash_margin")
    revolutions: np.ndarray = _like("revolutions")


def speed_records(result, speeds, epsilon, events=None) -> SpeedRecords:
    """The :class:`SpeedRecords` of a :class:`~valvetrain.dynamics.sweep.SweepResult` at engine speeds [rad/s] (S,)
    with the perturbation parameters (S,): :func:`speed_record` of every speed, over the speeds at once; its events
    ``events`` (:class:`~valvetrain.dynamics.events.SweepEvents`, those refined at the speeds that decide the headlines,
    :class:`~valvetrain.dynamics.accuracy.Refinement`), else the sweep's own."""
    events = result.events if events is None else events
    surge = result.surge_amplitude.max(axis=1) if result.surge_amplitude.shape[1] else None
    return SpeedRecords(np.asarray(speeds, dtype=float), np.asarray(epsilon, dtype=float), events.min_contact_force,
                        result.contact_force.max(axis=1), events.seating_velocity, events.bounce_height,
                        events.bounce_count, events.jumped, events.jump_from, events.jump_to,
                        largest_lift_errors(result.lift, result.kinematic_lift), surge,
                        np.where(np.isfinite(result.clash_margin), result.clash_margin, np.nan), result.revolutions)


@dataclass(frozen=True)
class ResonanceRecord:
    """Resonant harmonic of the cam excitation at the rated speed and the distortion of the valve motion."""

    natural_frequency: float = quantity("natural_frequency_Hz", "Hz", "f0 = sqrt((K + c)/M) / 2 pi")
    order: int = quantity("harmonic_k", label="k = int(omega0 / omega_cam), the resonant harmonic")
    force: float = quantity("harmonic_force_N", "N", "amplitude of harmonic k of c k h")
    amplitude: float = quantity("amplitude_mm", "mm", "elastic amplitude Delta = F / (xi omega0)")
    distortion: float = quantity("distortion_percent", label="delta = Delta / (sqrt 2 h_rms), %")
    orders: tuple[int, ...] = quantity("spectrum_k", label="harmonics k - 2 ... k + 2")
    spectrum: tuple[float, ...] = quantity("spectrum_distortion_percent", label="delta at those harmonics, % (one "
                                           "harmonic alone is fragile: a piecewise profile can have exact zeros)")


@dataclass(frozen=True)
class PerSpeed:
    """One entry per speed of the sweep (SI), as in the CSV table."""

    speed: tuple[float, ...] = quantity("speed_rpm", "rpm", "engine speed")
    min_contact_force: tuple[float, ...] = quantity("min_contact_force_N", "N", "smallest cam contact force")
    seating_velocity: tuple[Optional[float], ...] = quantity("seating_velocity_m_s", "m/s",
                                                             "valve velocity at seating (null: no seating)")
    bounce: tuple[float, ...] = quantity("bounce_mm", "mm", "bounce height")
    bounce_count: tuple[int, ...] = quantity("bounce_count", label="bounces")
    jump: tuple[bool, ...] = quantity("jump", label="follower separation")
    max_lift_error: tuple[float, ...] = quantity("max_lift_error_mm", "mm", "largest |valve lift - rigid lift|")
    revolutions: tuple[int, ...] = quantity("revolutions", label="camshaft revolutions until the motion repeated")


@dataclass(frozen=True)
class Mode:
    """One natural mode of the train with every contact closed (undamped)."""

    frequency: float = quantity("frequency_Hz", "Hz", "natural frequency")
    shape: dict[str, float] = quantity("shape", label="displacement of each node at the valve, the largest 1 (sign: same or "
                           "opposite direction)")


@dataclass(frozen=True)
class AccuracyRecord:
    """Estimated discretisation errors of the headline numbers: the speeds that decide each simulated again at halved
    steps until it settles (:func:`~valvetrain.dynamics.accuracy.refine`)."""

    jump_speed: float = quantity("jump_speed_rpm", "rpm", "of the jump speed, its two parts together (null: no "
                                 "separation, or not estimated: the refinement's work limit reached first)")
    jump_speed_step: float = quantity("jump_speed_step_rpm", "rpm", "time step: the jump speed's change at the last "
                                      "halving of the step (null as jump_speed_rpm)")
    jump_speed_grid: float = quantity("jump_speed_grid_rpm", "rpm", "speed grid: its change by a speed simulated where "
                                      "it is interpolated between the speeds swept (null as jump_speed_rpm)")
    bounce_speed: float = quantity("bounce_speed_rpm", "rpm", "of the bounce onset speed, its two parts together "
                                   "(null: no bounce, or not estimated: the refinement's work limit reached first)")
    bounce_speed_step: float = quantity("bounce_speed_step_rpm", "rpm", "time step: its change at the last halving "
                                        "(null as bounce_speed_rpm)")
    bounce_speed_grid: float = quantity("bounce_speed_grid_rpm", "rpm", "speed grid: its change by a speed simulated "
                                        "where it is interpolated (null as bounce_speed_rpm)")
    max_seating_velocity: float = quantity("max_seating_velocity_m_s", "m/s", "of the largest |seating velocity|: its "
                                           "change at the last halving of the step (null: no seating, or not "
                                           "estimated: the refinement's work limit reached first)")
    rated_seating_velocity: float = quantity("rated_seating_velocity_m_s", "m/s", "of the seating velocity at the rated "
                                             "speed (null: the valve does not seat there, or not "
                                             "estimated: the refinement's work limit reached first)")
    rated_bounce: float = quantity("rated_bounce_mm", "mm", "of the bounce height at the rated speed (null: not "
                                   "estimated, the refinement's work limit reached first)")
    step: float = quantity("finest_step_cam_deg", "cam deg", "the finest step a headline was refined to (the sweep's "
                           "step halved at most " + str(MAX_HALVINGS) + " times)")


@dataclass(frozen=True)
class DynamicsResult:
    """The dynamics stage: the train, the headline numbers of the sweep, the rated speed and the resonance."""

    model: str = quantity("model", label="1dof or multi")
    parameters: DynamicsParameters = quantity("parameters")
    speed_range: tuple[float, ...] = quantity("speed_range_rpm", "rpm", "engine speeds swept, from and to")
    speeds: int = quantity("speeds", label="speeds swept")
    jump_speed: float = quantity("jump_speed_rpm", "rpm", "engine speed where the smallest contact force while the "
                                 "cam lifts reaches 0, interpolated between the speeds swept and checked by one "
                                 "simulated between, the speeds about it at a halved step until it settles (its "
                                 "estimated error: accuracy; null: no follower separation in the range)")
    bounce_speed: float = quantity("bounce_speed_rpm", "rpm", "engine speed where the bounce height first exceeds "
                                   "1 um, interpolated between the speeds swept and refined as the jump speed (null: "
                                   "none)")
    max_seating_velocity: float = quantity("max_seating_velocity_m_s", "m/s", "largest |seating velocity| of the "
                                           "sweep, the speeds near it at a halved step until it settles (null: the "
                                           "valve seats at no speed)")
    max_seating_velocity_speed: float = quantity("max_seating_velocity_speed_rpm", "rpm", "where it occurs (null: "
                                                 "the same)")
    coil_clash_speed: Optional[float] = quantity("coil_clash_speed_rpm", "rpm", "multi: lowest speed whose coils "
                                                 "meet (null: none)", omit_none=True)
    epsilon: float = quantity("epsilon", label="perturbation parameter at the rated speed")
    natural_frequency: float = quantity("natural_frequency_Hz", "Hz", "lowest natural frequency of the simulated "
                                        "train, the first of natural_frequencies_Hz (one mass: sqrt((K + c)/M) / 2 pi)")
    natural_frequencies: tuple[float, ...] = quantity("natural_frequencies_Hz", "Hz", "natural frequencies of the "
                                                      "simulated train with the valve off its seat (every other "
                                                      "contact closed), ascending")
    modes: tuple[Mode, ...] = quantity("modes", label="the natural modes: frequency and shape")
    max_revolutions: int = quantity("max_revolutions", label="most camshaft revolutions a speed took to repeat")
    unsettled_speeds: int = quantity("unsettled_speeds", label="speeds whose motion did not repeat within the "
                                     "revolutions key (the last revolution recorded)")
    unsettled_note: Optional[str] = quantity("unsettled_note", label="why those speeds did not repeat (null: every "
                                             "speed repeated)", omit_none=True)
    accuracy: AccuracyRecord = quantity("accuracy", label="estimated discretisation errors of the headline numbers "
                                        "and of the rated speed's seating")
    at_rated_speed: SpeedRecord = quantity("at_rated_speed")
    resonance: ResonanceRecord = quantity("resonance")
    per_speed: PerSpeed = quantity("per_speed", label="one entry per speed swept; the speeds that decide the headline "
                                   "numbers have the events of their finest step")
    sweep_table: str = quantity("sweep_table", label="CSV with one row per speed, relative to the output folder")
    sweep: Optional[SweepResult] = field(default=None, repr=False, compare=False)
    records: Optional[SpeedRecords] = field(default=None, repr=False, compare=False)    # every speed
    rated: Optional[SpeedResult] = field(default=None, repr=False, compare=False)      # at the rated speed
    refinement: Optional[Refinement] = field(default=None, repr=False, compare=False)  # the headlines refined


def finite_or_none(x) -> Optional[float]:
    """``x``, or None where it is not finite (a speed whose recorded revolution has no seating)."""
    return float(x) if np.isfinite(x) else None


def speed_record(r, speed, epsilon) -> SpeedRecord:
    """A :class:`SpeedRecord` of a :class:`~valvetrain.dynamics.sweep.SpeedResult` at engine speed [rad/s]."""
    surge = float(r.surge_amplitude.max()) if r.surge_amplitude.size else None
    clash = float(r.clash_margin) if np.isfinite(r.clash_margin) else None
    return SpeedRecord(float(speed), float(epsilon), float(r.min_contact_force), float(r.contact_force.max()),
                       float(r.seating_velocity), float(r.bounce_height), int(r.bounce_count),
                       float(largest_lift_errors(r.lift, r.kinematic_lift)[0]),
                       tuple(tuple(float(a) for a in pair) for pair in r.jump_intervals), surge, clash,
                       int(r.revolutions))


SWEEP_COLUMNS = [
    ("speed_rpm", "engine speed [rpm]"), ("camshaft_rpm", "camshaft speed [rpm]"),
    ("epsilon", "perturbation parameter M omega_cam^2 / (c + K)"),
    ("min_contact_force_N", "smallest cam contact force where the cam lifts the valve [N]"),
    ("max_contact_force_N", "largest cam contact force [N]"),
    ("seating_velocity_m_s", "valve velocity at the first seating [m/s]"),
    ("bounce_mm", "largest lift after the first seating [mm]"), ("bounce_count", "bounces"),
    ("jump", "follower separation: 1, else 0"), ("jump_from_cam_deg", "first separation starts [cam deg]"),
    ("jump_to_cam_deg", "last separation ends [cam deg]"), ("max_lift_error_mm", "largest |lift - rigid lift| [mm]"),
    ("revolutions", "camshaft revolutions until the motion repeated"),
]
"""Columns of ``tables/NAME_dynamics.csv`` (multi: also ``max_surge_mm`` with coil masses, and
``coil_clash_margin_mm`` where the spring's closing is monitored: a massless spring, coils_per_spring = 0, has no
surge but still goes solid)."""


def event_window(d, margin_deg: float = 10.0) -> np.ndarray:
    """Camshaft angles of the sweep around the event (where any speed or the rigid lift is off the seat)."""
    sw = d.sweep
    open_ = (sw.kinematic_lift > 0.0) | np.any(sw.lift > 1e-6, axis=0)
    idx = np.flatnonzero(open_)
    if idx.size == 0:
        return np.ones(sw.theta.size, dtype=bool)
    lo, hi = sw.theta[idx[0]] - np.radians(margin_deg), sw.theta[idx[-1]] + np.radians(margin_deg)
    return (sw.theta >= lo) & (sw.theta <= hi)


def sweep_columns(d) -> dict[str, list]:
    """The per-speed table of a :class:`DynamicsResult` as named columns (engineering units)."""
    records = d.records

    def column(name):
        """``(key, values)``: one field of the records as results.json shows it."""
        return shown(records, name)[0]

    to_cam = d.sweep.cam_speeds[0] / d.per_speed.speed[0]
    out = dict([column("speed"), ("camshaft_rpm", [s * to_cam / rpm_to_rad_s(1.0) for s in d.per_speed.speed])])
    out.update(column(name) for name in ("epsilon", "min_contact_force", "max_contact_force", "seating_velocity",
                                         "bounce", "bounce_count"))
    out["jump"] = [int(j) for j in records.jump.tolist()]
    out.update(column(name) for name in ("jump_from", "jump_to", "max_lift_error", "revolutions"))
    if d.model == "multi" and d.parameters.coils_per_spring > 0:
        out.update([column("max_surge")])
    if np.isfinite(records.clash_margin).any():
        out.update([column("clash_margin")])
    return out


__all__ = ["AccuracyRecord", "DynamicsParameters", "DynamicsResult", "Mode", "PerSpeed", "ResonanceRecord",
           "SWEEP_COLUMNS", "SpeedRecord", "SpeedRecords", "event_window", "finite_or_none", "speed_record",
           "speed_records", "sweep_columns"]
