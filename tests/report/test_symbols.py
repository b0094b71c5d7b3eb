"""The symbols of the report (report/symbols.py)."""

import re

from valvetrain.report.symbols import SYMBOLS, symbol_legend


def test_every_symbol_has_its_meaning_in_english_and_russian():
    """``key: (HTML, English, Russian)`` (an empty HTML: a meaning without a symbol of its own, the lift law's
    coefficients): a symbol without a Russian meaning would print English in the Russian
    report's legend (tests/report/test_russian.py looks for English words in the rendered reports)."""
    for key, (_, en, ru) in SYMBOLS.items():
        assert en and ru, key
        assert ru == en or re.search("[а-яА-Я]", ru), key       # the same formula in both (lambda: R/L) or Russian


def test_the_legend_explains_each_symbol_once():
    """Every symbol is explained where it is first used: a second legend of it says nothing."""
    legend = symbol_legend("ru")
    first = legend("D", "S")
    assert first.startswith('<p class="legend">') and SYMBOLS["D"][2] in first and SYMBOLS["S"][2] in first
    assert legend("D") == ""
    second = legend("D", "n")
    assert SYMBOLS["n"][2] in second and SYMBOLS["D"][2] not in second
