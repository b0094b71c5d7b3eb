"""Valve stages of the design: the law, the flow, the profile, the piston clearance and the checks
(Valve-train practical works (n.d.), works 1-4, Shang Hanji (1988), section 2.1).

Each stage is a function from SI inputs (the valve's and the engine's SI views,
:func:`valvetrain.specification.si`, and the results of earlier stages) to a typed, frozen result;
:func:`design_valve` composes them with the drive stage and can be entered with a law of the
caller's own.  Crank angles are measured from the gas-exchange TDC (the TDC that starts the
intake stroke) in (-360, 360]; camshaft angles from the cam nose.
"""

from dataclasses import dataclass, field, replace
from functools import cached_property
import math
from typing import Any, Optional, Union

import numpy as np

from .. import flow, geometry
from ..checks import Check, failed, ranked, tally
from ..crank.kinematics import displacement
from ..errors import InputError
from ..locale import NoteText, note
from ..followers import follower_of
from ..followers.finger import FingerKinematics
from ..followers.flat import FlatContact
from ..followers.roller import RollerContact
from ..laws import LiftLaw
from ..laws.base import Extremes
from ..laws.records import LawRecord
from ..numerics import extremum, first_largest
from ..specification import SpecError
from ..specification.messages import Problem, said
from ..specification.validate import spring_length_problems
from ..springs import NoSpringFits
from ..units import MM, to_display
from .drive import DriveResult, drive_record, drive_stage
from .drive_strength import strength_speed_range, strength_stage
from .dynamics import DynamicsResult, dynamics_stage, swept_range
from .grinding import GrindingResult, grinding_stage
from .hydraulic_actuation import HydraulicResult, hydraulic_stage
from .lost_motion import LostMotionResult, lost_motion_stage
from .lash_adjuster import LashAdjusterResult, lash_adjuster_stage
from .lubrication import LubricationResult, lubrication_stage
from .results import NamedValues, quantity, record
from .valve_checks import MAX_LIFT_TO_THROAT, clearance_check, mass_checks, valve_checks

CYCLE_CRANK = np.radians(np.linspace(-360.0, 360.0, 2881))
"""Crank angles of :attr:`ValveDesign.cycle_lift` [rad from the gas-exchange TDC]: the four-stroke cycle, a quarter
degree apart (the timing diagram's)."""

@dataclass(frozen=True)
class StepRecord:
    """A step of the tappet acceleration at a boundary of the law, at the rated speed: the jerk is an impulse there."""

    angle: float = quantity("cam_deg", "cam deg", "camshaft angle of the step, from the nose")
    before: float = quantity("before_m_s2", "m/s2", "tappet acceleration just before")
    after: float = quantity("after_m_s2", "m/s2", "tappet acceleration just after")
    size: float = quantity("step_m_s2", "m/s2", "the step, after - before")
    on_ramp: bool = quantity("on_ramp", label="within a ramp: the clearance is being taken up, the valve at rest")


def step_records(law, cam_speed) -> tuple[StepRecord, ...]:
    """The acceleration steps of a law (:meth:`~valvetrain.laws.LiftLaw.acceleration_steps`) as tappet
    accelerations at the camshaft speed [rad/s], a tuple of :class:`StepRecord`."""
    w2 = cam_speed**2
    return tuple(StepRecord(st.angle, w2 * st.before, w2 * st.after, w2 * st.size,
                            bool(st.angle < law.valve_opens or st.angle > law.valve_closes))
                 for st in law.acceleration_steps())


