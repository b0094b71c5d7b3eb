"""Drive stages of a valve design: reduced masses, spring characteristic and design, strength of the
drive parts (Valve-train practical works (n.d.), works 5-7)."""

from dataclasses import dataclass, replace

import numpy as np

from .. import flow, geometry, masses, springs, strength
from ..checks import check
from ..specification import si
from ..specification.cams import train_mass
from ..units import MM, MPA, rad_to_deg, to_display


@dataclass
class DriveResults:
    """Springs and strength of one valve: the JSON records and the curves for the report (SI)."""

    masses: dict
    spring: dict
    strength: dict
    checks: list                   # every valvetrain.checks.Check of the drive, passed or not
    lift: np.ndarray               # valve lift along the open event [m]
    inertia_force: np.ndarray      # m_v |j_v| where j_v < 0 [N]
    required_force: np.ndarray     # K_z m_v |j_v| [N]
    lines: dict                    # name -> springs.Characteristic (required, chosen, outer, inner)


def reduced_mass(v, throat_area, spring_mass_kg):
    """Reduced mass at the valve [kg] and a description of how it was obtained (the valve's SI view)."""
    return train_mass(si(v), spring_mass_kg)


def _spring_options(sp):
    """The spring search of a [valves.NAME.spring] section, SI (grades, overrides, ranges, arrangement)."""
    def si(value, unit):
        return None if value is None else value * unit

    materials = tuple(springs.SpringMaterial(
        grade=name, shear_modulus=si(sp.shear_modulus_MPa, MPA), density=sp.density_kg_m3,
        allowable_stress=si(sp.allowable_stress_MPa, MPA), endurance_limit=si(sp.endurance_limit_MPa, MPA),
        mean_stress_factor=sp.mean_stress_factor, min_safety=sp.min_safety_factor,
        min_resonance_ratio=sp.min_resonance_ratio, gap_factor=sp.coil_gap_factor) for name in sp.materials)
    installed = None if sp.installed_length_mm is None else tuple(x * MM for x in sp.installed_length_mm)
    return springs.SpringOptions(
        materials=materials, count=sp.count, inner_share=sp.inner_share, diameter_range=sp.mean_diameter_ratio,
        wire_range_mm=sp.wire_diameter_range_mm, wire_step_mm=sp.wire_step_mm, ratio_range=sp.deflection_ratio_range,
        installed_length_range=installed, max_free_length=si(sp.max_free_length_mm, MM), radial_gap=sp.radial_gap_mm * MM,
        min_frequency_difference=sp.min_frequency_difference)


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
        "resonance_ratio": s.resonance_ratio, "mass_kg": s.mass, "material": s.material,
        "target_deflection_ratio": s.target_ratio,
        "guide_sleeve_needed": bool(s.lengths["free_length"] / s.mean_diameter > 2.5),
        "passes_all_checks": s.passes, "binding_check": s.binding_check,
        "margins": s.margins,
    }


def _spring_checks(tag, s, note=""):
    """A designed spring's own checks, named after the spring (``spring``, ``outer``, ``inner``); a failed one
    carries ``note`` (the diagnosis)."""
    return [replace(c, quantity=f"{tag} {c.quantity}", note=c.note if c.passed else note) for key, c in s.checks.items()
            if key in ("tau_max", "fatigue_safety", "resonance_ratio", "working_coils", "installed_length",
                       "free_length", "coil_gap_at_full_lift")]


