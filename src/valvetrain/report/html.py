"""The HTML design report (Jinja2 template ``templates/report.html``): one file, its figures embedded."""

import base64

from jinja2 import Environment, PackageLoader, select_autoescape
import numpy as np

from .. import __version__
from ..design.dynamics import SOURCES as DYNAMICS_SOURCES
from ..design.results import record
from ..tables import lift_table_columns
from .i18n import SOURCES, TEXT

TABLE_COLUMNS = ["cam_deg", "crank_deg", "segment", "tappet_lift_mm", "tappet_velocity_m_s",
                 "tappet_acceleration_m_s2", "valve_lift_mm", "curtain_area_mm2", "time_area_mm2_s", "rho_mm"]
REPORT_STEP_DEG = 5.0
"""Step of the abridged lift table in the report [cam deg]."""

CAM_KEYS = ["phi_p0_deg", "ramp_deg", "ramp_height_mm", "tappet_lift_mm", "event_cam_deg", "nose_crank_deg",
            "camshaft_speed_rad_s", "max_velocity_m_s", "max_acceleration_m_s2", "min_acceleration_m_s2"]
GEOMETRY_KEYS = ["follower", "base_radius_mm", "heel_radius_mm", "rho_min_mm", "rho_min_cam_deg", "rho_max_mm",
                 "rho_max_cam_deg", "max_contact_offset_mm", "roller_radius_mm", "max_pressure_angle_deg",
                 "min_concave_radius_mm", "undercut"]
FLOW_KEYS = ["throat_area_mm2", "valve_lift_mm", "max_curtain_area_mm2", "V1_m_s", "V2_m_s"]
TIME_AREA_KEYS = ["stroke_crank_deg", "time_area_mm2_s", "time_area_open_mm2_s", "V3_m_s",
                  "mean_charge_velocity_m_s", "fullness"]


def fmt(x):
    """A number for a human: 6 significant digits; lists, booleans and text as they are."""
    if isinstance(x, bool):
        return str(x).lower()
    if isinstance(x, (int, float, np.floating)):
        return f"{float(x):.6g}"
    if isinstance(x, (list, tuple)):
        return ", ".join(fmt(v) for v in x)
    return "-" if x is None else str(x)


def _flatten(d, prefix=""):
    rows = []
    for k, v in d.items():
        if isinstance(v, dict):
            rows += _flatten(v, f"{prefix}{k}.")
        elif v is not None:
            rows.append((f"{prefix}{k}", v))
    return rows


def _abridged_table(valve):
    cols = lift_table_columns(valve.table)
    cam = cols["cam_deg"]
    keep = np.isclose(np.mod(cam, REPORT_STEP_DEG), 0.0) | np.isclose(np.mod(cam, REPORT_STEP_DEG),
                                                                        REPORT_STEP_DEG)
    keep[[0, -1]] = True
    return [[fmt(cols[c][i]) for c in TABLE_COLUMNS] for i in np.flatnonzero(keep)]


def _measured(rec):
    """The measured-table analysis for the report: scalars, durations at the checking heights, fit quality."""
    if rec is None:
        return None
    scalars = [(k, val) for k, val in rec.items() if not isinstance(val, (list, dict))]
    return {"summary": scalars, "durations": rec["durations_deg"], "quality": list(rec["fit_quality"].items())}


DYNAMICS_HEADLINE = ["speed_range_rpm", "speeds", "jump_speed_rpm", "bounce_speed_rpm", "max_seating_velocity_m_s",
                     "max_seating_velocity_speed_rpm", "coil_clash_speed_rpm", "epsilon", "natural_frequency_Hz"]


def _dynamics(rec):
    """The dynamics record for the report: headline rows, the train, the estimates, the rated speed, resonance."""
    if rec is None:
        return None
    params = rec["parameters"]
    return {"headline": [(k, rec[k]) for k in DYNAMICS_HEADLINE if k in rec],
            "parameters": [(k, val) for k, val in params.items() if k != "estimates" and not isinstance(val, dict)],
            "nodes": list(params.get("node_masses_kg", {}).items()), "estimates": params["estimates"],
            "rated": list(rec["at_rated_speed"].items()),
            "resonance": [(k, val) for k, val in rec["resonance"].items() if not k.startswith("spectrum")],
            "spectrum": list(zip(rec["resonance"]["spectrum_k"], rec["resonance"]["spectrum_distortion_percent"],
                                 strict=True)),
            "table": rec["sweep_table"], "revolutions": params["revolutions"]}


