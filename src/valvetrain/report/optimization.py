"""What ``valvetrain optimize`` writes besides the optimum's specification: the history of the search (table and
plot), the side-by-side comparison of the starting design and the optimum (table), and a report (HTML) that states
the constraints that bind and, for the power-polynomial cam, compares the optimum with its article."""

from html import escape
from typing import Any

from matplotlib.figure import Figure
import numpy as np

from ..bibliography import WORKS, cited_in
from ..laws.power_polynomial import ARTICLE_FULLNESS
from ..synthesis.objectives import shown_objective
from ..synthesis.optimize import BINDING
from ..locale import check_text
from .check_rows import check_note
from .names import quantity_text, unevaluated_text, unit_text


_MARGINS = ("spring reserve", "pressure angle", "concave radius", "rho_min", "contact stress", "max acceleration",
            "min acceleration", "seating velocity", "no jump", "spring design")

OPTIMIZE_TEXT = {
    "en": {
        "title": "Cam synthesis by optimisation", "key": "key", "start": "start", "optimum": "optimum",
        "bounds": "bounds", "quantity": "quantity", "unit": "unit", "range": "allowed", "margin": "relative margin",
        "state": "state", "fails": "fails", "binds": "binds", "holds": "holds", "none": "none",
        "method": ("The {objective} is maximised over the variables below by a differential evolution with the "
                   "limits as an exact penalty, then polished by SLSQP (UkrSURT Proceedings (2019); Shang Hanji "
                   "(1988), section 4.3). During the search the train and its spring are the starting design's; the "
                   "optimum is designed in full with its own spring and every limit is checked again on it, the "
                   "follower separation over a dynamics sweep (Shang Hanji (1988), chapter 3)."),
        "objective_fullness": "fullness of the valve lift diagram",
        "objective_time_area": "time-area of the whole opening, mm2 s",
        "objective_volumetric_efficiency": "volumetric efficiency, the mean over the breathing's speeds",
        "objective_torque": "indicated torque, the mean over the breathing's speeds, N m",
        "variables": "Variables", "comparison": "Starting design and optimum", "constraints": "Limits",
        "binding": "Limits that bind at the optimum", "history": "History of the search",
        "feasible": "within the limits", "infeasible": "outside the limits", "best": "best within the limits",
        "margins": {m: m for m in _MARGINS}, "evaluations": "evaluations",
        "relaxed": ("{quantity}: the starting design has {value:.4g} {unit} outside {range}; the limit is kept at the "
                    "start's value (no worse than the start)"),
        "article": "Comparison with UkrSURT Proceedings (2019)", "cam": "cam",
        "tappet_fullness": "fullness of the tappet lift over the valve-open part",
        "ours": "this optimum", "article_optimum": "the article's optimum (as printed)",
        "article_serial": "the serial cam (as printed)",
        "polydyne": "polydyne (2, 10, 18, 26, 34), same lift, ramp and angle (Valve-train practical works (n.d.))",
        "gain": "The optimum is {gain:.1f} % fuller than the polydyne.",
        "cost": "{n} evaluations, {s:.1f} s in all, {e:.1f} s of them in the evaluations.",
        "references": "References", "rows": {},
    },
    "ru": {
        "title": "Синтез профиля кулачка оптимизацией", "key": "параметр", "start": "исходный",
        "optimum": "оптимум", "bounds": "пределы", "quantity": "величина", "unit": "ед.", "range": "допустимо",
        "margin": "относительный запас", "state": "состояние", "fails": "не выполнено", "binds": "на границе",
        "holds": "выполнено", "none": "нет",
        "method": ("{objective} максимизируется по параметрам ниже дифференциальной эволюцией с ограничениями в виде "
                   "точного штрафа и уточняется методом SLSQP (UkrSURT Proceedings (2019); Shang Hanji (1988), "
                   "разд. 4.3). При поиске привод и пружина исходные; оптимум рассчитывается полностью, со своей "
                   "пружиной, и все ограничения проверяются на нём заново, отрыв толкателя по динамическому расчёту "
                   "в диапазоне частот (Shang Hanji (1988), гл. 3)."),
        "objective_fullness": "коэффициент полноты диаграммы подъёма клапана",
        "objective_time_area": "время-сечение всего открытия, мм²·с",
        "objective_volumetric_efficiency": "коэффициент наполнения, среднее по частотам вращения газообмена",
        "objective_torque": "индикаторный крутящий момент, среднее по частотам вращения газообмена, Н·м",
        "variables": "Параметры", "comparison": "Исходный вариант и оптимум", "constraints": "Ограничения",
        "binding": "Ограничения, определяющие оптимум", "history": "Ход поиска",
        "feasible": "в пределах ограничений", "infeasible": "вне ограничений", "best": "лучший в пределах",
        "margins": {"spring reserve": "запас пружины", "pressure angle": "угол давления",
                    "concave radius": "вогнутый радиус", "rho_min": "ρ_min",
                    "contact stress": "контактное напряжение", "max acceleration": "ускорение max",
                    "min acceleration": "ускорение min", "seating velocity": "скорость посадки",
                    "no jump": "отрыв толкателя", "spring design": "подбор пружины"},
        "evaluations": "число расчётов",
        "relaxed": ("{quantity}: у исходного варианта {value:.4g} {unit} вне пределов {range}; ограничение взято по "
                    "исходному значению (не хуже исходного)"),
        "article": "Сравнение с UkrSURT Proceedings (2019)", "cam": "кулачок",
        "tappet_fullness": "коэффициент полноты подъёма толкателя за время открытия клапана",
        "ours": "данный оптимум", "article_optimum": "оптимум статьи (по тексту)",
        "article_serial": "серийный кулачок (по тексту)",
        "polydyne": "полидинамический (2, 10, 18, 26, 34) того же подъёма, сбега и угла (Valve-train practical "
                    "works (n.d.))",
        "gain": "Полнота оптимума на {gain:.1f} % выше, чем у полидинамического кулачка.",
        "cost": "{n} расчётов, всего {s:.1f} с, из них {e:.1f} с в расчётах вариантов.",
        "references": "Литература",
        "rows": {"fullness": "коэффициент полноты", "time-area of the whole opening": "время-сечение всего открытия",
                 "time-area over the valve's stroke": "время-сечение за такт",
                 "tappet fullness (UkrSURT Proceedings (2019))": "полнота подъёма толкателя (UkrSURT Proceedings "
                 "(2019))", "max tappet acceleration": "наибольшее ускорение толкателя",
                 "min tappet acceleration": "наименьшее ускорение толкателя",
                 "max tappet velocity": "наибольшая скорость толкателя", "spring preload": "усилие пружины при "
                 "посадке", "spring rate": "жёсткость пружины", "spring reserve K_z": "коэффициент запаса K_з",
                 "rho_min": "ρ_min"},
    },
}
"""Texts of the optimisation's report (``valvetrain optimize``) and its history plot."""


