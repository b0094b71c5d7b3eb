"""Benchmark: a whole ``valvetrain run``, the command itself, beside the same command of baseline trees.

Run on demand: ``python benchmarks/bench_run.py [--baseline REF ...] [--repeats N]``.

Each baseline is the package of the commit ``REF`` (default :data:`BASELINES`: the tree before the work on the run's
speed, and main), unpacked into a temporary folder (``git archive``); each case runs ``python -m valvetrain run ...
--out DIR`` in a new process, imports included, in turn with this tree's ``src`` and each baseline's on
``PYTHONPATH``, after one run of each that is not counted (it fills numba's on-disk cache of the unpacked baseline,
the byte code of each tree's modules and the page cache): the times are those of warm runs, as an installed package
runs them (pip compiles the byte code; the byte code goes to a temporary folder, ``PYTHONPYCACHEPREFIX``, even where
``PYTHONDONTWRITEBYTECODE`` is set, which would compile every module of the package at each start, 0.3 s).  Cases
(:data:`CASES`): the built-in example with the default figures and with ``--figures none``, the textbook's appendix
(7cf5134's built-in example, which 7cf5134 runs beside it), ``examples/pushrod-dynamics.toml`` (a ``[dynamics]`` section) and
``examples/marine-hydraulic-exhaust.toml`` (a ``[hydraulic]`` section) with the default figures.  For each: the
best and the median wall time and processor time (the process and its children: the drawing processes) of
``--repeats`` runs, the median of the ratios of this tree's time to each baseline's, run beside it, and the load
average of the machine while they ran (on a machine that others use the wall time is the processor time plus the
wait, and a core that another process holds stretches it).
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
BASELINES = ("7cf5134", "main")
"""The commit before the work on the speed of ``valvetrain run`` (issue 22), and the main branch."""
GOAL_S = 2.0
"""Wall time of ``valvetrain run`` of the built-in example with the default figures, on a 2-core machine [s]."""
CASES = (("built-in example, default figures (the baseline's own built-in example)", [], None),
         ("the textbook's appendix, default figures (the built-in example until 7cf5134)",
          ["{examples}/seed000-appendix-kurz.toml"], []),
         ("built-in example, --figures none (the baseline's own built-in example)", ["--figures", "none"], None),
         ("examples/pushrod-dynamics.toml, default figures (each tree's own file)",
          ["{examples}/pushrod-dynamics.toml"], None),
         ("examples/marine-hydraulic-exhaust.toml, default figures (goal <= 4 s wall on 2 cores)",
          ["{examples}/marine-hydraulic-exhaust.toml"], None))
"""Each case: its title, the arguments of the run and those of the first baseline's, 7cf5134 (None: the same);
``{examples}`` is the tree's own examples folder, whose files match its package's keys."""


def command(src, args, out, pycache):
    """(wall, processor) time [s] of one ``valvetrain run`` of the package in ``src``, in a new process whose byte code
    is kept in ``pycache``."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run([sys.executable, "-m", "valvetrain", "run", *args, "--out", str(out)], check=True,
                   stdout=subprocess.DEVNULL, env={**env, "PYTHONPATH": str(src), "PYTHONPYCACHEPREFIX": str(pycache)})
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def baseline_tree(ref, folder):
    """The root of commit ``ref``'s ``src`` and ``examples`` folders, unpacked into ``folder``."""
    archive = subprocess.run(["git", "-C", str(ROOT), "archive", ref, "src", "examples"], check=True,
                             capture_output=True).stdout
    subprocess.run(["tar", "-x", "-C", str(folder)], input=archive, check=True)
    return folder


def _line(label, times, ours=None):
    walls, cpus = [w for w, _ in times], [c for _, c in times]
    paired = "" if ours is None else (
        f"; this tree / it, paired: wall {statistics.median(a[0] / b[0] for a, b in zip(ours, times)):.2f}, "
        f"processor {statistics.median(a[1] / b[1] for a, b in zip(ours, times)):.2f}")
    return (f"  {label:10s} wall best {min(walls):5.2f} s, median {statistics.median(walls):5.2f} s; "
            f"processor best {min(cpus):5.2f} s, median {statistics.median(cpus):5.2f} s{paired}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--baseline", action="append",
                        help=f"commit of a baseline, repeatable (default {' and '.join(BASELINES)})")
    parser.add_argument("--repeats", type=int, default=5, help="counted runs of each case and tree (default 5)")
    parser.add_argument("--case", type=int, action="append",
                        help=f"only the case of this number, 1-{len(CASES)}, repeatable (default: every case)")
    options = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        trees = {"this tree": ROOT}
        for k, ref in enumerate(options.baseline or BASELINES):
            (tmp / str(k)).mkdir()
            trees[ref] = baseline_tree(ref, tmp / str(k))
        for number, (title, args, baseline_args) in enumerate(CASES, 1):
            if options.case and number not in options.case:
                continue
            runs = {label: ([a.format(examples=root / "examples") for a in
                             (args if label != BASELINES[0] or baseline_args is None else baseline_args)],
                            root / "src")
                    for label, root in trees.items()}
            times = {label: [] for label in trees}
            for label, (run_args, src) in runs.items():
                command(src, run_args, tmp / "warm", tmp / "pycache")
            load = [os.getloadavg()[0]]
            for i in range(options.repeats):
                for label, (run_args, src) in runs.items():
                    times[label].append(command(src, run_args, tmp / "out", tmp / "pycache"))
                load.append(os.getloadavg()[0])
            goal = f" (goal <= {GOAL_S:g} s wall on 2 cores)" if not args else ""
            print(f"{number}. valvetrain run, {title}{goal}: {options.repeats} warm runs each, load average "
                  f"{min(load):.1f}-{max(load):.1f} on {os.cpu_count()} cores")
            for label, t in times.items():
                print(_line(label, t, None if label == "this tree" else times["this tree"]))


if __name__ == "__main__":
    main()
