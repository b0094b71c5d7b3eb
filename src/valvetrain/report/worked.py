"""Worked substitution for the calculation note: each main formula, the numbers put into it with their units, and the
result, so that a checker can follow a line with a pocket calculator.

The numbers are the design's own (its inputs and its typed results, as results.json shows them); the result printed
is the design's, and the substituted expression evaluates to it (``tests/report/test_worked.py`` evaluates every
line).  Formulas: Valve-train practical works (n.d.), works 1, 2, 4, 6 and 7; Shang Hanji (1988); Power units manual
(n.d.).
"""

from typing import Any

import numpy as np

from .. import strength
from ..design.results import shown_value
from ..laws.asymmetric import AsymmetricLaw
from ..locale import catalogue
from ..units import to_display
from .numbers import SUPERSCRIPTS, number
from .names import unit_text

LARGE = 1e6
"""A substituted number of this size or more prints as a power of ten (a modulus in Pa), not in whole units."""


def _symbol(key, lang) -> str:
    """A symbol of a worked example whose index is a word of the language (``v_vp``, ``v_вп``): ``LANG.toml``
    ``[worked_symbols]``."""
    return catalogue(lang)["worked_symbols"][key]


def _number(x, lang):
    """:func:`number`, a number of :data:`LARGE` or more as ``7.95·10¹⁰``."""
    if abs(x) < LARGE:
        return number(x, lang)
    mantissa, exponent = f"{x:.3e}".split("e")
    return number(float(mantissa), lang) + "·10" + str(int(exponent)).translate(SUPERSCRIPTS)


def _line(symbol, formula, values, result, unit, lang):
    """One worked line: ``symbol = formula = values = result unit`` (values: (number, unit) pairs joined by the
    formula's operators, given as a format string with ``{}`` per number)."""
    def quantity(x, u):
        return _number(x, lang) + ("°" if u == "deg" else f" {unit_text(u, lang)}" if u else "")

    text, numbers = values
    shown = text.format(*(quantity(x, u) for x, u in numbers))
    return {"symbol": symbol, "formula": formula, "substituted": shown,
            "result": f"{_number(result, lang)} {unit_text(unit, lang)}".strip()}


def flow_lines(valve, flow, engine, lang="en") -> list[dict[str, Any]]:
    """The throat and curtain sections and the conditional gas velocities (Valve-train practical works (n.d.), work 1,
    eqs. (1.1)-(1.3)).

    Parameters
    ----------
    valve : valvetrain.specification.models.Valve
        The valve's inputs as given (``throat_diameter_mm`` [mm], ``seat_angle_deg`` [deg], ``count``).
    flow : valvetrain.design.valve.FlowResult
        The valve's flow stage (throat and curtain areas, V', V'', valve lift).
    engine : valvetrain.design.EngineRecord
        The engine's figures (mean piston speed, piston area).
    """
    def shown(result, *names):
        return [shown_value(result, n) for n in names]

    d, phi, i = valve.throat_diameter_mm, valve.seat_angle_deg, valve.count
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


