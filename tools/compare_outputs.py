#!/usr/bin/env python
"""Compare the numbers a change writes with those written before it, byte for byte.

``write OUT`` designs the built-in example and every ``examples/*.toml`` and writes, for each, what a run writes
but the figures, the report and the list of files (results.json, spec.toml, tables/, contour/ with the DXF) into
``OUT/NAME``;
``diff A B`` compares two such folders file by file and exits 1 when a file differs or is missing.  A speed change
that keeps the method keeps every file.  Run ``write`` once on the tree before the change, once after (the files
name the tree's absolute paths in spec.toml where a table file is read: compare trees at the same path)::

    PYTHONPATH=src python tools/compare_outputs.py write /tmp/before    # before the change
    PYTHONPATH=src python tools/compare_outputs.py write /tmp/after     # after it
    python tools/compare_outputs.py diff /tmp/before /tmp/after
"""

import argparse
import filecmp
from pathlib import Path
import sys

EXAMPLES = Path(__file__).parents[1] / "examples"


def write(out):
    """Write the numbers of every example into ``out``; a refused specification writes ``NAME/ERROR``."""
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
        for other in ("report.html", ".valvetrain-output"):   # text around the figures, the list of files
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


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    sub.add_parser("write").add_argument("out", type=Path)
    both = sub.add_parser("diff")
    both.add_argument("a", type=Path)
    both.add_argument("b", type=Path)
    args = parser.parse_args()
    if args.command == "write":
        write(args.out)
    else:
        sys.exit(1 if diff(args.a, args.b) else 0)


if __name__ == "__main__":
    main()
