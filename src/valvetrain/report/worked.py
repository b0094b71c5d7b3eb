"""Worked substitution for the calculation note: each main formula, the numbers put into it with their units, and the
result, so that a checker can follow a line with a pocket calculator.

The numbers are the design's own (its inputs and its typed results, as results.json shows them); the result printed is the design's, and
the substituted expression evaluates to it (``tests/report/test_worked.py`` evaluates every line).  Formulas: Valve-train practical works
(n.d.), works 1 and 6.
"""

from typing import Any

from ..design.results import shown_value
from .numbers import number
from .names import unit_text


def _line(symbol, formula, values, result, unit, lang):
    """One worked line: ``symbol = formula = values = result unit`` (values: (number, unit) pairs joined by the
    formula's operators, given as a format string with ``{}`` per number)."""
    def quantity(x, u):
        return number(x, lang) + ("°" if u == "deg" else f" {unit_text(u, lang)}" if u else "")

    text, numbers = values
    shown = text.format(*(quantity(x, u) for x, u in numbers))
    return {"symbol": symbol, "formula": formula, "substituted": shown,
            "result": f"{number(result, lang)} {unit_text(unit, lang)}".strip()}


def flow_lines(valve, flow, engine, lang="en") -> list[dict[str, Any]]:
    """The throat and curtain sections and the conditional gas velocities (Valve-train practical works (n.d.), work 1,
    eqs. (1.1)-(1.3)).

    Parameters
    ----------
    valve : dict
        The valve's inputs (``throat_diameter_mm`` [mm], ``seat_angle_deg`` [deg], ``count``).
    flow : valvetrain.design.valve.FlowResult
        The valve's flow stage (throat and curtain areas, V', V'', valve lift).
    engine : valvetrain.design.EngineRecord
        The engine's figures (mean piston speed, piston area).
    """
    def shown(result, *names):
        return [shown_value(result, n) for n in names]

    d, phi, i = valve["throat_diameter_mm"], valve["seat_angle_deg"], valve["count"]
    h, fg, fmax, v1, v2 = shown(flow, "valve_lift", "throat_area", "max_curtain_area", "v1", "v2")
    cp, fp = shown(engine, "mean_piston_speed", "piston_area")
    return [
        _line("f_g", "π d_g² / 4", ("π × ({})² / 4", [(d, "mm")]), fg, "mm2", lang),
        _line("f_max", "π h (d_g cos φ + h sin φ cos² φ)",
              ("π × {} × ({} × cos {} + {} × sin {} × cos² {})",
               [(h, "mm"), (d, "mm"), (phi, "deg"), (h, "mm"), (phi, "deg"), (phi, "deg")]),
              fmax, "mm2", lang),
        _line("V′", "c_p F_p / (i f_g)", ("{} × {} / ({} × {})", [(cp, "m/s"), (fp, "mm2"), (i, ""), (fg, "mm2")]),
              v1, "m/s", lang),
        _line("V″", "c_p F_p / (i f_max)", ("{} × {} / ({} × {})", [(cp, "m/s"), (fp, "mm2"), (i, ""),
                                                                   (fmax, "mm2")]),
              v2, "m/s", lang),
    ]


def spring_lines(spring, lang="en") -> list[dict[str, Any]]:
    """The spring's force at full lift, index and largest shear stress (Valve-train practical works (n.d.), works 5
    and 6): P_max = P_min + c f, C = D/d, tau_max = k 8 P_max D / (pi d^3), with k the shape factor of the design.

    Parameters
    ----------
    spring : valvetrain.design.drive.SpringRecord
        The designed spring (for a nested pair the outer spring's record with the pair's loads).
    """
    p0, c, fmax, fmin, pmax, d, dm, k, index, tau = (shown_value(spring, n) for n in (
        "preload", "rate", "max_deflection", "preload_deflection", "max_force", "wire_diameter", "mean_diameter",
        "shape_factor", "spring_index", "tau_max"))
    return [
        _line("P_max", "P_min + c h", ("{} + {} × {}", [(p0, "N"), (c, "N/mm"), (fmax - fmin, "mm")]), pmax, "N", lang),
        _line("C", "D / d", ("{} / {}", [(dm, "mm"), (d, "mm")]), index, "", lang),
        _line("τ_max", "k 8 P_max D / (π d³)", ("{} × 8 × {} × {} / (π × ({})³)",
                                                [(k, ""), (pmax, "N"), (dm, "mm"), (d, "mm")]),
              tau, "MPa", lang),
    ]
