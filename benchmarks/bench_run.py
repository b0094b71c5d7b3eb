"""Benchmark: a whole ``valvetrain run`` of the built-in example.

Run on demand: ``python benchmarks/bench_run.py``.  Times, best of several repeats:

* in this process, the calculation (``design.run``) and the writing of every artefact (JSON, CSV, DXF, plots,
  report) with the default figures (``figures="main"``) and, as the baseline in the same run, with every figure
  (``figures="all"``, what a run wrote before ``--figures``); the default figures drawn in other processes
  (:class:`valvetrain.report.drawing.FigureProcess`, as the command draws them on Linux) against those drawn here;
  and the peak Python memory of one full run;
* the command itself, ``python -m valvetrain run --out ...`` in a new process (imports included), with the default
  figures and with ``--figures all`` and ``--figures none``, alternately: wall time and the processor time of the
  process (on a machine that others use the wall time is the processor time plus the wait).
"""

import os
import resource
import subprocess
import sys
import tempfile
import time
import tracemalloc
from pathlib import Path

from valvetrain.design import run
from valvetrain.export import write_outputs
from valvetrain.report.drawing import FigureProcess
from valvetrain.specification import example_spec

REPEATS = 5
COMMAND_REPEATS = 3
GOAL_S = 2.0


def _command(out, figures):
    """(wall, processor) time [s] of one ``valvetrain run`` in a new process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run([sys.executable, "-m", "valvetrain", "run", "--out", str(out), "--figures", figures],
                   check=True, stdout=subprocess.DEVNULL, env=os.environ.copy())
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main():
    spec = example_spec()
    calc, write, forked = [], {"main": [], "all": []}, []
    with tempfile.TemporaryDirectory() as tmp:
        for i in range(REPEATS):
            for figures in write:
                t0 = time.perf_counter()
                results = run(spec)
                t1 = time.perf_counter()
                write_outputs(results, Path(tmp) / f"{figures}{i}", figures=figures)
                t2 = time.perf_counter()
                calc.append(t1 - t0)
                write[figures].append(t2 - t1)
            if sys.platform.startswith("linux"):
                t0 = time.perf_counter()
                write_outputs(results, Path(tmp) / f"forked{i}", drawer=FigureProcess())
                forked.append(time.perf_counter() - t0)
        tracemalloc.start()
        write_outputs(run(spec), Path(tmp) / "mem")
        peak = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
        commands = {"main": [], "all": [], "none": []}
        for i in range(COMMAND_REPEATS):
            for figures in commands:
                commands[figures].append(_command(Path(tmp) / f"cmd-{figures}{i}", figures))
    print(f"design.run (calculation):                          best {min(calc) * 1e3:7.1f} ms")
    print(f"write_outputs, default figures (main):             best {min(write['main']) * 1e3:7.1f} ms")
    print(f"write_outputs, every figure (all; the baseline):   best {min(write['all']) * 1e3:7.1f} ms")
    if forked:
        print(f"write_outputs, default figures drawn in other processes: best {min(forked) * 1e3:7.1f} ms wall "
              f"(drawn here: {min(write['main']) * 1e3:7.1f} ms, the baseline)")
    print(f"peak traced Python memory of one run: {peak / 2**20:.1f} MiB")
    for figures, label in (("main", "default figures (main)"), ("all", "--figures all (the baseline)"),
                           ("none", "--figures none")):
        wall, cpu = min(w for w, _ in commands[figures]), min(c for _, c in commands[figures])
        print(f"valvetrain run, {label + ':':31s} best wall {wall:5.2f} s, best processor {cpu:5.2f} s "
              f"(goal <= {GOAL_S:g} s)")
    print(f"load average during the run: {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")


if __name__ == "__main__":
    main()
