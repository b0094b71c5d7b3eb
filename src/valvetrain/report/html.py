"""The HTML design report (Jinja2 template ``templates/report.html``): one file, its figures embedded."""

import base64
from dataclasses import fields, is_dataclass
from html import unescape

import re

from jinja2 import Environment, FileSystemBytecodeCache, PackageLoader, select_autoescape
from markupsafe import Markup
import numpy as np

from .. import __version__
from ..checks import tally
from ..design.dynamics import SOURCES as DYNAMICS_SOURCES
from ..design.grinding import SOURCES as GRINDING_SOURCES
from ..design.hydraulic_actuation import SOURCES as HYDRAULIC_SOURCES
from ..design.lash_adjuster import SOURCES as ADJUSTER_SOURCES
from ..design.lost_motion import SOURCES as LOST_MOTION_SOURCES
from ..design.camshaft import WORKS as CAMSHAFT_SOURCES
from ..design.lubrication import SOURCES as LUBRICATION_SOURCES
from ..design.results import NamedValues, shown, shown_value
from ..design.drive import spring_options
from ..specification.si import si
from ..tables import lift_table_columns
from ..bibliography import WORKS, corrections_notes
from ..units import to_display
from ..locale import verdict
from .engine_chapters import breathing_chapter, camshaft_chapter, flatten, phaser_chapters
from .check_rows import (chapter_checks, check_class, check_margin, check_name, check_note, check_range,
                         check_verdict, marked_citations, not_checked)
from .i18n import TEXT
from .numbers import number, percent
from .russian import russian_citations, russian_typography
from .typography import AND, CORRECTIONS, LOCATORS, typography
from .worked import crank_lines, flow_lines, law_lines, spring_lines, strength_lines, time_area_lines
from .switching import switching_chapters
from .symbols import INPUT_SYMBOLS, WARNING_SYMBOLS, symbol_legend
from .names import has_name, label, link_names, quantity_text, translate, unevaluated_text, unit_text, value_text
from ..locale.wording import diagnosis_text, fit_reason

TABLE_COLUMNS = ["cam_deg", "crank_deg", "segment", "tappet_lift_mm", "tappet_velocity_m_s",
                 "tappet_acceleration_m_s2", "valve_lift_mm", "curtain_area_mm2", "time_area_mm2_s", "rho_mm"]
REPORT_STEP_DEG = 10.0
"""Step of the abridged lift table in the report [cam deg]."""

CAM_FIELDS = ("main_half_angle", "ramp_angle", "ramp_height", "tappet_lift", "event", "nose", "cam_speed",
              "max_velocity", "max_acceleration", "min_acceleration")
"""The law stage's figures in the report's law table (:class:`valvetrain.design.valve.CamResult`)."""

BYTECODE_CACHES = {lang: FileSystemBytecodeCache(pattern=f"__jinja2_valvetrain_{lang}_%s.cache") for lang in TEXT}
"""The compiled template of each language, kept between runs in Jinja2's folder of the temporary directory
(compiling it is a fifth of a second of every run; a changed template is compiled again).  One per language: Jinja2
applies a filter to a literal when it compiles (``{{ "mm" | unit }}``), so a filter applied to a literal must depend
on the language alone (``fmt``, ``unit``), never on the run."""

FLOW_FIELDS = ("throat_area", "valve_lift", "max_curtain_area", "v1", "v2")
TIME_AREA_FIELDS = ("stroke", "time_area", "time_area_open", "v3", "charge_velocity", "fullness")
"""The flow stage's figures in the report's flow and time-area tables (:class:`valvetrain.design.valve.FlowResult`)."""


def fmt(x, lang="en") -> str:
    """A number for a human by :func:`number`'s rule; a list with commas (semicolons in Russian, whose decimal
    separator is the comma); yes/no; a text value in ``lang``; "-" for no value (None, or a number that is not
    finite: results.json's null)."""
    if isinstance(x, bool):
        return TEXT[lang]["yes" if x else "no"]
    if isinstance(x, (int, float, np.floating, np.integer)):
        return number(x, lang) if np.isfinite(x) else "-"
    if isinstance(x, (list, tuple)):
        return ("; " if lang == "ru" else ", ").join(fmt(v, lang) for v in x)
    return "-" if x is None else str(value_text(x, lang))


NAME_KEYS = ("name", "material", "table_file", "lift_file", "cd_file")
"""Keys whose values are names given by the designer (shown as they are, in every language)."""

CITE_KEYS = ("source", "gas_force_source")
"""Keys whose values cite a source (shown as they are: the bibliography's)."""


