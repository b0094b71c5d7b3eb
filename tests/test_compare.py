"""valvetrain compare: laws side by side at equal lift and duration (issue 5)."""

import json
import re
from pathlib import Path

from click.testing import CliRunner
import numpy as np
import pytest
from scipy.optimize import brentq

from valvetrain.cli import main

EXAMPLES = Path(__file__).parents[1] / "examples"


def test_compare_two_files(tmp_path):
    out = tmp_path / "cmp"
    files = [str(EXAMPLES / "seed000-appendix-kurz.toml"), str(EXAMPLES / "seed000-polydyne.toml")]
    result = CliRunner().invoke(main, ["compare", *files, "--out", str(out)])
    assert result.exit_code == 0, result.output
    data = json.loads((out / "compare.json").read_text())
    kurz, poly = data["entries"]["seed000-appendix-kurz:intake"], data["entries"]["seed000-polydyne:intake"]
    # the same figures as the design run (spec 4.4-4.5): time-area 2.8564 vs 2.7657, j_max 3487.8 vs 4585.5
    assert kurz["time_area_mm2_s"] == pytest.approx(2.8564, abs=1e-4)
    assert poly["time_area_mm2_s"] == pytest.approx(2.7657, abs=1e-4)
    assert poly["max_acceleration_m_s2"] == pytest.approx(4585.5, abs=0.1)
    # equal lift and duration: the polydyne intake matches the Kurz lobe's lift; the exhaust valve is flagged
    assert kurz["valve_lift_mm"] == pytest.approx(poly["valve_lift_mm"])
    assert any("exhaust" in n for n in data["notes"])
    # without a [dynamics] section the default one is swept, 40 speeds over 10 %-125 % of the rated 7000 rpm
    assert kurz["sweep_speed_range_rpm"] == "700-8750 (40)" and kurz["harmonic_k"] >= 1
    for name in ("lift", "velocity", "acceleration", "jerk"):
        assert (out / "plots" / f"compare_{name}.png").stat().st_size > 0
    assert (out / "compare.csv").read_text().startswith("quantity,")


def test_duration_at_1mm_against_the_analytic_law(tmp_path):
    """The duration at 1 mm valve lift of the Kurz cam of Valve-train practical works (n.d.), from an independent root finding on (2.5)-(2.8)."""
    from conftest import seed000_law

    law = seed000_law()
    rise = brentq(lambda t: 1.6 * (law.lift(t) - 0.25e-3) - 1e-3, law.start + law.ramp_angle, 0.0)
    out = tmp_path / "c"
    CliRunner().invoke(main, ["compare", str(EXAMPLES / "seed000-appendix-kurz.toml"), "--out", str(out)])
    entry = json.loads((out / "compare.json").read_text())["entries"]["intake"]
    assert entry["duration_1mm_cam_deg"] == pytest.approx(np.degrees(-2 * rise), abs=1e-6)


def test_compare_refuses_bad_files(tmp_path):
    f = tmp_path / "bad.toml"
    f.write_text("[engine]\nbore_mm = 80\n")
    result = CliRunner().invoke(main, ["compare", str(f), "--out", str(tmp_path / "c")])
    assert result.exit_code == 2
    assert not (tmp_path / "c").exists()


def test_files_of_the_same_name_are_all_compared(tmp_path):
    """v1/engine.toml and v2/engine.toml: each valve of each file is a column (one was silently dropped)."""
    for d in ("v1", "v2"):
        (tmp_path / d).mkdir()
        (tmp_path / d / "engine.toml").write_text((EXAMPLES / "seed000-appendix-kurz.toml").read_text())
    out = tmp_path / "cmp"
    files = [str(tmp_path / "v1" / "engine.toml"), str(tmp_path / "v2" / "engine.toml"),
             str(tmp_path / "v2" / "engine.toml")]
    result = CliRunner().invoke(main, ["compare", *files, "--out", str(out)])
    assert result.exit_code == 0, result.output
    entries = json.loads((out / "compare.json").read_text())["entries"]
    assert sorted(entries) == ["v1/engine:intake", "v2/engine (1):intake", "v2/engine (2):intake"]


DYNAMICS_EXAMPLE = EXAMPLES / "dynamics-comparison"


