"""One browser tab of the designer: the specification being edited, the last good design and the baseline.

Pure Python on :mod:`valvetrain.api` (no Bokeh here), so that every callback of the page is tested without a
browser: an edit of a field, a drag of a handle, the pinning of a baseline, the TOML to download.  Nothing is
written to disk.
"""

import copy
from dataclasses import dataclass, field
import tomllib
import typing
from typing import Any

import numpy as np
from pydantic import BaseModel
import tomli_w

from .. import api
from ..specification import REGISTRY, SpecError, example_text, set_keys
from ..specification.cams import main_half_angle_deg
from ..specification.fields import Range
from ..specification.models import Drive, Dynamics, Engine, Masses, Spring, Valve

HANDLE_STEP = {"deg": 0.01, "mm": 0.001}
"""A dragged handle is rounded to these steps [cam deg, mm]: a saved specification reads like a typed one."""

MIN_SEGMENT_DEG = 0.1
"""The shortest segment a drag leaves (the specification's own least segment angle, cam deg)."""


@dataclass(frozen=True)
class Field:
    """One input of the specification panel: the dotted key, the kind of input and its bounds or options."""

    path: str
    kind: str                  # "float", "int", "choice", "text" (a TOML value: a string, a list, a table)
    value: object
    low: float = None
    high: float = None
    unit: str = ""
    options: tuple = ()
    optional: bool = False

    @property
    def bounds_text(self):
        """``[5, 2000] mm``, ``1 ... 64`` or an empty text."""
        if self.low is None and self.high is None:
            return ""
        return f"{self.low:g} ... {self.high:g}{' ' + self.unit if self.unit else ''}"


def _unwrapped(annotation):
    """The annotation without Optional, and whether it was optional."""
    if typing.get_origin(annotation) is typing.Union:
        args = [a for a in typing.get_args(annotation) if a is not type(None)]
        if len(args) == 1:
            return args[0], True
    return annotation, False


def field_of(path, info, value) -> Field:
    """The :class:`Field` of a pydantic model field (its FieldInfo) at a dotted key, with the document's value."""
    annotation, optional = _unwrapped(info.annotation)
    metadata = list(info.metadata)
    if typing.get_origin(annotation) is typing.Annotated:
        metadata += list(annotation.__metadata__)
        annotation = typing.get_args(annotation)[0]
    if typing.get_origin(annotation) is typing.Literal:
        return Field(path, "choice", value, options=typing.get_args(annotation), optional=optional)
    if annotation in (float, int):
        rng = next((m for m in metadata if isinstance(m, Range)), None)
        low = rng.low if rng else next((m.ge for m in metadata if hasattr(m, "ge")), None)
        high = rng.high if rng else next((m.le for m in metadata if hasattr(m, "le")), None)
        return Field(path, annotation.__name__, value, low, high, rng.unit if rng else "", optional=optional)
    if annotation is bool:
        return Field(path, "choice", value, options=(True, False), optional=optional)
    return Field(path, "text", value, optional=optional)


SECTIONS = (("engine", Engine), ("valves.{}", Valve), ("valves.{}.cam", None), ("valves.{}.drive", Drive),
            ("valves.{}.drive.masses", Masses), ("valves.{}.spring", Spring), ("valves.{}.dynamics", Dynamics))
"""The sections of the specification panel and their models (the cam's is the registry's model of its law)."""


def _get(document, path):
    node = document
    for part in path.split("."):
        if not isinstance(node, dict) or part not in node:
            return None
        node = node[part]
    return node


def _section_fields(document, path, model):
    section = _get(document, path) or {}
    out = []
    for key, info in model.model_fields.items():
        sub, _ = _unwrapped(info.annotation)
        if key == "closing" or (isinstance(sub, type) and issubclass(sub, BaseModel)):
            continue
        out.append(field_of(f"{path}.{key}", info, section.get(key, None if info.is_required() else info.default)))
    return out


def form(document) -> list[tuple[str, list[Field]]]:
    """The specification panel of a document: ``[(section path, [Field, ...]), ...]``, every scalar key of the
    engine and of each valve's sections, with the document's values (a key it lacks shows the model's default)."""
    out = []
    for pattern, model in SECTIONS:
        for name in (document.get("valves") or {}) if "{}" in pattern else [None]:
            path = pattern.format(name)
            section_model = model or REGISTRY.get(_get(document, path + ".law"))
            if section_model is not None:
                out.append((path, _section_fields(document, path, section_model)))
    return out