def cell(key, value, lang) -> str:
    """The value of a key for a table cell: names and citations as they are (marked), the rest by :func:`fmt`."""
    leaf = key.rsplit(".", 1)[-1]
    if leaf == "link_names":
        return link_names(value, lang)
    if leaf in NAME_KEYS and isinstance(value, str):
        return Markup('<span class="name">{}</span>').format(value)
    if leaf in CITE_KEYS and isinstance(value, str):
        text = translate(value, lang)
        return Markup('<span class="cite">{}</span>').format(value) if text == value else text
    return fmt(value, lang)


def check_value(c, lang) -> str:
    """The value of a :class:`~valvetrain.checks.Check` with its unit in ``lang``, or that it cannot be evaluated
    and why (:func:`~valvetrain.report.names.unevaluated_text`)."""
    if not c.evaluated:
        return unevaluated_text(c, lang)
    return f"{fmt(c.shown_value, lang)} {unit_text(c.unit, lang)}".rstrip()


def _quantity(check, lang, parts):
    """A check's quantity in ``lang``, the name of its part (a valve, a port) marked as a name."""
    text = quantity_text(check, lang)
    head, sep, rest = text.partition(": ")
    if sep and head in parts:
        return Markup('<span class="name">{}</span>: {}').format(head, rest)
    return text


def _coefficient_symbols(coefficients):
    """The symbols of a lift law's coefficient table (:class:`~valvetrain.results.NamedValues`)."""
    if "c11" in coefficients:
        return ["c_ij", "k_i", "K12"]
    if "C2" in coefficients:
        return ["h_max", "C_poly", "pqrs"]
    return ["coefficients"]


def _coefficients(coefficients, prefix=""):
    """The rows of a lift law's coefficient table: ``(name, value)``, a flank's own coefficients under its name."""
    rows = []
    for k, val in coefficients.items():
        rows += _coefficients(val, f"{prefix}{k}.") if isinstance(val, NamedValues) else [(f"{prefix}{k}", val)]
    return rows


def _rows(result, prefix=""):
    """The rows of a result read from its attributes in the order declared (:func:`shown`), a nested result's rows
    under its key (``textbook.max_velocity_m_s``), a flattened one's in its place; values that are None left out."""
    rows = []
    for f in fields(result):
        value = getattr(result, f.name)
        if "key" not in f.metadata or value is None:
            continue
        if is_dataclass(value):
            rows += _rows(value, prefix if f.metadata["flatten"] else f"{prefix}{f.metadata['key']}.")
        else:
            rows.append((prefix + f.metadata["key"], shown_value(result, f.name)))
    return rows


def _abridged_table(valve, lang):
    cols = lift_table_columns(valve.table)
    cam = cols["cam_deg"]
    keep = np.isclose(np.mod(cam, REPORT_STEP_DEG), 0.0) | np.isclose(np.mod(cam, REPORT_STEP_DEG),
                                                                        REPORT_STEP_DEG)
    keep[[0, -1]] = True
    return [[fmt(cols[c][i], lang) for c in TABLE_COLUMNS] for i in np.flatnonzero(keep)]


def _material(valve, spring):
    """The grade of a designed spring with the specification's overrides (G, rho, tau_-1, psi_tau) for its worked
    lines."""
    return next(m for m in spring_options(si(valve).spring).materials if m.grade == spring.material)


def _geometry(v):
    """The rows of the report's geometry table: the follower and the radii of the cam, the curvature, the contact
    (flat or roller), the undercut and a finger's linkage, those that exist."""
    rows = (shown(v.cam, "follower", "base_radius", "heel_radius")
            + shown(v.profile, "rho_min", "rho_min_angle", "rho_max", "rho_max_angle") + shown(v.profile.contact)
            + shown(v.profile, "undercut") + (shown(v.profile.finger) if v.profile.finger is not None else []))
    return [(k, val) for k, val in rows if val is not None]


def _seed(v):
    """The appendix formulas of a Kurz cam beside the profile's exact figures: ``(key, formula, exact)``."""
    formulas = v.records.seed_formulas
    if formulas is None:
        return []
    exact = dict(shown(v.cam, "max_velocity", "max_acceleration", "min_acceleration")
                 + shown(v.profile, "rho_min", "rho_max"))
    return [(k, val, exact[k]) for k, val in shown(formulas)]


def _measured(rec, lang):
    """The measured-table analysis (:class:`~valvetrain.laws.records.MeasuredRecord`) for the report: scalars (the
    fit's reason in the report's language), durations at the checking heights, fit quality."""
    if rec is None:
        return None
    hidden = ("durations", "fit_reason_code", "spline_smoothing", "gcv_ratio", "fit_quality")
    scalars = [(k, _fit_reason(rec, lang) if k == "fit_reason" else val)
               for k, val in shown(rec, *(f.name for f in fields(rec) if f.name not in hidden))]
    return {"summary": scalars, "durations": rec.durations, "quality": rec.fit_quality.items()}


