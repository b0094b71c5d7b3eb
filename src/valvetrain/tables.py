"""Tables of a design as named columns in the units engineers read (mm, deg, MPa): the one conversion of the
stage results for the CSV files, the exports for manufacture and the report."""

import numpy as np

from .results import shown
from .units import MM, rad_to_deg, to_display

LIFT_COLUMNS = [
    ("cam_deg", "camshaft angle from the cam nose [deg]"),
    ("crank_deg", "crank angle from the gas-exchange TDC [deg]"),
    ("segment", "segment of the lift law"),
    ("tappet_lift_mm", "tappet (follower) lift including the ramp [mm]"),
    ("tappet_velocity_m_s", "tappet velocity [m/s]"),
    ("tappet_acceleration_m_s2", "tappet acceleration [m/s2]"),
    ("tappet_jerk_m_s3", "tappet jerk [m/s3]"),
    ("valve_lift_mm", "valve lift [mm]"),
    ("curtain_area_mm2", "valve curtain area [mm2]"),
    ("time_area_mm2_s", "running time-area from the start of the event [mm2 s]"),
    ("rho_mm", "radius of curvature of the cam profile [mm]; empty on a straight flank (infinite radius)"),
    ("pressure_angle_deg", "pressure angle (roller follower) [deg]"),
    ("contact_offset_mm", "contact point off the follower axis (flat follower) [mm]"),
]
"""Columns of ``tables/NAME_lift.csv`` with their meaning and unit."""


def lift_table_columns(table) -> dict[str, np.ndarray]:
    """The lift table of a valve as ordered columns in the units of :data:`LIFT_COLUMNS`."""
    return {
        "cam_deg": rad_to_deg(table.cam_angle),
        "crank_deg": rad_to_deg(table.crank_angle),
        "segment": table.segment,
        "tappet_lift_mm": table.lift / MM,
        "tappet_velocity_m_s": table.velocity,
        "tappet_acceleration_m_s2": table.acceleration,
        "tappet_jerk_m_s3": table.jerk,
        "valve_lift_mm": table.valve_lift / MM,
        "curtain_area_mm2": table.curtain_area / MM**2,
        "time_area_mm2_s": table.time_area / MM**2,
        "rho_mm": table.rho / MM,
        "pressure_angle_deg": rad_to_deg(table.pressure_angle),
        "contact_offset_mm": table.contact_offset / MM,
    }


STRENGTH_COLUMNS = [
    ("speed_rpm", "engine speed [rpm]"),
    ("load", "the cam force: quasi-static (spring + gas + inertia of the rigid train) or dynamic (simulated)"),
    ("cam_force_max_N", "largest force between cam and follower at that speed [N]"),
    ("cam_force_max_cam_deg", "where, camshaft angle from the nose [deg]"),
    ("cam_contact_stress_MPa", "largest Hertz stress of the cam contact at that speed [MPa] (needs parts.cam_width_mm)"),
    ("cam_contact_stress_cam_deg", "where, camshaft angle from the nose [deg]"),
]
"""Columns of ``tables/NAME_strength.csv``, one row per engine speed of the strength checks (the contact stress
columns only where the cam width is given and the profile is not undercut)."""


def strength_speed_columns(strength) -> dict[str, list[str]|np.ndarray]:
    """The per-speed table of a :class:`~valvetrain.design.drive_strength.StrengthResult` in the units of
    :data:`STRENGTH_COLUMNS`."""
    p = strength.per_speed
    out = {"speed_rpm": to_display(np.asarray(p.speed), "rpm"), "load": list(p.load),
           "cam_force_max_N": np.asarray(p.cam_force_max),
           "cam_force_max_cam_deg": rad_to_deg(np.asarray(p.cam_force_max_angle))}
    if p.contact_stress is not None:
        out["cam_contact_stress_MPa"] = to_display(np.asarray(p.contact_stress), "MPa")
        out["cam_contact_stress_cam_deg"] = rad_to_deg(np.asarray(p.contact_stress_angle))
    return out


CRANK_COLUMNS = [
    ("crank_deg", "crank angle of the cycle (0 = TDC of intake for a four-stroke, firing TDC at 360) [deg]"),
    ("s_mm", "piston displacement [mm]"), ("v_m_s", "piston velocity [m/s]"), ("j_m_s2", "piston acceleration [m/s2]"),
    ("beta_deg", "connecting-rod angle [deg]"), ("p_abs_MPa", "absolute cylinder pressure [MPa]"),
    ("p_gas_MPa", "gauge gas pressure p_g - p_0 [MPa]"), ("p_j_MPa", "specific inertia force [MPa]"),
    ("p_MPa", "total specific force on the pin axis [MPa]"), ("p_N_MPa", "normal (side) force [MPa]"),
    ("p_S_MPa", "rod force [MPa]"), ("p_K_MPa", "radial force on the crank [MPa]"),
    ("p_T_MPa", "tangential force [MPa]"), ("T_N", "tangential force [N]"),
    ("M_cyl_Nm", "torque of one cylinder [N m]"), ("pin_radial_N", "crank-pin load, radial (K + rod centrifugal) [N]"),
    ("pin_tangential_N", "crank-pin load, tangential [N]"),
]
"""Columns of ``tables/crank.csv`` (one cylinder over its cycle; sign conventions of Power units manual (n.d.)), in the units of
every table: mm, deg, m/s, m/s2, MPa, N, N m."""


