#!/usr/bin/env python
"""Compare the numbers a change writes with those written before it, byte for byte.

``write OUT`` designs the built-in example and every ``examples/*.toml`` and writes, for each, what a run writes
but the figures, the report and the list of files (results.json, spec.toml, tables/, contour/ with the DXF) into
``OUT/NAME``;
``diff A B`` compares two such folders file by file and exits 1 when a file differs or is missing;
``expected DIR`` writes a small fingerprint of each example's results.json, tables, contours and report text into
``DIR/NAME.json``, which ``tests/test_outputs.py`` compares a run with (numbers to :data:`RTOL`, text exactly).  A speed change
that keeps the method keeps every file.  Run ``write`` once on the tree before the change, once after (the files
name the tree's absolute paths in spec.toml where a table file is read: compare trees at the same path)::

    PYTHONPATH=src python tools/compare_outputs.py write /tmp/before    # before the change
    PYTHONPATH=src python tools/compare_outputs.py write /tmp/after     # after it
    python tools/compare_outputs.py diff /tmp/before /tmp/after

After a deliberate change of the outputs, refresh the expected fingerprints of the test (and say why in the
commit)::

    PYTHONPATH=src python tools/compare_outputs.py expected tests/data/outputs

``machines [VARIANT ...]`` checks that the fingerprints do not depend on the machine: it writes them in a
subprocess per variant, a set of environment variables (``OPENBLAS_CORETYPE=Prescott``, or several joined by
commas), and compares each with those of this machine's defaults; without variants, every OpenBLAS kernel this
CPU can run and numba compiling for a generic CPU (``NUMBA_CPU_NAME=generic``).  numpy's own SIMD loops can be
narrowed with ``NPY_DISABLE_CPU_FEATURES`` (``X86_V3`` with numpy 2.4)::

    PYTHONPATH=src python tools/compare_outputs.py machines
    PYTHONPATH=src python tools/compare_outputs.py machines NPY_DISABLE_CPU_FEATURES=X86_V3 --names measured-lobe
"""

import argparse
import csv
import filecmp
import hashlib
import io
import json
import math
import os
from pathlib import Path
import re
import subprocess
import sys
import tempfile

EXAMPLES = Path(__file__).parents[1] / "examples"


RTOL = 1e-9
"""Relative tolerance of a number in :func:`compare` (tables are written with 10 significant digits)."""

ATOL = 1e-12
"""Absolute tolerance of a number in :func:`compare`, for values that should be zero (in the file's units)."""

ANGLE_ATOL = 1e-9
"""Absolute tolerance of an angle [deg] (a key or column named ``*_deg``), RTOL of a degree: an angle near zero is the
difference of angles of the order of a turn and carries their round-off (a table's camshaft angles from a measured
lobe's nose, itself fitted, come out some 1e-11 deg apart on two BLAS kernels), which RTOL of its own size would ask
to vanish."""

EXTREMUM_ATOL = math.sqrt(2.2e-16) * 360.0
"""Absolute tolerance [deg] of the location of an extremum found by Brent's method (:data:`EXTREMA`), sqrt(eps) of a
turn: the method stops within sqrt(eps) of the abscissa (``numerics.bounded_minimum``), and at a flat extremum the
values are equal to round-off over some sqrt(eps) of its width, so the point it stops at moves with the round-off of
the function (measured-lobe's rho_min_cam_deg: 0.35106824 and 0.35106829 on two BLAS kernels), while the value
there, compared to :data:`RTOL`, does not."""

EXTREMA = {"rho_min_cam_deg", "rho_max_cam_deg", "max_velocity_crank_deg", "max_acceleration_crank_deg",
           "min_acceleration_crank_deg"}
"""The keys of locations of extrema refined by Brent's method (``numerics.extremum``): a profile's smallest and
largest radius, the piston's extreme velocity and accelerations."""

SAMPLED = 24
"""Longest list of numbers a fingerprint keeps whole; a longer one keeps about this many and its sums."""


def write(out, report=False, names=None):
    """Write the numbers of every example (those of ``names`` where given) into ``out`` (and ``report.html`` without
    figures where ``report``); a refused specification writes ``NAME/ERROR``."""
    from valvetrain.design import run
    from valvetrain.export import write_outputs
    from valvetrain.specification import SpecError, example_spec, load_spec

    files = {f.stem: f for f in sorted(EXAMPLES.glob("*.toml"))}
    chosen = ["builtin", *files] if names is None else names
    for name in chosen:
        spec = example_spec() if name == "builtin" else load_spec(files[name])
        try:
            results = run(spec)
        except SpecError as err:
            (out / name).mkdir(parents=True, exist_ok=True)
            (out / name / "ERROR").write_text("\n".join(err.problems), encoding="utf-8")
            continue
        write_outputs(results, out / name, force=True, figures="none")
        for other in ("report.html", ".valvetrain-output")[int(report):]:   # text around the figures, the list of files
            (out / name / other).unlink()
        print(f"{name}: written")