def time_area_lines(flow, cam, engine, count, lift_table, lang="en") -> list[dict[str, Any]]:
    """The gas velocity over the time-area, the mean charge velocity and the fullness of the lift diagram
    (Valve-train practical works (n.d.), work 1, eq. (1.4), work 4, eq. (4.3); Shang Hanji (1988), eq. 2.3).

    Parameters
    ----------
    flow : valvetrain.design.valve.FlowResult
        The valve's flow stage (time-area [mm^2 s], the velocities [m/s], fullness, valve lift [mm]).
    cam : valvetrain.design.valve.CamResult
        The law stage: the valve's opening and closing [crank deg], Phi their distance in cam degrees.
    engine : valvetrain.design.EngineRecord
        The engine's swept volume V_h [cm^3].
    count : int
        Valves of this kind per cylinder, i.
    lift_table : dict
        The valve's lift table (``cam_deg`` [cam deg], ``valve_lift_mm`` [mm]), for the integral of the lift over the
        opening.

    Notes
    -----
    cm^3 / (mm^2 s) is m/s: the velocities need no factor.  The integral of h_v over the opening is the trapezoidal
    sum of the lift table from the last closed row before the opening to the first closed row after it (or the table's
    first and last rows, where it holds the event alone: a measured lobe's table begins at its opening).
    """
    vh = shown_value(engine, "swept_volume")
    ta, v3, vvp, fullness, lift = (shown_value(flow, n) for n in ("time_area", "v3", "charge_velocity", "fullness",
                                                                  "valve_lift"))
    angle, h = np.asarray(lift_table["cam_deg"]), np.asarray(lift_table["valve_lift_mm"])
    opened = np.flatnonzero(h > 0.0)
    start, end = max(opened[0] - 1, 0), min(opened[-1] + 1, h.size - 1)    # a table may begin or end at the event
    area = float(np.trapezoid(h[start:end + 1], angle[start:end + 1]))
    event = (shown_value(cam, "valve_closes") - shown_value(cam, "valve_opens")) / 2.0
    return [
        _line("V‴", "V_h / (i ∫f dt)", ("{} / ({} × {})", [(vh, "cm3"), (count, ""), (ta, "mm2 s")]), v3, "m/s", lang),
        _line(_symbol("v_vp", lang), "V_h / ∫f dt", ("{} / {}", [(vh, "cm3"), (ta, "mm2 s")]), vvp, "m/s",
              lang),
        _line("ξ", "∫h_v dφ / (h_v max Φ)", ("{} / ({} × {})", [(area, "mm cam deg"), (lift, "mm"),
                                                               (event, "cam deg")]),
              fullness, "", lang),
    ]


def law_lines(law, cam, lang="en") -> list[dict[str, Any]]:
    """The coefficients of the valve's law with its numbers: a Kurz law's from its segments (Valve-train practical
    works (n.d.), work 2, eqs. (2.23)-(2.34)), a polydyne's from its exponents (work 3, eqs. (3.4)-(3.8)), a
    power-polynomial law's ramp and negative amplitude (UkrSURT Proceedings (2019), reconstructed); no lines for
    another law (its coefficients are the table's) nor for an asymmetric cam (its two flanks' laws, each its own).

    Parameters
    ----------
    law : valvetrain.laws.base.LiftLaw
        The valve's law: a Kurz law's Phi1, Phi2, Phi3 [rad camshaft], Z and w' [m/rad]; a polydyne's ramp height
        h_0 [m].
    cam : valvetrain.design.valve.CamResult
        The law stage (tappet lift h_T max [mm], the coefficients [mm, rad, deg; dimensionless C of a polydyne]).
    """
    name = None if isinstance(law, AsymmetricLaw) else getattr(law, "name", None)
    if name == "polydyne":
        return _polydyne_lines(law, cam, lang)
    if name == "power_polynomial":
        return _power_polynomial_lines(law, cam, lang)
    if name != "kurz":
        return []
    c = shown_value(cam, "coefficients")
    h = shown_value(cam, "tappet_lift")
    w = to_display(law.ramp_velocity, "mm/rad")
    z, f1, f2, f3 = law.shape_factor, law.phi1, law.phi2, law.phi3
    return [
        _line("k_1", "8 Z (Φ_2 / π)²", ("8 × {} × ({} / π)²", [(z, ""), (f2, "rad")]), c["k1"], "rad2", lang),
        _line("k_2", "(5 + Z) Φ_3² / 6", ("(5 + {}) × ({})² / 6", [(z, ""), (f3, "rad")]), c["k2"], "rad2", lang),
        _line("k_3", "(4 + 2 Z) Φ_3 / 3", ("(4 + 2 × {}) × {} / 3", [(z, ""), (f3, "rad")]), c["k3"], "rad", lang),
        _line("K_1", "k_1 + k_2 + k_3 Φ_2", ("{} + {} + {} × {}", [(c["k1"], "rad2"), (c["k2"], "rad2"),
                                                                (c["k3"], "rad"), (f2, "rad")]), c["K1"], "rad2", lang),
        _line("K_2", "k_3 + 4 Z Φ_2 / π", ("{} + 4 × {} × {} / π", [(c["k3"], "rad"), (z, ""), (f2, "rad")]),
              c["K2"], "rad", lang),
        _line("c_11", "(K_1 w′ + K_2 h_T max) / (2 K_1 + K_2 Φ_1)",
              ("({} × {} + {} × {}) / (2 × {} + {} × {})",
               [(c["K1"], "rad2"), (w, "mm/rad"), (c["K2"], "rad"), (h, "mm"), (c["K1"], "rad2"), (c["K2"], "rad"),
                (f1, "rad")]), c["c11"], "mm/rad", lang),
        _line("c_12", "(c_11 − w′) Φ_1 / π", ("({} − {}) × {} / π", [(c["c11"], "mm/rad"), (w, "mm/rad"), (f1, "rad")]),
              c["c12"], "mm", lang),
        _line("c_32", "−(2 c_11 − w′) / K_2", ("−(2 × {} − {}) / {}", [(c["c11"], "mm/rad"), (w, "mm/rad"),
                                                                      (c["K2"], "rad")]), c["c32"], "mm/rad2", lang),
    ]


