"""The report of a tolerance study (report/tolerance.py): the histograms' SVG geometry worked by hand, the names of
the tolerances' keys, and the table of failing checks ordered by probability with the tolerance that drives each,
for a study summary written out here."""

import re

from valvetrain.bibliography import cite
from valvetrain.report.tolerance import HEIGHT, WIDTH, histogram_svg, key_name, report_html


def test_histogram_bars_and_bound_by_hand():
    """edges 0, 1, 2, 4 and counts 2, 4, 1 on 320 x 120 px: 80 px per unit; the tallest bar (4) is 120 - 14 = 106 px
    high, so heights 53, 106, 26.5 px from y = 67, 14, 93.5; widths 80 - 1, 80 - 1, 160 - 1 px; the bound at 1.5
    draws a line at x = 120 px."""
    assert (WIDTH, HEIGHT) == (320, 120)
    svg = histogram_svg({"edges": [0.0, 1.0, 2.0, 4.0], "counts": [2, 4, 1]}, mark=1.5)
    bars = re.findall(r'<rect x="([\d.]+)" y="([\d.]+)" width="([\d.]+)" height="([\d.]+)"', svg)
    assert [tuple(map(float, b)) for b in bars] == [(0.0, 67.0, 79.0, 53.0), (80.0, 14.0, 79.0, 106.0),
                                                    (160.0, 93.5, 159.0, 26.5)]
    assert '<line x1="120.0" x2="120.0"' in svg
    assert ">0</text>" in svg and ">4</text>" in svg
    assert "<line" not in histogram_svg({"edges": [0.0, 1.0, 2.0, 4.0], "counts": [2, 4, 1]}, mark=-0.5)
    assert "<line" not in histogram_svg({"edges": [0.0, 1.0], "counts": [0]})


def test_key_names():
    """A valve's key: the valve as its name, then the key's label; a key without a name as the file gives it."""
    assert key_name("valves.intake.max_lift_mm", "en") == '<span class="name">intake</span>: valve lift h_v max, mm'
    assert key_name("valves.intake.no_such_key_mm", "en") == '<code class="name">valves.intake.no_such_key_mm</code>'


def _check(probability, failures, sensitivities):
    return {"code": "flow.throat_velocity", "params": {}, "valve": "intake", "severity": "warning", "accepted": False,
            "probability": probability, "failures": failures, "samples": 100,
            "confidence_95": (probability / 2, probability * 1.5), "sensitivities": sensitivities, "margin": None}


def _study(checks):
    return {"tolerances": [{"key": "engine.bore_mm", "distribution": "uniform", "nominal": 80.0, "half_range": 0.05,
                            "low": 79.95, "high": 80.05}],
            "checks": checks, "headlines": {}, "samples": 100, "method": "lhs", "seed": 7,
            "refused": {"samples": 0, "probability": 0.0}}


def test_failing_checks_by_probability_with_their_driver():
    """Two failing checks (0.05 and 0.30) and one that never fails: the table lists the two, the likelier first, each
    with the tolerance of the largest |rank correlation| (-0.8 beats 0.5); the method's text cites Devroye (1986) and
    Wilson (1927) by the bibliography's short form."""
    page = report_html(_study({
        "a": _check(0.05, 5, {"engine.bore_mm": 0.5, "valves.intake.max_lift_mm": -0.8}),
        "b": _check(0.30, 30, {"engine.bore_mm": 0.2, "valves.intake.max_lift_mm": None}),
        "c": _check(0.0, 0, {"engine.bore_mm": 0.9})}))
    rows = page.split("Checks that fail in some sample")[1].split("</table>")[0].split("<tr>")[2:]
    assert len(rows) == 2
    assert "<td>30 / 100</td><td>0.3</td><td>0.15...0.45</td>" in rows[0]
    assert rows[0].endswith("(+0.20)</td></tr>") and "(-0.80)" in rows[1]
    assert '<span class="name">intake</span>: valve lift h_v max, mm (-0.80)' in rows[1]
    assert cite("devroye1986") in page and cite("wilson1927") in page
    assert "100 samples (Latin hypercube, random seed = 7); 0 refused" in page


def test_no_failing_check_says_so():
    page = report_html(_study({"c": _check(0.0, 0, {"engine.bore_mm": 0.9})}))
    assert "<p>No check fails in any sample.</p>" in page and "<th>check</th>" not in page
    assert 'lang="ru"' in report_html(_study({}), "ru")


def test_sobol_bars_by_hand():
    """S_i = 0.25 +- 0.05 and S_Ti = 0.5 +- 0.6 on 200 px for the index 1: bars 50 and 100 px wide (rows at y = 2 and
    13 px, 9 px high), error bars 40...60 px and, clipped to 0 ... 1, 0...200 px (-0.1 ... 1.1) at the rows' middles
    6.5 and 17.5 px."""
    from valvetrain.report.tolerance import INDEX_WIDTH, indices_svg

    assert INDEX_WIDTH == 200
    svg = indices_svg({"first": 0.25, "first_95": 0.05, "total": 0.5, "total_95": 0.6})
    bars = re.findall(r'<rect x="0" y="(\d+)" width="([\d.]+)" height="9"', svg)
    assert [tuple(map(float, b)) for b in bars] == [(2.0, 50.0), (13.0, 100.0)]
    assert '<line x1="40.0" x2="60.0" y1="6.5" y2="6.5"' in svg
    assert '<line x1="0.0" x2="200.0" y1="17.5" y2="17.5"' in svg
