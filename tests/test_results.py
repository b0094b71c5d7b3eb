"""The typed-results machinery (valvetrain.results): the rows a result shows read from its attributes, its record for
results.json, and values shown without the float noise of their unit conversion."""

from dataclasses import dataclass
from typing import Optional

import numpy as np

from valvetrain.checks import check
from valvetrain.export import json_text
from valvetrain.report.numbers import percent
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


@dataclass(frozen=True)
class _Angles:
    cam: tuple[float, ...] = quantity("angle_cam_deg", "cam deg", "angles from the nose")
    crank: float = quantity("opens_crank_deg", "crank deg", "an event")
    twist: float = quantity("twist_cam_deg", "cam deg", "a small angle of many digits")


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


def test_a_margin_in_the_record_is_the_margin_of_the_numbers_it_shows():
    """The relative margin of a record is worked out from its shown value and bounds in decimal, by hand:
    seat angle 45 deg against 30...30 deg: (30 - 45) / 30 = -0.5 (not -0.5000000000000001, the margin of the radians);
    closing lag 78 against 40...60 crank deg: (60 - 78) / 60 = -0.3; a throat area share 0.40625 against 0.25...0.4:
    (0.4 - 0.40625) / 0.4 = -0.015625; a value on its bound: 0 (not -0.0); a bound of 0 divides by 1 in SI, as
    :attr:`Check.margin` says: 2 mm against <= 0 mm is -0.002.  The report prints the first as -50 %."""
    seat = check("valve.seat_angle", 45.0 * DEG, 30.0 * DEG, 30.0 * DEG, unit="deg", source="a test")
    assert seat.margin != -0.5                                         # the noise of the SI margin
    assert seat.as_dict()["margin"] == -0.5 and seat.warning()["margin"] == -0.5
    assert '"margin": -0.5\n' in json_text(seat.warning())
    assert percent(seat.margin) == "-50 %"
    lag = check("timing.closing_lag", 78.0 * DEG, 40.0 * DEG, 60.0 * DEG, unit="crank deg", source="a test")
    assert lag.as_dict()["margin"] == -0.3
    share = check("engine.throat_area_share", 0.40625, 0.25, 0.4, source="a test")
    assert share.margin != -0.015625 and share.as_dict()["margin"] == -0.015625
    bound = check("valve.seat_angle", 30.0 * DEG, 30.0 * DEG, 30.0 * DEG, unit="deg", source="a test")
    assert repr(bound.as_dict()["margin"]) == "0.0"
    gap = check("profile.rho_min", 2e-3, high=0.0, unit="mm", source="a test")
    assert gap.as_dict()["margin"] == -0.002


def test_an_angle_on_a_turn_is_shown_without_the_noise_of_the_turn():
    """An angle computed in radians on a revolution carries the round-off of the turn: the grid point k = 1799 of 3600
    from -180 deg is -180 + 1799 x 0.1 = -0.1 deg by hand, -0.10000000000001923 as computed; an event 250 - 2 x 138 =
    -26 crank deg.  The record shows -0.1 and -26; a small angle of many digits (a twist) keeps them."""
    grid = -np.pi + 2.0 * np.pi * np.arange(3600) / 3600
    event = 250.0 * DEG - 2.0 * 138.0 * DEG
    assert to_display(grid[1799], "cam deg") != -0.1 and to_display(event, "crank deg") != -26.0
    rec = record(_Angles((grid[1799], grid[1801], grid[0]), event, 0.11399658396381009 * DEG))
    assert rec == {"angle_cam_deg": [-0.1, 0.1, -180.0], "opens_crank_deg": -26.0,
                   "twist_cam_deg": 0.11399658396381009}


def test_shown_without_nested_records_reads_only_the_numbers():
    """shown(result, nested=False) gives the rows of a table of numbers: a field holding a record of its own is left
    out before it is made into an object, a flattened result's numbers stay.  Rows written out by hand."""
    @dataclass(frozen=True)
    class _WithNested:
        preload: float = quantity("preload_N", "N", "preload")
        nested: _Inner = quantity("nested", label="a record of its own")
        inner: _Inner = quantity("inner", flatten=True)

    result = _WithNested(100.0, _Inner(1.0, 1.0 * MM), _Inner(250.0, 4.0 * MM))
    assert shown(result, nested=False) == [("preload_N", 250.0), ("wire_mm", 4.0)]
    assert dict(shown(result))["nested"] == {"preload_N": 1.0, "wire_mm": 1.0}
