"""Benchmark: the processor time of each default figure of ``valvetrain run`` (the built-in example), beside the
same figures of baseline trees measured in the same run.

Run on demand: ``python benchmarks/bench_figures.py [--baseline REF ...] [--repeats N] [--lang en|ru]``.

Each baseline is the package of the commit ``REF`` (default: main), unpacked into a temporary folder (``git
archive``, :func:`bench_run.baseline_tree`).  Each repeat runs, for this tree and each baseline in turn, a new
process (``--worker``) that designs the built-in example, then does what a drawing process of the run does
(:mod:`valvetrain.report.drawing`): the results as the drawers receive them (``figure_inputs``), matplotlib imported
and warmed (``_warm_up``), then every figure of ``--figures main`` drawn into memory (``write_plots``), each
figure's processor time taken between the drawer's claims (``write_plots``'s ``claim`` is called once before the
first figure and once after each).  Printed: each figure's median processor time over the repeats, the total and
the import and warm-up, with the median of the ratios of this tree's time to the baseline's, run beside it (the
machine is shared: processor time, not wall time, is the figure that does not depend on the others' load).
"""

import argparse
import json
import os
from pathlib import Path
import statistics
import subprocess
import sys
import tempfile
import time

from bench_run import ROOT, baseline_tree


def worker(lang):
    """Design the built-in example and draw its default figures as a drawer does; print the processor times [s]."""
    from valvetrain.design import run
    from valvetrain.specification import example_spec

    results = run(example_spec())
    start = time.process_time()
    from valvetrain.report import drawing
    from valvetrain.report.plots import write_plots

    inputs = drawing.figure_inputs(results, "main")
    drawing._warm_up()
    warm = time.process_time() - start
    stamps = []

    def claim():
        stamps.append(time.process_time())
        return len(stamps) - 1

    written = write_plots(inputs, {}, lang, "main", claim=claim)
    names = [name for files in written.values() for name in ([files] if isinstance(files, str) else files.values())]
    times = [b - a for a, b in zip(stamps, stamps[1:])]
    print(json.dumps({"import and warm-up": warm, **dict(zip(names, times, strict=True))}))


def measure(src, lang):
    """The processor times [s] of :func:`worker` run with the package in ``src``."""
    env = {**os.environ, "PYTHONPATH": str(src)}
    out = subprocess.run([sys.executable, __file__, "--worker", "--lang", lang], check=True, capture_output=True,
                         text=True, env=env).stdout
    return json.loads(out.splitlines()[-1])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--baseline", action="append", help="commit of a baseline, repeatable (default main)")
    parser.add_argument("--repeats", type=int, default=5, help="processes of each tree (default 5)")
    parser.add_argument("--lang", default="en", choices=("en", "ru"), help="the figures' language (default en)")
    parser.add_argument("--worker", action="store_true", help=argparse.SUPPRESS)
    options = parser.parse_args()
    if options.worker:
        worker(options.lang)
        return
    with tempfile.TemporaryDirectory() as tmp:
        trees = {"this tree": ROOT / "src"}
        for k, ref in enumerate(options.baseline or ["main"]):
            (Path(tmp) / str(k)).mkdir()
            trees[ref] = baseline_tree(ref, Path(tmp) / str(k)) / "src"
        for src in trees.values():
            measure(src, options.lang)                       # numba's cache and the byte code filled, not counted
        runs = {label: [] for label in trees}
        load = [os.getloadavg()[0]]
        for _ in range(options.repeats):
            for label, src in trees.items():
                runs[label].append(measure(src, options.lang))
            load.append(os.getloadavg()[0])
    print(f"Default figures of the built-in example ({options.lang}), processor time per figure [ms], median of "
          f"{options.repeats} processes each; load average {min(load):.1f}-{max(load):.1f} on {os.cpu_count()} cores")
    ours = runs.pop("this tree")
    for key in ours[0]:
        line = f"  {key:32s} this tree {statistics.median(r[key] for r in ours) * 1e3:7.1f}"
        for label, theirs in runs.items():
            if key in theirs[0]:
                ratio = statistics.median(a[key] / b[key] for a, b in zip(ours, theirs))
                line += f"; {label} {statistics.median(r[key] for r in theirs) * 1e3:7.1f} (ratio {ratio:.2f})"
        print(line)
    total = [sum(v for k, v in r.items() if k.endswith(".png")) for r in ours]
    line = f"  {'all figures':32s} this tree {statistics.median(total) * 1e3:7.1f}"
    for label, theirs in runs.items():
        their_total = [sum(v for k, v in r.items() if k.endswith(".png")) for r in theirs]
        line += (f"; {label} {statistics.median(their_total) * 1e3:7.1f} (ratio "
                 f"{statistics.median(a / b for a, b in zip(total, their_total)):.2f})")
    print(line)


if __name__ == "__main__":
    main()