def _fit_reason(rec, lang):
    """The fit a measured table used and why, from its codes in the report's language."""
    ratio = float("nan") if rec.gcv_ratio is None else rec.gcv_ratio if rec.fit == "harmonic" else 1.0 / rec.gcv_ratio
    return fit_reason(rec.fit, rec.harmonics, rec.fit_reason_code, ratio, rec.spline_smoothing, lang)


def _strength(st):
    """The strength chapter of a valve from its :class:`~valvetrain.design.drive_strength.StrengthResult`: the rows and the
    checks whose parts are not given (its checks are the chapter's, :func:`chapter_checks`)."""
    return {"rows": shown(st, nested=False), "not_checked": st.not_checked}


DYNAMICS_HEADLINE = ("speed_range", "speeds", "jump_speed", "bounce_speed", "max_seating_velocity",
                     "max_seating_velocity_speed", "coil_clash_speed", "epsilon", "natural_frequency",
                     "natural_frequencies", "max_revolutions", "unsettled_speeds", "unsettled_note")
"""The fields of :class:`~valvetrain.design.dynamics_records.DynamicsResult` in the head of the report's dynamics chapter."""


def _present(result, *names):
    """:func:`~valvetrain.design.results.shown` of the named fields of a result (every field without names), less
    those that results.json leaves out where they are None."""
    names = names or tuple(f.name for f in fields(result) if "key" in f.metadata)
    omitted = {f.name for f in fields(result) if f.metadata.get("omit_none") and getattr(result, f.name) is None}
    return [row for row, name in zip(shown(result, *names), names, strict=True) if name not in omitted]


def _except(result, *names):
    """The names of a result's fields in results.json less the named."""
    return tuple(f.name for f in fields(result) if "key" in f.metadata and f.name not in names)


def _dynamics(d):
    """The dynamics chapter of a valve from its :class:`~valvetrain.design.dynamics_records.DynamicsResult`: headline rows,
    their estimated errors, the train, the estimates, the rated speed, resonance."""
    if d is None:
        return None
    p, res = d.parameters, d.resonance
    return {"headline": _present(d, *DYNAMICS_HEADLINE), "accuracy": _present(d.accuracy),
            "parameters": _present(p, *_except(p, "estimates", "node_masses")),
            "nodes": [] if p.node_masses is None else list(shown_value(p, "node_masses").items()),
            "estimates": p.estimates, "rated": _present(d.at_rated_speed),
            "resonance": _present(res, *_except(res, "orders", "spectrum")),
            "spectrum": list(zip(res.orders, shown_value(res, "spectrum"), strict=True)),
            "table": d.sweep_table, "revolutions": p.revolutions}


def _grinding(name, v):
    """The grinding chapter of a valve: its rows (booleans and numbers; the table's file is listed with the
    master's files) and the files written for manufacture."""
    g = v.grinding
    if g is None:
        return None
    files = [] if v.profile.undercut or g.wear_table_file is None else [g.wear_table_file]
    if g.master_makeable and not v.profile.undercut:
        files += [f"contour/{name}_master.csv", f"contour/{name}_master_cartesian.csv", f"contour/{name}_master.dxf"]
    return {"rows": _present(g, *_except(g, "wear_table_file")), "files": files}


def _hydraulic(v):
    """The hydraulic chapter of a valve: its rows (the simulated speed), the notes on the defaults taken and the
    tables' files (the sweep is shown in its figure)."""
    h = v.hydraulic
    if h is None:
        return None
    gas = h.gas_force
    return {"rows": _present(h, *_except(h, "table_file", "sweep_table", "notes", "gas_force", "speed_range",
                                         "per_speed")),
            "gas_rows": [] if gas is None else [(f"gas_force.{k}", val) for k, val in _present(gas, *_except(gas, "source"))],
            "gas_source": None if gas is None else gas.source,
            "notes": h.notes, "table": h.table_file, "sweep_table": h.sweep_table}