@dataclass(frozen=True)
class CamResult:
    """The law stage: the cam's lift law at the rated speed and what the rest of the design needs of it (SI)."""

    law: LiftLaw = field(repr=False)
    name: str = quantity("law", label="lift law")
    source: str = quantity("source", label="source of the law's formulas")
    coefficients: NamedValues = quantity("coefficients", label="the law's coefficients in its source's units")
    extremes: Extremes = field(repr=False)
    max_velocity: float = quantity("max_velocity_m_s", "m/s", "largest tappet velocity")
    max_acceleration: float = quantity("max_acceleration_m_s2", "m/s2", "largest tappet acceleration")
    min_acceleration: float = quantity("min_acceleration_m_s2", "m/s2", "smallest tappet acceleration")
    main_half_angle: float = quantity("phi_p0_deg", "cam deg", "phi_p0, half the main event (ramps excluded)")
    ramp_angle: float = quantity("ramp_deg", "cam deg", "ramp length on the opening flank")
    ramp_height: float = quantity("ramp_height_mm", "mm", "ramp height (the clearance taken up)")
    tappet_lift: float = quantity("tappet_lift_mm", "mm", "tappet lift above the ramp, h_T max")
    opening_velocity: float = quantity("valve_opening_velocity_m_s", "m/s", "valve velocity as it leaves its seat")
    seating_velocity: float = quantity("valve_seating_velocity_m_s", "m/s", "valve velocity as it meets its seat")
    event: float = quantity("event_cam_deg", "cam deg", "cam event, ramps included")
    nose: float = quantity("nose_crank_deg", "crank deg", "crank angle of the nose from the gas-exchange TDC")
    valve_opens: float = quantity("valve_opens_crank_deg", "crank deg",
                                  "where the valve leaves its seat, from the gas-exchange TDC")
    valve_closes: float = quantity("valve_closes_crank_deg", "crank deg",
                                   "where the valve meets its seat, from the gas-exchange TDC")
    cam_speed: float = quantity("camshaft_speed_rad_s", "rad/s", "camshaft speed omega_cam at the rated speed")
    follower: str = quantity("follower", label="follower: flat, roller or finger")
    base_radius: float = quantity("base_radius_mm", "mm", "r0, where the main lift starts")
    heel_radius: float = quantity("heel_radius_mm", "mm", "heel (base) circle of the cam, r0 - ramp height")
    roller_radius: float = 0.0
    rocker_ratio: float = 1.0
    acceleration_steps: tuple[StepRecord, ...] = quantity(
        "acceleration_steps", label="steps of the tappet acceleration at the rated speed (the jerk is an impulse "
        "there): cam angle, before, after, step, on a ramp", default=())
    follower_model: Any = field(default=None, repr=False)
    """The cam's :class:`~valvetrain.followers.Follower` (:func:`~valvetrain.followers.follower_of` the cam section)."""

    def valve_lift(self, theta) -> float | np.ndarray:
        """Valve lift [m] at camshaft angles theta."""
        return self.law.valve_lift(theta, self.rocker_ratio, self.follower_model)


@dataclass(frozen=True)
class FlowResult:
    """The flow stage: flow sections, conditional velocities, time-area and fullness (Valve-train practical works (n.d.), works 1, 4; Shang Hanji (1988))."""

    throat_area: float = quantity("throat_area_mm2", "mm2", "throat area f_g")
    max_curtain_area: float = quantity("max_curtain_area_mm2", "mm2", "curtain area at full lift")
    v1: float = quantity("V1_m_s", "m/s", "V', throat velocity (eq. 1.1)")
    v2: float = quantity("V2_m_s", "m/s", "V'', curtain velocity at full lift (eq. 1.2)")
    v3: float = quantity("V3_m_s", "m/s", "V''', time-area velocity (eq. 1.4)")
    time_area: float = quantity("time_area_mm2_s", "mm2 s", "time-area over the valve's own stroke")
    time_area_open: float = quantity("time_area_open_mm2_s", "mm2 s", "time-area over the whole opening")
    charge_velocity: float = quantity("mean_charge_velocity_m_s", "m/s", "v_vp, mean charge velocity (eq. 4.3)")
    fullness: float = quantity("fullness", label="fullness of the valve lift diagram (Shang Hanji (1988), eq. 2.3)")
    valve_lift: float = quantity("valve_lift_mm", "mm", "largest valve lift")
    stroke: tuple[float, float] = quantity("stroke_crank_deg", "crank deg", "the valve's own stroke, from and to")


@dataclass(frozen=True)
class LiftTable:
    """Sampled lift diagram of one valve; arrays share one camshaft-angle grid (SI units)."""

    cam_angle: np.ndarray          # rad from the nose
    crank_angle: np.ndarray        # rad from gas-exchange TDC
    segment: np.ndarray            # segment names
    lift: np.ndarray               # tappet lift incl. ramp [m]
    velocity: np.ndarray           # [m/s]
    acceleration: np.ndarray       # [m/s^2]
    jerk: np.ndarray               # [m/s^3]
    valve_lift: np.ndarray         # [m]
    curtain_area: np.ndarray       # [m^2]
    time_area: np.ndarray          # running, from the table start [m^2 s]
    rho: np.ndarray                # cam profile radius of curvature [m]
    pressure_angle: np.ndarray     # roller: pressure angle [rad]; flat: zero
    contact_offset: np.ndarray     # flat: contact point off the follower axis [m]; roller: zero


