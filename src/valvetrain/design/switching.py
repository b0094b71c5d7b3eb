"""Switching stage: a switching roller finger follower (``[valves.NAME.switching]``) on a finger-driven valve.

Latched, the valve is the finger's as the valve's own chapters design it (the same lift, springs and dynamics).
Unlatched (deactivation), the valve stays shut and the inner arm follows its cam against the lost-motion spring: the
spring is drawn from the arm's inertia at the over-speed, the torsion spring sized for it, its natural frequency
found, the arm's motion simulated by the dynamics' sweep as a one-mass train (its jump speed), the force it leaves at
the shut valve compared with the valve spring's preload; and the latch's load and contact stress in the latched mode
(:mod:`valvetrain.switching`).
"""

from dataclasses import dataclass
from typing import Optional

import numpy as np

from .. import switching as sw
from . import two_step as ts
from ..bibliography import cite
from ..checks import Check, check
from ..dynamics.sweep import sweep
from ..locale import NoteText, cited, note
from ..spring_materials import grade
from ..specification.messages import Problem, SpecError
from ..springs import DEFLECTION_RATIO_RANGE, enveloping_line
from ..strength import LIMITS, STEEL_MODULUS
from .dynamics import sweep_excess
from .results import quantity, record

SPEEDS_OVER = 2.0
"""The arm's sweep runs from a quarter of the over-speed to this many times it (camshaft speeds)."""

SWEEP_STEP_DEG = 0.5
"""The arm's sweep's angle step [cam deg]: the arm on its cam is a smooth, lightly loaded one-mass train."""

AIR = (287.0, 1.4)
"""R [J/(kg K)] and gamma of the deactivated cylinder's trapped charge: dry air's near room temperature, taken constant
over the cycle (an exhaust charge's gamma is lower: this package's choice, one gas for every trapped charge)."""

LATCH_LIMIT = LIMITS["rocker_pad_stress"][0]
"""The latch pin's allowable Hertz stress [Pa]: the rocker's hardened pad on the valve tip's, taken for the latch."""

LATCH_SOURCE = cited(note("source.latch_allowable", work=cite("vt_works", "eq. (7.13)")))

SPRING_SOURCE = cited(note("source.follower_dynamics", work=cite("norton2009")), cite("hendriksma2007"),
                      note("source.lost_motion_spring", low=DEFLECTION_RATIO_RANGE[0], high=DEFLECTION_RATIO_RANGE[1],
                           work=cite("vt_works", "work 5")))


@dataclass(frozen=True)
class TwoStepRecord:
    """A two-step finger's modes: the valve's events and time-area latched (the main lobe) and unlatched (the low
    lobe), the low lobe's profile, the valve's jump speed on it and, with [breathing], each mode's breathing."""

    latched_opens: float = quantity("valve_opens_latched_crank_deg", "crank deg", "latched: where the valve leaves "
                                    "its seat, from the gas-exchange TDC")
    latched_closes: float = quantity("valve_closes_latched_crank_deg", "crank deg", "latched: where it meets its "
                                     "seat")
    unlatched_opens: float = quantity("valve_opens_unlatched_crank_deg", "crank deg", "unlatched (the low lobe): "
                                      "where the valve leaves its seat")
    unlatched_closes: float = quantity("valve_closes_unlatched_crank_deg", "crank deg", "unlatched: where it meets "
                                       "its seat")
    time_area_latched: float = quantity("time_area_latched_mm2_s", "mm2 s", "latched: time-area over the whole "
                                        "opening at the rated speed, one valve")
    time_area_unlatched: float = quantity("time_area_unlatched_mm2_s", "mm2 s", "unlatched: the same of the low lobe")
    low_rho_min: float = quantity("low_lobe_rho_min_mm", "mm", "smallest radius of curvature of the low lobe's "
                                  "profile")
    valve_jump: float = quantity("valve_jump_speed_unlatched_rpm", "rpm", "engine speed at which the valve leaves "
                                 "the low lobe (rigid train; the lost-motion spring's load on the body subtracted)")
    breathing: Optional[tuple[ts.ModeBreath, ...]] = quantity(
        "breathing", label="with [breathing]: each mode's breathing at each condition", omit_none=True, default=None)


