"""Orchestration: ``run(spec) -> DesignResults``, the chain of stages of a valve-lift design.

This is the one place where the specification's engineering units (mm, deg, rpm) are
converted to SI for the physics functions.  Stages per valve:

1. flow sections and conditional velocities V', V'' (seed 000, work 1);
2. the cam lift law and its extremes (works 2-3);
3. time-area, V''', mean charge velocity, fullness (work 1 eq. 1.4, work 4; seed 002 eq. 2.3);
4. cam contour, curvature, pressure angle, undercut, valve-piston clearance (seed 002, section 2.1);
5. recommended-range checks of every stage (warnings, never exceptions).

Crank angles in the results are measured from the gas-exchange TDC (the TDC that
starts the intake stroke) in (-360, 360]; camshaft angles from the cam nose.
"""

from dataclasses import dataclass, field

import numpy as np

from . import flow, geometry, masses, springs, strength
from .checks import Finding, check_range
from .crank.kinematics import piston_displacement
from .laws import KurzLaw, PolydyneLaw
from .numerics import extremum
from .spec import KurzCam, kurz_phi3_deg, main_half_angle_deg
from .units import DEG, MM, MPA, rad_to_deg, rpm_to_rad_s

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
    warnings: list = field(default_factory=list)
    drive: object = None           # DriveResults: masses, spring curves, strength


@dataclass
class DriveResults:
    """Springs and strength of one valve: the JSON records and the curves for the report (SI)."""

    masses: dict
    spring: dict
    strength: dict
    warnings: list
    lift: np.ndarray               # valve lift along the open event [m]
    inertia_force: np.ndarray      # m_v |j_v| where j_v < 0 [N]
    required_force: np.ndarray     # K_z m_v |j_v| [N]
    lines: dict                    # name -> springs.Characteristic (required, chosen, outer, inner)


@dataclass
class DesignResults:
    """Result of :func:`run`: the engine's derived figures, each valve's design, all warnings."""

    spec: object
    engine: dict
    valves: dict
    warnings: list

    def to_dict(self):
        """JSON-ready dictionary (engineering units, named in the keys)."""
        from . import __version__

        return {
            "valvetrain_version": __version__,
            "engine": self.engine,
            "valves": {name: v.summary for name, v in self.valves.items()},
            "warnings": [w.as_dict() for w in self.warnings],
        }


def build_law(valve, strokes=4):
    """The lift law of a valve specification, in SI (tappet side)."""
    cam = valve.cam
    lift = valve.max_lift_mm / valve.rocker_ratio * MM
    if isinstance(cam, KurzCam):
        phi3 = kurz_phi3_deg(cam, valve, strokes)
        return KurzLaw(lift, valve.clearance_mm * MM, cam.ramp_end_velocity_mm_per_deg * MM / DEG,
                       cam.phi1_deg * DEG, cam.phi2_deg * DEG, phi3 * DEG, cam.shape_factor)
    ramp_height = valve.clearance_mm * MM if cam.ramp else 0.0
    ramp_velocity = cam.ramp_end_velocity_mm_per_deg * MM / DEG if cam.ramp else 0.0
    return PolydyneLaw(lift, main_half_angle_deg(valve, strokes) * DEG, cam.p, cam.q, cam.r, cam.s,
                       ramp_height=ramp_height, ramp_velocity=ramp_velocity)


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


def _convex_radius(law, theta, heel, follower, roller_radius):
    """Profile radius of curvature where the profile is convex, +inf where it is concave.

    A concave stretch (possible with a roller follower) is not an undercut; its radius
    is reported on its own.
    """
    rho = _profile(law, theta, heel, follower, roller_radius)[1]
    if follower == "flat":
        return rho
    return np.where(rho + roller_radius > 0.0, rho, np.inf)


