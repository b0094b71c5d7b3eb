"""Measured lift tables (seed 002 sections 5.1-5.3; spec/methods-seeds-002-004.md sections 9-11)."""

import json
from pathlib import Path

from click.testing import CliRunner
import numpy as np
import pytest
from scipy.optimize import brentq

from valvetrain.cli import main
from valvetrain.design import run
from valvetrain.laws import measured
from valvetrain.laws.measured import TableFileError, TableLaw, harmonic_fit, read_lift_table, symmetry_shift
from valvetrain.spec import load_spec

from conftest import seed000_law

EXAMPLE = Path(__file__).parents[1] / "examples" / "measured-lobe.toml"
EXAMPLE_TABLE = EXAMPLE.parent / "data" / "measured-intake-lobe.csv"
"""Valve lift every 2 crank deg from -70 to 300: the seed 000 appendix lobe x 1.6, 3 crank deg late, 2 um noise."""


def _write_table(path, angle, lift):
    path.write_text("angle_deg,lift_mm\n" + "".join(f"{a:.10g},{h:.10g}\n" for a, h in zip(angle, lift)))
    return path


def _sampled(shift_deg=0.0, noise=0.0, step_deg=1.0):
    law = seed000_law()
    theta = np.radians(np.arange(-92.0, 92.01, step_deg))
    lift = law.lift(theta) + np.random.default_rng(7).normal(0.0, noise, theta.size)
    return law, theta + np.radians(shift_deg), lift


def test_harmonic_fit_residual_on_a_smooth_law():
    """An N-harmonic approximation of the seed 000 Kurz lift: the residual falls with N, below 1 um by N = 30."""
    _, theta, lift = _sampled()
    rms = []
    for n in (8, 16, 30):
        a, b, w = harmonic_fit(theta, lift, n, 1.15 * theta.max())
        k = np.arange(n + 1)
        fit = np.cos(np.outer(theta, k * w)) @ a + np.sin(np.outer(theta, k * w)) @ b
        rms.append(np.sqrt(np.mean((fit - lift) ** 2)))
    assert rms[0] > rms[1] > rms[2]
    assert rms[2] < 1e-6


@pytest.mark.parametrize("shift", [-4.0, 0.0, 2.5, 7.0])
def test_nose_finding_recovers_a_known_shift(shift):
    """The symmetry axis of a symmetric lobe measured from a shifted origin is found again (spec section 10)."""
    _, theta, lift = _sampled(shift, noise=2e-6)
    law = TableLaw(theta, lift)
    assert np.degrees(law.centre) == pytest.approx(shift, abs=0.01)
    assert law.asymmetry_rms < 5e-6  # the remaining (true) asymmetry is at the noise level


def test_nose_finding_does_not_depend_on_the_order():
    """A lobe 2.5 deg off the origin with 2 um noise (spec section 10): the axis found from fits of order 8 to 60 is
    the known shift to 0.01 deg. A fit of high order over a window shorter than its period has large coefficients
    that cancel inside the data; the odd part is therefore measured over the data, not by sum b_k^2."""
    _, theta, lift = _sampled(2.5, noise=2e-6)
    top = int(np.argmax(lift))
    for n in (8, 25, 40, 60):
        a, b, w = harmonic_fit(theta - theta[top], lift, n, 1.15 * (theta[-1] - theta[top]))
        shift, odd = symmetry_shift(a, b, w, theta[top] - theta[0])
        assert np.degrees(theta[top] + shift) == pytest.approx(2.5, abs=0.01)
        assert odd < 2e-6   # the remaining odd part is below the noise


