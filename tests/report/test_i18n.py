"""The Russian report is Russian throughout: every visible text of the report of the built-in example and of every
shipped example, every check quantity and every plot label (issue 10, "The report" and "Words")."""

from collections import defaultdict
from pathlib import Path
import re

import pytest

from valvetrain.design import run
from valvetrain.report import plots as report_plots
from valvetrain.report.figure import figure_texts
from valvetrain.report.html import render_report
from valvetrain.report.i18n import TEXT
from valvetrain.report.names import label, quantity_text
from valvetrain.specification import example_spec, load_spec

from visible_text import Visible, english_words

EXAMPLES = sorted((Path(__file__).parents[2] / "examples").glob("*.toml"))

def _plots():
    """Plot file names for a report rendered without its folder (the figures are linked, not embedded)."""
    return defaultdict(lambda: defaultdict(lambda: "figure.png"))


def _specs():
    return [("built-in", example_spec())] + [(f.stem, load_spec(f)) for f in EXAMPLES]


@pytest.fixture(scope="module")
def designs():
    return {name: run(spec) for name, spec in _specs()}


def test_russian_report_without_its_figures_has_no_english_words(designs):
    """A figure not drawn (``--figures``) is named in Russian, beside the command that draws it."""
    parser = Visible()
    parser.feed(render_report(designs["built-in"], {}, "ru"))
    notes = [text for text in parser.texts if "строится по запросу" in text]
    # the built-in example's 8 of each of its two valves (6, and 2 of its dynamics), the timing, 3 of the crank
    assert len(notes) == 2 * 8 + 1 + 3 and english_words(notes) == []


def test_russian_report_has_no_english_words(designs):
    for name, results in designs.items():
        parser = Visible()
        parser.feed(render_report(results, _plots(), "ru"))
        assert parser.texts
        assert english_words(parser.texts) == [], name


def test_the_extractor_finds_english():
    parser = Visible()
    parser.feed('<p>подъём <span class="cite">Valve-train practical works (n.d.), work 1</span> tappet_lift_mm</p><img alt="lift">'
                '<style>p { color: red }</style>')
    assert [w for w, _ in english_words(parser.texts)] == ["tappet", "lift", "mm", "lift"]


def test_english_report_shows_names_not_keys(designs):
    html = render_report(designs["built-in"], _plots(), "en")
    parser = Visible()
    parser.feed(html)
    keys = [t for t in parser.texts if re.search(r"\b[a-z]+_[a-z_]+\b", t) and not re.search(r"[A-Za-z]_[A-Za-z]{1,3}\b", t)]
    assert keys == []
    assert "valve lift h<sub>v</sub>, mm" in html.lower()      # the index of a symbol as a subscript


def test_every_check_of_the_examples_has_a_russian_name(designs):
    """Every check the examples make is named in Russian from the catalogue, by its code: a check that has none is
    refused when it is made (tests/locale/test_catalogue.py)."""
    for results in designs.values():
        for c in results.checks:
            text = quantity_text(c, "ru")
            assert text != c.quantity and not re.search(r"\b(?:the|of|at|and)\b", text), (c.code, text)


def _figure_texts(fig):
    """The figure's texts but its ticks' (numbers, labelled when drawn; matplotlib's findobj would make them: a
    quarter of this file's time): test_plots.py's test_a_symbols_index_is_a_subscript_in_every_figure holds
    figure_texts to findobj's texts."""
    texts = [t.get_text() for t in figure_texts(fig)]
    return [t for t in texts if t and not re.fullmatch(r"[−\-+0-9.,e ]*", t)]


def test_plot_labels_come_from_the_texts(designs):
    """Every figure's titles, axis labels and legends are the Russian texts (valve and port names excepted)."""
    t = TEXT["ru"]
    seen = 0
    for results in designs.values():
        names = set(results.valves) | (set(results.two_stroke.summary["ports"]) if results.two_stroke else set())
        figures = [make(v, t) for v in results.valves.values() for make in report_plots.FIGURES.values()]
        figures += [make(v, t) for v in results.valves.values() if v.hydraulic is not None
                    for make in (report_plots.hydraulic_figure, report_plots.hydraulic_sweep_figure)]
        if results.valves:
            figures.append(report_plots.timing_figure(results.valves, t))
        for stage, makers in report_plots.ENGINE_FIGURES.items():
            data = getattr(results, stage)
            if data is not None:
                figures += [make(data, t) for make in makers.values()]
        for fig in figures:
            texts = [re.sub("|".join(map(re.escape, sorted(names, key=len, reverse=True))), "", x) if names else x
                     for x in _figure_texts(fig)]
            assert english_words(texts) == []
            seen += 1
    assert seen > 20


def test_one_symbol_for_one_quantity():
    """Acceleration is a, jerk is j, in the plots and in the tables of both languages."""
    for lang in ("en", "ru"):
        t = TEXT[lang]
        assert "a_T" in t["acceleration"] and "j_T" in t["jerk"] and "v_T" in t["velocity"]
        assert "a_v" in t["inertia_force"] and "j_" not in t["inertia_force"] + t["required_force"]
        assert "a_T" in label("lift.tappet_acceleration_m_s2", lang)
