"""Benchmark: cam synthesis by optimisation, measured through the command itself (issue 22).

Run on demand: ``python benchmarks/bench_optimize.py [--case ukrsurt|kurz|both]``.

Each case runs ``valvetrain optimize`` in this process exactly as the command line does (``valvetrain.cli.main``
with the arguments printed), and reads what it measured from the optimization.json it wrote; so the figures are the
command's own and cannot disagree with it.  Printed for each case, beside its baseline measured in the same run:

* the wall time of the whole command (reading the file, the start's design, the search, the final designs, writing
  the outputs), against the goal of 10 s for the article's case;
* the evaluations of the search and the time of one (law, objective, margins, and the dynamics where a point needs
  it), against the time of one evaluation of the law on the search's grid of angles (:data:`GRID`), its baseline:
  the goal is at most 3 law evaluations per evaluation;
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
from valvetrain.synthesis.optimize import GRID

from timing import best_time

UKRSURT = Path(__file__).parents[1] / "examples" / "ukrsurt2019-diesel.toml"


def law_time(path):
    """Time [s] of one evaluation of the start's law (lift and its derivatives) on the search's grid."""
    law = run(load_spec(path)).valves["intake"].law
    theta = np.linspace(law.start, 0.0, GRID)
    return best_time(lambda: law.derivatives(theta), repeats=50)


def case(name, path, *args):
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
    law = law_time(path)
    print(f"{name}: valvetrain {' '.join(argv[:2])} {' '.join(args)}: exit status {status}, {wall:.1f} s wall "
          "(goal: 10 s for the article's case)")
    if record is None:
        return
    n, per = record["evaluations"], record["seconds_in_evaluations"] / record["evaluations"]
    print(f"  {n} evaluations of {per * 1e3:.2f} ms = {per / law:.1f} law evaluations each (goal: <= 3; one law "
          f"evaluation on {GRID} angles: {law * 1e3:.3f} ms, this run); {record['law_samples'] / n:.0f} law angles "
          f"per evaluation; {record['simulations']} dynamics simulations; search {record['seconds']:.1f} s of the "
          f"command's {wall:.1f} s")
    print(f"  {record['objective']} {record['start_value']:.6g} -> {record['value']:.6g}; every limit met: "
          f"{record['feasible']}")


def main():
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
