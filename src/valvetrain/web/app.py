"""The page of the designer: a Bokeh document per browser tab, on a :class:`~valvetrain.web.session.Session`.

The page fits 1400 x 900 px: a bar of commands on top; on the left the specification panel, generated from the
specification's models (:func:`valvetrain.web.form.form`) and grouped as a designer thinks (engine, valve, cam,
spring, drive, dynamics), each input with its name, unit and range; on the right the lift and the acceleration with
their handles, below them the other plots in tabs (velocity and jerk; contour and curvature; time-area and spring;
the dynamics at speed; the breathing's volumetric efficiency against the speed), and at the bottom the checks and
the cam card.

The handles are dragged by the page's own script (``page.js``): one to one with the pointer within their limits,
which the selected handle shows; while the pointer moves, the server works out the kinematics of the handle's
valve at its newest position (one request at a time) and the curves follow; the release draws them at once and
keeps the design when its worker thread has designed it (springs, checks, breathing: an edit that can be undone;
the spring plot is empty until then, the spring being the design's), arrow keys nudge the selected handle, Ctrl-Z
and Ctrl-Y undo and redo.  The plots of the tabs not shown hold their painting until their tab is chosen.  The
speed sweep of a design kept runs in a worker thread and only the newest one is drawn (an older one is stopped at
its next speed).

The page keeps its timings: ``window.vtTimes`` (the release of a drag, a key or an undo to the painted frame of its
curves, ms), ``window.vtChecksTimes`` (to the painted frame of its checks, card and panel), ``window.vtSweepTimes`` (to the painted frame of the sweep panel), ``window.vtTimesArrived`` (to the
arrival of the redraw), ``window.vtMoveTimes`` (a move of the pointer sent to the painted frame of the curves it
brought); ``window.vtTimesDone``, ``window.vtSweepTimesDone`` count the redraws painted.
"""

import base64
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from functools import partial
import hashlib
import json
from pathlib import Path
import time
import tomllib

from bokeh.core.property.descriptors import UnsetValueError
from bokeh.layouts import column, row
from bokeh.models import (Button, ColorBar, ColumnDataSource, CustomJS, DataTable, Div, Dropdown, FileInput,
                          HTMLTemplateFormatter, InlineStyleSheet, Label, LinearAxis, LinearColorMapper, NumericInput,
                          Range1d, Select, Slider, TableColumn, TabPanel, Tabs, TextInput)
from bokeh.plotting import figure
import numpy as np

from ..errors import ValvetrainError
from ..languages import LANGS
from ..locale import catalogue
from ..report.html import check_range
from ..report.i18n import TEXT
from ..report.names import label, record_quantity_text, translate
from ..units import per_cam_degree
from .form import GROUPS, form, parse_value, value_at, value_of, value_text
from .session import document_key, has_points

WORDS = {lang: catalogue(lang)["designer"] for lang in LANGS}
"""The designer's own words in each language, from the catalogue's ``[designer]`` (the plots' and the checks' come from
the report's)."""

INCH = 25.4
"""mm per inch."""

VALVE_CARD = ("cam.max_acceleration_m_s2", "cam.min_acceleration_m_s2", "cam.rho_min_mm", "flow.time_area_mm2_s",
              "flow.fullness")
"""The keys of a valve's results on the cam card below its events."""

EVENTS = (("cc_at_seat", ("seat_opens", "seat_closes", "seat_duration")),
          ("cc_at_1mm", ("opens_at_1mm", "closes_at_1mm", "duration_at_1mm")),
          ("cc_at_050", ("opens_at_0_050in", "closes_at_0_050in", "duration_at_0_050in")))
"""The cam card's events: at each checking height (the report's words) the opening, closing and duration keys of a
valve's record of ``cam_card`` (crank deg)."""

KINEMATIC_PLOTS = (("lift", "valve_lift_mm", 0), ("velocity", "valve_velocity_m_s", 1),
                   ("acceleration", "valve_acceleration_m_s2", 2), ("jerk", "valve_jerk_m_s3", 3))
"""The plots against the camshaft angle: name, series, order of the derivative."""

CURVES = {"tappet": "tappet_lift_mm", "crank_x": "crank_deg", "time_area": "time_area_mm2_s",
          "curtain": "curtain_area_mm2"}
"""The columns of a design's curves besides the kinematics (:data:`KINEMATIC_PLOTS`), the curvature, the contour and
the spring, and the series they hold (the current and the baseline each have their source).  One source for all, the
shorter series padded with NaN (which a line leaves out): a redraw sends one change, not one per curve."""

PLOTS = {"lift": ("x", "lift"), "velocity": ("x", "velocity"), "acceleration": ("x", "acceleration"),
         "jerk": ("x", "jerk"), "contour": ("contour_x", "contour_y"), "curvature": ("x", "curvature"),
         "time_area": ("crank_x", "time_area"), "spring": ("spring_x", "spring_y")}
"""Each plot's columns of abscissae and ordinates."""

HANDLE_ROOM = 0.25
"""The kinematic plots' room above and below the curves, a fraction of their span: how far one drag takes a handle
beyond the highest or lowest point.  A redraw keeps the range while at least half this room is left
(:func:`kept_range`)."""

PLOT_ROOM = 0.05
"""The other plots' room around their curves, a fraction of their span (none kept: the curves only stay inside)."""

RANGES = {"x": (("x",), 0.0), "lift": (("lift",), HANDLE_ROOM), "velocity": (("velocity",), HANDLE_ROOM),
          "acceleration": (("acceleration",), HANDLE_ROOM), "jerk": (("jerk",), HANDLE_ROOM),
          "curvature": (("curvature", "curvature_limit"), PLOT_ROOM), "crank_x": (("crank_x",), 0.0),
          "time_area": (("time_area",), PLOT_ROOM), "curtain": (("curtain",), PLOT_ROOM),
          "spring_x": (("spring_x", "spring_line_x"), PLOT_ROOM), "spring": (("spring_y", "spring_line_y"), PLOT_ROOM)}
"""The plots' fixed ranges (the contour's follows its data, to keep its aspect): the columns they hold, of the
design and of the baseline (the spring's: the required force and the chosen spring's line; the curvature's: its
limit too), and their room (:func:`kept_range`)."""

SEVERITY_COLOURS = {"failure": "#f4c7c3", "warning": "#fce8b2", "info": "#e8eaf6", "pass": "#d9ead3",
                    "accepted": "#dde3ee", "pending": "#eeeeee"}
"""The colours of the checks table's rows, each beside the word of its status (:data:`STATUS_WORDS`): failing by
severity, accepted (a failure the specification accepts), passing, pending (its speed sweeps to come)."""

STATUS_WORDS = {"failure": "fails", "warning": "warns", "info": "remarks", "pass": "passes", "accepted": "accepted",
                "pending": "pending"}
"""The designer's word of each status of a check (:data:`WORDS`)."""

WIDTH, PANEL_WIDTH, PLOT_WIDTH = 1390, 330, 520
"""The page's width, the specification panel's and a large plot's [px]: 1400 px wide with the browser's margin."""

INPUT_CSS = """
:host { width: 100%; }
.bk-input-group { flex-direction: row; align-items: center; gap: 6px; }
.bk-input-group > label { flex: 1 1 auto; min-width: 0; font-size: 12px; line-height: 1.2; white-space: normal;
                          overflow: visible; text-overflow: clip; overflow-wrap: anywhere; }
.bk-input-group > .bk-input, .bk-input-group > select, .bk-input-group > .bk-input-container {
    flex: 0 0 104px; width: 104px; height: 24px; padding: 1px 4px; font-size: 12px; }
:host(.vt-refused) .bk-input { border-color: #b00020; background: #fdecea; }
"""
"""The panel's inputs in one row each: the name with its unit and range, then the input (a refused one red)."""

BAR_CSS = """
.bk-input-group { flex-direction: row; align-items: center; gap: 4px; }
.bk-input-group > label { font-size: 12px; white-space: nowrap; }
.bk-input-group > select { height: 26px; font-size: 12px; padding: 1px 2px; }
"""
"""The command bar's selects with their titles beside them."""

STAMP_JS = """
// a redraw painted: its time from the release (a drag, a key, an undo) that asked for it, and from the move it answered
const arrived = performance.now();
const data = cb_obj.data instanceof Map ? Object.fromEntries(cb_obj.data) : cb_obj.data;
const seq = data.seq[0];
const vt = window.vt || {};
if (key === 'vtTimes' && vt.inflight && seq >= vt.inflight) {
  vt.inflight = 0;
  if (vt.pending && vt.drag) {
    vt.pending = false;
    vt.send_move();
  }
}
const sent = key === 'vtTimes' && vt.sent ? vt.sent[seq] : undefined;
requestAnimationFrame(() => requestAnimationFrame(() => {
  const t = performance.now();
  for (const k of [key, key + 'Arrived', key + 'Server', 'vtMoveTimes']) {
    window[k] = window[k] || [];
  }
  if (window.vtRelease !== undefined && vt.release && seq === vt.release) {
    window[key].push(t - window.vtRelease);
    window[key + 'Arrived'].push(arrived - window.vtRelease);
    const release = performance.timeOrigin + window.vtRelease;
    window[key + 'Server'].push([data.began[0] - release, data.ended[0] - data.began[0],
                                 performance.timeOrigin + arrived - data.ended[0], data.cpu[0]]);
  } else if (sent !== undefined && seq !== vt.release) {
    window.vtMoveTimes.push(t - sent);
  }
  window[key + 'Done'] = (window[key + 'Done'] || 0) + 1;
}));
"""
"""The page's probe: on the change of a stamp (the last change of a redraw), the time from the release that asked for
it to the second animation frame after it came (the frame that shows it painted)."""

