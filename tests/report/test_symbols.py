"""The symbols of the report (report/symbols.py: their notation; their meanings in the catalogues' [symbols])."""

import re

from valvetrain.locale import catalogue
from valvetrain.report.symbols import NOTATION, symbol_legend


def test_every_symbol_has_its_meaning_in_english_and_russian():
    """The notation (an empty one: a meaning without a symbol of its own, the lift law's coefficients) and its
    meaning in each language: a symbol without a Russian meaning would print English in the Russian report's legend
    (tests/report/test_russian.py looks for English words in the rendered reports)."""
    en, ru = catalogue("en")["symbols"], catalogue("ru")["symbols"]
    for key in NOTATION:
        assert en[key] and ru[key], key
        assert ru[key] == en[key] or re.search("[а-яА-Я]", ru[key]), key   # the same formula (lambda: R/L) or Russian


def test_the_legend_explains_each_symbol_once():
    """Every symbol is explained where it is first used: a second legend of it says nothing."""
    meaning = catalogue("ru")["symbols"]
    legend = symbol_legend("ru")
    first = legend("D", "S")
    assert first.startswith('<p class="legend">') and meaning["D"] in first and meaning["S"] in first
    assert legend("D") == ""
    second = legend("D", "n")
    assert meaning["n"] in second and meaning["D"] not in second
    assert second.startswith('<p class="legend">') and "— частота вращения коленчатого вала, мин⁻¹" in second
