"""The typography of the rendered report's text, in every language: a symbol's index as a subscript (``a_T`` ->
a<sub>T</sub>), ``<=`` and ``>=`` as ≤ and ≥, a power of ten for a number's exponent (``3.6e+05`` -> 3.6·10⁵), × between
numbers, superscript unit powers (``m/s2`` -> m/s²).  Only the text is changed, never a tag, an attribute, a name the
designer gave, a link or a work in another language's entry (:func:`map_text`).
"""

import re

from ..languages import LANGS
from ..locale import catalogue

_WORDS = [catalogue(lang)["locators"] for lang in LANGS]
AND = "|".join(f" {words['and']} " for words in _WORDS)
"""The words joining two numbers of a locator or two locators, in every language (``[locators]`` of the catalogues):
`` and | и ``."""

LOCATOR = "(?:" + "|".join(word for words in _WORDS for word in words["words"]) + ")"
"""The words of a locator in a citation in every language (``[locators]`` of the catalogues): ``work 2``,
``eqs. (2.23)-(2.34)``, ``section 2.1``, ``Fig. 2.6``, ``формулы 6.12``..."""

CORRECTIONS = "(?:" + "|".join(words["corrections"] for words in _WORDS) + ")"
"""A citation of the corrections notes in every language (``corrections note 20``, ``поправка 20``), without its
number."""

_NUMBER = r"(?:[A-Z]-?)?\d+(?:[.\-–]\d+)*[a-zа-я]?"
_NUMBER = rf"(?:\({_NUMBER}\)|{_NUMBER})"
LOCATORS = rf"{LOCATOR}(?: {_NUMBER}(?:(?:-|–|, |{AND}){_NUMBER})*)?"
"""A locator with its numbers, a list or a range of them (``eqs. (2.23)-(2.34)``, ``формулы 6.12, 6.14``,
``разделы 5.1-5.3``)."""

_TAG = re.compile(r"(<[^>]+>)")
_OPEN = re.compile(r"<(\w+)([^>]*)>")
_NAME = re.compile(r'class="name"')
_LANG = re.compile(r'\blang="([^"]*)"')
"""Elements whose text is kept as it is: names given by the designer, file names (``class="name"``) and works in
another language than the page's (``lang``)."""
_KEPT_TAGS = ("a", "style", "title", "script")
_VOID = ("br", "img", "meta", "hr", "input", "link")


def map_text(page, change, lang) -> str:
    """``page`` (HTML in ``lang``) with ``change(text)`` applied to every run of its text outside the kept elements
    (the designer's names, links, the head, works in another language); ``change`` may return markup.

    >>> map_text('<p>a <span class="name">b</span> c <i lang="de">d</i></p>', str.upper, "en")
    '<p>A <span class="name">b</span> C <i lang="de">d</i></p>'
    """
    out, kept = [], []
    for part in _TAG.split(page):
        if part.startswith("<"):
            if part.startswith("</"):
                if kept and part[2:-1].strip() == kept[-1][0]:
                    kept[-1][1] -= 1
                    if kept[-1][1] == 0:
                        kept.pop()
            else:
                m = _OPEN.match(part)
                if m and not part.endswith("/>") and m[1] not in _VOID:
                    if kept and m[1] == kept[-1][0]:
                        kept[-1][1] += 1
                    elif m[1] in _KEPT_TAGS or _NAME.search(m[2]) or _LANG.search(m[2]) and \
                            _LANG.search(m[2])[1] != lang:
                        kept.append([m[1], 1])
            out.append(part)
        elif kept or not part.strip():
            out.append(part)
        else:
            out.append(change(part))
    return "".join(out)


GREEK = {"phi": "φ", "tau": "τ", "rho": "ρ", "psi": "ψ", "chi": "χ", "omega": "ω"}
"""Greek letters spelt out in a symbol of a source's text (``phi_p0``)."""

_LETTER = "A-Za-zΑ-Ωα-ωА-Яа-яЁё"
SYMBOL = re.compile(rf"(?<![\w.-])(Δ?[{_LETTER}]{{1,2}}|{'|'.join(GREEK)})_(-?[{_LETTER}0-9]{{1,4}}"
                    rf"(?: (?:max|min)(?![{_LETTER}0-9_]))?)(?![{_LETTER}0-9_])")
"""A symbol with its index: one or two letters (or a Greek letter's name) joined by ``_`` to an index of up to four
letters or digits, ``max``/``min`` after a blank taken into the index (``a_T max``); not a key of the specification
(``stroke_mm``, ``masses.at_valve_kg``), whose first word is longer or follows a dot."""

SUPERSCRIPTS = str.maketrans("-+0123456789", "⁻⁺⁰¹²³⁴⁵⁶⁷⁸⁹")
_EXPONENT = re.compile(r"(?<![\w.])(-?\d+(?:\.\d+)?)e([+-]?)0*(\d+)\b")
_RELATION = (("&lt;=", "≤"), ("&gt;=", "≥"))
_TIMES = re.compile(r"(?<=\d) x (?=\d)")
_POWER = re.compile(r"(?<=\d )(m/s|kg/m|mm|cm|m)([23])\b")


def _symbols(text) -> str:
    def sub(m):
        base = GREEK.get(m.group(1), m.group(1))
        return f"{base}<sub>{m.group(2)}</sub>"
    return SYMBOL.sub(sub, text)


def _exponent(m) -> str:
    sign = "-" if m.group(2) == "-" else ""
    return f"{m.group(1)}·10{(sign + m.group(3)).translate(SUPERSCRIPTS)}"


def typography(page, lang) -> str:
    """The rendered report with its symbols' indices as subscripts, ≤ and ≥, powers of ten, × between numbers and
    superscript unit powers in its text (:func:`map_text`).

    >>> typography('<td>a_T max &lt;= 3500 m/s2, f_max/f_min, phi_p0, 3.603e+05 N/mm, 2 x 3</td>', "en")
    '<td>a<sub>T max</sub> ≤ 3500 m/s², f<sub>max</sub>/f<sub>min</sub>, φ<sub>p0</sub>, 3.603·10⁵ N/mm, 2 × 3</td>'
    >>> typography('<td>stroke_mm / bore_mm, masses.at_valve_kg, Δa_T, d_g²</td><a href="x">intake_lift.csv</a>', "en")
    '<td>stroke_mm / bore_mm, masses.at_valve_kg, Δa<sub>T</sub>, d<sub>g</sub>²</td><a href="x">intake_lift.csv</a>'
    """
    def change(text):
        for ascii_, sign in _RELATION:
            text = text.replace(ascii_, sign)
        text = _EXPONENT.sub(_exponent, text)
        text = _POWER.sub(lambda m: m.group(1) + m.group(2).translate(SUPERSCRIPTS), _TIMES.sub(" × ", text))
        return _symbols(text)
    return map_text(page, change, lang)