def crank_columns(crank) -> dict[str, np.ndarray]:
    """The crank table of one cylinder in the units of :data:`CRANK_COLUMNS`."""
    c = crank.columns
    mpa = 1e-6
    return {
        "crank_deg": rad_to_deg(crank.phi), "s_mm": c.s / MM, "v_m_s": c.v, "j_m_s2": c.j,
        "beta_deg": rad_to_deg(c.beta), "p_abs_MPa": c.p_abs * mpa, "p_gas_MPa": c.p_gas * mpa,
        "p_j_MPa": c.p_j * mpa, "p_MPa": c.p * mpa, "p_N_MPa": c.p_N * mpa, "p_S_MPa": c.p_S * mpa,
        "p_K_MPa": c.p_K * mpa, "p_T_MPa": c.p_T * mpa, "T_N": c.T, "M_cyl_Nm": c.torque,
        "pin_radial_N": c.pin_radial, "pin_tangential_N": c.pin_tangential,
    }


def engine_torque_columns(crank) -> dict[str, np.ndarray]:
    """``crank_deg, M_total_Nm`` and one column per cylinder over one cycle."""
    out = {"crank_deg": rad_to_deg(crank.psi), "M_total_Nm": crank.total_torque}
    for i, m in enumerate(crank.cylinder_torques, start=1):
        out[f"M_cyl{i}_Nm"] = m
    return out


def camshaft_torsion_columns(camshaft) -> dict[str, np.ndarray]:
    """The camshaft's steady torsional response against the engine speed: ``speed_rpm``, the fluctuation of each
    cylinder's lobe timing (largest less smallest lag over a revolution) [cam deg] and the largest force of the timing
    drive [N] (:class:`~valvetrain.design.camshaft.CamshaftResults`)."""
    out = {"speed_rpm": to_display(camshaft.speeds, "rpm")}
    for i, cylinder in enumerate(camshaft.figures.cylinders):
        out[f"timing_fluctuation_cyl{cylinder}_cam_deg"] = rad_to_deg(camshaft.fluctuation[:, i])
    out["drive_force_N"] = camshaft.drive_forces
    return out


def two_stroke_columns(ports) -> dict[str, np.ndarray]:
    """Port areas against the crank angle from TDC [deg, mm2]."""
    out = {"crank_deg": rad_to_deg(ports.phi)}
    out.update({f"{name}_area_mm2": c.area / MM**2 for name, c in ports.curves.items()})
    return out


def two_stroke_speed_columns(ports) -> dict[str, np.ndarray]:
    """Time-area of every port against the crank speed [rpm, mm2 s] (Z = K1 K2 / n, Valve-train practical works (n.d.) eq. 8.6)."""
    out = {"speed_rpm": to_display(ports.speeds, "rpm")}
    out.update({f"{name}_time_area_mm2_s": c.time_area / MM**2 for name, c in ports.curves.items()})
    return out


BREATHING_COLUMNS = [
    ("crank_deg", "crank angle from the gas-exchange TDC [deg]"), ("volume_cm3", "cylinder volume [cm3]"),
    ("pressure_kPa", "cylinder pressure [kPa]"), ("temperature_K", "cylinder gas temperature [K]"),
    ("mass_mg", "mass in the cylinder [mg]"), ("burned_fraction", "share of burned or residual gas"),
    ("intake_flow_g_s", "mass flow into the cylinder through the intake valves [g/s] (negative: back-flow)"),
    ("exhaust_flow_g_s", "mass flow out of the cylinder through the exhaust valves [g/s] (negative: back-flow)"),
    ("intake_port_kPa", "pressure in the intake port at the valves [kPa]"),
    ("exhaust_port_kPa", "pressure in the exhaust port at the valves [kPa]"),
]
"""Columns of ``tables/breathing_condition_N.csv``: the converged cycle of the N-th condition, every crank degree."""

BREATHING_STEP_DEG = 1.0
"""Step of the breathing's per-angle tables [crank deg]."""


def breathing_columns(result) -> dict[str, np.ndarray]:
    """The converged cycle of a :class:`~valvetrain.breathing.BreathingResult` every :data:`BREATHING_STEP_DEG`, in
    the units of :data:`BREATHING_COLUMNS` (linear between the integration's steps)."""
    c = result.columns
    deg = np.arange(0.0, 720.0 + BREATHING_STEP_DEG / 2, BREATHING_STEP_DEG)
    at = rad_to_deg(c.angle)

    def on(values):
        return np.interp(deg, at, values)

    return {"crank_deg": deg, "volume_cm3": on(c.volume) * 1e6, "pressure_kPa": on(c.pressure) * 1e-3,
            "temperature_K": on(c.temperature), "mass_mg": on(c.mass) * 1e6,
            "burned_fraction": on(c.burned_mass / c.mass), "intake_flow_g_s": on(c.intake_flow) * 1e3,
            "exhaust_flow_g_s": on(c.exhaust_flow) * 1e3, "intake_port_kPa": on(c.intake_port) * 1e-3,
            "exhaust_port_kPa": on(c.exhaust_port) * 1e-3}


