#!/usr/bin/env python
"""Boundary fuzzing of the newer features: every numeric key of a section at, just inside and just outside the bounds
its pydantic field declares, plus zero, NaN, inf, a huge value and the section or key removed.

The keys are those of the sections a base specification holds (present or left at their defaults), read from the
models of ``valvetrain.specification`` (the :class:`~valvetrain.specification.fields.Range` of a bounded field, the
``ge``/``le`` of an integer field): the finger follower's ``finger_*`` keys, ``[lash_adjuster]``,
``[lubrication]``, ``[camshaft]``, ``[dynamics]`` and the valve, drive and spring keys around them.  Each case is
one ``set`` or ``delete`` operation of tools/fuzz_specs.py and runs through its ``run_case`` (``load_spec ->
design.run``, classified: ok, refused, traceback, hang, nan_output, nonsense, bad_message); ``--paths tolerance``
runs ``valvetrain tolerance`` per key with a ``[[tolerances]]`` entry reaching out of its range or a narrow normal
one, and ``--paths api`` runs ``valvetrain.api.design`` and ``api.sweep`` with dictionary specifications.

Usage (from the repository root)::

    PYTHONPATH=src python tools/fuzz_bounds.py --workers 2 --report /tmp/fuzz-bounds.json
    PYTHONPATH=src python tools/fuzz_bounds.py --base examples/modern-dohc-roller-finger.toml --only lash_adjuster \
        --paths run,tolerance,api
"""

import argparse
from collections import Counter
import json
import math
from pathlib import Path
import sys
import types
import typing

import numpy as np
from pydantic import BaseModel

from valvetrain.specification.cams import REGISTRY
from valvetrain.specification.fields import Range
from valvetrain.specification.models import Spec

sys.path.insert(0, str(Path(__file__).resolve().parent))
import fuzz_specs as fuzz  # noqa: E402 (the tools folder, put on the path above)

BASES = ("examples/modern-dohc-roller-finger.toml", "examples/pushrod-dynamics.toml",
         "examples/marine-hydraulic-exhaust.toml")
"""The finger follower with lash adjuster and lubrication, the pushrod train with dynamics and [camshaft], the
hydraulic drive."""

HUGE = 1e300


def _unwrap(tp):
    """The types inside ``tp`` (Optional, Annotated, list, dict) and the metadata met on the way."""
    meta = []
    while True:
        origin = typing.get_origin(tp)
        if origin is typing.Annotated:
            tp, *more = typing.get_args(tp)
            meta += more
            continue
        if origin in (typing.Union, types.UnionType):
            args = [a for a in typing.get_args(tp) if a is not type(None)]
            if len(args) == 1:
                tp = args[0]
                continue
        return tp, meta


def _bounds(meta, field_info=None):
    """``(low, high, low_open, high_open)`` of a field's metadata (its :class:`Range`), or None."""
    for m in meta + list(getattr(field_info, "metadata", []) or []):
        if isinstance(m, Range):
            return m.low, m.high, m.low_open, m.high_open
    return None


def _model_of(tp, node):
    """The model class a table ``node`` of type ``tp`` validates against (the cam by its law), or None."""
    tp, _ = _unwrap(tp)
    if typing.get_origin(tp) is typing.Union:
        law = node.get("law") if isinstance(node, dict) else None
        return REGISTRY.get(law)
    return tp if isinstance(tp, type) and issubclass(tp, BaseModel) else None


def numeric_fields(doc):
    """``[(path, (low, high, low_open, high_open) or None, kind)]`` of every numeric field of every section of
    ``doc`` the models know, present or not (kind "float" or "int"; list fields give their first item's path)."""
    out = []

    def walk(model, node, prefix):
        for name, info in model.model_fields.items():
            tp, meta = _unwrap(info.annotation)
            value = node.get(name) if isinstance(node, dict) else None
            origin = typing.get_origin(tp)
            if origin is dict and isinstance(value, dict):
                item = typing.get_args(tp)[1]
                for key, sub in value.items():
                    sub_model = _model_of(item, sub)
                    if sub_model is not None and isinstance(sub, dict):
                        walk(sub_model, sub, prefix + (name, key))
                continue
            if origin is list:
                item, item_meta = _unwrap(typing.get_args(tp)[0])
                if isinstance(value, list) and value:
                    sub_model = _model_of(item, value[0])
                    if sub_model is not None:
                        for i, sub in enumerate(value):
                            walk(sub_model, sub, prefix + (name, i))
                    elif item in (float, int):
                        out.append((prefix + (name, 0), _bounds(item_meta),
                                    "int" if item is int else "float"))
                continue
            sub_model = _model_of(tp, value)
            if sub_model is not None:
                if isinstance(value, dict):
                    walk(sub_model, value, prefix + (name,))
                continue
            if tp in (float, int):
                out.append((prefix + (name,), _bounds(meta, info), "int" if tp is int else "float"))

    walk(Spec, doc, ())
    return out


def _step(x):
    return max(abs(x) * 1e-3, 1e-6)