def test_comparative_dynamics_table_of_the_worked_example(tmp_path):
    """The worked example of the comparative dynamics of cam profiles (Valve-train dynamics article (n.d.), as
    corrected in the methods notes): r0 = 20 mm, h_T = 6 mm, half action angle 60 deg, phi1 = 23 deg, i_k = 1.5,
    n = 5000 rpm, m = 0.2458 kg, C_mgr = 2742.9 N/mm, P0 = 200 N, K3 = 1.8.  Its table, to the digits printed:
    three-arc C_pr 71.43 N/mm, f0 539 Hz, k 12, F_k 62.3 N, Delta 207 um, delta 2.52 %; polydyne (2, 10, 18, 26,
    34) 67.30 N/mm, 538 Hz, 12, 84.3 N, 280 um, 3.39 %."""
    out = tmp_path / "cmp"
    files = [str(DYNAMICS_EXAMPLE / f"{n}.toml") for n in ("three-arc", "kurz", "polydyne")]
    result = CliRunner().invoke(main, ["compare", *files, "--out", str(out)])
    assert result.exit_code == 0, result.output
    data = json.loads((out / "compare.json").read_text())["entries"]
    table = {"three-arc:intake": (71.43, 539, 12, 62.3, 207, 2.52), "polydyne:intake": (67.30, 538, 12, 84.3, 280, 3.39)}
    for label, (c_pr, f0, k, force, amplitude, delta) in table.items():
        e = data[label]
        assert e["spring_rate_N_per_mm"] == pytest.approx(c_pr, abs=0.005)
        assert e["drive_stiffness_N_per_mm"] == pytest.approx(2742.9, abs=0.05)
        assert e["reduced_mass_kg"] == 0.2458 and e["spring_preload_N"] == 200.0
        assert e["natural_frequency_Hz"] == pytest.approx(f0, abs=0.5)
        assert e["harmonic_k"] == k
        assert e["harmonic_force_N"] == pytest.approx(force, abs=0.05)
        assert e["amplitude_mm"] * 1e3 == pytest.approx(amplitude, abs=0.5)
        assert e["distortion_percent"] == pytest.approx(delta, abs=0.005)
    # equal lift and main event; every design has the simulated jump speed of its short sweep and the drive load
    for e in data.values():
        assert e["valve_lift_mm"] == pytest.approx(9.0) and e["duration_cam_deg"] == pytest.approx(120.0)
        assert e["sweep_speed_range_rpm"] == "1000-7000 (40)"
        assert e["jump_speed_rpm"] is None or 1000.0 <= e["jump_speed_rpm"] <= 7000.0
        assert e["max_drive_load_N"] > e["spring_preload_N"]
    csv = (out / "compare.csv").read_text()
    assert "natural frequency f0" in csv and "distortion delta, %" in csv
    assert (out / "plots" / "compare_dynamics.png").stat().st_size > 0


def test_max_drive_load_against_a_hand_computation():
    """F0 + K y + M j: at rest the spring force at full lift, and at speed the positive-acceleration peak,
    against a direct evaluation on a fine grid (Shang Hanji (1988),
    eqs. (2.8)-(2.9))."""
    from valvetrain.compare import max_drive_load
    from valvetrain.laws import PolydyneLaw

    law = PolydyneLaw(6e-3, np.radians(60), 10)
    omega = np.pi * 5000 / 60
    theta = np.linspace(law.start, law.end, 200001)
    h, _, d2h = law.derivatives(theta)[:3]
    direct = np.max(200.0 + 70e3 * 1.5 * h + 0.2458 * 1.5 * omega**2 * d2h)
    assert max_drive_load(law, omega, 1.5, 0.2458, 70e3, 200.0) == pytest.approx(direct, rel=1e-5)
    assert max_drive_load(law, 0.0, 1.5, 0.2458, 70e3, 200.0) == pytest.approx(200.0 + 70e3 * 9e-3, rel=1e-12)


def test_a_value_not_computed_is_empty_not_nan(tmp_path):
    """The marine example has no cam width (no contact stress) and its one-mass train does not jump up to 125 % of
    its rated speed: both cells are empty in the printed table and the CSV and null in compare.json (they printed
    'nan', against the label's 'empty: none in the range')."""
    out = tmp_path / "cmp"
    result = CliRunner().invoke(main, ["compare", str(EXAMPLES / "marine-hydraulic-exhaust.toml"), "--out", str(out)])
    assert result.exit_code == 0, result.output
    assert not re.search(r"\bnan\b", result.output, re.I)
    assert not re.search(r"\bnan\b", (out / "compare.csv").read_text(), re.I)
    entry = json.loads((out / "compare.json").read_text())["entries"]["exhaust"]
    assert entry["max_contact_stress_MPa"] is None and entry["jump_speed_rpm"] is None


def test_breathing_side_by_side(tmp_path):
    """Two specifications with [breathing] (the TCC-III example and the same engine with 400 mm runners) are compared
    condition by condition: compare_breathing.csv holds each file's three conditions, compare.json their records,
    and the longer runners breathe differently at 1300 rpm (a runner's tuning shows)."""
    long = tmp_path / "long.toml"
    long.write_text((EXAMPLES / "tcc3-motored.toml").read_text(encoding="utf-8").replace(
        "runner_length_mm = 279.86", "runner_length_mm = 400.0"), encoding="utf-8")
    (tmp_path / "data").mkdir()
    for f in (EXAMPLES / "data").glob("tcc3-*.csv"):
        (tmp_path / "data" / f.name).write_text(f.read_text(encoding="utf-8"), encoding="utf-8")
    out = tmp_path / "cmp"
    result = CliRunner().invoke(main, ["compare", str(EXAMPLES / "tcc3-motored.toml"), str(long), "--out", str(out)])
    assert result.exit_code == 0, result.output
    rows = (out / "compare_breathing.csv").read_text(encoding="utf-8").splitlines()
    assert rows[0].startswith("label,part,speed_rpm,intake_pressure_kPa,air_mass_flow_g_s,volumetric_efficiency")
    assert [r.split(",")[0] for r in rows[1:]] == ["tcc3-motored"] * 3 + ["long"] * 3
    records = json.loads((out / "compare.json").read_text(encoding="utf-8"))["breathing"]
    short, longer = (records[k]["conditions"][1]["volumetric_efficiency"] for k in ("tcc3-motored", "long"))
    assert abs(longer / short - 1.0) > 1e-3
    assert (out / "plots" / "compare_breathing.png").exists() and not (out / "compare.csv").exists()