def test_an_accuracy_finer_than_the_noise_is_a_warning():
    """accuracy_mm = 1e-5 on a table with 2 um noise: the N-harmonic fit cannot meet it by max_harmonics; the law
    warns (spec section 9), and the lobe centre found from that overfitted series is still the true axis (0) to
    0.01 deg."""
    _, theta, lift = _sampled(noise=2e-6)
    law = TableLaw(theta, lift, accuracy=1e-8)
    assert law.harmonics == 60 and law.checks()[0].quantity == "measured table: rms residual of the N-harmonic fit"
    assert TableLaw(theta, lift, accuracy=5e-6).checks() == []
    assert np.degrees(law.centre) == pytest.approx(0.0, abs=0.01)


def test_durations_at_checking_heights():
    """Durations of the fitted table against root finding on the analytic law (0.1, 0.5, 1.0 mm, 0.050 in)."""
    exact, theta, lift = _sampled(step_deg=0.5)
    law = TableLaw(theta, lift)
    for h_mm in (0.1, 0.5, 1.0, 1.27):
        h = h_mm * 1e-3
        rise = brentq(lambda t, h=h: exact.lift(t) - h, exact.start, 0.0)
        assert law.duration(h) == pytest.approx(-2 * rise, abs=np.radians(0.02))


def test_spline_and_harmonic_quality():
    _, theta, lift = _sampled(noise=2e-6)
    law = TableLaw(theta, lift)
    for kind in ("spline", "harmonic"):
        q = law.quality(kind)
        assert q.rms_residual < 5e-6 and q.max_residual < 2e-5
        assert q.jerk_sign_changes >= 2


BAD = [("angle,lift\n", ":1: header 'angle,lift': allowed 'angle_deg,lift_mm'"), ("angle_deg,lift_mm\n0,1\n1,x\n", ":3: '1,x' is not two numbers"),
       ("angle_deg,lift_mm\n" + "".join(f"{a},0\n" for a in range(12)) + "5,0\n", ":14: angle_deg = 5 must be larger"),
       ("angle_deg,lift_mm\n0,0\n1,0\n", "at least 10 rows")]


@pytest.mark.parametrize("text,message", BAD)
def test_bad_tables(tmp_path, text, message):
    f = tmp_path / "t.csv"
    f.write_text(text)
    with pytest.raises(TableFileError, match=message):
        read_lift_table(f)


def test_measured_example_runs():
    """The synthetic measurement of the seed 000 lobe (3 crank deg late): the table sets the timing."""
    res = run(load_spec(EXAMPLE))
    m = res.to_dict()["valves"]["intake"]["cam"]["measured"]
    assert m["lobe_centre_deg"] == pytest.approx(119.0, abs=0.05)      # nose at 116 + 3 crank deg
    assert m["max_lift_mm"] == pytest.approx(10.0, abs=0.01)
    assert [d["height_mm"] for d in m["durations_deg"]] == [0.1, 0.5, 1.0, 1.27]
    assert all(np.isfinite(d["duration_deg"]) for d in m["durations_deg"])
    assert res.valves["intake"].nose_crank == pytest.approx(np.radians(119.0), abs=1e-3)


def test_inconsistent_timing_is_a_warning(tmp_path):
    """Timing and lift given beside a table: 40 deg against the table's 17.1 (the example's opening at 0.1 mm) is
    flagged, 75 deg closing agrees; 10.5 mm lift against the table's 10.0 (5 %) is flagged, 10.05 (0.5 %) is not."""
    def names(given):
        text = EXAMPLE.read_text().replace("# max_lift_mm, opens_deg and closes_deg may be given", given + "\n#")
        f = tmp_path / "m.toml"
        f.write_text(text.replace('table_file = "data/', f'table_file = "{EXAMPLE.parent}/data/'))
        return {w.quantity for w in run(load_spec(f)).warnings}

    flagged = names("opens_deg = 40.0\ncloses_deg = 75.0\nmax_lift_mm = 10.5")
    assert "intake: opens_deg against the measured table" in flagged
    assert "intake: closes_deg against the measured table" not in flagged
    assert "intake: max_lift_mm against the measured table" in flagged
    assert "intake: max_lift_mm against the measured table" not in names("max_lift_mm = 10.05")


