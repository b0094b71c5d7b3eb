"""Benchmark: the breathing (gas exchange) at one speed and over a 20-speed torque curve (issue 37).

Run on demand: ``python benchmarks/bench_breathing.py``.  Prints, best of several repeats (the compiled kernels
loaded by a first, uncounted call), wall and CPU time of:

* one speed converged: the TCC-III example's 1300 rpm wide-open condition (examples/tcc3-motored.toml, runners on
  both sides), and the built-in example's designed valves fired at 3000 rpm with a 350 mm intake runner;
* a 20-speed torque curve of the latter, 1000-7000 rpm (``breathing_records``, the designer's function);
* the baseline measured in the same run: one cycle of the 1300 rpm condition (the kernel alone), so that the ratios
  (converged speed / one cycle) hold under any load.

The targets of issue 37 are one speed in 50 ms and the curve in 1 s on the 2-core machine with nothing else running;
the machine's load average is printed beside the figures, wall times under load are not those.
"""

import os
from pathlib import Path
import time

import numpy as np

from timing import best_time

from valvetrain.breathing import breathe
from valvetrain.design import run
from valvetrain.design.breathing import breathing_records, condition_of
from valvetrain.specification import example_spec, load_spec, si, spec_document, validate

EXAMPLE = Path(__file__).parents[1] / "examples" / "tcc3-motored.toml"
REPEATS = 5


def _cpu(fn, repeats=REPEATS):
    """The shortest CPU time [s] of ``repeats`` calls of ``fn()``."""
    out = np.inf
    for _ in range(repeats):
        t0 = time.process_time()
        fn()
        out = min(out, time.process_time() - t0)
    return out


def _fired_builtin():
    doc = spec_document(example_spec())
    doc["breathing"] = {"mode": "fired", "wall_temperature_C": 150.0,
                        "intake": {"runner_length_mm": 350.0, "runner_diameter_mm": 38.0},
                        "exhaust": {"runner_length_mm": 300.0, "runner_diameter_mm": 34.0},
                        "curve": {"speed_range_rpm": [1000.0, 7000.0], "points": 20, "intake_pressure_kPa": 100.0,
                                  "intake_temperature_C": 25.0, "exhaust_pressure_kPa": 105.0}}
    spec = validate(doc)
    return spec, run(spec).breathing


def main():
    print(f"load average {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores")
    spec = load_spec(EXAMPLE)
    tcc = run(spec).breathing
    view = si(spec.breathing, spec)
    engine, condition = tcc.engines[1], condition_of(view.conditions[1], view.conditions[1].speed, view)
    one = tcc.conditions[1]
    steps = one.columns.angle.size - 1
    t_one, c_one = best_time(lambda: breathe(engine, condition), REPEATS), _cpu(lambda: breathe(engine, condition))
    t_cyc = best_time(lambda: breathe(engine, condition, tolerance=1.0, max_cycles=2), REPEATS) / 2.0
    print(f"TCC-III 1300 rpm, 94.93 kPa: converged in {one.figures.cycles} cycles of {steps} steps: wall "
          f"{t_one * 1e3:.1f} ms, CPU {c_one * 1e3:.1f} ms; one cycle {t_cyc * 1e3:.1f} ms, ratio "
          f"{t_one / t_cyc:.2f}")
    spec, fired = _fired_builtin()
    view = si(spec.breathing, spec)
    curve = [condition_of(view.curve, n, view) for n in np.linspace(1000.0, 7000.0, 20) * np.pi / 30]
    at3000 = condition_of(view.curve, 3000 * np.pi / 30, view)
    r3 = breathe(fired.engines[0], at3000)
    engine = fired.engines[0]
    t3, c3 = best_time(lambda: breathe(engine, at3000), REPEATS), _cpu(lambda: breathe(engine, at3000))
    print(f"built-in, fired, 3000 rpm: converged in {r3.figures.cycles} cycles of {r3.columns.angle.size - 1} steps: "
          f"wall {t3 * 1e3:.1f} ms, CPU {c3 * 1e3:.1f} ms")
    tc = best_time(lambda: breathing_records(fired.engines[0], curve, 1e-3, 60, curve=True), 3)
    cc = _cpu(lambda: breathing_records(fired.engines[0], curve, 1e-3, 60, curve=True), 3)
    print(f"built-in, fired, 20 speeds 1000-7000 rpm: wall {tc:.3f} s, CPU {cc:.3f} s ({tc / 20 * 1e3:.1f} ms a "
          f"speed, {tc / t_cyc:.0f} TCC-III cycles)")
    print(f"load average {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
