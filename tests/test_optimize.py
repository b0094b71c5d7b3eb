"""valvetrain optimize: the power-polynomial cam's parameters maximising the fullness under the limits of
UkrSURT Proceedings (2019), on the 26/27 diesel example (a short search; the full one is the command's default)."""

import json
from pathlib import Path

from click.testing import CliRunner
import pytest

from valvetrain.cli import main
from valvetrain.design import run
from valvetrain.specification.validate import load_spec, parse_spec
from valvetrain.synthesis.constraints import Limits
from valvetrain.synthesis.optimize import Problem, optimize_valve

EXAMPLE = Path(__file__).parents[1] / "examples" / "ukrsurt2019-diesel.toml"


def test_fast_margins_agree_with_the_design():
    """The optimiser's margins on the law alone match the constraints of the full design (same spring)."""
    design = run(load_spec(EXAMPLE)).valves["intake"]
    problem = Problem(design, Limits.article(min_spring_reserve=2.2))
    fullness, margins = problem.evaluate([135.2, 19.3, 0.2, 0.8])
    assert fullness == pytest.approx(design.records["power_polynomial"]["tappet_fullness"], rel=1e-12)
    named = dict(zip(problem.margin_names(), margins))
    assert named["concave radius"] == pytest.approx(1 - 170 / 102.43, abs=2e-3)
    assert named["pressure angle"] == pytest.approx((30 - 26.8165) / 30, abs=1e-4)
    assert problem.evaluate([5.0, 3.0, 0.5, 0.5])[0] == 0.0          # no cam: lift never reached in the angle


def test_a_short_search_finds_a_feasible_fuller_cam():
    result = optimize_valve(load_spec(EXAMPLE), maxiter=6, popsize=6)
    assert all(c.passed for c in result.checks)
    assert result.fullness > 0.64
    assert result.polydyne_fullness == pytest.approx(0.578, abs=1e-3)
    optimum = parse_spec(result.spec_text)
    assert optimum.valves["intake"].cam.peak_acceleration_mm_per_rad2 == pytest.approx(
        result.optimum["peak_acceleration_mm_per_rad2"], rel=1e-5)
    assert run(optimum).valves["intake"].records["power_polynomial"]["tappet_fullness"] == pytest.approx(
        result.fullness, rel=1e-6)


def test_cli_writes_a_spec_that_run_accepts(tmp_path):
    out = tmp_path / "opt"
    r = CliRunner().invoke(main, ["optimize", str(EXAMPLE), "--out", str(out), "--maxiter", "3"])
    assert r.exit_code == 0, r.output
    record = json.loads((out / "optimization.json").read_text())
    assert set(record["optimum"]) == {"peak_acceleration_mm_per_rad2", "phi1_deg", "peak_position", "trough_position"}
    assert record["evaluations"] > 0 and record["constraints"]
    r = CliRunner().invoke(main, ["run", str(out / "optimum.toml"), "--out", str(tmp_path / "run")])
    assert r.exit_code == 0, r.output


def test_cli_refuses_another_law(tmp_path):
    other = Path(__file__).parents[1] / "examples" / "seed000-polydyne.toml"
    r = CliRunner().invoke(main, ["optimize", str(other), "--out", str(tmp_path / "o")])
    assert r.exit_code == 2 and "power_polynomial" in r.output
