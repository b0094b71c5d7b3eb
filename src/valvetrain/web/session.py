"""One browser tab of the designer: the specification being edited, the last good design and the baseline.

Pure Python on :mod:`valvetrain.api` (no Bokeh here), so that every callback of the page is tested without a
browser: an edit of a field, a drag of a handle, the pinning of a baseline, the TOML to download.  Nothing is
written to disk.
"""

from collections import OrderedDict
import copy
from dataclasses import dataclass, field
import json
from typing import Any

import numpy as np

from .. import api
from ..errors import InputError
from ..specification import REGISTRY, SpecError, example_text, set_keys, toml_tables
from ..laws import PolydyneLaw
from ..specification.cam_base import main_half_angle_deg
from ..specification.cams import Ratio
from ..specification.models import Spec, Valve
from ..units import MM
from .form import field_of, without_nones

HANDLE_STEP = {"deg": 0.01, "mm": 0.001}
"""A dragged handle is rounded to these steps [cam deg, mm]: a saved specification reads like a typed one."""

MIN_SEGMENT_DEG = 0.1
"""The shortest segment a drag leaves (the specification's own least segment angle, cam deg)."""


@dataclass(frozen=True)
class Handle:
    """A point on a plot that the user drags: its plot (``"lift"`` or ``"acceleration"``), where it is and the
    ranges it is dragged in (``x_limits`` [cam deg from the nose], ``y_limits`` [mm] on the lift plot, [m/s²] on the
    acceleration plot; a range of one value holds that coordinate: the handle moves along the other only)."""

    name: str
    plot: str
    x: float
    y: float
    x_limits: tuple = (-np.inf, np.inf)
    y_limits: tuple = (-np.inf, np.inf)


def _interp(series, key, x):
    return float(np.interp(x, series["cam_deg"], series[key]))


def _ordered(a, b):
    return (min(a, b), max(a, b))


def handles(document, spec, name, series) -> list[Handle]:
    """The handles of valve ``name``: the nose lift (on the lift plot, at the nose) and, on the acceleration plot,
    the points of its law's shape on the opening flank (the closing flank of a symmetric cam follows by the law),
    each with the ranges it is dragged in (:class:`Handle`), which keep every segment at least
    :data:`MIN_SEGMENT_DEG` and every key within its range:

    - a cam of segment angles (``phi1_deg``, ``phi2_deg``: Kurz, constant acceleration): the two boundaries between
      its segments, ``phi1`` and ``phi2`` (of a Kurz cam ``phi2``'s height sets the shape factor; the peak of the
      positive acceleration, in the middle of phi1, moves with ``phi1``: a handle of its own would move the
      boundary twice as far as the pointer);
    - a polydyne cam: its positive peak (``peak``, where the exponents put it: :func:`polydyne_peak`);
    - a power-polynomial cam: the start of the ramp (``ramp``), the positive peak (``peak``, where
      ``peak_position`` puts it and as high as ``peak_acceleration_mm_per_rad2`` makes it), the end of the positive
      part (``phi1``) and the negative peak (``trough``, ``trough_position``);
    - a combined cam: the end of each segment but the last (``end.K``, segment K counted from 1), whose height sets
      a ratio that names that segment.

    A lift table given by its points inline (:func:`has_points`) has a handle on the lift plot at each point
    (``point.K``, K counted from 0, kept between its neighbours) and one on the acceleration plot at each point off
    the base circle but the first and the last (``acceleration.K``, :func:`acceleration_step`, moved up and down),
    and no other; a table in a file has none (its points are the file's).
    """
    valve = document["valves"][name]
    cam = valve.get("cam", {})
    if has_points(cam):
        x, lifts = TablePoints(cam, series).plot_x(cam["table_angles_deg"]), cam["table_lifts_mm"]
        step = HANDLE_STEP["deg"] * TablePoints(cam, series).scale
        bounds = np.concatenate([[-np.inf], x[:-1] + step]), np.concatenate([x[1:] - step, [np.inf]])
        return ([Handle(f"point.{k}", "lift", float(xk), float(yk), (float(bounds[0][k]), float(bounds[1][k])),
                        (0.0, np.inf))
                 for k, (xk, yk) in enumerate(zip(x, lifts, strict=True))]
                + [Handle(f"acceleration.{k}", "acceleration", float(x[k]),
                          _interp(series, "valve_acceleration_m_s2", x[k]), (float(x[k]), float(x[k])))
                   for k in range(1, len(x) - 1) if lifts[k] > 0.0])
    v = spec.valves[name]
    if not v.cam.needs_timing:
        return []   # a measured table from its file: its own lift and timing, nothing to drag
    out = []
    if valve.get("max_lift_mm") is not None:
        low, high = _key_range(Valve, "max_lift_mm")
        out.append(Handle("nose", "lift", 0.0, _interp(series, "valve_lift_mm", 0.0), (0.0, 0.0), (low, high)))
    half = main_half_angle_deg(v, spec.engine.strokes)
    for key, x, x_limits, y_limits in _shape_points(cam, half, series):
        y = _interp(series, "valve_acceleration_m_s2", x)
        out.append(Handle(key, "acceleration", x, y, x_limits, (y, y) if y_limits is None else y_limits))
    return out