def diff(a, b):
    """The number of files of ``a`` and ``b`` that differ or are missing from one of them."""
    files = [{p.relative_to(top) for p in top.rglob("*") if p.is_file()} for top in (a, b)]
    bad = sorted(files[0] ^ files[1])
    bad += [p for p in sorted(files[0] & files[1]) if not filecmp.cmp(a / p, b / p, shallow=False)]
    for p in bad:
        print(f"differs or missing: {p}")
    print(f"{len(files[0] | files[1])} files compared, {len(bad)} differ")
    return len(bad)


def _number(cell):
    """A CSV cell as a number (None for an empty cell), or the cell itself where it is text."""
    if cell == "":
        return None
    try:
        return float(cell)
    except ValueError:
        return cell


def _numbers(values):
    """A list of numbers (None allowed) whole, or sampled: about :data:`SAMPLED` of them, with their count, sum and
    sum of magnitudes."""
    if len(values) <= SAMPLED:
        return list(values)
    step = math.ceil(len(values) / SAMPLED)
    kept = [v for v in values if v is not None]
    return {"sampled": [values[i] for i in [*range(0, len(values), step), len(values) - 1]], "n": len(values),
            "sum": math.fsum(kept), "abs": math.fsum(abs(v) for v in kept)}


def _is_numbers(values):
    return all(v is None or (isinstance(v, (int, float)) and not isinstance(v, bool)) for v in values)


def _digest(x):
    """A JSON value with its long lists of numbers sampled (:func:`_numbers`)."""
    if isinstance(x, dict):
        return {k: _digest(v) for k, v in x.items()}
    if isinstance(x, list):
        return _numbers(x) if len(x) > SAMPLED and _is_numbers(x) else [_digest(v) for v in x]
    return x


def _table(path):
    """A CSV file's fingerprint: comment lines and header as text, each column sampled (numbers) or run-length
    encoded (text)."""
    lines = path.read_text(encoding="utf-8").splitlines()
    comments = [line for line in lines if line.startswith("#")]
    rows = list(csv.reader(io.StringIO("\n".join(line for line in lines if not line.startswith("#")))))
    columns = {}
    for i, head in enumerate(rows[0]):
        cells = [_number(r[i]) for r in rows[1:]]
        if _is_numbers(cells):
            columns[head] = _numbers(cells)
        else:
            runs = []
            for c in cells:
                if runs and runs[-1][0] == c:
                    runs[-1][1] += 1
                else:
                    runs.append([c, 1])
            columns[head] = {"runs": runs}
    return {"comments": comments, "header": rows[0], "rows": len(rows) - 1, "columns": columns}


def fingerprint(folder):
    """The fingerprint of one example's outputs: results.json (:func:`_digest`), every CSV of tables/ and contour/
    (:func:`_table`) and the SHA-256 of report.html (the package version and the folder of the examples, which the
    report names where a table file is read, left out: the same on every checkout)."""
    if (folder / "ERROR").exists():
        return {"ERROR": (folder / "ERROR").read_text(encoding="utf-8")}
    from valvetrain import __version__

    report = (folder / "report.html").read_text(encoding="utf-8").replace(f"valvetrain {__version__}", "valvetrain")
    report = report.replace(str(EXAMPLES.resolve()), "examples")
    out = {"results.json": _digest(json.loads((folder / "results.json").read_text(encoding="utf-8"))),
           "report.html sha256": hashlib.sha256(report.encode()).hexdigest()}
    out["results.json"].pop("valvetrain_version")
    for path in sorted(folder.glob("*/*.csv")):
        out[path.relative_to(folder).as_posix()] = _table(path)
    return out


def fingerprints(names=None):
    """The fingerprint of every example's outputs (those of ``names`` where given) as this tree makes them,
    ``name -> fingerprint``."""
    with tempfile.TemporaryDirectory() as tmp:
        write(Path(tmp), report=True, names=names)
        return {d.name: fingerprint(d) for d in sorted(Path(tmp).iterdir())}


