"""Worked substitution for the calculation note: each main formula, the numbers put into it with their units, and the
result, so that a checker can follow a line with a pocket calculator.

The numbers are the design's own (its inputs and its results.json record); the result printed is the design's, and
the substituted expression evaluates to it (``tests/test_worked.py`` evaluates every line).  Formulas: Valve-train practical works
(n.d.), works 1 and 6.
"""

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


def flow_lines(valve, flow, engine, lang="en"):
    """The throat and curtain sections and the conditional gas velocities (Valve-train practical works (n.d.), work 1,
    eqs. (1.1)-(1.3)).

    Parameters
    ----------
    valve : dict
        The valve's inputs (``throat_diameter_mm``, ``seat_angle_deg``, ``count``).
    flow : dict
        The valve's ``flow`` record (``throat_area_mm2``, ``max_curtain_area_mm2``, ``V1_m_s``, ``V2_m_s``,
        ``valve_lift_mm``).
    engine : dict
        The engine record (``mean_piston_speed_m_s``, ``piston_area_mm2``).
    """
    d, phi, i, h = valve["throat_diameter_mm"], valve["seat_angle_deg"], valve["count"], flow["valve_lift_mm"]
    cp, fp = engine["mean_piston_speed_m_s"], engine["piston_area_mm2"]
    return [
        _line("f_g", "π d_g² / 4", ("π × ({})² / 4", [(d, "mm")]), flow["throat_area_mm2"], "mm2", lang),
        _line("f_max", "π h (d_g cos φ + h sin φ cos² φ)",
              ("π × {} × ({} × cos {} + {} × sin {} × cos² {})",
               [(h, "mm"), (d, "mm"), (phi, "deg"), (h, "mm"), (phi, "deg"), (phi, "deg")]),
              flow["max_curtain_area_mm2"], "mm2", lang),
        _line("V′", "c_p F_p / (i f_g)", ("{} × {} / ({} × {})", [(cp, "m/s"), (fp, "mm2"), (i, ""),
                                                                 (flow["throat_area_mm2"], "mm2")]),
              flow["V1_m_s"], "m/s", lang),
        _line("V″", "c_p F_p / (i f_max)", ("{} × {} / ({} × {})", [(cp, "m/s"), (fp, "mm2"), (i, ""),
                                                                   (flow["max_curtain_area_mm2"], "mm2")]),
              flow["V2_m_s"], "m/s", lang),
    ]


def spring_lines(spring, lang="en"):
    """The spring's force at full lift, index and largest shear stress (Valve-train practical works (n.d.), works 5
    and 6): P_max = P_min + c f, C = D/d, tau_max = k 8 P_max D / (pi d^3), with k the shape factor of the design.

    Parameters
    ----------
    spring : dict
        The valve's ``spring`` record.
    """
    p0, c, f = spring["preload_N"], spring["rate_N_per_mm"], spring["max_deflection_mm"] - spring["preload_deflection_mm"]
    pmax, d, dm, k = spring["max_force_N"], spring["wire_mm"], spring["mean_diameter_mm"], spring["shape_factor"]
    return [
        _line("P_max", "P_min + c h", ("{} + {} × {}", [(p0, "N"), (c, "N/mm"), (f, "mm")]), pmax, "N", lang),
        _line("C", "D / d", ("{} / {}", [(dm, "mm"), (d, "mm")]), spring["spring_index"], "", lang),
        _line("τ_max", "k 8 P_max D / (π d³)", ("{} × 8 × {} × {} / (π × ({})³)",
                                                [(k, ""), (pmax, "N"), (dm, "mm"), (d, "mm")]),
              spring["tau_max_MPa"], "MPa", lang),
    ]