@dataclass(frozen=True)
class LatchSwitching:
    """The latch's switching: the window in which it may move (both arms on their base circles) and the pin's travel
    times under the oil and back on its spring."""

    window: float = quantity("switching_window_cam_deg", "cam deg", "the switching window: the camshaft's turn with "
                             "both arms on their base circles, 360 less the lobes' event")
    window_time: float = quantity("switching_window_ms", "ms", "that window's time at the rated speed")
    engage: float = quantity("latch_engage_time_ms", "ms", "the pin's travel under the oil against its spring")
    back: float = quantity("latch_return_time_ms", "ms", "its travel back on the spring, its oil drained through "
                           "the passage")
    share: float = quantity("latch_time_share", label="the longer travel over the window's time at the rated speed")


@dataclass(frozen=True)
class SwitchingRecord:
    """A valve's switching roller finger follower: the two modes, the lost-motion spring, the arm's dynamics and the
    latch."""

    mode: str = quantity("mode", label="the unlatched mode: deactivation (the valve stays shut) or two_step (the "
                         "valve follows the low lobe)")
    latched_lift: float = quantity("latched_valve_lift_mm", "mm", "valve lift latched (the finger's)")
    unlatched_lift: float = quantity("unlatched_valve_lift_mm", "mm", "valve lift unlatched: the low lobe's "
                                     "(two-step), or the finger's at its rest angle, where the body stays")
    arm_swing: float = quantity("arm_swing_deg", "deg", "the unlatched inner arm's largest turn in the body")
    over_speed: float = quantity("over_speed_rpm", "rpm", "engine speed the arm must follow its cam at")
    reserve: float = quantity("reserve", label="margin of the lost-motion spring over the arm's inertia torque")
    required_torque: float = quantity("required_torque_max_Nm", "N m", "largest torque the arm needs at the "
                                      "over-speed, margin included")
    preload: float = quantity("spring_preload_Nm", "N m", "lost-motion spring's torque with the arm at rest, T_0")
    rate: float = quantity("spring_rate_Nm_per_rad", "N m/rad", "its torsional rate about the arm's pivot, k")
    max_torque: float = quantity("spring_torque_max_Nm", "N m", "its torque at the arm's full swing")
    coils: float = quantity("spring_active_coils", label="active coils of the torsion spring, E d^4 / (64 D k)")
    stress: float = quantity("spring_stress_max_MPa", "MPa", "largest bending stress of its wire, K_b 32 T / (pi d^3)")
    stress_share: float = quantity("spring_stress_share", label="that stress over the wire's tensile strength R_m")
    frequency: float = quantity("arm_frequency_Hz", "Hz", "natural frequency of the arm on its spring, off the cam")
    frequency_orders: float = quantity("arm_frequency_orders", label="that frequency over the camshaft's at the "
                                       "over-speed")
    jump_speed: Optional[float] = quantity("jump_speed_rpm", "rpm", "engine speed at which the unlatched arm leaves "
                                           "its cam (the dynamic sweep; none up to its top speed or without a sweep: "
                                           "two-step)", omit_none=True)
    jump_speed_static: float = quantity("jump_speed_quasi_static_rpm", "rpm", "the same of a rigid arm, "
                                        "min sqrt((T_0 + k phi) / (J (-phi'')))")
    sweep_top: Optional[float] = quantity("sweep_top_rpm", "rpm", "highest engine speed of the arm's sweep (none "
                                          "two-step: no sweep)", omit_none=True)
    arm_force: float = quantity("arm_contact_force_max_N", "N", "largest force of the unlatched arm on its cam at the "
                                "over-speed (the sweep's; two-step the rigid arm's)")
    valve_force: float = quantity("valve_force_unlatched_N", "N", "the force that leaves at the shut valve, "
                                  "N L_r / G_0")
    valve_preload: float = quantity("valve_spring_preload_N", "N", "the valve spring's preload that holds it shut")
    cam_force: float = quantity("cam_force_max_N", "N", "largest cam force latched (the strength chapter's)")
    latch_force: float = quantity("latch_force_max_N", "N", "the latch's load, N L_i / L_l")
    latch_stress: float = quantity("latch_stress_max_MPa", "MPa", "Hertz stress of the latch pin on its seat")
    air_work: Optional[float] = quantity("deactivated_work_J", "J", "the deactivated cylinder's trapped charge: its "
                                         "work on the piston per cycle at the rated speed (negative: a loss)",
                                         omit_none=True, default=None)
    air_loss: Optional[float] = quantity("deactivated_loss_kPa", "kPa", "that loss per cycle over the swept volume, "
                                         "a mean effective pressure", omit_none=True, default=None)
    air_peak: Optional[float] = quantity("deactivated_peak_pressure_kPa", "kPa", "the trapped charge's peak "
                                         "pressure", omit_none=True, default=None)
    air_revolutions: Optional[int] = quantity("deactivated_revolutions", label="revolutions integrated to the "
                                              "repeating one", omit_none=True, default=None)
    speeds: tuple[float, ...] = quantity("sweep_speeds_rpm", "rpm", "engine speeds of the arm's sweep", default=())
    min_force: tuple[float, ...] = quantity("arm_contact_force_min_N", "N", "the arm's smallest force on its cam while "
                                            "the cam lifts it, at each speed (0: it has left the cam)", default=())
    spring_source: str = quantity("spring_source", label="where the lost-motion spring's requirement comes from",
                                  default=SPRING_SOURCE)
    two_step: Optional[TwoStepRecord] = quantity("two_step", label="two-step: both modes' events, time-area and "
                                                 "breathing", omit_none=True, default=None)
    latch: Optional[LatchSwitching] = quantity("latch_switching", label="with the latch's oil and spring: its "
                                               "switching window and travel times", omit_none=True, default=None)