def drive_stage(v, gas, law, omega, heel, roller):
    """Stages 6 and 7: reduced masses, spring characteristic and design, strength of the drive parts."""
    i_k = v.rocker_ratio
    d_g = v.throat_diameter_mm * MM
    f_g = float(flow.circle_area(d_g))
    found = []

    theta = np.unique(np.concatenate([np.linspace(law.valve_opens, law.valve_closes, 2001), law.breakpoints]))
    theta = theta[(theta >= law.valve_opens) & (theta <= law.valve_closes)]
    h, dh, d2h, _ = law.derivatives(theta)
    y = law.valve_lift(theta, i_k)
    a_v = i_k * omega**2 * d2h
    lift = law.lift_max * i_k

    if v.kind == "exhaust":
        p_gas = springs.gas_opening_force(d_g, gas.exhaust_back_pressure_MPa * MPA, gas.cylinder_intake_pressure_MPa * MPA)
        gas_source = "Valve-train practical works (n.d.), eq. (5.4)"
    else:
        p_gas = springs.gas_opening_force(d_g, gas.intake_port_pressure_MPa * MPA, gas.cylinder_exhaust_pressure_MPa * MPA)
        gas_source = "Valve-train practical works (n.d.), eq. (5.5)"

    sp = v.spring
    options = _spring_options(sp)
    spring_total_mass = 0.0
    for _ in range(20):
        m_v, mass_source = reduced_mass(v, f_g, spring_total_mass)
        required = springs.required_spring_force(m_v, a_v, v.drive.spring_reserve)
        seat = springs.seat_load(m_v) if sp.min_preload_N is None else sp.min_preload_N
        requirement = springs.Requirement(y, required, max(p_gas, seat))
        search = springs.design_springs(requirement, d_g, omega, options)
        line, designs, n_pass = search.line, search.designs, search.passing
        preload, rate = line.preload, line.rate
        raised = preload <= requirement.min_preload * (1.0 + 1e-9) and requirement.min_preload > 0.0
        lines = {"required": line}
        if sp.count == 2:
            lines.update(outer=designs["outer"].characteristic, inner=designs["inner"].characteristic)
        new_mass = sum(d.mass for d in designs.values())
        if v.drive.masses is None or v.drive.masses.spring_kg is not None or abs(new_mass - spring_total_mass) < 1e-7:
            break
        spring_total_mass = new_mass
    diagnosis = None if search.passes else springs.diagnose(requirement, d_g, omega, options, search,
                                                            2.0 * omega)
    m_t = masses.reduced_mass_at_tappet(m_v, i_k)

    chosen_line = springs.Characteristic(sum(d.characteristic.preload for d in designs.values()),
                                         sum(d.characteristic.rate for d in designs.values()), lift)
    lines["chosen"] = chosen_line
    ratio = chosen_line.max_deflection / chosen_line.preload_deflection
    found.append(check("spring reserve K_z", v.drive.spring_reserve, *springs.SPRING_RESERVE_RANGE,
                       source="Valve-train practical works (n.d.), eq. (5.3)"))
    found.append(check("spring f_max/f_min", ratio, *springs.DEFLECTION_RATIO_RANGE, source="Valve-train practical works (n.d.), work 5 "
                       "(the chosen springs' rounded coils can move it off the required line's ratio)"))
    if sp.count == 2:
        found.append(check("inner spring share", sp.inner_share, *springs.INNER_SHARE_RANGE, source="Valve-train practical works (n.d.), work 5"))
    for tag, d in designs.items():
        found += _spring_checks(tag, d, diagnosis["text"] if diagnosis else "")
    if sp.count == 2:
        found.append(replace(designs["inner"].checks["frequency_difference"],
                             quantity="inner/outer spring frequency difference"))

    spring_rec = {
        "count": sp.count, "material": sp.material,
        "preload_N": chosen_line.preload, "max_force_N": chosen_line.max_force, "rate_N_per_mm": chosen_line.rate * MM,
        "required_preload_N": preload, "required_rate_N_per_mm": rate * MM, "required_max_force_N": line.max_force,
        "required_deflection_ratio": line.max_deflection / line.preload_deflection,
        "preload_set_by_gas_force": bool(raised and p_gas >= seat), "gas_force_N": p_gas, "gas_force_source": gas_source,
        "preload_set_by_seat_load": bool(raised and seat > p_gas), "seat_load_N": seat,
        "seat_load_source": "min_preload_N of the specification" if sp.min_preload_N is not None else
        f"m_v x {springs.SEAT_ACCELERATION:.5g} m/s2 (100 g, a stated default)",
        "deflection_ratio": ratio, "spring_reserve": v.drive.spring_reserve, "candidates_passing": n_pass,
        "candidates_tried": search.tried,
    }
    if diagnosis:
        spring_rec["diagnosis"] = diagnosis
    if sp.count == 1:
        spring_rec.update(_spring_record(designs["spring"]))
    else:
        spring_rec.update({k: val for k, val in _spring_record(designs["outer"]).items()
                           if k not in ("preload_N", "max_force_N", "rate_N_per_mm")})
        spring_rec["passes_all_checks"] = search.passes
        spring_rec["outer"] = _spring_record(designs["outer"])
        spring_rec["inner"] = _spring_record(designs["inner"])
        spring_rec["inner_share"] = sp.inner_share

    mass_rec = {"at_valve_kg": m_v, "at_tappet_kg": m_t, "source": mass_source, "layout": v.layout}
    if v.drive.stiffness_N_per_mm is not None:
        train, train_checks = _train_dynamics(v, law, omega, m_v, chosen_line.rate)
        mass_rec.update(train)
        found += train_checks

    strength_rec, strength_found = _strength(v, law, omega, heel, roller, theta, y, h, dh, d2h, a_v, m_v, chosen_line,
                                             gas)
    found += strength_found
    inertia = m_v * np.clip(-a_v, 0.0, None)
    return DriveResults(mass_rec, spring_rec, strength_rec, found, y, inertia, required, lines)


