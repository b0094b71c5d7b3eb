"""Benchmark: cam synthesis by optimisation (issue 12 item 6).

Run on demand: ``python benchmarks/bench_optimize.py [--case ukrsurt|kurz|both]``.

* ``ukrsurt``: the power-polynomial cam of the 26/27 diesel (examples/ukrsurt2019-diesel.toml, UkrSURT Proceedings
  (2019)) under the article's limits (30 deg, the 170 mm wheel, spring reserve 2.2), the command's default search,
  with and without the dynamics (no jump up to 1.1 x rated speed);
* ``kurz``: the built-in example's Kurz cam, time-area under its own limits and no jump up to 1.1 x rated speed.

For each: the wall time of the whole optimisation, the evaluations, the time of one evaluation (law stage, flow
stage, margins, one-mass dynamics, spring design) against the time of one evaluation of the law alone (its lift
over the opening flank on the same grid), and the objective at the start and at the optimum.
"""

import argparse
from pathlib import Path

import numpy as np

from valvetrain.specification import example_spec
from valvetrain.specification.validate import load_spec
from valvetrain.synthesis.optimize import GRID, optimize_valve

from timing import best_time

UKRSURT = Path(__file__).parents[1] / "examples" / "ukrsurt2019-diesel.toml"


def law_time(spec, valve):
    """Time [s] of one evaluation of the valve's law: lift, velocity, acceleration and jerk on the search's grid."""
    from valvetrain.design import run

    law = run(spec).valves[valve].law
    theta = np.linspace(law.start, 0.0, GRID)
    return best_time(lambda: law.derivatives(theta), repeats=50)


def case(name, spec, **kw):
    result = optimize_valve(spec, **kw)
    per = result.seconds_in_evaluations / result.evaluations
    law = law_time(spec, result.valve)
    print(f"{name}: {result.seconds:.1f} s in all, {result.evaluations} evaluations, {per * 1e3:.2f} ms each "
          f"= {per / law:.0f} x one law evaluation ({law * 1e6:.0f} us); {result.objective} {result.start_value:.6g} "
          f"-> {result.value:.6g}; every limit met: {result.feasible}")


def main():
    if ARGS.case in ("ukrsurt", "both"):
        spec = load_spec(UKRSURT)
        case("26/27 diesel, article limits", spec, wheel_radius=0.170, no_jump_factor=None)
        case("26/27 diesel, article limits and no jump up to 1.1 x rated", spec, wheel_radius=0.170,
             no_jump_factor=1.1)
    if ARGS.case in ("kurz", "both"):
        case("built-in Kurz cam, time-area, no jump up to 1.1 x rated", example_spec(), objective="time_area",
             no_jump_factor=1.1)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--case", choices=["ukrsurt", "kurz", "both"], default="both")
    ARGS = parser.parse_args()
    main()
