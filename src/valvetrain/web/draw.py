"""The pieces the designer's page is drawn with: its words, the plots' columns and fixed ranges, the page's styles
and scripts (with ``page.js``), the units shown, and the helpers that send a source's data to the page (only when it
changed), thin a curve to what a plot shows, and stamp a redraw with the server's times.
"""

from dataclasses import dataclass
from pathlib import Path
import time

from bokeh.models import ColumnDataSource, CustomJS
import numpy as np

from ..languages import LANGS
from ..locale import NoteText, catalogue, note_text
from ..report.names import translate
from ..specification.messages import Problem
from ..units import per_cam_degree

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

PAINTED_JS = """
const PlotView = Bokeh.require("models/plots/plot_canvas").PlotView;
const paint = PlotView.prototype._actual_paint;
if (!paint.vtMarked) {
  PlotView.prototype._actual_paint = function () {
    paint.call(this);
    this.vtPainted = performance.now();
  };
  PlotView.prototype._actual_paint.vtMarked = true;
}
"""
"""Run once when the page is ready: each plot's view marks when it last painted (``vtPainted``, for the probe,
:data:`STAMP_JS`)."""

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

STAMP_JS = VIEW_JS + """
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
// the plots this stamp resumes, when the redraw changed them: the frame that shows it is the one they were painted in
const changed = data.changed === undefined || data.changed[0] !== 0;
const views = changed ? plots.map(view).filter((v) => v != null) : [];
const record = (t, frames) => {
  for (const k of [key, key + 'Arrived', key + 'Server', key + 'Frames', 'vtMoveTimes']) {
    window[k] = window[k] || [];
  }
  if (window.vtRelease !== undefined && vt.release && seq === vt.release) {
    window[key].push(t - window.vtRelease);
    window[key + 'Arrived'].push(arrived - window.vtRelease);
    window[key + 'Frames'].push(frames);
    const release = performance.timeOrigin + window.vtRelease;
    window[key + 'Server'].push([data.began[0] - release, data.ended[0] - data.began[0],
                                 performance.timeOrigin + arrived - data.ended[0], data.cpu[0]]);
  } else if (sent !== undefined && seq !== vt.release) {
    window.vtMoveTimes.push(t - sent);
  }
  window[key + 'Done'] = (window[key + 'Done'] || 0) + 1;
};
let frames = 0;
const frame_end = () => requestAnimationFrame(() => {
  // a task posted from a frame's animation callbacks runs when the frame's own work (its paint) is done
  const channel = new MessageChannel();
  channel.port1.onmessage = () => {
    frames += 1;
    if (frames < 10 && views.length && !views.some((v) => v.vtPainted > arrived)) {
      frame_end();            // Bokeh put the paint off (at most one a frame): the next frame
    } else {
      record(performance.now(), frames);
    }
  };
  channel.port2.postMessage(null);
});
frame_end();
"""
"""The page's probe: on the change of a stamp (the last change of a redraw), the time from the release that asked for
it to the end of the frame that shows it: the first frame after it came whose animation callbacks (where Bokeh
paints) painted one of the ``plots`` the stamp resumes, if the redraw changed them (:data:`PAINTED_JS` marks a
plot's paint), else the first frame after it came; its end is when the page's main thread has done the frame's
work (a task posted from the frame's animation callback), the compositor's drawing of it after.  (The probe waited
for the second animation frame after the update, a frame later than the one that shows it: up to 17 ms more.)"""

PAUSE_JS = VIEW_JS + """
if (!window[key]) {
  window[key] = plots.map(view).filter((v) => v != null);
  window[key].forEach((v) => v.pause());
}
"""

UNPAUSE_JS = """
const views = window[key] || [];
window[key] = null;
const data = cb_obj.data instanceof Map ? Object.fromEntries(cb_obj.data) : cb_obj.data;
const changed = data.changed === undefined || data.changed[0] !== 0;
views.forEach((v) => v.unpause(!changed));
"""
"""Resume the plots a :func:`_held` source paused, painted again only when the redraw changed something (the
stamp's ``changed``, :func:`_count`): a release where the pointer last moved changes nothing the last move's answer
did not draw, and painting the plots again was most of the page's work of it."""

