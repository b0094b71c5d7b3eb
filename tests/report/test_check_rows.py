"""The checks as the report's rows show them (report/check_rows.py)."""

from dataclasses import replace

from valvetrain.checks import check
from valvetrain.design.drive_strength import not_given
from valvetrain.report.check_rows import check_class, check_margin, check_range, check_verdict, not_checked


def test_a_checks_row_says_its_kind_of_range_and_its_acceptance():
    """A failure's range is an allowable limit ("met" / "NOT MET"), a warning's a recommended one ("in range" /
    "outside"); an accepted failed check keeps its severity's class and says so; the margin of 85.07 m/s against
    50...80 m/s is (80 - 85.07) / 80 = -6.3375 %, printed with 4 significant figures."""
    passed = check("flow.throat_velocity", 70.0, 50, 80, source="s", unit="m/s", severity="failure")
    failed = check("flow.throat_velocity", 85.07, 50, 80, source="s", unit="m/s")
    accepted = replace(failed, accepted=True, reason="r")
    assert [check_class(c) for c in (passed, failed, accepted)] == ["pass", "warn", "warn accepted"]
    assert [check_verdict(c, "en") for c in (passed, failed, accepted)] == ["met", "outside", "outside; accepted"]
    assert check_verdict(failed, "ru") == "вне пределов"
    assert check_margin(failed, "en") == "-6.338 %" and check_margin(failed, "ru") == "-6,338 %"
    assert check_range(failed, "en") == "50...80 m/s" and check_range(failed, "ru") == "50...80 м/с"


def test_a_check_whose_parts_are_not_given_is_said_in_words():
    """The note keeps its record's English (results.json) and its codes, from which the report names the check and
    the keys in its language (the catalogues' [names]); a text without codes is shown as it is."""
    note = not_given("pushrod_buckling_margin", ["pushrod_length_mm", "pushrod_diameter_mm"])
    assert note == "pushrod_buckling_margin: not checked, parts.pushrod_length_mm, parts.pushrod_diameter_mm not given"
    assert not_checked(note, "en") == ("buckling safety factor of the pushrod: not checked, not given: pushrod length, "
                                       "mm, pushrod diameter, mm")
    assert not_checked(note, "ru") == ("запас устойчивости штанги: не проверено, не задано: длина штанги, мм, диаметр "
                                       "штанги, мм")
    assert not_checked("something else", "ru") == "something else"
