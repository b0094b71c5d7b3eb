"""Benchmark: a tolerance study of the built-in example with its dynamics (issues 27 and 38), serially, with
``--workers 2`` and on a local Dask cluster, beside a baseline tree in the same run.

Run on demand: ``python benchmarks/bench_tolerance.py [--samples N] [--baseline SRC]``, e.g. ``--baseline
/work/wt/base/src`` (the ``src`` folder of another checkout: the last landed tree).  The built-in example (two valves,
each with a [dynamics] sweep of 200 speeds) gets four tolerances (both clearances, uniform +-0.03 mm; both valve
masses, normal sigma 1 g), or with ``--tolerances 2`` the README's two (the intake's clearance and valve mass: a
process designs the exhaust valve once, :data:`valvetrain.tolerance.DESIGNS`).  Each tree is measured in a process
of its own (``PYTHONPATH`` its ``src``), this tree first, then the baseline; printed for each:

* the processor time of one sample (all threads of the process, the median over 16 distinct samples of the study;
  the other jobs of a shared machine change it less than the wall time), :func:`valvetrain.tolerance.evaluate_sample`,
  beside the full design of the same documents (:func:`valvetrain.design.run` as ``valvetrain run`` designs, every
  speed of the sweeps; the median of 6), and the time 10^4 samples take at it on two idle cores;
* ``valvetrain tolerance`` of N Latin-hypercube samples as a whole command (start-up, validation, the samples, the
  writing) serially, with ``--workers 2`` and on a Dask ``LocalCluster`` of two one-thread worker processes: the
  wall time and samples per second of each, the processor time of the command and its worker processes (serial and
  ``--workers 2``: the Dask workers are the cluster's, not the command's) with the samples per processor second,
  the load average of the machine when it ended, and whether the three give the same results;
* the ratios of this tree to the baseline: samples per second (the wall rate, which the load of other jobs moves)
  and samples per processor second (which it moves less), and the processor time of a sample of the two trees
  measured in turn, three times each (the trees' own figures above are minutes apart: on 2026-12-02 under a load
  of 6-10 they gave 0.217 against 0.214 s where the trees in turn gave 0.8 times the baseline's); ``--alternate
  --baseline SRC`` measures this alone (about a minute);
* what a Dask cluster of K machines like this one would do: the tasks are independent, so the rate is K times the
  local cluster's (less the scheduler's 3-6 ms a task of up to 32 samples), and K times two cores over the processor
  time of a sample on idle machines.

On a machine shared with other jobs the wall rates follow the load: compare the trees by the processor-time figures
and re-measure the wall rates idle.
"""

import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

CLEARANCE = """[[tolerances]]
key = "valves.{}.clearance_mm"
distribution = "uniform"
half_range = 0.03
"""

VALVE_MASS = """[[tolerances]]
key = "valves.{}.drive.masses.valve_kg"
distribution = "normal"
sigma = 0.001
"""

TOLERANCES = {4: "".join("\n" + t.format(v) for t in (CLEARANCE, VALVE_MASS) for v in ("intake", "exhaust")),
              2: "".join("\n" + t.format("intake") for t in (CLEARANCE, VALVE_MASS))}
"""The tolerances added to the built-in example, by their count (``--tolerances``)."""

SOURCE = Path(__file__).resolve().parent.parent / "src"
"""This tree's package folder."""


