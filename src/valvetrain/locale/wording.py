"""The words for the data the physics returns, in English and Russian: the spring diagnosis
(:class:`valvetrain.springs.Diagnosis`) and the fit a measured table uses and why
(:class:`valvetrain.laws.measured.TableLaw`).

The physics returns codes and values in SI; this module alone turns them into sentences, into the units a reader
reads and into the specification's key names.  results.json and the CLI take the English (``lang="en"``), the
report its own language.
"""

from ..units import symbol as unit_text, to_display
from . import catalogue, check_text

FIT_WORDS = {
    "en": {
            "fit_used": {"harmonic": "N-harmonic fit (N = {n})", "spline": "smoothing spline"},
            "fit_reasons": {
                "given": "fit = \"{fit}\" in the specification",
                "harmonic_gcv": "the N-harmonic fit meets accuracy_mm and predicts left-out rows better than the smoothing "
                                "spline (generalised cross-validation score {ratio:.3g} x the spline's)",
                "spline_gcv": "the smoothing spline predicts left-out rows better than the N-harmonic fit, which also meets "
                              "accuracy_mm (generalised cross-validation score {ratio:.3g} x the N-harmonic fit's)",
                "harmonic_misses": "the N-harmonic fit does not meet accuracy_mm by its highest order",
                "harmonic_swings": "the N-harmonic fit swings outside the table's range between the rows",
            },
            "smoothings": {
                "accuracy": "the smoothing spline is smoothed to an RMS residual of accuracy_mm (Reinsch 1967)",
                "gcv": "the smoothing spline is smoothed by generalised cross-validation, whose residual exceeds accuracy_mm: "
                       "the table is noisier than accuracy_mm or bends more sharply than its rows resolve (the foot of a "
                       "valve lift)",
            },
    },
    "ru": {
            "fit_used": {"harmonic": "N-гармоническая аппроксимация (N = {n})", "spline": "сглаживающий сплайн"},
            "fit_reasons": {
                "given": "способ аппроксимации задан в исходных данных",
                "harmonic_gcv": "N-гармоническая аппроксимация укладывается в заданную точность измерения и лучше предсказывает "
                                "исключённые точки, чем сглаживающий сплайн (критерий обобщённой перекрёстной проверки "
                                "{ratio:.3g} от критерия сплайна)",
                "spline_gcv": "сглаживающий сплайн лучше предсказывает исключённые точки, чем N-гармоническая "
                              "аппроксимация, тоже укладывающаяся в заданную точность измерения (критерий обобщённой перекрёстной "
                              "проверки {ratio:.3g} от критерия гармонической аппроксимации)",
                "harmonic_misses": "N-гармоническая аппроксимация не укладывается в заданную точность измерения и при наибольшем порядке",
                "harmonic_swings": "N-гармоническая аппроксимация выходит между точками за пределы подъёмов таблицы"},
            "smoothings": {
                "accuracy": "сплайн сглажен до СКО отклонения, равного заданной точности измерения (Reinsch (1967))",
                "gcv": "сплайн сглажен по обобщённой перекрёстной проверке, СКО отклонения которой больше точности измерения: "
                       "шум таблицы больше точности измерения или таблица изгибается круче, чем разрешают её точки "
                       "(начало подъёма клапана)"},
    },
}
"""The fit a measured table uses (``fit_used``), why (``fit_reasons``, by the code of
:func:`valvetrain.laws.fits.choose_fit`) and how a spline is smoothed (``smoothings``), per language."""

DIAGNOSIS_WORDS = {
    "en": {
        "head": "No spring passes; the best candidate: ", "head_pair": "No nested pair passes; the best pair: ",
        "conflict": "{tag}{quantity} {value:.4g}{spaced_unit} against {limit:.4g}{spaced_unit} (short by {shortfall:.1%})",
        "window": "",
        "where": "at D/d = 12 and f_max/f_min = {deflection_ratio:.3g} (f_max = {max_deflection_mm:.3g} mm), while "
                 "{material} allows at most {stress_allowed_MPa:.0f} MPa there ([tau] and the fatigue safety)",
        "resonance_stress": "The resonance ratio {resonance_ratio:g} needs tau_max >= {stress_needed_MPa:.0f} MPa even "
                            "{where}: no wire and no diameter of this grade can pass at this speed and lift.",
        "pair_frequencies": "The two springs of a pair share f_max, so their frequencies stand as tau_max / chi: "
                            "frequencies {frequency_difference:.0%} apart with both resonance ratios >= "
                            "{resonance_ratio:g} need tau_max up to {stress_pair_MPa:.0f} MPa even {where}: no nested "
                            "pair of this grade can pass at this speed and lift.",
        "helped": "A spring passes with {}.", "helped_join": "; or ", "tried": "None passes with {}.",
        "tried_join": ", ", "remedies": "",
        "grams": " ({grams:.0f} g)",
        "material": "{key} = \"{value}\"{grams}",
        "count": {"1": "one spring ({key} = 1){grams}", "2": "a nested pair ({key} = 2){grams}"},
        "max_installed_length": ("an installed length up to {mm:.1f} mm", "no installed length limit"),
        "rated_speed_factor": ("a rated speed lowered to {value:.1%}{rpm}", "a rated speed down to {percent:g} %"),
        "rpm": " ({rpm:.0f} rpm)",
        "reduced_mass_factor": ("a reduced mass lowered by {saved:.0%}", "a reduced mass down to {percent:g} %"),
    },
    "ru": {
        "head": "Ни одна пружина не проходит все проверки; лучший вариант: ",
        "head_pair": "Ни одна пружина не проходит все проверки; лучший вариант: ",
        "conflict": "{spring} {quantity} {value:.4g} {unit} при допустимом {limit:.4g} {unit} (не хватает {shortfall:.1%})",
        "window": "Для отношения частот нужно касательное напряжение τ_max не менее {stress_needed_MPa:.0f} МПа, "
                  "а сталь допускает не более {stress_allowed_MPa:.0f} МПа.",
        "resonance_stress": "", "pair_frequencies": "", "helped": "", "tried": "",
        "remedies": "Изменения, при которых пружина проходит, перечислены в results.json (spring.diagnosis.remedies).",
    },
}
"""The words of the spring diagnosis; an empty text is not said in that language (the Russian report states the
stress window and points to the remedies in results.json)."""


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
    words, springs = DIAGNOSIS_WORDS[lang], catalogue(lang)["springs"]
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
    t = FIT_WORDS[lang]
    text = t["fit_used"][fit].format(n=harmonics) + ": " + t["fit_reasons"][code].format(fit=fit, ratio=ratio)
    return text + ("; " + t["smoothings"][smoothing] if fit == "spline" else "")
