"""valvetrain compare: laws side by side at equal lift and duration (issue 5)."""

import json
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
    for name in ("lift", "velocity", "acceleration", "jerk"):
        assert (out / "plots" / f"compare_{name}.png").stat().st_size > 0
    assert (out / "compare.csv").read_text().startswith("quantity,")


def test_duration_at_1mm_against_the_analytic_law(tmp_path):
    """The duration at 1 mm valve lift of the seed 000 Kurz cam, from an independent root finding on (2.5)-(2.8)."""
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
