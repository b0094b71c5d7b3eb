"""Designer-facing output: plots and the HTML report (English and Russian)."""

from .html import write_report
from .plots import write_plots

__all__ = ["write_plots", "write_report"]
