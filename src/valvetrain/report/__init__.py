"""Designer-facing output: plots and the HTML report (English and Russian).

The plots import matplotlib (a third of a second): :func:`write_plots` is imported on first use, so a run that draws
no figure does without it.
"""

__all__ = ["write_plots", "write_report"]


def __getattr__(name):
    if name == "write_plots":
        from .plots import write_plots
        return write_plots
    if name == "write_report":
        from .html import write_report
        return write_report
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