def children_cpu():
    """Processor time [s] of the waited child processes of this one (and theirs) so far."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def tolerance(spec, out, samples, *backend):
    """``valvetrain tolerance`` with ``backend`` options: its wall time [s], its processor time with its worker
    processes [s], its tolerance.json without the folder's name, and the load average over the last minute when it
    ended."""
    c0, t0 = children_cpu(), time.perf_counter()
    subprocess.run([sys.executable, "-m", "valvetrain", "tolerance", str(spec), "--samples", str(samples),
                    "--method", "lhs", "--out", str(out), *backend], check=True, stdout=subprocess.DEVNULL)
    wall, cpu = time.perf_counter() - t0, children_cpu() - c0
    result = json.loads((out / "tolerance.json").read_text(encoding="utf-8").replace(out.name, "X"))
    return {"wall": wall, "cpu": cpu, "load": os.getloadavg()[0],
            "result": {k: result[k] for k in ("checks", "headlines", "refused", "failed")}}


def cpu_per_call(function, documents):
    """Processor time of one call [s]: the median of the calls on ``documents`` after a warm-up call on the first
    (the median, as the other jobs of a shared machine slow some calls down)."""
    function(documents[0])
    times = []
    for document in documents:
        c0 = time.process_time()
        function(document)
        times.append(time.process_time() - c0)
    return statistics.median(times)


def distinct_samples(path, count):
    """``count`` samples of the study of the file ``path`` (Latin hypercube, seed 1), the documents a study designs:
    a process designing one document again would take the designs it keeps of the last
    (:data:`valvetrain.tolerance.DESIGNS`)."""
    from valvetrain.specification import load_spec
    from valvetrain.study import read_document, with_values
    from valvetrain.tolerance import check_tolerances, draw

    document, spec = read_document(path), load_spec(path)
    keys = [t.key for t in spec.tolerances]
    values = draw(spec, check_tolerances(document, spec), count, "lhs", 1)
    return [with_values(document, dict(zip(keys, map(float, row), strict=True))) for row in values]


def measure(samples):
    """Every figure of the tree on ``sys.path`` (run in a process of its own), a dict."""
    from distributed import LocalCluster

    import valvetrain
    from valvetrain.design import run
    from valvetrain.specification import example_text, validate
    from valvetrain.tolerance import evaluate_sample

    out = {"tree": str(Path(valvetrain.__file__).parent.parent)}
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        spec = tmp / "engine.toml"
        spec.write_text(example_text() + TOLERANCES[ARGS.tolerances], encoding="utf-8")
        documents = distinct_samples(spec, 16)
        out["load"] = os.getloadavg()[0]
        out["full"] = cpu_per_call(lambda d: run(validate(d)), documents[:6])   # first: evaluate_sample keeps the heap
        out["sample"] = cpu_per_call(evaluate_sample, documents)
        out["serial"] = tolerance(spec, tmp / "serial", samples)
        out["workers"] = tolerance(spec, tmp / "workers", samples, "--workers", "2")
        with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
            out["dask"] = tolerance(spec, tmp / "dask", samples, "--scheduler", cluster.scheduler_address)
    return out


def measured(source, samples):
    """:func:`measure` of the tree whose package folder is ``source``, in a child process."""
    env = dict(os.environ, PYTHONPATH=str(source))
    res = subprocess.run([sys.executable, __file__, "--child", "--samples", str(samples),
                          "--tolerances", str(ARGS.tolerances)], env=env, check=True,
                         capture_output=True, text=True)
    return json.loads(res.stdout.splitlines()[-1])


def sample_cpu():
    """The processor time of one sample [s] (:func:`cpu_per_call` of :func:`valvetrain.tolerance.evaluate_sample` on
    the 16 distinct samples) of the tree on ``sys.path``, run in a process of its own."""
    from valvetrain.specification import example_text
    from valvetrain.tolerance import evaluate_sample

    with tempfile.TemporaryDirectory() as tmp:
        spec = Path(tmp) / "engine.toml"
        spec.write_text(example_text() + TOLERANCES[ARGS.tolerances], encoding="utf-8")
        return cpu_per_call(evaluate_sample, distinct_samples(spec, 16))


def alternate(baseline, rounds=3):
    """:func:`sample_cpu` of this tree and of the baseline in child processes taken in turn, ``rounds`` times each
    (the load of other jobs then weighs on both alike): the lists of seconds, (this, baseline)."""
    times = ([], [])
    for _ in range(rounds):
        for source, into in zip((SOURCE, Path(baseline).resolve()), times, strict=True):
            env = dict(os.environ, PYTHONPATH=str(source))
            res = subprocess.run([sys.executable, __file__, "--child-sample", "--tolerances", str(ARGS.tolerances)],
                                 env=env, check=True, capture_output=True, text=True)
            into.append(float(res.stdout.split()[-1]))
    return times


def show(name, m, samples):
    """Print the figures of one tree."""
    print(f"\n{name} ({m['tree']}): CPU time of one sample {m['sample']:.3f} s (the full design, every speed of "
          f"the sweeps: {m['full']:.3f} s, {m['full'] / m['sample']:.1f} times as much); load average {m['load']:.1f}")
    print(f"  10^4 samples on an otherwise idle 2-core machine at that CPU time: {1e4 * m['sample'] / 2 / 60:.1f} min")
    for key, label in (("serial", "serial"), ("workers", "--workers 2"),
                       ("dask", "Dask LocalCluster, 2 workers x 1 thread")):
        r = m[key]
        cpu = (f", {r['cpu']:.1f} s processor time ({samples / r['cpu']:.2f} samples per processor second)"
               if key != "dask" else "")
        print(f"  tolerance, {samples} samples, {label}: {r['wall']:.1f} s, {samples / r['wall']:.2f} samples/s "
              f"(10^4 samples: {1e4 * r['wall'] / samples / 60:.1f} min){cpu}; load average {r['load']:.1f}")
    same = m["serial"]["result"] == m["workers"]["result"] == m["dask"]["result"]
    print(f"  same results serial, --workers 2 and Dask: {same}")


def main():
    samples = ARGS.samples
    print(f"tolerance benchmark: the built-in example with {ARGS.tolerances} tolerances, {samples} samples, "
          f"{os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f} at the start")
    new = measured(SOURCE, samples)
    show("this tree", new, samples)
    if ARGS.baseline:
        base = measured(Path(ARGS.baseline).resolve(), samples)
        show("baseline", base, samples)
        print("\nthis tree / baseline:")
        print(f"  processor time of a sample: {new['sample'] / base['sample']:.2f} (baseline / this: "
              f"{base['sample'] / new['sample']:.2f} x the samples per processor second)")
        for key, label in (("serial", "serial"), ("workers", "--workers 2"), ("dask", "Dask")):
            wall = base[key]["wall"] / new[key]["wall"]
            cpu = (f", samples per processor second x {base[key]['cpu'] / new[key]['cpu']:.2f}"
                   if key != "dask" else "")
            print(f"  {label}: samples/s x {wall:.2f}{cpu}")
        print(f"  same results as the baseline (serial): {new['serial']['result'] == base['serial']['result']}")
        mine, theirs = alternate(ARGS.baseline)
        print(f"  processor time of a sample, the trees taken in turn 3 times (load average {os.getloadavg()[0]:.1f}): "
              f"{', '.join(f'{t:.3f}' for t in mine)} s against {', '.join(f'{t:.3f}' for t in theirs)} s, this / "
              f"baseline {statistics.median(mine) / statistics.median(theirs):.2f} (of the medians)")
    for k in (4, 16, 64):
        rate = k * samples / new["dask"]["wall"]
        print(f"a Dask cluster of {k} machines like this one: {rate:.1f} samples/s at the Dask rate measured here, "
              f"{k * 2 / new['sample']:.0f} samples/s on idle machines; 10^4 samples in {1e4 / rate / 60:.2f} min "
              f"and {1e4 / (k * 2 / new['sample']) / 60:.2f} min")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=int, default=100)
    parser.add_argument("--tolerances", type=int, choices=sorted(TOLERANCES), default=4,
                        help="4: both valves' clearances and masses; 2: the intake's (the README's example)")
    parser.add_argument("--baseline", help="the src folder of the baseline tree (e.g. /work/wt/base/src)")
    parser.add_argument("--child", action="store_true", help=argparse.SUPPRESS)
    parser.add_argument("--child-sample", action="store_true", help=argparse.SUPPRESS)
    parser.add_argument("--alternate", action="store_true",
                        help="only the processor time of a sample of this tree and the baseline's, taken in turn")
    ARGS = parser.parse_args()
    if ARGS.child_sample:
        print(sample_cpu())
    elif ARGS.alternate:
        mine, theirs = alternate(ARGS.baseline)
        print(f"processor time of a sample, this tree and the baseline in turn (load average "
              f"{os.getloadavg()[0]:.1f}): {', '.join(f'{t:.3f}' for t in mine)} s against "
              f"{', '.join(f'{t:.3f}' for t in theirs)} s; this / baseline "
              f"{statistics.median(mine) / statistics.median(theirs):.2f} (of the medians)")
    elif ARGS.child:
        print(json.dumps(measure(ARGS.samples)))
    else:
        main()