def _lost_motion(v):
    """The lost-motion chapter of a valve: the full lift's rows, the table of the solenoid timings, the table's file."""
    lm = v.lost_motion
    if lm is None:
        return None
    return {"rows": [(k, val) for k, val in shown(lm) if k not in ("closings", "table", "breathing", "sweep")
                     and val is not None],
            "columns": [k for k, _ in shown(lm.closings[0])],
            "table": [[val for _, val in shown(c)] for c in lm.closings], "file": lm.table_file,
            "breathing_columns": [k for k, _ in shown(lm.breathing[0])] if lm.breathing else [],
            "breathing": [[val for _, val in shown(b)] for b in lm.breathing],
            "sweep_columns": [k for k, _ in shown(lm.sweep[0].closing, *LOST_MOTION_SWEEP)] if lm.sweep else [],
            "sweep": [[shown_value(c, "speed"), *(val for _, val in shown(c.closing, *LOST_MOTION_SWEEP))]
                      for c in lm.sweep or ()]}


LOST_MOTION_SWEEP = ("solenoid_opens", "valve_closes", "seating_velocity", "residual_lift")
"""The columns of the report's table of the lost-motion timings over the speed sweep after the speed (fields of
:class:`~valvetrain.design.lost_motion.Closing`)."""


LUBRICATION_COLUMNS = ("speed", "min_film", "min_lambda", "boundary", "mixed", "full", "mean_friction_torque",
                       "friction_power", "max_flash", "max_drive_torque")
"""The columns of the report's table of the cam contact against engine speed (fields of
:class:`~valvetrain.design.lubrication.LubricationPerSpeed`)."""


def _table(per_speed, columns):
    """A per-speed result's table: {"columns": the fields' results.json keys (the headings), "table": its rows}."""
    shown_columns = shown(per_speed, *columns)
    return {"columns": [k for k, _ in shown_columns],
            "table": list(zip(*(c for _, c in shown_columns), strict=True))}


def _lubrication(v):
    """The lubrication chapter of a valve: its headline rows and its table against engine speed."""
    lub = v.lubrication
    if lub is None:
        return None
    return {"rows": _present(lub, *_except(lub, "per_speed", "follower", "zero_entrainment")),
            "zero": shown_value(lub, "zero_entrainment"), **_table(lub.per_speed, LUBRICATION_COLUMNS)}


ADJUSTER_COLUMNS = ("speed", "leak_down", "valve_lash", "refill_share", "stiffness_at_valve", "pump_up", "pumped_up",
                    "held_open", "revolutions")
"""The columns of the report's table of the lash adjuster against engine speed (fields of
:class:`~valvetrain.design.lash_adjuster.LashAdjusterPerSpeed`)."""


def _lash_adjuster(v):
    """The lash-adjuster chapter of a valve: its headline rows and its table against engine speed."""
    adj = v.lash_adjuster
    if adj is None:
        return None
    return {"rows": _present(adj, *_except(adj, "per_speed", "location")), "location": adj.location,
            **_table(adj.per_speed, ADJUSTER_COLUMNS)}


def _summary(results, t):
    """The report's first page: one row per valve (its open failures, warnings and info, and its accepted checks),
    the limits not met (ranked) and the failures the specification accepts."""
    rows = []
    for name, v in results.valves.items():
        spring = v.drive.spring.design
        wire, mean, coils = (shown_value(spring, k) for k in ("wire_diameter", "mean_diameter", "active_coils"))
        text = t["spring_text"].format(count=v.drive.spring.count, wire_mm=wire, mean_diameter_mm=mean,
                                       active_coils=coils, material=spring.material)
        binding = spring.binding_check
        lang = t["lang"]
        opens, closes = shown_value(v.cam, "valve_opens"), shown_value(v.cam, "valve_closes")
        rows.append({"name": name, "kind": t[v.kind], "law": value_text(v.law.name, lang),
                     "lift": shown_value(v.flow, "valve_lift"), "opens": opens, "closes": closes,
                     "duration": closes - opens, "time_area": shown_value(v.flow, "time_area"),
                     "fullness": v.flow.fullness, "spring": text,
                     "binding": f"{label('spring.' + binding, lang)} ({percent(spring.margins[binding], lang)})",
                     **{key: sum(c.severity == level for c in v.warnings) for key, level in
                        (("failures", "failure"), ("warnings", "warning"), ("info", "info"))},
                     "accepted": len(v.accepted)})
    counts = tally(results.checks)
    return {"verdict": verdict(counts, t["lang"]), "open_failures": counts["failure"],
            "valves": rows, "failures": [c for c in results.warnings if c.severity == "failure"],
            "accepted_failures": [c for c in results.accepted if c.severity == "failure"]}


def _conclusions(results, t):
    """Per valve: the open checks in the verdict's words, the binding spring check and the three allowable limits
    met with the least margin (what binds the design)."""
    lang, out = t["lang"], []
    for name, v in results.valves.items():
        spring = v.drive.spring.design
        binding = spring.binding_check
        met = sorted((c for c in v.checks if c.passed and c.severity == "failure" and c.evaluated),
                     key=lambda c: c.margin)[:3]
        out.append({"name": name, "counts": verdict(tally(v.checks), lang)[1],
                    "binding": f"{label('spring.' + binding, lang)} ({percent(spring.margins[binding], lang)})",
                    "closest": [(c, percent(c.margin, lang)) for c in met]})
    return out