def _strength(v, law, omega, heel, roller, theta, y, h, dh, d2h, a_v, m_v, line, gas):
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
                                         f"coefficient {parts.camshaft_deflection_coefficient:.4g} (corrections note 20: not 0.8)"))
    if need(["cam_width_mm"], "cam_contact_stress"):
        flat = v.cam.follower == "flat"
        rho = (geometry.flat_follower_curvature(heel, h, d2h) if flat
               else geometry.roller_follower_curvature(heel, roller, h, dh, d2h))
        # line contact needs a convex profile (flat) or a concave one wider than the roller
        if not np.all((rho > 0.0) if flat else (rho > 0.0) | (rho < -roller)):
            notes.append("cam_contact_stress: not checked, the profile is undercut (no line contact)")
        else:
            curv = 1.0 / rho + (0.0 if flat else 1.0 / roller)
            sigma = strength.hertz_line_stress(cam, parts.cam_width_mm * MM, curv, e_contact)
            j = int(np.argmax(sigma))
            rec["cam_contact_stress_cam_deg"] = rad_to_deg(theta[j])
            verdicts.append(strength.verdict("cam_contact_stress", sigma[j], "along the profile with the "
                                             "instantaneous force and radius (Shang Hanji (1988), eq. 2.5)"))
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
                                             f"Euler load {p_cr:.5g} N; E = {parts.pushrod_modulus_MPa:g} MPa (corrections note 21)"))
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
                                             f"built-in beam (7.15, corrections note 48); simply supported: "
                                             f"{st['bending_simply_supported'] / MPA:.4g} MPa; load P_T max (corrections note 25)"))
            verdicts.append(strength.verdict("rocker_shaft_shear", st["shear"]))
            verdicts.append(strength.verdict("rocker_shaft_bearing", st["bearing"]))
    rec["checks"] = {c.quantity: _strength_record(c) for c in verdicts}
    rec["not_checked"] = notes
    return rec, [replace(c, quantity=c.quantity.replace("_", " ")) for c in verdicts]


def _strength_record(c):
    """results.json record of a strength check: value and limit in its unit, pass, source (and a note)."""
    limit = c.high if c.high is not None else c.low
    out = {"value": c.shown_value, "allowed": f"{'<=' if c.high is not None else '>='} {to_display(limit, c.unit):g}",
           "limit": to_display(limit, c.unit), "unit": c.unit, "pass": c.passed, "source": c.source}
    if c.note:
        out["note"] = c.note
    return out


def _train_dynamics(v, law, omega, mass, spring_rate):
    """Natural frequency of the one-mass train and the perturbation parameter (Shang Hanji (1988), sections 1 and 3.3).

    omega_n = sqrt((c + K) / M) with the drive stiffness c and the spring rate K at the valve;
    epsilon = M omega^2 / (c + K) (the printed M omega^3 / c is dimensionally wrong, corrections note 30); and the law's own
    checks against the train (:meth:`valvetrain.laws.LiftLaw.train_checks`).
    """
    c = v.drive.stiffness_N_per_mm / MM
    omega_n = float(np.sqrt((c + spring_rate) / mass))
    out = {"drive_stiffness_N_per_mm": c * MM, "natural_frequency_Hz": omega_n / (2 * np.pi),
           "epsilon": mass * omega**2 / (c + spring_rate)}
    return out, law.train_checks(omega_n, omega)
