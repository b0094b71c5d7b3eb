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
"""

import argparse
import csv
import filecmp
import hashlib
import io
import json
import math
from pathlib import Path
import sys
import tempfile

EXAMPLES = Path(__file__).parents[1] / "examples"


RTOL = 1e-9
"""Relative tolerance of a number in :func:`compare` (tables are written with 10 significant digits)."""

ATOL = 1e-12
"""Absolute tolerance of a number in :func:`compare`, for values that should be zero (in the file's units)."""

SAMPLED = 24
"""Longest list of numbers a fingerprint keeps whole; a longer one keeps about this many and its sums."""


def write(out, report=False):
    """Write the numbers of every example into ``out`` (and ``report.html`` without figures where ``report``); a
    refused specification writes ``NAME/ERROR``."""
    from valvetrain.design import run
    from valvetrain.export import write_outputs
    from valvetrain.specification import SpecError, example_spec, load_spec

    specs = {"builtin": example_spec(), **{f.stem: load_spec(f) for f in sorted(EXAMPLES.glob("*.toml"))}}
    for name, spec in specs.items():
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


def fingerprints():
    """The fingerprint of every example's outputs as this tree makes them, ``name -> fingerprint``."""
    with tempfile.TemporaryDirectory() as tmp:
        write(Path(tmp), report=True)
        return {d.name: fingerprint(d) for d in sorted(Path(tmp).iterdir())}


def expected(out):
    """Write the fingerprints of this tree's outputs as ``out/NAME.json``."""
    out.mkdir(parents=True, exist_ok=True)
    for name, found in fingerprints().items():
        (out / f"{name}.json").write_text(json.dumps(found, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")


def _close(a, b, scale=0.0):
    return abs(a - b) <= RTOL * max(abs(a), abs(b), scale) + ATOL


def compare(want, got, where=""):
    """The differences between two fingerprints, one line each: numbers to :data:`RTOL` relative (and
    :data:`ATOL`), everything else exactly; a sampled list's sums to :data:`RTOL` of the sum of its magnitudes."""
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
    if all(numbers) and _close(want, got):
        return []
    return [] if want == got and type(want) is type(got) else [f"{where}: expected {want!r}, got {got!r}"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    sub.add_parser("write").add_argument("out", type=Path)
    both = sub.add_parser("diff")
    both.add_argument("a", type=Path)
    both.add_argument("b", type=Path)
    sub.add_parser("expected").add_argument("out", type=Path)
    args = parser.parse_args()
    if args.command == "write":
        write(args.out)
    elif args.command == "expected":
        expected(args.out)
    else:
        sys.exit(1 if diff(args.a, args.b) else 0)


if __name__ == "__main__":
    main()