TOC_HEADING = re.compile(r"<h2( class=\"[^\"]*\")?>(.*?)</h2>", re.S)


def with_contents(page, title) -> str:
    """The report with a numbered anchor on every chapter (``h2``) and a table of contents at ``<!--toc-->``."""
    entries = []

    def anchor(m):
        entries.append(m.group(2))
        return f'<h2 id="ch{len(entries)}"{m.group(1) or ""}>{m.group(2)}</h2>'

    page = TOC_HEADING.sub(anchor, page)
    items = "".join(f'<li><a href="#ch{i}">{text}</a></li>' for i, text in enumerate(entries, 1))
    return page.replace("<!--toc-->", f'<nav id="toc"><h2 class="toc">{title}</h2><ol>{items}</ol></nav>', 1)


def render_report(results, plots, lang="en", folder=None) -> str:
    """The report as HTML text.

    Parameters
    ----------
    results : valvetrain.design.DesignResults
    plots : dict
        ``{valve name: {figure kind: file name relative to plots/}}`` of the figures drawn (the report names the
        command that draws the others).
    lang : {"en", "ru"}
    folder : Path or dict, optional
        The output folder holding ``plots/``, or the figures drawn in memory (``{filename: PNG bytes}``,
        :func:`valvetrain.report.plots.write_plots` into a dict): the figures are embedded in the report (one file
        to mail, :func:`embedded`); without it they are linked (``plots/NAME``), and the page rendered before they
        are drawn.
    """
    env = Environment(loader=PackageLoader("valvetrain", "report/templates"), autoescape=select_autoescape(),
                      bytecode_cache=BYTECODE_CACHES[lang])
    env.filters["fmt"] = lambda x: fmt(x, lang)
    env.filters["label"] = lambda key: label(key, lang)
    env.filters["named"] = lambda key: has_name(key)
    env.filters["unit"] = lambda unit: unit_text(unit, lang)
    env.filters["tr"] = lambda text: translate(text, lang)
    env.filters["range"] = lambda c: check_range(c, lang)
    env.filters["value"] = lambda c: check_value(c, lang)
    env.filters["not_checked"] = lambda note: not_checked(note, lang)
    env.filters["verdict"] = lambda c: check_verdict(c, lang)
    env.filters["margin"] = lambda c: check_margin(c, lang)
    env.filters["check_class"] = check_class
    env.filters["check_name"] = lambda c: check_name(c, lang)
    env.filters["check_note"] = lambda c: check_note(c, lang)
    env.filters["cited"] = marked_citations
    env.globals["cell"] = lambda key, value: cell(key, value, lang)
    env.globals["legend"] = symbol_legend(lang)
    env.filters["shown"] = shown_value
    env.globals["figure"] = lambda name, alt, part="": _figure(name, alt, TEXT[lang], part)
    env.globals["of_valve"] = lambda name: of_part("valve", name, lang)
    env.globals["of_port"] = lambda name: of_part("port", name, lang)
    env.filters["bare"] = lambda title: re.sub(r"^\d+\.\s*", "", title)
    env.filters["lowerfirst"] = lambda text: text[:1].lower() + text[1:]
    spec = results.spec.model_dump()
    parts = list(results.valves) + (list(results.two_stroke.figures.ports) if results.two_stroke is not None else [])
    env.filters["quantity"] = lambda c: _quantity(c, lang, parts)
    env.filters["diagnosis"] = lambda d: diagnosis_text(d, lang)
    valves, checks = [], chapter_checks(results)
    for name, v in results.valves.items():
        spring = v.drive.spring
        lift = lift_table_columns(v.table)
        valves.append({
            "name": name, "valve": v, "plots": plots.get(name, {}),
            "inputs": flatten(spec["valves"][name]),
            "worked_flow": flow_lines(results.spec.valves[name], v.flow, results.engine, lang),
            "worked_time_area": time_area_lines(v.flow, v.cam, results.engine, results.spec.valves[name].count, lift,
                                                lang),
            "worked_law": law_lines(v.law, v.cam, lang),
            "worked_spring": spring_lines(spring.design, _material(results.spec.valves[name], spring.design),
                                          shown_value(v.cam, "cam_speed"), lang),
            "worked_strength": strength_lines(results.spec.valves[name].parts, v.drive.strength, lift,
                                              shown_value(v.cam, "follower"), lang,
                                              to_display(v.cam.roller_radius, "mm")),
            "flow": shown(v.flow, *FLOW_FIELDS),
            "time_area": shown(v.flow, *TIME_AREA_FIELDS),
            "cam": shown(v.cam, *CAM_FIELDS),
            "steps": v.cam.acceleration_steps,
            "geometry": _geometry(v),
            "coefficients": _coefficients(v.cam.coefficients),
            "coefficient_symbols": _coefficient_symbols(v.cam.coefficients),
            "input_symbols": INPUT_SYMBOLS,
            "seed": _seed(v),
            "residuals": list((v.records.residuals or {}).items()),
            "measured": _measured(v.records.measured, lang),
            "clearance": [] if v.clearance is None else shown(v.clearance),
            "masses": shown(v.drive.masses),
            "spring": shown(spring, nested=False),
            "pair": [(t, _present(pair, *_except(pair, "margins")))
                     for pair, t in ((spring.outer, "outer_spring"), (spring.inner, "inner_spring")) if pair is not None],
            "no_spring_passes": not spring.design.passes_all_checks and spring.candidates_passing == 0,
            "strength": _strength(v.drive.strength),
            "table": _abridged_table(v, lang),
            "warnings": v.warnings,
            "dynamics": _dynamics(v.dynamics),
            "grinding": _grinding(name, v),
            "hydraulic": _hydraulic(v),
            "lost_motion": _lost_motion(v),
            "lubrication": _lubrication(v),
            "lash_adjuster": _lash_adjuster(v),
            "checks": checks[name],
        })
    first_page = _summary(results, TEXT[lang])
    crank = None
    if results.crank is not None:
        figures = results.crank.figures
        crank = {"inputs": flatten(spec["crank"]), "plots": plots.get("crank", {}),
                 "summary": [(k, v) for k, v in _rows(figures) if k != "pressure_source"],
                 "worked": crank_lines(figures, lang),
                 "pressure_source": figures.pressure_source}
    ports = None
    if results.two_stroke is not None:
        ports = {"inputs": [(k, v) for k, v in flatten(spec["two_stroke"]) if not k.startswith("ports.")],
                 "plots": plots.get("two_stroke", {}),
                 "ports": {name: shown(port) for name, port in results.two_stroke.figures.ports.items()}}
    breathing = breathing_chapter(results, spec, plots)
    warning_symbols = [key for key, codes in WARNING_SYMBOLS.items()
                       if any(w.code in codes for w in (*results.warnings, *results.accepted))]
    context = dict(
        t=TEXT[lang], warning_symbols=warning_symbols, lang=lang, version=__version__, engine=results.engine,
        engine_inputs=flatten(spec["engine"]), valves=valves, warnings=results.warnings, accepted=results.accepted,
        first_page=first_page, timing=plots.get("(timing)"), table_columns=TABLE_COLUMNS,
        engine_rows=shown(results.engine, "mean_piston_speed", "swept_volume", "displacement", "piston_area"),
        cam_card=results.cam_card,
        conclusions=_conclusions(results, TEXT[lang]), document=spec.get("document", {}), checks=checks[None],
        dynamics_sources=DYNAMICS_SOURCES, grinding_sources=GRINDING_SOURCES,
        hydraulic_sources=HYDRAULIC_SOURCES, lost_motion_sources=LOST_MOTION_SOURCES,
        lubrication_sources=LUBRICATION_SOURCES,
        adjuster_sources=ADJUSTER_SOURCES,
        step=REPORT_STEP_DEG, output=flatten(spec["output"]), crank=crank, ports=ports,
        camshaft=camshaft_chapter(results, spec, plots), camshaft_sources=CAMSHAFT_SOURCES, breathing=breathing,
        phasers=phaser_chapters(results, spec, plots, checks), switching=switching_chapters(results, checks, lang),
    )
    template = env.get_template("report.html")
    # the corrections notes the report cites, found in a first rendering
    first = unescape(template.render(corrections=[], **context))
    page = numbered_citations(template.render(corrections=cited_corrections(first, lang), **context), lang)
    page = with_contents(numbered_floats(page, lang), TEXT[lang]["toc"])
    page = typography(russian_citations(page) if lang == "ru" else page, lang)
    page = russian_typography(page) if lang == "ru" else page
    return page if folder is None else embedded(page, folder)


