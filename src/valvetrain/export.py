"""Writing results: JSON, CSV tables, contour CSV and DXF, and the whole output folder atomically."""

from contextlib import nullcontext
import csv
from functools import partial
import io
import json
import math
from pathlib import Path

import numpy as np

from .design.dynamics_records import sweep_columns
from .design.grinding import master_cartesian_columns, master_polar_columns, wear_columns
from .design.hydraulic_actuation import sweep_columns as hydraulic_sweep_columns, table_columns as hydraulic_columns
from .design.lost_motion import table_columns as lost_motion_columns
from .outfolder import atomic_folder
from .specification import spec_toml
from .tables import (breathing_columns, breathing_record_columns, camshaft_torsion_columns, cartesian_contour_columns,
                     contour_columns, crank_columns, engine_torque_columns, lift_export_columns, lift_export_comments,
                     lift_table_columns, polar_contour_columns, strength_speed_columns, two_stroke_columns,
                     two_stroke_speed_columns)
from .units import MM

def _cell(x):
    if isinstance(x, str):
        return x
    if x is None:
        return ""
    if isinstance(x, bool):
        return str(x).lower()
    return _number(float(x))


def _number(x):
    """A float's cell: 10 significant digits, empty where it is not finite."""
    return f"{x:.10g}" if math.isfinite(x) else ""


def _cells(column):
    """The cells of a column (:func:`_cell` of each value); an array of floats converted to Python floats at once."""
    if isinstance(column, np.ndarray) and column.dtype.kind == "f":
        return [_number(x) for x in column.tolist()]
    return [_cell(x) for x in column]


def write_csv(path, columns, comments=()) -> None:
    """Write equal-length columns (a dict name -> sequence) as a CSV file with a header row, after ``comments``
    (lines written with a leading ``# ``).

    Numbers are written with 10 significant digits; a quantity that is not finite (the infinite
    radius of curvature of a straight flank) or None is an empty cell, never ``inf`` or ``nan``; booleans are
    ``true`` and ``false``."""
    names = list(columns)
    with open(path, "w", newline="", encoding="utf-8") as fh:
        fh.writelines(f"# {line}\n" for line in comments)
        w = csv.writer(fh)
        w.writerow(names)
        w.writerows(zip(*(_cells(columns[n]) for n in names), strict=True))


def write_dxf(path, valve) -> None:
    """Write the cam contour as DXF (millimetres).

    Layers: ``CAM_PROFILE`` (closed polyline of the contour), ``BASE_CIRCLE`` (the heel
    circle), ``RAMP_BOUNDARIES`` and ``SEGMENT_BOUNDARIES`` (radial lines to the ends of
    the ramps and to the other junctions of the lift-law segments), ``AXES`` (centre lines;
    +y is the nose direction).

    The file is reproducible: ezdxf's fixed metadata (creation date, GUIDs) replaces the clock
    and random identifiers, so the same design writes the same bytes.
    """
    _save_dxf(lambda: _dxf_document(valve), path)


def dxf_bytes(valve) -> bytes:
    """The cam contour as DXF: the bytes :func:`write_dxf` writes, written nowhere (the designer's download)."""
    stream = io.StringIO()
    _save_dxf(lambda: _dxf_document(valve), stream)
    return stream.getvalue().encode("utf-8")


def _save_dxf(build, path):
    """Build a DXF document (``build()``) and save it with ezdxf's fixed metadata (creation date, GUIDs) in place
    from its creation on, so the same design writes the same bytes.

    ``path`` is a file's path or a text stream.

    ezdxf registers the CLASS entries of the entity types in use when it saves, in the order of a set, which
    follows the interpreter's string hashing (PYTHONHASHSEED): registered here first, the required classes in
    ezdxf's order and the types in use sorted by name, they are written in that order whatever the seed."""
    import ezdxf
    from ezdxf.sections.classes import REQ_R2004, REQUIRED_CLASSES

    fixed = ezdxf.options.write_fixed_meta_data_for_testing
    ezdxf.options.write_fixed_meta_data_for_testing = True
    try:
        doc = build()
        for name in (*REQUIRED_CLASSES.get(doc.dxfversion, REQ_R2004), *sorted(doc.entitydb.dxf_types_in_use())):
            doc.classes.add_class(name)
        if isinstance(path, io.TextIOBase):
            doc.write(path)
        else:
            doc.saveas(path)
    finally:
        ezdxf.options.write_fixed_meta_data_for_testing = fixed


