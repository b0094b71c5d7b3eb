"""Writing results: JSON, CSV tables, contour CSV and DXF, and the whole output folder atomically."""

import csv
import json
from pathlib import Path

import numpy as np

from .outfolder import atomic_folder
from .units import MM, rad_to_deg

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


def lift_table_columns(table):
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


CRANK_COLUMNS = [
    ("crank_deg", "crank angle of the cycle (0 = TDC of intake for a four-stroke, firing TDC at 360) [deg]"),
    ("s_m", "piston displacement [m]"), ("v_m_s", "piston velocity [m/s]"), ("j_m_s2", "piston acceleration [m/s2]"),
    ("beta_deg", "connecting-rod angle [deg]"), ("p_abs_MPa", "absolute cylinder pressure [MPa]"),
    ("p_gas_MPa", "gauge gas pressure p_g - p_0 [MPa]"), ("p_j_MPa", "specific inertia force [MPa]"),
    ("p_MPa", "total specific force on the pin axis [MPa]"), ("p_N_MPa", "normal (side) force [MPa]"),
    ("p_S_MPa", "rod force [MPa]"), ("p_K_MPa", "radial force on the crank [MPa]"),
    ("p_T_MPa", "tangential force [MPa]"), ("T_kN", "tangential force [kN]"),
    ("M_cyl_Nm", "torque of one cylinder [N m]"), ("pin_radial_kN", "crank-pin load, radial (K + rod centrifugal) [kN]"),
    ("pin_tangential_kN", "crank-pin load, tangential [kN]"),
]
"""Columns of ``tables/crank.csv`` (one cylinder over its cycle; sign conventions of seed 001)."""


def crank_columns(crank):
    """The crank table of one cylinder in the units of :data:`CRANK_COLUMNS`."""
    c = crank.columns
    mpa = 1e-6
    return {
        "crank_deg": rad_to_deg(crank.phi), "s_m": c["s"], "v_m_s": c["v"], "j_m_s2": c["j"],
        "beta_deg": rad_to_deg(c["beta"]), "p_abs_MPa": c["p_abs"] * mpa, "p_gas_MPa": c["p_gas"] * mpa,
        "p_j_MPa": c["p_j"] * mpa, "p_MPa": c["p"] * mpa, "p_N_MPa": c["p_N"] * mpa, "p_S_MPa": c["p_S"] * mpa,
        "p_K_MPa": c["p_K"] * mpa, "p_T_MPa": c["p_T"] * mpa, "T_kN": c["T"] * 1e-3, "M_cyl_Nm": c["torque"],
        "pin_radial_kN": c["pin_radial"] * 1e-3, "pin_tangential_kN": c["pin_tangential"] * 1e-3,
    }


def engine_torque_columns(crank):
    """``crank_deg, M_total_Nm`` and one column per cylinder over one cycle."""
    out = {"crank_deg": rad_to_deg(crank.psi), "M_total_Nm": crank.total_torque}
    for i, m in enumerate(crank.cylinder_torques, start=1):
        out[f"M_cyl{i}_Nm"] = m
    return out


def two_stroke_columns(ports):
    """Port areas against the crank angle from TDC [deg, mm2]."""
    out = {"crank_deg": rad_to_deg(ports.phi)}
    out.update({f"{name}_area_mm2": a / MM**2 for name, a in ports.areas.items()})
    return out


def two_stroke_speed_columns(ports):
    """Time-area of every port against the crank speed [rpm, mm2 s] (Z = K1 K2 / n, seed 000 eq. 8.6)."""
    out = {"speed_rpm": ports.speeds}
    out.update({f"{name}_time_area_mm2_s": z / MM**2 for name, z in ports.time_areas.items()})
    return out


def _cell(x):
    if isinstance(x, str):
        return x
    x = float(x)
    return f"{x:.10g}" if np.isfinite(x) else ""


def write_csv(path, columns):
    """Write equal-length columns (a dict name -> sequence) as a CSV file with a header row.

    Numbers are written with 10 significant digits; a quantity that is not finite (the infinite
    radius of curvature of a straight flank) is an empty cell, never ``inf`` or ``nan``."""
    names = list(columns)
    with open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(names)
        for row in zip(*(columns[n] for n in names), strict=True):
            w.writerow([_cell(x) for x in row])


def contour_columns(valve):
    """Cam contour of a valve for manufacture: cam angle, x, y, polar radius and angle [mm, deg]."""
    x, y = valve.contour / MM
    return {
        "cam_deg": rad_to_deg(valve.contour_angle),
        "x_mm": x,
        "y_mm": y,
        "radius_mm": np.hypot(x, y),
        "polar_angle_deg": rad_to_deg(np.arctan2(x, y)),
    }


