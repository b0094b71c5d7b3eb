"""The figures of the engine's chapters (report/engine_plots.py): the crank mechanism's and the breathing's."""

import re

from matplotlib.backends.backend_agg import FigureCanvasAgg
import numpy as np
import pytest

from valvetrain.design import run
from valvetrain.report import engine_plots
from valvetrain.report.i18n import TEXT

from appendix import appendix_spec
from figure_checks import all_texts_on_the_figures


@pytest.fixture(scope="module")
def results():
    return run(appendix_spec())


def test_the_crank_figures_legends_cover_no_curve(results):
    """Issue 39: the crank torque figure's legend covered the curves (upper right of the axes, over the cylinders'
    torque).  Every legend of the crank figures lies beside its axes (their window extents do not meet), every text
    on the figure, the cycle's angle from 0 to 720 deg with a tick at 720 (it stopped at 630), in both languages."""
    crank = results.crank
    figures = [(kind, lambda t, make=make: make(crank, t)) for kind, make in engine_plots.ENGINE_FIGURES["crank"].items()]
    all_texts_on_the_figures(figures)
    for kind, draw in figures:
        for lang in ("en", "ru"):
            fig = draw(TEXT[lang])
            renderer = FigureCanvasAgg(fig).get_renderer()
            for ax in fig.axes:
                legend = ax.get_legend()
                if legend is not None:
                    assert not legend.get_window_extent(renderer).overlaps(ax.get_window_extent(renderer)), kind
                if kind != "crank_pin_polar":
                    assert ax.get_xlim() == pytest.approx((0.0, 720.0)) and 720.0 in ax.get_xticks(), kind


def test_the_breathing_figures_in_both_languages():
    """Issue 37: the breathing chapter's figures, English and Russian: the p-V and the log p - log V indicator
    diagrams (one line per condition, the cycle's volumes and pressures, the second axes logarithmic on both) and
    the volumetric efficiency with the indicated torque of a fired engine against the curve's speeds; every text on
    the figure, its titles in the report's language."""
    from valvetrain.specification import example_spec, spec_document, validate
    doc = spec_document(example_spec())
    for valve in doc["valves"].values():
        valve["dynamics"]["speeds"] = 20
    doc["breathing"] = {"mode": "fired", "wall_temperature_C": 150.0,
                        "conditions": [{"speed_rpm": 3000.0, "intake_pressure_kPa": 100.0, "intake_temperature_C": 25.0,
                                        "exhaust_pressure_kPa": 105.0}],
                        "curve": {"speed_range_rpm": [2000.0, 6000.0], "points": 3, "intake_pressure_kPa": 100.0,
                                  "intake_temperature_C": 25.0, "exhaust_pressure_kPa": 105.0}}
    breathing = run(validate(doc)).breathing
    figures = [(kind, lambda t, make=make: make(breathing, t))
               for kind, make in engine_plots.ENGINE_FIGURES["breathing"].items()]
    all_texts_on_the_figures(figures)
    cycle = breathing.conditions[0].columns
    for lang in ("en", "ru"):
        t = TEXT[lang]
        linear, logs = engine_plots.breathing_pv_figure(breathing, t).axes
        assert (logs.get_xscale(), logs.get_yscale(), linear.get_xscale()) == ("log", "log", "linear")
        for ax, title in ((linear, t["br_pv"]), (logs, t["br_log_pv"])):
            (line,) = ax.get_lines()
            assert np.array_equal(line.get_xdata(), cycle.volume * 1e6)
            assert np.array_equal(line.get_ydata(), cycle.pressure * 1e-3) and ax.get_title() == title
        efficiency, torque = engine_plots.breathing_speed_figure(breathing, t).axes
        assert list(efficiency.get_lines()[0].get_xdata()) == pytest.approx([2000.0, 4000.0, 6000.0])
        assert list(efficiency.get_lines()[0].get_ydata()) == [r.figures.volumetric_efficiency
                                                                for r in breathing.curve]
        assert list(torque.get_lines()[0].get_ydata()) == pytest.approx([r.figures.torque for r in breathing.curve])
        assert efficiency.get_ylabel().startswith(t["br_efficiency"].split(" η")[0]) and "η_{v}" in efficiency.get_ylabel()
        assert torque.get_ylabel() == t["br_torque"]
    assert re.search("[а-я]", TEXT["ru"]["br_log_pv"] + TEXT["ru"]["br_torque"])
