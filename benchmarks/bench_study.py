"""Benchmark: a design study of 1,000 points (issue 12 item 4) in local processes and on a Dask LocalCluster.

Run on demand: ``python benchmarks/bench_study.py [--points-per-key N]``.  The grid is the appendix example's
(examples/seed000-appendix-kurz.toml: one valve, no dynamics) cam shape factor (40 values) times its rated speed
(25 values); ``valvetrain study`` runs it with ``--workers 2`` and with ``--scheduler`` on a
``dask.distributed.LocalCluster(n_workers=2, processes=True)`` started here, each as a whole command (start-up, validation, the points, the writing), and the two
``study.csv`` files are compared byte for byte; the ratio of their throughputs is printed beside the goal of
issue 22 (>= 0.8).  Before the study, the thread CPU time of one design (which the other jobs of a shared machine
do not change) in this process and in the cluster's two workers, one as its nanny starts it and one after
``valvetrain.study.heap_arrays``.
"""

import argparse
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

APPENDIX = Path(__file__).parents[1] / "examples" / "seed000-appendix-kurz.toml"


def study(spec, out, *backend):
    shape = ",".join(f"{z:.4f}" for z in np.linspace(0.3, 0.9, ARGS.shape_factors))
    speed = ",".join(str(n) for n in np.linspace(5000, 8000, ARGS.speeds).round().astype(int))
    t0 = time.perf_counter()
    subprocess.run([sys.executable, "-m", "valvetrain", "study", str(spec), "--grid",
                    f"valves.intake.cam.shape_factor={shape}", "--grid", f"engine.rated_speed_rpm={speed}",
                    "--out", str(out), *backend], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - t0, (out / "study.csv").read_bytes()


def cpu_per_design(document, restore=False, repeats=10):
    """The thread CPU time of one design [s] (the mean of ``repeats`` after two warm-up designs), unlike the wall
    time indifferent to the other jobs of a shared machine; ``restore`` calls :func:`valvetrain.study.heap_arrays`
    first."""
    from valvetrain.study import evaluate_point, heap_arrays

    if restore:
        heap_arrays()
    evaluate_point(document)
    evaluate_point(document)
    start = time.thread_time()
    for _ in range(repeats):
        evaluate_point(document)
    return (time.thread_time() - start) / repeats


def main():
    from dask.distributed import Client, LocalCluster

    from valvetrain.study import read_document

    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        spec = tmp / "engine.toml"
        spec.write_text(APPENDIX.read_text(encoding="utf-8"), encoding="utf-8")
        n = ARGS.shape_factors * ARGS.speeds
        local, table_local = study(spec, tmp / "local", "--workers", "2")
        print(f"{n} points, --workers 2: {local:.1f} s ({local / n * 1e3:.1f} ms a point)")
        t0 = time.perf_counter()
        with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
            start = time.perf_counter() - t0
            document = read_document(spec)
            with Client(cluster) as client:
                first, second = client.scheduler_info()["workers"]
                as_is = client.submit(cpu_per_design, document, workers=[first], pure=False).result()
                restored = client.submit(cpu_per_design, document, True, workers=[second], pure=False).result()
            print(f"CPU time of one design: {cpu_per_design(document) * 1e3:.1f} ms in this process, in a Dask "
                  f"worker {as_is * 1e3:.1f} ms as its nanny starts it, {restored * 1e3:.1f} ms after heap_arrays()")
            dask, table_dask = study(spec, tmp / "dask", "--scheduler", cluster.scheduler_address)
        print(f"{n} points, LocalCluster(n_workers=2): {dask:.1f} s ({dask / n * 1e3:.1f} ms a point), "
              f"plus {start:.1f} s to start the cluster")
        print(f"throughput of the cluster / --workers 2: {local / dask:.2f} (issue 22 goal: >= 0.8)")
        rows = table_local.decode().count("\n") - 1
        print(f"tables identical: {table_local == table_dask} ({rows} rows, {len(table_local)} bytes)")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--shape-factors", type=int, default=40)
    parser.add_argument("--speeds", type=int, default=25)
    ARGS = parser.parse_args()
    main()
