"""What the report's figures share (report/figure.py): the PNG a figure is written as, the decimal comma of the Russian
figures' ticks.  The figures are those of the appendix example (tests/appendix.py)."""

import io
import re

from matplotlib import rc_context
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.text import Text
import numpy as np
from PIL import Image
import pytest

from valvetrain.design import run
from valvetrain.report import figure, plots
from valvetrain.report.i18n import TEXT

from appendix import appendix_spec


@pytest.fixture(scope="module")
def results():
    return run(appendix_spec())


def _tick_texts(fig):
    """The tick labels and offsets of a drawn figure, as the PNG shows them (the secondary axes' too)."""
    FigureCanvasAgg(fig).draw()
    return [text for ax in figure.every_axes(fig)
            for axis in (ax.xaxis, ax.yaxis)
            for text in [label.get_text() for label in axis.get_ticklabels()] + [axis.get_offset_text().get_text()]]


def test_the_russian_figures_number_their_ticks_with_a_decimal_comma(results):
    """Russian writes decimals with a comma (0,5), English with a point (0.5): the time-area figure's ticks (steps of
    0.5) in each language, and the comma set by the drawing, not by the process's locale."""
    v = results.valves["intake"]
    russian, english = (_tick_texts(plots.time_area_figure(v, TEXT[lang])) for lang in ("ru", "en"))
    assert any("," in text for text in russian) and not any("." in text for text in russian), russian
    assert any("." in text for text in english) and not any("," in text for text in english), english
    for make in plots.FIGURES.values():                      # no Russian figure shows a decimal point
        fig = make(v, TEXT["ru"])
        assert not any("." in text for text in _tick_texts(fig)), make
        ticks = {id(label) for ax in figure.every_axes(fig)
                 for axis in (ax.xaxis, ax.yaxis)
                 for tick in axis.get_major_ticks() + axis.get_minor_ticks() for label in (tick.label1, tick.label2)}
        texts = [text.get_text() for text in fig.findobj(Text) if id(text) not in ticks]  # titles, legends, notes
        assert not [text for text in texts if re.search(r"\d\.\d", text)], make


def test_the_figures_pngs_have_the_pixels_of_matplotlibs_own(results):
    """write_png writes a figure without the opacity of its pixels (RGB), its text without hinting: figures of the
    appendix, read back (Pillow's PNG decoder), have the colours of the same figures written by matplotlib's own
    ``savefig`` with the text unhinted (``text.hinting = no_hinting``; RGBA, the reference), whose every pixel is
    opaque, so that nothing is lost; at the same resolution.  With matplotlib's default hinting they differ."""
    for name, draw in [("kinematics", lambda t: plots.kinematics_figure(results.valves["intake"], t)),
                       ("contour", lambda t: plots.contour_figure(results.valves["intake"], t)),
                       ("timing", lambda t: plots.timing_figure(results.valves, t))]:
        for lang in ("en", "ru"):
            ours, theirs = io.BytesIO(), io.BytesIO()
            figure.write_png(draw(TEXT[lang]), ours)
            with rc_context({"text.hinting": "no_hinting"}):
                draw(TEXT[lang]).savefig(theirs, format="png", dpi=figure.DPI)
            hinted = io.BytesIO()
            draw(TEXT[lang]).savefig(hinted, format="png", dpi=figure.DPI)
            ours, theirs = Image.open(ours), Image.open(theirs)
            assert (ours.mode, theirs.mode) == ("RGB", "RGBA"), name
            assert ours.info["dpi"] == pytest.approx(theirs.info["dpi"]), name
            rgba = np.asarray(theirs)
            assert (rgba[..., 3] == 255).all(), name
            assert np.array_equal(np.asarray(ours), rgba[..., :3]), (name, lang)
            assert not np.array_equal(np.asarray(Image.open(hinted))[..., :3], rgba[..., :3]), (name, lang)
