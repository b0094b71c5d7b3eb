"""The message catalogue: the texts of the design checks in every language, kept as data.

Every check of a design has a stable code (``tappet_acceleration.max``) and may have parameters (the exponent of a
power-polynomial cam, the port of a two-stroke).  Its texts are renderings of the code from one file per language
in this folder, loaded once:

* ``en.toml`` ``[record]``: the check's English text in ``results.json``, the console and ``[[accepted]]``;
* ``en.toml`` ``[former]``: record texts a code had before, still names of its check in ``[[accepted]]``;
* ``LANG.toml`` ``[checks]``: the check as the report in ``LANG`` names it;
* ``LANG.toml`` ``[springs]``: the springs whose own checks are named after them;
* ``LANG.toml`` ``[verdict]``: the verdict of a design, the same on the command line, in the report and in ``repr``;
* ``LANG.toml`` ``[designer]``: the words of the designer in the browser (``valvetrain serve``, :mod:`valvetrain.web`);
* ``LANG.toml`` ``[words]``, ``[check_words]``, ``[stage_words]``, ``[note_words]``, ``[report]``: the words of the
  report (:data:`valvetrain.report.i18n.TEXT`), ``[optimize_words]`` and ``[tolerance_words]`` those of the
  optimisation's and the tolerance study's reports;
* ``LANG.toml`` ``[names]``, ``[stage_names]``, ``[symbols]``, ``[name_words]``: the names of the keys of the records,
  the meanings of the report's symbols (:mod:`valvetrain.report.names`, :mod:`valvetrain.report.symbols`);
  ``[values]``, ``[segments]``, ``[links]`` (not in ``en.toml``: their English is the key itself) the text values of
  the records, the lift law's segments and the drive links;
* ``LANG.toml`` ``[reference_words]``: the words of a reference in the list of sources (:mod:`valvetrain.bibliography`);
  ``[worked_symbols]``: the worked examples' symbols whose index is a word; ``ru.toml`` ``[citation_locators]``,
  ``[citation_units]`` (regular expressions of the English): the Russian of the locators and units of the report's
  citations (:mod:`valvetrain.report.russian`);
* ``LANG.toml`` ``[notes]``: the notes of the checks (how a value was obtained: where, at which speed), each a code
  with parameters (:func:`note`), rendered by :func:`note_text` in every language, its numbers by
  :func:`number_text`; so are the words of the sources (``source.*``, :func:`cited`), the refusals of a key's value
  (``field.*``: its range; ``spec.*``: a problem across keys) and of a lift law (``law_error.*``).

``{name}`` in a text stands for the parameter ``name``; in a note, a parameter may be a note of its own (a list
said inside the part, joined by what follows ``|`` in its field: ``{remedies:|; or }``), and ``{name:@section}``
says the word of the value in that section of the language (``@units``: a unit's symbol).  ``tests/locale/test_catalogue.py`` fails when a code lacks a
text in a language or a text names no code the package uses; docs/checks.md lists every code.

A check's code (dotted snake_case) is stable: never renamed once shipped.  ``[[accepted]]`` takes the code (every
check of the code) or the printed text, which :func:`code_of` maps to the code and its parameters.  To add a check:
make it with ``checks.check("domain.quantity", value, low, high, source=..., unit=..., params={...})`` and give the
code its texts with ``PYTHONPATH=src python tools/check_codes.py add CODE "record text" "English name" "Russian
name"`` (or edit the files by hand and run ``tools/check_codes.py``, which rewrites docs/checks.md).  A text made with
numbers is a code of ``[notes]`` with its numbers as parameters (``{speed_rpm:.0f}``: the format of the number,
the same in every language); a record's text made so is a :class:`NoteText` (its English,
keeping its parts).  A check's source is its citations and their words (:func:`cited`: each work as written, its
words a ``source.*`` code of ``[notes]``), said in each language in the report and the designer alike, their
locators in Russian by ``[citation_locators]`` and ``[citation_units]``; ``[locators]`` holds the words
by which each language's locators are found in a citation (:mod:`valvetrain.report.typography`).  :mod:`.wording` words the data the physics returns (the spring diagnosis, a measured
table's fit reason) in every language.

To add a language: a ``LANG.toml`` with every section, the language in :data:`valvetrain.languages.LANGS`, its symbol
column in :data:`valvetrain.units.UNITS`.  To add a unit: one row of :data:`valvetrain.units.UNITS`.
"""

from functools import cache
from importlib.resources import files
import numbers
import re
import string
import tomllib
from typing import Any