_SHORTS = {alternative: key for key, work in WORKS.items()
           for alternative in (work.short, str(Markup.escape(work.short)))}
CITATION = re.compile("(" + "|".join(re.escape(s) for s in sorted(_SHORTS, key=len, reverse=True)) + ")"
                      rf"((?:, {LOCATORS}(?:(?:, |{AND}){LOCATORS})*)?)")
"""A citation of a work by its in-text form (raw or HTML-escaped) and its locators."""

LANGUAGE_CODES = {"English": "en", "Russian": "ru", "Ukrainian": "uk", "Chinese": "zh-Latn", "German": "de"}
"""The language of a work's entry in the list of sources, for the browser (hyphenation) and the typography."""

_ALONE = re.compile(r'\((<span class="cite">)?(\[\d+[^\[\]()]*(?:\([^()]*\)[^\[\]()]*)*\])(</span>)?\)')
"""A numbered citation alone in brackets (or in a citation's span in brackets)."""

_KEPT_TEXT = re.compile(r'(<span class="name">.*?</span>|<style.*?</style>)', re.S)


def numbered_citations(page, lang) -> str:
    """The rendered report with every citation of a work (its in-text form and its locators) as its number in the
    list of sources, the number in the order of the first citation (GOST 7.32): ``Shang Hanji (1988), eq. (2.1)``
    -> ``[1, eq. (2.1)]``, a citation alone in brackets without them; and that list, each work in the form of GOST
    7.1 (:meth:`valvetrain.bibliography.Work.reference`), at ``<!--sources-->``.  Names the designer gave are
    left as they are.

    >>> page = "<p>(Shang Hanji (1988), eq. 2.3); Heywood (1988); Shang Hanji (1988), ch. 3 and ch. 7</p><!--sources-->"
    >>> print(numbered_citations(page, "en").split("<ol")[0])
    <p>[1, eq. 2.3]; [2]; [1, ch. 3 and ch. 7]</p>
    """
    numbers = {}

    def number(m):
        n = numbers.setdefault(_SHORTS[m.group(1)], len(numbers) + 1)
        return f"[{n}{', ' + m.group(2)[2:] if m.group(2) else ''}]"

    parts = _KEPT_TEXT.split(page)
    for i in range(0, len(parts), 2):
        parts[i] = _ALONE.sub(r"\1\2\3", CITATION.sub(number, parts[i]))
    items = "".join(f'<li value="{n}" lang="{LANGUAGE_CODES[WORKS[key].language]}">'
                    f'{Markup.escape(WORKS[key].reference(lang))}</li>' for key, n in numbers.items())
    return "".join(parts).replace("<!--sources-->", f'<ol class="bibliography">{items}</ol>', 1)


