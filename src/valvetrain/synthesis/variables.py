"""The variables of a cam synthesis: keys of the valve's specification with their bounds (:class:`Variable`), the
default set of each law with parameters (:func:`default_variables`), parsed from the command line
(:func:`parse_variables`) and checked against the key's own allowed range (:func:`check_bounds`)."""

import copy
from dataclasses import dataclass, field
import difflib
import math
from typing import Any

from pydantic import BaseModel, ValidationError

from .. import springs
from ..errors import InputError
from ..laws.kurz import RAMP_VELOCITY_RANGE_MM_PER_DEG
from ..specification.models import Valve


@dataclass(frozen=True)
class Variable:
    """One design variable: a numeric key under ``[valves.NAME]`` and its bounds (the key's own unit).

    ``path`` is dotted, list entries by their 1-based position: ``cam.phi1_deg``, ``drive.spring_reserve``,
    ``cam.ratios.2.value``.
    """

    path: str
    low: float
    high: float
    written: tuple = field(default=None, compare=False)
    """LOW and HIGH as the user wrote them (for messages)."""

    def put(self, data, value) -> None:
        """Set the variable in a valve section's data (dict, changed in place)."""
        *parents, last = self.path.split(".")
        node = data
        for part in parents:
            node = node[int(part) - 1] if isinstance(node, list) else node.setdefault(part, {})
        if isinstance(node, list):
            node[int(last) - 1] = value
        else:
            node[last] = value

    def get(self, data) -> Any:
        """The variable's value in a valve section's data (dict), None where the section has no such key."""
        node = data
        for part in self.path.split("."):
            if isinstance(node, list) and part.isdigit() and 0 < int(part) <= len(node):
                node = node[int(part) - 1]
            elif isinstance(node, dict) and part in node:
                node = node[part]
            else:
                return None
        return node


def _ramp_and_spring(cam):
    """The ramp end velocity within its band (Valve-train practical works (n.d.), eq. 2.1) and the spring reserve
    K_z within its band (eq. 5.3)."""
    out = [Variable("drive.spring_reserve", *springs.SPRING_RESERVE_RANGE)]
    if getattr(cam, "ramp_end_velocity_mm_per_deg", None) is not None:
        out.insert(0, Variable("cam.ramp_end_velocity_mm_per_deg", *RAMP_VELOCITY_RANGE_MM_PER_DEG))
    return out


def default_variables(valve, engine) -> list[Variable]:
    """The default design variables of a valve's cam law (a list of :class:`Variable`).

    Parameters
    ----------
    valve, engine : the specification's ``[valves.NAME]`` and ``[engine]`` sections.

    Returns
    -------
    list of Variable
        Kurz: phi1, phi2, shape factor Z; constant acceleration: phi1, phi2, kappa; polydyne: the exponents the
        cam gives; combined: the ratios' values; each with the ramp end velocity (0.008-0.022 mm/deg) and the
        spring reserve K_z (1.5-2.25).  The power polynomial: a_qd, phi_1, x_d, x_g (its article holds the spring
        and the ramp).

    Raises
    ------
    ValueError
        A law without parameters to vary (a measured table, three arcs), or an asymmetric cam.

    Notes
    -----
    Each cam model gives its law's own (:meth:`search_variables` of :mod:`valvetrain.specification.cams`).
    """
    cam = valve.cam
    if getattr(cam, "closing", None) is not None:
        raise InputError("optimize: the cam has a [cam.closing] flank of its own; name the variables with --vary")
    own = cam.search_variables(valve, engine)
    if own is None:
        raise InputError(f"optimize: law = {cam.law!r} has no default variables; name them with --vary KEY=LOW,HIGH "
                         "(e.g. --vary cam.nose_radius_mm=5,12)")
    out = [Variable(*v) for v in own]
    return out + _ramp_and_spring(cam) if cam.varies_ramp_and_spring else out


def parse_variables(items) -> list[Variable]:
    """Variables from ``KEY=LOW,HIGH`` texts (``cam.phi1_deg=20,35``).

    Raises
    ------
    ValueError
        A text that is not of that form, LOW >= HIGH, or a key named twice; the message names the text.
    """
    out = []
    for item in items:
        key, sep, bounds = item.partition("=")
        parts = bounds.split(",")
        try:
            low, high = (float(p) for p in parts) if sep and len(parts) == 2 else (None, None)
        except ValueError:
            low = high = None
        if not key.strip() or low is None or not (math.isfinite(low) and math.isfinite(high) and low < high):
            raise InputError(f"--vary {item[:80]!r}: allowed KEY=LOW,HIGH with finite LOW < HIGH, KEY a path under "
                             "[valves.NAME] such as cam.phi1_deg")
        out.append(Variable(key.strip(), low, high, tuple(p.strip() for p in parts)))
    return unique_variables(out)


