"""Valve stages of the design: flow sections, the lift law and its extremes, time-area and fullness,
the cam contour and curvature, and the recommended-range checks (seed 000 works 1-4, seed 002 section 2.1).

Crank angles in the results are measured from the gas-exchange TDC (the TDC that
starts the intake stroke) in (-360, 360]; camshaft angles from the cam nose.
"""

from dataclasses import dataclass, field

import numpy as np

from .. import flow, geometry
from ..checks import check, failed
from ..crank.kinematics import displacement
from ..laws import AsymmetricLaw, CombinedLaw, ConstantAccelerationLaw, DynamicLaw, HarmonicLaw, KurzLaw, PolydyneLaw, PolynomialLaw, TangentLaw, ThreeArcLaw
from ..numerics import extremum
from ..spec import SpecError, kurz_phi3_deg, main_half_angle_deg
from ..springs import NoSpringFits
from ..units import DEG, MM, rad_to_deg, rpm_to_rad_s
from ..files import read_lift_table
from ..laws.measured import CHECKING_HEIGHTS_MM, MIN_VALVE_LIFT_MM, TableLaw, lobe_table
from ..laws.takeup import ClearanceTakeUp
from .drive import drive_stage, reduced_mass

ACCELERATION_LIMITS = (3500.0, -1500.0)
"""Upper ends of the recommended bands of positive (1500-3500) and negative (500-1500) tappet
acceleration [m/s^2] (seed 000, work 2)."""

TIMING_RANGES = {"intake": ((20.0, 30.0), (40.0, 60.0))}
"""Recommended inlet opening advance and closing lag [crank deg] (seed 000, work 2)."""

CLEARANCE_RANGES = {"intake": (0.25, 0.35), "exhaust": (0.35, 0.50)}
"""Recommended valve clearance h0 [mm] (seed 000, work 2)."""

SEAT_ANGLE_USUAL = {"intake": (30.0, 30.0), "exhaust": (45.0, 45.0)}
"""Usual seat angles [deg] (seed 000, work 1)."""

ROCKER_RATIO_RANGE = (1.4, 1.75)
"""Recommended rocker ratio when not 1 (direct drive) (seed 000, work 2)."""

BASE_RADIUS_TO_LIFT_RANGE = (1.5, 4.0)
"""r0 / valve lift: 1.5-2.0 naturally aspirated, up to 3.0-4.0 supercharged (seed 000, work 2)."""

RHO_MIN_MM = 2.0
"""Smallest recommended radius of curvature of the cam profile [mm] (seed 002, section 2.1)."""

PRESSURE_ANGLE_MAX_DEG = 30.0
"""Largest recommended pressure angle of a roller follower [deg] (seed 004, via spec section 2)."""

SEATING_VELOCITY_MAX = 0.5
"""Working limit of the valve's seating velocity at rated speed [m/s] (no primary source; spec
methods-seeds-002-004.md, section 2: 0.3-0.5 m/s)."""

SEATING_VELOCITY_SOURCE = "spec/methods-seeds-002-004.md, section 2 (working guidance 0.3-0.5 m/s; seed 000, work 2)"

THROAT_AREA_SHARE_RANGE = (0.25, 0.40)
"""Inlet plus exhaust throat areas as a share of the piston area (seed 000, work 1)."""


@dataclass
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


@dataclass
class ValveDesign:
    """Everything computed for one valve (SI inside, engineering units in ``summary``)."""

    name: str
    kind: str
    law: object
    omega_cam: float
    rocker_ratio: float
    heel_radius: float
    follower: str
    roller_radius: float
    nose_crank: float              # crank angle of the nose [rad from gas-exchange TDC]
    stroke_window: tuple           # (start, end) camshaft angles of the valve's own stroke [rad]
    table: LiftTable
    contour: np.ndarray            # (2, n) [m], cam frame, nose on +y
    contour_angle: np.ndarray      # camshaft angle of each contour point [rad from the nose]
    summary: dict
    checks: list = field(default_factory=list)   # every valvetrain.checks.Check of the valve, passed or not
    drive: object = None           # DriveResults: masses, spring curves, strength

    @property
    def warnings(self):
        """The checks that fail."""
        return failed(self.checks)


