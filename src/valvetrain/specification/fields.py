"""Field types of the specification: bounded numbers with messages that state the allowed range.

Units are in the key names (``_mm``, ``_deg``, ``_rpm``, ``_MPa``); :mod:`.si` converts them to SI.
"""

from dataclasses import dataclass
import math
from typing import Annotated, Any

from pydantic import AfterValidator, BaseModel, ConfigDict, Field


@dataclass(frozen=True)
class Range:
    """The bounds of a bounded field, kept in its annotation for the editors that draw an input for it (the
    designer in the browser): pydantic ignores it, the field's validator enforces it."""

    low: float
    high: float
    unit: str = ""
    low_open: bool = True
    high_open: bool = False


def _bounded(low, high, unit="", low_open=True, high_open=False):
    """A float constrained to a physical range, with a message that states the whole range."""
    lo_sym, hi_sym = ("(" if low_open else "["), (")" if high_open else "]")
    text = f"allowed {lo_sym}{low:g}, {high:g}{hi_sym}{' ' + unit if unit else ''}"

    def check(v):
        if not math.isfinite(v):
            raise ValueError(f"must be a finite number; {text}")
        below = v <= low if low_open else v < low
        above = v >= high if high_open else v > high
        if below or above:
            raise ValueError(text)
        return v

    return Annotated[float, AfterValidator(check), Range(low, high, unit, low_open, high_open)]


def Length(low, high, **kw) -> Any:  # noqa: N802 (a type factory)
    """A float bounded to [low, high] in mm (:func:`_bounded`)."""
    return _bounded(low, high, "mm", **kw)


def _zero_or(low, high, unit="", zero="none"):
    """A float that is either 0 (meaning ``zero``) or within [low, high]: a tiny positive value is no quantity."""
    suffix = f" {unit}" if unit else ""

    def check(v):
        if not (v == 0.0 or low <= v <= high):
            raise ValueError(f"allowed 0 ({zero}) or [{low:g}, {high:g}]{suffix}")
        return v

    return Annotated[float, AfterValidator(check)]


def Pair(low, high, unit="") -> Any:  # noqa: N802 (a type factory, like Length)
    """Two bounded numbers, written as a TOML array ``[a, b]``."""
    return Annotated[tuple[_bounded(low, high, unit), _bounded(low, high, unit)], Field(strict=False)]


RAMP_VELOCITY = _bounded(0.001, 1.0, "mm/deg", low_open=False)
"""Tappet velocity at the end of a ramp; Valve-train practical works (n.d.), work 2 recommends 0.008-0.022 mm/deg, and below 0.001 mm/deg
a ramp of the usual clearance would outlast the whole cam revolution."""

SEGMENT_ANGLE = _bounded(0.1, 180.0, "deg", low_open=False)
"""A segment of a lift law [cam deg]: below 0.1 deg the accelerations of any law leave every physical scale."""


class _Model(BaseModel):
    """A section of the specification: unknown keys refused, no silent type coercion, immutable (hashable views)."""

    model_config = ConfigDict(extra="forbid", strict=True, frozen=True)