from ..errors import InputError
from ..languages import LANGS
from ..units import symbol as unit_symbol


@cache
def catalogue(lang) -> dict[str, Any]:
    """The catalogue of ``lang`` as read from ``LANG.toml``."""
    if lang not in LANGS:
        raise InputError(f"language {lang!r}: allowed {LANGS}")
    return tomllib.loads(files("valvetrain.locale").joinpath(f"{lang}.toml").read_text(encoding="utf-8"))


def codes() -> tuple[str, ...]:
    """Every check code of the catalogue, in its order."""
    return tuple(catalogue("en")["record"])


def _template(section, code, lang="en"):
    try:
        return catalogue(lang)[section][code]
    except KeyError:
        raise InputError(f"check code {code!r} has no text in src/valvetrain/locale/{lang}.toml [{section}]: "
                         "add it (docs/architecture.md, Checks)") from None


def parameters(code) -> tuple[str, ...]:
    """The names of the parameters of a check code, in the order its English record names them."""
    return tuple(name for _, name, _, _ in string.Formatter().parse(_template("record", code)) if name)


def record_text(code, params=()) -> str:
    """The English text of a check in the records (``results.json``, console, ``[[accepted]]``).

    >>> record_text("law.power_polynomial.exponent", {"exponent": "n"})
    'power-polynomial exponent n'
    """
    return _template("record", code).format(**dict(params))


def check_text(code, params, lang) -> str:
    """The name of a check in the report in ``lang`` (without the valve or chapter it belongs to).

    >>> check_text("tappet_acceleration.max", {}, "ru")
    'наибольшее ускорение толкателя a_T max'
    """
    return _template("checks", code, lang).format(**dict(params))


def spring_text(spring, lang) -> str:
    """The name of a spring of a drive (``spring``, ``outer``, ``inner``) in ``lang``."""
    return catalogue(lang)["springs"][spring]


@cache
def _patterns():
    out = []
    former = catalogue("en").get("former", {})
    for code in codes():
        for template in (_template("record", code), *former.get(code, ())):
            parts = [re.escape(lit) + ("" if name is None else f"(?P<{name}>.+?)")
                     for lit, name, _, _ in string.Formatter().parse(template)]
            out.append((code, re.compile("".join(parts), re.IGNORECASE)))
    return tuple(out)


def code_of(text) -> tuple[str, dict[str, str]] | None:
    """The code and the parameters of a check's English record text (case and blanks as written), or None: the
    texts printed before the codes stay valid names of their checks, and so do the record texts a code had before
    (``en.toml`` ``[former]``: ``[[accepted]]`` tables written with them).

    >>> code_of("Power-polynomial exponent  n")
    ('law.power_polynomial.exponent', {'exponent': 'n'})
    """
    text = " ".join(text.split())
    for code, pattern in _patterns():
        m = pattern.fullmatch(text)
        if m:
            return code, m.groupdict()
    return None


def code_table() -> str:
    """The Markdown table of every check code: its parameters and its texts in every language (docs/checks.md,
    written by ``python tools/check_codes.py``)."""
    head = ["code", "parameters", "record text (results.json, [[accepted]])", *(f"report ({lang})" for lang in LANGS)]
    rows = [[f"`{code}`", ", ".join(parameters(code)), _template("record", code),
             *(_template("checks", code, lang) for lang in LANGS)] for code in codes()]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    lines += ["| " + " | ".join(cell.replace("|", "\\|") for cell in row) + " |" for row in rows]
    return "\n".join(lines)


def number_text(x, spec, lang="en") -> str:
    """A number of a text in ``lang``, formatted by ``spec`` (:func:`format`'s), with a decimal comma in Russian: the
    one rule of the numbers of the catalogue's texts.

    >>> number_text(1.25, ".3g"), number_text(1.25, ".3g", "ru"), number_text(-7200.4, ".0f", "ru")
    ('1.25', '1,25', '-7200')
    """
    text = format(x, spec)
    return text.replace(".", ",") if lang == "ru" else text