@dataclass(frozen=True)
class ProfileResult:
    """The profile stage: lift table, contour, curvature and contact of the cam (Shang Hanji (1988), section 2.1)."""

    table: LiftTable = field(repr=False)
    contour: np.ndarray = field(repr=False)        # (2, n) [m], cam frame, nose on +y
    contour_angle: np.ndarray = field(repr=False)  # camshaft angle of each contour point [rad from the nose]
    rho_min: float = quantity("rho_min_mm", "mm", "smallest radius of curvature of the profile")
    rho_max: float = quantity("rho_max_mm", "mm", "largest radius of curvature (null: straight flanks)")
    rho_min_angle: float = quantity("rho_min_cam_deg", "cam deg", "where the radius is smallest")
    rho_max_angle: float = quantity("rho_max_cam_deg", "cam deg", "where the radius is largest")
    straight_flanks: bool = quantity("straight_flanks", label="the profile has straight flanks")
    contact: Union[FlatContact, RollerContact] = quantity("contact", flatten=True)
    undercut: bool = quantity("undercut", label="the profile is undercut (cannot be made)")
    finger: Optional[FingerKinematics] = quantity("finger", label="the finger follower's linkage over the lift",
                                                  omit_none=True, default=None)


@dataclass(frozen=True)
class ClearanceResult:
    """The valve-piston clearance stage (Shang Hanji (1988), eqs. 2.13-2.14)."""

    min_gap: float = quantity("min_clearance_mm", "mm", "smallest valve-to-piston gap over the open event")
    angle: float = quantity("crank_deg", "crank deg", "where the gap is smallest")
    crank: np.ndarray = field(repr=False)   # crank angles of the open event, rad from the gas-exchange TDC
    gap: np.ndarray = field(repr=False)     # valve-to-piston gap at those angles [m]

    def within(self, low, high) -> Optional[tuple[float, float]]:
        """The smallest gap [m] and its crank angle [rad] between the crank angles low and high, or None."""
        inside = (self.crank >= low) & (self.crank <= high)
        if not np.any(inside):
            return None
        i = int(np.argmin(np.where(inside, self.gap, np.inf)))
        return float(self.gap[i]), float(self.crank[i])


def wrap_crank(a) -> np.ndarray:
    """Crank angle wrapped into (-360, 360] deg (in rad)."""
    return np.where(a > 2 * np.pi, a - 4 * np.pi, np.where(a <= -2 * np.pi, a + 4 * np.pi, a))


def law_stage(valve, engine, law=None) -> CamResult:
    """Build (or take) the lift law of a valve and find what the design needs of it.

    Parameters
    ----------
    valve, engine : SI views of the valve and the engine (:func:`valvetrain.specification.si`).
    law : LiftLaw, optional
        A law of the caller's own instead of the one the cam section builds.

    Returns
    -------
    CamResult

    Raises
    ------
    ValueError
        The inputs admit no law that can be made: the law's own rules, a lift that overshoots the nose or dips
        below the base circle, an event of a whole revolution or more, a valve lift beyond half the throat, a
        measured table's lift that the spring's lengths do not admit; the argument is a
        :class:`~valvetrain.specification.messages.Problem` naming the key within the valve (``cam``, ``max_lift_mm``,
        ``spring.installed_length_mm``).
    """
    cam = valve.cam
    try:
        law = cam.section.build(valve, engine) if law is None else law
    except ValueError as exc:
        raise InputError(Problem("cam", said(exc))) from None
    nose_lift = law.lift_max + law.ramp_height
    low, high = (extremum(law.lift, law.breakpoints, kind)[1] for kind in ("min", "max"))
    if high > nose_lift * (1.0 + 1e-6) or low < -1e-6 * nose_lift:
        raise InputError(Problem("cam", NoteText(note("spec.lift_range", low=low / MM, high=high / MM,
                                                      nose=nose_lift / MM))))
    event = law.end - law.start
    if not event < 2.0 * np.pi:
        ramp = math.degrees(law.ramp_angle)
        raise InputError(Problem("cam", NoteText(note("spec.event_over_revolution", event=math.degrees(event),
                                                      ramps=note("spec.long_ramps", ramp=ramp) if ramp > 0.0 else ()))))
    lift = law.lift_max * valve.rocker_ratio
    if lift > MAX_LIFT_TO_THROAT * valve.throat_diameter:
        allowed = note("spec.lift_to_throat", share=MAX_LIFT_TO_THROAT,
                       most=MAX_LIFT_TO_THROAT * valve.throat_diameter / MM)
        if cam.law == "table":
            key = "cam.table_file" if cam.table_file is not None else "cam.table_lifts_mm"
            raise InputError(Problem(key, NoteText(note("spec.measured_lift", lift=lift / MM, allowed=allowed))))
        raise InputError(Problem("max_lift_mm", NoteText(allowed), f"{lift / MM:.4g} mm"))
    if cam.law == "table":     # the spring's lengths against the lift, checked at validation where it is given
        found = spring_length_problems(valve.spring.section, lift / MM, note("spec.measured_valve_lift"))
        if found:
            raise InputError(found[0])
    follower = follower_of(cam)
    # a finger on a measured table (or a caller's law): its lift known only now
    problem = follower.geometry_problem(cam.base_radius - law.ramp_height, law.lift_max + law.ramp_height)
    if problem:
        key, value, message, joiner = problem
        raise InputError(Problem(f"cam.{key}", message, value, joiner))
    omega = engine.rated_speed / 2.0
    ext = law.extremes(omega)
    seat = valve.rocker_ratio * omega * np.abs(law.derivatives(np.array([law.valve_opens, law.valve_closes]))[1])
    nose = cam.section.nose_crank(valve, law)
    return CamResult(law, law.name, law.source, NamedValues.of(law.coefficients()), ext, ext.max_velocity, ext.max_acceleration,
                     ext.min_acceleration, law.main_half_angle, law.ramp_angle, law.ramp_height, law.lift_max,
                     float(seat[0]), float(seat[1]), event, nose, nose + 2.0 * law.valve_opens,
                     nose + 2.0 * law.valve_closes, omega, cam.follower, cam.base_radius,
                     cam.base_radius - law.ramp_height, cam.roller_radius or 0.0, valve.rocker_ratio,
                     step_records(law, omega), follower)


