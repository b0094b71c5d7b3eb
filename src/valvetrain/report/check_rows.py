"""The checks as the report shows them: each in the chapter that shows it (:func:`chapter_checks`), its name
without its chapter's, its range, verdict, margin and the class of its row, the citations in its note marked, a
check whose parts are not given in words."""

import re

from markupsafe import Markup
import numpy as np

from ..bibliography import WORKS
from ..checks import describe_range
from ..locale import NoteText, catalogue, note_text
from ..units import to_display
from .i18n import TEXT
from .names import label, quantity_text, translate, unit_text
from .numbers import percent


def check_range(c, lang) -> str:
    """The allowed range of a check record or :class:`~valvetrain.checks.Check` with its unit in ``lang``."""
    get = c.get if isinstance(c, dict) else lambda k: getattr(c, k)
    unit = get("unit")
    low, high = get("low"), get("high")
    if not isinstance(c, dict):
        low, high = (None if x is None else to_display(x, unit) for x in (low, high))
    text = describe_range(low, high, unit_text(unit, lang), bool(get("strict_low") or False), lang)
    return TEXT[lang]["any"] if text == "any" else text


def not_checked(note, lang) -> str:
    """A check whose parts are not given in words of ``lang``: a note of
    :func:`~valvetrain.design.drive_strength.not_given` with the names of the check and of the keys missing
    (:func:`label`), another note with codes (the undercut profile's) rendered from them, a text as it is."""
    if not isinstance(note, NoteText):
        return note
    code, params = note.parts[0]
    if code != "strength.not_checked" or len(note.parts) > 1:
        return translate(note, lang)
    params = dict(params)
    keys = ", ".join(label(dict(key)["key"], lang) for _, key in params["keys"])
    return TEXT[lang]["not_checked_note"].format(check=label(params["check"], lang), parts=keys)


CHECK_CHAPTERS = {
    "flow": "flow", "valve.seat_angle": "flow", "flow.time_area_velocity": "time_area",
    "flow.charge_velocity": "time_area", "law": "law", "ramp": "law", "tappet_acceleration": "law", "timing": "law",
    "seating_velocity": "law", "valve.clearance": "law", "drive.rocker_ratio": "law", "synthesis": "law",
    "cam": "geometry", "profile": "geometry", "piston": "geometry", "follower": "geometry", "spring": "springs",
    "drive.specific_mass": "springs", "gas_force": "springs", "strength": "strength", "dynamics": "dynamics",
    "grinding": "grinding", "hydraulic": "hydraulic", "lubrication": "lubrication", "lash_adjuster": "lash_adjuster",
    "engine": "engine", "crank": "crank", "camshaft": "camshaft", "ports": "ports", "breathing": "breathing",
    "phaser": "phaser", "switching": "switching", "lost_motion": "lost_motion",
}
"""The chapter of the report that shows the checks of a code: the entry of the code's longest dotted prefix
(:func:`check_chapter`)."""


def check_chapter(code) -> str:
    """The chapter of the report that shows a check of ``code`` (:data:`CHECK_CHAPTERS`), ``"other"`` for a code
    of no chapter.

    >>> check_chapter("flow.throat_velocity"), check_chapter("flow.charge_velocity"), check_chapter("new.code")
    ('flow', 'time_area', 'other')
    """
    parts = code.split(".")
    for n in range(len(parts), 0, -1):
        if ".".join(parts[:n]) in CHECK_CHAPTERS:
            return CHECK_CHAPTERS[".".join(parts[:n])]
    return "other"


def chapter_checks(results) -> dict:
    """Every check of a design in the chapter of the report that shows it: ``{valve name or None: {chapter:
    [checks]}}`` (None: the engine's chapters).  A valve's check whose chapter the report does not have (a chapter
    of a stage that did not run, a code of no chapter) is in the valve's ``"other"``, an engine's in
    ``"engine"``: every check is shown once, with its limit."""
    present = {None: {"engine", "crank" if results.crank is not None else "",
                      "camshaft" if results.camshaft is not None else "",
                      "ports" if results.two_stroke is not None else "",
                      "breathing" if results.breathing is not None else ""}}
    for name, v in results.valves.items():
        present[name] = {"flow", "law", "time_area", "geometry", "springs", "strength", "other",
                         *(k for k in ("dynamics", "grinding", "hydraulic", "lubrication", "lash_adjuster",
                                       "lost_motion")
                           if getattr(v, k) is not None), "phaser" if name in results.phasers else "",
                         "switching" if name in results.switching else ""}
    found = {key: {} for key in present}
    for c in results.checks:
        chapter = check_chapter(c.code)
        if chapter not in present[c.valve]:
            chapter = "engine" if c.valve is None else "other"
        found[c.valve].setdefault(chapter, []).append(c)
    return found


def check_verdict(c, lang) -> str:
    """A check's verdict in words (the colour of its row says the same): within or outside its range, which says
    the kind of the range (an allowable limit, a recommended range, a remark's), accepted in the specification,
    or not evaluated."""
    t = TEXT[lang]
    if not c.evaluated:
        return t["verdict_unevaluated"]
    text = t[("verdict_in_" if c.passed else "verdict_out_") + c.severity]
    return f"{text}; {t['verdict_accepted']}" if c.accepted and not c.passed else text


def check_margin(c, lang) -> str:
    """The margin of a check in per cent (:attr:`~valvetrain.checks.Check.shown_margin`), "-" where the check has
    no bound or no value."""
    margin = c.shown_margin
    return percent(margin, lang) if np.isfinite(margin) else "-"


def check_class(c) -> str:
    """The class of a check's row: ``pass``, or the severity of a check outside its range (``fail``, ``warn``,
    ``info``), ``accepted`` added for an accepted one."""
    if c.passed:
        return "pass"
    level = {"failure": "fail", "warning": "warn"}.get(c.severity, "info")
    return f"{level} accepted" if c.accepted else level


def check_note(c, lang) -> str:
    """A check's note in ``lang``: rendered from its codes (:attr:`~valvetrain.checks.Check.note_parts`), else its
    text (:func:`~valvetrain.report.names.translate`)."""
    return note_text(c.note_parts, lang) if c.note_parts else translate(c.note, lang)


SHORT_FORMS = re.compile("|".join(re.escape(w.short) for w in WORKS.values()))
"""The in-text form of every work of the bibliography."""


def marked_citations(text) -> Markup:
    """``text`` (a check's note, in the report's language) with the citations of the bibliography in it marked as
    citations (``span.cite``)."""
    parts = SHORT_FORMS.split(text)
    cites = [Markup('<span class="cite">{}</span>').format(m) for m in SHORT_FORMS.findall(text)]
    return Markup("").join(Markup.escape(p) + (cites[i] if i < len(cites) else "") for i, p in enumerate(parts))


PART_PARAMS = ("port",)
"""Parameters of a check's code that name a part the designer named (shown as names, in every language)."""


def check_name(c, lang) -> str:
    """A check's quantity in ``lang`` without its valve's or chapter's name (the chapter of the report that shows
    it names it), a part the designer named marked as a name."""
    text = quantity_text(c, lang)
    head, sep, rest = text.partition(": ")
    if sep and (head == c.valve or head in catalogue(lang)["chapters"].values()):
        text = rest
    names = [str(v) for k, v in c.params if k in PART_PARAMS]
    return Markup("").join(Markup('<span class="name">{}</span>').format(part) if part in names else part
                           for part in re.split(f"({'|'.join(map(re.escape, names))})", text)) if names else text
