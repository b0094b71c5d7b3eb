"""The report's chapter of a switching roller finger (valvetrain.report.switching): every row named in English and
Russian from the catalogue, the sweep's table the record's, the checks in their chapter."""

from pathlib import Path

import pytest

from valvetrain.design import run
from valvetrain.locale import catalogue
from valvetrain.report.check_rows import chapter_checks, check_chapter
from valvetrain.report.switching import switching_chapters
from valvetrain.specification import load_spec, spec_document, validate

EXAMPLE = Path(__file__).parents[2] / "examples" / "switching-finger.toml"


@pytest.fixture(scope="module")
def results():
    doc = spec_document(load_spec(EXAMPLE))
    del doc["valves"]["exhaust"]
    doc["valves"]["intake"]["lash_adjuster"] = None
    return run(validate(doc))


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_every_row_has_its_words(results, lang):
    (chapter,) = switching_chapters(results, chapter_checks(results), lang)
    names = catalogue(lang)["switching"]["names"]
    assert set(names) == set(catalogue("en")["switching"]["names"])
    assert all(key in names for key, _ in chapter["rows"])
    assert len(chapter["rows"]) == 28                        # jump speed found, the air spring given: every row
    record = results.to_dict()["switching"]["intake"]
    assert chapter["speeds"] == list(zip(record["sweep_speeds_rpm"], record["arm_contact_force_min_N"]))
    assert {c.code for c in chapter["checks"]} == {"switching.jump_speed", "switching.valve_held",
                                                   "switching.spring_stress", "switching.latch_stress",
                                                   "switching.latch_time"}


def test_switching_checks_have_their_chapter():
    assert check_chapter("switching.latch_stress") == "switching"