def build_law(valve, strokes=4, rated_speed=None):
    """The lift law of a valve (see :func:`build_side`); an asymmetric cam joins two flanks at the nose."""
    closing = valve.cam.closing_cam() if hasattr(valve.cam, "closing_cam") else None
    if closing is None:
        return build_side(valve, strokes, rated_speed)
    opening = build_side(valve.model_copy(update={"cam": valve.cam.model_copy(update={"closing": None})}), strokes,
                         rated_speed)
    return AsymmetricLaw(opening, build_side(valve.model_copy(update={"cam": closing}), strokes, rated_speed))


def build_side(valve, strokes=4, rated_speed=None):
    """The lift law of a valve specification, in SI (tappet side).

    Laws with a ramp take up the clearance on it (ramp height = clearance); the arc cams
    (three-arc, tangent) and the polynomial laws without a ramp lift the valve lift plus the
    clearance from a heel circle of radius r0 - h0 and take the clearance up on their flanks
    (:class:`~valvetrain.laws.takeup.ClearanceTakeUp`), so that with any law the valve
    reaches ``max_lift_mm`` and starts to move at radius r0.
    The dynamic cam's ramp ends where the drive force reaches the preload; its design speed
    defaults to ``rated_speed`` [rpm] and its mass is the reduced mass at the valve without
    the spring (unless the masses give ``spring_kg``).
    """
    cam = valve.cam
    lift = valve.max_lift_mm / valve.rocker_ratio * MM if valve.max_lift_mm is not None else None
    half = main_half_angle_deg(valve, strokes) * DEG if valve.opens_deg is not None else None
    r0 = cam.base_radius_mm * MM
    h0 = valve.clearance_mm * MM
    ramp = {}
    if getattr(cam, "ramp_end_velocity_mm_per_deg", None) is not None:
        ramp = dict(ramp_kind=cam.ramp_type, ramp_fraction=cam.ramp_acceleration_fraction)
        velocity = cam.ramp_end_velocity_mm_per_deg * MM / DEG
    if cam.law == "kurz":
        return KurzLaw(lift, h0, velocity, cam.phi1_deg * DEG, cam.phi2_deg * DEG,
                       kurz_phi3_deg(cam, valve, strokes) * DEG, cam.shape_factor, **ramp)
    if cam.law == "constant_acceleration":
        return ConstantAccelerationLaw(lift, h0, velocity, cam.phi1_deg * DEG, cam.phi2_deg * DEG,
                                       kurz_phi3_deg(cam, valve, strokes) * DEG, cam.kappa, **ramp)
    if cam.law == "table":
        return table_law(valve)
    if cam.law == "harmonic":
        target = build_side(valve.model_copy(update={"cam": cam.target}), strokes, rated_speed)
        return HarmonicLaw(target, cam.harmonics, cam.junction_order)
    if cam.law == "dynamic":
        omega = rpm_to_rad_s(cam.design_speed_rpm or rated_speed) / 2.0
        mass = reduced_mass(valve, float(flow.circle_area(valve.throat_diameter_mm * MM)), 0.0)[0]
        return DynamicLaw(valve.max_lift_mm * MM, half, cam.exponents, cam.valve_opening_velocity_m_s / omega,
                          cam.drive_stiffness_N_per_mm / MM, mass, cam.spring_rate_N_per_mm / MM, cam.spring_preload_N,
                          omega, valve.rocker_ratio, valve.clearance_mm * MM * valve.rocker_ratio, cam.ramp_type,
                          cam.ramp_acceleration_fraction)
    if cam.law == "combined":
        return CombinedLaw(lift, h0, velocity, [(seg.shape, seg.length_deg * DEG) for seg in cam.segments],
                           [(r.segment - 1, r.value) for r in cam.ratios], **ramp)
    if getattr(cam, "ramp", False):
        ramp.update(ramp_height=h0, ramp_velocity=velocity)
        return _rampless(cam, lift, half, r0, **ramp)
    if h0 == 0.0:
        return _rampless(cam, lift, half, r0)
    # no ramp: the flanks take up the clearance; the heel circle lies h0 below r0 as with a ramp
    return ClearanceTakeUp(_rampless(cam, lift + h0, half, r0 - h0), h0)


