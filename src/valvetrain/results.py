"""Typed results of the design stages: SI fields whose metadata give the key, unit and meaning in results.json.

A stage result is a frozen dataclass.  A field declared with :func:`quantity` is part of the
results: ``key`` is its name in ``results.json`` (engineering units in the name, as in the
specification: ``rho_min_mm``), ``unit`` the unit it is shown in (:data:`valvetrain.units.UNITS`),
``label`` what it is.  :func:`shown` reads fields from a result's attributes as ``(key, value)`` rows in
their display units, the one place where a result leaves SI (the report reads its tables so);
:func:`record` is the dictionary of those rows, made once per design for results.json
(:attr:`valvetrain.design.DesignResults.projection`); :func:`json_schema` describes the same
dictionary as a JSON Schema, generated from the same metadata.  Fields without the metadata
(arrays, the law object) stay inside.
"""

from collections.abc import Iterator
from dataclasses import MISSING, dataclass, field, fields, is_dataclass
import typing
from typing import Any, Union

import numpy as np

from .units import displayed


def quantity(key, unit="", label="", *, default=MISSING, flatten=False, omit_none=False) -> Any:
    """A result field shown in results.json as ``key`` in ``unit``.

    Parameters
    ----------
    key : str
        Name in results.json.
    unit : str
        Display unit of the value (a key of :data:`valvetrain.units.UNITS`); numbers,
        tuples and arrays of numbers are converted, other values kept.
    label : str
        What the quantity is, for the schema and the report.
    default
        Default value of the field.
    flatten : bool
        A nested result whose keys are merged into the parent's record.
    omit_none : bool
        Leave the key out where the value is None (a quantity that exists only for some designs).
    """
    meta = {"key": key, "unit": unit, "label": label, "flatten": flatten, "omit_none": omit_none}
    return field(metadata=meta) if default is MISSING else field(default=default, metadata=meta)


@dataclass(frozen=True)
class NamedValues:
    """Named values in a given order where the names are not fixed fields (a law's coefficients, named and ordered
    as in its source): shown in results.json as an object.

    >>> c = NamedValues.of({"A1": 2.5, "flank": {"a": [1.0, 2.0]}})
    >>> c["A1"], "flank" in c, c["flank"]["a"]
    (2.5, True, (1.0, 2.0))
    """

    names: tuple[str, ...]
    values: tuple[Union[float, int, str, tuple[float, ...], "NamedValues"], ...]

    @classmethod
    def of(cls, mapping) -> "NamedValues":
        """The named values of a mapping (nested mappings become nested named values, lists tuples)."""
        def value(v):
            if isinstance(v, dict):
                return cls.of(v)
            return tuple(v) if isinstance(v, (list, tuple, np.ndarray)) else v
        return cls(tuple(mapping), tuple(value(v) for v in mapping.values()))

    def items(self) -> Iterator[tuple[str, Any]]:
        """``(name, value)`` in order."""
        return zip(self.names, self.values, strict=True)

    def __contains__(self, name) -> bool:
        return name in self.names

    def __getitem__(self, name) -> Any:
        return self.values[self.names.index(name)]


def _shown(value, unit):
    if value is None or isinstance(value, (str, bool)):
        return value
    if isinstance(value, NamedValues):
        return {k: _shown(v, unit) for k, v in value.items()}
    if is_dataclass(value):
        return record(value)
    if isinstance(value, dict):
        return {k: _shown(v, unit) for k, v in value.items()}
    if isinstance(value, (tuple, list, np.ndarray)):
        return [_shown(v, unit) for v in value]
    if isinstance(value, (int, np.integer)) and not unit:
        return int(value)
    return displayed(value, unit)


def record(result: Any) -> dict[str, Any]:
    """The results.json dictionary of a stage result (engineering units, keys from the field metadata): the rows of
    :func:`shown`."""
    return dict(shown(result))


def shown(result: Any, *names: str, nested: bool = True) -> list[tuple[str, Any]]:
    """``(key, value)`` of the named fields of a stage result as results.json shows them (the field's key, the value
    in its display unit), read from the attributes in the order named.  Without names, every field's in the order
    declared: a flattened result's rows in its place (a key it shares with the parent's keeps the parent's place and
    takes its value), a field left out where it is None and results.json leaves it out (the rows of its
    :func:`record`).  ``nested`` False leaves out the fields whose value is a record of its own (a nested result,
    named values, a mapping), which results.json shows as an object: the rows of a table of numbers.

    >>> from valvetrain.followers.flat import FlatContact
    >>> shown(FlatContact(0.0125), "max_contact_offset")
    [('max_contact_offset_mm', 12.5)]
    """
    if names:
        meta = {f.name: f.metadata for f in fields(result)}
        return [(meta[n]["key"], _shown(getattr(result, n), meta[n]["unit"])) for n in names]
    rows = {}
    for f in fields(result):
        meta = f.metadata
        value = getattr(result, f.name)
        if "key" not in meta or value is None and (meta["omit_none"] or meta["flatten"]):
            continue
        if meta["flatten"]:
            rows.update(shown(value, nested=nested))
        elif nested or not (is_dataclass(value) or isinstance(value, (NamedValues, dict))):
            rows[meta["key"]] = _shown(value, meta["unit"])
    return list(rows.items())


def shown_value(result: Any, name: str) -> Any:
    """The value of one field of a stage result as results.json shows it (:func:`shown`)."""
    return shown(result, name)[0][1]


_JSON_TYPES = {float: ["number", "null"], int: "integer", str: "string", bool: "boolean", dict: "object"}
"""JSON types of the field annotations; a float may be null, which is how results.json writes a quantity that is
not finite or not defined (see :func:`valvetrain.export.json_text`)."""


def _type_schema(annotation):
    origin = typing.get_origin(annotation)
    if origin is typing.Union or origin is getattr(__import__("types"), "UnionType", None):
        options = [_type_schema(a) for a in typing.get_args(annotation)]
        return {"anyOf": options}
    if annotation is type(None):
        return {"type": "null"}
    if origin in (tuple, list):
        return {"type": "array", "items": _type_schema(typing.get_args(annotation)[0])}
    if origin is dict:
        values = _type_schema(typing.get_args(annotation)[1])
        return {"type": "object", **({"additionalProperties": values} if values else {})}
    if annotation is NamedValues:
        return {"type": "object"}
    if isinstance(annotation, type) and is_dataclass(annotation):
        return json_schema(annotation)
    if annotation in _JSON_TYPES:
        return {"type": _JSON_TYPES[annotation]}
    return {}


def json_schema(cls) -> dict[str, Any]:
    """JSON Schema (draft 2020-12) of the record of a result class: properties from the fields' metadata."""
    hints = typing.get_type_hints(cls)
    props, required = {}, []
    for f in fields(cls):
        meta = f.metadata
        if "key" not in meta:
            continue
        sub = _type_schema(hints[f.name])
        if meta["flatten"]:
            for nested in [sub, *sub.get("anyOf", [])]:
                props.update(nested.get("properties", {}))
            continue
        text = meta["label"] + (f" [{meta['unit']}]" if meta["unit"] else "")
        props[meta["key"]] = {**sub, "description": text} if text else sub
        if not meta["omit_none"]:
            required.append(meta["key"])
    return {"type": "object", "title": cls.__name__, "description": (cls.__doc__ or "").strip().split("\n")[0],
            "properties": props, "required": required}
