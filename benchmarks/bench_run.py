"""Benchmark: a whole ``valvetrain run``, the command itself, beside the same command of a baseline tree.

Run on demand: ``python benchmarks/bench_run.py [--baseline REF] [--repeats N]``.

The baseline is the package of the commit ``REF`` (default :data:`BASELINE`, the tree before the work on the run's
speed), unpacked into a temporary folder (``git archive``); each case runs ``python -m valvetrain run ... --out DIR``
in a new process, imports included, alternately with this tree's ``src`` and the baseline's on ``PYTHONPATH``, after
one run of each that is not counted (it fills numba's on-disk cache of the unpacked baseline, and the page cache):
the times are those of warm runs.  Cases: the built-in example with the default figures and with ``--figures none``,
and ``examples/pushrod-dynamics.toml`` (a ``[dynamics]`` section) with the default figures.  For each: the best and
the median wall time and processor time (the process and its children: the drawing processes) of ``--repeats``
runs, and the load average of the machine while they ran (on a machine that others use the wall time is the
processor time plus the wait, and a core that another process holds stretches it).
"""

import argparse
import os
from pathlib import Path
import resource
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = Path(__file__).parents[1]
BASELINE = "7cf5134"
"""The commit before the work on the speed of ``valvetrain run`` (issue 22)."""
GOAL_S = 2.0
"""Wall time of ``valvetrain run`` of the built-in example with the default figures, on a 2-core machine [s]."""
CASES = (("built-in example, default figures", []),
         ("built-in example, --figures none", ["--figures", "none"]),
         ("examples/pushrod-dynamics.toml, default figures", [str(ROOT / "examples" / "pushrod-dynamics.toml")]))


def command(src, args, out):
    """(wall, processor) time [s] of one ``valvetrain run`` of the package in ``src``, in a new process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run([sys.executable, "-m", "valvetrain", "run", *args, "--out", str(out)], check=True,
                   stdout=subprocess.DEVNULL, env={**os.environ, "PYTHONPATH": str(src)})
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def baseline_tree(ref, folder):
    """The ``src`` folder of commit ``ref``, unpacked into ``folder``."""
    archive = subprocess.run(["git", "-C", str(ROOT), "archive", ref, "src"], check=True, capture_output=True).stdout
    subprocess.run(["tar", "-x", "-C", str(folder)], input=archive, check=True)
    return folder / "src"


def _line(label, times):
    walls, cpus = [w for w, _ in times], [c for _, c in times]
    return (f"  {label:10s} wall best {min(walls):5.2f} s, median {statistics.median(walls):5.2f} s; "
            f"processor best {min(cpus):5.2f} s, median {statistics.median(cpus):5.2f} s")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--baseline", default=BASELINE, help=f"commit of the baseline (default {BASELINE})")
    parser.add_argument("--repeats", type=int, default=5, help="counted runs of each case and tree (default 5)")
    options = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        trees = {"this tree": ROOT / "src", f"{options.baseline}": baseline_tree(options.baseline, tmp)}
        for title, args in CASES:
            times = {label: [] for label in trees}
            for label, src in trees.items():
                command(src, args, tmp / "warm")
            load = [os.getloadavg()[0]]
            for i in range(options.repeats):
                for label, src in trees.items():
                    times[label].append(command(src, args, tmp / "out"))
                load.append(os.getloadavg()[0])
            goal = f" (goal <= {GOAL_S:g} s wall on 2 cores)" if not args else ""
            print(f"valvetrain run, {title}{goal}: {options.repeats} warm runs each, load average "
                  f"{min(load):.1f}-{max(load):.1f} on {os.cpu_count()} cores")
            for label, t in times.items():
                print(_line(label, t))


if __name__ == "__main__":
    main()
