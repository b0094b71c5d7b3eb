"""The report's engine chapters (camshaft, phasers, breathing) and a specification section's inputs as rows."""

from types import SimpleNamespace

import pytest

from valvetrain.design import run
from valvetrain.report.engine_chapters import breathing_chapter, camshaft_chapter, flatten, phaser_chapters
from valvetrain.specification import example_spec, spec_document, validate


def test_a_sections_inputs_are_dotted_rows_without_the_unset():
    """The dotted key of a nested table, in the order given; an unset (None) value left out."""
    assert flatten({"a": 1.0, "b": {"c": 2, "d": None, "e": {"f": "x"}}, "g": None}) == [
        ("a", 1.0), ("b.c", 2), ("b.e.f", "x")]


def test_without_their_sections_an_engine_has_no_such_chapters():
    results = SimpleNamespace(camshaft=None, breathing=None, phasers={})
    assert camshaft_chapter(results, {}, {}) is None
    assert breathing_chapter(results, {}, {}) is None
    assert phaser_chapters(results, {}, {}, {}) == []


@pytest.fixture(scope="module")
def breathing():
    """The built-in example breathing at two conditions (3000 and 5000 rpm) and on a curve of two speeds."""
    doc = spec_document(example_spec())
    for valve in doc["valves"].values():
        valve["dynamics"]["speeds"] = 20
    condition = {"intake_pressure_kPa": 100.0, "intake_temperature_C": 25.0, "exhaust_pressure_kPa": 105.0}
    doc["breathing"] = {"mode": "motored", "wall_temperature_C": 150.0,
                        "conditions": [{"speed_rpm": 3000.0, **condition}, {"speed_rpm": 5000.0, **condition}],
                        "curve": {"speed_range_rpm": [2000.0, 6000.0], "points": 2, **condition}}
    return run(validate(doc)), doc


def test_the_breathing_chapter_has_a_column_a_condition_and_a_row_a_speed_of_the_curve(breathing):
    """Each condition's column holds its own figures (the speed as given, its volumetric efficiency as results.json
    has it); the curve's rows its speeds; the inputs the section's keys but the conditions and the curve; the files
    the tables written."""
    results, doc = breathing
    chapter = breathing_chapter(results, doc, {})
    rows = dict(zip(chapter["names"], chapter["rows"], strict=True))
    assert rows["speed_rpm"] == [3000.0, 5000.0]                       # the conditions as specified
    assert rows["volumetric_efficiency"] == [c.figures.volumetric_efficiency for c in results.breathing.conditions]
    assert [row[0] for row in chapter["curve_rows"]] == [2000.0, 6000.0]   # the curve's ends
    assert ("wall_temperature_C", 150.0) in chapter["inputs"]
    assert not any(k.startswith(("conditions", "curve")) for k, _ in chapter["inputs"])
    assert chapter["files"] == ["breathing_condition_1.csv", "breathing_condition_2.csv", "breathing_conditions.csv",
                                "breathing_curve.csv"]