def _rampless(cam, lift, half, r0, **ramp):
    """Polydyne, polynomial and arc cams of a lift above their base circle of radius r0 [m]."""
    if cam.law == "polydyne":
        return PolydyneLaw(lift, half, cam.p, cam.q, cam.r, cam.s, **ramp)
    if cam.law == "polynomial":
        return PolynomialLaw(lift, half, cam.exponents, **ramp)
    if cam.law == "three_arc":
        if cam.nose_radius_mm is not None:
            return ThreeArcLaw(r0, lift, half, cam.nose_radius_mm * MM)
        if cam.flank_radius_mm is not None:
            return ThreeArcLaw.from_flank_radius(r0, lift, half, cam.flank_radius_mm * MM)
        return ThreeArcLaw.from_flank_angle(r0, lift, half, cam.flank_angle_deg * DEG)
    return TangentLaw(r0, lift, half, cam.roller_radius_mm * MM)


def table_law(valve):
    """The law of a measured table (seed 002, sections 5.1-5.3), checked as one lobe of this valve.

    A table of valve lift is divided by the rocker ratio; a table of tappet lift is the cam's lift with its ramps,
    and the valve moves once the clearance is taken up.  The table sets the lift: a ``max_lift_mm`` given beside
    it must agree with it to 1 %.  The lobe must open the valve during the valve's own stroke.

    Raises
    ------
    ValueError
        ``"<table file>: <what is wrong, the value, what is allowed>"``.
    """
    cam = valve.cam
    angle, lift = read_lift_table(cam.table_file)      # its errors name the file and the line
    try:
        return _checked_table_law(valve, angle, lift)
    except ValueError as exc:
        raise ValueError(f"{cam.table_file}: {exc}") from None


def _checked_table_law(valve, angle, lift):
    cam, i_k = valve.cam, valve.rocker_ratio
    at_valve = cam.table_lift_at == "valve"
    clearance = 0.0 if at_valve else valve.clearance_mm
    least = MIN_VALVE_LIFT_MM / (1.0 if at_valve else i_k) + clearance
    theta, lift, per_point = lobe_table(angle, lift, cam.table_angle, cam.table_zero, cam.accuracy_mm, least)
    to_tappet = MM / (i_k if at_valve else 1.0)
    law = TableLaw(theta, lift * to_tappet, cam.fit, cam.accuracy_mm * to_tappet, cam.max_harmonics,
                   clearance * MM, per_point)
    table_lift = law.lift_max * i_k / MM
    if valve.max_lift_mm is not None and abs(valve.max_lift_mm - table_lift) > 0.01 * table_lift:
        raise ValueError(f"max_lift_mm = {valve.max_lift_mm:g} disagrees with the table's valve lift {table_lift:.4g} "
                         f"mm; allowed {0.99 * table_lift:.4g}...{1.01 * table_lift:.4g} mm (+-1 %), or leave it out: "
                         "the table sets the lift")
    nose = valve_nose(valve, law)
    lo, hi = (0.0, 180.0) if valve.kind == "intake" else (-180.0, 0.0)
    opens, closes = (rad_to_deg(nose + 2.0 * t) for t in (law.valve_opens, law.valve_closes))
    if closes <= lo or opens >= hi:
        raise ValueError(f"the lobe opens the valve from {opens:.4g} to {closes:.4g} crank deg after the "
                         f"gas-exchange TDC and misses the {valve.kind} stroke, {lo:g}...{hi:g} crank deg; check "
                         "table_angle and table_zero (a table from the firing TDC needs table_zero = \"firing_tdc\")")
    return law


def valve_nose(valve, law):
    """Crank angle of the cam nose [rad]: from the measured table when the law carries its timing, else from
    opens_deg/closes_deg."""
    centre = getattr(law, "nose_cam_angle", None)
    if centre is not None:
        return 2.0 * centre
    if isinstance(law, AsymmetricLaw):  # the main lift starts where the specification says, the nose follows it
        start = -valve.opens_deg * DEG if valve.kind == "intake" else (-180.0 - valve.opens_deg) * DEG
        return start + 2.0 * law.main_half_angle
    return nose_crank_angle(valve)