def edge_values(bounds, kind, value):
    """The values a numeric key is tried with: its bounds (inside and just outside), 0, NaN, inf, huge, and half
    and twice its value."""
    vals = [0, -1, math.nan, math.inf, -math.inf, HUGE] if kind == "float" else [0, -1, 2 ** 63]
    if bounds is not None:
        low, high, low_open, high_open = bounds
        if low is not None:
            inside = low + _step(low) if low_open else low
            vals += [inside, low - _step(low)] + ([low] if low_open else [])
        if high is not None:
            inside = high - _step(high) if high_open else high
            vals += [inside, high + _step(high)] + ([high] if high_open else [])
    if isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value):
        vals += [value * 0.5, value * 2.0]
    if kind == "int":
        vals = sorted({int(v) for v in vals if math.isfinite(v) and abs(v) < 2 ** 64})
    seen, out = set(), []
    for v in vals:
        key = repr(v)
        if key not in seen:
            seen.add(key)
            out.append(v)
    return out


def bound_cases(base, doc, only=None):
    """Cases ``{"base", "ops"}`` of one base: every numeric field at its edge values, every section deleted."""
    cases = []
    for path, bounds, kind in numeric_fields(doc):
        if only and only not in path:
            continue
        for v in edge_values(bounds, kind, fuzz._get(doc, path)):
            cases.append({"base": base, "ops": [["set", list(path), v]]})
    for path in fuzz.tables(doc):
        if path and (not only or only in path):
            cases.append({"base": base, "ops": [["delete", list(path)]]})
    return cases


def tolerance_cases(base, doc, only=None):
    """``valvetrain tolerance`` with one [[tolerances]] entry per numeric key: a uniform range reaching from just
    inside to beyond the key's upper bound (refused before sampling), and a narrow normal one (sampled)."""
    cases = []
    for path, bounds, kind in numeric_fields(doc):
        value = fuzz._get(doc, path)
        if kind != "float" or not isinstance(value, (int, float)) or isinstance(value, bool) or \
                (only and only not in path) or any(isinstance(p, int) for p in path):
            continue
        key = ".".join(str(p) for p in path)
        entries = [{"key": key, "distribution": "normal", "sigma": max(abs(value) * 0.02, 1e-6)}]
        if bounds is not None and bounds[1] is not None:
            entries.append({"key": key, "distribution": "uniform", "low": float(value),
                            "high": float(bounds[1]) + _step(bounds[1])})
        for entry in entries:
            cases.append({"base": base, "ops": [["set", ["tolerances"], [entry]]],
                          "command": ["tolerance", "--samples", "4"]})
    return cases


PYTHON_VALUES = [None, (1.0, 2.0), np.float64("nan"), np.int64(7), np.float32(1.5), b"1", {1: 2}, float("inf")]
"""Values a dictionary can hand ``valvetrain.api`` that no TOML file holds."""


def api_cases(base, doc, only=None):
    """``api.design`` and ``api.sweep`` on the dictionary: every numeric key at its bounds and at the Python values
    of :data:`PYTHON_VALUES`, every section removed."""
    cases = [{**c, "api": True} for c in bound_cases(base, doc, only)]
    for path, _, _ in numeric_fields(doc):
        if not only or only in path:
            cases += [{"base": base, "ops": [["set", list(path), v]], "api": True} for v in PYTHON_VALUES]
    return cases


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--base", action="append", help=f"base specification (default: {', '.join(BASES)})")
    ap.add_argument("--only", help="only keys whose path holds this part (e.g. lash_adjuster, finger_pad_arm_mm)")
    ap.add_argument("--paths", default="run", help="comma-separated: run (load_spec -> design.run), tolerance "
                    "(valvetrain tolerance per key), api (valvetrain.api.design and api.sweep with the dictionary, "
                    "and Python values TOML cannot hold); default run")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=60.0)
    ap.add_argument("--report", help="write the JSON report here")
    args = ap.parse_args(argv)

    bases = fuzz.base_specs()
    cases = []
    for base in args.base or BASES:
        doc = bases[base][0]
        for what in args.paths.split(","):
            cases += {"run": bound_cases, "tolerance": tolerance_cases, "api": api_cases}[what](base, doc, args.only)
    print(f"running {len(cases)} cases on {args.workers} workers", file=sys.stderr)
    step = max(len(cases) // 20, 1)

    def progress(done, total, rec):
        if done % step == 0 or done == total:
            print(f"  {done}/{total}", file=sys.stderr, flush=True)
        if rec["outcome"] in fuzz.FAILURES:
            print(f"  [{rec['outcome']}] {rec['base']}: {'; '.join(rec['mutation'])} -> {rec.get('signature')}",
                  file=sys.stderr, flush=True)

    records = fuzz.run_cases(cases, args.workers, args.timeout, progress=progress)
    counts = Counter((r["base"], "api" if r.get("api") else r.get("command", ["run"])[0], r["outcome"]) for r in records)
    for (base, command, outcome), n in sorted(counts.items()):
        print(f"{base:<45} {command:<10} {outcome:<12} {n:>5}")
    groups = {}
    for r in records:
        if r["outcome"] in fuzz.FAILURES:
            for sig in r["signatures"]:
                groups.setdefault(sig, []).append(r)
    for sig, recs in sorted(groups.items(), key=lambda kv: -len(kv[1])):
        rep = min(recs, key=lambda r: len(json.dumps(r["mutation"])))
        print(f"\n[{rep['outcome']}] x{len(recs)} {sig}\n    base: {rep['base']}")
        for d in rep["mutation"] + rep.get("detail", [])[:3]:
            print(f"    {d}")
    if args.report:
        Path(args.report).write_text(json.dumps(records, indent=1, default=str), encoding="utf-8")
    return 1 if groups else 0


if __name__ == "__main__":
    sys.exit(main())