def test_bad_table_file_exits_2(tmp_path, refused):
    (tmp_path / "t.csv").write_text("angle_deg,lift_mm\n0,0\n1,abc\n")
    assert "t.csv:3:" in refused(EXAMPLE.read_text().replace("data/measured-intake-lobe.csv", "t.csv"), "run")


def test_lift_and_timing_keys_required_for_other_laws(refused):
    from valvetrain.spec import example_text

    output = refused(example_text().replace("opens_deg = 26.0", "").replace("max_lift_mm = 10.0", ""))
    assert "valves.intake.opens_deg: required key is missing" in output
    assert "valves.intake.max_lift_mm: required key is missing" in output


def test_table_cams_get_the_common_checks(refused):
    """A measured-table cam sets its own timing but not its geometry: a throat wider than the bore is refused."""
    text = (EXAMPLE.read_text().replace("throat_diameter_mm = 36.8", "throat_diameter_mm = 85.0")
            .replace('table_file = "data/', f'table_file = "{EXAMPLE.parent}/data/'))
    assert "valves.intake.throat_diameter_mm = 85 must be smaller than engine.bore_mm = 80" in refused(text)


def test_report_shows_the_measured_analysis(tmp_path):
    """The report carries the measured table's analysis: durations at the checking heights of results.json (0.1, 0.5,
    1.0 mm and 0.050 in = 1.27 mm) and the quality of both fits."""
    out = tmp_path / "d"
    assert CliRunner().invoke(main, ["run", str(EXAMPLE), "--out", str(out)]).exit_code == 0
    html = (out / "report.html").read_text()
    data = json.loads((out / "results.json").read_text())["valves"]["intake"]["cam"]
    assert "Measured lift table" in html and "sign changes of the jerk" in html
    for d in data["measured"]["durations_deg"]:
        assert f'<td class="n">{d["height_mm"]:.6g}</td><td class="n">{d["duration_deg"]:.6g}</td>' in html
    assert "seed 002, sections 5.1-5.3; GCV smoothing spline" in html


def test_too_many_rows(tmp_path, monkeypatch):
    """A table of more rows than MAX_TABLE_ROWS (10^6; 50 here) is refused when read, naming the file."""
    monkeypatch.setattr(measured, "MAX_TABLE_ROWS", 50)
    with pytest.raises(TableFileError, match=r"t.csv: 60 rows; allowed at most 50"):
        read_lift_table(_write_table(tmp_path / "t.csv", np.arange(60.0), np.zeros(60)))


def test_the_plain_and_the_line_reader_agree(tmp_path, monkeypatch):
    """A plain file is parsed in one numpy call, one with comments line by line: the same numbers either way
    (the example table has comment lines; without them, with CRLF line ends, it takes the plain path, which does
    not call the line reader)."""
    from valvetrain import csvfiles

    angle, lift = read_lift_table(EXAMPLE_TABLE)
    plain = "\r\n".join(line for line in EXAMPLE_TABLE.read_text().splitlines() if not line.startswith("#"))
    (tmp_path / "plain.csv").write_text(plain, newline="")
    monkeypatch.setattr(csvfiles, "read_two_columns", None)
    again = read_lift_table(tmp_path / "plain.csv")
    assert np.array_equal(again[0], angle) and np.array_equal(again[1], lift)
    assert angle.size == 186 and lift.max() == 10.0032


def test_echoed_rows_are_cut(tmp_path):
    """Issue 9: a row of 10,000 characters is echoed as its first 40 and '...'."""
    f = tmp_path / "t.csv"
    f.write_text("angle_deg,lift_mm\n0,0\n1," + "9" * 10_000 + "x\n")
    with pytest.raises(TableFileError) as err:
        read_lift_table(f)
    assert str(err.value) == f"{f}:3: '1,{'9' * 38}...' is not two numbers"