def unique_variables(variables) -> list[Variable]:
    """``variables`` (a list of :class:`Variable`) with each key once.

    Raises
    ------
    ValueError
        A key named twice.
    """
    seen = set()
    for v in variables:
        if v.path in seen:
            raise InputError(f"--vary {v.path}: the key is named twice; allowed once, with one LOW,HIGH")
        seen.add(v.path)
    return list(variables)


def numeric_keys(section) -> list[str]:
    """The dotted paths of the numbers of a valve's section (``cam.phi1_deg``, ``drive.spring_reserve``), given or
    defaults, list entries by their 1-based position: what ``--vary`` may name."""
    out = []

    def walk(node, prefix):
        if isinstance(node, BaseModel):
            node = {k: getattr(node, k) for k in type(node).model_fields}
        if isinstance(node, dict):
            for k, v in node.items():
                walk(v, f"{prefix}{k}.")
        elif isinstance(node, list):
            for i, v in enumerate(node, start=1):
                walk(v, f"{prefix}{i}.")
        elif isinstance(node, (int, float)) and not isinstance(node, bool):
            out.append(prefix[:-1])

    walk(section, "")
    return out


def unknown_key(path, name, section) -> str:
    """The message of a ``--vary`` key that the valve's section does not have, with the nearest of its numbers."""
    keys = numeric_keys(section)
    near = difflib.get_close_matches(path, keys, n=2, cutoff=0.6) or [k for k in keys if k.endswith(f".{path}")][:2]
    return (f"--vary {path}: valves.{name}.{path} is no key of the valve (unknown key)"
            + (f"; did you mean {' or '.join(near)}?" if near else "; name a number under [valves.NAME], such as "
               "cam.phi1_deg or drive.spring_reserve"))


def not_continuous(v, name, section, value) -> str | None:
    """The message of a ``--vary`` key whose value (``value``, as in the section) cannot be varied continuously: an
    integer (a count) or a list as a whole; None for any other value."""
    head = f"--vary {v.path}={','.join(v.written or (f'{v.low:g}', f'{v.high:g}'))}: valves.{name}.{v.path}"
    if isinstance(value, list):
        entries = [k for k in numeric_keys(section) if k.startswith(f"{v.path}.")][:2]
        return (f"{head} is a list ({value}) and cannot be varied continuously as a whole; vary one of its numbers by "
                f"its 1-based position, such as {' or '.join(entries)}" if entries else
                f"{head} is a list ({value}) and cannot be varied continuously; --vary takes a real-valued key under "
                "[valves.NAME], such as cam.phi1_deg or drive.spring_reserve")
    if isinstance(value, int) and not isinstance(value, bool):
        return (f"{head} is an integer ({value}) and cannot be varied continuously; --vary takes a real-valued key "
                "under [valves.NAME], such as cam.phi1_deg or drive.spring_reserve")
    return None


def check_bounds(section, name, variables) -> None:
    """Refuse a variable whose key cannot be varied continuously (an integer, a list), and bounds outside the allowed
    range of its key.

    Parameters
    ----------
    section : valvetrain.specification.models.Valve
        The valve's section.
    name : str
        The valve's name.
    variables : list of Variable

    Raises
    ------
    ValueError
        A key whose value is an integer or a list (:func:`not_continuous`); a bound that the key's own validation
        refuses, naming the bound as written and the key's allowed range.
    """
    data = section.model_dump(mode="json", exclude_unset=True, exclude_none=True)
    given = section.model_dump(mode="json")
    for v in variables:
        message = not_continuous(v, name, section, v.get(given))
        if message is not None:
            raise InputError(message)
        for i, (which, value) in enumerate((("LOW", v.low), ("HIGH", v.high))):
            trial = copy.deepcopy(data)
            try:
                v.put(trial, value)
                Valve.model_validate(trial)
            except (IndexError, TypeError):
                break  # not a key of the section: Problem names it
            except ValidationError as exc:
                for e in exc.errors():
                    at = ".".join(str(part + 1) if isinstance(part, int) else str(part) for part in e["loc"])
                    if at == v.path and e["type"] == "extra_forbidden":
                        raise InputError(unknown_key(v.path, name, section)) from None
                    if at == v.path:
                        written = v.written or (f"{v.low:g}", f"{v.high:g}")
                        reason = e["msg"].removeprefix("Value error, ")
                        raise InputError(f"--vary {v.path}={','.join(written)}: {which} = {written[i]} is outside "
                                         f"the range of valves.{name}.{v.path}: {reason}") from None
