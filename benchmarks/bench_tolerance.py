"""Benchmark: a tolerance study of the built-in example with its dynamics (issue 27 item 2), serially and with
``--workers 2``.

Run on demand: ``python benchmarks/bench_tolerance.py [--samples N]``.  The built-in example (two valves, each with
a [dynamics] sweep) gets four tolerances (both clearances, uniform +-0.03 mm; both valve masses, normal sigma 1 g);
``valvetrain tolerance`` runs N Latin-hypercube samples as a whole command (start-up, validation, the samples, the
writing) serially and with ``--workers 2``.  Printed: samples per second of each, beside the baseline measured in the
same run, one ``valvetrain run``-like design of the example in this process (:func:`valvetrain.study.evaluate_point`
after a warm-up); the CPU time of one sample (which the other jobs of a shared machine do not change) and the time
10^4 samples would take at it on two idle cores; the two results compared; the time 10^4 samples take at the measured rate, and what a Dask cluster
of K machines of C cores each would do at the measured rate per process (the tasks are independent: the rate scales
with the processes, less the scheduler's 3-6 ms a task of up to 32 samples).
"""

import argparse
import subprocess
import sys
import tempfile
import time
from pathlib import Path

TOLERANCES = """
[[tolerances]]
key = "valves.intake.clearance_mm"
distribution = "uniform"
half_range = 0.03

[[tolerances]]
key = "valves.exhaust.clearance_mm"
distribution = "uniform"
half_range = 0.03

[[tolerances]]
key = "valves.intake.drive.masses.valve_kg"
distribution = "normal"
sigma = 0.001

[[tolerances]]
key = "valves.exhaust.drive.masses.valve_kg"
distribution = "normal"
sigma = 0.001
"""


def tolerance(spec, out, *backend):
    t0 = time.perf_counter()
    subprocess.run([sys.executable, "-m", "valvetrain", "tolerance", str(spec), "--samples", str(ARGS.samples),
                    "--method", "lhs", "--out", str(out), *backend], check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - t0, (out / "tolerance.json").read_text(encoding="utf-8")


def main():
    from valvetrain.specification import example_text
    from valvetrain.study import evaluate_point, read_document
    from valvetrain.tolerance import evaluate_sample

    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        spec = tmp / "engine.toml"
        spec.write_text(example_text() + TOLERANCES, encoding="utf-8")
        document = read_document(spec)
        evaluate_point(document)
        t0 = time.perf_counter()
        evaluate_point(document)
        one = time.perf_counter() - t0
        evaluate_sample(document)
        c0 = time.process_time()
        for _ in range(3):
            evaluate_sample(document)
        cpu = (time.process_time() - c0) / 3
        serial, result1 = tolerance(spec, tmp / "serial")
        workers, result2 = tolerance(spec, tmp / "workers", "--workers", "2")
    n = ARGS.samples
    print(f"baseline: one design of the built-in example with dynamics in this process: {one:.3f} s "
          f"({1 / one:.2f} designs/s)")
    print(f"tolerance, {n} samples, serial:      {serial:.1f} s, {n / serial:.2f} samples/s")
    print(f"tolerance, {n} samples, --workers 2: {workers:.1f} s, {n / workers:.2f} samples/s")
    print(f"same results: {result1.replace('serial', 'X') == result2.replace('workers', 'X')}")
    print(f"CPU time of one sample (all threads of this process; the other jobs of a shared machine do not change "
          f"it): {cpu:.3f} s; 10^4 samples on an otherwise idle 2-core machine: {1e4 * cpu / 2 / 60:.1f} min")
    rate = n / workers
    print(f"10^4 samples at the --workers 2 rate: {1e4 / rate / 60:.1f} min")
    per_process = rate / 2
    for k, cores in ((4, 8), (16, 16)):
        print(f"a Dask cluster of {k} machines x {cores} cores at {per_process:.2f} samples/s a process: "
              f"{1e4 / (per_process * k * cores) / 60:.2f} min for 10^4 samples")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=int, default=100)
    ARGS = parser.parse_args()
    main()
