"""The page of the designer: a Bokeh document per browser tab, on a :class:`~valvetrain.web.session.Session`.

The specification panel is generated from the specification's models (:func:`valvetrain.web.session.form`); the
plots are plain Bokeh figures fed by column data sources; the handles are points of a ``PointDrawTool`` whose
release sends the new position to Python; the speed sweep runs in a worker thread and only the newest one is
drawn (an older one is stopped at its next speed).  The page keeps its timings in ``window.vtTimes`` (release of a
drag to the redrawn kinematics, ms) and ``window.vtSweepTimes`` (to the redrawn sweep panel), and in
``window.vtTimesArrived`` and ``window.vtSweepTimesArrived`` the times to the arrival of the update (before drawing).
"""

from concurrent.futures import ThreadPoolExecutor
from dataclasses import replace
from functools import partial
import time

from bokeh.layouts import column, row
from bokeh.models import (Button, ColumnDataSource, CustomJS, DataTable, LinearAxis, Div, HTMLTemplateFormatter, Label,
                          LinearColorMapper, NumericInput, PointDrawTool, Range1d, Select, TableColumn, TabPanel, Tabs,
                          TextInput)
from bokeh.plotting import figure
import numpy as np

from ..languages import LANGS
from ..locale import catalogue
from ..report.html import check_range
from ..report.i18n import TEXT
from ..report.names import label, record_quantity_text, translate
from ..units import per_cam_degree
from .session import form, has_points, parse_value, value_text

WORDS = {lang: catalogue(lang)["designer"] for lang in LANGS}
"""The designer's own words in each language, from the catalogue's ``[designer]`` (the plots' and the checks' come from
the report's)."""

CARD_KEYS = ("cam.valve_opens_crank_deg", "cam.valve_closes_crank_deg", "cam.event_cam_deg", "cam.nose_crank_deg",
             "cam.phi_p0_deg", "flow.valve_lift_mm", "flow.time_area_mm2_s", "flow.fullness",
             "cam.max_acceleration_m_s2", "cam.min_acceleration_m_s2", "cam.rho_min_mm")
"""The keys of a valve's results shown on the cam card."""

KINEMATIC_PLOTS = (("lift", "valve_lift_mm", "lift_mm", 0), ("velocity", "valve_velocity_m_s", "velocity_valve", 1),
                   ("acceleration", "valve_acceleration_m_s2", "acceleration_valve", 2),
                   ("jerk", "valve_jerk_m_s3", "jerk_valve", 3))
"""The plots against the camshaft angle: name, series, axis words, order of the derivative."""

CURVES = {"x": "cam_deg", "lift": "valve_lift_mm", "tappet": "tappet_lift_mm", "curvature": "rho_mm",
          "crank_x": "crank_deg", "time_area": "time_area_mm2_s", "curtain": "curtain_area_mm2",
          "spring_x": "spring_lift_mm", "spring_y": "required_force_N", "spring_line_x": "spring_line_lift_mm",
          "spring_line_y": "spring_line_force_N"}
"""The columns of a design's curves (the current and the baseline each have their source) and the series they hold,
besides the derivatives of the lift (:data:`KINEMATIC_PLOTS`) and the closed contour.  One source for all, the shorter
series padded with NaN (which a line leaves out): a redraw sends one change, not one per curve or abscissa (each
change is a message to the page, and a message costs the server a walk over the document's models)."""

PLOTS = {"lift": ("x", "lift"), "velocity": ("x", "velocity"), "acceleration": ("x", "acceleration"),
         "jerk": ("x", "jerk"), "contour": ("contour_x", "contour_y"), "curvature": ("x", "curvature"),
         "time_area": ("crank_x", "time_area"), "spring": ("spring_x", "spring_y")}
"""Each plot's columns of abscissae and ordinates."""


HANDLE_ROOM = 0.25
"""The kinematic plots' room above and below the curves, a fraction of their span: how far one drag takes a handle
beyond the highest or lowest point (an edit tool drops the pointer's moves outside the plot's frame).  A redraw keeps
the range while at least half this room is left (:func:`kept_range`)."""

PLOT_ROOM = 0.05
"""The other plots' room around their curves, a fraction of their span (none kept: the curves only stay inside)."""

RANGES = {"x": ("x", 0.0), "lift": ("lift", HANDLE_ROOM), "velocity": ("velocity", HANDLE_ROOM),
          "acceleration": ("acceleration", HANDLE_ROOM), "jerk": ("jerk", HANDLE_ROOM), "curvature_x": ("x", 0.0),
          "curvature": ("curvature", PLOT_ROOM), "crank_x": ("crank_x", 0.0), "time_area": ("time_area", PLOT_ROOM),
          "curtain": ("curtain", PLOT_ROOM), "spring_x": ("spring_x", PLOT_ROOM), "spring": ("spring_y", PLOT_ROOM)}
"""The plots' fixed ranges (the contour's follows its data, to keep its aspect): the column they hold, of the design
and of the baseline, and their room (:func:`kept_range`)."""


