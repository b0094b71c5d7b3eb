"""valvetrain optimize --objective volumetric_efficiency / torque: a cam synthesis by the breathing.

The built-in example's designed valves (Valve-train practical works (n.d.), appendix) breathe through a 350 mm intake
runner; the objective is the mean of the breathing's converged cycles over the speeds of [breathing].  References:
the breathing stage of ``valvetrain run`` itself (the objective of a design is the chapter's records, computed there
by the same stage from the full design), and the known direction of the intake valve's closing (Heywood (1988),
section 6.3: a later closing loses charge to back-flow at low speed and gains it by the inflow's inertia at high
speed)."""

from dataclasses import replace
from pathlib import Path
import re

from click.testing import CliRunner
import numpy as np
import pytest

from valvetrain.cli import main
from valvetrain.design import run
from valvetrain.specification import example_spec, spec_document, validate
from valvetrain.specification.reading import parse_spec
from valvetrain.synthesis.objectives import breathing_objective, objective_value
from valvetrain.synthesis.optimize import design_limits, optimize_valve
from valvetrain.synthesis.problem import Problem
from valvetrain.synthesis.variables import parse_variables

CLOSING = parse_variables(["closes_deg=60,90"])
"""The intake valve's closing [crank deg after BDC], the example's 78."""


def _document(speeds=(2000.0, 7000.0), mode="motored"):
    doc = spec_document(example_spec())
    doc["breathing"] = {"mode": mode, "wall_temperature_C": 150.0,
                        "intake": {"runner_length_mm": 350.0, "runner_diameter_mm": 38.0},
                        "curve": {"speed_range_rpm": [speeds[0], speeds[-1]], "points": len(speeds),
                                  "intake_pressure_kPa": 100.0, "intake_temperature_C": 25.0,
                                  "exhaust_pressure_kPa": 105.0}}
    return doc


@pytest.fixture(scope="module")
def start():
    spec = validate(_document())
    return spec, run(spec)


def _problem(spec, results, conditions=None):
    objective = breathing_objective(spec, results)
    if conditions is not None:
        objective = replace(objective, conditions=conditions)
    design = results.valves["intake"]
    return Problem(spec, design, CLOSING, design_limits(design)[0], "volumetric_efficiency", objective)


def test_the_objective_of_the_start_is_the_breathing_stage(start):
    """The search's objective at the start equals the mean of the volumetric efficiencies that the breathing chapter
    of ``run`` reports for the curve's two speeds (to round-off: the same cycles from the same lift)."""
    spec, results = start
    problem = _problem(spec, results)
    chapter = [r.figures.volumetric_efficiency for r in results.breathing.curve]
    assert len(chapter) == 2
    assert problem.evaluate(problem.x0)[0] == pytest.approx(np.mean(chapter), rel=1e-12)
    assert objective_value(results, "intake", "volumetric_efficiency") == pytest.approx(np.mean(chapter), rel=1e-15)


def test_a_later_intake_closing_loses_at_low_speed_and_gains_at_high_speed(start):
    """Heywood (1988), section 6.3: closing the intake 12 crank deg later than the example's 78 lowers the volumetric
    efficiency at 2000 rpm (back-flow before the closing) and raises it at 7000 rpm (the inflow's inertia fills the
    cylinder past BDC); each speed alone (its converged cycle from the plenums' state)."""
    spec, results = start
    _, swept = breathing_objective(spec, results).conditions
    low, high = (_problem(spec, results, ([c], [])) for c in swept)
    assert low.evaluate([90.0])[0] < low.evaluate([78.0])[0] - 0.02
    assert high.evaluate([90.0])[0] > high.evaluate([78.0])[0] + 0.01


def test_a_short_search_at_high_speed_closes_later_and_run_agrees():
    """At 7000 rpm alone a short search (two generations of four points) closes the intake later than the start and
    gains volumetric efficiency; the optimum's file, run again, meets every limit and gives the reported objective:
    its breathing chapter's volumetric efficiency at 7000 rpm, to round-off."""
    doc = _document(speeds=(7000.0,))
    doc["breathing"]["conditions"] = [{"speed_rpm": 7000.0, "intake_pressure_kPa": 100.0,
                                       "intake_temperature_C": 25.0, "exhaust_pressure_kPa": 105.0}]
    del doc["breathing"]["curve"]
    result = optimize_valve(validate(doc), "intake", CLOSING, "volumetric_efficiency", maxiter=2, popsize=4)
    assert result.feasible
    assert result.optimum["closes_deg"] > 78.0 and result.value > result.start_value
    optimum = parse_spec(result.spec_text)
    assert optimum.valves["intake"].closes_deg == pytest.approx(result.optimum["closes_deg"], rel=1e-12)
    again = run(optimum)
    assert result.value == pytest.approx(again.breathing.conditions[0].figures.volumetric_efficiency, rel=1e-12)
    assert not [c for c in again.checks if c.code.startswith("breathing.") and not c.passed]
    assert result.comparison[0][2:] == pytest.approx((result.start_value, result.value), rel=1e-12)


def _given(node):
    """A document with its None (defaulted) keys left out, as a file would give it."""
    if isinstance(node, dict):
        return {k: _given(v) for k, v in node.items() if v is not None}
    return [_given(v) for v in node] if isinstance(node, list) else node


@pytest.mark.parametrize("change, message", [
    ({"objective": "torque"}, r"--objective torque needs breathing.mode = 'fired' \(the file's is 'motored'"),
    ({"breathing": None}, r"--objective volumetric_efficiency needs a \[breathing\] section"),
    ({"lift_file": True}, r"breathing.intake.lift_file lifts the intake valves by a measured table"),
])
def test_what_the_breathing_cannot_give_is_refused(tmp_path, change, message):
    """Refused before the start is designed, naming the key: torque of a motored engine, no [breathing], an intake
    lifted by a measured table."""
    import tomli_w

    doc = _document()
    if change.get("breathing", 1) is None:
        del doc["breathing"]
    if change.get("lift_file"):
        (tmp_path / "lift.csv").write_text("crank_deg,lift_mm\n340,0\n460,8\n580,0\n", encoding="utf-8")
        cd = Path(__file__).parents[2] / "examples" / "data" / "tcc3-valve-cd.csv"
        (tmp_path / "cd.csv").write_text(cd.read_text(encoding="utf-8"), encoding="utf-8")
        doc["breathing"]["intake"].update(lift_file="lift.csv", cd_file="cd.csv", cd_diameter_mm=25.4)
    path = tmp_path / "engine.toml"
    path.write_text(tomli_w.dumps(_given(doc)), encoding="utf-8")
    out = CliRunner().invoke(main, ["optimize", str(path), "--out", str(tmp_path / "optimum"), "--objective",
                                    change.get("objective", "volumetric_efficiency"), "--no-jump", "0"])
    assert out.exit_code == 2, out.output
    assert re.search(message, out.output)
    assert not (tmp_path / "optimum").exists()
