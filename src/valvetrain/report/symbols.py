"""The symbols of the report (their notation here, their meanings in the catalogues' ``[symbols]``), and the legend
that explains each where it is first used."""

from collections.abc import Callable

from markupsafe import Markup

from ..locale import catalogue
from .i18n import TEXT

NOTATION = {
    "D": "D", "S": "S", "ic": "i<sub>c</sub>", "Vh": "V<sub>h</sub>", "n": "n", "cp": "c<sub>p</sub>",
    "spring_text": "D", "Fp": "F<sub>p</sub>", "i": "i", "dg": "d<sub>g</sub>", "phi_seat": "φ",
    "hv": "h<sub>v</sub>", "h0": "h<sub>0</sub>", "ik": "i<sub>k</sub>", "r0": "r<sub>0</sub>", "w1": "w′",
    "Phi123": "Φ<sub>1</sub>, Φ<sub>2</sub>, Φ<sub>3</sub>", "Kz": "K<sub>z</sub>", "V1": "V′", "V2": "V″",
    "V3": "V‴", "fg": "f<sub>g</sub>", "fmax": "f<sub>max</sub>", "f": "f", "hT": "h<sub>T</sub>",
    "vT": "v<sub>T</sub>", "aT": "a<sub>T</sub>", "jT": "j<sub>T</sub>", "av": "a<sub>v</sub>",
    "phi_p0": "φ<sub>p0</sub>", "Phi0": "Φ<sub>0</sub>", "omega_cam": "ω<sub>cam</sub>",
    "c_ij": "c<sub>11</sub>...c<sub>33</sub>", "k_i": "k<sub>1</sub>, k<sub>2</sub>, k<sub>3</sub>",
    "K12": "K<sub>1</sub>, K<sub>2</sub>", "h_max": "h<sub>max</sub>",
    "C_poly": "C<sub>2</sub>, C<sub>p</sub>, C<sub>q</sub>, C<sub>r</sub>, C<sub>s</sub>", "pqrs": "p, q, r, s",
    "coefficients": "", "dt": "∫f dt", "phi": "φ", "vvp": "v<sub>vp</sub>", "xi": "ξ", "Phi_open": "Φ", "rho": "ρ",
    "hpp": "h″", "b": "b", "E": "E", "gap": "Δ", "s0": "s<sub>0</sub>", "hv0": "h<sub>v0</sub>",
    "Pin": "P<sub>in</sub>", "mv": "m<sub>v</sub>", "Pspr": "P<sub>spr</sub>", "Pgas": "P<sub>gas</sub>",
    "fmin": "f<sub>min</sub>", "fmax_spring": "f<sub>max</sub>", "tau": "τ", "chi": "χ", "P": "P", "D_spring": "D",
    "d_wire": "d", "iw": "i<sub>w</sub>", "n_safety": "n", "omega_c1": "ω<sub>c1</sub>", "PT": "P<sub>T</sub>",
    "mT": "m<sub>T</sub>", "R": "R", "L": "L", "lambda": "λ", "beta": "β", "pg": "Δp<sub>g</sub>",
    "pin": "p<sub>in</sub>", "p_total": "p", "pN": "p<sub>N</sub>", "pS": "p<sub>S</sub>", "pK": "p<sub>K</sub>",
    "pT": "p<sub>T</sub>", "T": "T", "M": "M", "Wi": "W<sub>i</sub>", "tau_strokes": "τ", "mj": "m<sub>j</sub>",
    "mr": "m<sub>r</sub>", "Kr": "K<sub>r</sub>", "pi": "p<sub>i</sub>", "K1K2": "K<sub>1</sub>, K<sub>2</sub>",
    "Z": "Z",
}
"""The notation of every symbol of the report (HTML), the same in every language; its meaning with its unit is
``[symbols]`` of the catalogues."""



def symbol_legend(lang) -> Callable[..., str]:
    """A Jinja function ``legend(*symbols)``: the symbols not yet explained in this report, each with its meaning
    and unit (every symbol is explained where it is first used)."""
    seen = set()

    def legend(*keys):
        new = [k for k in keys if k not in seen]
        seen.update(new)
        if not new:
            return ""
        meanings = catalogue(lang)["symbols"]
        items = Markup("; ").join(Markup("{} — {}").format(Markup(NOTATION[k]), Markup(meanings[k])) for k in new)
        return Markup('<p class="legend">{}: {}.</p>').format(TEXT[lang]["where"], items)
    return legend


INPUT_SYMBOLS = ("i", "dg", "phi_seat", "hv", "h0", "ik", "r0", "w1", "Phi123", "Kz")
"""Symbols of the valve's input table."""

WARNING_SYMBOLS = {
    "V1": ("flow.throat_velocity",), "V2": ("flow.curtain_velocity",), "V3": ("flow.time_area_velocity",),
    "vvp": ("flow.charge_velocity",), "aT": ("tappet_acceleration.max", "tappet_acceleration.min"),
    "dg": ("flow.throat_to_bore", "flow.equivalent_throat_to_bore", "flow.lift_to_throat"),
    "hv": ("flow.lift_to_throat", "cam.base_radius_to_lift", "hydraulic.max_lift", "hydraulic.residual_lift"),
    "h0": ("valve.clearance",), "ik": ("drive.rocker_ratio",), "r0": ("cam.base_radius_to_lift",),
    "rho": ("profile.undercut_flat", "profile.rho_min"), "Kz": ("spring.reserve",),
    "Phi123": ("law.kurz.phi2_to_phi3", "law.kurz.negative_to_positive"), "w1": ("ramp.end_velocity",),
    "lambda": ("engine.rod_ratio", "crank.rod_ratio"),
}
"""Symbols of the legend that the checks of these codes use."""