def _key_range(model, key):
    """The bounds of a bounded key of a specification model (its :class:`Range`): ``(low, high)``."""
    f = field_of(key, model.model_fields[key], None)
    return f.low, f.high


def has_points(cam) -> bool:
    """Whether a cam section is a lift table given by its points inline (``table_angles_deg``,
    ``table_lifts_mm``): the designer's control points, dragged, added and removed on the lift plot."""
    return cam.get("law") == "table" and cam.get("table_angles_deg") is not None


@dataclass(frozen=True)
class TablePoints:
    """The map between an inline lift table's angles and the lift plot's camshaft angle from the nose: the table's
    angles in its frame (``table_angle`` crank or cam deg from ``table_zero``) are moved into the engine's cam frame
    as the table law does it (:func:`valvetrain.laws.measured.lobe_table`: crank deg halved, the firing TDC 360
    crank deg after the gas-exchange TDC, whole turns so that the highest point lies within (-180, 180] cam deg),
    then measured from the nose, which the design's series give (crank deg = nose + 2 x cam deg)."""

    scale: float          # cam deg per table deg
    offset: float         # plot cam deg at table angle 0

    def __init__(self, cam, series):
        revolution = 720.0 if cam["table_angle"] == "crank" else 360.0
        scale = 360.0 / revolution
        start = 0.5 * revolution if cam.get("table_zero", "gas_exchange_tdc") == "firing_tdc" else 0.0
        top = cam["table_angles_deg"][int(np.argmax(cam["table_lifts_mm"]))]
        turns = np.ceil(((top + start) * scale - 180.0) / 360.0)
        nose = 0.5 * (series["crank_deg"][0] - 2.0 * series["cam_deg"][0])
        object.__setattr__(self, "scale", scale)
        object.__setattr__(self, "offset", start * scale - 360.0 * turns - nose)

    def plot_x(self, angles) -> np.ndarray:
        """The lift plot's abscissae [cam deg from the nose] of table angles [table deg]."""
        return self.scale * np.asarray(angles, dtype=float) + self.offset

    def angles(self, x) -> np.ndarray:
        """The table angles [table deg] of plot abscissae [cam deg from the nose], rounded to
        :data:`HANDLE_STEP`."""
        return np.round((np.asarray(x, dtype=float) - self.offset) / self.scale, 2)


def _points_moved(at, cam, series, x, y):
    """``{dotted key: value}`` of an inline table whose points are put at plot abscissae ``x`` [cam deg from the
    nose] and lifts ``y`` [mm]: sorted by angle, two points closer than :data:`HANDLE_STEP` made one, no lift below
    zero (the base circle), to :data:`HANDLE_STEP`."""
    angles = TablePoints(cam, series).angles(x)
    lifts = np.round(np.maximum(np.asarray(y, dtype=float), 0.0), 3)
    order = np.argsort(angles, kind="stable")
    angles, lifts = angles[order], lifts[order]
    keep = np.concatenate([[True], np.diff(angles) > 0.0])
    return {f"{at}.cam.table_angles_deg": [float(a) for a in angles[keep]],
            f"{at}.cam.table_lifts_mm": [float(h) for h in lifts[keep]]}


