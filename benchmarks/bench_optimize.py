"""Benchmark: cam synthesis by optimisation, measured through the command itself (issue 22).

Run on demand: ``python benchmarks/bench_optimize.py [--case ukrsurt|kurz|both]``.

Each case runs ``valvetrain optimize`` in this process exactly as the command line does (``valvetrain.cli.main``
with the arguments printed), and reads what it measured from the optimization.json it wrote; so the figures are the
command's own and cannot disagree with it.  Printed for each case, beside its baseline measured in the same run:

* the wall time of the whole command (reading the file, the start's design, the search, the final designs, writing
  the outputs), against the goal of 10 s for the article's case;
* the evaluations of the search and the time of one (law, objective, margins, and the dynamics where a point needs
  it), as the command measured it (wall time, what a loaded machine stretches);
* the processor time of one evaluation without the dynamics (:meth:`Problem.evaluate` with ``dynamics=False``, the
  cache emptied) at the search's own points, against its baseline, the processor time of one evaluation of the
  start's law on the search's grid of angles (:data:`GRID`): each evaluation at :data:`PAIRED` of the search's
  points is followed by one of the law, so that both see the same load, in :data:`PASSES` passes; the goal is at
  most 3 law evaluations per evaluation.  Printed: the ratio of the summed times and that of each pass;
* the angles at which the law was sampled per evaluation, and the dynamics simulations of the search;
* the objective at the start and at the optimum, and whether every limit is met (exit status 0).

Cases: ``ukrsurt``, the power-polynomial cam of the 26/27 diesel (examples/ukrsurt2019-diesel.toml, UkrSURT
Proceedings (2019)) with the 170 mm wheel and the command's defaults (no jump up to [engine] over_speed_ratio);
``kurz``, the built-in example's Kurz cam, time-area.
"""

import argparse
import json
from pathlib import Path
import tempfile
import time

import numpy as np

from valvetrain.cli import main as cli
from valvetrain.design import run
from valvetrain.specification import example_text
from valvetrain.specification.reading import load_spec
from valvetrain.synthesis import optimize
from valvetrain.synthesis.optimize import GRID

UKRSURT = Path(__file__).parents[1] / "examples" / "ukrsurt2019-diesel.toml"
PAIRED = 600
"""Points of the search (evenly spread over it) at which an evaluation is timed against the law's."""
PASSES = 3
"""Passes over the points; each gives a ratio."""


class _Recorded(optimize.Problem):
    """The command's problem, kept (:data:`PROBLEMS`) to time its evaluations again at its own points."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        PROBLEMS.append(self)


PROBLEMS = []


def paired(problem, law):
    """(ratio of each pass, summed evaluation time [s], summed law time [s], points): processor time of
    :meth:`Problem.evaluate` without the dynamics at the search's points, each followed by an evaluation of the start's
    law on the search's grid, over :data:`PASSES` passes."""
    theta = np.linspace(law.start, 0.0, GRID)
    points = [problem.points[i] for i in np.linspace(0, len(problem.points) - 1, PAIRED).astype(int)]
    ratios, total_eval, total_law = [], 0.0, 0.0
    for _ in range(PASSES):
        problem._cache.clear()
        evaluation = base = 0.0
        for x in points:
            t0 = time.process_time()
            problem.evaluate(x, dynamics=False)
            t1 = time.process_time()
            law.derivatives(theta)
            t2 = time.process_time()
            evaluation, base = evaluation + t1 - t0, base + t2 - t1
        ratios.append(evaluation / base)
        total_eval, total_law = total_eval + evaluation, total_law + base
    return ratios, total_eval, total_law, PASSES * len(points)


def case(name, path, *args):
    PROBLEMS.clear()
    with tempfile.TemporaryDirectory() as tmp:
        argv = ["optimize", str(path), "--out", str(Path(tmp) / "o"), *args]
        t0 = time.perf_counter()
        try:
            cli.main(argv, standalone_mode=False)
            status = 0
        except SystemExit as exc:
            status = exc.code
        wall = time.perf_counter() - t0
        written = Path(tmp) / "o" / "optimization.json"
        record = json.loads(written.read_text()) if written.exists() else None
    print(f"{name}: valvetrain {' '.join(argv[:2])} {' '.join(args)}: exit status {status}, {wall:.1f} s wall "
          "(goal: 10 s for the article's case)")
    if record is None:
        return
    n, per = record["evaluations"], record["seconds_in_evaluations"] / record["evaluations"]
    print(f"  {n} evaluations of {per * 1e3:.2f} ms wall (the dynamics included); {record['law_samples'] / n:.0f} "
          f"law angles per evaluation; {record['simulations']} dynamics simulations; search {record['seconds']:.1f} s "
          f"of the command's {wall:.1f} s")
    ratios, evaluation, law, points = paired(PROBLEMS[0], run(load_spec(path)).valves[PROBLEMS[0].name].law)
    print(f"  processor time, paired: one evaluation without the dynamics {evaluation / points * 1e3:.3f} ms = "
          f"{evaluation / law:.2f} law evaluations (goal: <= 3; the baseline, one law evaluation on {GRID} angles: "
          f"{law / points * 1e3:.3f} ms, timed after each evaluation, {PAIRED} of the search's points, {PASSES} "
          f"passes); the passes' ratios {', '.join(f'{r:.2f}' for r in ratios)}")
    print(f"  {record['objective']} {record['start_value']:.6g} -> {record['value']:.6g}; every limit met: "
          f"{record['feasible']}")


def main():
    optimize.Problem = _Recorded
    if ARGS.case in ("ukrsurt", "both"):
        case("26/27 diesel, article limits", UKRSURT, "--wheel-radius", "170")
    if ARGS.case in ("kurz", "both"):
        with tempfile.TemporaryDirectory() as tmp:
            path = Path(tmp) / "example.toml"
            path.write_text(example_text(), encoding="utf-8")
            case("built-in Kurz cam, time-area", path, "--objective", "time_area")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--case", choices=["ukrsurt", "kurz", "both"], default="both")
    ARGS = parser.parse_args()
    main()