def parse_value(f, text) -> Any:
    """The value of a :class:`Field` from what the page sent: a number, an option, or TOML value text; an empty
    input of an optional key is ``None`` (the key removed)."""
    if f.kind in ("float", "int"):
        if text is None or text == "":
            return None
        return float(text) if f.kind == "float" else int(text)
    if f.kind == "choice":
        return next((o for o in f.options if str(o) == str(text)), text)
    if text is None or str(text).strip() == "":
        return None
    try:
        return tomllib.loads(f"v = {text}")["v"]
    except tomllib.TOMLDecodeError:
        return str(text)


def value_text(value) -> str:
    """A value as the text of an input: a TOML value (``"VDSiCr"``, ``[2.0, 7.0]``), empty for None."""
    if value is None:
        return ""
    return tomli_w.dumps({"v": value}).removeprefix("v = ").strip()


def without_nones(node) -> Any:
    """A document with the keys whose value is None removed (an optional key left empty)."""
    if isinstance(node, dict):
        return {k: without_nones(v) for k, v in node.items() if v is not None}
    return node


@dataclass(frozen=True)
class Handle:
    """A point on a plot that the user drags: its plot (``"lift"`` or ``"acceleration"``) and where it is."""

    name: str
    plot: str
    x: float
    y: float


def _interp(series, key, x):
    return float(np.interp(x, series["cam_deg"], series[key]))


def handles(document, spec, name, series) -> list[Handle]:
    """The handles of valve ``name``: the nose lift (on the lift plot, at the nose) and, on the acceleration plot,
    the points of its law's shape on the opening flank (the closing flank of a symmetric cam follows by the law):

    - a cam of segment angles (``phi1_deg``, ``phi2_deg``: Kurz, constant acceleration): the two boundaries between
      its segments, ``phi1`` and ``phi2``;
    - a power-polynomial cam: the start of the ramp (``ramp``), the positive peak (``peak``, where
      ``peak_position`` puts it and as high as ``peak_acceleration_mm_per_rad2`` makes it), the end of the positive
      part (``phi1``) and the negative peak (``trough``, ``trough_position``);
    - a combined cam: the end of each segment but the last (``end.K``, segment K counted from 1), whose height sets
      a ratio that names that segment.
    """
    valve = document["valves"][name]
    out = []
    if valve.get("max_lift_mm") is not None:
        out.append(Handle("nose", "lift", 0.0, _interp(series, "valve_lift_mm", 0.0)))
    cam = valve.get("cam", {})
    half = main_half_angle_deg(spec.valves[name], spec.engine.strokes)
    for key, x in _shape_points(cam, half, series["segments_cam_deg"]):
        out.append(Handle(key, "acceleration", x, _interp(series, "valve_acceleration_m_s2", x)))
    return out


def _shape_points(cam, half, edges):
    """``[(handle name, cam deg from the nose), ...]`` of a cam's shape on the opening flank (:func:`handles`);
    ``edges`` are the law's piece boundaries [cam deg] (the design's ``segments_cam_deg``)."""
    law = cam.get("law")
    if law == "power_polynomial":
        # the pieces: ramp a-b, positive part b-d-e (peak d), negative part e-g-h (trough g), dwell
        return list(zip(("ramp", "peak", "phi1", "trough"), (edges[0], edges[2], edges[3], edges[4]), strict=True))
    if law == "combined":
        ends = -half + np.cumsum([seg["length_deg"] for seg in cam["segments"]])
        return [(f"end.{k}", float(x)) for k, x in enumerate(ends[:-1], 1)]
    if {"phi1_deg", "phi2_deg"} <= set(cam):
        return [("phi1", -half + cam["phi1_deg"]), ("phi2", -half + cam["phi1_deg"] + cam["phi2_deg"])]
    return []


def _split(start, a, b, x):
    """Two adjacent angles ``a``, ``b`` [cam deg] (the first from ``start``) with their boundary dragged to ``x``:
    the new pair, rounded to :data:`HANDLE_STEP`, each at least :data:`MIN_SEGMENT_DEG`, adding up as before."""
    new = round(min(max(x - start, MIN_SEGMENT_DEG), a + b - MIN_SEGMENT_DEG), 2)
    return new, round(a + b - new, 2)


def _position(x, start, length):
    """Where ``x`` lies in a part from ``start`` of ``length`` [cam deg], as a fraction within
    :data:`POSITION_RANGE`, to 3 digits."""
    return round(min(max((x - start) / length, POSITION_RANGE[0]), POSITION_RANGE[1]), 3)


POSITION_RANGE = (0.02, 0.98)
"""The range a peak position (a fraction of its part) is dragged in: at 0 or 1 the two pieces of a part become one."""