def measured_summary(valve, law, nose):
    """The measured-table record of results.json and its timing findings (seed 002, sections 5.1-5.3)."""
    cam = valve.cam
    to_table = 2.0 if cam.table_angle == "crank" else 1.0        # table angle units per cam angle
    at_valve = valve.rocker_ratio if cam.table_lift_at == "valve" else 1.0
    durations = [{"height_mm": h, "duration_deg": _finite(rad_to_deg(law.duration(h * MM / at_valve)) * to_table)}
                 for h in CHECKING_HEIGHTS_MM]
    quality = {kind: {"rms_residual_mm": q.rms_residual / MM, "max_residual_mm": q.max_residual / MM,
                      "jerk_sign_changes": q.jerk_sign_changes}
               for kind in ("spline", "harmonic") for q in [law.quality(kind)]}
    rec = {"max_lift_mm": (law.lift_max + law.ramp_height) * at_valve / MM,
           "lobe_centre_deg": rad_to_deg(law.centre) * to_table, "durations_deg": durations, "fit": law.fit,
           "harmonics": law.harmonics, "asymmetry_rms_mm": law.asymmetry_rms * at_valve / MM, "fit_quality": quality,
           "table_angle": cam.table_angle, "table_lift_at": cam.table_lift_at, "table_zero": cam.table_zero}
    # the timing the table implies, where the valve lift crosses the first checking height (0.1 mm)
    rise, fall = law.crossings(law.ramp_height + CHECKING_HEIGHTS_MM[0] * MM / valve.rocker_ratio)
    opens = -(nose + 2.0 * rise) if valve.kind == "intake" else -np.pi - (nose + 2.0 * rise)
    closes = (nose + 2.0 * fall) - (np.pi if valve.kind == "intake" else 0.0)
    rec["opens_deg_at_0.1mm"], rec["closes_deg_at_0.1mm"] = _finite(rad_to_deg(opens)), _finite(rad_to_deg(closes))
    found = []
    for key, derived in (("opens_deg", rec["opens_deg_at_0.1mm"]), ("closes_deg", rec["closes_deg_at_0.1mm"])):
        given = getattr(valve, key)
        if given is not None and derived is not None:
            found.append(check(f"{key} against the measured table", given * DEG, (derived - 2.0) * DEG,
                               (derived + 2.0) * DEG, source="the table's timing at 0.1 mm valve lift (+-2 crank deg)",
                               unit="crank deg"))
    return rec, found


def _finite(x):
    """A float, or None where it is not defined (a checking height the lift never reaches)."""
    return float(x) if np.isfinite(x) else None


def nose_crank_angle(valve):
    """Crank angle of the cam nose from gas-exchange TDC [rad] (four-stroke).

    Intake: the main lift opens ``opens_deg`` before TDC (crank 0) and closes
    ``closes_deg`` after BDC (crank 180).  Exhaust: opens ``opens_deg`` before BDC
    (crank -180) and closes ``closes_deg`` after TDC (crank 0).
    """
    if valve.kind == "intake":
        return (180.0 + valve.closes_deg - valve.opens_deg) / 2.0 * DEG
    return (valve.closes_deg - 180.0 - valve.opens_deg) / 2.0 * DEG


def _table_grid(law, step):
    k = np.arange(np.ceil(law.start / step), np.floor(law.end / step) + 1) * step
    return np.unique(np.concatenate([[law.start], k, [law.end]]))


def _profile(law, theta, heel, follower, roller_radius):
    """Contour, profile radius of curvature, pressure angle and contact offset at camshaft angles theta.

    Flat follower: pressure angle zero, contact offset h'.  Roller follower: contact
    offset zero (the contact lies on the roller), pressure angle from the pitch curve.
    """
    h, dh, d2h, _ = law.derivatives(theta)
    if follower == "flat":
        xy = geometry.flat_follower_contour(theta, heel, h, dh)
        rho = geometry.flat_follower_curvature(heel, h, d2h)
        return xy, rho, np.zeros_like(theta), dh
    xy = geometry.roller_follower_contour(theta, heel, roller_radius, h, dh)
    rho = geometry.roller_follower_curvature(heel, roller_radius, h, dh, d2h)
    return xy, rho, geometry.roller_pressure_angle(heel, roller_radius, h, dh), np.zeros_like(theta)


def contour_points(law, theta, heel, follower, roller_radius):
    """Cam contour points at camshaft angles theta [m], shape (2, n) (seed 002, eqs. 2.15-2.16)."""
    return _profile(law, theta, heel, follower, roller_radius)[0]


def _convex_radius(law, theta, heel, follower, roller_radius):
    """Profile radius of curvature where the profile is convex, +inf where it is concave.

    A concave stretch (possible with a roller follower) is not an undercut; its radius
    is reported on its own.
    """
    rho = _profile(law, theta, heel, follower, roller_radius)[1]
    if follower == "flat":
        return rho
    return np.where(rho + roller_radius > 0.0, rho, np.inf)