CORRECTIONS_CITED = re.compile(rf"{CORRECTIONS} (\d+)(?:-(\d+))?")


def cited_corrections(text, lang) -> list[tuple[int, str, str]]:
    """The corrections notes ``text`` cites ("corrections note 20", "поправка 20", "corrections notes 42-45"), in
    ``lang``: ``[(N, title, text)]`` by number."""
    numbers = set()
    for a, b in CORRECTIONS_CITED.findall(text):
        numbers.update(range(int(a), int(b or a) + 1))
    notes = corrections_notes(lang)
    return [(n, *notes[n]) for n in sorted(numbers) if n in notes]


TALL_FIGURES = ("_kinematics.png",)
"""Figures of several stacked axes: printed taller than the others (the print style's ``img.tall``)."""


def _figure(name, alt, t, part=""):
    """A figure of ``plots/``: its ``<img>``, linked (:func:`embedded` embeds it), and its caption (``alt`` and the
    part it shows, ``part``; :func:`numbered_floats` numbers it), or where it was not drawn (``name`` undefined: not
    asked for, not in :data:`valvetrain.report.plots.MAIN_FIGURES`) the command that draws it."""
    if not name:
        return Markup('<p class="src">{} <span class="name">valvetrain run --figures all</span></p>').format(
            t["figure_on_request"].format(alt))
    tall = Markup(' class="tall"') if name.endswith(TALL_FIGURES) else ""
    return Markup('<figure><img src="plots/{}" alt="{}"{}><figcaption>{}{}</figcaption></figure>').format(
        name, alt, tall, alt[:1].upper() + alt[1:], part)


def of_part(kind, name, lang) -> Markup:
    """``, valve "intake"`` (``, клапан «intake»``): the part of the engine a caption's table or figure shows, the
    name as a name."""
    quoted = '«<span class="name">{}</span>»' if lang == "ru" else '"<span class="name">{}</span>"'
    return Markup(", {} " + quoted).format(TEXT[lang][f"part_{kind}"], name)


FLOATS = re.compile(r'<p class="tcap">|<figcaption>|<h2 class="appendix"')
"""Where a table's caption (above it) or a figure's (below it) begins, and the appendix."""