def _design_valve(name, v, spec):
    eng = spec.engine
    law = build_law(v, eng.strokes)
    omega = rpm_to_rad_s(eng.rated_speed_rpm) / 2.0
    cam = v.cam
    heel = cam.base_radius_mm * MM - law.ramp_height
    roller = (cam.roller_radius_mm or 0.0) * MM
    i_k = v.rocker_ratio
    d_throat, seat = v.throat_diameter_mm * MM, v.seat_angle_deg * DEG
    bore, stroke = eng.bore_mm * MM, eng.stroke_mm * MM
    nose = nose_crank_angle(v)

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

    # 2. extremes of the law (follower side)
    ext = law.extremes(omega)

    # 3. time-area over the valve's own stroke and over the whole opening
    stroke_crank = (0.0, np.pi) if v.kind == "intake" else (-np.pi, 0.0)
    window = tuple((c - nose) / 2.0 for c in stroke_crank)
    bp = law.breakpoints
    ta_stroke = flow.time_area(area, window[0], window[1], omega, bp)
    ta_open = flow.time_area(area, law.valve_opens, law.valve_closes, omega, bp)
    v3 = flow.time_area_velocity(swept, ta_stroke, v.count)
    v_charge = flow.mean_charge_velocity(swept, ta_stroke)
    xi = flow.fullness(valve_lift, law.valve_opens, law.valve_closes, lift_valve, bp)

    # 4. the lift table
    theta = _table_grid(law, spec.output.table_step_cam_deg * DEG)
    d = law.derivatives(theta)
    xy, rho, beta, offset = _profile(law, theta, heel, cam.follower, roller)
    table = LiftTable(
        cam_angle=theta, crank_angle=_wrap_crank(nose + 2.0 * theta), segment=law.segment_names(theta),
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

    summary_cam = {
        "law": law.name,
        "coefficients": law.coefficients(),
        "max_velocity_m_s": ext.max_velocity,
        "max_acceleration_m_s2": ext.max_acceleration,
        "min_acceleration_m_s2": ext.min_acceleration,
        "rho_min_mm": rho_min / MM,
        "rho_max_mm": rho_max / MM,
        "rho_min_cam_deg": rad_to_deg(x_min),
        "rho_max_cam_deg": rad_to_deg(x_max),
        "phi_p0_deg": rad_to_deg(law.main_half_angle),
        "ramp_deg": rad_to_deg(law.ramp_angle),
        "ramp_height_mm": law.ramp_height / MM,
        "tappet_lift_mm": law.lift_max / MM,
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
                             v3=v3, charge_velocity=v_charge, engine_type=eng.type, chamber=eng.chamber)
    found += check_range("max tappet acceleration", ext.max_acceleration, high=ACCELERATION_LIMITS[0],
                         source="seed 000, work 2 (positive 1500...3500 m/s2)", unit="m/s2")
    found += check_range("min tappet acceleration", ext.min_acceleration, low=ACCELERATION_LIMITS[1],
                         source="seed 000, work 2 (negative 500...1500 m/s2)", unit="m/s2")
    if v.kind in TIMING_RANGES:
        (o_lo, o_hi), (c_lo, c_hi) = TIMING_RANGES[v.kind]
        found += check_range("opening advance", v.opens_deg, o_lo, o_hi, source="seed 000, work 2", unit="crank deg")
        found += check_range("closing lag", v.closes_deg, c_lo, c_hi, source="seed 000, work 2", unit="crank deg")
    found += check_range("seat angle", v.seat_angle_deg, *SEAT_ANGLE_USUAL[v.kind],
                         source="seed 000, work 1 (usually 30 deg inlet, 45 deg exhaust)", unit="deg")
    found += check_range("clearance h0", v.clearance_mm, *CLEARANCE_RANGES[v.kind], source="seed 000, work 2",
                         unit="mm")
    if i_k != 1.0:
        found += check_range("rocker ratio", i_k, *ROCKER_RATIO_RANGE, source="seed 000, work 2 (or 1, direct drive)")
    found += check_range("base radius r0 / valve lift", cam.base_radius_mm / v.max_lift_mm,
                         *BASE_RADIUS_TO_LIFT_RANGE, source="seed 000, work 2 (1.5-2.0; supercharged 3.0-4.0)")
    if cam.follower == "flat":
        undercut = rho_min <= 0.0
        if undercut:
            found += check_range("cam profile undercut: rho_min (flat follower)", rho_min / MM, low=0.0,
                                 strict_low=True, source="seed 002, eq. (2.6); seed 000, E26", unit="mm")
    else:
        pitch = rho + roller
        undercut = bool(np.any(geometry.undercut_roller(pitch, roller)))
        if undercut:
            found += check_range("cam profile undercut: pitch radius of curvature - roller radius", rho_min / MM,
                                 low=0.0, strict_low=True, source="seed 002, eq. (2.7)", unit="mm")
        found += check_range("max pressure angle", summary_cam["max_pressure_angle_deg"],
                             high=PRESSURE_ANGLE_MAX_DEG, source="seed 004 (spec section 2)", unit="deg")
    if not undercut:
        found += check_range("rho_min (cam profile)", rho_min / MM, low=RHO_MIN_MM, source="seed 002, section 2.1",
                             unit="mm")
    summary_cam["undercut"] = bool(undercut)

    if v.piston_gap_tdc_mm is not None:
        crank = nose + 2.0 * np.linspace(law.valve_opens, law.valve_closes, 2001)
        s = piston_displacement(crank, stroke / 2.0, eng.rod_length_mm * MM)
        gap = geometry.valve_piston_clearance(s, valve_lift((crank - nose) / 2.0), v.piston_gap_tdc_mm * MM)
        i = int(np.argmin(gap))
        summary["piston_clearance"] = {"min_clearance_mm": gap[i] / MM, "crank_deg": rad_to_deg(_wrap_crank(crank[i]))}
        found += check_range("valve-piston clearance", gap[i] / MM, low=0.0, strict_low=True,
                             source="seed 002, eqs. (2.13)-(2.14)", unit="mm")

    drive = _drive(v, spec, law, omega, heel, roller)
    summary["masses"] = drive.masses
    summary["spring"] = drive.spring
    summary["strength"] = {k: rec for k, rec in drive.strength.items()}
    found += drive.warnings

    found = [Finding(f"{name}: {f.quantity}", f.value, f.range, f.source, f.unit) for f in found]
    return ValveDesign(name, v.kind, law, omega, i_k, heel, cam.follower, roller, nose, window, table, contour,
                       ctheta, summary, found, drive)


def _wrap_crank(a):
    """Crank angle wrapped into (-360, 360] deg (in rad)."""
    return np.where(a > 2 * np.pi, a - 4 * np.pi, np.where(a <= -2 * np.pi, a + 4 * np.pi, a))


def run(spec):
    """Run the whole design of a validated specification.

    Parameters
    ----------
    spec : valvetrain.spec.Spec

    Returns
    -------
    DesignResults
    """
    eng = spec.engine
    bore, stroke = eng.bore_mm * MM, eng.stroke_mm * MM
    valves = {name: _design_valve(name, v, spec) for name, v in spec.valves.items()}
    found = [f for v in valves.values() for f in v.warnings]
    kinds = {v.kind for v in spec.valves.values()}
    if kinds == {"intake", "exhaust"}:
        share = sum(v.count * float(flow.circle_area(v.throat_diameter_mm * MM)) for v in spec.valves.values())
        found += check_range("sum of throat areas / piston area", share / float(flow.circle_area(bore)),
                             *THROAT_AREA_SHARE_RANGE, source="seed 000, work 1")
    engine = {
        "name": eng.name,
        "bore_mm": eng.bore_mm,
        "stroke_mm": eng.stroke_mm,
        "rated_speed_rpm": eng.rated_speed_rpm,
        "cylinders": eng.cylinders,
        "strokes": eng.strokes,
        "mean_piston_speed_m_s": flow.mean_piston_speed(stroke, eng.rated_speed_rpm),
        "swept_volume_cm3": float(flow.swept_volume(bore, stroke)) * 1e6,
        "displacement_cm3": float(flow.swept_volume(bore, stroke)) * 1e6 * eng.cylinders,
        "piston_area_mm2": float(flow.circle_area(bore)) / MM**2,
    }
    return DesignResults(spec, engine, valves, found)


def _reduced_mass(v, throat_area, spring_mass_kg):
    """Reduced mass at the valve [kg] and a description of how it was obtained."""
    d = v.drive
    if d.masses is not None:
        m = d.masses
        spring = m.spring_kg if m.spring_kg is not None else spring_mass_kg
        arm = (d.valve_arm_mm or 1.0) * MM
        value = masses.reduced_mass_at_valve(m.valve_kg, m.retainer_kg, m.cotters_kg, spring, m.pushrod_kg,
                                             m.tappet_kg, m.rocker_inertia_kg_mm2 * MM**2, arm, v.rocker_ratio)
        source = "part masses, seed 000 eq. (5.2)" + ("" if m.spring_kg is not None else "; spring mass of the design")
        return value, source
    specific = d.specific_mass_kg_m2 or masses.SPECIFIC_MASS_DEFAULT[v.layout]
    given = "given" if d.specific_mass_kg_m2 else f"default for a {v.layout} drive"
    return masses.mass_from_specific(specific, throat_area), f"specific mass {specific:g} kg/m2 ({given}), seed 000 work 5"


def _material(sp):
    return springs.SpringMaterial(
        shear_modulus=sp.shear_modulus_MPa * MPA, density=sp.density_kg_m3, allowable_stress=sp.allowable_stress_MPa * MPA,
        endurance_limit=sp.endurance_limit_MPa * MPA, mean_stress_factor=sp.mean_stress_factor,
        min_safety=sp.min_safety_factor, min_resonance_ratio=sp.min_resonance_ratio, gap_factor=sp.coil_gap_factor)


def _spring_record(s):
    """results.json record of one designed spring (engineering units)."""
    c = s.characteristic
    return {
        "preload_N": c.preload, "max_force_N": c.max_force, "rate_N_per_mm": c.rate * MM,
        "wire_mm": s.wire_diameter / MM, "mean_diameter_mm": s.mean_diameter / MM,
        "outer_diameter_mm": (s.mean_diameter + s.wire_diameter) / MM, "active_coils": s.coils,
        "total_coils": s.coils + 2.0, "free_length_mm": s.lengths["free_length"] / MM,
        "installed_length_mm": s.lengths["installed_length"] / MM, "min_length_mm": s.lengths["min_length"] / MM,
        "min_pitch_mm": s.lengths["min_pitch"] / MM, "installed_pitch_mm": s.lengths["installed_pitch"] / MM,
        "free_pitch_mm": s.lengths["free_pitch"] / MM, "preload_deflection_mm": c.preload_deflection / MM,
        "max_deflection_mm": c.max_deflection / MM, "spring_index": s.mean_diameter / s.wire_diameter,
        "shape_factor": s.shape_factor, "wahl_factor": s.wahl, "tau_max_MPa": s.tau_max / MPA,
        "tau_min_MPa": s.tau_min / MPA, "safety_factor": s.safety, "natural_frequency_Hz": s.natural_frequency / (2 * np.pi),
        "resonance_ratio": s.resonance_ratio, "mass_kg": s.mass,
        "guide_sleeve_needed": bool(s.lengths["free_length"] / s.mean_diameter > 2.5),
        "passes_all_checks": s.passes, "binding_check": s.binding_check,
        "margins": s.margins,
    }


def _spring_findings(tag, s, sp):
    c = s.checks
    return (check_range(f"{tag} tau_max", s.tau_max / MPA, high=sp.allowable_stress_MPa,
                        source="seed 000, eq. (6.1): [tau] = 350-600 MPa", unit="MPa")
            + check_range(f"{tag} fatigue safety factor", s.safety, low=sp.min_safety_factor,
                          source=f"seed 000, eq. (6.12) with psi_tau = {sp.mean_stress_factor:g}: n >= 1.2-1.4")
            + check_range(f"{tag} resonance ratio omega_c1/omega_cam", s.resonance_ratio, low=sp.min_resonance_ratio,
                          source="seed 000, eq. (6.14): >= 10 (hard to meet at high speed, E27)")
            + check_range(f"{tag} working coils", c["working_coils"][0], low=2.0, source="seed 000, eq. (6.2)"))


def _drive(v, spec, law, omega, heel, roller):
    """Stages 6 and 7: reduced masses, spring characteristic and design, strength of the drive parts."""
    i_k = v.rocker_ratio
    d_g = v.throat_diameter_mm * MM
    f_g = float(flow.circle_area(d_g))
    gas = spec.gas
    found = []

    theta = np.unique(np.concatenate([np.linspace(law.valve_opens, law.valve_closes, 2001), law.breakpoints]))
    theta = theta[(theta >= law.valve_opens) & (theta <= law.valve_closes)]
    h, dh, d2h, _ = law.derivatives(theta)
    y = law.valve_lift(theta, i_k)
    a_v = i_k * omega**2 * d2h
    lift = law.lift_max * i_k

    if v.kind == "exhaust":
        p_gas = springs.gas_opening_force(d_g, gas.exhaust_back_pressure_MPa * MPA, gas.cylinder_intake_pressure_MPa * MPA)
        gas_source = "seed 000, eq. (5.4)"
    else:
        p_gas = springs.gas_opening_force(d_g, gas.intake_port_pressure_MPa * MPA, gas.cylinder_exhaust_pressure_MPa * MPA)
        gas_source = "seed 000, eq. (5.5)"

    sp = v.spring
    material = _material(sp)
    spring_total_mass = 0.0
    for _ in range(20):
        m_v, mass_source = _reduced_mass(v, f_g, spring_total_mass)
        required = springs.required_spring_force(m_v, a_v, v.drive.spring_reserve)
        preload, rate = springs.enveloping_line(y, required, sp.deflection_ratio_range, p_gas)
        raised = preload <= p_gas * (1.0 + 1e-9) and p_gas > 0.0
        line = springs.Characteristic(preload, rate, lift)
        lines = {"required": line}
        if sp.count == 1:
            chosen, n_pass = springs.design_spring(line, d_g, material, omega, sp.mean_diameter_ratio)
            designs = {"spring": chosen}
        else:
            outer_line, inner_line = line.split(sp.inner_share)
            outer, n_pass = springs.design_spring(outer_line, d_g, material, omega, sp.mean_diameter_ratio)
            room = outer.mean_diameter - outer.wire_diameter - 2.0 * sp.radial_gap_mm * MM

            def differs(s, outer=outer):
                diff = abs(s.natural_frequency - outer.natural_frequency) / outer.natural_frequency
                return {"frequency_difference": (diff, max(sp.min_frequency_difference, 1e-12), "min")}

            inner, n_in = springs.design_spring(inner_line, d_g, material, omega, (0.3, sp.mean_diameter_ratio[1]),
                                                max_outer=room, extra_check=differs,
                                                installed_length=outer.lengths["installed_length"])
            n_pass = min(n_pass, n_in)
            designs = {"outer": outer, "inner": inner}
            lines.update(outer=outer.characteristic, inner=inner.characteristic)
        new_mass = sum(d.mass for d in designs.values())
        if v.drive.masses is None or v.drive.masses.spring_kg is not None or abs(new_mass - spring_total_mass) < 1e-7:
            break
        spring_total_mass = new_mass
    m_t = masses.reduced_mass_at_tappet(m_v, i_k)

    chosen_line = springs.Characteristic(sum(d.characteristic.preload for d in designs.values()),
                                         sum(d.characteristic.rate for d in designs.values()), lift)
    lines["chosen"] = chosen_line
    ratio = chosen_line.max_deflection / chosen_line.preload_deflection
    found += check_range("spring reserve K_z", v.drive.spring_reserve, *springs.SPRING_RESERVE_RANGE,
                         source="seed 000, eq. (5.3)")
    found += check_range("spring f_max/f_min", ratio, *springs.DEFLECTION_RATIO_RANGE, source="seed 000, work 5 "
                         "(the chosen springs' rounded coils can move it off the required line's ratio)")
    if sp.count == 2:
        found += check_range("inner spring share", sp.inner_share, *springs.INNER_SHARE_RANGE, source="seed 000, work 5")
    for tag, d in designs.items():
        found += _spring_findings(tag if tag != "spring" else "spring", d, sp)
    if sp.count == 2:
        diff = designs["inner"].checks["frequency_difference"][0]
        found += check_range("inner/outer spring frequency difference", diff, low=sp.min_frequency_difference,
                             source="seed 000, eq. (6.14): the two ratios must differ (10 % assumed)")

    spring_rec = {
        "count": sp.count, "material": sp.material,
        "preload_N": chosen_line.preload, "max_force_N": chosen_line.max_force, "rate_N_per_mm": chosen_line.rate * MM,
        "required_preload_N": preload, "required_rate_N_per_mm": rate * MM, "required_max_force_N": line.max_force,
        "required_deflection_ratio": line.max_deflection / line.preload_deflection,
        "preload_set_by_gas_force": bool(raised), "gas_force_N": p_gas, "gas_force_source": gas_source,
        "deflection_ratio": ratio, "spring_reserve": v.drive.spring_reserve, "candidates_passing": n_pass,
    }
    if sp.count == 1:
        spring_rec.update(_spring_record(designs["spring"]))
    else:
        spring_rec.update({k: val for k, val in _spring_record(designs["outer"]).items()
                           if k not in ("preload_N", "max_force_N", "rate_N_per_mm")})
        spring_rec["outer"] = _spring_record(designs["outer"])
        spring_rec["inner"] = _spring_record(designs["inner"])
        spring_rec["inner_share"] = sp.inner_share

    mass_rec = {"at_valve_kg": m_v, "at_tappet_kg": m_t, "source": mass_source, "layout": v.layout}

    strength_rec, strength_found = _strength(v, law, omega, heel, roller, theta, y, dh, d2h, a_v, m_v, chosen_line,
                                             gas)
    found += strength_found
    inertia = m_v * np.clip(-a_v, 0.0, None)
    return DriveResults(mass_rec, spring_rec, strength_rec, found, y, inertia, required, lines)


_STRESS = (1.0 / MPA, "MPa")
_UNITS = {"camshaft_deflection": (1.0 / MM, "mm"), "cam_contact_stress": _STRESS, "tappet_side_pressure": _STRESS,
          "pushrod_buckling_margin": (1.0, ""), "ball_socket_stress": _STRESS, "pushrod_head_pressure": _STRESS,
          "rocker_pad_stress": _STRESS, "rocker_shaft_bending": _STRESS, "rocker_shaft_shear": _STRESS,
          "rocker_shaft_bearing": _STRESS}


def _strength(v, law, omega, heel, roller, theta, y, dh, d2h, a_v, m_v, line, gas):
    """Work 7: the cam load along the open event and every check the layout and the given dimensions allow."""
    i_k = v.rocker_ratio
    parts = v.parts
    spring_force = line.force(y)
    cam = strength.cam_force(spring_force, m_v * a_v, i_k)
    p_open = 0.0
    if v.kind == "exhaust" and parts.head_diameter_mm is not None:
        p_open = float(flow.circle_area(parts.head_diameter_mm * MM)) * max(
            (gas.exhaust_opening_pressure_MPa - gas.exhaust_back_pressure_MPa) * MPA, 0.0)
    cam[0] += i_k * p_open
    k = int(np.argmax(cam))
    p_max = float(cam[k])
    rec = {"cam_force_max_N": p_max, "cam_force_max_cam_deg": rad_to_deg(theta[k]),
           "valve_force_max_N": p_max / i_k, "gas_force_at_opening_N": p_open}
    verdicts = []
    notes = []

    def need(keys, check):
        missing = [key for key in keys if getattr(parts, key) is None]
        if missing:
            notes.append(f"{check}: not checked, parts.{', parts.'.join(missing)} not given")
        return not missing

    e_contact = parts.contact_modulus_MPa * MPA
    if need(["camshaft_diameter_mm", "camshaft_span_mm", "cam_to_bearing_mm"], "camshaft_deflection"):
        l1 = parts.cam_to_bearing_mm * MM
        f = strength.camshaft_deflection(p_max, l1, parts.camshaft_span_mm * MM - l1, parts.camshaft_diameter_mm * MM,
                                         parts.camshaft_bore_mm * MM, parts.camshaft_modulus_MPa * MPA,
                                         parts.camshaft_deflection_coefficient)
        verdicts.append(strength.verdict("camshaft_deflection", f,
                                         f"coefficient {parts.camshaft_deflection_coefficient:.4g} (E20: not 0.8)"))
    if need(["cam_width_mm"], "cam_contact_stress"):
        if v.cam.follower == "flat":
            rho = geometry.flat_follower_curvature(heel, law.lift(theta), d2h)
            curv = np.where(rho > 0, 1.0 / rho, np.inf)
        else:
            rho = geometry.roller_follower_curvature(heel, roller, law.lift(theta), dh, d2h)
            curv = 1.0 / rho + 1.0 / roller
        sigma = strength.hertz_line_stress(cam, parts.cam_width_mm * MM, curv, e_contact)
        j = int(np.argmax(sigma))
        rec["cam_contact_stress_cam_deg"] = rad_to_deg(theta[j])
        verdicts.append(strength.verdict("cam_contact_stress", sigma[j], "along the profile with the instantaneous "
                                         "force and radius (seed 002, eq. 2.5)"))
    if v.layout in ("direct", "pushrod") and v.cam.follower == "flat" and \
            need(["tappet_diameter_mm", "tappet_guide_length_mm"], "tappet_side_pressure"):
        b = float(np.max(np.abs(dh)))
        q = strength.tappet_side_pressure(p_max, b, parts.tappet_diameter_mm * MM, parts.tappet_guide_length_mm * MM)
        verdicts.append(strength.verdict("tappet_side_pressure", q, f"offset b = {b / MM:.4g} mm = max dh/dphi (7.7)"))
    if v.layout == "pushrod":
        if need(["pushrod_length_mm", "pushrod_diameter_mm"], "pushrod_buckling_margin"):
            inertia = strength.second_moment(parts.pushrod_diameter_mm * MM, parts.pushrod_bore_mm * MM)
            p_cr = strength.euler_load(parts.pushrod_modulus_MPa * MPA, inertia, parts.pushrod_length_mm * MM)
            verdicts.append(strength.verdict("pushrod_buckling_margin", p_cr / p_max,
                                             f"Euler load {p_cr:.5g} N; E = {parts.pushrod_modulus_MPa:g} MPa (E21)"))
        if need(["ball_radius_mm", "socket_radius_mm"], "ball_socket_stress"):
            verdicts.append(strength.verdict("ball_socket_stress", strength.sphere_socket_stress(
                p_max, e_contact, parts.ball_radius_mm * MM, parts.socket_radius_mm * MM)))
        if need(["pushrod_head_area_mm2"], "pushrod_head_pressure"):
            verdicts.append(strength.verdict("pushrod_head_pressure", p_max / (parts.pushrod_head_area_mm2 * MM**2)))
    if v.layout in ("rocker", "pushrod"):
        if need(["rocker_pad_width_mm", "rocker_pad_radius_mm"], "rocker_pad_stress"):
            verdicts.append(strength.verdict("rocker_pad_stress", strength.rocker_pad_stress(
                p_max / i_k, e_contact, parts.rocker_pad_width_mm * MM, parts.rocker_pad_radius_mm * MM)))
        if need(["rocker_shaft_span_mm", "rocker_shaft_diameter_mm", "rocker_width_mm"], "rocker_shaft"):
            st = strength.rocker_shaft_stresses(p_max, parts.rocker_shaft_span_mm * MM, parts.rocker_width_mm * MM,
                                                parts.rocker_shaft_diameter_mm * MM, parts.rocker_shaft_bore_mm * MM)
            verdicts.append(strength.verdict("rocker_shaft_bending", st["bending"],
                                             f"built-in beam (7.15, reading [A]); simply supported: "
                                             f"{st['bending_simply_supported'] / MPA:.4g} MPa; load P_T max (E25)"))
            verdicts.append(strength.verdict("rocker_shaft_shear", st["shear"]))
            verdicts.append(strength.verdict("rocker_shaft_bearing", st["bearing"]))
    checks = {}
    found = []
    for vd in verdicts:
        scale, unit = _UNITS[vd.check]
        checks[vd.check] = vd.as_dict(scale, unit)
        if not vd.passed:
            found += check_range(vd.check.replace("_", " "), vd.value * scale,
                                 high=vd.limit * scale if vd.kind == "max" else None,
                                 low=vd.limit * scale if vd.kind == "min" else None, source=vd.source, unit=unit)
    rec["checks"] = checks
    rec["not_checked"] = notes
    return rec, found