@dataclass(frozen=True)
class SwitchingResult:
    """The switching chapter of a valve: the record and the checks."""

    figures: SwitchingRecord
    checks: tuple[Check, ...] = ()

    @property
    def summary(self) -> dict:
        """The switching record of results.json."""
        return record(self.figures)


def switching_stage(name, switching, valve, engine, design, output=None, breathing=None, b=None) -> SwitchingResult:
    """The switching chapter of the valve ``name``.

    Parameters
    ----------
    name : str
    switching, valve, engine : SI views of [valves.NAME.switching], the valve and [engine].
    design : ValveDesign
        The valve, designed latched (its finger, law, valve spring and strength).
    output : SI view of [output]
        The low lobe's profile (two-step).
    breathing : BreathingResults, optional
        The breathing chapter: with it (and ``b``, the SI view of [breathing]) a two-step intake's breathing in each
        mode.

    Raises
    ------
    SpecError
        An arm's sweep larger than the dynamics chapter allows (:data:`~valvetrain.design.dynamics.MAX_SWEEP_WORK`,
        :data:`~valvetrain.design.dynamics.MAX_SWEEP_BYTES`), naming ``contact_stiffness_N_per_mm``; a low lobe that
        cannot be made or rises above the main one (:mod:`valvetrain.design.two_step`).

    Notes
    -----
    Over-speed omega_os = omega_cam(rated) x ``engine.over_speed_ratio``.  The arm turns in the body by
    phi = (u - u_b) / L_i with u the roller centre's travel on the main lobe and u_b the body's (0 deactivated, on
    the low lobe two-step; :func:`valvetrain.switching.roller_travel`); the spring's line T_0 + k phi is the tightest
    above K J omega_os^2 max(0, -u'' / L_i) (:func:`valvetrain.springs.enveloping_line`), the arm's inertia lumped at
    its roller (m = J / L_i^2) whose acceleration is the main lobe's whatever the body does.  Deactivated, the
    dynamic sweep is the arm as a one-mass train at its roller (:func:`valvetrain.switching.arm_train`) on the travel
    u(theta), from a quarter of the over-speed to :data:`SPEEDS_OVER` times it; its jump speed is the sweep's
    (:meth:`~valvetrain.dynamics.sweep.SweepResult.headline`).  Two-step, the spring's seat moves with the body,
    which the sweep's one-mass train (its spring on the ground) does not model: the arm's jump speed is the rigid
    arm's, and the valve's on the low lobe is the rigid train's with the lost-motion spring's load on the body
    subtracted from the valve spring's force.
    """
    cam, follower, law = design.cam, design.follower_model, design.law
    heel = cam.heel_radius
    reserve = switching.reserve if switching.reserve is not None else valve.drive.spring_reserve
    omega = cam.cam_speed * engine.over_speed_ratio
    two_step = switching.mode == "two_step"
    lobe = ts.low_lobe(name, switching.low_lobe, valve, engine, output, cam) if two_step else None
    theta = (ts.lobe_grid(cam, lobe) if two_step else
             np.unique(np.concatenate([np.linspace(law.start, law.end, 2001), law.breakpoints])))
    u, _, d2u = sw.roller_travel(follower, heel, *law.derivatives(theta)[:3])
    body = np.zeros_like(u)
    if two_step:
        low = lobe.derivatives(theta)
        body = sw.roller_travel(follower, heel, *low[:3])[0]
        ts.below_main(name, theta, u, body)
    inner, inertia = switching.inner_arm, switching.inner_arm_inertia
    phi = (u - body) / inner
    required = sw.required_torque(inertia, d2u / inner, omega, reserve)
    preload, rate = enveloping_line(phi, required)
    swing = float(phi.max())
    top = preload + rate * swing
    wire, mean = switching.spring_wire_diameter, switching.spring_mean_diameter
    stress = float(sw.torsion_stress(top, wire, mean))
    strength = float(grade(switching.spring_material).tensile_strength(wire))
    frequency = sw.arm_frequency(rate, inertia)
    train = sw.arm_train(inertia, inner, rate, preload, switching.contact_stiffness)
    static = sw.quasi_static_jump_speed(train.mass, train.preload, train.spring_rate, u - body, d2u)
    rest = np.array(follower.base_angle(heel))      # unlatched, the body stays where the heel circle holds it
    rest_arm = float(follower.valve_arm(rest))
    valve_preload = design.drive.spring.preload
    crank = engine.strokes / 2.0     # the engine's speed over the camshaft's
    if two_step:
        jump, speeds, min_force = static, None, ()
        arm_force = float(np.max(train.preload + train.spring_rate * (u - body) + train.mass * omega ** 2 * d2u))
        unlatched = lobe.flow.valve_lift
        psi = follower.angle_derivatives(heel, *low[:3])[0]
        load = sw.valve_force_of_arm(train.preload + train.spring_rate * (u - body), follower.roller_arm,
                                     follower.valve_arm(psi))
        spring = design.drive.spring
        valve_jump = sw.quasi_static_jump_speed(design.drive.masses.at_valve, spring.preload - load, spring.rate,
                                                low[0], low[2])
        modes = _modes(name, design, valve, lobe, breathing, b, crank * valve_jump)
    else:
        speeds = omega * np.unique(np.concatenate([np.linspace(0.25, SPEEDS_OVER, switching.speeds), [1.0]]))
        result = _arm_sweep(name, switching, sw.ArmTravel(law, follower, heel), train, speeds)
        jump = result.headline()["jump_speed"]
        arm_force = float(result.contact_force[int(np.flatnonzero(speeds == omega)[0])].max())
        min_force = tuple(float(f) for f in result.events.min_contact_force)
        unlatched = float(follower.valve_lift_of(rest, heel))
        modes = TwoStepFigures()
    valve_force = float(sw.valve_force_of_arm(arm_force, follower.roller_arm, rest_arm))
    cam_force = design.drive.strength.cam_force_max
    latch = float(sw.latch_force(cam_force, inner, switching.latch_arm))
    latch_stress = float(sw.latch_stress(latch, switching.latch_width, switching.latch_pin_diameter, STEEL_MODULUS,
                                         switching.latch_seat_radius))
    latching = _latching(switching, cam, 2.0 * np.pi - (theta[-1] - theta[0]))
    figures = SwitchingRecord(
        switching.mode, float(design.flow.valve_lift), unlatched, swing, crank * omega, reserve, float(required.max()),
        preload, rate, top, float(sw.torsion_coils(STEEL_MODULUS, wire, mean, rate)), stress, stress / strength,
        frequency, frequency * 2.0 * np.pi / omega,
        None if two_step or not np.isfinite(jump) else crank * jump, crank * static,
        None if speeds is None else crank * float(speeds[-1]), arm_force, valve_force, valve_preload, cam_force, latch,
        latch_stress, *_air_spring(switching, engine), () if speeds is None else tuple(crank * speeds), min_force,
        two_step=modes.record, latch=latching)
    checks = (
        check("switching.jump_speed", (jump if np.isfinite(jump) else speeds[-1]) / omega, low=1.0,
              source=cited(note("source.follower_dynamics", work=cite("norton2009"))), severity="failure",
              note="" if np.isfinite(jump) else note("switching.no_jump", factor=SPEEDS_OVER)),
        *((check("switching.low_lift_jump", valve_jump / omega, low=1.0, severity="failure",
                 source=cited(note("source.follower_dynamics", work=cite("norton2009")))),) if two_step else
          (check("switching.valve_held", valve_force / valve_preload, high=1.0, source=cite("hendriksma2007"),
                 severity="failure"),)),
        check("switching.spring_stress", stress, high=strength, unit="MPa", severity="failure",
              source=cited(note("source.wire_strength", work=cite("shigley2011", "Table 10-4")))),
        check("switching.latch_stress", latch_stress, high=LATCH_LIMIT, unit="MPa", source=LATCH_SOURCE,
              severity="failure"),
        *modes.checks,
        *(() if latching is None else (
            check("switching.latch_time", latching.share, high=1.0, severity="failure",
                  source=cited(note("source.pin_orifice", work=cite("merritt1967")),
                               note("source.latch_on_base_circle", work=cite("hendriksma2007")))),)),
    )
    return SwitchingResult(figures, tuple(c.of_valve(name) for c in checks))