def kept_range(start, end, low, high, room) -> tuple[float, float]:
    """The range [start, end] of a plot after a redraw whose curves span [low, high]: kept while the curves lie
    inside it with at least half the ``room`` (a fraction of their span) on either side and it is less than twice
    as wide as they want, else their span with the whole room on either side.

    Notes
    -----
    A plot whose range follows its data (a data range) lays itself out again on every redraw, its tick labels
    measured anew (about half the page's drawing time of a redraw); a range kept across small changes leaves the
    ticks and the layout as they were.
    """
    span = high - low or abs(high) or 1.0
    pad = room * span
    if start <= low - 0.5 * pad and end >= high + 0.5 * pad and end - start <= 2.0 * (span + 2.0 * pad):
        return start, end
    return low - pad, high + pad


PLOT_BUCKETS = 200
"""How many spans of its abscissa a long curve is thinned to for the page (:func:`thinned`, two points each): about
half the width of a plot's frame in pixels (400 to 440 px), as many as it can show."""


def thinned(x, y, buckets=PLOT_BUCKETS) -> tuple[np.ndarray, np.ndarray]:
    """A curve y(x) of ascending x with no more points than a plot can show: in each of ``buckets`` equal spans of x
    its lowest and its highest point, in the order of x, and its first and last point; a curve of no more than
    2 buckets + 2 points, with a gap (NaN) or of no span, as it is.

    Notes
    -----
    The line through the lowest and highest point of every span of about two pixels covers the pixels the whole
    curve covers (the min-max decimation of time series for display); a curve sent to the page with fewer points
    is sent and drawn faster (the spring's required force has about 2000, one per step of the camshaft angle).

    References
    ----------
    U. Jugel, Z. Jerzak, G. Hackenbroich and V. Markl, M4: a visualization-oriented time series data aggregation,
    Proceedings of the VLDB Endowment 7 (10) (2014), 797-808.
    """
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    if len(x) <= 2 * buckets + 2 or not (np.isfinite(x).all() and np.isfinite(y).all()) or x[-1] <= x[0]:
        return x, y
    span = np.minimum(((x - x[0]) / (x[-1] - x[0]) * buckets).astype(int), buckets - 1)
    order = np.lexsort((y, span))                         # by span, and by y within it
    ends = np.flatnonzero(np.diff(span[order])) + 1
    keep = np.unique(np.concatenate([[0, len(x) - 1], order[np.r_[0, ends]], order[np.r_[ends - 1, len(x) - 1]]]))
    return x[keep], y[keep]


def per_degree(values, order, omega) -> np.ndarray:
    """A derivative of the lift at the rated speed (m/s, m/s², m/s³) in mm per camshaft degree to the ``order``
    (:func:`valvetrain.units.per_cam_degree`), from the series' list."""
    return per_cam_degree(np.array(values, dtype=float), order, omega)

SEVERITY_COLOURS = {"failure": "#f4c7c3", "warning": "#fce8b2", "info": "#e8eaf6", "pass": "#d9ead3",
                    "pending": "#eeeeee"}
"""The colours of the checks table's rows: by severity when failing, passing, and pending (its speed sweeps to
come)."""

STAMP_JS = """
const now = performance.now();
requestAnimationFrame(() => requestAnimationFrame(() => {
  const t = performance.now();
  window[key] = window[key] || [];
  window[key + 'Arrived'] = window[key + 'Arrived'] || [];
  window[key + 'Server'] = window[key + 'Server'] || [];
  if (window.vtRelease !== undefined) {
    window[key].push(t - window.vtRelease);
    window[key + 'Arrived'].push(now - window.vtRelease);
    const data = cb_obj.data instanceof Map ? Object.fromEntries(cb_obj.data) : cb_obj.data;
    const release = performance.timeOrigin + window.vtRelease;
    window[key + 'Server'].push([data.began[0] - release, data.ended[0] - data.began[0],
                                 performance.timeOrigin + now - data.ended[0], data.cpu[0]]);
  }
  window[key + 'Done'] = (window[key + 'Done'] || 0) + 1;
}));
"""

PAUSE_JS = """
if (!window[key]) {
  window[key] = plots.map((p) => Bokeh.index.find_one(p)).filter((v) => v != null);
  window[key].forEach((v) => v.pause());
}
"""

UNPAUSE_JS = """
const views = window[key] || [];
window[key] = null;
views.forEach((v) => v.unpause());
"""

DRAWN_JS = """
requestAnimationFrame(() => requestAnimationFrame(() => { drawn.data = {n: [stamp.data.n[0]]}; }));
"""

SAME_STYLE_JS = """
const dom = Bokeh.require("core/dom");
const update = dom.InlineStyleSheet.prototype._update;
if (!update.vtSameKept) {
  dom.InlineStyleSheet.prototype._update = function (css) {
    if (this.el.textContent !== css) {
      update.call(this, css);
    }
  };
  dom.InlineStyleSheet.prototype._update.vtSameKept = true;
}
"""
"""Run once when the page is ready: a style sheet of the page's views set to the text it holds is left as it is.
Bokeh sets the position of every renderer (axis, grid, glyph, title, toolbar) in its own style sheet at each paint,
the same text mostly, and the browser takes each setting for a change of the styles: the next look-up of a colour
in them (each renderer reads its colours from the styles) works all the page's styles out again, one to three times
per renderer, about 60 times in a redraw (two thirds of the page's drawing of a redraw)."""

