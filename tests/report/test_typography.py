"""The typography of the report's text (report/typography.py).  Issue 39: the note's leftovers, "<=", "e+05", both
"об/мин" and "мин⁻¹", "сем. 001", underscores in printed symbols, are gone from the built-in example's note in both
languages; a designer's name, a link and a key of the specification are left as they are."""

import re

import pytest

from valvetrain.design import run
from valvetrain.report.html import render_report
from valvetrain.report.typography import SYMBOL, map_text, typography
from valvetrain.specification import example_spec


def test_symbols_relations_exponents_and_powers():
    """Each rule on a text written by hand, and what it leaves alone."""
    assert typography("<p>a_T max &lt;= 3500 m/s2; n &gt;= 1.3</p>", "en") == \
        "<p>a<sub>T max</sub> ≤ 3500 m/s²; n ≥ 1.3</p>"
    assert typography("<p>3.603e+05 N/mm, 6.8e-07 m, 1e+10</p>", "en") == "<p>3.603·10⁵ N/mm, 6.8·10⁻⁷ m, 1·10¹⁰</p>"
    assert typography("<p>m_кл/f_г, phi_p0, tau_-1, Φ_3², 4 x 387.8</p>", "ru") == \
        "<p>m<sub>кл</sub>/f<sub>г</sub>, φ<sub>p0</sub>, τ<sub>-1</sub>, Φ<sub>3</sub>², 4 × 387.8</p>"
    kept = ('<p><span class="name">a_T &lt;= 1e+05</span> stroke_mm, parts.tappet_diameter_mm, '
            'drive_stiffness_N_per_mm <a href="t">tables/intake_lift.csv</a></p>')
    assert typography(kept, "en") == kept
    assert typography('<li lang="de">a_T</li><li lang="en">a_T</li>', "en") == \
        '<li lang="de">a_T</li><li lang="en">a<sub>T</sub></li>'


def test_the_text_only_is_changed():
    """Tags and attributes are never changed, nested kept elements included."""
    page = '<img alt="a_T &lt;= 1"><p title="x_y">b_c <span class="name">d_e <b>f_g</b> h_i</span> j_k</p>'
    assert map_text(page, str.upper, "en") == \
        '<img alt="a_T &lt;= 1"><p title="x_y">B_C <span class="name">d_e <b>f_g</b> h_i</span> J_K</p>'


@pytest.fixture(scope="module")
def builtin():
    return run(example_spec())


def _visible(page):
    """The report's text outside the designer's names, links and works in other languages."""
    page = re.sub(r"<style.*?</style>", "", page, flags=re.S)
    page = re.sub(r'<(span|a) class="name"[^>]*>.*?</\1>|<a [^>]*>.*?</a>', "", page, flags=re.S)
    return re.sub(r"<[^>]+>", " ", page)


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_the_note_has_no_leftovers(builtin, lang):
    text = _visible(render_report(builtin, {}, lang))
    assert "&lt;=" not in text and "&gt;=" not in text and "≤" in text
    assert not re.search(r"\de[+-]\d", text)
    assert "об/мин" not in text and "сем. 0" not in text and (lang == "en" or "мин⁻¹" in text)
    symbols = [m.group() for m in SYMBOL.finditer(text)]
    assert symbols == [], symbols