def _latching(switching, cam, window) -> Optional[LatchSwitching]:
    """The latch's switching window ``window`` [camshaft rad] and its time at the rated speed, the pin's travel times
    both ways (:func:`valvetrain.switching.latch_travel_time`); None without the latch's oil and spring."""
    if switching.latch_stroke is None:
        return None
    area = np.pi * switching.latch_pin_diameter ** 2 / 4.0
    times = [sw.latch_travel_time(switching.latch_pin_mass_kg, area, switching.latch_stroke,
                                  switching.latch_spring_preload_N, switching.latch_spring_rate,
                                  switching.oil_pressure, np.pi * switching.oil_passage_diameter ** 2 / 4.0,
                                  switching.oil_density_kg_m3, switching.passage_discharge_coefficient, engage)
             for engage in (True, False)]
    window_time = window / cam.cam_speed
    return LatchSwitching(window, window_time, *times, max(times) / window_time)


def _arm_sweep(name, switching, travel, train, speeds):
    """The deactivated arm's dynamic sweep (:func:`valvetrain.dynamics.sweep.sweep`), refused where larger than the
    dynamics chapter allows."""
    excess = sweep_excess(train.network(), speeds, 3, SWEEP_STEP_DEG)
    if excess:
        raise SpecError([Problem(f"valves.{name}.switching.contact_stiffness_N_per_mm",
                                 NoteText(note("spec.arm_sweep", speeds=switching.speeds, excess=excess)),
                                 f"{switching.contact_stiffness * 1e-3:g}")])
    return sweep(travel, train, speeds, revolutions=3, step_deg=SWEEP_STEP_DEG)