DOWNLOAD_JS = """
const blob = new Blob([div.text], {type: mime});
const a = document.createElement('a');
a.href = URL.createObjectURL(blob);
a.download = name;
document.body.appendChild(a);
a.click();
a.remove();
"""

SWEEP_WORKERS = ThreadPoolExecutor(max_workers=1, thread_name_prefix="valvetrain-sweep")
"""One thread for the speed sweeps of every tab (2 cores: the kinematics keep the other)."""


def _held(plots, stamp, key):
    """A data source whose change pauses the drawing of ``plots`` in the page until ``stamp`` changes: the page would
    paint a plot once for each of a redraw's changes that reaches it in another frame; held, it paints each plot
    once, in the frame after the last (the server sends a callback's changes in one message,
    :func:`valvetrain.web.one_message`, which the hold does not rely on)."""
    hold = ColumnDataSource({"n": [0]})
    hold.js_on_change("data", CustomJS(args={"plots": plots, "key": key}, code=PAUSE_JS))
    stamp.js_on_change("data", CustomJS(args={"key": key}, code=UNPAUSE_JS))
    return hold


def _hold(hold):
    """Pause the drawing of the plots of a :func:`_held` source (the stamp's change resumes it)."""
    hold.data = {"n": [hold.data["n"][0] + 1]}


class Stale(Exception):
    """Raised into a speed sweep that a newer change made stale."""


def _array(values):
    """A series as a float array (None a gap, NaN): sent to the page as binary, not as JSON numbers."""
    return np.asarray(values, dtype=float)


def _send(source, data):
    """Set a source's ``data`` unless it holds the same already: an unchanged source sends nothing to the page (each
    change is a message, and a change of a table's rows draws its grid again)."""
    old = source.data
    if old.keys() != data.keys() or any(len(old[k]) != len(v) or not np.array_equal(
            old[k], v, equal_nan=np.asarray(v).dtype.kind == "f") for k, v in data.items()):   # NaN: a gap, the same
        source.data = data


def _rows_follow(table):
    """The page's grid of ``table`` redraws when its source's data change: its grid redraws when its view's rows
    change; new data of as many rows leaves them, and the old rows on screen: the view's change signal makes it
    take the new ones."""
    table.source.js_on_change("data", CustomJS(args={"table": table}, code="table.view.change.emit();"))


def _now():
    """The server's clocks when a change comes: ``time.time()`` and the process's processor time [s]."""
    return time.time(), time.process_time()


def _count(stamp, began):
    """One more redraw on a stamp's source (its change in the page stamps the time), with the server's times
    ``began`` (:func:`_now` when the change came) and now, as ms since the epoch: the page, on the same clock,
    parts its wait into the way up, the server and the way down; and the processor time the server's process spent
    in between [ms] (what the server costs on a loaded machine)."""
    stamp.data = {"n": [stamp.data["n"][0] + 1], "began": [1e3 * began[0]], "ended": [1e3 * time.time()],
                  "cpu": [1e3 * (time.process_time() - began[1])]}