def flow_stage(cam, valve, engine) -> FlowResult:
    """Flow sections, conditional velocities, time-area over the valve's stroke and opening, fullness.

    References
    ----------
    Valve-train practical works (n.d.), work 1, eqs. (1.1)-(1.4); work 4, eqs. (4.1), (4.3); Shang Hanji (1988), eqs. (2.1)-(2.3).
    """
    law, omega = cam.law, cam.cam_speed
    c_p = flow.mean_piston_speed(engine.stroke, to_display(engine.rated_speed, "rpm"))
    swept = float(flow.swept_volume(engine.bore, engine.stroke))
    lift = law.lift_max * cam.rocker_ratio
    d_g, seat = valve.throat_diameter, valve.seat_angle

    def area(theta):
        return flow.curtain_area(cam.valve_lift(theta), d_g, seat)

    f_max = float(flow.curtain_area(lift, d_g, seat))
    stroke = (0.0, np.pi) if valve.kind == "intake" else (-np.pi, 0.0)
    window = tuple((c - cam.nose) / 2.0 for c in stroke)
    bp = law.breakpoints
    ta_stroke = flow.time_area(area, window[0], window[1], omega, bp)
    return FlowResult(
        float(flow.circle_area(d_g)), f_max, flow.throat_velocity(c_p, engine.bore, d_g, valve.count),
        flow.curtain_velocity(c_p, engine.bore, f_max, valve.count),
        flow.time_area_velocity(swept, ta_stroke, valve.count), ta_stroke,
        flow.time_area(area, law.valve_opens, law.valve_closes, omega, bp),
        flow.mean_charge_velocity(swept, ta_stroke, valve.count),
        flow.fullness(cam.valve_lift, law.valve_opens, law.valve_closes, lift, bp), lift, stroke)


def _table_grid(law, step):
    k = np.arange(np.ceil(law.start / step), np.floor(law.end / step) + 1) * step
    return np.unique(np.concatenate([[law.start], k, [law.end]]))


def _first_best(candidates, sign) -> tuple[float, float]:
    """Of candidate ``(angle, value)`` pairs the largest ``sign * value``; of values equal to round-off the one at
    the smallest angle (:func:`~valvetrain.numerics.first_largest`)."""
    ordered = sorted(candidates, key=lambda p: p[0])
    return ordered[first_largest([sign * p[1] for p in ordered])]