def history_columns(result) -> dict[str, np.ndarray]:
    """The history as named columns: evaluation, objective, feasible (every margin >= 0), and each margin."""
    objective = np.array([h[0] for h in result.history])
    margins = np.array([h[1] for h in result.history]).reshape(len(result.history), len(result.margin_names))
    feasible = np.all(margins >= 0.0, axis=1)
    best = np.maximum.accumulate(np.where(feasible, objective, -np.inf))
    shown = shown_objective(result.objective, objective)
    out = {"evaluation": np.arange(1, objective.size + 1), f"{result.objective}": shown, "feasible": feasible,
           f"best_feasible_{result.objective}": np.where(np.isfinite(best), shown_objective(result.objective, best),
                                                         np.nan)}
    for i, name in enumerate(result.margin_names):
        out[f"margin_{name.replace(' ', '_')}"] = margins[:, i]
    return out


HISTORY_COMMENTS = ("valvetrain optimize: one row per evaluation of the search, in order",
                    "objective: fullness (-), time-area of the whole opening (mm2 s), or the breathing's volumetric "
                    "efficiency (-) or torque (N m), the mean over its speeds; margin_*: relative margin of a limit, "
                    ">= 0 when it holds")


def comparison_columns(result) -> dict[str, list[Any]]:
    """The side-by-side comparison as named columns."""
    rows = result.comparison
    return {"quantity": [r[0] for r in rows], "unit": [r[1] for r in rows], "start": [r[2] for r in rows],
            "optimum": [r[3] for r in rows]}


def history_figure(result, lang="en") -> Figure:
    """Objective (every evaluation, and the best feasible so far) and the constraints' margins against evaluations."""
    t = OPTIMIZE_TEXT[lang]
    cols = history_columns(result)
    n = cols["evaluation"]
    fig = Figure(figsize=(8, 7))
    top, bottom = fig.subplots(2, 1, sharex=True)
    y = cols[result.objective]
    top.plot(n[cols["feasible"]], y[cols["feasible"]], ".", ms=2, color="C0", label=t["feasible"])
    top.plot(n[~cols["feasible"]], y[~cols["feasible"]], ".", ms=2, color="0.7", label=t["infeasible"])
    top.plot(n, cols[f"best_feasible_{result.objective}"], color="C3", lw=1.2, label=t["best"])
    top.axhline(shown_objective(result.objective, result.start_value), color="k", lw=0.8, ls="--",
                label=t["start"])
    top.set_ylabel(t[f"objective_{result.objective}"])
    finite = y[y > 0]
    if finite.size:
        top.set_ylim(np.percentile(finite, 5) * 0.98, finite.max() * 1.01)
    top.legend(loc="lower right", fontsize=8)
    for i, name in enumerate(result.margin_names):
        bottom.plot(n, np.clip(cols[f"margin_{name.replace(' ', '_')}"], -1.0, 1.0), lw=0.6, label=t["margins"][name])
    bottom.axhline(0.0, color="k", lw=0.8)
    bottom.set_ylabel(t["margin"])
    bottom.set_xlabel(t["evaluations"])
    bottom.legend(loc="lower right", fontsize=7, ncol=2)
    for ax in (top, bottom):
        ax.grid(alpha=0.3)
    fig.tight_layout()
    return fig