def acceleration_step(x, k, change, omega, ratio=1.0) -> float:
    """The change of the lift [mm] of point ``k`` of a lift table that changes the table's acceleration at it by
    ``change``, its neighbours kept.

    Parameters
    ----------
    x : array_like
        The table's points as camshaft angles [cam deg] (from the nose: only their steps count).
    k : int
        The point, neither the first nor the last.
    change : float
        The change of the valve's acceleration at the point [m/s²] at the camshaft speed ``omega`` [rad/s].
    ratio : float
        Valve lift per table lift: 1 for a table of valve lift, the rocker ratio for one of tappet lift.

    Notes
    -----
    The valve's acceleration is a = i omega² h'' (h'' = d²h/dθ² of the table's lift h [m] against the camshaft
    angle θ [rad], i = ``ratio``).  A table's h'' at a point is twice the second divided difference of the point and
    its neighbours (the parabola through the three), h''_k = 2 ((h_{k+1} - h_k)/d2 - (h_k - h_{k-1})/d1) / (d1 + d2),
    d1 and d2 the angle steps before and after it; its derivative in h_k is -2 / (d1 d2), so the step of the lift
    is Δh_k = -Δh'' d1 d2 / 2 with Δh'' = change / (i omega²).  The neighbours' h'' answer by (d1 + d2)-weighted
    shares of the opposite sign, the table's ends stay where they were, and the law closes the lobe and keeps the
    lift's continuity as for any table (its smoothing spline follows the moved point as far as the table's accuracy
    lets it, so the fitted acceleration moves by about the change, not exactly).

    References
    ----------
    R. L. Burden and J. D. Faires, Numerical Analysis, 9th ed. (2011), section 3.3: f[x0, x1, x2] = f''(ξ) / 2.
    """
    d1, d2 = np.deg2rad(np.diff(np.asarray(x, dtype=float)[k - 1:k + 2]))
    return float(-change / (ratio * omega**2) * d1 * d2 / 2.0 / MM)


def _shape_points(cam, half, series):
    """``[(handle name, cam deg from the nose, x limits, y limits or None: held), ...]`` of a cam's shape on the
    opening flank (:func:`handles`); the law's piece boundaries are the design's ``segments_cam_deg``."""
    law = cam.get("law")
    edges = series["segments_cam_deg"]
    m = MIN_SEGMENT_DEG
    nose = _interp(series, "valve_acceleration_m_s2", 0.0)
    if law == "power_polynomial":
        # the pieces: ramp a-b, positive part b-d-e (peak d), negative part e-g-h (trough g), dwell
        positive, negative = (edges[1], edges[3]), (edges[3], edges[5])
        model = REGISTRY["power_polynomial"]
        low_a, high_a = _key_range(model, "peak_acceleration_mm_per_rad2")
        # the valve's acceleration per mm/rad² of a_qd (the peak scales with it)
        scale = _interp(series, "valve_acceleration_m_s2", edges[2]) / cam["peak_acceleration_mm_per_rad2"]
        return [("ramp", edges[0], (-half - _key_range(model, "ramp_angle_deg")[1], -half - m), None),
                ("peak", edges[2], tuple(positive[0] + f * (positive[1] - positive[0]) for f in POSITION_RANGE),
                 _ordered(scale * low_a, scale * high_a)),
                ("phi1", edges[3], (edges[1] + m, edges[1] + half - m), None),
                ("trough", edges[4], tuple(negative[0] + f * (negative[1] - negative[0]) for f in POSITION_RANGE),
                 None)]
    if law == "combined":
        lengths = [seg["length_deg"] for seg in cam["segments"]]
        ends = -half + np.cumsum(lengths)
        named = {r["segment"] for r in cam.get("ratios", [])}
        low_r, high_r = _key_range(Ratio, "value")
        return [(f"end.{k}", float(x), (float(x - lengths[k - 1] + m), float(x + lengths[k] - m)),
                 _ordered(low_r * nose, high_r * nose) if k in named else None)
                for k, x in enumerate(ends[:-1], 1)]
    if law == "polydyne":
        _, q, r, s = _exponents(cam)
        top = min(200.0, q - 0.01) if q is not None else 200.0
        return [("peak", -half * polydyne_peak(*_exponents(cam)),
                 (-half * polydyne_peak(top, q, r, s), -half * polydyne_peak(3.0, q, r, s)), None)]
    if {"phi1_deg", "phi2_deg"} <= set(cam):
        phi1, phi2 = cam["phi1_deg"], cam["phi2_deg"]
        phi3 = cam.get("phi3_deg", half - phi1 - phi2)
        shape = (_ordered(SHAPE_FACTOR_RANGE[0] * nose, SHAPE_FACTOR_RANGE[1] * nose) if law == "kurz" else None)
        return [("phi1", -half + phi1, (-half + m, -half + phi1 + phi2 - m), None),
                ("phi2", -half + phi1 + phi2, (-half + phi1 + m, -half + phi1 + phi2 + phi3 - m), shape)]
    return []