def profile_stage(cam, valve, output) -> ProfileResult:
    """The lift table, the contour over a revolution, the profile's curvature extremes, contact and undercut.

    ``output`` is the SI view of ``[output]`` (table step, contour points).

    References
    ----------
    Shang Hanji (1988), section 2.1, eqs. (2.6)-(2.7), (2.15)-(2.16); Valve-train practical works (n.d.), work 2 (rho_min, corrections note 2, corrections note 26).
    """
    law, omega, heel, follower = cam.law, cam.cam_speed, cam.heel_radius, cam.follower_model
    bp = law.breakpoints
    theta = _table_grid(law, output.table_step)
    d = law.derivatives(theta)
    _, rho, beta, offset = law.profile(theta, heel, follower)

    def area(t):
        return flow.curtain_area(cam.valve_lift(t), valve.throat_diameter, valve.seat_angle)

    table = LiftTable(
        cam_angle=theta, crank_angle=wrap_crank(cam.nose + 2.0 * theta), segment=law.segment_names(theta),
        lift=d[0], velocity=omega * d[1], acceleration=omega**2 * d[2], jerk=omega**3 * d[3],
        valve_lift=cam.valve_lift(theta), curtain_area=area(theta),
        time_area=flow.cumulative_time_area(area, theta, omega, bp), rho=rho, pressure_angle=beta,
        contact_offset=offset)
    ctheta = np.unique(np.concatenate([np.linspace(-np.pi, np.pi, output.contour_points, endpoint=False), bp]))
    contour = law.profile(ctheta, heel, follower)[0]

    def convex(t):
        """Profile radius where the profile is convex, +inf where it is concave (a concave stretch of a roller
        cam is not an undercut; its radius is reported on its own)."""
        return follower.convex_radius(law.curvature(t, heel, follower))

    # the base circle (radius = heel radius for both followers) closes the profile; the smallest radius is refined
    # on the contour around the least sample of each piece and around the table's least, so that a dip between the
    # table's points (an undercut) is found
    # (of radii equal to round-off, a symmetric cam's two flanks, the one at the smallest angle)
    i = first_largest(-follower.convex_radius(rho))
    near = theta[[max(i - 1, 0), min(i + 1, theta.size - 1)]]
    x_min, rho_min = _first_best([extremum(convex, bp, "min"), extremum(convex, near, "min"), (np.pi, heel)], -1.0)

    def convex_or_low(t):
        """The convex radius, -inf where the profile is concave (the largest radius is that of a convex stretch)."""
        r = convex(t)
        return np.where(np.isinf(r), -np.inf, r)

    x_max, rho_max = _first_best([extremum(convex_or_low, bp, "max"), (np.pi, heel)], 1.0)
    straight = bool(np.any(np.isposinf(rho)))   # straight flanks (tangent cam): the largest radius is infinite
    return ProfileResult(table, contour, ctheta, rho_min, None if straight else rho_max, x_min,
                         None if straight else x_max, straight,
                         follower.profile_contact(law, heel, cam.max_velocity / omega), follower.undercut(rho_min),
                         follower.kinematics(heel, law.lift_max + law.ramp_height))


def clearance_stage(cam, valve, engine, advance=0.0) -> Optional[ClearanceResult]:
    """The smallest valve-to-piston gap over the open event, or None without ``piston_gap_tdc_mm``; with ``advance``
    [crank rad] the events that much earlier (a cam phaser's, :mod:`valvetrain.design.phaser`).

    Raises
    ------
    ValueError
        A gap of zero or less: the valve hits the piston.

    References
    ----------
    Shang Hanji (1988), eqs. (2.13)-(2.14), with the exact slider-crank displacement (Power units manual (n.d.), eq. 1.2).
    """
    if valve.piston_gap_tdc is None:
        return None
    law, radius = cam.law, engine.stroke / 2.0
    crank = cam.nose - advance + 2.0 * np.linspace(law.valve_opens, law.valve_closes, 2001)
    s = displacement(crank, radius, radius / engine.rod_length)
    gap = geometry.valve_piston_clearance(s, cam.valve_lift((crank + advance - cam.nose) / 2.0), valve.piston_gap_tdc)
    i = int(np.argmin(gap))
    angle = float(wrap_crank(crank[i]))
    if gap[i] <= 0.0:
        raise InputError(NoteText(note("spec.valve_hits_piston", gap=gap[i] / MM, angle=math.degrees(angle),
                                       tdc_gap=valve.piston_gap_tdc / MM)))
    return ClearanceResult(float(gap[i]), angle, wrap_crank(crank), gap)