def _polydyne_lines(law, cam, lang):
    """C_2 ... C_s of a polydyne from p, q, r, s (work 3, eqs. (3.4)-(3.8)) without a ramp; none with a ramp (the
    coefficients solve a 5x5 system, no closed form; their check h_0 = h_nose (1 + sum C) loses its figures to the
    cancellation of the sum about -1)."""
    if law.ramp_height > 0.0:
        return []
    c = shown_value(cam, "coefficients")
    p, q, r, s = (c[k] for k in "pqrs")
    lines = [_line("C_2", "−p q r s / ((p − 2)(q − 2)(r − 2)(s − 2))",
                   ("−{} × {} × {} × {} / (({} − 2) × ({} − 2) × ({} − 2) × ({} − 2))",
                    [(x, "") for x in (p, q, r, s, p, q, r, s)]), c["C2"], "", lang)]
    for k in "pqrs":   # C_k = (-1)^(k's place + 1) 2 (product of the others) / ((k - 2) product of the differences)
        others = [o for o in "pqrs" if o != k]
        pairs = [(max(o, k), min(o, k)) for o in others]
        sign = "−" if k in "qs" else ""
        lines.append(_line(
            f"C_{k}", f"{sign}2 {' '.join(others)} / (({k} − 2)" + "".join(f"({a} − {b})" for a, b in pairs) + ")",
            (f"{sign}2 × {{}} × {{}} × {{}} / (({{}} − 2)" + " × ({} − {})" * 3 + ")",
             [(c[x], "") for x in (*others, k, *(x for pair in pairs for x in pair))]), c[f"C{k}"], "", lang))
    return lines


