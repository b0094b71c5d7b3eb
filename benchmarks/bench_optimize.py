"""Benchmark: cam synthesis by optimisation, measured through the command itself (issue 22).

Run on demand: ``python benchmarks/bench_optimize.py [--case ukrsurt|kurz|both]``.

Each case runs ``valvetrain optimize`` in this process exactly as the command line does (``valvetrain.cli.main``
with the arguments printed), and reads what it measured from the optimization.json it wrote; so the figures are the
command's own and cannot disagree with it.  Printed for each case, beside its baseline measured in the same run:

* the wall time of the whole command (reading the file, the start's design, the search, the final designs, writing
  the outputs), against the goal of 10 s for the article's case;
* the evaluations of the search and the time of one (law, objective, margins, and the dynamics where a point needs
  it), as the command measured it (wall time, what a loaded machine stretches);
* the processor time of one evaluation without the dynamics, against its baseline, the processor time of one
  evaluation of the start's law on the search's grid of angles (:data:`GRID`): the search's calls are replayed as it
  made them (:meth:`Problem.evaluate_many` with ``dynamics=False``, the cache emptied: each generation's population
  as one batch, each point of the polish on its own), each call followed by as many evaluations of the law as it
  evaluated points, so that both see the same load, in :data:`PASSES` passes; the goal is at most 3 law evaluations
  per evaluation.  Printed: the ratio of the summed times and that of each pass;
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
from valvetrain.synthesis.problem import GRID

UKRSURT = Path(__file__).parents[1] / "examples" / "ukrsurt2019-diesel.toml"
PASSES = 3
"""Passes over the search's calls; each gives a ratio."""


class _Recorded(optimize.Problem):
    """The command's problem, kept (:data:`PROBLEMS`) with the points each of its calls evaluated (``calls``), to
    time its evaluations again as the search made them."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self.calls = []
        PROBLEMS.append(self)

    def evaluate_many(self, xs, dynamics=None):
        before = len(self.points)
        out = super().evaluate_many(xs, dynamics)
        if len(self.points) > before:
            self.calls.append(self.points[before:])
        return out


PROBLEMS = []


def paired(problem, law):
    """(ratio of each pass, summed evaluation time [s], summed law time [s], evaluations, calls): processor time of
    the search's calls of :meth:`Problem.evaluate_many` replayed without the dynamics, each followed by as many
    evaluations of the start's law on the search's grid as it evaluated points, over :data:`PASSES` passes."""
    theta = np.linspace(law.start, 0.0, GRID)
    calls = list(problem.calls)
    ratios, total_eval, total_law = [], 0.0, 0.0
    for _ in range(PASSES):
        problem._cache.clear()
        evaluation = base = 0.0
        for points in calls:
            t0 = time.process_time()
            problem.evaluate_many(points, dynamics=False)
            t1 = time.process_time()
            for _ in points:
                law.derivatives(theta)
            t2 = time.process_time()
            evaluation, base = evaluation + t1 - t0, base + t2 - t1
        ratios.append(evaluation / base)
        total_eval, total_law = total_eval + evaluation, total_law + base
    return ratios, total_eval, total_law, PASSES * sum(len(points) for points in calls), len(calls)


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
    ratios, evaluation, law, points, calls = paired(PROBLEMS[0], run(load_spec(path)).valves[PROBLEMS[0].name].law)
    print(f"  processor time, paired: one evaluation without the dynamics {evaluation / points * 1e3:.3f} ms = "
          f"{evaluation / law:.2f} law evaluations (goal: <= 3; the baseline, one law evaluation on {GRID} angles: "
          f"{law / points * 1e3:.3f} ms, timed after each call; the search's {calls} calls, {points // PASSES} "
          f"evaluations, replayed in {PASSES} passes); the passes' ratios {', '.join(f'{r:.2f}' for r in ratios)}")
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