def write_master_dxf(path, grinding) -> None:
    """Write the master cam of a valve's grinder as DXF (millimetres).

    Layers: ``MASTER_PROFILE`` (closed polyline of the master contour), ``MASTER_BASE_CIRCLE`` (its heel
    circle), ``AXES`` (centre lines; +y is the direction of the cam nose, the master turns with the cam).
    """
    _save_dxf(lambda: _master_document(grinding), path)


def _profile_document(contour, heel, layers):
    """A DXF document in mm with ``layers`` (name, colour), the closed ``contour`` (2, n) [m] on the first layer,
    the heel circle of radius ``heel`` [m] on the second and centre lines on ``AXES``; and its points [mm]."""
    import ezdxf
    from ezdxf import units

    doc = ezdxf.new("R2010")
    doc.units = units.MM
    for name, color in layers:
        doc.layers.add(name, color=color)
    msp = doc.modelspace()
    pts = (contour / MM).T
    msp.add_lwpolyline([tuple(p) for p in pts], close=True, dxfattribs={"layer": layers[0][0]})
    msp.add_circle((0.0, 0.0), heel / MM, dxfattribs={"layer": layers[1][0]})
    reach = 1.2 * float(np.max(np.hypot(*pts.T)))
    msp.add_line((-reach, 0.0), (reach, 0.0), dxfattribs={"layer": "AXES"})
    msp.add_line((0.0, -reach), (0.0, reach), dxfattribs={"layer": "AXES"})
    return doc, pts


def _master_document(grinding):
    return _profile_document(grinding.master_contour, grinding.master_base_radius,
                             (("MASTER_PROFILE", 7), ("MASTER_BASE_CIRCLE", 3), ("AXES", 5)))[0]


def _dxf_document(valve):
    doc, pts = _profile_document(valve.contour, valve.heel_radius,
                                 (("CAM_PROFILE", 7), ("BASE_CIRCLE", 3), ("RAMP_BOUNDARIES", 6),
                                  ("SEGMENT_BOUNDARIES", 1), ("AXES", 5)))
    msp = doc.modelspace()
    ramps = {s.end if "opening" in s.name else s.start for s in valve.law.segments if s.name.startswith("ramp")}
    for a in valve.law.breakpoints:
        k = int(np.argmin(np.abs(valve.contour_angle - a)))
        layer = "RAMP_BOUNDARIES" if any(np.isclose(a, r) for r in ramps) else "SEGMENT_BOUNDARIES"
        msp.add_line((0.0, 0.0), tuple(pts[k]), dxfattribs={"layer": layer})
    return doc


def results_json(results) -> str:
    """results.json text."""
    return json_text(results.to_dict())


def json_text(data) -> str:
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


MASTER_COMMENTS = [
    "master cam of the copy grinder against the spindle angle (from the cam nose direction towards +x) [deg]",
    "wheel_centre_radius_mm: distance of the wheel centre from the cam axis; master_follower_lift_mm: bar ratio x "
    "its travel; master_radius_mm: polar radius of the master contour; master_flat_lift_mm: lift of a flat face "
    "on the master (surface grinder), empty where the master is concave",
]
"""Comment lines of ``contour/NAME_master.csv``."""


def write_dxf_files(results, folder) -> None:
    """Write the DXF files of ``results`` into ``folder`` (the output's ``contour/``): ``NAME.dxf``, the cam contour
    of each valve whose profile is not undercut (:func:`write_dxf`), and ``NAME_master.dxf``, the master cam of a
    ``[grinding]`` section whose wheel grinds the cam (:func:`write_master_dxf`)."""
    for name, v in results.valves.items():
        if v.profile.undercut:
            continue  # no follower can trace an undercut profile: nothing is written for its manufacture
        if v.grinding is not None and v.grinding.master_makeable:
            write_master_dxf(folder / f"{name}_master.dxf", v.grinding)
        write_dxf(folder / f"{name}.dxf", v)


DRAWER_IMPORTS = ("ezdxf",)
"""The modules that :func:`write_outputs` has the drawing process use beside matplotlib (it writes the DXF files,
:func:`write_dxf_files`): imported there while the design runs (:func:`valvetrain.report.drawing.start`), a third of
a second taken off the writing."""


