"""Field types of the specification: bounded numbers with messages that state the allowed range.

Units are in the key names (``_mm``, ``_deg``, ``_rpm``, ``_MPa``); :mod:`.si` converts them to SI.
"""

from dataclasses import dataclass
import math
from typing import Annotated, Any

from pydantic import AfterValidator, BaseModel, ConfigDict, Field
from pydantic_core import core_schema

from ..errors import InputError
from ..locale import Note, NoteText, note, note_text


@dataclass(frozen=True)
class Range:
    """The bounds of a bounded field, kept in its annotation for the editors that draw an input for it (the
    designer in the browser), and its check: pydantic calls it after the float's own validation
    (:meth:`__get_pydantic_core_schema__`), with a message that states the whole range."""

    low: float
    high: float
    unit: str = ""
    low_open: bool = True
    high_open: bool = False
    whole: bool = False

    @property
    def allowed(self) -> Note:
        """The allowed range as the messages state it (a note: ``allowed (0, 5] mm`` in English).

        >>> Range(0.0, 5.0, "mm").text, note_text(Range(0.5, 20.0, "kg", low_open=False).allowed, "ru")
        ('allowed (0, 5] mm', 'допускается [0,5; 20] кг')
        """
        return note("field.allowed", open="(" if self.low_open else "[", low=self.low, high=self.high,
                    close=")" if self.high_open else "]", unit=_unit(self.unit))

    @property
    def text(self) -> NoteText:
        """:attr:`allowed` as a text: its English, keeping its parts."""
        return NoteText(self.allowed)

    def check(self, v) -> float:
        """``v`` if finite and within the bounds, else a ValueError stating the allowed range."""
        if not math.isfinite(v):
            raise InputError(NoteText(note("field.not_finite", allowed=self.allowed)))
        below = v <= self.low if self.low_open else v < self.low
        above = v >= self.high if self.high_open else v > self.high
        if below or above:
            raise InputError(self.text)
        return v

    def number(self, v) -> float:
        """``v`` if a number (not a bool; an integer if ``whole``), else a ValueError stating the allowed range: a
        unit string (``"10 mm"``) was 'Input should be a valid number', ``4.5`` for a count 'Input should be a valid
        integer', the range and the unit left out."""
        if self.whole and (isinstance(v, bool) or not isinstance(v, int)):
            raise InputError(NoteText(note("field.not_whole", allowed=self.allowed)))
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            raise InputError(NoteText(note("field.not_number", allowed=self.allowed)))
        return v

    def __get_pydantic_core_schema__(self, source, handler) -> core_schema.CoreSchema:
        """:meth:`number`, the float's schema, then :meth:`check` (the schemas ``BeforeValidator`` and
        ``AfterValidator`` make, built directly: a tenth of a millisecond less a field, at every start of the
        program)."""
        return core_schema.no_info_after_validator_function(
            self.check, core_schema.no_info_before_validator_function(self.number, handler(source)))


def _bounded(low, high, unit="", low_open=True, high_open=False):
    """A float constrained to a physical range, with a message that states the whole range."""
    return Annotated[float, Range(low, high, unit, low_open, high_open)]


def Whole(low, high) -> Any:  # noqa: N802 (a type factory)
    """An integer (a count) within [low, high], with a message that states the whole range."""
    return Annotated[int, Range(low, high, low_open=False, whole=True)]


def Length(low, high, **kw) -> Any:  # noqa: N802 (a type factory)
    """A float bounded to [low, high] in mm (:func:`_bounded`)."""
    return _bounded(low, high, "mm", **kw)


def _unit(unit) -> Note:
    """The unit of a range said after it (a note; none without a unit)."""
    return note("field.unit", unit=unit) if unit else ()


def _zero_or(low, high, unit="", zero="field.zero_none"):
    """A float that is either 0 (meaning ``zero``, a code of ``[notes]``) or within [low, high]: a tiny positive value
    is no quantity."""
    said = NoteText(note("field.zero_or", zero=note(zero), low=low, high=high, unit=_unit(unit)))

    def check(v):
        if not (v == 0.0 or low <= v <= high):
            raise InputError(said)
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
