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
from ..bibliography import cite
from ..checks import Check, check
from ..dynamics.sweep import sweep, sweep_size
from ..locale import note
from ..spring_materials import grade
from ..specification.messages import Problem, SpecError
from ..springs import DEFLECTION_RATIO_RANGE, enveloping_line
from ..strength import LIMITS, STEEL_MODULUS
from .dynamics import MAX_SWEEP_BYTES, MAX_SWEEP_WORK
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

LATCH_SOURCE = (cite("vt_works", "eq. (7.13): <= 2000 MPa, the hardened rocker pad's, taken for the latch pin "
                     "on its seat (no published allowable of the latch was found)"))

SPRING_SOURCE = (f"{cite('norton2009', 'the chapter on the dynamics of follower trains')}; "
                 f"{cite('hendriksma2007')}; the force ratio's range {DEFLECTION_RATIO_RANGE[0]:g}..."
                 f"{DEFLECTION_RATIO_RANGE[1]:g} the valve spring's ({cite('vt_works', 'work 5')}), taken for "
                 "the lost-motion spring (none published for it)")


@dataclass(frozen=True)
class SwitchingRecord:
    """A valve's switching roller finger follower: the two modes, the lost-motion spring, the arm's dynamics and the
    latch."""

    mode: str = quantity("mode", label="the unlatched mode: deactivation (the valve stays shut)")
    latched_lift: float = quantity("latched_valve_lift_mm", "mm", "valve lift latched (the finger's)")
    unlatched_lift: float = quantity("unlatched_valve_lift_mm", "mm", "valve lift unlatched: the finger's at its rest "
                                     "angle, where the body stays")
    arm_swing: float = quantity("arm_swing_deg", "deg", "the unlatched inner arm's turn from the heel to the nose")
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
                                           "its cam (the dynamic sweep; none up to its top speed)", omit_none=True)
    jump_speed_static: float = quantity("jump_speed_quasi_static_rpm", "rpm", "the same of a rigid arm, "
                                        "min sqrt((T_0 + k phi) / (J (-phi'')))")
    sweep_top: float = quantity("sweep_top_rpm", "rpm", "highest engine speed of the arm's sweep")
    arm_force: float = quantity("arm_contact_force_max_N", "N", "largest force of the unlatched arm on its cam at the "
                                "over-speed (the sweep's)")
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


@dataclass(frozen=True)
class SwitchingResult:
    """The switching chapter of a valve: the record and the checks."""

    figures: SwitchingRecord
    checks: tuple[Check, ...] = ()

    @property
    def summary(self) -> dict:
        """The switching record of results.json."""
        return record(self.figures)


