"""Benchmark: a whole ``valvetrain run``, the command itself, beside the same command of a baseline tree.

Run on demand: ``python benchmarks/bench_run.py [--baseline REF] [--repeats N]``.

The baseline is the package of the commit ``REF`` (default :data:`BASELINE`, the tree before the work on the run's
speed), unpacked into a temporary folder (``git archive``); each case runs ``python -m valvetrain run ... --out DIR``
in a new process, imports included, alternately with this tree's ``src`` and the baseline's on ``PYTHONPATH``, after
one run of each that is not counted (it fills numba's on-disk cache of the unpacked baseline, and the page cache):
the times are those of warm runs.  Cases (:data:`CASES`): the built-in example with the default figures and with
``--figures none``, the textbook's appendix (the built-in example of the baseline) and
``examples/pushrod-dynamics.toml`` (a ``[dynamics]`` section) with the default figures.  For each: the best and the
median wall time and processor time (the process and its children: the drawing processes) of ``--repeats``
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
CASES = (("built-in example, default figures (the baseline's own built-in example)", [], None),
         ("the textbook's appendix, default figures (the built-in example until 7cf5134)",
          ["{examples}/seed000-appendix-kurz.toml"], []),
         ("built-in example, --figures none (the baseline's own built-in example)", ["--figures", "none"], None),
         ("examples/pushrod-dynamics.toml, default figures (each tree's own file)",
          ["{examples}/pushrod-dynamics.toml"], None))
"""Each case: its title, the arguments of this tree's run and those of the baseline's (None: the same); ``{examples}``
is the tree's own examples folder, whose files match its package's keys."""


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
    """The root of commit ``ref``'s ``src`` and ``examples`` folders, unpacked into ``folder``."""
    archive = subprocess.run(["git", "-C", str(ROOT), "archive", ref, "src", "examples"], check=True,
                             capture_output=True).stdout
    subprocess.run(["tar", "-x", "-C", str(folder)], input=archive, check=True)
    return folder


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
        trees = {"this tree": ROOT, f"{options.baseline}": baseline_tree(options.baseline, tmp)}
        for title, args, baseline_args in CASES:
            runs = {label: ([a.format(examples=root / "examples") for a in
                             (args if label == "this tree" or baseline_args is None else baseline_args)], root / "src")
                    for label, root in trees.items()}
            times = {label: [] for label in trees}
            for label, (run_args, src) in runs.items():
                command(src, run_args, tmp / "warm")
            load = [os.getloadavg()[0]]
            for i in range(options.repeats):
                for label, (run_args, src) in runs.items():
                    times[label].append(command(src, run_args, tmp / "out"))
                load.append(os.getloadavg()[0])
            goal = f" (goal <= {GOAL_S:g} s wall on 2 cores)" if not args else ""
            print(f"valvetrain run, {title}{goal}: {options.repeats} warm runs each, load average "
                  f"{min(load):.1f}-{max(load):.1f} on {os.cpu_count()} cores")
            for label, t in times.items():
                print(_line(label, t))


if __name__ == "__main__":
    main()
