"""What `valvetrain optimize` writes besides the specification (report/optimization.py): the history's columns, the
comparison's columns and the report, for a search of four evaluations and two limits written out here, the expected
values worked by hand."""

from html import escape
import re
from types import SimpleNamespace

import numpy as np
import pytest

from valvetrain.bibliography import WORKS
from valvetrain.checks import check
from valvetrain.report.optimization import comparison_columns, history_columns, history_figure, report_html

SOURCE = "Valve-train practical works (n.d.), work 1"


def _result(objective="fullness", history=None):
    """A search over two margins: evaluation 1 breaks the second limit, 2 and 3 keep both, 4 breaks the first."""
    history = history or [(0.50, (0.1, -0.2)), (0.60, (0.2, 0.1)), (0.55, (0.05, 0.3)), (0.70, (-0.1, 0.2))]
    holds = check("flow.throat_velocity", 60.0, 50.0, 80.0, source=SOURCE, unit="m/s")       # margin 0.2
    binds = check("flow.throat_velocity", 79.99, 50.0, 80.0, source=SOURCE, unit="m/s")       # margin 1.25e-4
    fails = check("flow.throat_velocity", 85.07, 50.0, 80.0, source=SOURCE, unit="m/s")       # margin -0.0634
    return SimpleNamespace(
        valve="intake", objective=objective, history=history, margin_names=("spring reserve", "no jump"),
        start_value=0.5, start={"phi1_deg": 27.0}, optimum={"phi1_deg": 25.5}, bounds=((20.0, 35.0),),
        comparison=[("fullness", "", 0.5, 0.6)], checks=[holds, binds, fails], checks_start=[], binding=[binds],
        limit_notes=[], polydyne_fullness=None, evaluations=4, seconds=1.5, seconds_in_evaluations=1.2)


def test_history_columns_by_hand():
    """Feasible where every margin >= 0: evaluations 2 and 3; the best feasible objective so far: none after the
    first, then 0.60 (the 0.70 of the fourth is outside the limits)."""
    cols = history_columns(_result())
    assert list(cols["evaluation"]) == [1, 2, 3, 4]
    assert list(cols["feasible"]) == [False, True, True, False]
    assert cols["fullness"] == pytest.approx([0.50, 0.60, 0.55, 0.70])
    best = cols["best_feasible_fullness"]
    assert np.isnan(best[0]) and list(best[1:]) == pytest.approx([0.60, 0.60, 0.60])
    assert list(cols["margin_spring_reserve"]) == [0.1, 0.2, 0.05, -0.1]
    assert list(cols["margin_no_jump"]) == [-0.2, 0.1, 0.3, 0.2]


def test_a_time_area_is_shown_in_mm2_s():
    """The time-area objective is SI inside (m^2 s) and mm^2 s in the columns: 2.5e-6 m^2 s = 2.5 mm^2 s."""
    cols = history_columns(_result("time_area", [(2.5e-6, (0.1, 0.1)), (3.0e-6, (0.1, -0.1))]))
    assert cols["time_area"] == pytest.approx([2.5, 3.0])
    assert cols["best_feasible_time_area"] == pytest.approx([2.5, 2.5])


def test_comparison_columns_and_history_figure():
    result = _result()
    result.comparison = [("fullness", "", 0.5, 0.6), ("max tappet acceleration", "m/s2", 3400.0, 3100.0)]
    assert comparison_columns(result) == {"quantity": ["fullness", "max tappet acceleration"], "unit": ["", "m/s2"],
                                          "start": [0.5, 3400.0], "optimum": [0.6, 3100.0]}
    fig = history_figure(result)
    top, bottom = fig.axes
    assert len(bottom.lines) == 2 + 1           # a margin each and the zero line


def test_the_report_states_which_limits_hold_bind_and_fail():
    """Margins of V' against 50...80 m/s, the smaller of (V' - 50) / 50 and (80 - V') / 80: 60 m/s has
    min(0.2, 0.25) = 0.2 and holds, 79.99 m/s 1.25e-4 < 1e-3 and binds, 85.07 m/s -0.0634 and fails; the binding one
    is named; the works the report cites are in its list of references."""
    page = report_html(_result())
    rows = page.split("<h2>Limits</h2>")[1].split("</table>")[0].split("<tr>")[2:]
    assert [r.rsplit("<td>", 1)[1].removesuffix("</td></tr>") for r in rows] == ["holds", "binds", "fails"]
    assert ["0.2000", "0.0001", "-0.0634"] == [r.split("<td>")[5].removesuffix("</td>") for r in rows]
    assert "<p>Limits that bind at the optimum: V′ (throat velocity).</p>" in page
    # the method's text cites UkrSURT Proceedings (2019) and Shang Hanji (1988): their references are listed
    listed = re.findall(r"<li>(.*?)</li>", page.split("<h2>References</h2>")[1])
    assert sorted(listed) == sorted(escape(WORKS[k].reference()) for k in ("ukrsurt2019", "shang1988"))
    assert 'lang="ru"' in report_html(_result(), "ru")


def test_the_notes_of_the_limits_are_in_the_reports_language():
    """A limit's note is rendered from its code in the report's language: the spring reserve checked with the
    search's spring scaled by 1.05 ("с исходной пружиной × 1,05"), the Hertz stress's cam width (the Russian report
    printed only the first, without its scale, and dropped every other note)."""
    from dataclasses import replace

    from valvetrain.locale import note, note_text

    result = _result()
    held = note("synthesis.start_spring_scaled", scale=1.05)
    width = note("synthesis.cam_width", width_mm=12.5, top=1.1)
    result.checks = [replace(c, note=note_text(parts), note_parts=parts)
                     for c, parts in zip(result.checks[:2], (held, width), strict=True)]
    assert escape("(with the starting design's spring x 1.05)") in report_html(result)
    russian = report_html(result, "ru")
    assert "(с исходной пружиной × 1,05)" in russian
    assert "(ширина кулачка 12,5 мм, от неподвижного вала до 1,1 номинальной частоты вращения)" in russian


def test_a_limits_range_is_written_as_the_design_report_writes_it():
    """Issue 41: the range of a limit in the report's language and units, as the design report's checks table writes
    it (report/check_rows.py check_range): "<= 4000 m/s²" and a limit without bounds "any" / "любое" (before, the
    English range with its unit's symbol replaced: "any" in the Russian report)."""
    result = _result()
    result.checks = [check("tappet_acceleration.max", 3400.0, high=4000.0, source=SOURCE, unit="m/s2"),
                     check("flow.throat_velocity", 60.0, source=SOURCE, unit="m/s")]
    for lang, ranges in (("en", ["&lt;= 4000 m/s²", "any"]), ("ru", ["&lt;= 4000 м/с²", "любое"])):
        rows = report_html(result, lang).split("</h2>")[3].split("</table>")[0].split("<tr>")[2:]
        assert [r.split("<td>")[4].removesuffix("</td>") for r in rows] == ranges, lang