VIEW_JS = """
const view = (model) => {
  const kept = window.vtViews || (window.vtViews = new Map());
  let found = kept.get(model.id);
  if (found == null || found.is_destroyed) {
    found = Bokeh.index.find_one(model);
    if (found != null) {
      kept.set(model.id, found);
    }
  }
  return found;
};
"""
"""The start of the page's scripts that look up a model's view: ``view(model)``, kept once found.  Bokeh's
``Bokeh.index.find_one`` walks every view of the page (977 on the built-in example: the panel's inputs, the tables,
the plots' renderers and tools) and was called about 20 times per redraw (the holds' plots, the handles' plots): 30
to 40 ms of the page's drawing of a release at a load of 7."""

PAUSE_JS = VIEW_JS + """
if (!window[key]) {
  window[key] = plots.map(view).filter((v) => v != null);
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

TABS_JS = """
plots.forEach((shown, i) => shown.forEach((p) => {
  const held = i !== tabs.active;
  if (p.hold_render !== held) {
    p.setv({hold_render: held}, {sync: false});
  }
}));
"""
"""Run when the page is ready and when another tab of plots is chosen: the plots of the tabs not shown hold their
painting (``hold_render``, set in the page alone), those of the tab shown paint their newest data.  Bokeh paints
every plot of the tabs at each change of its data, shown or not (a tab hides its panel by its visibility, its plots
stay laid out): the six plots of the curves' other three tabs were painted with the lift and the acceleration at
every redraw of a drag.  (Not by pausing their views: Bokeh resumes a paused plot at each layout of it.)"""

PAGE_JS = VIEW_JS + (Path(__file__).parent / "page.js").read_text(encoding="utf-8")
"""The page's handling of the handles, the keys and the edits kept across a reload (page.js)."""

DOWNLOAD_JS = """
const data = div.text;
const bytes = binary ? Uint8Array.from(atob(data), (c) => c.charCodeAt(0)) : data;
const blob = new Blob([bytes], {type: mime});
const a = document.createElement('a');
a.href = URL.createObjectURL(blob);
a.download = name;
document.body.appendChild(a);
a.click();
a.remove();
"""

SWEEP_WORKERS = ThreadPoolExecutor(max_workers=1, thread_name_prefix="valvetrain-sweep")
"""One thread for the speed sweeps of every tab (2 cores: the kinematics keep the other)."""

DESIGN_WORKERS = ThreadPoolExecutor(max_workers=1, thread_name_prefix="valvetrain-design")
"""One thread for the designs of the drags released (their springs, checks and breathing), beside the sweeps': the
page's answer to the release (the valve's kinematics) and to the next move does not wait for them."""


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


@dataclass(frozen=True)
class Units:
    """The units the page shows: lengths in ``"mm"`` or ``"in"``; angles as ``"cam"`` deg from the nose or
    ``"crank"`` deg from the gas-exchange TDC; the lift's derivatives at the rated speed (``"rated"``: m/s, m/s²,
    m/s³) or per degree of the angle (``"deg"``: mm or in per deg to the order).  The session's are mm, cam deg
    from the nose and m/s^n: each plot's abscissa and ordinate are ``scale x value + offset`` of them
    (:meth:`of`)."""

    length: str = "mm"
    angle: str = "cam"
    derivative: str = "rated"

    @property
    def mm(self) -> float:
        """Shown lengths per mm."""
        return 1.0 if self.length == "mm" else 1.0 / INCH

    @staticmethod
    def timing(series) -> tuple[float, float]:
        """A valve's crank degrees per cam degree and its nose's crank angle, from its series (crank = nose +
        ratio x cam: 2 on a four-stroke)."""
        cam, crank = np.asarray(series["cam_deg"], dtype=float), np.asarray(series["crank_deg"], dtype=float)
        ratio = (crank[-1] - crank[0]) / (cam[-1] - cam[0])
        return float(ratio), float(crank[0] - ratio * cam[0])

    def of(self, series, omega, order=None) -> tuple[float, float]:
        """``(scale, offset)`` of the abscissa (``order`` None) or of the ordinate of the lift's derivative of
        ``order`` (0 the lift) of a valve with these ``series`` and camshaft speed ``omega`` [rad/s]."""
        ratio, nose = self.timing(series)
        if order is None:
            return (ratio, nose) if self.angle == "crank" else (1.0, 0.0)
        if order == 0:
            return self.mm, 0.0
        if self.derivative == "rated":
            return 1.0, 0.0
        per = ratio if self.angle == "crank" else 1.0
        return float(per_cam_degree(1.0, order, omega)) * self.mm / per**order, 0.0


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


class Stale(ValvetrainError):
    """Raised into a speed sweep that a newer change made stale."""


def _array(values):
    """A series as a float array (None a gap, NaN): sent to the page as binary, not as JSON numbers."""
    return np.asarray([np.nan if v is None else v for v in values] if isinstance(values, list) and None in values
                      else values, dtype=float)


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


def _count(stamp, began, seq=0):
    """One more redraw on a stamp's source (its change in the page stamps the time), with the server's times
    ``began`` (:func:`_now` when the change came) and now, as ms since the epoch: the page, on the same clock,
    parts its wait into the way up, the server and the way down; the processor time the server's process spent
    in between [ms] (what the server costs on a loaded machine); ``seq`` the page's request it answers."""
    stamp.data = {"n": [stamp.data["n"][0] + 1], "began": [1e3 * began[0]], "ended": [1e3 * time.time()],
                  "cpu": [1e3 * (time.process_time() - began[1])], "seq": [seq]}


def _stamp(name):
    return ColumnDataSource({"n": [0], "began": [0.0], "ended": [0.0], "cpu": [0.0], "seq": [0]}, name=name)