def _table(head, rows):
    cells = "".join(f"<th>{escape(h)}</th>" for h in head)
    body = "".join("<tr>" + "".join(f"<td>{escape(str(c))}</td>" for c in row) + "</tr>" for row in rows)
    return f"<table><tr>{cells}</tr>{body}</table>"


def _g(x):
    return "" if x is None else f"{x:.5g}"


def _checked(c, lang):
    """The value of a check (its unit is the range's), or that it cannot be evaluated and why."""
    return _g(c.shown_value) if c.evaluated else unevaluated_text(c, lang)


def report_html(result, lang="en") -> str:
    """The optimisation's report in ``lang`` (HTML text): method, variables, comparison, constraints, history."""
    t = OPTIMIZE_TEXT[lang]
    start = {c.quantity: c for c in result.checks_start}
    parts = [f"<h1>{escape(t['title'])}: {escape(result.valve)}</h1>",
             f"<p>{escape(t['method'].format(objective=t[f'objective_{result.objective}']))}</p>"]
    parts.append(f"<h2>{escape(t['variables'])}</h2>")
    bounds = dict(zip(result.start, result.bounds, strict=True))
    parts.append(_table([t["key"], t["start"], t["optimum"], t["bounds"]],
                        [(k, _g(result.start[k]), _g(result.optimum[k]), f"{bounds[k][0]:g}...{bounds[k][1]:g}")
                         for k in result.start]))
    parts.append(f"<h2>{escape(t['comparison'])}</h2>")
    parts.append(_table([t["quantity"], t["unit"], t["start"], t["optimum"]],
                        [(t["rows"].get(q, q), unit_text(u, lang), _g(a), _g(b)) for q, u, a, b in result.comparison]))
    parts.append(f"<h2>{escape(t['constraints'])}</h2>")
    rows = []
    for c in result.checks:
        s = start.get(c.quantity)
        state = t["fails"] if not c.passed else t["binds"] if c.margin < BINDING else t["holds"]
        note = check_note(c, lang)
        shown_range = c.range.replace(c.unit, unit_text(c.unit, lang)) if c.unit else c.range
        rows.append((quantity_text(c, lang) + (f" ({note})" if note else ""),
                     _checked(s, lang) if s else "", _checked(c, lang), shown_range, f"{c.margin:.4f}", state))
    parts.append(_table([t["quantity"], t["start"], t["optimum"], t["range"], t["margin"], t["state"]], rows))
    binding = [quantity_text(c, lang) for c in result.binding]
    parts.append(f"<p>{escape(t['binding'])}: {escape(', '.join(binding) if binding else t['none'])}.</p>")
    for note in result.limit_notes:
        shown = {**note, "quantity": check_text(note["code"], {}, lang), "unit": unit_text(note["unit"], lang)}
        parts.append(f"<p>{escape(t['relaxed'].format(**shown))}</p>")
    if result.polydyne_fullness is not None:
        tappet = next(r for r in result.comparison if r[0].startswith("tappet fullness"))
        parts.append(f"<h2>{escape(t['article'])}</h2>")
        parts.append(_table([t["cam"], t["tappet_fullness"]], [
            (t["ours"], f"{tappet[3]:.4f}"), (t["article_optimum"], f"{ARTICLE_FULLNESS['optimum']:.3f}"),
            (t["article_serial"], f"{ARTICLE_FULLNESS['serial']:.3f}"),
            (t["polydyne"], f"{result.polydyne_fullness:.4f}")]))
        gain = tappet[3] / result.polydyne_fullness - 1.0
        parts.append(f"<p>{escape(t['gain'].format(gain=100 * gain))}</p>")
    parts.append(f"<h2>{escape(t['history'])}</h2><img src=\"history.png\" alt=\"history\">")
    parts.append(f"<p>{escape(t['cost'].format(n=result.evaluations, s=result.seconds, e=result.seconds_in_evaluations))}</p>")
    text = "\n".join(parts)
    works = [WORKS[k].reference() for k in cited_in(text)]
    refs = "".join(f"<li>{escape(w)}</li>" for w in works)
    return (f"<!DOCTYPE html><html lang=\"{lang}\"><head><meta charset=\"utf-8\"><title>{escape(t['title'])}</title>"
            "<style>body{font-family:sans-serif;max-width:60em;margin:2em auto}table{border-collapse:collapse}"
            "td,th{border:1px solid #bbb;padding:2px 6px;text-align:left}img{max-width:100%}</style></head><body>"
            f"{text}<h2>{escape(t['references'])}</h2><ol>{refs}</ol></body></html>\n")


__all__ = ["HISTORY_COMMENTS", "comparison_columns", "history_columns", "history_figure", "report_html"]