def moved(document, spec, name, handle, x, y, series) -> dict[str, Any]:
    """The keys a drag of ``handle`` to (x, y) sets: ``{dotted key: value}``; x [cam deg from the nose], y [mm] on
    the lift plot, [m/s²] (valve side, at the rated speed) on the acceleration plot; ``series`` the design's.

    The nose sets the valve lift ``max_lift_mm`` to y.  A boundary between two angles sets both so that the other
    boundaries stay and the flank still adds up to the half-angle (phi1_deg and phi2_deg for ``phi1`` of a cam of
    segment angles, phi2_deg and, where it is given, phi3_deg for ``phi2``; the lengths of segments K and K+1 for
    ``end.K`` of a combined cam, and the value of a ratio naming segment K, y over the acceleration at the nose).
    Of a power-polynomial cam, ``ramp`` sets ramp_angle_deg (the ramp ends where the main event starts), ``phi1``
    the positive part phi1_deg, ``peak`` the peak_position in it and peak_acceleration_mm_per_rad2 in the ratio of
    y to the peak's present height (the valve's acceleration is the tappet's analogue times the rocker ratio and the
    camshaft speed squared), ``trough`` the trough_position in the negative part.
    """
    at = f"valves.{name}"
    if handle == "nose":
        return {f"{at}.max_lift_mm": round(max(y, HANDLE_STEP["mm"]), 3)}
    cam = document["valves"][name]["cam"]
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
    phi1, phi2 = cam["phi1_deg"], cam["phi2_deg"]
    phi3 = cam.get("phi3_deg")
    if handle == "phi1":
        new1, new2 = _split(-half, phi1, phi2, x)
        return {f"{at}.cam.phi1_deg": new1, f"{at}.cam.phi2_deg": new2}
    new2, new3 = _split(-half + phi1, phi2, half - phi1 - phi2 if phi3 is None else phi3, x)
    out = {f"{at}.cam.phi2_deg": new2}
    if phi3 is not None:
        out[f"{at}.cam.phi3_deg"] = new3
    return out


@dataclass
class Session:
    """The state of one tab: the document (a dict of TOML tables) edited, the result of its last good design,
    the problems of the last edit (key -> message), the baseline pinned."""

    document: dict
    good: dict = None
    good_document: dict = None
    problems: list = field(default_factory=list)
    baseline: dict = None

    @classmethod
    def start(cls, text=None, source_dir=None):
        """A session on TOML text (the built-in example without it).

        Raises
        ------
        SpecError
            The text is no specification, or one that does not design.
        """
        try:
            document = tomllib.loads(text if text is not None else example_text())
        except tomllib.TOMLDecodeError as exc:
            raise SpecError([f"not valid TOML: {exc}"]) from None
        if source_dir is not None:
            document["source_dir"] = str(source_dir)
        s = cls(document)
        if not s.apply(document):
            raise SpecError([p["text"] for p in s.problems])
        return s

    def apply(self, document):
        """Design ``document``; keep it as the good design if it designs, else keep the last good one and the
        problems.  Returns True when it designed."""
        result = api.design(without_nones(document))
        self.document = document
        self.problems = result["errors"]
        if result["ok"]:
            self.good, self.good_document = result, copy.deepcopy(document)
        return result["ok"]

    def edit(self, values):
        """Set dotted keys (``{"engine.rated_speed_rpm": 7500}``) and design; see :meth:`apply`."""
        return self.apply(set_keys(self.document, values))

    @property
    def spec(self):
        """The validated specification of the good design."""
        from ..specification import validate

        return validate(without_nones(self.good_document))

    def handles(self, name):
        """The handles of valve ``name`` on the good design (:func:`handles`)."""
        return handles(self.good_document, self.spec, name, self.good["series"][name])

    def drag(self, name, handle, x, y):
        """Move a handle of valve ``name`` to (x, y) and design (:func:`moved`, :meth:`edit`).  Returns the keys set
        (``{dotted key: value}``) when it designed, else an empty dict."""
        values = moved(self.good_document, self.spec, name, handle, x, y, self.good["series"][name])
        return values if self.edit(values) else {}

    def pin(self):
        """Pin the good design as the baseline that the plots and the checks table compare with."""
        self.baseline = self.good

    def report(self, lang):
        """The report of the good design as HTML text in ``lang``."""
        return api.report_html(without_nones(self.good_document), lang, "main")

    def toml(self):
        """The specification of the good design as TOML text (every default written out)."""
        return api.toml_text(without_nones(self.good_document))
