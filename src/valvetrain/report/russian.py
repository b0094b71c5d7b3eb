"""The Russian report's citations and typography: the locators of the numbered citations (work, eq., section) in
Russian (their words in the catalogue, ``ru.toml``), the decimal comma and «» quotes.

The report cites every work by its number in its list of sources (:func:`valvetrain.report.html.numbered_citations`),
each work described in its own language (:meth:`valvetrain.bibliography.Work.reference`);
:func:`russian_citations` turns the locators of the rendered Russian report's citations into Russian; the words of
the sources come from the catalogue already (``source.*`` notes, :func:`valvetrain.locale.cited`).
"""

from functools import cache
from html import escape, unescape
import re

from ..locale import catalogue
from .typography import LOCATORS, map_text


@cache
def _citation_words():
    """The Russian of the citations' locators and units from the catalogue (``ru.toml`` ``[citation_locators]``,
    ``[citation_units]``): regular expressions and their replacements, in the catalogue's order."""
    words = catalogue("ru")
    return tuple(words["citation_locators"].items()) + tuple(words["citation_units"].items())


_CITE = re.compile(r'(<span class="cite">)(.*?)(</span>)', re.S)


def citation(text) -> str:
    """One citation in Russian: its locators and units (its words are said in Russian before, from the catalogue's
    ``source.*`` notes: :func:`valvetrain.report.names.translate`).

    >>> citation("[2, work 1, eq. (1.1)]")
    '[2, работа 1, формула (1.1)]'
    >>> citation("[1, section 2.1, eqs. (2.13)-(2.14)]; [6, Tables 10-4, 10-6]: 0.5 mm")
    '[1, раздел 2.1, формулы (2.13)-(2.14)]; [6, таблицы 10-4, 10-6]: 0.5 мм'
    """
    for pattern, ru in _citation_words():
        text = re.sub(pattern, ru, text)
    return text


def russian_citations(page) -> str:
    """The rendered Russian report with its citations in Russian (:func:`citation` on every ``span.cite``)."""
    return _CITE.sub(lambda m: m.group(1) + escape(citation(unescape(m.group(2))), quote=False) + m.group(3), page)


_DECIMAL = re.compile(r"(?<![\d,])(?<!\d\.)(?<!\()(\d+)\.(\d+)(?!\.?\d)")
"""A decimal point between digits, not in an equation's number in brackets (``(7.4)``) nor in a version
(``0.1.0``)."""
_LOCATED = re.compile(LOCATORS)
"""A locator of a source with its numbers (:data:`~.typography.LOCATORS`): their points are not decimal."""
_QUOTED = re.compile(r'"([^"<>]*)"')


def russian_typography(page) -> str:
    """The rendered Russian report with a decimal comma in every number of its text and «» for quotation marks
    (:data:`_DECIMAL`; the designer's names, links, the file's head and works in other languages as they are).

    >>> russian_typography('<p>при 7700 мин⁻¹, -56.87 град, формулы (7.4)-(7.5), "quoted"</p>')
    '<p>при 7700 мин⁻¹, -56,87 град, формулы (7.4)-(7.5), «quoted»</p>'
    >>> russian_typography('<span class="name">v1.5</span> 0.5...0.75 <a href="x">tables/a.0.5.csv</a>')
    '<span class="name">v1.5</span> 0,5...0,75 <a href="x">tables/a.0.5.csv</a>'
    """
    return map_text(page, lambda text: _QUOTED.sub(r"«\1»", _decimal_commas(text)), "ru")


def _decimal_commas(text) -> str:
    """``text`` with a decimal comma for each decimal point of :data:`_DECIMAL` outside the locators of sources
    (:data:`_LOCATED`).

    >>> _decimal_commas("формулы 6.12, 6.14; разделы 5.1-5.3 при 0.25 мм; ф. 2.5 при 1.5 мм")
    'формулы 6.12, 6.14; разделы 5.1-5.3 при 0,25 мм; ф. 2.5 при 1,5 мм'
    """
    parts, end = [], 0
    for m in _LOCATED.finditer(text):
        parts += [_DECIMAL.sub(r"\1,\2", text[end:m.start()]), m.group()]
        end = m.end()
    return "".join(parts) + _DECIMAL.sub(r"\1,\2", text[end:])