def polar_contour_columns(valve, step_deg):
    """The contour's polar radius at polar angles every ``step_deg`` [deg, mm], for manufacture.

    The polar angle is measured from the nose direction (+y) towards +x; each radius is
    solved on the analytic contour (root of the contour point's polar angle), not
    interpolated, so the table is exact at any step.
    """
    from scipy.optimize import brentq

    theta = valve.contour_angle
    psi = np.unwrap(np.arctan2(*valve.contour))
    targets = np.radians(np.arange(-180.0, 180.0, step_deg))
    law, heel, follower, roller = valve.law, valve.heel_radius, valve.follower, valve.roller_radius
    from .design.valve import contour_points

    def polar(t):
        x, y = contour_points(law, np.array([t]), heel, follower, roller)[:, 0]
        return np.arctan2(x, y), np.hypot(x, y)

    radii = []
    for target in targets:
        k = int(np.clip(np.searchsorted(psi, target), 1, psi.size - 1))
        lo, hi = theta[k - 1], theta[k]
        f = lambda t, target=target: np.angle(np.exp(1j * (polar(t)[0] - target)))  # noqa: E731
        t = brentq(f, lo, hi, xtol=1e-14) if f(lo) * f(hi) < 0 else (lo if abs(f(lo)) < abs(f(hi)) else hi)
        radii.append(polar(t)[1])
    return {"polar_angle_deg": np.degrees(targets), "radius_mm": np.array(radii) / MM}


def cartesian_contour_columns(valve, step_deg):
    """Contour points every ``step_deg`` of camshaft angle [deg, mm] (follower angle from the nose)."""
    from .design.valve import contour_points

    theta = np.radians(np.arange(-180.0, 180.0, step_deg))
    x, y = contour_points(valve.law, theta, valve.heel_radius, valve.follower, valve.roller_radius) / MM
    return {"cam_deg": np.degrees(theta), "x_mm": x, "y_mm": y}


def lift_export_columns(valve, step_deg):
    """Tappet lift every ``step_deg`` cam degrees in the measured-table format ``angle_deg,lift_mm``.

    The angles are camshaft degrees in the engine's cam frame (crank angle from the
    gas-exchange TDC / 2) and the lift is the cam's, ramps included, so ``law = "table"``
    with ``table_angle = "cam"`` and ``table_lift_at = "tappet"`` reads the file back to the
    same valve lift and timing (the ramp takes up the valve's clearance).
    """
    law = valve.law
    theta = np.radians(np.arange(np.ceil(np.degrees(law.start) / step_deg) * step_deg, np.degrees(law.end), step_deg))
    return {"angle_deg": np.degrees(theta + valve.nose_crank / 2.0), "lift_mm": law.lift(theta) / MM}


def write_dxf(path, valve):
    """Write the cam contour as DXF (millimetres).

    Layers: ``CAM_PROFILE`` (closed polyline of the contour), ``BASE_CIRCLE`` (the heel
    circle), ``RAMP_BOUNDARIES`` and ``SEGMENT_BOUNDARIES`` (radial lines to the ends of
    the ramps and to the other junctions of the lift-law segments), ``AXES`` (centre lines;
    +y is the nose direction).

    The file is reproducible: ezdxf's fixed metadata (creation date, GUIDs) replaces the clock
    and random identifiers, so the same design writes the same bytes.
    """
    import ezdxf

    fixed = ezdxf.options.write_fixed_meta_data_for_testing
    ezdxf.options.write_fixed_meta_data_for_testing = True
    try:
        _dxf_document(valve).saveas(path)
    finally:
        ezdxf.options.write_fixed_meta_data_for_testing = fixed