_SECTION = re.compile(r"(<h[23][^>]*>.*?</h[23]>)", re.S)
_FLOAT_ID = re.compile(r'id="(table|figure)-([^"]+)"')


def numbered_floats(page, lang) -> str:
    """The rendered report with its tables and figures numbered (GOST 2.105): "Table 3 – ..." above a table,
    "Figure 2 – ..." below a figure ("Таблица", "Рисунок"), each kind in its own sequence, those of the appendix
    with its letter ("Table A.1"); and in every chapter and section that has any, under its heading, the sentence
    that refers to them ("See tables 3–5 and figure 2.").

    >>> page = ('<h3>Flow</h3><p class="tcap">Flow sections</p><table></table><figure><img src="plots/a.png" alt="">'
    ...         '<figcaption>Lift</figcaption></figure><h2 class="appendix">Appendix A</h2><p class="tcap">Input</p>')
    >>> print(numbered_floats(page, "en").replace("><", ">\\n<"))
    <h3>Flow</h3>
    <p class="refs">See <a href="#table-1">table 1</a> and <a href="#figure-1">figure 1</a>.</p>
    <p class="tcap" id="table-1">Table 1 – Flow sections</p>
    <table>
    </table>
    <figure>
    <img src="plots/a.png" alt="">
    <figcaption id="figure-1">Figure 1 – Lift</figcaption>
    </figure>
    <h2 class="appendix">Appendix A</h2>
    <p class="refs">See <a href="#table-A.1">table A.1</a>.</p>
    <p class="tcap" id="table-A.1">Table A.1 – Input</p>
    """
    t = TEXT[lang]
    counts, prefix = {"table": 0, "figure": 0}, ""

    def number(m):
        nonlocal prefix
        if m.group().startswith("<h2"):
            counts.update(table=0, figure=0)
            prefix = t["appendix_letter"] + "."
            return m.group()
        kind = "table" if "tcap" in m.group() else "figure"
        counts[kind] += 1
        label = f"{prefix}{counts[kind]}"
        return f'{m.group()[:-1]} id="{kind}-{label}">{t[kind + "_word"]} {label} – '

    parts = _SECTION.split(FLOATS.sub(number, page))
    for i in range(1, len(parts), 2):
        found = {"table": [], "figure": []}
        for kind, number_id in _FLOAT_ID.findall(parts[i + 1]):
            found[kind].append(number_id)
        refs = [_refs(kind, found[kind], t) for kind in ("table", "figure") if found[kind]]
        if refs:
            parts[i] += '<p class="refs">' + t["see"].format(f" {t['and']} ".join(refs)) + "</p>"
    return "".join(parts)


def _refs(kind, labels, t) -> str:
    """``table 3``, ``tables 3–5``, ``tables 3, 7`` (the labels of one kind in a section), each number a link."""
    def link(label):
        return f'<a href="#{kind}-{label}">{label}</a>'

    runs, start = [], 0
    for k in range(1, len(labels) + 1):
        if k == len(labels) or _index(labels[k]) != _index(labels[k - 1]) + 1:
            a, b = labels[start], labels[k - 1]
            runs.append(link(a) if a == b else f"{link(a)}, {link(b)}" if k - start == 2 else f"{link(a)}–{link(b)}")
            start = k
    word = t[f"{kind}_ref"][len(labels) > 1]
    if len(labels) == 1:
        return f'<a href="#{kind}-{labels[0]}">{word} {labels[0]}</a>'
    return f"{word} {', '.join(runs)}"


def _index(label) -> int:
    """The number of a table's or figure's label (``3``, ``A.3``)."""
    return int(label.rsplit(".", 1)[-1])


FIGURE_LINK = re.compile(r'<img src="plots/([^"]*)"')
"""The source of a figure's ``<img>`` linked by :func:`_figure`: the file's name in ``plots/`` (HTML-escaped)."""


def embedded(page, folder) -> str:
    """``page`` (:func:`render_report` without a folder) with each figure it links embedded as a data URI (PNG,
    base64) from ``folder``: the output folder holding ``plots/``, or a dict ``{filename: PNG bytes}``."""
    def image(m):
        name = unescape(m.group(1))
        png = folder[name] if isinstance(folder, dict) else (folder / "plots" / name).read_bytes()
        return '<img src="data:image/png;base64,' + base64.b64encode(png).decode("ascii") + '"'

    return FIGURE_LINK.sub(image, page)


def write_report(results, path, plots, lang="en") -> None:
    """Write ``report.html`` with its figures embedded (``path``'s folder holds ``plots/``)."""
    path.write_text(render_report(results, plots, lang, path.parent), encoding="utf-8")
