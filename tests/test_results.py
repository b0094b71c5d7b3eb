"""The typed-results machinery (valvetrain.results): the rows a result shows read from its attributes, its record for
results.json, and values shown without the float noise of their unit conversion."""

from dataclasses import dataclass
from typing import Optional

from valvetrain.checks import check
from valvetrain.results import quantity, record, shown
from valvetrain.units import DEG, MM, to_display


@dataclass(frozen=True)
class _Inner:
    preload: float = quantity("preload_N", "N", "preload")
    wire: float = quantity("wire_mm", "mm", "wire")


@dataclass(frozen=True)
class _Outer:
    preload: float = quantity("preload_N", "N", "preload")
    seat_angle: float = quantity("seat_angle_deg", "deg", "seat angle")
    extra: Optional[float] = quantity("extra_mm", "mm", "only for some designs", omit_none=True)
    inner: _Inner = quantity("inner", flatten=True)
    ratio: float = quantity("ratio", label="a ratio of more digits")
    hidden: float = 0.0


def test_a_value_converted_for_results_json_is_shown_as_written():
    """30 deg kept in radians is 29.999999999999996 deg converted back (one unit in the last place); results.json and
    a check's record show it as the specification wrote it, 30.  8/3 is kept as it is (its digits are not noise)."""
    assert to_display(30.0 * DEG, "deg") != 30.0                      # the noise a plain conversion carries
    rec = record(_Outer(100.0, 30.0 * DEG, None, _Inner(250.0, 4.2 * MM), 8.0 / 3.0))
    assert rec["seat_angle_deg"] == 30.0 and rec["wire_mm"] == 4.2   # as typed in the specification
    assert rec["ratio"] == 8.0 / 3.0
    seat = check("valve.seat_angle", 30.0 * DEG, 30.0 * DEG, 30.0 * DEG, unit="deg", source="a test")
    assert seat.as_dict()["value"] == 30.0 and seat.warning()["value"] == 30.0


def test_shown_rows_are_the_record_read_from_the_attributes():
    """Without names, shown() gives the record's rows in the order declared: a flattened result's rows in its place,
    a key it shares with the parent's in the parent's place with the nested value (as dict.update does), a None left
    out where results.json leaves it out, a field without metadata not shown.  Expected rows written out by hand."""
    result = _Outer(100.0, 45.0 * DEG, None, _Inner(250.0, 4.0 * MM), 0.5)
    rows = [("preload_N", 250.0), ("seat_angle_deg", 45.0), ("wire_mm", 4.0), ("ratio", 0.5)]
    assert shown(result) == rows
    assert record(result) == dict(rows)
    assert shown(result, "ratio", "preload") == [("ratio", 0.5), ("preload_N", 100.0)]   # named: the field's own