@dataclass(frozen=True, repr=False)
class ValveDesign:
    """Everything computed for one valve: the stage results (SI), the law's own records and every check."""

    name: str
    kind: str
    count: int
    cam: CamResult
    flow: FlowResult
    profile: ProfileResult
    clearance: Optional[ClearanceResult]
    records: LawRecord             # the law's own results (seed formulas, a measured table's analysis)
    drive: DriveResult             # masses, spring curves, strength
    checks: tuple[Check, ...] = ()                  # every check of the valve, passed or not
    dynamics: Optional[DynamicsResult] = None       # with a [dynamics] section
    grinding: Optional[GrindingResult] = None       # with a [grinding] section
    hydraulic: Optional[HydraulicResult] = None     # with a [hydraulic] section
    lubrication: Optional[LubricationResult] = None        # with a [lubrication] section
    lash_adjuster: Optional[LashAdjusterResult] = None     # with a [lash_adjuster] section
    lost_motion: Optional[LostMotionResult] = None          # with a [hydraulic.lost_motion] section
    geometry: Optional["ValveGeometry"] = field(default=None, repr=False, compare=False)  # before the drive

    @property
    def warnings(self) -> list[Check]:
        """The checks that fail and that the specification does not accept, ranked (failures first)."""
        return ranked(c for c in failed(self.checks) if not c.accepted)

    @property
    def accepted(self) -> list[Check]:
        """The checks that fail and that the specification accepts, ranked."""
        return ranked(c for c in failed(self.checks) if c.accepted)

    # the stage results that the edges (tables, plots, exports) read
    law = property(lambda self: self.cam.law)
    omega_cam = property(lambda self: self.cam.cam_speed)
    rocker_ratio = property(lambda self: self.cam.rocker_ratio)
    heel_radius = property(lambda self: self.cam.heel_radius)
    follower = property(lambda self: self.cam.follower)
    follower_model = property(lambda self: self.cam.follower_model)
    roller_radius = property(lambda self: self.cam.roller_radius)
    nose_crank = property(lambda self: self.cam.nose)
    table = property(lambda self: self.profile.table)
    contour = property(lambda self: self.profile.contour)
    contour_angle = property(lambda self: self.profile.contour_angle)

    @cached_property
    def cycle_lift(self) -> np.ndarray:
        """The valve lift [m] at the crank angles :data:`CYCLE_CRANK`, the camshaft turning at half the crank's speed
        (the timing diagram's), evaluated once: the first process of a run evaluates it before it sends the results
        to the processes that draw the figures, which then need not load the lift laws' compiled code
        (:func:`valvetrain.report.drawing.figure_inputs`)."""
        return self.law.valve_lift((CYCLE_CRANK - self.nose_crank) / 2.0, self.rocker_ratio, self.follower_model)

    @cached_property
    def summary(self) -> dict[str, Any]:
        """The valve's record in results.json (engineering units, named in the keys), made once: read it, don't
        change it."""
        out = {"kind": self.kind, "count": self.count, "rocker_ratio": self.rocker_ratio,
               "cam": {**record(self.cam), **record(self.profile), **record(self.records)}, "flow": record(self.flow)}
        if self.clearance is not None:
            out["piston_clearance"] = record(self.clearance)
        out.update(drive_record(self.drive))
        if self.dynamics is not None:
            out["dynamics"] = record(self.dynamics)
        if self.grinding is not None:
            out["grinding"] = record(self.grinding)
        if self.hydraulic is not None:
            out["hydraulic"] = record(self.hydraulic)
        if self.lubrication is not None:
            out["lubrication"] = record(self.lubrication)
        if self.lash_adjuster is not None:
            out["lash_adjuster"] = record(self.lash_adjuster)
        if self.lost_motion is not None:
            out["lost_motion"] = record(self.lost_motion)
        return out

    def __repr__(self):
        f = self.flow
        return (f"ValveDesign({self.name!r}: {self.kind}, {self.law.name} law, valve lift {f.valve_lift / MM:.4g} mm, "
                f"time-area {f.time_area / MM**2:.4g} mm2 s, fullness {f.fullness:.4g}, "
                "open failures {failure}, warnings {warning}, info {info} of {checks} checks)".format(**tally(self.checks)))


def kinematic_stages(name, valve, engine, output, law=None) -> tuple[CamResult, FlowResult, ProfileResult]:
    """The first stages of one valve, all that its lift curves and contour need: the law, the flow and the profile
    (:func:`law_stage`, :func:`flow_stage`, :func:`profile_stage`; no drive, no spring, no checks).  The designer's
    answer while a handle is dragged, and the start of :func:`design_valve`.

    Parameters
    ----------
    name : str
        The valve's name in the specification (the key path of a problem).
    valve, engine, output : SI views of the valve, the engine and ``[output]``.
    law : LiftLaw, optional
        As for :func:`design_valve`.

    Returns
    -------
    (CamResult, FlowResult, ProfileResult)

    Raises
    ------
    SpecError
        A cam the law cannot make, its message naming the valve's keys.
    """
    try:
        cam = law_stage(valve, engine, law)
    except ValueError as exc:
        raise SpecError([_stage_problem(exc, f"valves.{name}")]) from None
    return cam, flow_stage(cam, valve, engine), profile_stage(cam, valve, output)


