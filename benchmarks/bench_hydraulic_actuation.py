"""Benchmark: ``valvetrain run examples/marine-hydraulic-exhaust.toml`` and where its time goes.

Run on demand: ``python benchmarks/bench_hydraulic_actuation.py``.  Prints, best of several repeats:

* the command itself (a subprocess, as a user types it, its byte code compiled by the first, uncounted run): wall
  time and CPU time (user + system);
* the same command on the example without its ``[valves.exhaust.hydraulic]`` section, the baseline measured in the
  same run: the difference is what the hydraulic stage and its two figures cost;
* in one process: the imports, ``design.run``, the hydraulic stage alone (14 revolutions: the simulated speed, the
  12 speeds of the sweep and the simulated speed without the gas force) and ``write_outputs`` with its figures.

Wall times depend on the load of the machine (2 cores shared); CPU times much less, so both are printed.
"""

import os
from pathlib import Path
import resource
import subprocess
import sys
import tempfile
import time

EXAMPLE = Path(__file__).parents[1] / "examples" / "marine-hydraulic-exhaust.toml"
REPEATS = 3


def _command(spec_path, out):
    """Wall and CPU time [s] of one ``valvetrain run`` of ``spec_path`` as a subprocess, its byte code kept beside
    ``out`` (as an installed package keeps it, even where ``PYTHONDONTWRITEBYTECODE`` is set: compiling every module
    at each start would add 0.3 s)."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run([sys.executable, "-m", "valvetrain", "run", str(spec_path), "--out", str(out)], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                   env={**env, "PYTHONPYCACHEPREFIX": str(out.parent / "pycache")})
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def _without_hydraulic(text):
    """The example's text without its hydraulic section (the lines from its header to the next section)."""
    out, skipping = [], False
    for line in text.splitlines():
        if line.startswith("["):
            skipping = line.strip() == "[valves.exhaust.hydraulic]"
        if not skipping:
            out.append(line)
    return "\n".join(out) + "\n"


def _best(pairs):
    return min(w for w, _ in pairs), min(c for _, c in pairs)


def _in_process(tmp):
    """Wall and CPU times [s] of the stages of one run in this process (the first import included)."""
    clock = [(time.perf_counter(), time.process_time())]

    def lap():
        clock.append((time.perf_counter(), time.process_time()))
        return clock[-1][0] - clock[-2][0], clock[-1][1] - clock[-2][1]

    from valvetrain.design import run
    from valvetrain.design.hydraulic_actuation import CylinderPressure, hydraulic_stage
    from valvetrain.export import write_outputs
    from valvetrain.specification import load_spec, si
    imports = lap()
    spec = load_spec(EXAMPLE)
    results = run(spec)
    design = lap()
    valve = results.valves["exhaust"]
    cylinder = CylinderPressure(results.crank.phi, results.crank.columns.p_abs, results.crank.pressure_source)
    args = (si(spec.valves["exhaust"], spec), valve.cam.law, si(spec.engine), si(spec.gas), "exhaust",
            valve.cam.nose, cylinder)
    stage = []
    for _ in range(5):
        lap()
        hydraulic_stage(*args)
        stage.append(lap())
    lap()
    write_outputs(results, Path(tmp) / "in-process")
    write = lap()
    return imports, design, _best(stage), write


def main():
    with tempfile.TemporaryDirectory() as tmp:
        bare = Path(tmp) / "no-hydraulic.toml"
        bare.write_text(_without_hydraulic(EXAMPLE.read_text(encoding="utf-8")), encoding="utf-8")
        _command(EXAMPLE, Path(tmp) / "warm")            # the numba cache and the file cache warm
        full = _best([_command(EXAMPLE, Path(tmp) / f"full{i}") for i in range(REPEATS)])
        base = _best([_command(bare, Path(tmp) / f"bare{i}") for i in range(REPEATS)])
        imports, design, stage, write = _in_process(tmp)
    print(f"load average {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores; best of {REPEATS}, wall / CPU")
    print(f"valvetrain run {EXAMPLE.name}:        {full[0]:6.2f} s / {full[1]:6.2f} s")
    print(f"  baseline, without its hydraulic section: {base[0]:6.2f} s / {base[1]:6.2f} s")
    print(f"  difference (the stage and its figures):  {full[0] - base[0]:6.2f} s / {full[1] - base[1]:6.2f} s")
    print("in one process:")
    print(f"  imports                                  {imports[0]:6.2f} s / {imports[1]:6.2f} s")
    print(f"  design.run (with the hydraulic stage)    {design[0]:6.2f} s / {design[1]:6.2f} s")
    print(f"  hydraulic stage alone (14 revolutions)   {stage[0] * 1e3:6.1f} ms / {stage[1] * 1e3:6.1f} ms")
    print(f"  write_outputs (figures, report, tables)  {write[0]:6.2f} s / {write[1]:6.2f} s")


if __name__ == "__main__":
    main()