def expected(out, names=None):
    """Write the fingerprints of this tree's outputs (of the examples ``names`` where given) as ``out/NAME.json``."""
    out.mkdir(parents=True, exist_ok=True)
    for name, found in fingerprints(names).items():
        (out / f"{name}.json").write_text(json.dumps(found, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")


OPENBLAS_KERNELS = {"Prescott": "sse3", "Core2": "ssse3", "Nehalem": "sse4_2", "Sandybridge": "avx",
                    "Haswell": "avx2", "Zen": "avx2", "SkylakeX": "avx512f"}
"""OpenBLAS's x86-64 kernels (``OPENBLAS_CORETYPE``) and the CPU flag each needs."""


def variants():
    """The default variants of :func:`machines`: each OpenBLAS kernel whose flag /proc/cpuinfo lists (Prescott alone
    where it cannot be read) and numba compiling for a generic x86-64."""
    try:
        flags = set(next(line for line in Path("/proc/cpuinfo").read_text().splitlines()
                         if line.startswith("flags")).split(":")[1].split())
    except (OSError, StopIteration):
        flags = {"sse3"}
    if "pni" in flags:      # Linux's name of SSE3
        flags.add("sse3")
    return [f"OPENBLAS_CORETYPE={k}" for k, flag in OPENBLAS_KERNELS.items() if flag in flags] + \
        ["NUMBA_CPU_NAME=generic"]


def fingerprints_with(variant, names=None):
    """The fingerprints of the examples ``names`` (every one by default) made in a subprocess with the environment
    variables of ``variant`` (``NAME=VALUE`` joined by commas; empty: this machine's defaults)."""
    import valvetrain

    env = {**os.environ, **dict(item.split("=", 1) for item in variant.split(",") if item)}
    env["PYTHONPATH"] = os.pathsep.join([str(Path(valvetrain.__file__).parents[1]),    # the package imported here
                                         *filter(None, [os.environ.get("PYTHONPATH")])])
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([sys.executable, __file__, "expected", tmp, *(names or [])], env=env, check=True,
                       stdout=subprocess.DEVNULL)
        return {p.stem: json.loads(p.read_text(encoding="utf-8")) for p in sorted(Path(tmp).glob("*.json"))}


def machines(chosen, names=None):
    """The number of variants (:func:`fingerprints_with`) whose fingerprints differ from this machine's defaults'
    (:func:`compare`); the differences are printed."""
    base = fingerprints_with("", names)
    bad = 0
    for variant in chosen:
        found = fingerprints_with(variant, names)
        lines = [line for name in base for line in compare(base[name], found.get(name), name)]
        print(f"{variant}: {'the same' if not lines else f'{len(lines)} differences'}")
        for line in lines[:40]:
            print(f"  {line}")
        bad += bool(lines)
    return bad


def _close(a, b, scale=0.0, atol=ATOL):
    return abs(a - b) <= RTOL * max(abs(a), abs(b), scale) + atol


def _atol(where):
    """The absolute tolerance of the number at ``where`` (a path of :func:`compare`), by its key's name."""
    name = re.sub(r"(\[\d+\])+$", "", where.rsplit("/", 1)[-1])
    return EXTREMUM_ATOL if name in EXTREMA else ANGLE_ATOL if name.endswith("_deg") else ATOL


def compare(want, got, where=""):
    """The differences between two fingerprints, one line each: numbers to :data:`RTOL` relative (and
    :data:`ATOL`; angles :data:`ANGLE_ATOL`, the locations of extrema :data:`EXTREMUM_ATOL`), everything else
    exactly; a sampled list's sums to :data:`RTOL` of the sum of its magnitudes."""
    if isinstance(want, dict) and "sampled" in want and isinstance(got, dict) and "sampled" in got:
        out = compare(want["sampled"], got["sampled"], where) + compare(want["n"], got["n"], where + " (count)")
        return out + ([] if _close(want["sum"], got["sum"], want["abs"]) and _close(want["abs"], got["abs"])
                      else [f"{where}: sums {want['sum']!r}, {want['abs']!r} != {got['sum']!r}, {got['abs']!r}"])
    if isinstance(want, dict) and isinstance(got, dict):
        keys = list(dict.fromkeys([*want, *got]))
        return [line for k in keys for line in (compare(want[k], got[k], f"{where}/{k}") if k in want and k in got
                                                 else [f"{where}/{k}: only in {'expected' if k in want else 'run'}"])]
    if isinstance(want, list) and isinstance(got, list) and len(want) == len(got):
        return [line for i, (a, b) in enumerate(zip(want, got)) for line in compare(a, b, f"{where}[{i}]")]
    numbers = [isinstance(x, (int, float)) and not isinstance(x, bool) for x in (want, got)]
    if all(numbers) and _close(want, got, atol=_atol(where)):
        return []
    return [] if want == got and type(want) is type(got) else [f"{where}: expected {want!r}, got {got!r}"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    sub.add_parser("write").add_argument("out", type=Path)
    both = sub.add_parser("diff")
    both.add_argument("a", type=Path)
    both.add_argument("b", type=Path)
    exp = sub.add_parser("expected")
    exp.add_argument("out", type=Path)
    exp.add_argument("names", nargs="*", help="the examples (all by default)")
    mach = sub.add_parser("machines")
    mach.add_argument("variants", nargs="*", help="NAME=VALUE[,NAME=VALUE...] each (default: every OpenBLAS kernel "
                                                   "this CPU runs, NUMBA_CPU_NAME=generic)")
    mach.add_argument("--names", nargs="*", help="the examples (all by default)")
    args = parser.parse_args()
    if args.command == "write":
        write(args.out)
    elif args.command == "expected":
        expected(args.out, args.names or None)
    elif args.command == "machines":
        sys.exit(1 if machines(args.variants or variants(), args.names) else 0)
    else:
        sys.exit(1 if diff(args.a, args.b) else 0)


if __name__ == "__main__":
    main()
