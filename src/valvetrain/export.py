"""Writing results: JSON, CSV tables, contour CSV and DXF, and the whole output folder atomically."""

import csv
import json
import os
from pathlib import Path
import shutil
import tempfile

import numpy as np

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
    ("rho_mm", "radius of curvature of the cam profile [mm]"),
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


def _cell(x):
    return x if isinstance(x, str) else f"{float(x):.10g}"


def write_csv(path, columns):
    """Write equal-length columns (a dict name -> sequence) as a CSV file with a header row."""
    names = list(columns)
    with open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(names)
        for row in zip(*(columns[n] for n in names)):
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


def write_dxf(path, valve):
    """Write the cam contour as DXF (millimetres).

    Layers: ``CAM_PROFILE`` (closed polyline of the contour), ``BASE_CIRCLE`` (the heel
    circle), ``SEGMENTS`` (radial lines to the junctions of the lift-law segments),
    ``AXES`` (centre lines; +y is the nose direction).
    """
    import ezdxf
    from ezdxf import units

    doc = ezdxf.new("R2010")
    doc.units = units.MM
    for name, color in (("CAM_PROFILE", 7), ("BASE_CIRCLE", 3), ("SEGMENTS", 1), ("AXES", 5)):
        doc.layers.add(name, color=color)
    msp = doc.modelspace()
    pts = (valve.contour / MM).T
    msp.add_lwpolyline([tuple(p) for p in pts], close=True, dxfattribs={"layer": "CAM_PROFILE"})
    heel = valve.heel_radius / MM
    msp.add_circle((0.0, 0.0), heel, dxfattribs={"layer": "BASE_CIRCLE"})
    reach = 1.2 * float(np.max(np.hypot(*pts.T)))
    msp.add_line((-reach, 0.0), (reach, 0.0), dxfattribs={"layer": "AXES"})
    msp.add_line((0.0, -reach), (0.0, reach), dxfattribs={"layer": "AXES"})
    for a in valve.law.breakpoints:
        k = int(np.argmin(np.abs(valve.contour_angle - a)))
        msp.add_line((0.0, 0.0), tuple(pts[k]), dxfattribs={"layer": "SEGMENTS"})
    doc.saveas(path)


def results_json(results):
    """results.json text."""
    return json.dumps(results.to_dict(), indent=2, default=_json_default, ensure_ascii=False)


def _json_default(x):
    if isinstance(x, np.generic):
        return x.item()
    if isinstance(x, np.ndarray):
        return x.tolist()
    raise TypeError(f"cannot write {type(x).__name__} to JSON")


def write_outputs(results, out, lang="en"):
    """Write every artefact of a design into the folder ``out``, atomically.

    Everything is written into a temporary sibling folder first and moved into place
    only when complete; an existing ``out`` is replaced in one rename.  A failure or an
    interruption leaves ``out`` as it was (absent, or the previous results).

    Layout::

        out/results.json
        out/tables/NAME_lift.csv
        out/contour/NAME.csv, NAME.dxf
        out/plots/NAME_kinematics.png, NAME_contour.png, NAME_time_area.png, NAME_curvature.png
        out/report.html
    """
    from .report import write_plots, write_report

    out = Path(out)
    if out.exists() and not out.is_dir():
        raise FileExistsError(f"--out {out}: exists and is not a folder")
    out.parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=f".{out.name}.", suffix=".tmp", dir=out.parent))
    try:
        for sub in ("tables", "contour", "plots"):
            (tmp / sub).mkdir()
        (tmp / "results.json").write_text(results_json(results), encoding="utf-8")
        for name, v in results.valves.items():
            write_csv(tmp / "tables" / f"{name}_lift.csv", lift_table_columns(v.table))
            write_csv(tmp / "contour" / f"{name}.csv", contour_columns(v))
            write_dxf(tmp / "contour" / f"{name}.dxf", v)
        plots = write_plots(results, tmp / "plots", lang)
        write_report(results, tmp / "report.html", plots, lang)
        _replace_dir(tmp, out)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    return out


def _replace_dir(new, out):
    if not out.exists():
        os.replace(new, out)
        return
    old = Path(tempfile.mkdtemp(prefix=f".{out.name}.", suffix=".old", dir=out.parent))
    os.replace(out, old / "previous")
    try:
        os.replace(new, out)
    except BaseException:
        os.replace(old / "previous", out)
        raise
    finally:
        shutil.rmtree(old, ignore_errors=True)