def switching_stage(name, switching, valve, engine, design) -> SwitchingResult:
    """The switching chapter of the valve ``name``.

    Parameters
    ----------
    name : str
    switching, valve, engine : SI views of [valves.NAME.switching], the valve and [engine].
    design : ValveDesign
        The valve, designed latched (its finger, law, valve spring and strength).

    Raises
    ------
    SpecError
        An arm's sweep larger than the dynamics chapter allows (:data:`~valvetrain.design.dynamics.MAX_SWEEP_WORK`,
        :data:`~valvetrain.design.dynamics.MAX_SWEEP_BYTES`), naming ``contact_stiffness_N_per_mm``.

    Notes
    -----
    Over-speed omega_os = omega_cam(rated) x ``engine.over_speed_ratio``.  The arm turns by phi = u / L_i with u the
    roller centre's travel (:func:`valvetrain.switching.roller_travel`); the spring's line T_0 + k phi is the tightest
    above K J omega_os^2 max(0, -phi'') (:func:`valvetrain.springs.enveloping_line`).  The dynamic sweep is the arm as
    a one-mass train at its roller (:func:`valvetrain.switching.arm_train`) on the travel u(theta), from a quarter of
    the over-speed to :data:`SPEEDS_OVER` times it; its jump speed is the sweep's (:meth:`~valvetrain.dynamics.sweep.
    SweepResult.headline`).
    """
    cam, follower, law = design.cam, design.follower_model, design.law
    heel = cam.heel_radius
    reserve = switching.reserve if switching.reserve is not None else valve.drive.spring_reserve
    omega = cam.cam_speed * engine.over_speed_ratio
    theta = np.unique(np.concatenate([np.linspace(law.start, law.end, 2001), law.breakpoints]))
    u, _, d2u = sw.roller_travel(follower, heel, *law.derivatives(theta)[:3])
    inner, inertia = switching.inner_arm, switching.inner_arm_inertia
    phi, d2phi = u / inner, d2u / inner
    required = sw.required_torque(inertia, d2phi, omega, reserve)
    preload, rate = enveloping_line(phi, required)
    swing = float(phi.max())
    top = preload + rate * swing
    wire, mean = switching.spring_wire_diameter, switching.spring_mean_diameter
    stress = float(sw.torsion_stress(top, wire, mean))
    strength = float(grade(switching.spring_material).tensile_strength(wire))
    frequency = sw.arm_frequency(rate, inertia)
    train = sw.arm_train(inertia, inner, rate, preload, switching.contact_stiffness)
    speeds = omega * np.unique(np.concatenate([np.linspace(0.25, SPEEDS_OVER, switching.speeds), [1.0]]))
    work, size = sweep_size(train.network(), speeds, 3, SWEEP_STEP_DEG)
    if work > MAX_SWEEP_WORK or size > MAX_SWEEP_BYTES:
        raise SpecError([Problem(f"valves.{name}.switching.contact_stiffness_N_per_mm", f"with speeds = "
                                 f"{switching.speeds} the unlatched arm's sweep is about {work:.3g} integrator steps x "
                                 f"elements (allowed {MAX_SWEEP_WORK:.3g}) and {size / 1e6:.0f} MB (allowed "
                                 f"{MAX_SWEEP_BYTES / 1e6:.0f} MB): a softer contact, a heavier arm or fewer speeds",
                                 f"{switching.contact_stiffness * 1e-3:g}")])
    result = sweep(sw.ArmTravel(law, follower, heel), train, speeds, revolutions=3, step_deg=SWEEP_STEP_DEG)
    jump = result.headline()["jump_speed"]
    at = int(np.flatnonzero(speeds == omega)[0])
    arm_force = float(result.contact_force[at].max())
    rest = np.array(follower.base_angle(heel))      # unlatched, the body stays where the heel circle holds it
    rest_arm = float(follower.valve_arm(rest))
    unlatched = float(follower.valve_lift_of(rest, heel))
    valve_force = float(sw.valve_force_of_arm(arm_force, follower.roller_arm, rest_arm))
    cam_force = design.drive.strength.cam_force_max
    latch = float(sw.latch_force(cam_force, inner, switching.latch_arm))
    latch_stress = float(sw.latch_stress(latch, switching.latch_width, switching.latch_pin_diameter, STEEL_MODULUS,
                                         switching.latch_seat_radius))
    static = sw.quasi_static_jump_speed(train.mass, train.preload, train.spring_rate, u, d2u)
    crank = engine.strokes / 2.0     # the engine's speed over the camshaft's
    figures = SwitchingRecord(
        switching.mode, float(design.flow.valve_lift), unlatched, swing, crank * omega, reserve, float(required.max()),
        preload, rate, top, float(sw.torsion_coils(STEEL_MODULUS, wire, mean, rate)), stress, stress / strength,
        frequency, frequency * 2.0 * np.pi / omega, None if not np.isfinite(jump) else crank * jump, crank * static,
        crank * float(speeds[-1]), arm_force, valve_force, design.drive.spring.preload, cam_force, latch, latch_stress,
        *_air_spring(switching, engine), tuple(crank * speeds),
        tuple(float(f) for f in result.events.min_contact_force))
    checks = (
        check("switching.jump_speed", (jump if np.isfinite(jump) else speeds[-1]) / omega, low=1.0,
              source=cite("norton2009", "the chapter on the dynamics of follower trains"), severity="failure",
              note="" if np.isfinite(jump) else note("switching.no_jump", factor=SPEEDS_OVER)),
        check("switching.valve_held", valve_force / design.drive.spring.preload, high=1.0,
              source=cite("hendriksma2007"), severity="failure"),
        check("switching.spring_stress", stress, high=strength, unit="MPa", severity="failure",
              source=f"{cite('shigley2011', 'Table 10-4')}: the wire's tensile strength R_m, the most it can carry"),
        check("switching.latch_stress", latch_stress, high=LATCH_LIMIT, unit="MPa", source=LATCH_SOURCE,
              severity="failure"),
    )
    return SwitchingResult(figures, tuple(c.of_valve(name) for c in checks))


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