AXIS_NUMBERS_JS = """
return tick.toLocaleString(locale, {maximumFractionDigits: 4, useGrouping: false});
"""
"""An axis tick in the number format of the page's language (``[designer] numbers``, a BCP 47 locale): the decimal
comma of the Russian page, as the report's figures have (:mod:`valvetrain.report.figure`)."""

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

def kept_range(start, end, low, high, room, dragged=False) -> tuple[float, float]:
    """The range [start, end] of a plot after a redraw whose curves span [low, high]: kept while the curves lie
    inside it with at least half the ``room`` (a fraction of their span) on either side and it is less than twice
    as wide as they want, else their span with the whole room on either side.  While a handle is ``dragged`` (the
    redraws of the moves before the release) it is kept as long as the curves lie inside it at all: a range refitted
    under the pointer would take the handle away from it (the handle stays at its value, its pixel moves).

    Notes
    -----
    A plot whose range follows its data (a data range) lays itself out again on every redraw, its tick labels
    measured anew (about half the page's drawing time of a redraw); a range kept across small changes leaves the
    ticks and the layout as they were.
    """
    span = high - low or abs(high) or 1.0
    pad = room * span
    if dragged and start <= low and end >= high:
        return start, end
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


def problem_text(p, lang) -> str:
    """A problem's line (an :func:`~valvetrain.api.error_records` record) in ``lang``: its key and the value given as
    the line has them, its message in the language where the message is a note (:class:`~valvetrain.locale.NoteText`:
    a range refused, a key that needs another), else as :func:`~valvetrain.report.names.translate` says the line."""
    if lang == "en" or not isinstance(p["message"], NoteText):
        return translate(p["text"], lang)
    return note_text(Problem(p["path"], p["message"], p["value"], text=p["text"]).note(), lang, "")


def _now():
    """The server's clocks when a change comes: ``time.time()`` and the process's processor time [s]."""
    return time.time(), time.process_time()


def _count(stamp, began, seq=0, changed=True):
    """One more redraw on a stamp's source (its change in the page stamps the time), with the server's times
    ``began`` (:func:`_now` when the change came) and now, as ms since the epoch: the page, on the same clock,
    parts its wait into the way up, the server and the way down; the processor time the server's process spent
    in between [ms] (what the server costs on a loaded machine); ``seq`` the page's request it answers;
    ``changed`` whether the redraw changed anything of the plots its stamp holds (:data:`UNPAUSE_JS`)."""
    stamp.data = {"n": [stamp.data["n"][0] + 1], "began": [1e3 * began[0]], "ended": [1e3 * time.time()],
                  "cpu": [1e3 * (time.process_time() - began[1])], "seq": [seq], "changed": [int(changed)]}


def _stamp(name):
    return ColumnDataSource({"n": [0], "began": [0.0], "ended": [0.0], "cpu": [0.0], "seq": [0], "changed": [1]},
                            name=name)


def _fit(rng, columns, room, dragged=False):
    """A fixed range kept or fitted to the finite values of ``columns`` (:func:`kept_range`, ``dragged`` its rule
    while a handle is dragged), changed only when it moves."""
    values = np.concatenate([np.asarray(c, dtype=float) for c in columns]) if columns else np.array([])
    values = values[np.isfinite(values)]
    if values.size:
        start, end = kept_range(rng.start, rng.end, float(values.min()), float(values.max()), room, dragged)
        if (start, end) != (rng.start, rng.end):
            rng.update(start=start, end=end)


def _array_2d(values):
    """A map (a list of rows, None a gap) as a 2-D float array."""
    return np.array([[np.nan if v is None else v for v in r] for r in values], dtype=float)