def write_outputs(results, out, lang="en", inputs=(), force=False, figures="main", drawer=None) -> Path:
    """Write every artefact of a design into the folder ``out``, atomically.

    ``figures`` says which plots are drawn (:data:`valvetrain.report.plots.FIGURE_SETS`): ``main`` (those of
    :data:`valvetrain.report.plots.MAIN_FIGURES`), ``all`` or ``none``; the report embeds those drawn and names the
    command that draws the others.  ``drawer``, a :class:`valvetrain.report.drawing.FigureProcess`, draws them and
    writes the DXF files in its processes while this one writes the rest (it is ended on leaving); without it they
    are drawn and written here.

    Everything is written into a temporary sibling folder first and put in place only
    when complete (:func:`valvetrain.outfolder.atomic_folder`, which also says which
    folders may be replaced: ``inputs`` are the files the run read, ``force`` allows
    replacing a folder with files no valvetrain run wrote).  A failure or an interruption
    leaves ``out`` as it was (absent, or the previous results).

    Layout::

        out/results.json, spec.toml (the specification as run, every default written out)
        out/tables/NAME_lift.csv, NAME_strength.csv (one row per engine speed of the strength checks),
                   crank.csv, engine_torque.csv, two_stroke_ports.csv, two_stroke_time_area.csv,
                   camshaft_torsion.csv (a [camshaft] section: one row per engine speed),
                   breathing_condition_N.csv (the converged cycle of the N-th [[breathing.conditions]] every crank
                   degree), breathing_conditions.csv, breathing_curve.csv (their figures, one row a condition),
                   NAME_dynamics.csv (a [dynamics] section: one row per speed),
                   NAME_wear_error.csv (a [grinding] section: the lift error of the worn wheel)
                   NAME_hydraulic.csv (a [hydraulic] section: pressures and lifts against camshaft angle),
                   NAME_hydraulic_sweep.csv (a [hydraulic] section: one row per engine speed),
                   NAME_lost_motion.csv (a [hydraulic.lost_motion] section: the valve lift and the pressures of
                   each solenoid timing against camshaft angle)
        out/contour/NAME.csv, NAME_polar.csv, NAME_cartesian.csv, NAME_lift.csv, NAME.dxf
                    (not for a valve whose cam profile is undercut: it cannot be made)
                    NAME_master.csv, NAME_master_cartesian.csv, NAME_master.dxf (a [grinding] section whose
                    wheel grinds the cam and whose master its roller follows)
        out/plots/NAME_kinematics.png, NAME_contour.png, NAME_time_area.png (figures="all"),
                  NAME_curvature.png (all), NAME_spring.png (all), NAME_strength_speed.png (all),
                  NAME_dynamics_map.png (all), NAME_dynamics_speed.png (a [dynamics] section),
                  NAME_grinding.png (a [grinding] section),
                  NAME_hydraulic.png, NAME_hydraulic_sweep.png (all) (a [hydraulic] section),
                  crank_forces.png (all), crank_torque.png, crank_pin_polar.png (all),
                  two_stroke_ports.png, two_stroke_time_area.png (all), valve_timing.png,
                  breathing_pv.png, breathing_speed.png (two speeds or more),
                  NAME_phaser.png (a [phaser] section with [breathing])
        out/report.html
        out/.valvetrain-output (the files the run wrote)
    """
    from .report.drawing import figure_inputs

    with atomic_folder(out, inputs, force) as tmp, (drawer or nullcontext()):
        for sub in ("tables", "contour", "plots"):
            (tmp / sub).mkdir()
        if drawer is not None and figures != "none":
            drawn = figure_inputs(results, figures)
            drawer.submit(drawn, tmp / "plots", lang, figures,
                          also=partial(write_dxf_files, drawn, tmp / "contour"))   # the drawer has imported ezdxf
        else:
            write_dxf_files(results, tmp / "contour")
        (tmp / "results.json").write_text(results_json(results), encoding="utf-8")
        (tmp / "spec.toml").write_text(spec_toml(results.spec), encoding="utf-8")
        for name, v in results.valves.items():
            write_csv(tmp / "tables" / f"{name}_lift.csv", lift_table_columns(v.table))
            write_csv(tmp / "tables" / f"{name}_strength.csv", strength_speed_columns(v.drive.strength))
            if v.dynamics is not None:
                write_csv(tmp / v.dynamics.sweep_table, sweep_columns(v.dynamics))
            if v.hydraulic is not None:
                write_csv(tmp / v.hydraulic.table_file, hydraulic_columns(v.hydraulic))
                write_csv(tmp / v.hydraulic.sweep_table, hydraulic_sweep_columns(v.hydraulic))
            if v.lost_motion is not None:
                write_csv(tmp / v.lost_motion.table_file, lost_motion_columns(v.lost_motion))
            if v.profile.undercut:
                continue  # no follower can trace an undercut profile: nothing is written for its manufacture
            g = v.grinding
            if g is not None and g.wear is not None:
                write_csv(tmp / g.wear_table_file, wear_columns(g))
            if g is not None and g.master_makeable:   # no master for a wheel that cannot grind the cam
                write_csv(tmp / "contour" / f"{name}_master.csv", master_polar_columns(g), MASTER_COMMENTS)
                write_csv(tmp / "contour" / f"{name}_master_cartesian.csv", master_cartesian_columns(g))
            write_csv(tmp / "contour" / f"{name}.csv", contour_columns(v))
            step = results.spec.output.export_step_deg
            write_csv(tmp / "contour" / f"{name}_polar.csv", polar_contour_columns(v, step))
            write_csv(tmp / "contour" / f"{name}_cartesian.csv", cartesian_contour_columns(v, step))
            write_csv(tmp / "contour" / f"{name}_lift.csv", lift_export_columns(v, step), lift_export_comments(v))
        if results.crank is not None:
            write_csv(tmp / "tables" / "crank.csv", crank_columns(results.crank))
            write_csv(tmp / "tables" / "engine_torque.csv", engine_torque_columns(results.crank))
        if results.camshaft is not None:
            write_csv(tmp / results.camshaft.figures.response.table, camshaft_torsion_columns(results.camshaft))
        if results.two_stroke is not None:
            write_csv(tmp / "tables" / "two_stroke_ports.csv", two_stroke_columns(results.two_stroke))
            write_csv(tmp / "tables" / "two_stroke_time_area.csv", two_stroke_speed_columns(results.two_stroke))
        if results.breathing is not None:
            for i, r in enumerate(results.breathing.conditions, start=1):
                write_csv(tmp / "tables" / f"breathing_condition_{i}.csv", breathing_columns(r))
            for name, part in (("conditions", results.breathing.conditions), ("curve", results.breathing.curve)):
                if part:
                    write_csv(tmp / "tables" / f"breathing_{name}.csv",
                              breathing_record_columns([r.figures for r in part]))
        from .report.html import embedded, render_report, write_report

        if figures != "none" and drawer is not None:
            page = render_report(results, drawer.names(), lang)   # while the drawers draw, the figures linked
            drawer.result()
            (tmp / "report.html").write_text(embedded(page, tmp), encoding="utf-8")
        else:
            plots = {}
            if figures != "none":   # the plots import matplotlib
                from .report import write_plots

                plots = write_plots(results, tmp / "plots", lang, figures)
            write_report(results, tmp / "report.html", plots, lang)
    return Path(out)


def write_sweep(designs, out, lang="en", inputs=(), force=False) -> Path:
    """Write the speed sweeps of ``designs`` (name -> ValveDesign with dynamics) into ``out``, atomically.

    Layout::

        out/dynamics.json (valves.NAME: the dynamics record of results.json)
        out/tables/NAME_dynamics.csv (one row per speed)
        out/plots/NAME_dynamics_map.png, NAME_dynamics_speed.png
        out/.valvetrain-output (the files the run wrote)
    """
    from . import __version__
    from .design.results import record
    from .report.i18n import TEXT
    from .report.plots import write_dynamics_plots

    with atomic_folder(out, inputs, force) as tmp:
        for sub in ("tables", "plots"):
            (tmp / sub).mkdir()
        data = {"valvetrain_version": __version__, "valves": {}}
        for name, v in designs.items():
            data["valves"][name] = record(v.dynamics)
            write_csv(tmp / v.dynamics.sweep_table, sweep_columns(v.dynamics))
            write_dynamics_plots(name, v.dynamics, tmp / "plots", TEXT[lang])
        (tmp / "dynamics.json").write_text(json_text(data), encoding="utf-8")
    return Path(out)