def _dxf_document(valve):
    import ezdxf
    from ezdxf import units

    doc = ezdxf.new("R2010")
    doc.units = units.MM
    for name, color in (("CAM_PROFILE", 7), ("BASE_CIRCLE", 3), ("RAMP_BOUNDARIES", 6), ("SEGMENT_BOUNDARIES", 1),
                        ("AXES", 5)):
        doc.layers.add(name, color=color)
    msp = doc.modelspace()
    pts = (valve.contour / MM).T
    msp.add_lwpolyline([tuple(p) for p in pts], close=True, dxfattribs={"layer": "CAM_PROFILE"})
    heel = valve.heel_radius / MM
    msp.add_circle((0.0, 0.0), heel, dxfattribs={"layer": "BASE_CIRCLE"})
    reach = 1.2 * float(np.max(np.hypot(*pts.T)))
    msp.add_line((-reach, 0.0), (reach, 0.0), dxfattribs={"layer": "AXES"})
    msp.add_line((0.0, -reach), (0.0, reach), dxfattribs={"layer": "AXES"})
    ramps = {s.end if "opening" in s.name else s.start for s in valve.law.segments if s.name.startswith("ramp")}
    for a in valve.law.breakpoints:
        k = int(np.argmin(np.abs(valve.contour_angle - a)))
        layer = "RAMP_BOUNDARIES" if any(np.isclose(a, r) for r in ramps) else "SEGMENT_BOUNDARIES"
        msp.add_line((0.0, 0.0), tuple(pts[k]), dxfattribs={"layer": layer})
    return doc


def results_json(results):
    """results.json text."""
    return json_text(results.to_dict())


def json_text(data):
    """Strict JSON (RFC 8259) of nested dicts, lists, numbers and numpy values: a quantity that is not finite
    (an infinite margin of a check that is switched off, an undefined ratio) is written as null."""
    return json.dumps(_plain(data), indent=2, ensure_ascii=False, allow_nan=False)


def _plain(x):
    if isinstance(x, dict):
        return {k: _plain(v) for k, v in x.items()}
    if isinstance(x, (list, tuple, np.ndarray)):
        return [_plain(v) for v in x]
    if isinstance(x, np.generic):
        x = x.item()
    if isinstance(x, float) and not np.isfinite(x):
        return None
    if x is None or isinstance(x, (str, bool, int, float)):
        return x
    raise TypeError(f"cannot write {type(x).__name__} to JSON")


def write_outputs(results, out, lang="en", inputs=(), force=False):
    """Write every artefact of a design into the folder ``out``, atomically.

    Everything is written into a temporary sibling folder first and put in place only
    when complete (:func:`valvetrain.outfolder.atomic_folder`, which also says which
    folders may be replaced: ``inputs`` are the files the run read, ``force`` allows
    replacing a folder with files no valvetrain run wrote).  A failure or an interruption
    leaves ``out`` as it was (absent, or the previous results).

    Layout::

        out/results.json
        out/tables/NAME_lift.csv, crank.csv, engine_torque.csv, two_stroke_ports.csv, two_stroke_time_area.csv
        out/contour/NAME.csv, NAME_polar.csv, NAME_cartesian.csv, NAME_lift.csv, NAME.dxf
                    (not for a valve whose cam profile is undercut: it cannot be made)
        out/plots/NAME_kinematics.png, NAME_contour.png, NAME_time_area.png, NAME_curvature.png,
                  NAME_spring.png, crank_forces.png, crank_torque.png, crank_pin_polar.png,
                  two_stroke_ports.png, two_stroke_time_area.png
        out/report.html
        out/.valvetrain-output (the files the run wrote)
    """
    from .report import write_plots, write_report

    with atomic_folder(out, inputs, force) as tmp:
        for sub in ("tables", "contour", "plots"):
            (tmp / sub).mkdir()
        (tmp / "results.json").write_text(results_json(results), encoding="utf-8")
        for name, v in results.valves.items():
            write_csv(tmp / "tables" / f"{name}_lift.csv", lift_table_columns(v.table))
            if v.summary["cam"]["undercut"]:
                continue  # no follower can trace an undercut profile: nothing is written for its manufacture
            write_csv(tmp / "contour" / f"{name}.csv", contour_columns(v))
            step = results.spec.output.export_step_deg
            write_csv(tmp / "contour" / f"{name}_polar.csv", polar_contour_columns(v, step))
            write_csv(tmp / "contour" / f"{name}_cartesian.csv", cartesian_contour_columns(v, step))
            write_csv(tmp / "contour" / f"{name}_lift.csv", lift_export_columns(v, step))
            write_dxf(tmp / "contour" / f"{name}.dxf", v)
        if results.crank is not None:
            write_csv(tmp / "tables" / "crank.csv", crank_columns(results.crank))
            write_csv(tmp / "tables" / "engine_torque.csv", engine_torque_columns(results.crank))
        if results.two_stroke is not None:
            write_csv(tmp / "tables" / "two_stroke_ports.csv", two_stroke_columns(results.two_stroke))
            write_csv(tmp / "tables" / "two_stroke_time_area.csv", two_stroke_speed_columns(results.two_stroke))
        plots = write_plots(results, tmp / "plots", lang)
        write_report(results, tmp / "report.html", plots, lang)
    return Path(out)