class Designer:
    """The widgets, plots and callbacks of one browser tab."""

    def __init__(self, doc, session):
        self.doc, self.session, self.lang = doc, session, "en"
        self.names = list(session.document["valves"])
        self.valve = self.names[0]
        self.generation = 0
        self._syncing = False
        self.downloads = 0
        self.per_degree = False
        self.base_sweep = None
        self.sweep_due = False
        self.fields = {}
        self.errors = {}
        self.erring = set()
        self._build()
        self._texts()
        self.redraw()

    # --- building --------------------------------------------------------------------------------------------------
    def _widget(self, f):
        title = f"{f.path.rsplit('.', 1)[-1]}" + (f" [{f.bounds_text}]" if f.bounds_text else "")
        if f.kind in ("float", "int"):
            w = NumericInput(title=title, value=f.value, mode=f.kind, width=230)
        elif f.kind == "choice":
            w = Select(title=title, value=str(f.value), options=[str(o) for o in f.options], width=230)
        else:
            w = TextInput(title=title, value=value_text(f.value), width=230)
        w.name = f.path
        w.on_change("value", partial(self.on_field, f))
        self.fields[f.path] = w
        err = Div(text="", styles={"color": "#b00020", "font-size": "85%"}, width=230, name="error:" + f.path)
        self.errors[f.path] = err
        return column(w, err)

    def _build(self):
        t = WORDS["en"]
        self.language = Select(title=t["language"], value="en", options=[("en", "English"), ("ru", "Русский")],
                               name="language", width=120)
        self.language.on_change("value", self.on_language)
        self.valve_select = Select(title=t["valve"], value=self.valve, options=self.names, width=120)
        self.valve_select.on_change("value", self.on_valve)
        self.units = Select(title=t["units"], value="rated", options=[("rated", t["rated"]), ("deg", t["deg"])],
                            name="units", width=170)
        self.units.on_change("value", self.on_units)
        self.pin_button = Button(label=t["pin"], name="pin", width=160)
        self.pin_button.on_click(self.on_pin)
        self.toml_text = Div(text="", visible=False)
        self.toml_button = Button(label=t["toml"], name="download-toml", width=160)
        self.toml_text.js_on_change("text", CustomJS(args={"div": self.toml_text, "mime": "application/toml",
                                                           "name": "valvetrain.toml"}, code=DOWNLOAD_JS))
        self.toml_button.on_click(self.on_toml)
        self.report_text = Div(text="", visible=False)
        self.report_text.js_on_change("text", CustomJS(args={"div": self.report_text, "mime": "text/html",
                                                             "name": "report.html"}, code=DOWNLOAD_JS))
        self.report_button = Button(label=t["report"], name="download-report", width=160)
        self.report_button.on_click(self.on_report)
        self.status = Div(text="", name="status", styles={"color": "#b00020"})
        self.section_errors = Div(text="", name="section-errors", styles={"color": "#b00020"})
        panels = [TabPanel(title=path, child=column(*[self._widget(f) for f in fields], height=700,
                                                    styles={"overflow-y": "auto"}))
                  for path, fields in form(self.session.document)]
        self.spec_tabs = Tabs(tabs=panels, width=270)

        tools = "pan,wheel_zoom,box_zoom,reset,save"
        empty = {k: [] for k in [*CURVES, *(p[0] for p in KINEMATIC_PLOTS[1:]), "contour_x", "contour_y"]}
        self.curves, self.base_curves = ColumnDataSource(empty, name="curves"), ColumnDataSource(empty)
        self.figures = {}
        for name, *_ in KINEMATIC_PLOTS:
            # room above and below the curves for the handles: an edit tool drops the pointer's moves outside the
            # plot's frame, so a handle at the top of a tight range could not be dragged higher
            self.figures[name] = self._plot(figure(height=210, width=520, tools=tools, name=f"plot-{name}",
                                                   x_range=Range1d(0, 1), y_range=Range1d(0, 1)), name)
        self.figures["lift"].line("x", "tappet", source=self.curves, color="#2ca02c", line_width=1)
        self.segments = ColumnDataSource({"x": [], "y0": [], "y1": []})
        self.figures["acceleration"].segment("x", "y0", "x", "y1", source=self.segments, color="#bbbbbb",
                                             line_dash="dotted")
        self.handles, self.draw_tools = {}, {}
        for plot in ("lift", "acceleration"):
            src = ColumnDataSource({"x": [], "y": [], "name": []}, name=f"handles-{plot}")
            r = self.figures[plot].scatter("x", "y", source=src, size=13, color="#d62728", marker="circle")
            tool = PointDrawTool(renderers=[r], add=False, drag=True)
            self.draw_tools[plot] = tool
            self.figures[plot].add_tools(tool)
            self.figures[plot].toolbar.active_drag = tool
            self.figures[plot].js_on_event("panend", CustomJS(code="window.vtRelease = performance.now();"))
            src.on_change("data", partial(self.on_handles, plot))
            self.handles[plot] = src
        for name in ("lift", "velocity", "acceleration"):
            self.figures[name].x_range = self.figures["jerk"].x_range

        for name in ("contour", "curvature", "time_area", "spring"):
            kw = {"match_aspect": True} if name == "contour" else {"x_range": Range1d(0, 1), "y_range": Range1d(0, 1)}
            self.figures[name] = self._plot(figure(height=260, width=520 if name != "contour" else 300, tools=tools,
                                                   name=f"plot-{name}", **kw), name)
        self.heel = ColumnDataSource({"x": [], "y": []})
        self.figures["contour"].line("x", "y", source=self.heel, color="#2ca02c", line_dash="dashed")
        self.figures["spring"].line("spring_line_x", "spring_line_y", source=self.curves, color="black", line_width=2)
        ta = self.figures["time_area"]
        ta.line("crank_x", "curtain", source=self.curves, color="#ff7f0e", y_range_name="curtain")
        ta.extra_y_ranges = {"curtain": Range1d(0, 1)}
        # the fullness in the plot, not in its title: a title's new text lays the plot out again
        self.fullness = Label(x=0, y=0, text="", text_font_size="11px", text_baseline="top")
        ta.add_layout(self.fullness)
        f = self.figures
        self.ranges = {"x": f["jerk"].x_range, "curvature_x": f["curvature"].x_range, "crank_x": ta.x_range,
                       "spring_x": f["spring"].x_range, "curtain": ta.extra_y_ranges["curtain"],
                       **{name: f[name].y_range for name in ("lift", "velocity", "acceleration", "jerk", "curvature",
                                                             "time_area", "spring")}}
        self.curtain_axis = LinearAxis(y_range_name="curtain", axis_label_text_color="#ff7f0e")
        ta.add_layout(self.curtain_axis, "right")

        self.checks = ColumnDataSource({k: [] for k in ("key", "quantity", "value", "allowed", "margin", "source",
                                                        "colour", "baseline")})
        fmt = HTMLTemplateFormatter(template='<div style="background:<%= colour %>; padding-left:3px"><%= value %></div>')
        self.check_columns = [TableColumn(field="quantity", title="", width=330),
                              TableColumn(field="value", title="", formatter=fmt, width=120),
                              TableColumn(field="baseline", title="", width=110),
                              TableColumn(field="allowed", title="", width=120),
                              TableColumn(field="margin", title="", width=70),
                              TableColumn(field="source", title="", width=350)]
        # the columns keep their widths: fitted to the table (autosized), they would be measured again on every change
        # of the rows
        self.table = DataTable(source=self.checks, columns=self.check_columns, width=1100, height=360,
                               index_position=None, name="checks", autosize_mode="none")
        _rows_follow(self.table)
        # the cam card is a table: new rows leave the page's layout (a Div's new text lays the page out again)
        self.card = ColumnDataSource({"quantity": [], "value": []}, name="card")
        self.card_columns = [TableColumn(field="quantity", title="", width=210),
                             TableColumn(field="value", title="", width=90)]
        self.card_title = Div(text="")
        self.card_table = DataTable(source=self.card, columns=self.card_columns, width=300, height=300,
                                   index_position=None, autosize_mode="none")
        _rows_follow(self.card_table)

        # the sweep panel
        # the sweep's state inside its plot, not in a title: a title's new text lays the plot out again
        self.sweep_status = Label(x=6, y=6, x_units="screen", y_units="screen", text="", name="sweep-status",
                                  text_font_size="11px", background_fill_color="white", background_fill_alpha=0.8)
        self.sweep_sources = {k: ColumnDataSource({"x": [], "y": []}) for k in ("force", "seating")}
        self.base_sweep_sources = {k: ColumnDataSource({"x": [], "y": []}) for k in ("force", "seating")}
        self.sweep_marks = ColumnDataSource({"x": [], "y0": [], "y1": []})
        for key in ("force", "seating"):
            p = figure(height=220, width=420, tools=tools, name=f"plot-sweep-{key}")
            p.line("x", "y", source=self.base_sweep_sources[key], color="#999999", line_dash="dashed", line_width=1.5)
            p.line("x", "y", source=self.sweep_sources[key], color="#1f77b4", line_width=2)
            p.segment("x", "y0", "x", "y1", source=self.sweep_marks, color="#d62728", line_dash="dashed")
            self.figures["sweep_" + key] = p
        self.figures["sweep_force"].add_layout(self.sweep_status)
        self.map_source = ColumnDataSource({"image": [], "x": [], "y": [], "dw": [], "dh": []})
        self.mapper = LinearColorMapper(palette="RdBu11", low=-1.0, high=1.0)
        p = figure(height=220, width=420, tools=tools, name="plot-sweep-map")
        p.image("image", x="x", y="y", dw="dw", dh="dh", source=self.map_source, color_mapper=self.mapper)
        self.figures["sweep_map"] = p

        # the stamps are data sources, not widgets: a widget's change lays the whole page out again (~100 ms)
        self.kinematic_stamp = ColumnDataSource({"n": [0], "began": [0.0], "ended": [0.0], "cpu": [0.0]},
                                                name="kinematic-stamp")
        self.kinematic_hold = _held([self.figures[k] for k in PLOTS], self.kinematic_stamp, "vtPausedKinematics")
        self.kinematic_stamp.js_on_change("data", CustomJS(args={"key": "vtTimes"}, code=STAMP_JS))
        # the page says when it has drawn the kinematics: the sweep starts then, not to hold their drawing up
        self.drawn = ColumnDataSource({"n": [0]}, name="drawn")
        self.drawn.on_change("data", self.on_drawn)
        self.kinematic_stamp.js_on_change("data", CustomJS(args={"stamp": self.kinematic_stamp, "drawn": self.drawn},
                                                           code=DRAWN_JS))
        self.sweep_stamp = ColumnDataSource({"n": [0], "began": [0.0], "ended": [0.0], "cpu": [0.0]},
                                            name="sweep-stamp")
        self.sweep_hold = _held([self.figures[k] for k in ("sweep_force", "sweep_seating", "sweep_map")],
                                self.sweep_stamp, "vtPausedSweep")
        self.sweep_stamp.js_on_change("data", CustomJS(args={"key": "vtSweepTimes"}, code=STAMP_JS))

        f = self.figures
        plots = row(column(f["lift"], f["velocity"], f["acceleration"], f["jerk"]),
                    column(f["contour"], f["curvature"], f["time_area"], f["spring"]))
        self.sweep_title = Div(text="")
        sweep = column(self.sweep_title, row(f["sweep_force"], f["sweep_seating"], f["sweep_map"]))
        top = row(self.language, self.valve_select, self.units, self.pin_button, self.toml_button, self.report_button,
                  self.status)
        self.checks_title = Div(text="")
        self.doc.add_root(column(top, row(column(self.section_errors, self.spec_tabs), column(row(plots, column(self.card_title, self.card_table)),
                                 self.checks_title, self.table, sweep)), self.toml_text, self.report_text))
        self.doc.js_on_event("document_ready", CustomJS(code=SAME_STYLE_JS))
        self.doc.add_root(self.kinematic_stamp)
        self.doc.add_root(self.sweep_stamp)
        self.doc.add_root(self.drawn)
        self.doc.add_root(self.kinematic_hold)
        self.doc.add_root(self.sweep_hold)

    def _plot(self, p, name):
        """Plot ``name`` on figure ``p``: the baseline dashed under the current design."""
        x, y = PLOTS[name]
        p.line(x, y, source=self.base_curves, color="#999999", line_dash="dashed", line_width=1.5)
        p.line(x, y, source=self.curves, color="#1f77b4", line_width=2)
        return p

    # --- drawing ---------------------------------------------------------------------------------------------------
    def _texts(self):
        t, w = TEXT[self.lang], WORDS[self.lang]
        unit = "_deg" if self.per_degree else ""
        axes = {"lift": w["lift_mm"], "velocity": w["velocity_valve" + unit],
                "acceleration": w["acceleration_valve" + unit], "jerk": w["jerk_valve" + unit]}
        for name, words in axes.items():
            self.figures[name].yaxis.axis_label = words
            self.figures[name].title.text = words
        self.figures["jerk"].xaxis.axis_label = t["cam_deg"]
        self.figures["contour"].title.text = t["contour"]
        self.figures["curvature"].title.text = t["rho"]
        self.figures["curvature"].xaxis.axis_label = t["cam_deg"]
        self.figures["time_area"].xaxis.axis_label = t["crank_deg"]
        self.figures["time_area"].title.text = t["running_ta"]
        self.curtain_axis.axis_label = t["curtain"]
        self.figures["spring"].title.text = t["spring_title"]
        self.figures["spring"].xaxis.axis_label = t["valve_lift_axis"]
        self.figures["spring"].yaxis.axis_label = t["force"]
        self.figures["sweep_force"].title.text = w["min_force"]
        self.figures["sweep_seating"].title.text = w["seating"]
        self.figures["sweep_map"].title.text = w["map"]
        for key in ("sweep_force", "sweep_seating", "sweep_map"):
            self.figures[key].xaxis.axis_label = t["speed"] if key != "sweep_map" else t["cam_deg"]
        self.sweep_title.text = f"<h3>{w['sweep']}</h3>"
        self.checks_title.text = f"<h3>{w['checks']}</h3>"
        self.card_title.text = f"<h3>{w['card']}</h3>"
        for c, key in zip(self.check_columns, ("quantity", "value", "baseline", "allowed", "margin", "source"),
                          strict=True):
            c.title = {"value": t["value"] + f" ({w['current']})", "baseline": w["baseline"],
                       "margin": w["margin"]}.get(key) or t[key]
        for c, key in zip(self.card_columns, ("quantity", "value"), strict=True):
            c.title = t[key]
        self.language.title, self.valve_select.title, self.units.title = w["language"], w["valve"], w["units"]
        self.units.options = [("rated", w["rated"]), ("deg", w["deg"])]
        self.pin_button.label, self.toml_button.label, self.report_button.label = w["pin"], w["toml"], w["report"]

    def _checks(self):
        """The checks table: the whole design's checks when they have come, else the good design's and, pending, the
        ones of the last whole design that only the speed sweeps give."""
        s = self.session
        base = {c["quantity"]: c for c in (s.baseline or {"results": {"checks": []}})["results"]["checks"]}
        out = {k: [] for k in self.checks.data}
        for c in sorted(s.checked["checks"], key=lambda c: (c["pass"], {"failure": 0, "warning": 1}.get(c["severity"], 2),
                                                            c["margin"] if c["margin"] is not None else 1e300)):
            self._check_row(out, c, base)
            out["value"].append("-" if c["value"] is None else f"{c['value']:.5g} {c['unit']}".rstrip())
            out["margin"].append("" if c["margin"] is None else f"{c['margin']:+.3g}")
            out["colour"].append(SEVERITY_COLOURS["pass" if c["pass"] or c["accepted"] else c["severity"]])
        for c in s.pending:
            self._check_row(out, c, base)
            out["value"].append("…")
            out["margin"].append("")
            out["colour"].append(SEVERITY_COLOURS["pending"])
        _send(self.checks, out)

    def _check_row(self, out, c, base):
        """The columns of a check's row that do not wait for its value: its name, the baseline, the range, the
        source."""
        out["key"].append(c["quantity"])
        out["quantity"].append(record_quantity_text(c, self.lang))
        b = base.get(c["quantity"])
        out["baseline"].append("" if b is None or b["value"] is None else f"{b['value']:.5g}"
                               + ("" if b["pass"] else " ✗"))
        out["allowed"].append(check_range(c, self.lang))
        out["source"].append(translate(c["source"], self.lang))

    def _card(self):
        v = self.session.good["results"]["valves"][self.valve]
        rows = {"quantity": [], "value": []}
        for key in CARD_KEYS:
            group, leaf = key.split(".")
            value = v.get(group, {}).get(leaf)
            if value is not None:
                rows["quantity"].append(label(key, self.lang))
                rows["value"].append(f"{value:.5g}")
        _send(self.card, rows)

    def _omega(self, result):
        """The camshaft speed of a design [rad/s] when the plots are per degree, else None."""
        return result["results"]["valves"][self.valve]["cam"]["camshaft_speed_rad_s"] if self.per_degree else None

    @staticmethod
    def _curves(series, omega=None) -> dict:
        """The columns of a design's curves (:data:`CURVES`), NaN-padded to one length, as 32-bit floats (7 digits:
        more than a plot shows, half the bytes to send); the spring's required force thinned (:func:`thinned`) and
        the contour to about as many points as the other curves (every k-th point, closed: 0.5 cam deg apart it has
        twice as many as its 300 px plot can show)."""
        out = {key: _array(series[name]) for key, name in CURVES.items()}
        for name, key, _, order in KINEMATIC_PLOTS:
            out[name] = _array(series[key]) if omega is None or order == 0 else per_degree(series[key], order, omega)
        out["spring_x"], out["spring_y"] = thinned(out["spring_x"], out["spring_y"])
        step = -(-len(series["contour_x_mm"]) // (2 * PLOT_BUCKETS))
        for axis in ("x", "y"):
            contour = _array(series[f"contour_{axis}_mm"])
            out[f"contour_{axis}"] = np.append(contour[::step], contour[0])
        n = max(len(v) for v in out.values())
        return {k: np.pad(v, (0, n - len(v)), constant_values=np.nan).astype(np.float32) for k, v in out.items()}

    def _ranges(self, with_base):
        """Each fixed range of the plots kept or fitted to the curves of the design and the baseline
        (:func:`kept_range`); a range changed only when it moves (a change lays its plot out again)."""
        for key, (name, room) in RANGES.items():
            values = np.concatenate([source.data[name] for source in (self.curves, self.base_curves)[:1 + with_base]])
            values = values[np.isfinite(values)]
            if values.size == 0:
                continue
            rng = self.ranges[key]
            start, end = kept_range(rng.start, rng.end, float(values.min()), float(values.max()), room)
            if (start, end) != (rng.start, rng.end):
                rng.update(start=start, end=end)

    def redraw(self, sweep=True, began=None) -> None:
        """Draw the good design (and the baseline), its checks, card and handles; start its speed sweep (``sweep``)
        or draw the last one again.  ``began``: :func:`_now` when the change came (default now)."""
        began = _now() if began is None else began
        _hold(self.kinematic_hold)
        try:
            s = self.session
            series = s.good["series"][self.valve]
            omega = self._omega(s.good)
            self.curves.data = self._curves(series, omega)
            phi = np.linspace(0.0, 2.0 * np.pi, 181)
            r = series["heel_radius_mm"]
            _send(self.heel, {"x": r * np.cos(phi), "y": r * np.sin(phi)})
            base = s.baseline["series"].get(self.valve) if s.baseline else None
            if base is not None:
                _send(self.base_curves, self._curves(base, self._omega(s.baseline)))
            self._ranges(base is not None)
            edges = series["segments_cam_deg"]
            acc = self.ranges["acceleration"]
            _send(self.segments, {"x": edges, "y0": [acc.start] * len(edges), "y1": [acc.end] * len(edges)})
            ta = self.ranges["time_area"]
            self.fullness.update(x=self.ranges["crank_x"].start, y=ta.end - 0.02 * (ta.end - ta.start),
                                 text=f"{TEXT[self.lang]['s_fullness']} "
                                      f"{s.good['results']['valves'][self.valve]['flow']['fullness']:.4g}")
            self._handles(omega)
            self._checks()
            self._card()
        finally:
            _count(self.kinematic_stamp, began)
        self.sweep_due = self.sweep_due or sweep          # a switch of language before the page drew keeps it due
        if self.session.full is not None:
            self._sweep_panel()

    def _handles(self, omega=None):
        # the points of an inline lift table are added (a tap) and removed (selected, Backspace) on the lift plot
        self.draw_tools["lift"].add = has_points(self.session.good_document["valves"][self.valve].get("cam", {}))
        self._placed = {}
        found = self.session.handles(self.valve)
        for plot, src in self.handles.items():
            mine = [h if omega is None or plot == "lift" else replace(h, y=float(per_degree(h.y, 2, omega)))
                    for h in found if h.plot == plot]
            self._placed[plot] = [(h.name, h.x, h.y) for h in mine]
            _send(src, {"x": [h.x for h in mine], "y": [h.y for h in mine], "name": [h.name for h in mine]})

    def show_problems(self) -> None:
        """Each problem at its field (or above the panel when it names no field); the status line says the last
        good design stays."""
        shown = {p["path"]: p["message"] for p in self.session.problems if p["path"] in self.errors}
        for path in set(shown) | self.erring:
            self.errors[path].text = shown.get(path, "")
        self.erring = set(shown)
        loose = [p["text"] for p in self.session.problems if p["path"] not in self.errors]
        self.section_errors.text = "<br>".join(loose)
        self.status.text = WORDS[self.lang]["kept"] if self.session.problems else ""

    # --- the speed sweep -------------------------------------------------------------------------------------------
    def on_drawn(self, attr, old, new) -> None:
        """The page has drawn the kinematics of redraw ``new["n"]``: the sweep of the newest one starts (its thread
        would have held up the sending of the kinematics, and the page's drawing of them)."""
        if self.sweep_due and new["n"][0] == self.kinematic_stamp.data["n"][0]:
            self.sweep_due = False
            self.start_sweep()

    def start_sweep(self) -> None:
        """The whole design of the good document, with its speed sweeps, in the worker thread
        (:meth:`~valvetrain.web.session.Session.settle`); a newer change stops it at its next speed."""
        self.generation += 1
        generation = self.generation
        self.sweep_status.text = WORDS[self.lang]["sweeping"]
        document = self.session.good_document

        def progress(name, done, total):
            if generation != self.generation:
                raise Stale

        def work():
            began = _now()
            try:
                result = self.session.settle(document, progress=progress)
            except Stale:
                return
            self.doc.add_next_tick_callback(partial(self.draw_sweep, generation, result, began))

        SWEEP_WORKERS.submit(work)

    def _sweep_of(self, result):
        return result["sweeps"].get(self.valve) or next(iter(result["sweeps"].values()))

    @staticmethod
    def _sweep_curves(sw, sources):
        _send(sources["force"], {"x": sw["speed_rpm"], "y": sw["min_contact_force_N"]})
        _send(sources["seating"], {"x": sw["speed_rpm"],
                                   "y": [None if v is None else abs(v) for v in sw["seating_velocity_m_s"]]})

    def draw_sweep(self, generation, result, began) -> None:
        """Keep the whole design of redraw ``generation`` if it is the newest: its checks to the table, its sweeps
        to the sweep panel; ``began`` as for :meth:`redraw`, when the worker took it up."""
        if generation != self.generation:
            return
        self.session.settled(result)
        _hold(self.sweep_hold)
        try:
            if result["ok"] and result["results"] is not None:
                self._checks()
            self._sweep_panel()
        finally:
            _count(self.sweep_stamp, began)

    def _sweep_panel(self):
        """The sweep panel of the whole design kept (its problems in the panel's title when it did not design)."""
        result = self.session.full
        if not result["ok"]:
            self.sweep_status.text = "; ".join(p["text"] for p in result["errors"])
            return
        sw = self._sweep_of(result)
        self._sweep_curves(sw, self.sweep_sources)
        if self.base_sweep is not None:
            self._sweep_curves(self._sweep_of(self.base_sweep), self.base_sweep_sources)
        marks = [v for v in (sw["jump_speed_rpm"], sw["bounce_speed_rpm"]) if v is not None]
        forces = [v for v in sw["min_contact_force_N"] if v is not None]
        _send(self.sweep_marks, {"x": marks, "y0": [min(forces)] * len(marks), "y1": [max(forces)] * len(marks)})
        err = np.array(sw["map_lift_error_mm"], dtype=float)
        bound = float(np.nanmax(np.abs(err))) or 1.0
        self.mapper.low, self.mapper.high = -bound, bound
        x, n = sw["map_cam_deg"], sw["speed_rpm"]
        _send(self.map_source, {"image": [err], "x": [x[0]], "y": [n[0]], "dw": [x[-1] - x[0]], "dh": [n[-1] - n[0]]})
        t = WORDS[self.lang]
        self.sweep_status.text = ", ".join(f"{t[k]} {v:.5g} rpm" for k, v in (("jump", sw["jump_speed_rpm"]),
                                                                               ("bounce", sw["bounce_speed_rpm"]))
                                           if v is not None) or "-"

    # --- callbacks -------------------------------------------------------------------------------------------------
    def on_field(self, f, attr, old, new) -> None:
        began = _now()
        if self._syncing:
            return
        try:
            value = parse_value(f, new)
        except ValueError as exc:
            self.errors[f.path].text = str(exc)
            self.erring.add(f.path)
            return
        if self.session.edit({f.path: value}):
            self.redraw(began=began)
        self.show_problems()

    def on_handles(self, plot, attr, old, new) -> None:
        began = _now()
        placed = getattr(self, "_placed", {}).get(plot, [])
        if len(new["x"]) != len(placed):      # a point added or removed: a table's points, else put them back
            keys = self.session.set_points(self.valve, new["x"], new["y"]) if self.draw_tools[plot].add else {}
            self._answer(keys, began)
            return
        omega = self._omega(self.session.good)
        for (name, x, y), nx, ny in zip(placed, new["x"], new["y"], strict=True):
            if abs(nx - x) > 1e-9 or abs(ny - y) > 1e-9:
                if plot == "acceleration" and omega is not None:     # to m/s², as the session takes it
                    ny = ny / float(per_degree(1.0, 2, omega))
                self._answer(self.session.drag(self.valve, name, nx, ny), began)
                return

    def _answer(self, keys, began):
        """After a change of the handles that set ``keys`` (none: it did not design): redraw, or put the handles
        back; the problems and the panel's inputs follow."""
        if keys:
            self.redraw(began=began)
        else:
            self._handles(self._omega(self.session.good))
        self.show_problems()
        self._sync_fields(keys)

    def _sync_fields(self, values):
        """The panel's inputs show the values a drag set (``{dotted key: value}``)."""
        self._syncing = True
        for path, value in values.items():
            w = self.fields.get(path)
            if w is not None:
                w.value = value if isinstance(w, NumericInput) else value_text(value)
        self._syncing = False

    def on_language(self, attr, old, new) -> None:
        self.lang = new
        self._texts()
        self.redraw(sweep=False)
        self.show_problems()

    def on_units(self, attr, old, new) -> None:
        self.per_degree = new == "deg"
        self._texts()
        self.redraw(sweep=False)

    def on_valve(self, attr, old, new) -> None:
        self.valve = new
        self.redraw()

    def on_report(self) -> None:
        """The report of the good design, to the page, which saves it (a comment makes every one a change)."""
        self.downloads += 1
        self.report_text.text = self.session.report(self.lang) + f"<!-- download {self.downloads} -->\n"

    def on_toml(self) -> None:
        """The specification of the good design, to the page, which saves it (a comment makes every one a change)."""
        self.downloads += 1
        self.toml_text.text = self.session.toml() + f"# download {self.downloads}\n"

    def on_pin(self) -> None:
        self.session.pin()
        full = self.session.full
        self.base_sweep = full if full is not None and full["ok"] else None
        self.redraw(sweep=False)

