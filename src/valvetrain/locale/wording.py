"""The words for the data the physics returns, in English and Russian: the spring diagnosis
(:class:`valvetrain.springs.Diagnosis`) and the fit a measured table uses and why
(:class:`valvetrain.laws.measured.TableLaw`).

The physics returns codes and values in SI; this module alone turns them into notes of the catalogues' ``[notes]``
(the diagnosis: :func:`diagnosis_note`) and sentences (``[fit_words]``), in the units a reader reads and with the
specification's key names.  results.json and the CLI take the English (``lang="en"``), the
report its own language.
"""

from ..units import to_display
from . import Note, catalogue, note, note_text

CODES = {"count": {1: "spring.remedy.count_1", 2: "spring.remedy.count_2"},
         "tried": {"rated_speed_factor": "spring.remedy.rated_speed_tried",
                   "reduced_mass_factor": "spring.remedy.reduced_mass_tried"},
         "kind": {"resonance_stress": "spring.resonance_stress", "pair_frequencies": "spring.pair_frequencies"}}
"""The ``[notes]`` codes of a nested pair's or a single spring's count, of a factor tried in vain and of the kind of
conflict (:data:`valvetrain.springs.diagnosis.RESONANCE_STRESS`, ``PAIR_FREQUENCIES``)."""


def _remedy(r) -> Note:
    """One remedy as a note's part."""
    grams = note("spring.remedy.grams", grams=r.spring_mass * 1e3) if r.passes and r.spring_mass is not None else ()
    if r.change == "material":
        return note("spring.remedy.material", key=r.key, value=r.value, grams=grams)
    if r.change == "count":
        return note(CODES["count"][r.value], key=r.key, grams=grams)
    if r.change == "max_installed_length":
        return (note("spring.remedy.installed_length", mm=to_display(r.value, "mm")) if r.passes and r.value is not None
                else note("spring.remedy.no_installed_length_limit"))
    if not r.passes:
        return note(CODES["tried"][r.change], percent=r.value * 100.0)
    if r.change == "rated_speed_factor":
        rpm = () if r.rated_speed is None else note("spring.remedy.rpm", rpm=to_display(r.rated_speed, "rpm"))
        return note("spring.remedy.rated_speed", value=r.value, rpm=rpm)
    return note("spring.remedy.reduced_mass", saved=1.0 - r.value)


def _conflict(x, pair) -> Note:
    """A failing check of the best candidate as a note's part: the check by its code, its value and bound in their
    display unit, the spring of a pair named."""
    values = {"check": f"spring.{x.check}", "value": to_display(x.value, x.unit),
              "limit": to_display(x.limit, x.unit), "shortfall": x.shortfall}
    part = note("spring.conflict_in", unit=x.unit, **values) if x.unit else note("spring.conflict", **values)
    return note("spring.conflict_of", spring=x.spring, conflict=part) if pair else part


def diagnosis_note(d) -> Note:
    """The spring diagnosis (:class:`valvetrain.springs.Diagnosis`) as a note of the catalogue's ``[notes]``: the
    conflicts of the best candidate, what the stress window proves, the remedies that help and those tried in vain
    (the note of a failed spring check, rendered in the report's language)."""
    said = note("spring.no_pair_passes" if d.pair else "spring.no_spring_passes",
                conflicts=sum((_conflict(x, d.pair) for x in d.conflicts), ()))
    if d.window is not None:
        w = d.window
        where = note("spring.stress_where", deflection_ratio=w.deflection_ratio,
                     max_deflection_mm=to_display(w.max_deflection, "mm"), material=w.material,
                     stress_allowed_MPa=to_display(w.allowed, "MPa"))
        needed = to_display(w.needed, "MPa")
        if d.kind is None:
            said += note("spring.stress_window", stress_needed_MPa=needed,
                         stress_allowed_MPa=to_display(w.allowed, "MPa"))
        else:
            said += note(CODES["kind"][d.kind], resonance_ratio=w.resonance_ratio, stress_needed_MPa=needed, where=where,
                         frequency_difference=d.frequency_difference,
                         stress_pair_MPa=to_display(w.needed * (1.0 + d.frequency_difference), "MPa"))
    for code, remedies in (("spring.helped", d.helped), ("spring.tried", d.tried)):
        if remedies:
            said += note(code, remedies=sum((_remedy(r) for r in remedies), ()))
    return note("spring.diagnosis", sentences=said)


def diagnosis_text(d, lang) -> str:
    """The spring diagnosis (:class:`valvetrain.springs.Diagnosis`) in words of ``lang``: :func:`diagnosis_note`
    rendered."""
    return note_text(diagnosis_note(d), lang)


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
