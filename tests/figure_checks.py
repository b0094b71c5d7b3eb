"""Checks the tests of the report's figures share."""

from matplotlib.backends.backend_agg import FigureCanvasAgg

from valvetrain.report.figure import DPI
from valvetrain.report.i18n import TEXT


def all_texts_on_the_figures(figures):
    """Every text of each figure ``(kind, draw(t))`` lies inside it, in English and Russian (matplotlib's tight
    bounding box of the drawn figure)."""
    for kind, draw in figures:
        for lang in ("en", "ru"):
            fig = draw(TEXT[lang])
            fig.set_dpi(DPI)
            box = fig.get_tightbbox(FigureCanvasAgg(fig).get_renderer())
            width, height = fig.get_size_inches()
            assert box.x0 >= 0.0 and box.y0 >= 0.0 and box.x1 <= width and box.y1 <= height, (kind, lang, box)