def design_valve(name, valve, engine, gas, output, law=None, progress=None, cylinder=None,
                 headlines_only=False, diagnose=True, gas_load=None) -> ValveDesign:
    """All stages of one valve and its drive (masses, springs, strength).

    Parameters
    ----------
    name : str
        The valve's name in the specification.
    valve, engine, gas, output : SI views of the valve, the engine, ``[gas]`` and ``[output]``.
    law : LiftLaw, optional
        Enter the design with a law of the caller's own (the cam section's ``build`` is skipped).
    progress : callable, optional
        ``progress(done, total)`` during the speed sweep of a ``[dynamics]`` section.
    cylinder : valvetrain.design.hydraulic_actuation.CylinderPressure, optional
        The engine's cycle, whose pressure on the valve head a ``[hydraulic]`` section's valve opens against.
    headlines_only : bool
        The ``[dynamics]`` sweep simulates only the speeds that decide its headlines (``dynamics_stage``).
    diagnose : bool
        Diagnose springs that do not pass (:func:`~valvetrain.design.drive.drive_stage`).
    gas_load : (float, str), optional
        The spring's closed-valve gas load [N] and its source (:func:`~valvetrain.design.drive.drive_stage`).

    Returns
    -------
    ValveDesign

    Raises
    ------
    SpecError
        Inputs that admit no design, each message naming the valve's keys.
    """
    geometry = valve_geometry(name, valve, engine, output, law)
    try:
        drive = drive_stage(valve, gas, geometry.cam, diagnose, gas_load)
    except NoSpringFits as exc:
        raise SpecError([Problem(f"valves.{name}.spring", said(exc))]) from None
    return driven_design(name, valve, engine, gas, output, geometry, drive, progress, cylinder, headlines_only)


@dataclass(frozen=True, repr=False)
class ValveGeometry:
    """What a valve's design computes before its drive, which no load on the drive changes: the law stage, the flow,
    the profile, the piston clearance, the law's own records and the checks of the law's section."""

    cam: CamResult
    flow: FlowResult
    profile: ProfileResult
    clearance: Optional[ClearanceResult]
    records: LawRecord
    checks: tuple[Check, ...]


def valve_geometry(name, valve, engine, output, law=None) -> ValveGeometry:
    """The stages of one valve before its drive: :func:`design_valve`'s first part (parameters as there).

    Raises
    ------
    SpecError
        A cam the law cannot make or a piston clearance that cannot be computed, naming the valve's keys.
    """
    at = f"valves.{name}"
    cam, flow_result, profile = kinematic_stages(name, valve, engine, output, law)
    try:
        clearance = clearance_stage(cam, valve, engine)
    except ValueError as exc:
        raise SpecError([Problem(at, said(exc))]) from None
    records, found = valve.cam.section.records(cam.law, valve, engine, cam.nose)
    return ValveGeometry(cam, flow_result, profile, clearance, records, tuple(found))


def driven_design(name, valve, engine, gas, output, geometry, drive, progress=None, cylinder=None,
                  headlines_only=False) -> ValveDesign:
    """A valve's design from its geometry (:func:`valve_geometry`) and its drive stage (:func:`drive_stage`): the
    checks, the dynamics, the strength, the lubrication, the lash adjuster, the grinding and the hydraulic drive,
    :func:`design_valve`'s second part (parameters as there).

    Raises
    ------
    SpecError
        Inputs that admit no design, each message naming the valve's keys.
    """
    at = f"valves.{name}"
    cam, flow_result, profile, clearance, records = (geometry.cam, geometry.flow, geometry.profile, geometry.clearance,
                                                     geometry.records)
    found = list(geometry.checks)
    found += valve_checks(cam, flow_result, profile, valve, engine, valve.cam.section.timing(valve, records))
    found += list(drive.checks)
    found += mass_checks(valve, drive.masses.at_valve, flow_result.throat_area)
    if clearance is not None:
        found.append(clearance_check(valve.kind, clearance.min_gap, clearance.angle))
    dynamics = None
    if valve.dynamics is not None:
        loads = strength_speed_range(engine, swept_range(valve.dynamics, engine))[:2] if headlines_only else None
        dynamics, dynamics_found = dynamics_stage(valve.dynamics, valve, engine, cam.law, drive, name, progress, cam,
                                                   loads)
        found += dynamics_found
    strength_result, strength_found = strength_stage(valve, gas, engine, cam, drive, dynamics)
    drive = replace(drive, strength=strength_result, checks=drive.checks + tuple(strength_found))
    found += strength_found
    lubrication = None
    if valve.lubrication is not None and not profile.undercut:  # an undercut has no line contact: graded above
        lubrication, lubrication_found = lubrication_stage(valve.lubrication, valve, engine, cam, drive, dynamics, name)
        found += lubrication_found
    adjuster = None
    if valve.lash_adjuster is not None:
        adjuster, adjuster_found = lash_adjuster_stage(valve.lash_adjuster, valve, engine, cam, drive, dynamics, name)
        found += adjuster_found
    grinding = None
    if valve.grinding is not None:
        try:
            grinding, grinding_found = grinding_stage(valve.grinding, cam, name, output.export_step)
        except ValueError as exc:
            raise SpecError([_stage_problem(exc, f"{at}.grinding")]) from None
        found += grinding_found
    design = ValveDesign(name, valve.kind, valve.count, cam, flow_result, profile, clearance, records, drive,
                         tuple(c.of_valve(name) for c in found), dynamics, grinding, lubrication=lubrication,
                         lash_adjuster=adjuster, geometry=geometry)
    return with_hydraulic(design, valve, engine, gas, cylinder)




