"""The SI view of a specification: the one place where its engineering units become SI.

A specification names the unit of every number in its key (``throat_diameter_mm``,
``opens_deg``, ``rated_speed_rpm``, ``allowable_stress_MPa``).  :func:`si` turns a section
into a frozen dataclass whose fields are the same keys without the unit and in SI
(``throat_diameter`` [m], ``opens`` [rad], ``rated_speed`` [rad/s], ``allowable_stress``
[Pa]); keys whose unit is already SI (``_kg``, ``_N``, ``_J``, ``_m_s``, ``_kg_m2``) keep
their names and values.  Nested sections become nested views, lists tuples, so a view is
immutable and compares (and, without arrays, hashes) by value: stage results can be cached
by their inputs.  Angles keep their kind: a crank angle stays a crank angle, a camshaft
angle a camshaft angle (the spec says which in its key documentation).
"""

from dataclasses import field, make_dataclass
from functools import cache
from typing import Any

import numpy as np
from pydantic import BaseModel

from ..units import si_name

def _convert(value, factor, root):
    if isinstance(value, BaseModel):
        return si(value, root)
    if isinstance(value, dict):
        return {k: _convert(v, factor, root) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return tuple(_convert(v, factor, root) for v in value)
    if isinstance(value, np.ndarray):
        return value * factor
    if isinstance(value, (int, float)) and not isinstance(value, bool) and factor != 1.0:
        return value * factor
    return value


@cache
def _keys(model):
    """``(key, SI field, factor to SI)`` of each key of a section's model."""
    return tuple((key, *si_name(key)) for key in model.model_fields)


@cache
def _view_class(model):
    fields = [(si_name(key)[0], object) for key in model.model_fields]
    fields += [(name, object) for name in getattr(model, "si_extras", ())]
    fields.append(("section", object, field(default=None, compare=False, repr=False)))
    return make_dataclass(f"{model.__name__}SI", fields, frozen=True,
                          namespace={"__doc__": f"SI view of :class:`{model.__module__}.{model.__name__}` (its keys "
                                                "without the unit, in SI; ``section`` is the section itself)."})


def si(section, root=None) -> Any:
    """The SI view of a specification section (a pydantic model of :mod:`valvetrain.specification`).

    A section may name data it brings along in ``si_extras`` and provide them with
    ``read_extras(root)`` (a measured lift table, an indicator diagram: the files are read here,
    by :mod:`valvetrain.files`, so that the design never reads a file); ``root`` is the whole
    specification.

    Examples
    --------
    >>> from valvetrain.specification import example_spec
    >>> valve = si(example_spec().valves["intake"])
    >>> valve.throat_diameter, round(valve.opens, 6), valve.cam.law
    (0.038, 0.453786, 'kurz')
    """
    values = {name: _convert(getattr(section, key), factor, root) for key, name, factor in _keys(type(section))}
    if getattr(section, "si_extras", ()):
        values.update(section.read_extras(root))
    return _view_class(type(section))(**values, section=section)