def _exponents(cam):
    """A polydyne cam's exponents p, q, r, s (None: the law's progression)."""
    return tuple(cam.get(k) for k in ("p", "q", "r", "s"))


PEAK_GRID = np.linspace(0.0, 1.0, 2001)
"""The fractions of the half-angle on which :func:`polydyne_peak` looks for the peak."""


def polydyne_peak(p, q=None, r=None, s=None) -> float:
    """Where the positive acceleration of a polydyne lift peaks on a flank: the fraction x of the half-angle phi_p0
    from the nose (0 at the nose, 1 at the start of lift), to 1/2000.

    Parameters
    ----------
    p, q, r, s : float
        The exponents (q, r, s None: the progression of the law).

    Notes
    -----
    h = h_nose (1 + C2 x^2 + Cp x^p + Cq x^q + Cr x^r + Cs x^s): the lift and the half-angle scale the acceleration
    and its abscissa out, so the peak's x depends on the exponents alone.  Of the law without a ramp: a ramp joined
    to the flank moves the peak of the cam by little.

    References
    ----------
    Valve-train practical works (n.d.), work 3, eqs. (3.1)-(3.8).
    """
    acceleration = PolydyneLaw(1.0, 1.0, p, q, r, s).derivatives(-PEAK_GRID)[2]
    return float(PEAK_GRID[np.argmax(acceleration)])


def polydyne_p(x, q=None, r=None, s=None) -> float:
    """The first exponent p (3 up to 200, below a given q) of a polydyne lift whose positive acceleration peaks at
    the fraction ``x`` of the half-angle from the nose (:func:`polydyne_peak`, which grows with p: 0.40 at p = 3,
    0.81 at 8, 0.99 at 200), by bisection, to 0.01."""
    low, high = 3.0, min(200.0, q - 0.01) if q is not None else 200.0
    while high - low > 0.005:
        mid = 0.5 * (low + high)
        low, high = (mid, high) if polydyne_peak(mid, q, r, s) < x else (low, mid)
    return round(0.5 * (low + high), 2)


def _split(start, a, b, x):
    """Two adjacent angles ``a``, ``b`` [cam deg] (the first from ``start``) with their boundary dragged to ``x``:
    the new pair, rounded to :data:`HANDLE_STEP`, each at least :data:`MIN_SEGMENT_DEG`, adding up as before."""
    new = round(min(max(x - start, MIN_SEGMENT_DEG), a + b - MIN_SEGMENT_DEG), 2)
    return new, round(a + b - new, 2)


def _position(x, start, length):
    """Where ``x`` lies in a part from ``start`` of ``length`` [cam deg], as a fraction within
    :data:`POSITION_RANGE`, to 3 digits."""
    return round(min(max((x - start) / length, POSITION_RANGE[0]), POSITION_RANGE[1]), 3)


SHAPE_FACTOR_RANGE = (0.05, 0.99)
"""The range a Kurz cam's shape factor Z is dragged in (the specification allows [0.05, 1))."""

POSITION_RANGE = (0.02, 0.98)
"""The range a peak position (a fraction of its part) is dragged in: at 0 or 1 the two pieces of a part become one."""


