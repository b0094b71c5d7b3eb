"""The specification panel's fields: each scalar key of the specification's models as an input (its kind, value,
bounds or options), grouped as a designer thinks (:data:`GROUPS`), and the values the page sends parsed back.

Pure Python on the specification's models (no Bokeh here).
"""

from dataclasses import dataclass, replace
import tomllib
import typing
from typing import Any

from pydantic import BaseModel
import tomli_w

from ..specification import REGISTRY
from ..specification.fields import Range
from ..specification.models import Drive, Dynamics, Engine, LostMotion, Masses, Spring, Valve
from ..specification.switching import Switching


@dataclass(frozen=True)
class Field:
    """One input of the specification panel: the dotted key, the kind of input, its value and its bounds or
    options.  Kinds: ``"float"``, ``"int"``, ``"choice"`` (an option), ``"string"`` (a text), ``"list"`` (numbers
    or texts, comma-separated), ``"text"`` (any other TOML value: a table, a text or a list of texts)."""

    path: str
    kind: str
    value: object
    low: float = None
    high: float = None
    unit: str = ""
    options: tuple = ()
    optional: bool = False
    default: object = None

    @property
    def name(self) -> str:
        """The key within its valve or the engine (``cam.phi1_deg``, ``bore_mm``): what its label is looked up by."""
        parts = self.path.split(".")
        return ".".join(parts[2:] if parts[0] == "valves" else parts[1:])

    @property
    def bounds_text(self) -> str:
        """``5 ... 2000 mm``, ``1 ... 64`` or an empty text."""
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


def _is_table(annotation) -> bool:
    """Whether a field holds a table (a model, or a choice of models: the cam's law)."""
    args = typing.get_args(annotation) if typing.get_origin(annotation) is typing.Union else (annotation,)
    return any(isinstance(a, type) and issubclass(a, BaseModel) for a in args)


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
        rng = next((m for m in metadata if isinstance(m, Range)), Range(None, None))
        return Field(path, annotation.__name__, value, rng.low, rng.high, rng.unit, optional=optional)
    if annotation is bool:
        return Field(path, "choice", value, options=(True, False), optional=optional)
    if annotation is str:
        return Field(path, "string", value, optional=optional)
    if typing.get_origin(annotation) in (list, tuple):
        return Field(path, "list", value, optional=optional)
    return Field(path, "text", value, optional=optional)


GROUPS = (("engine", (("engine", Engine),)), ("valve", (("valves.{}", Valve),)), ("cam", (("valves.{}.cam", None),)),
          ("spring", (("valves.{}.spring", Spring),)),
          ("drive", (("valves.{}.drive", Drive), ("valves.{}.drive.masses", Masses))),
          ("dynamics", (("valves.{}.dynamics", Dynamics),)),
          ("vva", (("valves.{}.hydraulic.lost_motion", LostMotion), ("valves.{}.switching", Switching))))
"""The groups of the specification panel as a designer thinks of them, each with its sections and their models
(the cam's is the registry's model of its law)."""

WHERE_PRESENT = ("valves.{}.hydraulic.lost_motion", "valves.{}.switching")
"""The sections of the panel shown only where the document has them (variable valve actuation: a lost-motion
hydraulic drive, a switching finger)."""


def value_at(document, path) -> Any:
    """The value at a dotted key of a document, None where it has none."""
    node = document
    for part in path.split("."):
        if not isinstance(node, dict) or part not in node:
            return None
        node = node[part]
    return node


def _section_fields(document, path, model):
    section = value_at(document, path) or {}
    out = []
    for key, info in model.model_fields.items():
        if key == "closing" or _is_table(_unwrapped(info.annotation)[0]):
            continue
        default = None if info.is_required() else info.default
        out.append(replace(field_of(f"{path}.{key}", info, section.get(key, default)), default=default))
    return out


def value_of(document, f) -> Any:
    """The value a document gives a :class:`Field` of the panel (the model's default where it lacks the key)."""
    parent, key = f.path.rsplit(".", 1)
    section = value_at(document, parent)
    return section.get(key, f.default) if isinstance(section, dict) else f.default


def form(document, valve=None) -> list[tuple[str, list[Field]]]:
    """The specification panel of a document for valve ``valve``: ``[(group, [Field, ...]), ...]`` (:data:`GROUPS`),
    every scalar key of the engine and of the valve's sections, with the document's values (a key it lacks shows
    the model's default); the engine's alone without a valve; a group without fields left out."""
    out = []
    for group, sections in GROUPS:
        if valve is None and group != "engine":
            continue
        fields = []
        for pattern, model in sections:
            path = pattern.format(valve)
            if pattern in WHERE_PRESENT and not isinstance(value_at(document, path), dict):
                continue
            section_model = model or REGISTRY.get(value_at(document, path + ".law"))
            if section_model is not None:
                fields += _section_fields(document, path, section_model)
        if fields:                                  # none: sections only where present (WHERE_PRESENT), absent
            out.append((group, fields))
    return out


def parse_value(f, text) -> Any:
    """The value of a :class:`Field` from what the page sent: a number, an option, a text as typed, a list without
    its brackets (``2.0, 7.0``; texts need no quotes: ``VDSiCr, 60S2A``), or TOML value text; an empty input of an
    optional key is ``None`` (the key removed)."""
    if f.kind in ("float", "int"):
        if text is None or text == "":
            return None
        return float(text) if f.kind == "float" else int(text)
    if f.kind == "choice":
        return next((o for o in f.options if str(o) == str(text)), text)
    if text is None or str(text).strip() == "":
        return None
    text = str(text).strip()
    if f.kind == "string":
        return text
    for wrapped in (f"[{text}]", text) if f.kind == "list" and not text.startswith("[") else (text, f"[{text}]"):
        try:
            return tomllib.loads(f"v = {wrapped}")["v"]
        except (tomllib.TOMLDecodeError, RecursionError):    # nested deeper than the parser goes: as text
            continue
    return [part.strip() for part in text.split(",")] if "," in text else text


def value_text(value) -> str:
    """A value as the text of an input: a text as it is (``VDSiCr``), a list without brackets (``2.0, 7.0``), a
    table as TOML (``{ a = 1 }``), empty for None."""
    if value is None:
        return ""
    if isinstance(value, str):
        return value
    if isinstance(value, (list, tuple)):
        words = all(isinstance(v, str) and "," not in v and v.strip() == v for v in value)
        return ", ".join(v if words else _toml_value(v) for v in value)
    return _toml_value(value)


def _toml_value(value):
    return " ".join(tomli_w.dumps({"v": value}).removeprefix("v = ").split())


def without_nones(node) -> Any:
    """A document with the keys whose value is None removed (an optional key left empty)."""
    if isinstance(node, dict):
        return {k: without_nones(v) for k, v in node.items() if v is not None}
    return node
