"""The words for the data the physics returns, in English and Russian: the spring diagnosis
(:class:`valvetrain.springs.Diagnosis`) and the fit a measured table uses and why
(:class:`valvetrain.laws.measured.TableLaw`).

The physics returns codes and values in SI; this module alone turns them into sentences (of the words of the
catalogues ``LANG.toml`` ``[diagnosis_words]`` and ``[fit_words]``), into the units a reader reads and into the
specification's key names.  results.json and the CLI take the English (``lang="en"``), the
report its own language.
"""

from ..units import symbol as unit_text, to_display
from . import catalogue, check_text

def _window_record(w):
    """The stress window of results.json (MPa, mm)."""
    return {"material": w.material, "deflection_ratio": w.deflection_ratio,
            "max_deflection_mm": to_display(w.max_deflection, "mm"), "stress_needed_MPa": to_display(w.needed, "MPa"),
            "stress_allowed_MPa": to_display(w.allowed, "MPa")}


def _remedy_text(r, words):
    """One remedy in English words."""
    grams = words["grams"].format(grams=r.spring_mass * 1e3) if r.passes and r.spring_mass is not None else ""
    if r.change == "material":
        return words["material"].format(key=r.key, value=r.value, grams=grams)
    if r.change == "count":
        return words["count"][str(r.value)].format(key=r.key, grams=grams)
    helped, tried = words[r.change]
    if not r.passes:
        return tried.format(percent=None if r.value is None else r.value * 100.0)
    rpm = "" if r.rated_speed is None else words["rpm"].format(rpm=to_display(r.rated_speed, "rpm"))
    mm = None if r.value is None else to_display(r.value, "mm")
    return helped.format(value=r.value, mm=mm, rpm=rpm, saved=1.0 - r.value)


def diagnosis_text(d, lang) -> str:
    """The spring diagnosis (:class:`valvetrain.springs.Diagnosis`) in words of ``lang``: the conflicts, what the
    stress window proves, the remedies."""
    words, springs = catalogue(lang)["diagnosis_words"], catalogue(lang)["springs"]
    said = []
    for x in d.conflicts:
        unit = unit_text(x.unit, lang) if lang != "en" else x.unit
        said.append(words["conflict"].format(
            tag=f"{x.spring} " if d.pair else "", spring=springs[x.spring] if x.spring in ("outer", "inner") else "",
            quantity=x.quantity if lang == "en" else check_text(f"spring.{x.check}", {}, lang),
            value=to_display(x.value, x.unit), limit=to_display(x.limit, x.unit), unit=unit,
            spaced_unit=f" {unit}" if unit else "", shortfall=x.shortfall))
    text = [words["head_pair" if d.pair else "head"] + "; ".join(said) + "."]
    if d.window is not None:
        w = d.window
        values = {**_window_record(w), "resonance_ratio": w.resonance_ratio,
                  "frequency_difference": d.frequency_difference,
                  "stress_pair_MPa": to_display(w.needed * (1.0 + d.frequency_difference), "MPa")}
        values["where"] = words.get("where", "").format(**values)
        text += [words[key].format(**values) for key in ("window", d.kind) if key and words[key]]
    if d.helped and words["helped"]:
        text.append(words["helped"].format(words["helped_join"].join(_remedy_text(r, words) for r in d.helped)))
    if d.tried and words["tried"]:
        text.append(words["tried"].format(words["tried_join"].join(_remedy_text(r, words) for r in d.tried)))
    if words["remedies"]:
        text.append(words["remedies"])
    return " ".join(text)


def fit_reason(fit, harmonics, code, ratio, smoothing, lang="en") -> str:
    """The fit a measured table uses and why, in ``lang``: one sentence.

    Parameters
    ----------
    fit : {"spline", "harmonic"}
        The fit used.
    harmonics : int
        Its harmonic order N.
    code : str
        Why (a code of :func:`valvetrain.laws.fits.choose_fit`).
    ratio : float
        The generalised cross-validation score of the fit used / the other's (NaN where not compared).
    smoothing : {"accuracy", "gcv"}
        How the spline's smoothing was chosen (:func:`valvetrain.laws.fits.smoothing_spline`).
    """
    t = catalogue(lang)["fit_words"]
    text = t["fit_used"][fit].format(n=harmonics) + ": " + t["fit_reasons"][code].format(fit=fit, ratio=ratio)
    return text + ("; " + t["smoothings"][smoothing] if fit == "spline" else "")