def moved(document, spec, name, handle, x, y, series, valve=None) -> dict[str, Any]:
    """The keys a drag of ``handle`` to (x, y) sets: ``{dotted key: value}``; x [cam deg from the nose], y [mm] on
    the lift plot, [m/s²] (valve side, at the rated speed) on the acceleration plot; ``series`` and ``valve`` (its
    results) the design's.

    The nose sets the valve lift ``max_lift_mm`` to y.  A boundary between two angles sets both so that the other
    boundaries stay and the flank still adds up to the half-angle (phi1_deg and phi2_deg for ``phi1`` of a cam of
    segment angles, and for the ``peak`` of a Kurz cam, which puts the middle of phi1 at x; phi2_deg and, where it is
    given, phi3_deg for ``phi2``, whose height also sets a Kurz cam's shape factor Z, the ratio of the accelerations
    at the phi2/phi3 junction and at the nose, y over the nose's; the lengths of segments K and K+1 for
    ``end.K`` of a combined cam, and the value of a ratio naming segment K, y over the acceleration at the nose).
    Of a power-polynomial cam, ``ramp`` sets ramp_angle_deg (the ramp ends where the main event starts), ``phi1``
    the positive part phi1_deg, ``peak`` the peak_position in it and peak_acceleration_mm_per_rad2 in the ratio of
    y to the peak's present height (the valve's acceleration is the tappet's analogue times the rocker ratio and the
    camshaft speed squared), ``trough`` the trough_position in the negative part.  The ``peak`` of a polydyne cam
    sets p so that the peak lies at x (:func:`polydyne_p`; its height follows from the lift).  A point ``point.K`` of an inline
    lift table sets its angle (kept between its neighbours) and its lift (at least zero); a point
    ``acceleration.K`` sets the lift of point K so that the table's acceleration there changes by the drag's height
    (:func:`acceleration_step`, at the camshaft speed and rocker ratio of ``valve``; its angle stays).  A handle the
    valve does not have (:func:`handles`: a request of a page drawn before its law changed) is a ValueError.
    """
    known = [h.name for h in handles(document, spec, name, series)]
    if handle not in known:
        raise InputError(f"valves.{name} has no handle {handle!r} (its handles: {', '.join(known) or 'none'})")
    at = f"valves.{name}"
    if handle == "nose":
        return {f"{at}.max_lift_mm": round(float(np.clip(y, *_key_range(Valve, "max_lift_mm"))), 3)}
    cam = document["valves"][name]["cam"]
    if has_points(cam):
        k = int(handle.split(".")[1])
        x_all = TablePoints(cam, series).plot_x(cam["table_angles_deg"])
        lifts = list(cam["table_lifts_mm"])
        if handle.startswith("acceleration."):
            ratio = valve["rocker_ratio"] if cam["table_lift_at"] == "tappet" else 1.0
            lifts[k] += acceleration_step(x_all, k, y - _interp(series, "valve_acceleration_m_s2", x_all[k]),
                                          valve["cam"]["camshaft_speed_rad_s"], ratio)
            return _points_moved(at, cam, series, x_all, lifts)
        lo = x_all[k - 1] if k > 0 else -np.inf
        hi = x_all[k + 1] if k + 1 < len(x_all) else np.inf
        step = HANDLE_STEP["deg"] * TablePoints(cam, series).scale
        x_all[k], lifts[k] = min(max(x, lo + step), hi - step), y        # a point stays between its neighbours
        return _points_moved(at, cam, series, x_all, lifts)
    half = main_half_angle_deg(spec.valves[name], spec.engine.strokes)
    edges = series["segments_cam_deg"]
    if cam["law"] == "power_polynomial":
        if handle == "ramp":
            return {f"{at}.cam.ramp_angle_deg": round(max(-x - half, MIN_SEGMENT_DEG), 2)}
        if handle == "phi1":
            return {f"{at}.cam.phi1_deg": round(min(max(x - edges[1], MIN_SEGMENT_DEG), half - MIN_SEGMENT_DEG), 2)}
        if handle == "trough":
            return {f"{at}.cam.trough_position": _position(x, edges[3], edges[5] - edges[3])}
        old = _interp(series, "valve_acceleration_m_s2", edges[2])
        return {f"{at}.cam.peak_position": _position(x, edges[1], edges[3] - edges[1]),
                f"{at}.cam.peak_acceleration_mm_per_rad2": round(cam["peak_acceleration_mm_per_rad2"] * max(y, 0.0)
                                                                 / old, 2)}
    if cam["law"] == "combined":
        k = int(handle.split(".")[1])
        segments = [dict(seg) for seg in cam["segments"]]
        start = -half + sum(seg["length_deg"] for seg in segments[:k - 1])
        segments[k - 1]["length_deg"], segments[k]["length_deg"] = _split(
            start, segments[k - 1]["length_deg"], segments[k]["length_deg"], x)
        out = {f"{at}.cam.segments": segments}
        ratios = cam.get("ratios", [])
        if any(r["segment"] == k for r in ratios):
            nose = _interp(series, "valve_acceleration_m_s2", 0.0)
            out[f"{at}.cam.ratios"] = [{**r, "value": round(y / nose, 3)} if r["segment"] == k else dict(r)
                                       for r in ratios]
        return out
    if cam["law"] == "polydyne":
        _, q, r, s = _exponents(cam)
        return {f"{at}.cam.p": polydyne_p(min(max(-x / half, 0.0), 1.0), q, r, s)}
    phi1, phi2 = cam["phi1_deg"], cam["phi2_deg"]
    phi3 = cam.get("phi3_deg")
    if handle == "phi1":
        new1, new2 = _split(-half, phi1, phi2, x)
        return {f"{at}.cam.phi1_deg": new1, f"{at}.cam.phi2_deg": new2}
    new2, new3 = _split(-half + phi1, phi2, half - phi1 - phi2 if phi3 is None else phi3, x)
    out = {f"{at}.cam.phi2_deg": new2}
    if phi3 is not None:
        out[f"{at}.cam.phi3_deg"] = new3
    if cam["law"] == "kurz":
        nose = _interp(series, "valve_acceleration_m_s2", 0.0)
        out[f"{at}.cam.shape_factor"] = round(float(min(max(y / nose, SHAPE_FACTOR_RANGE[0]),
                                                        SHAPE_FACTOR_RANGE[1])), 3)
    return out


