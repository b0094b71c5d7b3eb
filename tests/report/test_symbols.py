"""The symbols of the report (report/symbols.py)."""

import re

from valvetrain.report.symbols import SYMBOLS


def test_every_symbol_has_its_meaning_in_english_and_russian():
    """``key: (HTML, English, Russian)`` (an empty HTML: a meaning without a symbol of its own, the lift law's
    coefficients): a symbol without a Russian meaning would print English in the Russian
    report's legend (tests/report/test_russian.py looks for English words in the rendered reports)."""
    for key, (_, en, ru) in SYMBOLS.items():
        assert en and ru, key
        assert ru == en or re.search("[а-яА-Я]", ru), key       # the same formula in both (lambda: R/L) or Russian