def _power_polynomial_lines(law, cam, lang):
    """The ramp's A_0, B_0, C_0 from a(b) = 0, v(b) = v_qb, S(b) = S_b solved in closed form (A_0 = 12 S_b/phi_0^2
    - 6 v_qb/phi_0, B_0 = 30 v_qb/phi_0 - 48 S_b/phi_0^2, C_0 = 36 S_b/phi_0^2 - 24 v_qb/phi_0) and, for the R2
    reconstruction, the negative amplitude a_g = -v_e / (phi_2 (x_g I(r, s) + (1 - x_g) I(t, u))),
    I(a, b) = (b/(a + 1) - a/(b + 1)) / (b - a) (UkrSURT Proceedings (2019), reconstructed in
    :mod:`valvetrain.laws.power_polynomial`).  phi_0 is substituted in degrees times pi/180: the terms of B_0 nearly
    cancel, and a 4-figure radian would not give its result."""
    c = shown_value(cam, "coefficients")
    sb, vqb, phi0 = shown_value(cam, "ramp_height"), to_display(law.v_qb, "mm/rad"), shown_value(cam, "ramp_angle")
    lines = [
        _line("A_0", "12 S_b / φ_0² − 6 v_b / φ_0", ("12 × {} / ({} × π/180)² − 6 × {} / ({} × π/180)",
                                                   [(sb, "mm"), (phi0, "deg"), (vqb, "mm/rad"), (phi0, "deg")]),
              c["A0_mm_rad2"], "mm/rad2", lang),
        _line("B_0", "30 v_b / φ_0 − 48 S_b / φ_0²", ("30 × {} / ({} × π/180) − 48 × {} / ({} × π/180)²",
                                                    [(vqb, "mm/rad"), (phi0, "deg"), (sb, "mm"), (phi0, "deg")]),
              c["B0_mm_rad2"], "mm/rad2", lang),
        _line("C_0", "36 S_b / φ_0² − 24 v_b / φ_0", ("36 × {} / ({} × π/180)² − 24 × {} / ({} × π/180)",
                                                    [(sb, "mm"), (phi0, "deg"), (vqb, "mm/rad"), (phi0, "deg")]),
              c["C0_mm_rad2"], "mm/rad2", lang),
    ]
    if c["reconstruction"] != "R2":
        return lines

    integral = "({} / ({} + 1) − {} / ({} + 1)) / ({} − {})"
    return lines + [_line(
        "a_g", "−v_e / (φ_2 (x_g I(r, s) + (1 − x_g) I(t, u))), I(a, b) = (b/(a + 1) − a/(b + 1)) / (b − a)",
        (f"−{{}} / ({{}} × ({{}} × {integral} + (1 − {{}}) × {integral}))", [
            (c["v_e_mm_rad"], "mm/rad"), (law.phi2, "rad"), (c["x_g"], ""),
            *((c[k], "") for k in ("s", "r", "r", "s", "s", "r")), (c["x_g"], ""),
            *((c[k], "") for k in ("u", "t", "t", "u", "u", "t"))]), c["a_g_mm_rad2"], "mm/rad2", lang)]