def _summary(results, t):
    """The report's first page: one row per valve and the limits not met."""
    rows = []
    for name, v in results.valves.items():
        s = v.summary
        spring = s["spring"]
        text = t["spring_text"].format(count=spring["count"], wire_mm=spring["wire_mm"],
                                       mean_diameter_mm=spring["mean_diameter_mm"],
                                       active_coils=spring["active_coils"], material=spring["material"])
        binding = spring["binding_check"]
        rows.append({"name": name, "kind": t[v.kind], "law": v.law.name, "lift": s["flow"]["valve_lift_mm"],
                     "opens": s["cam"]["valve_opens_crank_deg"], "closes": s["cam"]["valve_closes_crank_deg"],
                     "duration": s["cam"]["valve_closes_crank_deg"] - s["cam"]["valve_opens_crank_deg"],
                     "time_area": s["flow"]["time_area_mm2_s"], "fullness": s["flow"]["fullness"], "spring": text,
                     "binding": f"{binding} ({spring['margins'][binding]:+.0%})",
                     "failures": sum(c.severity == "failure" for c in v.warnings),
                     "warnings": sum(c.severity != "failure" for c in v.warnings)})
    return {"valves": rows, "failures": [c for c in results.warnings if c.severity == "failure"]}


def render_report(results, plots, lang="en", folder=None):
    """The report as HTML text.

    Parameters
    ----------
    results : valvetrain.design.DesignResults
    plots : dict
        ``{valve name: {figure kind: file name relative to plots/}}``.
    lang : {"en", "ru"}
    folder : Path, optional
        The output folder holding ``plots/``: the figures are embedded in the report (one file to mail); without
        it they are linked.
    """
    env = Environment(loader=PackageLoader("valvetrain", "report/templates"), autoescape=select_autoescape())
    env.filters["fmt"] = fmt
    env.filters["image"] = lambda name: _image(folder, name)
    spec = results.spec.model_dump()
    valves = []
    for name, v in results.valves.items():
        s = v.summary
        valves.append({
            "name": name, "valve": v, "summary": s, "plots": plots[name],
            "inputs": _flatten(spec["valves"][name]),
            "flow": [(k, s["flow"][k]) for k in FLOW_KEYS],
            "time_area": [(k, s["flow"][k]) for k in TIME_AREA_KEYS],
            "cam": [(k, s["cam"][k]) for k in CAM_KEYS],
            "geometry": [(k, s["cam"][k]) for k in GEOMETRY_KEYS if s["cam"].get(k) is not None],
            "coefficients": list(s["cam"]["coefficients"].items()),
            "seed": [(k, val, s["cam"][k]) for k, val in s["cam"].get("seed_formulas", {}).items()],
            "residuals": list(s["cam"].get("residuals", {}).items()),
            "measured": _measured(s["cam"].get("measured")),
            "clearance": list(s.get("piston_clearance", {}).items()),
            "masses": list(s["masses"].items()),
            "spring": [(k, val) for k, val in s["spring"].items() if not isinstance(val, dict)],
            "pair": [(t, s["spring"][k]) for k, t in (("outer", "outer_spring"), ("inner", "inner_spring"))
                     if k in s["spring"]],
            "strength": s["strength"],
            "table": _abridged_table(v),
            "warnings": v.warnings,
            "dynamics": _dynamics(s.get("dynamics")),
        })
    first_page = _summary(results, TEXT[lang])
    crank = None
    if results.crank is not None:
        summary = results.crank.summary
        crank = {"inputs": _flatten(spec["crank"]), "plots": plots["crank"],
                 "summary": [(k, v) for k, v in _flatten(summary) if k != "pressure_source"],
                 "pressure_source": summary["pressure_source"]}
    ports = None
    if results.two_stroke is not None:
        ports = {"inputs": [(k, v) for k, v in _flatten(spec["two_stroke"]) if not k.startswith("ports.")],
                 "plots": plots["two_stroke"], "ports": results.two_stroke.summary["ports"]}
    return env.get_template("report.html").render(
        t=TEXT[lang], lang=lang, version=__version__, engine=record(results.engine), engine_inputs=_flatten(spec["engine"]),
        valves=valves, warnings=results.warnings, first_page=first_page, timing=plots.get("(timing)"), sources=SOURCES,
        dynamics_sources=DYNAMICS_SOURCES, table_columns=TABLE_COLUMNS,
        step=REPORT_STEP_DEG, output=_flatten(spec["output"]), crank=crank, ports=ports,
    )


def _image(folder, name):
    """A figure of ``plots/`` as a data URI (PNG, base64) or, without a folder, as a relative link."""
    if folder is None:
        return f"plots/{name}"
    return "data:image/png;base64," + base64.b64encode((folder / "plots" / name).read_bytes()).decode("ascii")


def write_report(results, path, plots, lang="en"):
    """Write ``report.html`` with its figures embedded (``path``'s folder holds ``plots/``)."""
    path.write_text(render_report(results, plots, lang, path.parent), encoding="utf-8")
