"""Benchmark: a tolerance study of the built-in example with its dynamics (issue 27 item 2), serially, with
``--workers 2`` and on a local Dask cluster.

Run on demand: ``python benchmarks/bench_tolerance.py [--samples N]``.  The built-in example (two valves, each with
a [dynamics] sweep of 200 speeds) gets four tolerances (both clearances, uniform +-0.03 mm; both valve masses, normal
sigma 1 g).  Printed:

* the processor time of one sample (all threads of this process, the median of 15; the other jobs of a shared machine
  change it less than the wall time), :func:`valvetrain.tolerance.evaluate_sample`, beside its baseline measured in
  the same run: the same design with the full sweep (:func:`valvetrain.design.run` as ``valvetrain run`` designs, the
  samples' design before the headline sweep, measured first, before a sample keeps the heap), and the time 10^4
  samples take at it on two idle cores;
* ``valvetrain tolerance`` of N Latin-hypercube samples as a whole command (start-up, validation, the samples, the
  writing) serially, with ``--workers 2`` and on a Dask ``LocalCluster`` of two one-thread worker processes: samples
  per second of each, the load average of the machine beside them, and whether the three give the same results;
* what a Dask cluster of K machines like this one would do: the tasks are independent, so the rate is K times the
  local cluster's (less the scheduler's 3-6 ms a task of up to 32 samples), and K times two cores over the processor
  time of a sample on idle machines.
"""

import argparse
import os
import statistics
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
    """Wall time [s] of ``valvetrain tolerance`` with ``backend`` options, its tolerance.json without the folder's
    name, and the load average over the last minute when it ended."""
    t0 = time.perf_counter()
    subprocess.run([sys.executable, "-m", "valvetrain", "tolerance", str(spec), "--samples", str(ARGS.samples),
                    "--method", "lhs", "--out", str(out), *backend], check=True, stdout=subprocess.DEVNULL)
    wall = time.perf_counter() - t0
    return wall, (out / "tolerance.json").read_text(encoding="utf-8").replace(out.name, "X"), os.getloadavg()[0]


def cpu_per_call(function, document, repeat):
    """Processor time of one call [s]: the median of ``repeat`` calls after a warm-up call (the median, as the other
    jobs of a shared machine slow some calls down)."""
    function(document)
    times = []
    for _ in range(repeat):
        c0 = time.process_time()
        function(document)
        times.append(time.process_time() - c0)
    return statistics.median(times)


def main():
    from distributed import LocalCluster

    from valvetrain.design import run
    from valvetrain.specification import example_text, validate
    from valvetrain.study import read_document
    from valvetrain.tolerance import evaluate_sample

    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        spec = tmp / "engine.toml"
        spec.write_text(example_text() + TOLERANCES, encoding="utf-8")
        document = read_document(spec)
        load0 = os.getloadavg()[0]
        full = cpu_per_call(lambda d: run(validate(d)), document, 5)   # first: evaluate_sample keeps the heap
        cpu = cpu_per_call(evaluate_sample, document, 15)
        serial, result1, load1 = tolerance(spec, tmp / "serial")
        workers, result2, load2 = tolerance(spec, tmp / "workers", "--workers", "2")
        with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
            dask, result3, load3 = tolerance(spec, tmp / "dask", "--scheduler", cluster.scheduler_address)
    n = ARGS.samples
    print(f"CPU time of one sample: {cpu:.3f} s (baseline, the full sweep of 200 speeds a valve: {full:.3f} s, "
          f"{full / cpu:.1f} times as much); load average {load0:.1f}")
    print(f"10^4 samples on an otherwise idle 2-core machine: {1e4 * cpu / 2 / 60:.1f} min "
          f"(baseline {1e4 * full / 2 / 60:.1f} min)")
    for name, wall, load in (("serial", serial, load1), ("--workers 2", workers, load2),
                             ("Dask LocalCluster, 2 workers x 1 thread", dask, load3)):
        print(f"tolerance, {n} samples, {name}: {wall:.1f} s, {n / wall:.2f} samples/s "
              f"(10^4 samples: {1e4 / (n / wall) / 60:.1f} min); load average {load:.1f}")
    print(f"same results serial, --workers 2 and Dask: {result1 == result2 == result3}")
    for k in (4, 16, 64):
        print(f"a Dask cluster of {k} machines like this one: {k * n / dask:.1f} samples/s at the Dask rate measured "
              f"here, {k * 2 / cpu:.0f} samples/s on idle machines; 10^4 samples in "
              f"{1e4 / (k * n / dask) / 60:.2f} min and {1e4 / (k * 2 / cpu) / 60:.2f} min")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=int, default=100)
    ARGS = parser.parse_args()
    main()