DESIGNS_KEPT = 32
"""How many designs a tab keeps by their document (:meth:`Session.design`): a drag's last position designed
while the pointer moved, an undo or a redo, is answered without designing again."""


def document_key(document) -> str:
    """A document as the text that keys its design: JSON with sorted keys (TOML's values are JSON's)."""
    return json.dumps(document, sort_keys=True, default=str)


@dataclass
class Session:
    """The state of one tab: the good design (its document, a dict of TOML tables, and its result), the problems of
    the last edit refused (records of :func:`valvetrain.api.design`) and the values it tried, the documents to undo
    and to redo, the baseline pinned.

    Every edit applies to the good design (:meth:`edit`): one that designs becomes the good design (and can be
    undone), one that does not leaves the good design, the undo and the redo as they were.

    An edit is answered in steps: a drag's sketch first (:meth:`preview`: the valve's kinematics alone, kept as
    neither); :meth:`apply` designs without the speed sweeps of the ``[dynamics]`` sections and without the
    diagnosis of springs that do not pass (``good``: the kinematics, springs and checks in tens of ms; a valve the
    edit left as it was is not designed again: ``memo``; a document designed before is not designed again:
    :meth:`design`); :meth:`settle` adds them (``full``: the checks of the whole design and the sweeps), in the
    background, and :meth:`settled` keeps it."""

    good_document: dict
    good: dict = None
    problems: list = field(default_factory=list)
    refused: dict = field(default_factory=dict)
    undone: list = field(default_factory=list)
    redone: list = field(default_factory=list)
    baseline: dict = None
    full: dict = None
    last_full: dict = None
    memo: dict = field(default_factory=dict)
    designs: OrderedDict = field(default_factory=OrderedDict)
    specs: OrderedDict = field(default_factory=OrderedDict)
    sketches: OrderedDict = field(default_factory=OrderedDict)

    @classmethod
    def start(cls, text=None, source_dir=None) -> "Session":
        """A session on TOML text (the built-in example without it).

        Raises
        ------
        SpecError
            The text is no specification, or one that does not design.
        """
        document = toml_tables(text if text is not None else example_text())
        if source_dir is not None:
            document["source_dir"] = str(source_dir)
        s = cls(copy.deepcopy(document))
        s.good = s.design(document)
        if not s.good["ok"]:
            raise SpecError([p["text"] for p in s.good["errors"]])
        return s

    @property
    def document(self) -> dict:
        """The document of the good design (the one drawn)."""
        return self.good_document

    def design(self, document) -> dict:
        """:func:`valvetrain.api.design` of ``document`` without its speed sweeps and spring diagnosis
        (``dynamics=False``, ``diagnose=False``; it is validated whole), or the same design kept from before (the
        last :data:`DESIGNS_KEPT`)."""
        key = document_key(document)
        result = self.designs.get(key)
        if result is None:
            result = api.design(without_nones(document), dynamics=False, diagnose=False, memo=self.memo)
            self.designs[key] = result
            if len(self.designs) > DESIGNS_KEPT:
                self.designs.popitem(last=False)
        else:
            self.designs.move_to_end(key)
        return result

    def apply(self, document, values=None) -> bool:
        """Design ``document`` (:meth:`design`) and keep it as the good design if it designs (the good design before
        it can be undone; nothing to redo), else keep the good design and record the problems and the ``values``
        tried (dotted key -> value).  Returns True when it designed."""
        result = self.design(document)
        if not result["ok"]:
            self.problems, self.refused = result["errors"], dict(values or {})
            return False
        self.problems, self.refused = [], {}
        if document_key(document) != document_key(self.good_document):
            self.undone.append(self.good_document)
            self.redone.clear()
            self._keep(document, result)
        return True

    def _keep(self, document, result):
        self.good, self.good_document = result, copy.deepcopy(document)
        self.last_full, self.full = self.full or self.last_full, None

    def edit(self, values) -> bool:
        """Set dotted keys (``{"engine.rated_speed_rpm": 7500}``) on the good design and design; see :meth:`apply`."""
        try:
            document = set_keys(self.good_document, values)
        except ValueError as exc:
            self.problems, self.refused = api.error_records(SpecError([exc.args[0]])), dict(values)
            return False
        return self.apply(document, values)

    def preview(self, values, name) -> tuple[dict, dict]:
        """The document of the good design with dotted keys set and the sketch of its valve ``name``
        (:meth:`sketch`), kept as neither: what a drag shows while the pointer moves, and at once on its release
        (the last move's, kept: :meth:`sketch`).

        Raises
        ------
        ValueError
            A key that cannot be set (:func:`~valvetrain.specification.set_keys`).
        """
        document = set_keys(self.good_document, values)
        return document, self.sketch(document, name)

    def sketch(self, document, name) -> dict:
        """The good design with valve ``name``'s curves and contour, its camshaft speed and flow figures those of
        ``document`` (:func:`valvetrain.api.kinematics`: its kinematic stages alone, a fraction of :meth:`design`'s
        time), its checks and the other valves the good design's; ``{"ok": False, "errors"}`` where the kinematics
        do not design.  The spring's series (its required force and chosen line, which the drive stage designs)
        are those of ``document``'s design where it is kept (:meth:`design`), else empty: never another design's.
        The kinematics of the last :data:`DESIGNS_KEPT` documents are kept: a release where the pointer last moved
        is not sketched again."""
        key = (document_key(document), name)
        found = self.sketches.get(key)
        if found is None:
            found = self.sketches[key] = api.kinematics(without_nones(document), name)
            while len(self.sketches) > DESIGNS_KEPT:
                self.sketches.popitem(last=False)
        if not found["ok"]:
            return found
        good = self.good
        valve = good["results"]["valves"][name]
        mine = found["results"]["valves"][name]
        designed = self.designs.get(key[0])
        own = designed["series"][name] if designed is not None and designed["ok"] else {}
        spring = {k: own.get(k, []) for k in good["series"][name] if k.startswith(("spring_", "required_"))}
        return {**good, "series": {**good["series"], name: {**spring, **found["series"][name]}},
                "results": {**good["results"], "valves": {**good["results"]["valves"], name: {
                    **valve, "cam": {**valve["cam"], **mine["cam"]}, "flow": {**valve["flow"], **mine["flow"]}}}}}

    def undo(self) -> bool:
        """Go back to the good design before the last edit kept (the current one can be redone); False when there
        is none."""
        return self._step(self.undone, self.redone)

    def redo(self) -> bool:
        """Bring back the design the last :meth:`undo` left; False when there is none."""
        return self._step(self.redone, self.undone)

    def _step(self, source, target):
        if not source:
            return False
        document = source.pop()
        target.append(self.good_document)
        self._keep(document, self.design(document))
        self.problems, self.refused = [], {}
        return True

    @staticmethod
    def settle(document, progress=None, memo=None) -> dict:
        """The whole design of a good document, with its speed sweeps (and the diagnosis of springs that do not
        pass): :func:`valvetrain.api.design` with ``sweeps``; a document without a ``[dynamics]`` section is swept
        with the default one (:func:`valvetrain.api.sweep`) and its design is the good one (``results`` None).
        ``progress`` as there; ``memo`` the valves swept before (:meth:`sweep_one`'s): not swept again.  Pure but
        for the memo: called in a worker thread, kept by :meth:`settled`."""
        plain = without_nones(document)
        if any("dynamics" in v for v in plain.get("valves", {}).values()):
            return api.design(plain, sweeps=True, progress=progress, memo=memo)
        return {**api.sweep(plain, progress=progress, memo=memo), "results": None}

    @staticmethod
    def sweep_one(document, name, progress=None, memo=None) -> dict | None:
        """The speed-sweep series of valve ``name`` of a good document alone (:func:`valvetrain.api.sweep` of that
        valve): the whole design's (:meth:`settle`) sweep of it in a fraction of the time; with a ``memo``, kept
        there for :meth:`settle`, which then does not sweep it again.  None where the whole design sweeps no such
        valve (another valve has a ``[dynamics]`` section and this one none) or the sweep does not come (the whole
        design says why).  ``progress`` as for :meth:`settle`."""
        plain = without_nones(document)
        valves = plain.get("valves", {})
        if name not in ([n for n, v in valves.items() if "dynamics" in v] or list(valves)):
            return None
        result = api.sweep(plain, progress=progress, names=[name], memo=memo)
        return result["sweeps"][name] if result["ok"] else None

    def settled(self, result) -> None:
        """Keep the whole design (:meth:`settle`) of the good document."""
        self.full = result

    @property
    def checked(self) -> dict:
        """The results whose checks the table shows: the whole design's when it has come, else the good one's."""
        return (self.full or {}).get("results") or self.good["results"]

    @property
    def pending(self) -> list:
        """The checks of the last whole design that the good design (without its sweeps) lacks, while its whole
        design is to come: they are shown as pending."""
        if self.full is not None or self.last_full is None or self.last_full.get("results") is None:
            return []
        have = {c["quantity"] for c in self.good["results"]["checks"]}
        return [c for c in self.last_full["results"]["checks"] if c["quantity"] not in have]

    def spec_of(self, document) -> Spec:
        """The validated specification of a document that designed (kept with its design: the handles of a drag's
        preview ask for it at every move)."""
        from ..specification import validate

        key = document_key(document)
        if key not in self.specs:
            self.specs[key] = validate(without_nones(document))
            while len(self.specs) > DESIGNS_KEPT:
                self.specs.popitem(last=False)
        return self.specs[key]

    @property
    def spec(self) -> Spec:
        """The validated specification of the good design."""
        return self.spec_of(self.good_document)

    def handles(self, name, document=None, result=None) -> list[Handle]:
        """The handles of valve ``name`` on the good design (:func:`handles`), or on ``document`` and its
        ``result`` (a drag's preview)."""
        document, result = (self.good_document, self.good) if document is None else (document, result)
        return handles(document, self.spec_of(document), name, result["series"][name])

    def moved(self, name, handle, x, y) -> dict:
        """The keys a drag of a handle of valve ``name`` to (x, y) sets on the good design (:func:`moved`)."""
        return moved(self.good_document, self.spec, name, handle, x, y, self.good["series"][name],
                     self.good["results"]["valves"][name])

    def drag(self, name, handle, x, y) -> dict:
        """Move a handle of valve ``name`` to (x, y) and design (:meth:`moved`, :meth:`edit`).  Returns the keys set
        (``{dotted key: value}``) when it designed, else an empty dict."""
        values = self.moved(name, handle, x, y)
        return values if self.edit(values) else {}

    def points(self, name, x, y) -> dict:
        """The keys that put the points of valve ``name``'s inline lift table at ``x`` [cam deg from the nose],
        ``y`` [mm] (points added or removed on the lift plot)."""
        cam = self.good_document["valves"][name]["cam"]
        return _points_moved(f"valves.{name}", cam, self.good["series"][name], x, y)

    def set_points(self, name, x, y) -> dict:
        """Put the points of an inline lift table (:meth:`points`) and design; see :meth:`drag`."""
        values = self.points(name, x, y)
        return values if self.edit(values) else {}

    def restore(self, document) -> bool:
        """Design a whole document the page kept across a reload (an edit that can be undone; its source folder is
        this session's, whatever the page sent)."""
        document = {k: v for k, v in document.items() if k != "source_dir"}
        if "source_dir" in self.good_document:
            document["source_dir"] = self.good_document["source_dir"]
        return self.apply(document)

    def pin(self) -> None:
        """Pin the good design as the baseline that the plots and the checks table compare with (with the checks of
        its whole design when it has come)."""
        self.baseline = {**self.good, "results": self.checked}

    def report(self, lang) -> str:
        """The report of the good design as HTML text in ``lang``."""
        return api.report_html(without_nones(self.good_document), lang, "main")

    def toml(self) -> str:
        """The specification of the good design as TOML text (every default written out)."""
        return api.toml_text(without_nones(self.good_document))

    def dxf(self, name) -> bytes | None:
        """The contour of valve ``name`` of the good design as DXF, the bytes of ``valvetrain run``'s
        ``contour/NAME.dxf``; None for an undercut profile (which has no contour to make)."""
        from ..design import run
        from ..export import dxf_bytes

        plain = without_nones(self.good_document)
        valve = run(api.without_dynamics(plain, self.spec), diagnose=False, memo=self.memo).valves[name]
        return None if valve.profile.undercut else dxf_bytes(valve)