def spring_lines(spring, material=None, cam_speed=None, lang="en") -> list[dict[str, Any]]:
    """The spring's force at full lift, index, largest shear stress, rate, fatigue safety, first natural frequency and
    resonance ratio (Valve-train practical works (n.d.), works 5 and 6): P_max = P_min + c f, C = D/d,
    tau_max = k 8 P_max D / (pi d^3), c = G d^4 / (8 D^3 i_p), n = tau_-1 / (tau_a + psi_tau tau_m) (6.12),
    omega_c1 = d / (D^2 i_p) sqrt(G / (2 rho)) (6.14), with k the shape factor of the design.

    Parameters
    ----------
    spring : valvetrain.design.drive.SpringRecord
        The designed spring (for a nested pair the outer spring's record with the pair's loads).
    material : valvetrain.springs.SpringMaterial, optional
        Its grade with the specification's overrides (G [Pa], rho [kg/m^3], tau_-1 and psi_tau of its wire): without
        it only the force, index and stress lines.
    cam_speed : float, optional
        omega_cam [rad/s] of the resonance ratio.
    """
    p0, c, fmax, fmin, pmax, d, dm, k, index, tau, tau_min, coils, safety, freq, ratio = (
        shown_value(spring, n) for n in (
            "preload", "rate", "max_deflection", "preload_deflection", "max_force", "wire_diameter", "mean_diameter",
            "shape_factor", "spring_index", "tau_max", "tau_min", "active_coils", "safety_factor",
            "natural_frequency", "resonance_ratio"))
    lines = [
        _line("P_max", "P_min + c h", ("{} + {} × {}", [(p0, "N"), (c, "N/mm"), (fmax - fmin, "mm")]), pmax, "N", lang),
        _line("C", "D / d", ("{} / {}", [(dm, "mm"), (d, "mm")]), index, "", lang),
        _line("τ_max", "k 8 P_max D / (π d³)", ("{} × 8 × {} × {} / (π × ({})³)",
                                                [(k, ""), (pmax, "N"), (dm, "mm"), (d, "mm")]),
              tau, "MPa", lang),
    ]
    if material is None:
        return lines
    g = material.shear_modulus
    _, endurance, psi = (float(x) for x in material.limits(spring.wire_diameter))
    omega = 2.0 * np.pi * freq
    lines += [
        _line("c", "G d⁴ / (8 D³ i_p)", ("{} × ({})⁴ / (8 × ({})³ × {})",
                                         [(to_display(g, "MPa"), "MPa"), (d, "mm"), (dm, "mm"), (coils, "")]),
              c, "N/mm", lang),
        _line("n", "τ₋₁ / ((τ_max − τ_min) / 2 + ψ_τ (τ_max + τ_min) / 2)",
              ("{} / (({} − {}) / 2 + {} × ({} + {}) / 2)",
               [(to_display(endurance, "MPa"), "MPa"), (tau, "MPa"), (tau_min, "MPa"), (psi, ""), (tau, "MPa"),
                (tau_min, "MPa")]), safety, "", lang),
        _line("ω_c1", "d / (D² i_p) √(G / (2 ρ))", ("{} / (({})² × {}) × √({} / (2 × {}))",
                                                   [(d / 1e3, "m"), (dm / 1e3, "m"), (coils, ""), (g, "Pa"),
                                                    (material.density, "kg/m3")]), omega, "rad/s", lang),
    ]
    if cam_speed is not None:
        lines.append(_line(_symbol("cam_speed_ratio", lang), "",
                           ("{} / {}", [(omega, "rad/s"), (cam_speed, "rad/s")]), ratio, "", lang))
    return lines


def strength_lines(parts, result, lift_table, follower, lang="en", roller_radius=None) -> list[dict[str, Any]]:
    """The cam's contact stress at its worst point and the pushrod's buckling margin (Valve-train practical works
    (n.d.), eqs. (7.4)-(7.5), (7.8)-(7.10); Shang Hanji (1988), eq. 2.5), those the design checked.

    Parameters
    ----------
    parts : valvetrain.specification.models.Parts
        The valve's ``[parts]`` inputs as given (cam width [mm], contact modulus [MPa], pushrod diameter, bore and length
        [mm] and modulus [MPa]).
    result : valvetrain.design.drive_strength.StrengthResult
        The strength stage's result (its checks, the angle of the largest contact stress and the cam force there,
        the largest cam force), read in the units results.json shows them (cam deg, N).
    lift_table : dict
        The valve's lift table (``cam_deg`` [cam deg], ``rho_mm`` [mm]): the cam's radius at the worst point.
    follower : str
        ``flat`` (1/rho_2 = 0) or ``roller`` (1/rho_2 = 1/r_r); no contact line for another follower.
    roller_radius : float, optional
        r_r, the roller's radius [mm] of a roller follower.

    Notes
    -----
    The contact line is worked at the angle of the largest contact stress with the cam force there; the profile's
    radius is the lift table's interpolated to that angle (negative on a concave flank).
    """
    checks, lines = {c.code: c for c in result.checks}, []
    contact, force = checks.get("strength.cam_contact_stress"), shown_value(result, "contact_force")
    if contact is not None and force is not None:
        rho = float(np.interp(shown_value(result, "contact_stress_angle"), lift_table["cam_deg"], lift_table["rho_mm"]))
        factor, symbol = strength.HERTZ_LINE, _symbol("contact_stress", lang)
        if follower == "flat":
            lines.append(_line(symbol, f"{number(factor, lang)} √(P E / (b ρ))", (
                "{} × √({} × {} / ({} × {}))",
                [(factor, ""), (force, "N"), (parts.contact_modulus_MPa, "MPa"), (parts.cam_width_mm, "mm"),
                 (rho, "mm")]), contact.shown_value, "MPa", lang))
        elif follower in ("roller", "finger") and roller_radius:
            lines.append(_line(symbol, f"{number(factor, lang)} {_symbol('roller_hertz', lang)}", (
                "{} × √({} × {} × (1/{} + 1/{}) / {})",
                [(factor, ""), (force, "N"), (parts.contact_modulus_MPa, "MPa"), (rho, "mm"),
                 (roller_radius, "mm"), (parts.cam_width_mm, "mm")]), contact.shown_value, "MPa", lang))
    buckling = checks.get("strength.pushrod_buckling_margin")
    if buckling is not None:
        big, bore, e, length = (getattr(parts, k) or 0.0 for k in (
            "pushrod_diameter_mm", "pushrod_bore_mm", "pushrod_modulus_MPa", "pushrod_length_mm"))
        second = float(strength.second_moment(big, bore))
        euler = float(strength.euler_load(e, second, length))
        lines += [
            _line("J", "π (D⁴ − d⁴) / 64", ("π × (({})⁴ − ({})⁴) / 64", [(big, "mm"), (bore, "mm")]), second, "mm4",
                  lang),
            _line("P_E", "π² E J / l²", ("π² × {} × {} / ({})²", [(e, "MPa"), (second, "mm4"), (length, "mm")]),
                  euler, "N", lang),
            _line("n", "P_E / P_T max", ("{} / {}", [(euler, "N"), (shown_value(result, "cam_force_max"), "N")]),
                  buckling.shown_value, "", lang),
        ]
    return lines