class Designer:
    """The widgets, plots and callbacks of one browser tab."""

    def __init__(self, doc, session, key=""):
        self.doc, self.session, self.lang = doc, session, "en"
        self.names = list(session.document.get("valves") or {})
        self.valve = self.names[0] if self.names else None
        self.units = Units()
        self.generation = 0
        self._syncing = False
        self.downloads = 0
        self.sweeps, self.base_sweeps = {}, None        # the valves' sweep series drawn, the baseline's
        self.sweep_due = False
        self.sweep_seq = 0
        self.sweep_key = None            # the document whose sweep was started last (document_key)
        self.shown = None                # a drag's preview drawn: (document, result), else the good design
        self.pending = None              # the design of a drag released, in the worker: (future, keys set, seq)
        self.fields, self.widgets = {}, {}
        self.refused_paths = set()
        self.key = key
        self._build()
        self._texts()
        self.redraw(sweep=bool(self.names))
        self.show_problems()

    # --- building --------------------------------------------------------------------------------------------------
    def _widget(self, f):
        """The input of a field of the panel: its name with its unit and range in the page's language, the key in
        its description (a hover on its mark)."""
        bounds = f" ({f.low:g} … {f.high:g})" if f.low is not None and f.high is not None else ""
        common = {"title": label(f.name, self.lang) + bounds, "stylesheets": [self.input_css], "description": f.path,
                  "width": PANEL_WIDTH - 40, "name": f.path}
        if f.kind in ("float", "int"):
            w = NumericInput(value=f.value, mode=f.kind, **common)
        elif f.kind == "choice":
            options = ([""] if f.optional else []) + [str(o) for o in f.options]
            w = Select(value="" if f.value is None else str(f.value), options=options, **common)
        else:
            w = TextInput(value=value_text(f.value), **common)
        w.on_change("value", partial(self.on_field, f))
        self.fields[f.path], self.widgets[f.path] = f, w
        return w

    def _panel(self) -> Tabs:
        """The specification panel in the page's language: a tab per group
        (:data:`~valvetrain.web.form.GROUPS`), in each the inputs of every valve, those of the valve shown
        visible.  Built again for another language (each input's new name would lay the page out once more)."""
        document = self.session.document
        self.group_columns, self.fields, self.widgets = {}, {}, {}
        self.laws = {valve: value_at(document, f"valves.{valve}.cam.law") for valve in self.names}
        tabs = []
        for group, _ in GROUPS:
            if group != "engine" and not self.names:
                continue
            parts = []
            for valve in [None] if group == "engine" else self.names:
                fields = dict(form(document, valve))[group]
                box = column(*[self._widget(f) for f in fields], visible=valve in (None, self.valve),
                             width=PANEL_WIDTH - 30)
                self.group_columns[(group, valve)] = box
                parts.append(box)
            tabs.append(TabPanel(title=WORDS[self.lang][f"group_{group}"],
                                 child=column(*parts, height=740, width=PANEL_WIDTH - 10,
                                              styles={"overflow-y": "auto", "overflow-x": "hidden"})))
        active = self.spec_tabs.active if getattr(self, "spec_tabs", None) is not None else 0
        self.spec_tabs = Tabs(tabs=tabs, width=PANEL_WIDTH, name="panel", active=active)
        return self.spec_tabs

    def _build(self):
        t = WORDS["en"]
        # one style sheet for every input of the panel, one for the bar's (a model of this document)
        self.input_css, self.bar_css = InlineStyleSheet(css=INPUT_CSS), InlineStyleSheet(css=BAR_CSS)
        self.language = Select(value="en", options=[("en", "English"), ("ru", "Русский")], name="language",
                               width=95, stylesheets=[self.bar_css])
        self.language.on_change("value", self.on_language)
        self.valve_select = Select(value=self.valve or "", options=self.names, width=140, name="valve",
                                   stylesheets=[self.bar_css], visible=bool(self.names))
        self.valve_select.on_change("value", self.on_valve)
        self.length_select = Select(value="mm", width=70, name="length", stylesheets=[self.bar_css])
        self.angle_select = Select(value="cam", width=170, name="angle", stylesheets=[self.bar_css])
        self.derivative_select = Select(value="rated", width=200, name="derivative", stylesheets=[self.bar_css])
        for w in (self.length_select, self.angle_select, self.derivative_select):
            w.on_change("value", self.on_units)
        self.buttons = {}
        for key, handler in (("undo", self.on_undo), ("redo", self.on_redo), ("pin", self.on_pin)):
            b = Button(label=t[key], name=f"button-{key}", width=len(t[key]) * 7 + 30, height=28)
            b.on_click(handler)
            self.buttons[key] = b
        self.download = Dropdown(label=t["download"], name="download", width=110, height=28,
                                 menu=[(t[k], k) for k in ("toml", "dxf", "report")])
        self.download.on_click(self.on_download)
        self.downloaded = {}
        for key, mime, name, binary in (("toml", "application/toml", "valvetrain.toml", False),
                                        ("dxf", "image/vnd.dxf", "cam.dxf", True),
                                        ("report", "text/html", "report.html", False)):
            div = Div(text="", visible=False)
            div.js_on_change("text", CustomJS(args={"div": div, "mime": mime, "name": name, "binary": binary},
                                              code=DOWNLOAD_JS))
            self.downloaded[key] = div
        self.overlay = FileInput(accept=".toml", width=210, name="overlay", stylesheets=[self.bar_css])
        self.overlay.on_change("value", self.on_overlay)
        self.status = Div(text="", name="status", styles={"color": "#b00020", "font-size": "12px"},
                          width=PANEL_WIDTH - 10)
        self.panel_box = column(self.status, self._panel())

        tools = "pan,wheel_zoom,box_zoom,reset,save"
        empty = {k: [] for k in ("x", "curvature", "curvature_limit", "spring_x", "spring_y", "spring_line_x",
                                 "spring_line_y", "contour_x", "contour_y", *CURVES, *(p[0] for p in KINEMATIC_PLOTS))}
        self.curves, self.base_curves = (ColumnDataSource(empty, name="curves"),
                                         ColumnDataSource(empty, name="base-curves"))
        self.figures = {}
        big = {"height": 250, "width": PLOT_WIDTH}
        for name, *_ in KINEMATIC_PLOTS:
            self.figures[name] = self._plot(figure(tools=tools, name=f"plot-{name}", x_range=Range1d(0, 1),
                                                   y_range=Range1d(0, 1), **big), name)
        for name in ("velocity", "jerk"):
            self.figures[name].height = 230
        self.figures["lift"].line("x", "tappet", source=self.curves, color="#2ca02c", line_width=1)
        self.segments = ColumnDataSource({"x": [], "y0": [], "y1": []})
        self.figures["acceleration"].segment("x", "y0", "x", "y1", source=self.segments, color="#bbbbbb",
                                             line_dash="dotted")
        self.handles, self.limits = {}, {}
        for plot in ("lift", "acceleration"):
            src = ColumnDataSource({k: [] for k in ("x", "y", "name", "x_lo", "x_hi", "y_lo", "y_hi")},
                                   name=f"handles-{plot}")
            lim = ColumnDataSource({k: [np.nan, np.nan] for k in ("x0", "y0", "x1", "y1", "sx", "sy")},
                                   name=f"limits-{plot}")
            fig = self.figures[plot]
            fig.segment("x0", "y0", "x1", "y1", source=lim, color="#d62728", line_width=3, line_alpha=0.35)
            fig.scatter("sx", "sy", source=lim, size=19, fill_alpha=0.0, line_color="#d62728", line_width=2)
            fig.scatter("x", "y", source=src, size=13, color="#d62728", marker="circle")
            self.handles[plot], self.limits[plot] = src, lim
        for name in ("lift", "velocity", "acceleration"):
            self.figures[name].x_range = self.figures["jerk"].x_range
        self.request = ColumnDataSource({k: [] for k in ("kind", "seq", "plot", "name", "x", "y", "text")},
                                        name="request")
        self.request.on_change("data", self.on_request)
        self.options = ColumnDataSource({"add": [False]}, name="options")
        self.saved = ColumnDataSource({"document": [json.dumps(self.session.document)]}, name="saved")

        self.figures["contour"] = self._plot(figure(height=230, width=230, tools=tools, name="plot-contour",
                                                    match_aspect=True), "contour")
        for name in ("curvature", "time_area", "spring"):
            self.figures[name] = self._plot(figure(height=230, width=PLOT_WIDTH if name != "curvature" else 790,
                                                   tools=tools, name=f"plot-{name}", x_range=Range1d(0, 1),
                                                   y_range=Range1d(0, 1)), name)
        self.figures["curvature"].x_range = self.figures["jerk"].x_range
        self.heel = ColumnDataSource({"x": [], "y": []})
        self.figures["contour"].line("x", "y", source=self.heel, color="#2ca02c", line_dash="dashed")
        self.figures["curvature"].line("x", "curvature_limit", source=self.curves, color="#b00020", line_dash="dashed")
        self.figures["spring"].line("spring_line_x", "spring_line_y", source=self.curves, color="black", line_width=2)
        ta = self.figures["time_area"]
        ta.line("crank_x", "curtain", source=self.curves, color="#ff7f0e", y_range_name="curtain")
        ta.extra_y_ranges = {"curtain": Range1d(0, 1)}
        # the fullness in the plot, not in its title: a title's new text lays the plot out again
        self.fullness = Label(x=0, y=0, text="", text_font_size="11px", text_baseline="top")
        ta.add_layout(self.fullness)
        f = self.figures
        self.ranges = {"x": f["jerk"].x_range, "crank_x": ta.x_range, "spring_x": f["spring"].x_range,
                       "curtain": ta.extra_y_ranges["curtain"],
                       **{name: f[name].y_range for name in ("lift", "velocity", "acceleration", "jerk", "curvature",
                                                             "time_area", "spring")}}
        self.curtain_axis = LinearAxis(y_range_name="curtain", axis_label_text_color="#ff7f0e")
        ta.add_layout(self.curtain_axis, "right")

        self.checks = ColumnDataSource({k: [] for k in ("key", "status", "quantity", "value", "allowed", "margin",
                                                        "source", "colour", "baseline")})
        fmt = HTMLTemplateFormatter(template='<div style="background:<%= colour %>; padding-left:3px"><%= value %></div>')
        self.check_columns = [TableColumn(field="status", title="", formatter=fmt, width=95),
                              TableColumn(field="quantity", title="", width=270),
                              TableColumn(field="value", title="", width=95),
                              TableColumn(field="baseline", title="", width=80),
                              TableColumn(field="allowed", title="", width=105),
                              TableColumn(field="margin", title="", width=55),
                              TableColumn(field="source", title="", width=300)]
        # the columns keep their widths: fitted to the table (autosized), they would be measured again on every change
        # of the rows
        self.table = DataTable(source=self.checks, columns=self.check_columns, width=WIDTH - PANEL_WIDTH - 330,
                               height=300, index_position=None, name="checks", autosize_mode="none", row_height=22)
        _rows_follow(self.table)
        # the cam card is a table: new rows leave the page's layout (a Div's new text lays the page out again)
        self.card = ColumnDataSource({k: [] for k in ("quantity", *self.names)}, name="card")
        self.card_columns = [TableColumn(field="quantity", title="", width=180)] + [
            TableColumn(field=n, title=n, width=max(60, 130 // max(1, len(self.names)))) for n in self.names]
        self.card_table = DataTable(source=self.card, columns=self.card_columns, width=320, height=300,
                                    index_position=None, autosize_mode="none", row_height=22, name="card-table")
        _rows_follow(self.card_table)

        # the dynamics at speed
        # the sweep's state inside its plot, not in a title: a title's new text lays the plot out again
        self.sweep_status = Label(x=6, y=6, x_units="screen", y_units="screen", text="", name="sweep-status",
                                  text_font_size="11px", background_fill_color="white", background_fill_alpha=0.8)
        self.sweep_sources = {k: ColumnDataSource({"x": [], "y": []}, name=f"sweep-{k}") for k in ("force", "seating")}
        self.base_sweep_sources = {k: ColumnDataSource({"x": [], "y": []}) for k in ("force", "seating")}
        self.sweep_marks = {k: ColumnDataSource({"x": [], "y0": [], "y1": []}) for k in ("force", "seating")}
        for key in ("force", "seating"):
            p = figure(tools=tools, name=f"plot-sweep-{key}", height=200, width=245, x_range=Range1d(0, 1),
                       y_range=Range1d(0, 1))
            p.line("x", "y", source=self.base_sweep_sources[key], color="#999999", line_dash="dashed", line_width=1.5)
            p.line("x", "y", source=self.sweep_sources[key], color="#1f77b4", line_width=2)
            p.segment("x", "y0", "x", "y1", source=self.sweep_marks[key], color="#d62728", line_dash="dashed")
            self.figures["sweep_" + key] = p
        self.figures["sweep_force"].add_layout(self.sweep_status)
        self.map_source = ColumnDataSource({"image": [], "x": [], "y": [], "dw": [], "dh": []}, name="sweep-map")
        self.mapper = LinearColorMapper(palette="RdBu11", low=-1.0, high=1.0)
        p = figure(tools=tools, name="plot-sweep-map", height=200, width=285, x_range=Range1d(0, 1),
                   y_range=Range1d(0, 1))
        p.image("image", x="x", y="y", dw="dw", dh="dh", source=self.map_source, color_mapper=self.mapper)
        p.xaxis.ticker.desired_num_ticks = 4
        self.colour_bar = ColorBar(color_mapper=self.mapper, width=10, name="map-colour-bar", label_standoff=4,
                                   major_label_text_font_size="10px")
        p.add_layout(self.colour_bar, "right")
        self.figures["sweep_map"] = p
        self.at_speed = ColumnDataSource({"x": [], "force": [], "acceleration": [], "rigid": []}, name="at-speed")
        p = figure(tools=tools, name="plot-at-speed", height=200, width=265, x_range=Range1d(-1, 1),
                   y_range=Range1d(0, 1))
        p.line("x", "force", source=self.at_speed, color="#1f77b4", line_width=2)
        p.extra_y_ranges = {"acceleration": Range1d(-1, 1)}
        p.line("x", "rigid", source=self.at_speed, color="#999999", line_dash="dashed", y_range_name="acceleration")
        p.line("x", "acceleration", source=self.at_speed, color="#ff7f0e", y_range_name="acceleration")
        p.xaxis.ticker.desired_num_ticks = 4
        self.acceleration_axis = LinearAxis(y_range_name="acceleration", axis_label_text_color="#ff7f0e")
        p.add_layout(self.acceleration_axis, "right")
        self.figures["at_speed"] = p
        # the breathing: the volumetric efficiency (and the torque, fired) against the speed, redrawn with the checks
        self.breathing = {k: ColumnDataSource({"speed": [], "ve": [], "torque": []}, name=f"breathing-{k}")
                          for k in ("curve", "conditions", "phased")}
        p = figure(tools=tools, name="plot-breathing", height=230, width=PLOT_WIDTH, x_range=Range1d(0, 1),
                   y_range=Range1d(0, 1))
        p.extra_y_ranges = {"torque": Range1d(0, 1)}
        p.line("speed", "ve", source=self.breathing["curve"], color="#1f77b4", line_width=2)
        p.scatter("speed", "ve", source=self.breathing["conditions"], color="#1f77b4", size=8)
        p.line("speed", "torque", source=self.breathing["curve"], color="#ff7f0e", y_range_name="torque")
        p.scatter("speed", "torque", source=self.breathing["conditions"], color="#ff7f0e", size=8, marker="square",
                  y_range_name="torque")
        # a cam phaser's best phase at each condition: the breathing there, hollow marks over the phase-0 points
        p.scatter("speed", "ve", source=self.breathing["phased"], line_color="#1f77b4", fill_color=None, size=14,
                  marker="diamond", line_width=2)
        p.scatter("speed", "torque", source=self.breathing["phased"], line_color="#ff7f0e", fill_color=None, size=14,
                  marker="diamond", line_width=2, y_range_name="torque")
        self.torque_axis = LinearAxis(y_range_name="torque", axis_label_text_color="#ff7f0e")
        p.add_layout(self.torque_axis, "right")
        self.breathing_status = Label(x=6, y=6, x_units="screen", y_units="screen", text="", name="breathing-status",
                                      text_font_size="11px", background_fill_color="white", background_fill_alpha=0.8)
        p.add_layout(self.breathing_status)
        self.figures["breathing"] = p
        self.speed = Slider(start=0, end=1, value=0, step=1, width=1020, name="speed", visible=False)
        self.speed.on_change("value_throttled", self.on_speed)

        # the stamps are data sources, not widgets: a widget's change lays the whole page out again (~100 ms)
        self.kinematic_stamp = _stamp("kinematic-stamp")
        self.kinematic_hold = _held([self.figures[k] for k in PLOTS], self.kinematic_stamp, "vtPausedKinematics")
        self.kinematic_stamp.js_on_change("data", CustomJS(args={"key": "vtTimes"}, code=STAMP_JS))
        # the page says when it has drawn the kinematics of a design kept: its sweep starts then
        self.drawn = ColumnDataSource({"n": [0]}, name="drawn")
        self.drawn.on_change("data", self.on_drawn)
        self.kinematic_stamp.js_on_change("data", CustomJS(args={"stamp": self.kinematic_stamp, "drawn": self.drawn},
                                                           code=DRAWN_JS))
        # the checks, card and panel of a design kept: with the curves, or after them (a drag released)
        self.checks_stamp = _stamp("checks-stamp")
        self.checks_stamp.js_on_change("data", CustomJS(args={"key": "vtChecksTimes"}, code=STAMP_JS))
        self.sweep_stamp = _stamp("sweep-stamp")
        self.sweep_hold = _held([self.figures[k] for k in ("sweep_force", "sweep_seating", "sweep_map", "at_speed")],
                                self.sweep_stamp, "vtPausedSweep")
        self.sweep_stamp.js_on_change("data", CustomJS(args={"key": "vtSweepTimes"}, code=STAMP_JS))

        f = self.figures
        self.plot_tabs = Tabs(name="plots", width=WIDTH - PANEL_WIDTH - 10, active=3, tabs=[
            TabPanel(title="", child=row(f["velocity"], f["jerk"])),
            TabPanel(title="", child=row(f["contour"], f["curvature"])),
            TabPanel(title="", child=row(f["time_area"], f["spring"])),
            TabPanel(title="", child=column(self.speed, row(f["sweep_force"], f["sweep_seating"], f["sweep_map"],
                                                            f["at_speed"]))),
            TabPanel(title="", child=row(f["breathing"]))])
        bar = row(self.valve_select, self.length_select, self.angle_select, self.derivative_select,
                  *self.buttons.values(), self.overlay, self.download, self.language, width=WIDTH, height=34)
        main = column(row(f["lift"], f["acceleration"]), self.plot_tabs, row(self.table, self.card_table))
        with self.doc.models.freeze():          # the document's models collected once, not once per root
            self._add_roots(bar, main)

    def _add_roots(self, bar, main):
        f = self.figures
        # the bar a root of its own: nested one level deeper, the plots of the tabs were laid out with no size
        # (Bokeh 3.9: a column holding a row holding a column of plots and tabs)
        self.doc.add_root(bar)
        self.doc.add_root(row(self.panel_box, main, name="page"))
        self.doc.js_on_event("document_ready", CustomJS(code=SAME_STYLE_JS))
        # the first design drawn: its sweep starts
        self.doc.js_on_event("document_ready", CustomJS(args={"stamp": self.kinematic_stamp, "drawn": self.drawn},
                                                        code=DRAWN_JS))
        self.doc.js_on_event("document_ready", CustomJS(
            args={"plots": {k: f[k] for k in self.handles}, "sources": self.handles, "limits": self.limits,
                  "options": self.options, "request": self.request, "saved": self.saved, "key": self.key},
            code=PAGE_JS))
        tabs = CustomJS(args={"tabs": self.plot_tabs, "plots": [[p for p in panel.select({"type": figure})]
                                                                 for panel in self.plot_tabs.tabs]}, code=TABS_JS)
        self.doc.js_on_event("document_ready", tabs)
        self.plot_tabs.js_on_change("active", tabs)
        for model in (*self.downloaded.values(), self.kinematic_stamp, self.checks_stamp, self.sweep_stamp, self.drawn, self.kinematic_hold,
                      self.sweep_hold, self.request, self.options, self.saved):
            self.doc.add_root(model)

    def _plot(self, p, name):
        """Plot ``name`` on figure ``p``: the baseline dashed under the current design."""
        x, y = PLOTS[name]
        p.line(x, y, source=self.base_curves, color="#999999", line_dash="dashed", line_width=1.5)
        p.line(x, y, source=self.curves, color="#1f77b4", line_width=2)
        p.toolbar.logo = None
        return p

    # --- drawing ---------------------------------------------------------------------------------------------------
    def _texts(self):
        t, w = TEXT[self.lang], WORDS[self.lang]
        u = self.units
        length, angle = w[f"unit_{u.length}"], w[f"unit_{u.angle}"]
        orders = {1: "", 2: "²", 3: "³"}
        derivative = {name: (w[f"{name}_valve"] if u.derivative == "rated" else
                             f"{w[f'{name}_valve'].split(',')[0]}, {length}/{angle}{orders[order]}")
                      for name, _, order in KINEMATIC_PLOTS[1:]}
        axes = {"lift": f"{w['lift_mm'].split(',')[0]}, {length}", **derivative}
        x_axis = w[f"angle_{u.angle}"]
        for name, words in axes.items():
            self.figures[name].yaxis.axis_label = words
            self.figures[name].xaxis.axis_label = x_axis
        self.figures["contour"].title.text = t["contour"]
        self.figures["curvature"].yaxis.axis_label = f"{w['curvature']}, 1/{length}"
        self.figures["curvature"].xaxis.axis_label = x_axis
        self.figures["time_area"].xaxis.axis_label = t["crank_deg"]
        self.figures["time_area"].yaxis.axis_label = t["running_ta"]
        self.curtain_axis.axis_label = t["curtain"]
        self.figures["spring"].xaxis.axis_label = f"{w['lift_mm'].split(',')[0]}, {length}"
        self.figures["spring"].yaxis.axis_label = t["force"]
        self.figures["sweep_force"].yaxis.axis_label = w["min_force"]
        self.figures["sweep_seating"].yaxis.axis_label = w["seating"]
        self.figures["sweep_map"].title.text = w["map"]
        for key in ("sweep_force", "sweep_seating", "sweep_map"):
            self.figures[key].xaxis.axis_label = t["speed"] if key != "sweep_map" else t["cam_deg"]
        self.figures["sweep_map"].yaxis.axis_label = t["speed"]
        self.figures["at_speed"].xaxis.axis_label = t["cam_deg"]
        self.figures["at_speed"].yaxis.axis_label = w["contact_force"]
        self.acceleration_axis.axis_label = w["acceleration_valve"]
        self.speed.title = w["speed"]
        self.figures["breathing"].xaxis.axis_label = t["speed"]
        self.figures["breathing"].yaxis.axis_label = w["volumetric_efficiency"]
        self.torque_axis.axis_label = w["torque"]
        for panel, key in zip(self.plot_tabs.tabs, ("tab_derivatives", "tab_cam", "tab_flow", "tab_speed",
                                                    "tab_breathing"), strict=True):
            panel.title = w[key]
        for c, key in zip(self.check_columns, ("status", "quantity", "value", "baseline", "allowed", "margin", "source"),
                          strict=True):
            c.title = {"status": w["status"], "value": t["value"] + f" ({w['current']})", "baseline": w["baseline"],
                       "margin": w["margin"]}.get(key) or t[key]
        self.card_columns[0].title = t["cam_card"]
        self.valve_select.title = w["valve"]
        self.length_select.options = [("mm", w["unit_mm"]), ("in", w["unit_in"])]
        self.angle_select.options = [("cam", w["angle_cam"]), ("crank", w["angle_crank"])]
        self.derivative_select.options = [("rated", w["rated"]), ("deg", w["deg"])]
        for key, b in self.buttons.items():
            b.label = w[key]
        self.download.label = w["download"]
        self.download.menu = [(w[k], k) for k in ("toml", "dxf", "report")]
        self.overlay.title = w["overlay"]

    def _shown(self):
        """The document and the design drawn: a drag's preview while the pointer moves, else the good design."""
        return self.shown or (self.session.document, self.session.good)

    def _omega(self, result):
        return result["results"]["valves"][self.valve]["cam"]["camshaft_speed_rad_s"]

    def _curves(self, result) -> dict:
        """The columns of a design's curves in the units shown, NaN-padded to one length, as 32-bit floats (7 digits:
        more than a plot shows, half the bytes to send); the spring's required force thinned (:func:`thinned`), the
        contour to about as many points as the other curves (every k-th point, closed), the curvature 1/rho with its
        limit, 1/rho_min of the check of the smallest convex radius."""
        series, omega, u = result["series"][self.valve], self._omega(result), self.units
        xs, x0 = u.of(series, omega)
        out = {"x": xs * _array(series["cam_deg"]) + x0, **{key: _array(series[name]) for key, name in CURVES.items()}}
        for name, key, order in KINEMATIC_PLOTS:
            out[name] = u.of(series, omega, order)[0] * _array(series[key])
        with np.errstate(divide="ignore"):
            out["curvature"] = 1.0 / (u.mm * _array(series["rho_mm"]))
        limit = next((c["low"] for c in result["results"]["checks"] if c["code"] == "profile.rho_min"
                      and c["valve"] == self.valve and c["low"]), None)
        out["curvature_limit"] = np.full(len(out["x"]), np.nan if limit is None else 1.0 / (u.mm * limit))
        out["spring_x"], out["spring_y"] = thinned(u.mm * _array(series["spring_lift_mm"]),
                                                   _array(series["required_force_N"]))
        out["spring_line_x"] = u.mm * _array(series["spring_line_lift_mm"])
        out["spring_line_y"] = _array(series["spring_line_force_N"])
        step = -(-len(series["contour_x_mm"]) // (2 * PLOT_BUCKETS))
        for axis in ("x", "y"):
            contour = u.mm * _array(series[f"contour_{axis}_mm"])
            out[f"contour_{axis}"] = np.append(contour[::step], contour[0])
        n = max(len(v) for v in out.values())
        return {k: np.pad(v, (0, n - len(v)), constant_values=np.nan).astype(np.float32) for k, v in out.items()}

    def _ranges(self, with_base):
        """Each fixed range of the plots kept or fitted to the curves of the design and the baseline
        (:func:`kept_range`); a range changed only when it moves (a change lays its plot out again)."""
        for key, (names, room) in RANGES.items():
            _fit(self.ranges[key], [source.data[name] for source in (self.curves, self.base_curves)[:1 + with_base]
                                    for name in names], room)

    def redraw(self, sweep=True, began=None, seq=0, live=False, curves_seq=None) -> None:
        """Draw the design shown (and the baseline), its handles and, unless ``live`` (a drag's preview), its checks,
        card, panel and breathing; start its speed sweep (``sweep``) or draw the last one again.  ``began``:
        :func:`_now` when the change came (default now); ``seq`` the page's request it answers (the stamp of the
        curves and, unless ``live``, that of the checks); ``curves_seq`` the curves' stamp's instead (0: the curves
        of the request drawn before, :meth:`_release`)."""
        began = _now() if began is None else began
        _hold(self.kinematic_hold)
        try:
            if self.valve is not None:
                self._draw_valve()
            if not live:
                self._checks()
                self._card()
                self._breathing()
                self._sync_fields()
                _send(self.saved, {"document": [json.dumps(self.session.document)]})
        finally:
            _count(self.kinematic_stamp, began, seq if curves_seq is None else curves_seq)
        if live:
            return
        _count(self.checks_stamp, began, seq)
        if sweep and self.sweep_key == document_key(self.session.document):
            sweep = False                                 # its sweep started at the release (_launch)
        if sweep:
            self.sweeps = {}                              # the sweeps of the design before: drawn no more
        self.sweep_due = self.sweep_due or sweep          # a switch of language before the page drew keeps it due
        self.sweep_seq = seq if sweep else self.sweep_seq
        if self.sweeps or self.session.full is not None:
            self._sweep_panel()

    def _draw_valve(self):
        s = self.session
        document, result = self._shown()
        series = result["series"][self.valve]
        _send(self.curves, self._curves(result))
        phi = np.linspace(0.0, 2.0 * np.pi, 181)
        r = self.units.mm * series["heel_radius_mm"]
        _send(self.heel, {"x": r * np.cos(phi), "y": r * np.sin(phi)})
        base = s.baseline["series"].get(self.valve) if s.baseline else None
        if base is not None:
            _send(self.base_curves, self._curves(s.baseline))
        elif len(self.base_curves.data["x"]):
            self.base_curves.data = {k: [] for k in self.base_curves.data}
        self._ranges(base is not None)
        xs, x0 = self.units.of(series, self._omega(result))
        edges = xs * np.asarray(series["segments_cam_deg"]) + x0
        acc = self.ranges["acceleration"]
        _send(self.segments, {"x": edges, "y0": [acc.start] * len(edges), "y1": [acc.end] * len(edges)})
        ta = self.ranges["time_area"]
        self.fullness.update(x=self.ranges["crank_x"].start, y=ta.end - 0.02 * (ta.end - ta.start),
                             text=f"{TEXT[self.lang]['s_fullness']} "
                                  f"{result['results']['valves'][self.valve]['flow']['fullness']:.4g}")
        self._handles(document, result)

    def _handles(self, document, result):
        """The handles of the design shown in the units shown, with their limits (infinite: none)."""
        # the points of an inline lift table are added (a tap) and removed (selected, Delete) on the lift plot
        _send(self.options, {"add": [has_points(document["valves"][self.valve].get("cam", {}))]})
        series, omega = result["series"][self.valve], self._omega(result)
        xs, x0 = self.units.of(series, omega)
        for plot, src in self.handles.items():
            ys = self.units.of(series, omega, 0 if plot == "lift" else 2)[0]
            mine = [h for h in self.session.handles(self.valve, document, result) if h.plot == plot]
            _send(src, {"x": _array([xs * h.x + x0 for h in mine]), "y": _array([ys * h.y for h in mine]),
                        "name": [h.name for h in mine],
                        "x_lo": _array([xs * h.x_limits[0] + x0 for h in mine]),
                        "x_hi": _array([xs * h.x_limits[1] + x0 for h in mine]),
                        "y_lo": _array([ys * h.y_limits[0] for h in mine]),
                        "y_hi": _array([ys * h.y_limits[1] for h in mine])})

    def _checks(self):
        """The checks table: the whole design's checks when they have come, else the good design's and, pending, the
        ones of the last whole design that only the speed sweeps give; each row's status in words and colour."""
        s = self.session
        base = {c["quantity"]: c for c in (s.baseline or {"results": {"checks": []}})["results"]["checks"]}
        out = {k: [] for k in self.checks.data}
        for c in sorted(s.checked["checks"], key=lambda c: (c["pass"], c["accepted"],
                                                            {"failure": 0, "warning": 1}.get(c["severity"], 2),
                                                            c["margin"] if c["margin"] is not None else 1e300)):
            status = "pass" if c["pass"] else "accepted" if c["accepted"] else c["severity"]
            self._check_row(out, c, base, status)
            out["value"].append("-" if c["value"] is None else f"{c['value']:.5g} {c['unit']}".rstrip())
            out["margin"].append("" if c["margin"] is None else f"{c['margin']:+.3g}")
        for c in s.pending:
            self._check_row(out, c, base, "pending")
            out["value"].append("…")
            out["margin"].append("")
        _send(self.checks, out)

    def _check_row(self, out, c, base, status):
        """The columns of a check's row that do not wait for its value: its status, name, baseline, range and
        source."""
        out["key"].append(c["quantity"])
        out["status"].append(WORDS[self.lang][STATUS_WORDS[status]])
        out["colour"].append(SEVERITY_COLOURS[status])
        out["quantity"].append(record_quantity_text(c, self.lang))
        b = base.get(c["quantity"])
        out["baseline"].append("" if b is None or b["value"] is None else f"{b['value']:.5g}"
                               + ("" if b["pass"] else " ✗"))
        out["allowed"].append(check_range(c, self.lang))
        out["source"].append(translate(c["source"], self.lang))

    def _card(self):
        """The cam card of the good design: each valve's events at the checking heights (crank deg from the
        gas-exchange TDC), its lobe centre and lift at TDC, the lobe separation and the overlaps, and the valves'
        accelerations, smallest radius, time-area and fullness."""
        t, mm = TEXT[self.lang], self.units.mm
        results = self.session.good["results"]
        card = (results.get("cam_card") or {})
        valves = card.get("valves") or {}
        rows = {k: [] for k in self.card.data}

        def add(name, values):
            rows["quantity"].append(name)
            for n in self.names:
                v = values.get(n)
                rows[n].append("" if v is None else f"{v:.5g}")

        crank = WORDS[self.lang]["unit_crank"]
        for group, keys in EVENTS:
            for word, key in zip(("cc_opens", "cc_closes", "cc_duration"), keys, strict=True):
                add(f"{t[group]}: {t[word]}, {crank}", {n: c.get(f"{key}_crank_deg") for n, c in valves.items()})
        if valves:
            add(f"{t['cc_centre']}, {crank}", {n: c.get("lobe_centre_crank_deg") for n, c in valves.items()})
            add(t["cc_lift_tdc"].replace("mm", WORDS[self.lang][f"unit_{self.units.length}"]),
                {n: None if c.get("lift_at_tdc_mm") is None else mm * c["lift_at_tdc_mm"]
                 for n, c in valves.items()})
        w = WORDS[self.lang]
        for key, word, unit, scale in (("lobe_separation_cam_deg", "cc_separation", w["unit_cam"], 1.0),
                                       ("overlap_crank_deg", "cc_overlap", crank, 1.0),
                                       ("overlap_at_0_050in_crank_deg", "cc_overlap_050", crank, 1.0),
                                       ("overlap_area_mm_crank_deg", "cc_overlap_area",
                                        f"{w[f'unit_{self.units.length}']}·{crank}", mm)):
            if card.get(key) is not None:
                add(f"{t[word]}, {unit}", dict.fromkeys(self.names, scale * card[key]))
        for key in VALVE_CARD:
            group, leaf = key.split(".")
            add(label(key, self.lang), {n: results["valves"][n].get(group, {}).get(leaf) for n in self.names})
        _send(self.card, rows)

    def _breathing(self):
        """The breathing of the good design: the volumetric efficiency against the speed along [breathing.curve]
        (a line) and at each [[breathing.conditions]] (points), the indicated torque on the right axis where the
        engine is fired; a cam phaser's (of the valve shown, else the first valve's) best phase at each condition
        (hollow diamonds: the breathing there) and its advance in the label; without [breathing], a line that says
        so."""
        results = self.session.good["results"]
        chapter = results.get("breathing")
        phasers = results.get("phasers") or {}
        phaser = phasers.get(self.valve) or next(iter(phasers.values()), None)
        t = WORDS[self.lang]
        self.breathing_status.text = "" if chapter else t["no_breathing"]
        if chapter and phaser and phaser["best"]:
            self.breathing_status.text = t["phased"].format(valve=phaser["valve"], best=", ".join(
                t["phased_at"].format(advance=f"{b['advance_crank_deg']:.3g}", speed=f"{b['speed_rpm']:.0f}")
                for b in phaser["best"]))
        fired = bool(chapter) and chapter["mode"] == "fired"
        for key, source in self.breathing.items():
            records = (((chapter or {}).get(key) if key != "phased" else (phaser or {}).get("best")) or [])
            _send(source, {"speed": _array([r["speed_rpm"] for r in records]),
                           "ve": _array([r["volumetric_efficiency"] for r in records]),
                           "torque": _array([r.get("torque_Nm") if fired else None for r in records])})
        self.torque_axis.visible = fired
        p = self.figures["breathing"]
        for rng, name, room in ((p.x_range, "speed", PLOT_ROOM), (p.y_range, "ve", PLOT_ROOM),
                                (p.extra_y_ranges["torque"], "torque", PLOT_ROOM)):
            _fit(rng, [source.data[name] for source in self.breathing.values()], room)

    def _sync_fields(self):
        """The panel's inputs show the good design's values (those an edit refused, a drag or an undo changed); the
        cam's group of a valve whose law changed is built again (its keys are the law's)."""
        document = self.session.document
        for valve in self.names:
            if value_at(document, f"valves.{valve}.cam.law") != self.laws[valve]:
                self.laws[valve] = value_at(document, f"valves.{valve}.cam.law")
                for path in [p for p in self.widgets if p.startswith(f"valves.{valve}.cam.")]:
                    del self.widgets[path], self.fields[path]
                self.group_columns[("cam", valve)].children = [self._widget(f) for f in dict(form(document,
                                                                                                  valve))["cam"]]
        self._syncing = True
        try:
            for path, w in self.widgets.items():
                value = value_of(document, self.fields[path])
                shown = (value if isinstance(w, NumericInput) else "" if value is None
                         else str(value) if isinstance(w, Select) else value_text(value))
                if w.value != shown:
                    w.value = shown
        finally:
            self._syncing = False

    def show_problems(self, kind="field") -> None:
        """The problems of the last edit refused in the status line, each with the value tried and the value the
        design drawn keeps, its input marked; nothing when it designed."""
        s, w = self.session, WORDS[self.lang]
        marked = {p for p in s.refused if p in self.widgets}
        for path in self.refused_paths | marked:
            self.widgets[path].css_classes = ["vt-refused"] if path in marked else []
        self.refused_paths = marked
        lines = []
        for p in s.problems:
            message = translate(p["message"] if p["path"] in s.refused else p["text"], self.lang)
            if kind == "field" and p["path"] in self.fields:
                f = self.fields[p["path"]]
                lines.append(w["refused"].format(what=label(f.name, self.lang),
                                                 value=_shown(s.refused.get(p["path"], p["value"])),
                                                 message=message, kept=_shown(f.value)))
            else:
                lines.append(w["refused_point" if kind == "point" else "refused_drag" if kind == "drag"
                               else "refused_edit"].format(message=translate(p["text"], self.lang)))
        self.status.text = "<br>".join(lines) or ("" if self.names else w["no_valves"])

    # --- the speed sweep -------------------------------------------------------------------------------------------
    def on_drawn(self, attr, old, new) -> None:
        """The page has drawn the kinematics of redraw ``new["n"]``: the sweep of the newest one starts (its thread
        would have held up the sending of the kinematics, and the page's drawing of them)."""
        if self.sweep_due and new["n"][0] == self.kinematic_stamp.data["n"][0]:
            self.sweep_due = False
            self.start_sweep()

    def start_sweep(self, document=None, job=None) -> None:
        """In the worker thread: the speed sweep of the valve shown alone, drawn as soon as it comes
        (:meth:`~valvetrain.web.session.Session.sweep_one`: a fraction of the whole design's time), then the whole
        design of the good document with every valve's sweep (:meth:`~valvetrain.web.session.Session.settle`; the
        valve shown is not swept again: the first's design is kept for it), its checks to the table; a newer change
        stops both at their next speed.  ``document``: a drag's released (default the good one), whose design
        ``job`` (a future of :meth:`~valvetrain.web.session.Session.design`) the whole design waits for: nothing
        more of it is swept when it does not design."""
        self.generation += 1
        generation, seq, valve = self.generation, self.sweep_seq, self.valve
        self.sweep_status.text = WORDS[self.lang]["sweeping"]
        document = self.session.document if document is None else document
        self.sweep_key = document_key(document)

        def progress(name, done, total):
            if generation != self.generation:
                raise Stale

        def work():
            began, memo = _now(), {}
            try:
                first = self.session.sweep_one(document, valve, progress=progress, memo=memo)
                if first is not None:
                    self.doc.add_next_tick_callback(partial(self.draw_sweep_of, generation, valve, first, began, seq))
                if job is not None and not job.result()["ok"]:
                    return
                result = self.session.settle(document, progress=progress, memo=memo)
            except Stale:
                return
            self.doc.add_next_tick_callback(partial(self.draw_sweep, generation, result, began,
                                                    0 if first is not None else seq))

        SWEEP_WORKERS.submit(work)

    def _sweep_curves(self, sw, sources):
        _send(sources["force"], {"x": _array(sw["speed_rpm"]), "y": _array(sw["min_contact_force_N"])})
        _send(sources["seating"], {"x": _array(sw["speed_rpm"]),
                                   "y": np.abs(_array(sw["seating_velocity_m_s"]))})

    def draw_sweep_of(self, generation, valve, sweep, began, seq=0) -> None:
        """Draw the sweep of one valve (:meth:`start_sweep`'s first answer) if it is the newest redraw's; ``began``
        as for :meth:`redraw`, when the worker took it up; ``seq`` the page's request of the design."""
        if generation != self.generation:
            return
        self.sweeps[valve] = sweep
        _hold(self.sweep_hold)
        try:
            self._sweep_panel()
        finally:
            _count(self.sweep_stamp, began, seq)

    def draw_sweep(self, generation, result, began, seq=0) -> None:
        """Keep the whole design of redraw ``generation`` if it is the newest: its checks to the table, its sweeps
        to the sweep panel; ``began`` as for :meth:`redraw`, when the worker took it up; ``seq`` the page's request
        of the design (0: its panel drawn already, from the valve's own sweep)."""
        if generation != self.generation:
            return
        self.finish_edit()                                # the document swept is the good one (its design came)
        if generation != self.generation:
            return
        self.session.settled(result)
        self.sweeps = dict(result.get("sweeps") or {}) if result["ok"] else {}
        if seq:
            _hold(self.sweep_hold)
        try:
            if result["ok"] and result["results"] is not None:
                self._checks()
            self._sweep_panel()
        finally:
            _count(self.sweep_stamp, began, seq)

    def _sweep_panel(self):
        """The sweep panel of the valve shown; without its sweep, its label says that the whole design is to come,
        the problems of the whole design when it did not design, or a dash (the whole design swept no such valve)."""
        sw = self.sweeps.get(self.valve)
        if sw is None:
            full = self.session.full
            self.sweep_status.text = (WORDS[self.lang]["sweeping"] if full is None
                                      else "; ".join(p["text"] for p in full["errors"]) or "-")
            return
        self._sweep_curves(sw, self.sweep_sources)
        base = (self.base_sweeps or {}).get(self.valve)
        if base is not None:
            self._sweep_curves(base, self.base_sweep_sources)
        for key in ("force", "seating"):
            p = self.figures["sweep_" + key]
            for rng, column_name, room in ((p.x_range, "x", 0.0), (p.y_range, "y", PLOT_ROOM)):
                _fit(rng, [s[key].data[column_name] for s in (self.sweep_sources, self.base_sweep_sources)], room)
        marks = [v for v in (sw["jump_speed_rpm"], sw["bounce_speed_rpm"]) if v is not None]
        for key, values in (("force", sw["min_contact_force_N"]), ("seating", sw["seating_velocity_m_s"])):
            found = np.abs(_array(values))
            found = found[np.isfinite(found)]
            low, high = (float(found.min()), float(found.max())) if found.size else (0.0, 1.0)
            _send(self.sweep_marks[key], {"x": _array(marks), "y0": _array([low] * len(marks)),
                                          "y1": _array([high] * len(marks))})
        err = _array_2d(sw["map_lift_error_mm"]) * self.units.mm
        bound = float(np.nanmax(np.abs(err))) if np.isfinite(err).any() else 1.0
        self.mapper.update(low=-(bound or 1.0), high=bound or 1.0)
        x, n = sw["map_cam_deg"], sw["speed_rpm"]
        _send(self.map_source, {"image": [err], "x": [x[0]], "y": [n[0]], "dw": [x[-1] - x[0]], "dh": [n[-1] - n[0]]})
        p = self.figures["sweep_map"]
        _fit(p.x_range, [[x[0], x[-1]]], 0.0)
        _fit(p.y_range, [[n[0], n[-1]]], 0.0)
        speeds = sw["speed_rpm"]
        step = (speeds[-1] - speeds[0]) / max(1, len(speeds) - 1)
        value = self.speed.value if self.speed.visible and speeds[0] <= self.speed.value <= speeds[-1] \
            else sw["rated_speed_rpm"]
        self.speed.update(start=speeds[0], end=speeds[-1], step=step or 1.0, visible=True,
                          value=float(speeds[int(np.argmin(np.abs(np.asarray(speeds) - value)))]))
        self._at_speed(sw)
        t = WORDS[self.lang]
        self.sweep_status.text = ", ".join(f"{t[k]} {v:.5g} rpm" for k, v in (("jump", sw["jump_speed_rpm"]),
                                                                               ("bounce", sw["bounce_speed_rpm"]))
                                           if v is not None) or "-"

    def _at_speed(self, sw):
        """The dynamics against the camshaft angle at the speed chosen (the slider, a speed of the sweep): the cam
        contact force, the valve's acceleration of the elastic train and the rigid one (the kinematic acceleration at
        the rated speed scaled by the square of the speed ratio)."""
        i = int(np.argmin(np.abs(np.asarray(sw["speed_rpm"]) - self.speed.value)))
        series = self.session.good["series"][self.valve]
        x = _array(sw["map_cam_deg"])
        rated = self.session.good["results"]["engine"]["rated_speed_rpm"]
        rigid = np.interp(x, series["cam_deg"], _array(series["valve_acceleration_m_s2"])) \
            * (sw["speed_rpm"][i] / rated) ** 2
        force, acceleration = (_array_2d(sw[k])[i] for k in ("map_contact_force_N", "map_valve_acceleration_m_s2"))
        _send(self.at_speed, {"x": x, "force": force, "acceleration": acceleration, "rigid": rigid})
        p = self.figures["at_speed"]
        _fit(p.x_range, [x], 0.0)
        _fit(p.y_range, [force], PLOT_ROOM)
        _fit(p.extra_y_ranges["acceleration"], [acceleration, rigid], PLOT_ROOM)
        p.title.text = WORDS[self.lang]["at_speed"].format(speed=f"{sw['speed_rpm'][i]:.0f}")

    # --- callbacks -------------------------------------------------------------------------------------------------
    def on_field(self, f, attr, old, new) -> None:
        began = _now()
        if self._syncing:
            return
        self.finish_edit()
        try:
            value = parse_value(f, new)
        except ValueError as exc:
            self.session.problems = [{"path": f.path, "value": new, "message": str(exc), "text": str(exc)}]
            self.session.refused = {f.path: new}
            self._answer(False, began, "field")
            return
        self._answer(self.session.edit({f.path: value}), began, "field")

    def _answer(self, designed, began, kind, seq=0, curves_seq=None):
        """After an edit (``designed`` or refused): the good design drawn (the panel shows it: a refused value's
        input goes back to the good design's, its message says why) and its sweep started; ``curves_seq`` as for
        :meth:`redraw`."""
        self.shown = None
        self.redraw(sweep=designed, began=began, seq=seq, curves_seq=curves_seq)
        self.show_problems(kind)

    def _release(self, values, began, seq):
        """A handle released or nudged (the keys it sets): its valve's kinematics drawn at once
        (:meth:`~valvetrain.web.session.Session.preview`, the page's probe times them), its design in the worker
        thread, kept when it comes (:meth:`finish_edit`); a sketch that does not design is answered as an edit."""
        try:
            document, sketch = self.session.preview(values, self.valve)
        except ValueError:
            sketch = {"ok": False}
        if not sketch["ok"]:
            self._answer(self.session.edit(values), began, "drag", seq)
            return
        self.generation += 1                              # the sweep of the design before: stale, stopped
        self.shown = (document, sketch)
        self.redraw(began=began, seq=seq, live=True)
        self.pending = [None, values, seq, document]
        # after this answer has gone: the two threads would hold up its sending
        self.doc.add_next_tick_callback(partial(self._launch, self.pending))

    def _launch(self, pending) -> None:
        """The design of a drag released (:meth:`_release`) in its worker thread and, beside it, the sweep of the
        valve shown (:meth:`start_sweep`: its document's sweep does not wait for its design; the whole design's
        sweeps do), unless an edit kept it before."""
        if self.pending is not pending:
            return
        document = pending[3]
        self.sweeps = {}                                  # the sweeps of the design before: drawn no more
        job = pending[0] = DESIGN_WORKERS.submit(self.session.design, document)
        job.add_done_callback(lambda _: self.doc.add_next_tick_callback(partial(self._designed, job)))
        self.sweep_seq = pending[2]
        self.start_sweep(document, job)

    def _designed(self, job) -> None:
        """The design of a drag released has come (:meth:`_launch`): kept, unless an edit kept it before."""
        if self.pending is not None and self.pending[0] is job:
            self.finish_edit()

    def finish_edit(self) -> None:
        """Keep the design of the drag released last (waited for when it has not come: every other edit applies to
        it): the good design, drawn with its checks, card, panel and breathing, its sweep started; or, refused, the
        good design before it drawn again with the reason.  Nothing when no drag's design is pending."""
        if self.pending is None:
            return
        job, values, seq, document = self.pending
        self.pending = None
        if job is not None:
            job.result()                                  # kept by the session: the edit below designs nothing
        designed = self.session.edit(values)
        if not designed and self.sweep_key == document_key(document):
            self.sweep_key = None                         # the refused design's sweep: the good design's again
            designed = True
        self._answer(designed, _now(), "drag", seq, curves_seq=0)

    def on_request(self, attr, old, new) -> None:
        """A request of the page (page.js): a handle moved (``move``: designed and drawn, not kept), released
        (``end``) or nudged (``key``), a table's point added (``add``) or removed (``remove``), ``undo``, ``redo``,
        or the document the page kept across a reload (``restore``)."""
        began = _now()
        if not new.get("kind"):
            return
        kind, seq, plot, name, x, y, text = (new[k][0] for k in ("kind", "seq", "plot", "name", "x", "y", "text"))
        self.finish_edit()
        if kind in ("undo", "redo"):
            done = self.session.undo() if kind == "undo" else self.session.redo()
            self._answer(done, began, "field", seq)
            return
        if kind == "restore":
            self._restore(text, began, seq)
            return
        if self.valve is None:
            return
        if kind in ("add", "remove"):
            self._points(kind, name, x, y, began, seq)
            return
        x, y = self._to_session(plot, x, y)
        try:
            values = self.session.moved(self.valve, name, x, y)
        except ValueError:      # a handle the valve no longer has (the page drawn before its law changed)
            self.shown = None
            self.redraw(sweep=False, began=began, seq=seq)
            return
        if kind == "move":
            try:
                document, result = self.session.preview(values, self.valve)
            except ValueError:
                return
            if result["ok"]:
                self.shown = (document, result)
                self.redraw(began=began, seq=seq, live=True)
            else:
                _count(self.kinematic_stamp, began, seq)
            return
        self._release(values, began, seq)

    def _to_session(self, plot, x, y):
        """A point of a handle's plot in the session's units (cam deg from the nose; mm or m/s²)."""
        result = self.session.good
        series, omega = result["series"][self.valve], self._omega(result)
        xs, x0 = self.units.of(series, omega)
        ys = self.units.of(series, omega, 0 if plot == "lift" else 2)[0]
        return (x - x0) / xs, y / ys

    def _points(self, kind, name, x, y, began, seq):
        """A point added to an inline lift table at (x, y) of the lift plot, or point ``name`` removed."""
        handles = [h for h in self.session.handles(self.valve) if h.plot == "lift"]
        xs, ys = [h.x for h in handles], [h.y for h in handles]
        if kind == "add":
            x, y = self._to_session("lift", x, y)
            xs, ys = [*xs, x], [*ys, y]
        else:
            keep = [h.name != name for h in handles]
            xs, ys = [v for v, k in zip(xs, keep, strict=True) if k], [v for v, k in zip(ys, keep, strict=True) if k]
        self._answer(self.session.edit(self.session.points(self.valve, xs, ys)), began, "point", seq)

    def _restore(self, text, began, seq):
        """The document the page kept across a reload designed again (an edit that can be undone), or the
        file's design kept with a message."""
        try:
            document = json.loads(text)
        except ValueError:
            return
        if not isinstance(document, dict):
            return
        designed = self.session.restore(document)
        self._answer(designed, began, "field", seq)
        w = WORDS[self.lang]
        self.status.text = (w["restored"] if designed else
                            w["restore_refused"].format(message="; ".join(p["text"] for p in self.session.problems)))

    def on_undo(self) -> None:
        began = _now()
        self.finish_edit()
        self._answer(self.session.undo(), began, "field")

    def on_redo(self) -> None:
        began = _now()
        self.finish_edit()
        self._answer(self.session.redo(), began, "field")

    def on_language(self, attr, old, new) -> None:
        self.lang = new
        self.panel_box.children = [self.status, self._panel()]
        self._texts()
        self.redraw(sweep=False)
        self.show_problems()

    def on_units(self, attr, old, new) -> None:
        self.units = Units(self.length_select.value, self.angle_select.value, self.derivative_select.value)
        self._texts()
        self.redraw(sweep=False)

    def on_valve(self, attr, old, new) -> None:
        self.finish_edit()
        self.valve = new
        for (group, valve), box in self.group_columns.items():
            box.visible = valve in (None, new)
        self.redraw(sweep=False)

    def on_speed(self, attr, old, new) -> None:
        if self.sweeps.get(self.valve) is not None:
            self._at_speed(self.sweeps[self.valve])

    def on_overlay(self, attr, old, new) -> None:
        """A specification file overlaid: designed and pinned as the baseline that the plots and the checks
        compare with (its message in the status line when it does not design)."""
        try:
            name = self.overlay.filename            # the page may send the file's name after its content
        except UnsetValueError:
            name = "overlay.toml"
        try:
            document = tomllib.loads(base64.b64decode(new).decode("utf-8"))
        except (ValueError, UnicodeDecodeError) as exc:
            self.status.text = WORDS[self.lang]["overlay_refused"].format(name=name, message=exc)
            return
        self.finish_edit()
        if "source_dir" in self.session.document:
            document["source_dir"] = self.session.document["source_dir"]
        result = self.session.design(document)
        if not result["ok"]:
            self.status.text = WORDS[self.lang]["overlay_refused"].format(
                name=name, message="; ".join(p["text"] for p in result["errors"]))
            return
        self.session.baseline = result
        self.base_sweeps = None
        self.status.text = ""
        self.redraw(sweep=False)

    def on_download(self, event) -> None:
        self.finish_edit()
        {"toml": self.on_toml, "dxf": self.on_dxf, "report": self.on_report}[event.item]()

    def on_report(self) -> None:
        """The report of the good design, to the page, which saves it (a comment makes every one a change)."""
        self.downloads += 1
        self.downloaded["report"].text = self.session.report(self.lang) + f"<!-- download {self.downloads} -->\n"

    def on_toml(self) -> None:
        """The specification of the good design, to the page, which saves it (a comment makes every one a change)."""
        self.downloads += 1
        self.downloaded["toml"].text = self.session.toml() + f"# download {self.downloads}\n"

    def on_dxf(self) -> None:
        """The contour of the valve shown as DXF (``valvetrain run``'s), to the page, which saves it."""
        if self.valve is None:
            return
        self.downloads += 1
        data = self.session.dxf(self.valve)
        # a DXF comment (group code 999) makes every download a change
        self.downloaded["dxf"].text = base64.b64encode(data + f"999\ndownload {self.downloads}\n".encode()).decode()

    def on_pin(self) -> None:
        self.finish_edit()
        self.session.pin()
        self.base_sweeps = dict(self.sweeps)
        self.redraw(sweep=False)


def _shown(value) -> str:
    """A value in a message: a number as ``%g``, anything else as its input shows it."""
    return f"{value:g}" if isinstance(value, (int, float)) and not isinstance(value, bool) else value_text(value)


def _fit(rng, columns, room):
    """A fixed range kept or fitted to the finite values of ``columns`` (:func:`kept_range`), changed only when it
    moves."""
    values = np.concatenate([np.asarray(c, dtype=float) for c in columns]) if columns else np.array([])
    values = values[np.isfinite(values)]
    if values.size:
        start, end = kept_range(rng.start, rng.end, float(values.min()), float(values.max()), room)
        if (start, end) != (rng.start, rng.end):
            rng.update(start=start, end=end)


def _array_2d(values):
    """A map (a list of rows, None a gap) as a 2-D float array."""
    return np.array([[np.nan if v is None else v for v in r] for r in values], dtype=float)


def page_key(text) -> str:
    """The key under which the page keeps the edits of a file's design across a reload: the file's text hashed."""
    return "valvetrain:" + hashlib.sha256((text or "").encode("utf-8")).hexdigest()[:16]
