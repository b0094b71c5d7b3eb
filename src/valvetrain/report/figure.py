"""What every figure of the report shares: the resolution and the writing of a PNG, the decimal comma of the Russian
figures' ticks and a symbol's index as a subscript in every text (:func:`localised`)."""

from typing import Any

from matplotlib import rc_context
from matplotlib.axis import Axis
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.text import Text
from matplotlib.ticker import ScalarFormatter
from PIL import Image

from .typography import GREEK, SYMBOL


DPI = 110
"""The figures' resolution [dots per inch]."""


TEXT_STYLE = {"text.hinting": "no_hinting"}
"""Matplotlib's settings of the figures' text: the glyphs' outlines as drawn, not fitted to the pixels by FreeType's
hinting (matplotlib's default), which took a tenth of the drawing time of the built-in example's eight figures; the
letters are as legible at 110 dots per inch, a little softer."""


def write_png(fig, target) -> None:
    """Draw ``fig`` at :data:`DPI` and write it to ``target`` (a path or a binary file) as a PNG of its colours
    without their opacity (RGB, zlib level 3), its text drawn without hinting (:data:`TEXT_STYLE`).

    The pixels are those of ``fig.savefig(target, dpi=DPI)`` under :data:`TEXT_STYLE`, whose figures are opaque (a
    white face): its PNG keeps the opacity of every pixel (RGBA) at zlib's default level, 6, whose encoding took 0.2 s
    of processor time for the built-in example's eight figures, this one 0.11 s (the files 0.81 MB in all, savefig's
    with hinted text 0.77 MB)."""
    canvas = FigureCanvasAgg(fig)
    fig.set_dpi(DPI)
    with rc_context(TEXT_STYLE):
        canvas.draw()
    rgba = Image.frombuffer("RGBA", canvas.get_width_height(physical=True), canvas.buffer_rgba(), "raw", "RGBA", 0, 1)
    rgba.convert("RGB").save(target, "png", compress_level=3, dpi=(DPI, DPI))


class DecimalComma(ScalarFormatter):
    """Matplotlib's plain tick labels (and their offset, ``1e6``) with a decimal comma: the Russian figures'
    numbers, set per axis, not through the process's locale."""

    def __call__(self, x, pos=None):
        return super().__call__(x, pos).replace(".", ",")

    def get_offset(self) -> str:
        return super().get_offset().replace(".", ",")


def every_axes(fig) -> list[Any]:
    """The axes of ``fig`` and their secondary axes (``secondary_xaxis``: children of an axes, not in ``fig.axes``)."""
    return [*fig.axes, *(child for ax in fig.axes for child in ax.child_axes)]


def localised(fig, t) -> Figure:
    """``fig`` with a :class:`DecimalComma` on every axis of plain numbers when ``t`` is the Russian texts (an axis of
    angles of a polar plot or a logarithmic one keeps its own formatter; the English figures keep the point), and in
    every text a symbol's index as a subscript (:func:`math_symbols`)."""
    if t["lang"] == "ru":
        for ax in every_axes(fig):
            for axis in (ax.xaxis, ax.yaxis):
                if type(axis.get_major_formatter()) is ScalarFormatter:
                    axis.set_major_formatter(DecimalComma())
    for text in figure_texts(fig):
        label = text.get_text()
        if "_" in label and "$" not in label:
            text.set_text(math_symbols(label))
    return fig


def figure_texts(artist) -> list[Text]:
    """Every text of ``artist`` (a figure) and of its children but its axes' ticks: titles, axis labels, legends,
    notes.

    Matplotlib's ``findobj(Text)`` asks every axis for its ticks, which makes them (a tick is a line, a marker and two
    texts: half of the time the report's figures took before they were drawn) with empty labels that the axis'
    formatter fills in when the figure is drawn; the figures' ticks are numbers, so nothing is lost by not making
    them here.

    >>> from matplotlib.figure import Figure
    >>> ax = Figure().subplots()
    >>> _ = ax.set(title="lift", xlabel="phi_p, deg"), ax.plot([0, 1], label="h_v"), ax.legend()
    >>> [t.get_text() for t in figure_texts(ax.figure) if t.get_text()]
    ['phi_p, deg', 'lift', 'h_v']
    """
    texts = [artist] if isinstance(artist, Text) else []
    for child in (artist.label, artist.offsetText) if isinstance(artist, Axis) else artist.get_children():
        texts += figure_texts(child)
    return texts


def math_symbols(label) -> str:
    """A figure's text with each symbol's index as a subscript in matplotlib's mathtext (the report's rule,
    :data:`valvetrain.report.typography.SYMBOL`).

    >>> math_symbols("tappet h_T, a_T max, m_кл|a_v|, phi_p0, stroke_mm") == (
    ...     "tappet $h_{T}$, $a_{T" + chr(92) + ",max}$, $m_{кл}$|$a_{v}$|, $φ_{p0}$, stroke_mm")
    True
    """
    return SYMBOL.sub(lambda m: f"${GREEK.get(m.group(1), m.group(1))}_{{{m.group(2).replace(' ', chr(92) + ',')}}}$",
                      label)