def crank_lines(figures, lang="en") -> list[dict[str, Any]]:
    """The crank's reduced masses, its angular speed, the piston's largest acceleration and the inertia and
    centrifugal forces (Power units manual (n.d.), eqs. (1.10), (2.6)-(2.10)): m_j = m_p + m_rod,p,
    m_r = m_c + m_rod,c, omega = pi n / 30, j_max = R omega^2 (1 + lambda) (a central mechanism, at the TDC),
    P_j = -m_j j_max, K_R = -m_r R omega^2.

    Parameters
    ----------
    figures : valvetrain.design.crank.CrankSummary
        The crank's figures (masses [kg], stroke [mm], speed [rpm], lambda, offset [mm], the largest acceleration
        [m/s^2], the centrifugal force [N]).
    """
    m = figures.masses
    mp, mrp, mc, mrc, mj, mr = (shown_value(m, k) for k in ("piston", "rod_pin", "crank", "rod_crank", "reciprocating",
                                                             "rotating"))
    stroke, n, lam, offset, j, k_r = (shown_value(figures, k) for k in (
        "stroke", "speed", "lam", "offset", "max_acceleration", "centrifugal_force"))
    r, omega = stroke / 2e3, np.pi * n / 30.0
    lines = [
        _line("m_j", _symbol("reciprocating_mass", lang), ("{} + {}", [(mp, "kg"), (mrp, "kg")]), mj,
              "kg", lang),
        _line("m_r", _symbol("rotating_mass", lang), ("{} + {}", [(mc, "kg"), (mrc, "kg")]), mr,
              "kg", lang),
        _line("ω", "π n / 30", ("π × {} / 30", [(n, "rpm")]), omega, "rad/s", lang),
    ]
    if offset == 0.0:
        lines.append(_line("j_max", "R ω² (1 + λ)", ("{} × ({})² × (1 + {})", [(r, "m"), (omega, "rad/s"), (lam, "")]),
                           j, "m/s2", lang))
    return lines + [
        _line("P_j", "−m_j j_max", ("−{} × {}", [(mj, "kg"), (j, "m/s2")]), -mj * j, "N", lang),
        _line("K_R", "−m_r R ω²", ("−{} × {} × ({})²", [(mr, "kg"), (r, "m"), (omega, "rad/s")]), k_r, "N", lang),
    ]
