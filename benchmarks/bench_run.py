"""Benchmark: a whole ``valvetrain run`` of the built-in example.

Run on demand: ``python benchmarks/bench_run.py``.  Times the calculation
(``design.run``) and the writing of every artefact (JSON, CSV, DXF, plots, report)
separately, best of several repeats, and the peak Python memory of one full run.
"""

import tempfile
import time
import tracemalloc
from pathlib import Path

from valvetrain.design import run
from valvetrain.export import write_outputs
from valvetrain.specification import example_spec

REPEATS = 5


def main():
    spec = example_spec()
    calc, write = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for i in range(REPEATS):
            t0 = time.perf_counter()
            results = run(spec)
            t1 = time.perf_counter()
            write_outputs(results, Path(tmp) / f"design{i}")
            t2 = time.perf_counter()
            calc.append(t1 - t0)
            write.append(t2 - t1)
        tracemalloc.start()
        write_outputs(run(spec), Path(tmp) / "mem")
        peak = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
    print(f"design.run (calculation):      best {min(calc) * 1e3:7.1f} ms")
    print(f"write_outputs (all artefacts): best {min(write) * 1e3:7.1f} ms")
    print(f"whole run:                     best {min(c + w for c, w in zip(calc, write)) * 1e3:7.1f} ms")
    print(f"peak traced Python memory of one run: {peak / 2**20:.1f} MiB")


if __name__ == "__main__":
    main()