@dataclass(frozen=True)
class TwoStepFigures:
    """A two-step finger's record (None deactivated) and the checks of its unlatched breathing."""

    record: Optional[TwoStepRecord] = None
    checks: tuple[Check, ...] = ()


def _modes(name, design, valve, lobe, breathing, b, valve_jump) -> TwoStepFigures:
    """Both modes' events, time-areas and, with the breathing chapter, breathing (:mod:`valvetrain.design.two_step`);
    ``valve_jump`` the valve's jump speed on the low lobe [engine rad/s]."""
    rows, found = ((), [])
    if breathing is not None and b is not None:
        rows, found = ts.mode_breathing(name, design, valve, lobe, breathing, b)
    main = design.cam
    return TwoStepFigures(TwoStepRecord(
        main.valve_opens, main.valve_closes, lobe.cam.valve_opens, lobe.cam.valve_closes,
        design.flow.time_area_open, lobe.flow.time_area_open, lobe.profile.rho_min, valve_jump, rows or None),
        tuple(found))


def _air_spring(switching, engine) -> tuple:
    """The deactivated cylinder's breathing at the rated speed (:func:`valvetrain.switching.air_spring`): work per
    cycle [J], its loss over the swept volume [Pa], the peak pressure [Pa], the revolutions; Nones without
    ``compression_ratio``."""
    if switching.compression_ratio is None:
        return None, None, None, None
    r, gamma = AIR
    eps = switching.compression_ratio
    swept = np.pi * engine.bore ** 2 / 4.0 * engine.stroke
    temperature = switching.trapped_temperature_C + 273.15
    mass = switching.trapped_pressure * swept * eps / (eps - 1.0) / (r * temperature)
    spring = sw.air_spring(engine.bore, engine.stroke, engine.rod_length, eps, mass, temperature,
                           switching.wall_temperature_C + 273.15, engine.rated_speed, r, gamma)
    work = spring.work * engine.strokes / 2.0        # revolutions per cycle
    return work, -work / swept, float(spring.pressure.max()), spring.revolutions