def with_gas_load(design, valve, engine, gas, output, gas_load, headlines_only=False, diagnose=True) -> ValveDesign:
    """The design with the spring's closed-valve gas load ``gas_load`` ((N, source), the breathing's): the drive
    stage anew and, where its springs, lines or masses change, what depends on them (the dynamics, the strength, the
    lubrication, the lash adjuster: :func:`driven_design`); the cam, the flow, the profile, the clearance and the
    law's records (:attr:`ValveDesign.geometry`, :func:`valve_geometry`) as they are.  Where the springs stay (the
    gas load below the line the inertia asks for), only the spring's record of its gas load changes.  The valve's
    ``[hydraulic]`` stage is not run (``valve`` without it: the caller adds it with its cylinder pressure).

    Raises
    ------
    SpecError
        No spring fits the new load; inputs that admit no design, each message naming the valve's keys.
    """
    geometry = design.geometry
    try:
        drive = drive_stage(valve, gas, geometry.cam, diagnose, gas_load)
    except NoSpringFits as exc:
        raise SpecError([Problem(f"valves.{design.name}.spring", said(exc))]) from None
    old = design.drive
    if (drive.lines, drive.masses, drive.checks) == (old.lines, old.masses, old.checks[:len(drive.checks)]) and \
            _same_springs(drive.spring, old.spring):
        return replace(design, drive=replace(old, spring=drive.spring))
    return driven_design(design.name, valve, engine, gas, output, geometry, drive, headlines_only=headlines_only)


def _same_springs(a, b) -> bool:
    """Two :class:`SpringResult` of the same springs: equal but for the gas load and where it comes from."""
    gas = ("preload_set_by_gas_force", "gas_force", "gas_force_source", "preload_set_by_seat_load")
    return replace(a, **{k: getattr(b, k) for k in gas}) == b


def _stage_problem(exc, prefix) -> Problem:
    """The :class:`Problem` of a stage's ``ValueError`` under the key ``prefix`` (``valves.NAME`` or a section of
    it): the stage's own :class:`Problem` (its key, value and message) where it raised one, else its text."""
    found = exc.args[0] if exc.args and isinstance(exc.args[0], Problem) else Problem("", said(exc))
    return found.within(prefix)


def with_hydraulic(design, valve, engine, gas, cylinder=None) -> ValveDesign:
    """The design with the hydraulic stage of the valve's ``[hydraulic]`` section (as it is without one) and, with its
    ``lost_motion`` section, the lost-motion stage (:func:`~valvetrain.design.lost_motion.lost_motion_stage`).

    Parameters
    ----------
    design : ValveDesign
    valve, engine, gas : SI views of the valve, the engine and ``[gas]``.
    cylinder : valvetrain.design.hydraulic_actuation.CylinderPressure, optional
        The engine's cycle (no gas force on the valve head without it).

    Raises
    ------
    SpecError
        A drive whose simulation asks for too much work, naming the key.
    """
    if valve.hydraulic is None:
        return design
    try:
        hydraulic, found = hydraulic_stage(valve, design.cam.law, engine, gas, design.name, design.cam.nose, cylinder)
        lost = None
        if valve.hydraulic.lost_motion is not None:
            lost, more = lost_motion_stage(valve, design.cam.law, engine, gas, design.name, design.cam.nose, hydraulic,
                                           cylinder)
            found = found + more
    except ValueError as exc:
        raise SpecError([_stage_problem(exc, f"valves.{design.name}.hydraulic")]) from None
    return replace(design, checks=design.checks + tuple(c.of_valve(design.name) for c in found), hydraulic=hydraulic,
                   lost_motion=lost)


__all__ = ["CamResult", "ClearanceResult", "FlowResult", "LiftTable", "ProfileResult", "StepRecord", "ValveDesign",
           "ValveGeometry", "clearance_stage", "design_valve", "driven_design", "flow_stage", "kinematic_stages",
           "law_stage", "profile_stage", "step_records", "valve_geometry", "with_gas_load", "with_hydraulic",
           "wrap_crank"]
