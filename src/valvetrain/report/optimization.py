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
from ..locale import catalogue, check_text
from .check_rows import check_note, check_range
from .names import quantity_text, unevaluated_text, unit_text


_MARGINS = ("spring reserve", "pressure angle", "concave radius", "rho_min", "contact stress", "max acceleration",
            "min acceleration", "seating velocity", "no jump", "spring design")


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
    t = catalogue(lang)["optimize_words"]
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
    t = catalogue(lang)["optimize_words"]
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
        rows.append((quantity_text(c, lang) + (f" ({note})" if note else ""),
                     _checked(s, lang) if s else "", _checked(c, lang), check_range(c, lang), f"{c.margin:.4f}", state))
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
