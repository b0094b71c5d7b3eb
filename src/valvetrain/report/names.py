"""Names a designer reads for the keys, units, values and texts of a design, in English and Russian: the words are
the catalogues' (:mod:`valvetrain.locale`, ``LANG.toml`` ``[names]``, ``[stage_names]``, ``[values]``,
``[segments]``, ``[links]``, ``[name_words]``), this module reads them.

The records of a design (``results.json``, the specification, the CSV headers) keep their machine keys
(``tappet_acceleration_m_s2``); the report shows :func:`label` of a key (``"tappet acceleration a_T, m/s²"``,
``"ускорение толкателя a_T, м/с²"``).  A key is looked up with the path of the table it belongs to
(``spring.count`` before ``count``); the unit comes from the key's suffix (``_mm``, ``_m_s2``, ``_MPa``...) and its
symbol from the one unit table :data:`valvetrain.units.UNITS`.  The names of the checks are not here: they are
renderings of their codes from the catalogue :mod:`valvetrain.locale`.

A note of a record (:class:`~valvetrain.locale.NoteText`) is rendered in the language from its codes
(:func:`translate`); a source is said in Russian by the words of its citations (:func:`valvetrain.report.russian.citation`).
A key, a value or a text without a Russian entry is shown as it is (in English): ``tests/report/test_i18n.py`` finds
them.

Symbols: one symbol for one quantity throughout the report and the plots: ``h`` lift, ``v`` velocity,
``a`` acceleration, ``j`` jerk (index ``T`` tappet side, ``v`` valve side).
"""

from ..locale import LANGS, NoteText, catalogue, check_text, note_text, record_text, spring_text
from ..units import SUFFIXES, symbol as unit_text

_NAMED = [{**catalogue(lang)["names"], **catalogue(lang)["stage_names"]} for lang in LANGS]
NAMES = {key: tuple(named[key] for named in _NAMED) for key in _NAMED[0]}
"""Names of the keys without their unit suffix (or a whole key where the suffix is no unit), one a language in the
order of :data:`~valvetrain.languages.LANGS`: ``[names]`` and ``[stage_names]`` of the catalogues."""

def _candidates(path):
    """``(name path, unit)`` to look up for a key: the whole key, then without each unit suffix it ends with,
    the shortest suffix first (``max_velocity_crank_deg`` is ``max_velocity_crank`` in deg before it is
    ``max_velocity`` in crank deg)."""
    leaf = path.rsplit(".", 1)[-1]
    prefix = path[: len(path) - len(leaf)]
    out = [(path, "")]
    for suffix, unit in sorted(SUFFIXES, key=lambda s: len(s[0])):
        if leaf.endswith(suffix) and len(leaf) > len(suffix):
            out.append((prefix + leaf[: -len(suffix)], unit))
    return out


def _lookup(path, table):
    """The entry of the longest tail of a dotted ``path`` in ``table``."""
    parts = path.split(".")
    for i in range(len(parts)):
        tail = ".".join(parts[i:])
        if tail in table:
            return table[tail]
    return None


ANGLE_UNITS = {
    **dict.fromkeys(("opens", "closes", "nose_crank", "stroke_crank", "valve_opens_crank", "valve_closes_crank",
                     "lift.crank", "opens_crank", "closes_crank", "peak_pressure_crank"), "crank deg"),
    **dict.fromkeys(("phi1", "phi2", "phi3", "phi_p0", "ramp", "event_cam", "rho_min_cam", "rho_max_cam", "lift.cam",
                     "output.table_step_cam", "cam_force_max_cam", "cam_contact_stress_cam", "lobe_centre_cam",
                     "roller_side_force_cam"),
                    "cam deg"),
}
"""Angles in degrees of the crank or of the camshaft (their keys end in ``_deg``)."""


def _named(path):
    for name_path, unit in _candidates(path):
        found = _lookup(name_path, NAMES)
        if found is not None:
            if unit == "deg":
                unit = _lookup(name_path, ANGLE_UNITS) or unit
            return found, unit
    return None, ""


def label(path, lang) -> str:
    """The name of a key of a record with its unit: ``"cam.max_velocity_m_s"`` -> ``"max tappet velocity
    v_T max, m/s"``.

    ``path`` is dotted (``"spring.count"``); the longest tail with a name wins, the unit comes from the key's
    suffix.  A key without a name is shown with spaces for its underscores -- :func:`has_name` finds them.
    """
    found, unit = _named(path)
    if found is None:
        return path.rsplit(".", 1)[-1].replace("_", " ")
    name = found[LANGS.index(lang)]
    return f"{name}, {unit_text(unit, lang)}" if unit else name


def has_name(path) -> bool:
    """True when :func:`label` has a name for ``path`` (not the key itself)."""
    return _named(path)[0] is not None


def value_text(value, lang) -> str:
    """A text value of a record (``"flat"``, ``"pushrod"``, a segment ``"Phi1 opening"``) in ``lang``: the
    catalogue's ``[values]``, or a segment of ``[segments]`` and its side (``[name_words]``); English is the value
    itself."""
    if lang == "en" or not isinstance(value, str):
        return value
    t = catalogue(lang)
    if value in t["values"]:
        return t["values"][value]
    for side in ("opening", "closing"):
        segment = value.removesuffix(f" {side}")
        if segment != value and segment in t["segments"]:
            return f"{t['segments'][segment]}, {t['name_words'][side]}"
    return translate(value, lang)


def link_names(names, lang) -> str:
    """The drive links of a dynamics record, comma-separated, in ``lang`` (``[links]`` of the catalogue; English is
    the name itself)."""
    links = catalogue(lang).get("links", {})
    return ", ".join(links.get(name, name) for name in names)


def translate(text, lang) -> str:
    """A text of a record in ``lang``: a note (:class:`~valvetrain.locale.NoteText`) rendered from its parts, a text
    that starts with drive links (``"pushrod: ..."``) with them named in ``lang`` (:func:`link_names`); another text as
    it is."""
    if lang == "en" or not text:
        return text
    if isinstance(text, NoteText):
        return note_text(text.parts, lang)
    head, sep, rest = text.partition(": ")
    if sep and all(name in catalogue(lang).get("links", {}) for name in head.split(", ")):
        return f"{link_names(head.split(', '), lang)}: {rest}"
    return text


def quantity_text(check, lang) -> str:
    """The quantity of a check in ``lang``: its valve or chapter, then the text of its code in the catalogue
    (:mod:`valvetrain.locale`): ``"intake: V′ (условная скорость в горловине)"``."""
    return record_quantity_text({"code": check.code, "params": dict(check.params), "quantity": check.quantity,
                                 "valve": check.valve}, lang)


def record_quantity_text(record, lang) -> str:
    """:func:`quantity_text` of a check record of results.json (``code``, ``params``, ``quantity``, ``valve``)."""
    params = record["params"]
    text = check_text(record["code"], params, lang)
    if "spring" in params:
        text = f"{spring_text(params['spring'], lang)}: {text}"
    head = record["quantity"].partition(": ")[0]
    if record["valve"] is not None:
        return f"{record['valve']}: {text}"
    if record["quantity"] != record_text(record["code"], params) and head in catalogue(lang)["chapters"]:
        return f"{catalogue(lang)['chapters'][head]}: {text}"
    return text


def unevaluated_text(check, lang) -> str:
    """``"cannot be evaluated: REASON"`` of a check that cannot be evaluated, in ``lang`` (the reason by
    :func:`translate`)."""
    return f"{catalogue(lang)['name_words']['cannot_evaluate']}: {translate(check.unevaluated, lang)}"

