"""Designer-facing output: plots and the HTML report (English and Russian).

The plots import matplotlib (a third of a second): :func:`write_plots` is imported on first use, so a run that draws
no figure does without it.

* :mod:`.plots`: a figure is its data and its drawing (``X_data``, ``draw_X``) on ``matplotlib.figure.Figure``, the
  Russian ones with a decimal comma on their ticks (:mod:`.figure`, what every figure shares); the main ones by
  default (``MAIN_FIGURES``: one a stage), every one on request; the engine chapters' figures in :mod:`.engine_plots`;
* :mod:`.drawing`: a run's figures drawn in two processes (Linux) forked before the design, importing matplotlib and
  ezdxf meanwhile, each reading the results from its own pipe and taking the figures one at a time from a shared
  counter, while :mod:`valvetrain.export` writes the rest and renders the report;
* :mod:`.html`: the report; it numbers the citations in the order of their first use (``numbered_citations``) and
  puts every check in its chapter (:mod:`.check_rows`: ``chapter_checks``, a check's row); :mod:`.i18n` its texts
  (read from the catalogues of :mod:`valvetrain.locale`; the symbols in :mod:`.symbols`), :mod:`.names` the names of
  keys and values (the checks' names come from :mod:`valvetrain.locale`);
* :mod:`.typography` (a symbol's index as a subscript, <= >=, powers of ten), :mod:`.russian` (the Russian report's
  locators, decimal comma, quotes), :mod:`.worked` (the worked substitution of the main formulas, each line
  re-evaluated from its printed numbers by the tests), :mod:`.numbers` (the one rule of printed numbers),
  :mod:`.optimization` and :mod:`.tolerance` (the reports of those commands).
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