class _Numbers(string.Formatter):
    """The catalogue's formatter in one language: a number by :func:`number_text`; a note (a parameter that is
    :func:`note`'s parts) rendered in the language, its parts joined by what follows ``|`` in the field's format
    (``{remedies:|; or }``; by ``"; "`` without one); a word by reference (``{check:@checks}``: the text of the value in the language's
    section ``[checks]``, the value itself where the language has none; ``{unit:@units}``: a unit's symbol,
    :func:`valvetrain.units.symbol`); any other value as it is."""

    def __init__(self, lang):
        self.lang = lang

    def format_field(self, value, format_spec):
        if isinstance(value, tuple):
            return note_text(value, self.lang, format_spec.removeprefix("|") if format_spec else "; ")
        if isinstance(value, str) and format_spec == "@units":
            return unit_symbol(value, self.lang)
        if isinstance(value, str) and format_spec.startswith("@"):
            return catalogue(self.lang).get(format_spec[1:], {}).get(value, value)
        if isinstance(value, numbers.Real) and not isinstance(value, bool):
            return number_text(value, format_spec, self.lang)
        return format(value, format_spec)


Note = tuple[tuple[str, tuple[tuple[str, "float | str | Note"], ...]], ...]
"""A check's note as data (:func:`note`'s parts): each part a ``[notes]`` code and its parameters (a number, a text,
or a note of its own: a list said inside the part)."""


def note(code, **params) -> Note:
    """A check's note as data: one part, the code of ``[notes]`` and its parameters (numbers in SI or display units
    as the text says, never preformatted); parts add up (``note(a) + note(b)``: joined by ``"; "``).

    >>> note("hydraulic.largest_at", speed_rpm=7000.0)
    (('hydraulic.largest_at', (('speed_rpm', 7000.0),)),)
    """
    _template("notes", code)
    return ((code, tuple(params.items())),)


def note_text(parts, lang="en", join="; ") -> str:
    """A check's note (:func:`note`'s parts) in ``lang``, the parts joined by ``join``; a part whose text is empty
    in ``lang`` is not said there.

    >>> note_text(note("hydraulic.largest_at", speed_rpm=7012.4), "ru")
    'наибольший при 7012 мин⁻¹'
    """
    formatter = _Numbers(lang)
    said = (formatter.format(_template("notes", code, lang), **dict(params)) for code, params in parts)
    return join.join(text for text in said if text)


class NoteText(str):
    """A note as the text of a result record: its English (what ``results.json`` and the console write, a plain text
    to them) that keeps its parts (:func:`note`), from which the report renders it in its language
    (:func:`valvetrain.report.names.translate`).

    >>> said = NoteText(note("hydraulic.largest_at", speed_rpm=7012.4))
    >>> said, note_text(said.parts, "ru")
    ('largest at 7012 rpm', 'наибольший при 7012 мин⁻¹')
    """

    parts: Note

    def __new__(cls, parts):
        text = super().__new__(cls, note_text(parts))
        text.parts = tuple(parts)
        return text

    @classmethod
    def of(cls, code, **params) -> "NoteText":
        """The text of one note (:func:`note`'s code and parameters): a message said in every language.

        >>> NoteText.of("field.zero_none")
        'none'
        """
        return cls(note(code, **params))

    def __reduce__(self):
        return NoteText, (self.parts,)


def note_of(text) -> Note:
    """The parts of a text said in every language: a :class:`NoteText`'s own, else the text as it is in every
    language (a message of a library, a file's name).

    >>> note_of(NoteText(note("field.zero_none"))), note_of("x")
    ((('field.zero_none', ()),), (('plain', (('text', 'x'),)),))
    """
    return text.parts if isinstance(text, NoteText) else note("plain", text=str(text))


def cited(*pieces) -> NoteText:
    """A source said in every language (a :class:`NoteText`): its pieces joined by ``"; "``, each a citation as
    written (a work and its locators, :func:`valvetrain.bibliography.cite`: the same in every language, its locators
    put in the report's language by the report), the words of a source (:func:`note` of a ``source.*`` code, the
    citation they qualify its parameter ``work``) or a source of its own.

    >>> said = cited("Shang Hanji (1988), ch. 3 and ch. 7", note("source.usual_seating"))
    >>> said, note_text(said.parts, "ru")
    ('Shang Hanji (1988), ch. 3 and ch. 7; 0.3-0.5 m/s usual', 'Shang Hanji (1988), ch. 3 and ch. 7; обычно 0,3-0,5 м/с')
    """
    return NoteText(sum((note_of(piece) if isinstance(piece, str) else piece for piece in pieces), ()))


def verdict(counts, lang="en") -> tuple[str, str]:
    """The verdict of a design in words: ``(sentence, counts)``, the same on the command line, in the report and in
    ``repr``.

    Parameters
    ----------
    counts : dict
        :func:`valvetrain.checks.tally` of the design's checks.
    lang : {"en", "ru"}
    """
    t = catalogue(lang)["verdict"]
    return t["fail" if counts["failure"] else "pass"].format(**counts), t["counts"].format(**counts)