def design_valve(name, v, spec):
    """Stages 1-5 of one valve and its drive (springs, strength); returns a :class:`ValveDesign`."""
    eng = spec.engine
    law = build_law(v, eng.strokes, eng.rated_speed_rpm)
    omega = rpm_to_rad_s(eng.rated_speed_rpm) / 2.0
    cam = v.cam
    heel = cam.base_radius_mm * MM - law.ramp_height
    roller = (cam.roller_radius_mm or 0.0) * MM
    i_k = v.rocker_ratio
    d_throat, seat = v.throat_diameter_mm * MM, v.seat_angle_deg * DEG
    bore, stroke = eng.bore_mm * MM, eng.stroke_mm * MM
    nose = valve_nose(v, law)

    def valve_lift(theta):
        return law.valve_lift(theta, i_k)

    def area(theta):
        return flow.curtain_area(valve_lift(theta), d_throat, seat)

    # 1. flow sections
    c_p = flow.mean_piston_speed(stroke, eng.rated_speed_rpm)
    swept = float(flow.swept_volume(bore, stroke))
    lift_valve = law.lift_max * i_k
    f_max = float(flow.curtain_area(lift_valve, d_throat, seat))
    v1 = flow.throat_velocity(c_p, bore, d_throat, v.count)
    v2 = flow.curtain_velocity(c_p, bore, f_max, v.count)

    # 2. extremes of the law (follower side) and the valve's velocity as it leaves and meets its seat
    ext = law.extremes(omega)
    seat_velocity = i_k * omega * np.abs(law.derivatives(np.array([law.valve_opens, law.valve_closes]))[1])

    # 3. time-area over the valve's own stroke and over the whole opening
    stroke_crank = (0.0, np.pi) if v.kind == "intake" else (-np.pi, 0.0)
    window = tuple((c - nose) / 2.0 for c in stroke_crank)
    bp = law.breakpoints
    ta_stroke = flow.time_area(area, window[0], window[1], omega, bp)
    ta_open = flow.time_area(area, law.valve_opens, law.valve_closes, omega, bp)
    v3 = flow.time_area_velocity(swept, ta_stroke, v.count)
    v_charge = flow.mean_charge_velocity(swept, ta_stroke, v.count)
    xi = flow.fullness(valve_lift, law.valve_opens, law.valve_closes, lift_valve, bp)

    # 4. the lift table
    theta = _table_grid(law, spec.output.table_step_cam_deg * DEG)
    d = law.derivatives(theta)
    xy, rho, beta, offset = _profile(law, theta, heel, cam.follower, roller)
    table = LiftTable(
        cam_angle=theta, crank_angle=wrap_crank(nose + 2.0 * theta), segment=law.segment_names(theta),
        lift=d[0], velocity=omega * d[1], acceleration=omega**2 * d[2], jerk=omega**3 * d[3],
        valve_lift=valve_lift(theta), curtain_area=area(theta),
        time_area=flow.cumulative_time_area(area, theta, omega, bp), rho=rho, pressure_angle=beta,
        contact_offset=offset,
    )

    # 5. contour over a whole camshaft revolution and the profile extremes
    n = spec.output.contour_points
    ctheta = np.unique(np.concatenate([np.linspace(-np.pi, np.pi, n, endpoint=False), bp]))
    contour = _profile(law, ctheta, heel, cam.follower, roller)[0]

    def convex(t):
        return _convex_radius(law, t, heel, cam.follower, roller)

    # the base circle (radius = heel radius for both followers) closes the profile
    x_min, rho_min = min(extremum(convex, bp, "min"), (np.pi, heel), key=lambda p: p[1])
    x_max, rho_max = max(extremum(lambda t: np.where(np.isinf(convex(t)), -np.inf, convex(t)), bp, "max"),
                         (np.pi, heel), key=lambda p: p[1])
    straight = bool(np.any(np.isposinf(rho)))   # rho of the table grid above
    if straight:  # straight flanks (tangent cam): the largest radius is infinite
        x_max, rho_max = None, None

    summary_cam = {
        "law": law.name,
        "source": law.source,
        "coefficients": law.coefficients(),
        "max_velocity_m_s": ext.max_velocity,
        "max_acceleration_m_s2": ext.max_acceleration,
        "min_acceleration_m_s2": ext.min_acceleration,
        "rho_min_mm": rho_min / MM,
        "rho_max_mm": None if straight else rho_max / MM,
        "rho_min_cam_deg": rad_to_deg(x_min),
        "rho_max_cam_deg": None if straight else rad_to_deg(x_max),
        "straight_flanks": straight,
        "phi_p0_deg": rad_to_deg(law.main_half_angle),
        "ramp_deg": rad_to_deg(law.ramp_angle),
        "ramp_height_mm": law.ramp_height / MM,
        "tappet_lift_mm": law.lift_max / MM,
        "valve_opening_velocity_m_s": seat_velocity[0],
        "valve_seating_velocity_m_s": seat_velocity[1],
        "event_cam_deg": rad_to_deg(law.end - law.start),
        "nose_crank_deg": rad_to_deg(nose),
        "camshaft_speed_rad_s": omega,
        "follower": cam.follower,
        "base_radius_mm": cam.base_radius_mm,
        "heel_radius_mm": heel / MM,
    }
    if isinstance(law, KurzLaw):
        sf = law.seed_formulas(cam.base_radius_mm * MM, omega)
        summary_cam["seed_formulas"] = {
            "max_velocity_m_s": sf["max_velocity"], "max_acceleration_m_s2": sf["max_acceleration"],
            "min_acceleration_m_s2": sf["min_acceleration"], "rho_min_mm": sf["rho_min"] / MM,
            "rho_max_mm": sf["rho_max"] / MM,
        }
        summary_cam["residuals"] = law.residuals()
    if cam.follower == "flat":
        summary_cam["max_contact_offset_mm"] = ext.max_velocity / omega / MM
    else:
        beta_max = extremum(lambda t: np.abs(_profile(law, t, heel, "roller", roller)[2]), bp, "max")[1]
        concave = extremum(lambda t: _profile(law, t, heel, "roller", roller)[1], bp, "min")[1]
        summary_cam["roller_radius_mm"] = roller / MM
        summary_cam["max_pressure_angle_deg"] = rad_to_deg(beta_max)
        summary_cam["min_concave_radius_mm"] = concave / MM if concave + roller < 0.0 else None

    summary_flow = {
        "throat_area_mm2": float(flow.circle_area(d_throat)) / MM**2,
        "max_curtain_area_mm2": f_max / MM**2,
        "V1_m_s": v1, "V2_m_s": v2, "V3_m_s": v3,
        "time_area_mm2_s": ta_stroke / MM**2,
        "time_area_open_mm2_s": ta_open / MM**2,
        "mean_charge_velocity_m_s": v_charge,
        "fullness": xi,
        "valve_lift_mm": lift_valve / MM,
        "stroke_crank_deg": [rad_to_deg(a) for a in stroke_crank],
    }
    summary = {"kind": v.kind, "count": v.count, "rocker_ratio": i_k, "cam": summary_cam, "flow": summary_flow}

    found = law.checks()
    found += flow.check_flow(v.kind, bore=bore, throat_diameter=d_throat, max_lift=lift_valve, v1=v1, v2=v2,
                             v3=v3, charge_velocity=v_charge, engine_type=eng.type, chamber=eng.chamber,
                             count=v.count)
    found.append(check("max tappet acceleration", ext.max_acceleration, high=ACCELERATION_LIMITS[0],
                       source="seed 000, work 2 (positive 1500...3500 m/s2)", unit="m/s2"))
    found.append(check("min tappet acceleration", ext.min_acceleration, low=ACCELERATION_LIMITS[1],
                       source="seed 000, work 2 (negative 500...1500 m/s2)", unit="m/s2"))
    opens, closes = v.opens_deg, v.closes_deg
    if isinstance(law, TableLaw):
        summary_cam["measured"], table_found = measured_summary(v, law, nose)
        found += table_found
        opens, closes = summary_cam["measured"]["opens_deg_at_0.1mm"], summary_cam["measured"]["closes_deg_at_0.1mm"]
    if v.kind in TIMING_RANGES:
        (o_lo, o_hi), (c_lo, c_hi) = TIMING_RANGES[v.kind]
        for label, angle, lo, hi in (("opening advance", opens, o_lo, o_hi), ("closing lag", closes, c_lo, c_hi)):
            if angle is not None:
                found.append(check(label, angle * DEG, lo * DEG, hi * DEG, source="seed 000, work 2", unit="crank deg"))
    if isinstance(law, ClearanceTakeUp):
        found.append(check("clearance taken up without a ramp: valve seating velocity", seat_velocity[1],
                           high=SEATING_VELOCITY_MAX, source=SEATING_VELOCITY_SOURCE, unit="m/s",
                           note=f"no ramp takes up clearance_mm = {v.clearance_mm:g}: the flank does"))
    found.append(check("seat angle", v.seat_angle_deg * DEG, *(a * DEG for a in SEAT_ANGLE_USUAL[v.kind]),
                       source="seed 000, work 1 (usually 30 deg inlet, 45 deg exhaust)", unit="deg"))
    found.append(check("clearance h0", v.clearance_mm * MM, *(c * MM for c in CLEARANCE_RANGES[v.kind]),
                       source="seed 000, work 2", unit="mm"))
    if i_k != 1.0:
        found.append(check("rocker ratio", i_k, *ROCKER_RATIO_RANGE, source="seed 000, work 2 (or 1, direct drive)"))
    found.append(check("base radius r0 / valve lift", cam.base_radius_mm * MM / lift_valve,
                       *BASE_RADIUS_TO_LIFT_RANGE, source="seed 000, work 2 (1.5-2.0; supercharged 3.0-4.0)"))
    if cam.follower == "flat":
        undercut = rho_min <= 0.0
        if undercut:
            found.append(check("cam profile undercut: rho_min (flat follower)", rho_min, low=0.0, strict_low=True,
                               source="seed 002, eq. (2.6); seed 000, E26", unit="mm", severity="failure"))
    else:
        pitch = rho + roller
        undercut = bool(np.any(geometry.undercut_roller(pitch, roller)))
        if undercut:
            found.append(check("cam profile undercut: pitch radius of curvature - roller radius", rho_min, low=0.0,
                               strict_low=True, source="seed 002, eq. (2.7)", unit="mm", severity="failure"))
        found.append(check("max pressure angle", summary_cam["max_pressure_angle_deg"] * DEG,
                           high=PRESSURE_ANGLE_MAX_DEG * DEG, source="seed 004 (spec section 2)", unit="deg"))
    if not undercut:
        found.append(check("rho_min (cam profile)", rho_min, low=RHO_MIN_MM * MM, source="seed 002, section 2.1",
                           unit="mm"))
    summary_cam["undercut"] = bool(undercut)

    if v.piston_gap_tdc_mm is not None:
        crank = nose + 2.0 * np.linspace(law.valve_opens, law.valve_closes, 2001)
        s = displacement(crank, stroke / 2.0, stroke / 2.0 / (eng.rod_length_mm * MM))
        gap = geometry.valve_piston_clearance(s, valve_lift((crank - nose) / 2.0), v.piston_gap_tdc_mm * MM)
        i = int(np.argmin(gap))
        summary["piston_clearance"] = {"min_clearance_mm": gap[i] / MM, "crank_deg": rad_to_deg(wrap_crank(crank[i]))}
        if gap[i] <= 0.0:
            raise SpecError([f"valves.{name}: the valve hits the piston: the valve-piston gap falls to "
                             f"{gap[i] / MM:.4g} mm at {rad_to_deg(wrap_crank(crank[i])):.4g} crank deg (seed 002, eqs. "
                             f"2.13-2.14, with piston_gap_tdc_mm = {v.piston_gap_tdc_mm:g}); allowed a gap > 0: lower "
                             "the lift near TDC or deepen the valve pocket"])

    try:
        drive = drive_stage(v, spec, law, omega, heel, roller)
    except NoSpringFits as exc:
        raise SpecError([f"valves.{name}.spring: {exc}"]) from None
    summary["masses"] = drive.masses
    summary["spring"] = drive.spring
    summary["strength"] = {k: rec for k, rec in drive.strength.items()}
    found += drive.checks

    found = [c.named(name) for c in found]
    return ValveDesign(name, v.kind, law, omega, i_k, heel, cam.follower, roller, nose, window, table, contour,
                       ctheta, summary, found, drive)


def wrap_crank(a):
    """Crank angle wrapped into (-360, 360] deg (in rad)."""
    return np.where(a > 2 * np.pi, a - 4 * np.pi, np.where(a <= -2 * np.pi, a + 4 * np.pi, a))