BREATHING_RECORD_KEYS = ("speed", "intake_pressure", "exhaust_pressure", "air_mass_flow", "volumetric_efficiency",
                         "trapped_mass", "residual_gas_fraction", "imep", "imep_gross", "pmep", "peak_pressure",
                         "peak_pressure_angle", "torque", "power")
"""Fields of the breathing's records in ``tables/breathing_conditions.csv`` and ``breathing_curve.csv`` (the torque
and power of a fired engine)."""


def breathing_record_columns(records) -> dict[str, list]:
    """The records of several conditions as columns: one row a condition, the keys and units of results.json."""
    fields = [k for k in BREATHING_RECORD_KEYS if all(getattr(r, k) is not None for r in records)]
    rows = [shown(r, *fields) for r in records]
    return {key: [row[i][1] for row in rows] for i, (key, _) in enumerate(rows[0])}


def contour_columns(valve) -> dict[str, np.ndarray]:
    """Cam contour of a valve for manufacture: cam angle, x, y, polar radius and angle [mm, deg]."""
    x, y = valve.contour / MM
    return {
        "cam_deg": rad_to_deg(valve.contour_angle),
        "x_mm": x,
        "y_mm": y,
        "radius_mm": np.hypot(x, y),
        "polar_angle_deg": rad_to_deg(np.arctan2(x, y)),
    }


def polar_contour_columns(valve, step_deg) -> dict[str, np.ndarray]:
    """The contour's polar radius at polar angles every ``step_deg`` [deg, mm], for manufacture.

    The polar angle is measured from the nose direction (+y) towards +x; each radius is
    solved on the analytic contour (:meth:`valvetrain.laws.LiftLaw.polar_radius`), not
    interpolated, so the table is exact at any step.
    """
    targets = np.radians(np.arange(-180.0, 180.0, step_deg))
    radii = valve.law.polar_radius(targets, valve.heel_radius, valve.follower_model)
    return {"polar_angle_deg": np.degrees(targets), "radius_mm": radii / MM}


def cartesian_contour_columns(valve, step_deg) -> dict[str, np.ndarray]:
    """Contour points every ``step_deg`` of camshaft angle [deg, mm] (follower angle from the nose)."""
    theta = np.radians(np.arange(-180.0, 180.0, step_deg))
    x, y = valve.law.profile(theta, valve.heel_radius, valve.follower_model)[0] / MM
    return {"cam_deg": np.degrees(theta), "x_mm": x, "y_mm": y}


def lift_export_columns(valve, step_deg) -> dict[str, np.ndarray]:
    """Tappet lift every ``step_deg`` cam degrees in the measured-table format ``angle_deg,lift_mm``.

    The angles are camshaft degrees in the engine's cam frame (crank angle from the
    gas-exchange TDC / 2) and the lift is the cam's, ramps included, so ``law = "table"``
    with ``table_angle = "cam"`` and ``table_lift_at = "tappet"`` reads the file back to the
    same valve lift and timing (the ramp takes up the valve's clearance).  The first and the last row lie on the
    base circle, at or just beyond the ends of the lift event: a table starts and ends there.
    """
    law = valve.law
    first, last = np.floor(np.degrees(law.start) / step_deg), np.ceil(np.degrees(law.end) / step_deg)
    theta = np.radians(np.arange(first, last + 0.5) * step_deg)
    return {"angle_deg": np.degrees(theta + valve.nose_crank / 2.0), "lift_mm": law.lift(theta) / MM}


def lift_export_comments(valve) -> list[str]:
    """The comment lines of ``contour/NAME_lift.csv``: what its columns measure, from where, in which units, and the
    keys of a ``law = "table"`` cam that read it back to the same valve lift and timing."""
    return [f"{valve.kind} valve cam: tappet (cam) lift including the ramps [mm] against the camshaft angle [deg]",
            "angles from the gas-exchange TDC (camshaft angle = crank angle / 2; not from the cam nose)",
            f"the ramps take up a clearance of {valve.law.ramp_height / MM:.6g} mm at the cam; valve lift = rocker "
            f"ratio {valve.rocker_ratio:.6g} x (tappet lift - clearance)",
            'read back with: law = "table", table_angle = "cam", table_lift_at = "tappet", '
            f'table_zero = "gas_exchange_tdc", clearance_mm = {valve.law.ramp_height / MM:.6g}, '
            f"rocker_ratio = {valve.rocker_ratio:.6g}"]
