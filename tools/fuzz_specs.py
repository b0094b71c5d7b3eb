#!/usr/bin/env python
"""Fuzz the specification path of valvetrain (issue 9, "Trustworthy under any input").

Every case is a base specification (the built-in example, ``examples/*.toml``, one specification per lift law
with a flat and a roller follower, asymmetric cams, a two-stroke with a crank) and a list of mutation
operations: numbers scaled by 0, -1, 1e-300 ... 1e300, set to NaN/inf, keys deleted, types changed, unknown keys
added, laws and followers swapped, deep or long arrays, byte-level damage of the file (BOM, truncation, bad
encodings), and malformed CSV files for measured lift tables and indicator diagrams.  Each case runs through
the command line's path, ``load_spec -> design.run`` (and ``export.write_outputs`` with ``--write``), with
numpy RuntimeWarnings turned into errors, and is classified:

``ok``           accepted, finite and plausible results;
``refused``      SpecError (exit status 2) whose messages each name a key;
``infeasible``   ``optimize`` found no point meeting every limit: exit status 1 with the documented message and
                 each failing limit named (a result, not an error);
``traceback``    any other exception (exit status 1 of the command line);
``hang``         no result within ``--timeout`` seconds;
``nan_output``   accepted, but NaN/inf in a table column or in results.json (null where it is not documented);
``nonsense``     accepted and finite, but a plausibility check fails (event >= 360 cam deg, valve lift not the
                 declared one within 1 %, fullness outside (0, 1]);
``bad_message``  refused with a message that names no key, carries library internals, or is over 300 characters.

Besides ``run``, one case in four runs a command (study, optimize, sweep, compare, tolerance: its [[tolerances]]
drawn, normal ones truncated far in their tails, and its records.jsonl damaged and the command run again, which must
redesign what was damaged and give the first run's results), one in ten the designer's session (edits of keys, drags
of handles, points of a table, the report and the TOML download, the whole design) and one in forty ``valvetrain
serve`` in a process of its own (on a free port, a taken one, a host that does not resolve; requests to its pages
and files, then Ctrl-C).  The mutations reach the finger follower (its geometry put on a valve in variants the
campaign of issue 36 met, measured tables among the bases, its keys mutated), the lash adjuster (added to a valve, its
keys mutated) and the camshaft ([camshaft] added, its keys mutated).

Usage (from the repository root, with the package on the path)::

    PYTHONPATH=src python tools/fuzz_specs.py --count 3000 --seed 1 --workers 2 --report fuzz-report.json

The mutation generator draws through a ``pick(sequence)`` chooser, so tests/test_fuzz.py drives the same
generator from hypothesis.
"""

import os
import zlib

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")  # one BLAS thread per worker: --workers processes share the cores

import argparse  # noqa: E402
from collections import Counter, deque  # noqa: E402
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait  # noqa: E402
from concurrent.futures.process import BrokenProcessPool  # noqa: E402
import copy  # noqa: E402
import csv  # noqa: E402
import datetime  # noqa: E402
import faulthandler  # noqa: E402
import functools  # noqa: E402
import json  # noqa: E402
import math  # noqa: E402
from pathlib import Path  # noqa: E402
import random  # noqa: E402
import re  # noqa: E402
import signal  # noqa: E402
import sys  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402
import tomllib  # noqa: E402
import traceback  # noqa: E402
import warnings  # noqa: E402

import numpy as np  # noqa: E402

import valvetrain  # noqa: E402
from valvetrain import export  # noqa: E402
from valvetrain import tables as columns  # noqa: E402
from valvetrain.design import run as run_design  # noqa: E402
from valvetrain.specification import LAWS, SpecError, example_text, load_spec  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "examples"
MEASURED_LOBE = "data/measured-intake-lobe.csv"

OUTCOMES = ("ok", "refused", "infeasible", "traceback", "hang", "nan_output", "nonsense", "bad_message")
FAILURES = ("traceback", "hang", "nan_output", "nonsense", "bad_message")
INFEASIBLE = re.compile(r"(?s)(.*\n)?error: no point of the search meets every limit .*\n"
                        r"  at the (point nearest to them|start): ")
"""What ``optimize`` prints when no point meets every limit: the message, then each failing limit at the point
nearest to them and at the start."""

# ---------------------------------------------------------------------------------------------------------------
# TOML text of a nested dictionary (tomllib reads, the standard library writes none)

_BARE = re.compile(r"^[A-Za-z0-9_-]+$")


def _key(k):
    return k if _BARE.match(k) else _string(k)


def _string(s):
    out = []
    for ch in s:
        if ch == '"':
            out.append('\\"')
        elif ch == "\\":
            out.append("\\\\")
        elif ch == "\n":
            out.append("\\n")
        elif ch == "\t":
            out.append("\\t")
        elif ord(ch) < 0x20 or ord(ch) == 0x7F:
            out.append(f"\\u{ord(ch):04X}")
        else:
            out.append(ch)
    return '"' + "".join(out) + '"'


def _value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, _Raw):
        return str(v)
    if isinstance(v, str):
        return _string(v)
    if isinstance(v, (datetime.date, datetime.datetime, datetime.time)):
        return v.isoformat()
    if isinstance(v, dict):
        return "{" + ", ".join(f"{_key(k)} = {_value(x)}" for k, x in v.items()) + "}"
    if isinstance(v, list):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    raise TypeError(f"cannot write {type(v).__name__} as TOML")


def toml_dumps(doc):
    """TOML text of a dictionary: scalars and arrays as ``key = value``, dictionaries as ``[tables]``."""
    lines = []

    def table(d, prefix):
        subs = [(k, v) for k, v in d.items() if isinstance(v, dict)]
        for k, v in d.items():
            if not isinstance(v, dict):
                lines.append(f"{_key(k)} = {_value(v)}")
        for k, v in subs:
            path = prefix + [k]
            lines.append("")
            lines.append("[" + ".".join(_key(p) for p in path) + "]")
            table(v, path)

    table(doc, [])
    return "\n".join(lines).lstrip("\n") + "\n"


# ---------------------------------------------------------------------------------------------------------------
# Base specifications

LAW_CAMS = {
    # valid cam sections of every law: those of tests/design/test_laws_in_design.py (CAMS), tests/laws/test_asymmetric.py and
    # examples/seed000-polydyne.toml; base_radius_mm and follower come from the example's cam
    "kurz": {"law": "kurz", "ramp_end_velocity_mm_per_deg": 0.02, "phi1_deg": 27.0, "phi2_deg": 6.0,
             "phi3_deg": 38.0, "shape_factor": 0.625},
    "polydyne": {"law": "polydyne", "p": 8},
    "polynomial": {"law": "polynomial", "exponents": [2, 6, 10, 14, 18, 22], "ramp": True,
                   "ramp_end_velocity_mm_per_deg": 0.015, "ramp_type": "constant_acceleration"},
    "constant_acceleration": {"law": "constant_acceleration", "ramp_end_velocity_mm_per_deg": 0.02,
                              "phi1_deg": 22.0, "phi2_deg": 30.0, "kappa": 0.6},
    "combined": {"law": "combined", "ramp_end_velocity_mm_per_deg": 0.02,
                 "segments": [{"shape": "half_sine", "length_deg": 25.0}, {"shape": "quarter_sine", "length_deg": 8.0},
                              {"shape": "parabola_to_nose", "length_deg": 38.0}],
                 "ratios": [{"segment": 2, "value": 0.625}]},
    "dynamic": {"law": "dynamic", "valve_opening_velocity_m_s": 0.3, "drive_stiffness_N_per_mm": 15000.0,
                "spring_rate_N_per_mm": 70.0, "spring_preload_N": 250.0, "ramp_type": "constant_acceleration"},
    "harmonic": {"law": "harmonic", "harmonics": 24, "junction_order": 2,
                 "target": {"law": "polydyne", "p": 8, "ramp": True, "ramp_end_velocity_mm_per_deg": 0.02}},
    "three_arc": {"law": "three_arc", "flank_angle_deg": 25.0},
    "tangent": {"law": "tangent"},
    "power_polynomial": {"law": "power_polynomial", "ramp_angle_deg": 20.0, "ramp_end_velocity_mm_per_rad": 1.1,
                         "peak_acceleration_mm_per_rad2": 40.0, "phi1_deg": 20.0},
    "table": {"law": "table", "table_file": "lobe.csv", "table_angle": "crank", "table_lift_at": "valve",
              "fit": "spline", "accuracy_mm": 0.005},
}

ASYMMETRIC_CAMS = {
    # Kurz: tests/laws/test_asymmetric.py, opening 21/5/30 cam deg, closing 30/7/49 (the flanks add up to 2 phi_p0 = 142);
    # the others: flanks of the same sum whose profile is not undercut
    "kurz": {**LAW_CAMS["kurz"], "phi1_deg": 21.0, "phi2_deg": 5.0, "phi3_deg": 30.0,
             "closing": {"phi1_deg": 30.0, "phi2_deg": 7.0, "phi3_deg": 49.0, "ramp_end_velocity_mm_per_deg": 0.015}},
    "constant_acceleration": {**LAW_CAMS["constant_acceleration"], "phi1_deg": 22.0, "phi2_deg": 30.0,
                              "phi3_deg": 4.0, "closing": {"phi1_deg": 30.0, "phi2_deg": 40.0, "phi3_deg": 16.0}},
    "combined": {**LAW_CAMS["combined"],
                 "closing": {"segments": [{"shape": "half_sine", "length_deg": 30.0},
                                          {"shape": "quarter_sine", "length_deg": 10.0},
                                          {"shape": "parabola_to_nose", "length_deg": 31.0}]}},
}

ROLLER = {"follower": "roller", "roller_radius_mm": 11.0}

TWO_STROKE_CRANK = {
    # an illustrative crank for examples/two-stroke-ports.toml (masses of a 56 mm bore, a small Wiebe cycle)
    "piston_kg": 0.15, "rod_kg": 0.12, "crank_kg": 0.1, "compression_ratio": 8.0, "step_deg": 1.0,
    "cycle": {"heat_input_J": 250.0},
}


def _with_cam(doc, cam, drop=()):
    doc = copy.deepcopy(doc)
    valve = doc["valves"]["intake"]
    old = valve["cam"]
    valve["cam"] = {**copy.deepcopy(cam), "base_radius_mm": old["base_radius_mm"], "follower": "flat"}
    for k in drop:
        valve.pop(k, None)
    return doc


def base_specs():
    """``{name: (document, {relative file name: bytes})}`` of every base specification, in a fixed order."""
    example = tomllib.loads(example_text())
    lobe = (EXAMPLES / MEASURED_LOBE).read_bytes()
    bases = {"example": (example, {})}
    for f in sorted(EXAMPLES.glob("*.toml")):
        text = f.read_text(encoding="utf-8")
        files = {MEASURED_LOBE: lobe} if "measured" in f.name else {}
        files.update({name: (EXAMPLES / name).read_bytes() for name in
                      (d.relative_to(EXAMPLES).as_posix() for d in sorted((EXAMPLES / "data").glob("*.csv")))
                      if f'"{name}"' in text})     # the data files the example names (the breathing's lift and C_D)
        bases[f"examples/{f.name}"] = (tomllib.loads(text), files)
    for law in LAWS:
        files = {"lobe.csv": lobe} if law == "table" else {}
        drop = ("max_lift_mm", "opens_deg", "closes_deg") if law == "table" else ()
        doc = _with_cam(example, LAW_CAMS[law], drop)
        if law != "tangent":
            bases[f"law:{law}"] = (doc, files)
        roller = copy.deepcopy(doc)
        roller["valves"]["intake"]["cam"].update(ROLLER)
        if law == "harmonic":
            roller["valves"]["intake"]["cam"]["target"].update(ROLLER)
        bases[f"law:{law}+roller"] = (roller, files)
    for law, cam in ASYMMETRIC_CAMS.items():
        bases[f"asymmetric:{law}"] = (_with_cam(example, cam), {})
    two = tomllib.loads((EXAMPLES / "two-stroke-ports.toml").read_text(encoding="utf-8"))
    two["crank"] = copy.deepcopy(TWO_STROKE_CRANK)
    bases["two-stroke+crank"] = (two, {})
    return bases


# ---------------------------------------------------------------------------------------------------------------
# Malformed CSV files

def _lobe(x, centre, half_width, height):
    """A lobe: height (1 + cos(pi u)) / 2, u = (x - centre) / half_width, zero outside (the 10 mm, 280 crank deg
    lobe has a profile radius of 5 mm at the nose on a 20 mm base circle with rocker ratio 1.6: no undercut)."""
    u = np.clip((np.asarray(x, dtype=float) - centre) / half_width, -1.0, 1.0)
    return height * (1.0 + np.cos(np.pi * u)) / 2.0


def _rows(header, x, y, fmt="{:.6f},{:.6f}"):
    return (header + "\n" + "".join(fmt.format(a, b) + "\n" for a, b in zip(x, y, strict=True))).encode()


LIFT_HEADER = "angle_deg,lift_mm"
_CRANK = np.arange(-40.0, 262.0, 2.0)          # crank deg of a 10 mm intake lobe: nose at 110, event 280 deg
_LOBE = _lobe(_CRANK, 110.0, 140.0, 10.0)


def _lift(x, y):
    return _rows(LIFT_HEADER, x, y)


LIFT_FILES = {
    # name: (angle unit the table is meant in, bytes)
    "valid_lobe": ("crank", _lift(_CRANK, _LOBE)),
    "empty": ("crank", b""),
    "header_only": ("crank", (LIFT_HEADER + "\n").encode()),
    "comments_only": ("crank", b"# a comment\n# another\n"),
    "bad_header": ("crank", _rows("angle,lift", _CRANK, _LOBE)),
    "semicolons": ("crank", _rows("angle_deg;lift_mm", _CRANK, _LOBE, "{:.6f};{:.6f}")),
    "three_columns": ("crank", _rows(LIFT_HEADER, _CRANK, _LOBE, "{:.6f},{:.6f},1")),
    "non_numbers": ("crank", _lift(_CRANK, _LOBE).replace(b"110.000000,10.000000", b"abc,def")),
    "nan_lift": ("crank", _lift(_CRANK, _LOBE).replace(b"110.000000,10.000000", b"110.0,nan")),
    "inf_lift": ("crank", _lift(_CRANK, _LOBE).replace(b"110.000000,10.000000", b"110.0,inf")),
    "nan_angle": ("crank", _lift(_CRANK, _LOBE).replace(b"110.000000,10.000000", b"nan,10.0")),
    "decreasing_angles": ("crank", _lift(_CRANK[::-1], _LOBE[::-1])),
    "duplicate_angle": ("crank", _lift(np.r_[_CRANK[:80], _CRANK[79:]], np.r_[_LOBE[:80], _LOBE[79:]])),
    "nine_rows": ("crank", _lift(np.linspace(-30, 250, 9), _lobe(np.linspace(-30, 250, 9), 110, 140, 10))),
    "ten_rows": ("crank", _lift(np.linspace(-30, 250, 10), _lobe(np.linspace(-30, 250, 10), 110, 140, 10))),
    "all_zero": ("crank", _lift(_CRANK, 0.0 * _LOBE)),
    "negative_lobe": ("crank", _lift(_CRANK, -_LOBE)),
    "negative_base": ("crank", _lift(_CRANK, _LOBE - 0.05)),
    "constant_lift": ("crank", _lift(_CRANK, 0.0 * _LOBE + 5.0)),
    "scaled_1e-300": ("crank", _rows(LIFT_HEADER, _CRANK, 1e-300 * _LOBE, "{:.6f},{:.6g}")),
    "scaled_1e-9": ("crank", _rows(LIFT_HEADER, _CRANK, 1e-9 * _LOBE, "{:.6f},{:.6g}")),
    "scaled_1e300": ("crank", _rows(LIFT_HEADER, _CRANK, 1e300 * _LOBE, "{:.6f},{:.6g}")),
    "firing_tdc_angles": ("crank", _lift(np.arange(337.0, 624.0, 2.0), _lobe(np.arange(337.0, 624.0, 2.0),
                                                                             480.0, 143.0, 10.0))),
    "cam_370_deg": ("cam", _lift(np.arange(-185.0, 186.0, 1.0),
                                 _lobe(np.arange(-185.0, 186.0, 1.0), 0.0, 185.0, 10.0))),
    "crank_740_deg": ("crank", _lift(np.arange(-260.0, 481.0, 2.0), _lobe(np.arange(-260.0, 481.0, 2.0), 110.0, 370.0,
                                                                          10.0))),
    "two_lobes": ("crank", _lift(np.arange(-100.0, 520.0, 2.0), _lobe(np.arange(-100.0, 520.0, 2.0), 30.0, 120.0, 10.0)
                                 + _lobe(np.arange(-100.0, 520.0, 2.0), 390.0, 120.0, 9.0))),
    "dense_15000": ("crank", _lift(np.linspace(-40.0, 260.0, 15000), _lobe(np.linspace(-40.0, 260.0, 15000), 110.0,
                                                                           140.0, 10.0))),
    "dense_100000": ("crank", _rows(LIFT_HEADER, np.linspace(-40.0, 260.0, 100000),
                                    _lobe(np.linspace(-40.0, 260.0, 100000), 110.0, 140.0, 10.0), "{:.7f},{:.7f}")),
    "single_spike": ("crank", _lift(_CRANK, np.where(_CRANK == 110.0, 10.0, 0.0))),
    "top_hat": ("crank", _lift(_CRANK, np.where(np.abs(_CRANK - 110.0) < 60.0, 10.0, 0.0))),
    "rising_only": ("crank", _lift(_CRANK, np.linspace(0.0, 10.0, _CRANK.size))),
    "max_at_first_row": ("crank", _lift(_CRANK, np.linspace(10.0, 0.0, _CRANK.size))),
    "short_event_10_deg": ("crank", _lift(np.linspace(100.0, 120.0, 41), _lobe(np.linspace(100.0, 120.0, 41), 110.0,
                                                                               5.0, 10.0))),
    "tiny_angle_span": ("crank", _lift(np.linspace(0.0, 1e-6, 50),
                                       _lobe(np.linspace(0.0, 1e-6, 50), 5e-7, 5e-7, 10.0))),
    "huge_angles": ("crank", _lift(_CRANK + 1e6, _LOBE)),
    "noise_everywhere": ("crank", _lift(_CRANK, _LOBE + 0.05 * np.sin(7.3 * _CRANK))),
    "utf16": ("crank", _lift(_CRANK, _LOBE).decode().encode("utf-16")),
    "bom": ("crank", b"\xef\xbb\xbf" + _lift(_CRANK, _LOBE)),
    "latin1_comment": ("crank", b"# Ventilhub \xe9\n" + _lift(_CRANK, _LOBE)),
    "blank_cells": ("crank", _lift(_CRANK, _LOBE).replace(b"110.000000,10.000000", b"110.0,")),
}
"""Lift tables (``angle_deg,lift_mm``) for ``law = "table"``."""

SLOW_FILES = {"dense_15000", "dense_100000", "pv_dense"}
"""Files that take seconds each: run once each by :func:`file_cases`, not drawn into random mutations."""

PRESSURE_ANGLE = "crank_deg,pressure_MPa"
PRESSURE_VOLUME = "volume_cm3,pressure_MPa"


def _geometry(doc):
    """bore, stroke, rod [mm], compression ratio and strokes of a (possibly mutated) document, with the example's
    values where a key is missing or not a number."""
    def num(*paths, default):
        for path in paths:
            v = _get(doc, path)
            if isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) and v > 0:
                return float(v)
        return default

    strokes = _get(doc, ("engine", "strokes"))
    return (num(("crank", "bore_mm"), ("engine", "bore_mm"), default=80.0),
            num(("crank", "stroke_mm"), ("engine", "stroke_mm"), default=77.142857),
            num(("crank", "rod_length_mm"), ("engine", "rod_length_mm"), default=135.0),
            num(("crank", "compression_ratio"), default=10.0),
            strokes if strokes in (2, 4) else 4)


def _cycle(phi, strokes):
    """An indicator diagram [MPa] over the cycle angle [deg]: intake, compression, a combustion peak at the firing
    TDC, expansion, exhaust (four-stroke: firing TDC 360; two-stroke: 0 = 360)."""
    fire = 360.0 if strokes == 4 else 0.0
    d = np.minimum(np.abs(phi - fire), np.abs(phi - fire - 360.0 * (strokes == 2)))
    return 0.1 + 1.5 * np.exp(-(d / 60.0) ** 2) + 5.0 * np.exp(-((phi - fire - 15.0) / 25.0) ** 2)


def _volume(phi, geom):
    bore, stroke, rod, cr, _ = geom
    r, lam = stroke / 2.0, stroke / 2.0 / rod
    a = np.radians(phi)
    with np.errstate(invalid="ignore"):       # a mutated rod shorter than the crank: a NaN volume, a malformed file
        s = r * (1.0 - np.cos(a) + (1.0 - np.sqrt(1.0 - (lam * np.sin(a)) ** 2)) / lam)
    area = np.pi * bore ** 2 / 4.0
    return (area * stroke / (cr - 1.0) + area * s) / 1000.0        # cm3


def _pv(geom, end_deg, scale=1.0, step=2.0):
    phi = np.arange(0.0, end_deg + step / 2, step)
    return _rows(PRESSURE_VOLUME, scale * _volume(phi, geom), _cycle(np.mod(phi, 180.0 * geom[4]), geom[4]),
                 "{:.9g},{:.6f}")


def _pa(geom, end=None, step=2.0, p=None):
    cycle = 180.0 * geom[4]
    phi = np.arange(0.0, (cycle if end is None else end) + step / 2, step)
    return _rows(PRESSURE_ANGLE, phi, _cycle(phi, geom[4]) if p is None else p(phi), "{:.6f},{:.6g}")


PRESSURE_FILES = {
    # name: function of the geometry (bore, stroke, rod, compression ratio, strokes) -> bytes
    "valid_p_phi": lambda g: _pa(g),
    "valid_p_v": lambda g: _pv(g, 180.0 * g[4]),
    "empty": lambda g: b"",
    "header_only": lambda g: (PRESSURE_ANGLE + "\n").encode(),
    "bad_header": lambda g: _pa(g).replace(PRESSURE_ANGLE.encode(), b"angle,p"),
    "non_numbers": lambda g: _pa(g).replace(b"\n20.000000,", b"\nxx,"),
    "nan_pressure": lambda g: _pa(g, p=lambda phi: np.where(phi == 20.0, np.nan, _cycle(phi, g[4]))),
    "inf_pressure": lambda g: _pa(g, p=lambda phi: np.where(phi == 20.0, np.inf, _cycle(phi, g[4]))),
    "decreasing_angles": lambda g: b"\n".join([PRESSURE_ANGLE.encode()] + _pa(g).splitlines()[1:][::-1]) + b"\n",
    "three_rows": lambda g: _pa(g, end=4.0),
    "angle_beyond_cycle": lambda g: _pa(g, end=180.0 * g[4] + 80.0),
    "negative_pressure": lambda g: _pa(g, p=lambda phi: _cycle(phi, g[4]) - 1.0),
    "zero_pressure": lambda g: _pa(g, p=lambda phi: 0.0 * phi),
    "constant_pressure": lambda g: _pa(g, p=lambda phi: 0.0 * phi + 0.1),
    "pressure_1e300": lambda g: _pa(g, p=lambda phi: 1e300 * _cycle(phi, g[4])),
    "pressure_1e-300": lambda g: _pa(g, p=lambda phi: 1e-300 * _cycle(phi, g[4])),
    "only_0_to_360": lambda g: _pa(g, end=360.0),
    "only_0_to_90": lambda g: _pa(g, end=90.0),
    "coarse_60_deg": lambda g: _pa(g, step=60.0),
    "dense_100000": lambda g: _pa(g, step=180.0 * g[4] / 100000),
    "pv_one_branch": lambda g: _pv(g, 180.0),
    "pv_two_branches": lambda g: _pv(g, 360.0),
    "pv_three_branches": lambda g: _pv(g, 540.0),
    "pv_five_branches": lambda g: _pv(g, 900.0),
    "pv_eight_branches": lambda g: _pv(g, 1440.0),
    "pv_constant_volume": lambda g: _rows(PRESSURE_VOLUME, np.full(200, 300.0),
                                          _cycle(np.linspace(0.0, 720.0, 200), g[4])),
    "pv_volume_x1000": lambda g: _pv(g, 180.0 * g[4], scale=1000.0),
    "pv_volume_x0.01": lambda g: _pv(g, 180.0 * g[4], scale=0.01),
    "pv_volume_1e-300": lambda g: _pv(g, 180.0 * g[4], scale=1e-300),
    "pv_four_rows": lambda g: _pv(g, 180.0 * g[4], step=180.0 * g[4] / 3),
    "pv_dense": lambda g: _pv(g, 180.0 * g[4], step=0.01),
    "pv_jitter": lambda g: _rows(PRESSURE_VOLUME, _volume(np.arange(0.0, 720.5, 2.0), g)
                                 * (1.0 + 1e-3 * np.sin(np.arange(361.0) * 2.1)),
                                 _cycle(np.arange(0.0, 720.5, 2.0), g[4]), "{:.9g},{:.6f}"),
}
"""Indicator diagrams for ``[crank] pressure_file``."""

# ---------------------------------------------------------------------------------------------------------------
# Mutations: operations on the parsed document (and on the bytes of the file), replayable in any subset

FACTORS = [0, -1, 1e-300, 1e-9, 0.01, 0.5, 2, 100, 1e300]
GENTLE = [0.8, 1.25, 0.95, 1.05, 1.5, 3, 10, 0.1, -0.5]
SPECIALS = [math.nan, math.inf, -math.inf, -0.0, 5e-324, 1.7976931348623157e308, 2 ** 63, -(2 ** 63), 0, 1]
OTHER_TYPES = ["", "10", "abc", True, [], [1.0], [[1.0]], {}, {"x": 1}, datetime.date(1979, 5, 27),
               "\u00fc\u4e2d\u0416", "x" * 5000, [1.0, "a"], [{"law": "kurz"}]]
LITERALS = {
    "kind": ["intake", "exhaust", "transfer", "inlet"], "follower": ["flat", "roller"], "law": list(LAWS),
    "layout": ["inline", "v", "direct", "rocker", "pushrod"], "type": ["si", "si_injected", "diesel"],
    "chamber": ["side_valve", "overhead", "prechamber_diesel", "direct_injection_diesel", "wedge", "hemispherical"],
    "ramp_type": ["cosine", "constant_velocity", "constant_acceleration"], "fit": ["spline", "harmonic"],
    "table_angle": ["crank", "cam"], "table_lift_at": ["valve", "tappet"], "kinematics": ["exact", "approximate"],
    "pv_method": ["exact", "brix"], "shape": ["half_sine", "quarter_sine", "quarter_cosine", "constant", "linear",
                                             "parabola_to_nose"],
    "strokes": [2, 4], "count": [1, 2, 8], "cylinders": [1, 2, 3, 64], "ramp": [True, False],
    "harmonics": [2, 3, 4, 400], "junction_order": [0, 1, 5, 10], "max_harmonics": [4, 400],
    "contour_points": [36, 100000], "segment": [1, 2, 3, 50], "model": ["1dof", "multi"],
    "location": ["pivot", "tappet", "bucket"], "drive": ["chain", "belt", "gears", "rocker"],
}
UNKNOWN_KEYS = ["bore", "Bore_mm", "max_lift", "phi4_deg", "\u00fcber", "x y", ""]
WEIRD_NAMES = ["crank", "two_stroke", "1st", "ex haust", "\u00e9chappement", "a" * 300, "x.y", ""]
NEST_DEPTHS = [2, 20, 100, 400, 2000]
LONG_LISTS = [0, 1, 65, 1000, 100000]
TEXT_OPS = ["bom", "crlf", "truncate_half", "truncate_end", "nul_byte", "latin1_byte", "empty", "utf16",
            "duplicate_key", "bom_twice"]

OP_KINDS = (["scale"] * 4 + ["gentle"] * 4 + ["special"] * 2 + ["type"] * 2 + ["delete"] * 2 + ["literal"] * 2
            + ["law"] * 2 + ["stage_key"] * 3 + ["stage"] * 2 + ["finger"] * 2 + ["finger_key"] * 2
            + ["camshaft_key"] * 2
            + ["unknown", "follower", "nest", "long_list", "text", "valve", "section", "lift_file", "pressure_file"])

STAGES = ("dynamics", "hydraulic", "lash_adjuster")
"""The sections of a valve whose keys :func:`draw_op` mutates on purpose (``stage_key``) and that it adds to a valve
(``stage``): the elastic train's speed sweep, the hydraulic drive and the hydraulic lash adjuster."""

FINGER_EXAMPLE = EXAMPLES / "modern-dohc-roller-finger.toml"
"""The shipped finger follower whose geometry the ``finger`` operation puts on a valve."""

FINGER_VARIANTS = {
    # name -> keys of the cam changed from the example's finger (mm, deg): what the fuzz campaign of issue 36 met
    "example": {},
    "pivot_out_of_reach": {"finger_pivot_y_mm": 80.0},
    "pad_at_the_pivot": {"finger_pad_arm_mm": -0.36},
    "negative_pad": {"finger_pad_arm_mm": -36.0},
    "pad_inside": {"finger_pad_arm_mm": 12.0, "finger_pad_drop_mm": -4.0, "finger_valve_angle_deg": 4.0},
    "centre_pivot_rocker": {"roller_radius_mm": 12.0, "finger_pivot_x_mm": 3.0, "finger_pivot_y_mm": 36.0,
                            "finger_roller_arm_mm": 30.0, "finger_pad_arm_mm": -40.0, "finger_pad_drop_mm": 2.0,
                            "finger_pad_radius_mm": 10.0, "finger_valve_angle_deg": 180.0},
    "tip_off_axis": {"finger_tip_offset_mm": 50.0},
    "tip_near_edge": {"finger_tip_offset_mm": 2.9},
}
"""Finger geometries of the ``finger`` operation."""

SHAFT_EXAMPLE = EXAMPLES / "pushrod-dynamics.toml"
"""The shipped [camshaft] section the ``section`` operation ``add_camshaft`` puts into a document."""

STAGE_OPS = ["scale", "gentle", "special", "type", "delete", "literal"]


def _get(doc, path):
    for p in path:
        try:
            doc = doc[p]
        except (KeyError, IndexError, TypeError):
            return None
    return doc


def _parent(doc, path):
    """The container holding ``path[-1]``, or None when the path no longer exists."""
    node = _get(doc, path[:-1])
    if isinstance(node, dict) and path[-1] in node:
        return node
    if isinstance(node, list) and isinstance(path[-1], int) and 0 <= path[-1] < len(node):
        return node
    return None


def leaves(doc, prefix=()):
    """Paths of every value (scalars, lists and list items, but not tables) in document order."""
    out = []
    for k, v in doc.items():
        path = prefix + (k,)
        if isinstance(v, dict):
            out += leaves(v, path)
            continue
        out.append(path)
        if isinstance(v, list):
            for i, x in enumerate(v):
                if isinstance(x, dict):
                    out += leaves(x, path + (i,))
                else:
                    out.append(path + (i,))
    return out


def tables(doc, prefix=()):
    """Paths of every table (dictionary), the document itself first."""
    out = [prefix]
    for k, v in doc.items():
        if isinstance(v, dict):
            out += tables(v, prefix + (k,))
    return out


def dotted(path):
    return ".".join(str(p) if not isinstance(p, int) else f"[{p}]" for p in path).replace(".[", "[") or "(document)"


def _show(v):
    try:
        text = _value(_swap_nested(v))        # a nested array may sit anywhere in v (a list of tables copied)
    except TypeError:                         # a Python value of an api case (None, bytes, numpy numbers)
        text = repr(v)
    return text if len(text) <= 60 else text[:40] + f"... ({len(text)} chars)"


class _Nested:
    """A value written as ``depth`` nested arrays around 1.0 (written by :func:`toml_dumps` through ``_value``)."""

    def __init__(self, depth):
        self.depth = depth


def _numbers(doc):
    return [p for p in leaves(doc) if isinstance(_get(doc, p), (int, float)) and not isinstance(_get(doc, p), bool)]


def _cams(doc):
    valves = doc.get("valves")
    if not isinstance(valves, dict):
        return []
    return [n for n, v in valves.items() if isinstance(v, dict) and isinstance(v.get("cam"), dict)]


def draw_op(pick, doc):
    """One mutation operation for the document ``doc``, drawn with ``pick(sequence) -> item``."""
    kind = pick(OP_KINDS)
    if kind == "stage_key":
        paths = [p for p in leaves(doc) if len(p) > 3 and p[0] == "valves" and p[2] in STAGES]
        if paths:
            return _stage_key_op(pick, doc, pick(paths))
    if kind == "finger_key":
        paths = [p for p in leaves(doc) if len(p) == 4 and p[0] == "valves" and p[2] == "cam"
                 and (p[3].startswith("finger_") or p[3] == "roller_radius_mm")
                 and _get(doc, p[:3] + ("follower",)) == "finger"]
        if paths:
            return _stage_key_op(pick, doc, pick(paths))
    if kind == "camshaft_key":
        paths = [p for p in leaves(doc) if p[0] == "camshaft"]
        if paths:
            return _stage_key_op(pick, doc, pick(paths))
    if kind == "stage" and _cams(doc):
        return ["stage", pick(_cams(doc)), pick(list(STAGES))]
    if kind == "finger" and _cams(doc):
        return ["finger", pick(_cams(doc)), pick(list(FINGER_VARIANTS))]
    numbers = _numbers(doc)
    if kind in ("scale", "gentle", "special") and numbers:
        path = pick(numbers)
        if kind == "special":
            return ["set", path, pick(SPECIALS)]
        return ["scale", path, pick(FACTORS if kind == "scale" else GENTLE)]
    if kind == "literal":
        paths = [p for p in leaves(doc) if isinstance(p[-1], str) and p[-1] in LITERALS]
        if paths:
            path = pick(paths)
            return ["set", path, pick(LITERALS[path[-1]])]
    if kind == "delete":
        paths = leaves(doc) + [t for t in tables(doc) if t]
        return ["delete", pick(paths)]
    if kind == "unknown":
        return ["set", pick(tables(doc)) + (pick(UNKNOWN_KEYS),), pick([1.0, "x", True])]
    if kind in ("law", "follower", "lift_file") and _cams(doc):
        valve = pick(_cams(doc))
        if kind == "law":
            return ["law", valve, pick(list(LAWS))]
        if kind == "follower":
            return ["follower", valve, pick(["roller", "flat"]), pick([11.0, 1e-9, 0.5, 200.0])]
        name = pick([n for n in LIFT_FILES if n not in SLOW_FILES])
        return ["lift_file", valve, name, pick(["valve", "tappet"]), pick(["spline", "harmonic"])]
    if kind == "pressure_file" and isinstance(doc.get("crank"), dict):
        return ["pressure_file", pick([n for n in PRESSURE_FILES if n not in SLOW_FILES]), pick(["exact", "brix"])]
    if kind == "nest":
        return ["nest", pick(leaves(doc)), pick(NEST_DEPTHS)]
    if kind == "long_list":
        lists = [p for p in leaves(doc) if isinstance(_get(doc, p), list)]
        if lists:
            return ["long_list", pick(lists), pick(LONG_LISTS)]
    if kind == "text":
        return ["text", pick(TEXT_OPS)]
    if kind == "valve" and _cams(doc):
        return ["valve", pick(_cams(doc)), pick(["rename", "copy_exhaust", "copy_many"]), pick(WEIRD_NAMES)]
    if kind == "section":
        return ["section", pick(["drop_valves", "drop_crank", "add_crank", "add_two_stroke", "drop_engine",
                                 "empty_valves", "add_cycle_and_file", "add_camshaft", "add_camshaft"])]
    paths = leaves(doc)
    return ["type", pick(paths), pick(OTHER_TYPES)]


def _stage_key_op(pick, doc, path):
    """A mutation of one key of a valve's [dynamics] or [hydraulic] section."""
    how = pick(STAGE_OPS)
    value = _get(doc, path)
    if how in ("scale", "gentle") and isinstance(value, (int, float)) and not isinstance(value, bool):
        return ["scale", path, pick(FACTORS if how == "scale" else GENTLE)]
    if how == "special":
        return ["set", path, pick(SPECIALS)]
    if how == "delete":
        return ["delete", path]
    if how == "literal" and path[-1] in LITERALS:
        return ["set", path, pick(LITERALS[path[-1]])]
    return ["type", path, pick(OTHER_TYPES)]


@functools.lru_cache(maxsize=1)
def stage_sections():
    """``{stage: table}``: the [dynamics] section of examples/pushrod-dynamics.toml (20 speeds: a case stays short)
    and the [hydraulic] section of examples/marine-hydraulic-exhaust.toml."""
    dyn = tomllib.loads((EXAMPLES / "pushrod-dynamics.toml").read_text(encoding="utf-8"))
    hyd = tomllib.loads((EXAMPLES / "marine-hydraulic-exhaust.toml").read_text(encoding="utf-8"))
    finger = tomllib.loads(FINGER_EXAMPLE.read_text(encoding="utf-8"))
    return {"dynamics": {**dyn["valves"]["intake"]["dynamics"], "speeds": 20},
            "hydraulic": hyd["valves"]["exhaust"]["hydraulic"],
            "lash_adjuster": finger["valves"]["intake"]["lash_adjuster"]}


@functools.lru_cache(maxsize=1)
def finger_cam():
    """The finger keys of examples/modern-dohc-roller-finger.toml's intake cam (``roller_radius_mm``, ``finger_*``)."""
    cam = tomllib.loads(FINGER_EXAMPLE.read_text(encoding="utf-8"))["valves"]["intake"]["cam"]
    return {k: v for k, v in cam.items() if k.startswith("finger_") or k == "roller_radius_mm"}


@functools.lru_cache(maxsize=1)
def shaft_section():
    """The [camshaft] of examples/pushrod-dynamics.toml on one cylinder (its first lobe station), every valve."""
    shaft = tomllib.loads(SHAFT_EXAMPLE.read_text(encoding="utf-8"))["camshaft"]
    shaft.pop("valves", None)
    return {**shaft, "cylinders": [1], "cylinder_positions_mm": shaft["cylinder_positions_mm"][:1]}


def draw_case(pick, bases):
    """A case ``{"base": name, "ops": [...]}``: a base specification and one to three operations."""
    base = pick(list(bases))
    doc = copy.deepcopy(bases[base][0])
    ops = []
    for _ in range(pick([1, 1, 1, 2, 3])):
        op = draw_op(pick, doc)
        ops.append(op)
        _apply(doc, {}, op)
    return {"base": base, "ops": ops}


def _scaled(v, factor):
    x = v * factor
    if isinstance(v, int) and isinstance(factor, int):
        return x
    if isinstance(v, int) and math.isfinite(x) and abs(x) < 2 ** 62 and x == int(x):
        return int(x)
    return float(x)


def _apply(doc, files, op):
    """Apply ``op`` to ``doc`` (and ``files``) in place; return its description, or None when it does not apply."""
    kind = op[0]
    if kind in ("scale", "set", "type", "delete", "nest", "long_list"):
        path = tuple(op[1])
        node = _parent(doc, path) if kind != "set" else _get(doc, path[:-1])
        if node is None or (kind == "set" and not isinstance(node, (dict, list))):
            return None
        if kind == "set" and isinstance(node, list) and not (isinstance(path[-1], int) and path[-1] < len(node)):
            return None
        old = node[path[-1]] if kind != "set" or (isinstance(node, list) or path[-1] in node) else None
        if kind == "delete":
            del node[path[-1]]
            return f"delete {dotted(path)}"
        if kind == "scale":
            if not isinstance(old, (int, float)) or isinstance(old, bool):
                return None
            node[path[-1]] = _scaled(old, op[2])
            return f"{dotted(path)} = {_show(node[path[-1]])}  (was {_show(old)}, x {op[2]:g})"
        if kind == "nest":
            node[path[-1]] = _Nested(op[2])
            return f"{dotted(path)} = {op[2]} nested arrays [[[...1.0...]]]"
        if kind == "long_list":
            if not isinstance(old, list):
                return None
            item = old[0] if old else 1.0
            node[path[-1]] = [copy.deepcopy(item) for _ in range(op[2])]
            return f"{dotted(path)} = a list of {op[2]} x {_show(item)}"
        node[path[-1]] = copy.deepcopy(op[2])
        return f"{dotted(path)} = {_show(op[2])}" + (f"  (was {_show(old)})" if old is not None else "  (new key)")
    if kind == "law":
        valve = _get(doc, ("valves", op[1]))
        if not isinstance(valve, dict) or not isinstance(valve.get("cam"), dict):
            return None
        old = valve["cam"]
        keep = {k: old[k] for k in ("base_radius_mm", "follower", "roller_radius_mm") if k in old}
        valve["cam"] = {**copy.deepcopy(LAW_CAMS[op[2]]), **keep}
        if op[2] == "table":
            files["lobe.csv"] = (EXAMPLES / MEASURED_LOBE).read_bytes()
        if op[2] == "tangent":
            valve["cam"].update(ROLLER)
        return f"valves.{op[1]}.cam = the {op[2]} cam of LAW_CAMS (was law {old.get('law')!r})"
    if kind == "stage":
        valve = _get(doc, ("valves", op[1]))
        if not isinstance(valve, dict):
            return None
        valve[op[2]] = copy.deepcopy(stage_sections()[op[2]])
        if op[2] == "lash_adjuster":       # an adjuster leaves no clearance (the specification's rule)
            valve["clearance_mm"] = 0.0
            return f"valves.{op[1]}.lash_adjuster = the modern example's [lash_adjuster], clearance_mm = 0"
        return f"valves.{op[1]}.{op[2]} = the [{op[2]}] section of stage_sections()"
    if kind == "finger":
        valve = _get(doc, ("valves", op[1]))
        if not isinstance(valve, dict) or not isinstance(valve.get("cam"), dict):
            return None
        valve["cam"].update({**finger_cam(), **FINGER_VARIANTS[op[2]], "follower": "finger"})
        valve.pop("rocker_ratio", None)
        drive = valve.get("drive") if isinstance(valve.get("drive"), dict) else {}
        drive.pop("valve_arm_mm", None)
        valve["drive"] = {**drive, "layout": "rocker"}
        return (f"valves.{op[1]}.cam: follower = \"finger\" with the modern example's finger, variant {op[2]!r} "
                "(rocker_ratio and drive.valve_arm_mm removed, drive.layout = \"rocker\")")
    if kind == "tolerances":
        doc["tolerances"] = copy.deepcopy(op[1])
        return "tolerances = " + "; ".join(f"{t['key']} {t['distribution']} "
                                           + ", ".join(f"{k} = {_show(v)}" for k, v in t.items()
                                                       if k not in ("key", "distribution")) for t in op[1])
    if kind == "follower":
        cam = _get(doc, ("valves", op[1], "cam"))
        if not isinstance(cam, dict):
            return None
        cam["follower"] = op[2]
        if op[2] == "roller":
            cam["roller_radius_mm"] = op[3]
            return f"valves.{op[1]}.cam.follower = \"roller\", roller_radius_mm = {op[3]:g}"
        cam.pop("roller_radius_mm", None)
        return f"valves.{op[1]}.cam.follower = \"flat\" (roller_radius_mm removed)"
    if kind == "lift_file":
        valve = _get(doc, ("valves", op[1]))
        if not isinstance(valve, dict) or not isinstance(valve.get("cam"), dict):
            return None
        unit, content = LIFT_FILES[op[2]]
        old = valve["cam"]
        keep = {k: old[k] for k in ("base_radius_mm", "follower", "roller_radius_mm") if k in old}
        # the file is named for the valve by a hash: a valve name may be 300 characters or hold spaces and dots
        name = f"lift-{zlib.crc32(op[1].encode('utf-8')):08x}.csv"
        valve["cam"] = {**LAW_CAMS["table"], **keep, "table_file": name, "table_angle": unit,
                        "table_lift_at": op[3], "fit": op[4]}
        for k in ("max_lift_mm", "opens_deg", "closes_deg"):
            valve.pop(k, None)
        files[name] = content
        return (f"valves.{op[1]}.cam: law = \"table\", table_file = LIFT_FILES[{op[2]!r}], table_angle = {unit!r}, "
                f"table_lift_at = {op[3]!r}, fit = {op[4]!r}")
    if kind == "pressure_file":
        crank = doc.get("crank")
        if not isinstance(crank, dict):
            return None
        crank["pressure_file"] = "pressure.csv"
        crank["pv_method"] = op[2]
        crank.pop("cycle", None)
        files["pressure.csv"] = PRESSURE_FILES[op[1]](_geometry(doc))
        return f"crank.pressure_file = PRESSURE_FILES[{op[1]!r}], pv_method = {op[2]!r}, [crank.cycle] removed"
    if kind == "valve":
        valves = doc.get("valves")
        if not isinstance(valves, dict) or op[1] not in valves:
            return None
        if op[2] == "rename":
            valves[op[3]] = valves.pop(op[1])
            return f"rename [valves.{op[1]}] to [valves.{_show(op[3])}]"
        if op[2] == "copy_exhaust":
            valves["exhaust2"] = copy.deepcopy(valves[op[1]])
            valves["exhaust2"]["kind"] = "exhaust"
            return f"add [valves.exhaust2] = a copy of [valves.{op[1]}] with kind = \"exhaust\""
        for i in range(40):
            valves[f"v{i}"] = copy.deepcopy(valves[op[1]])
        return f"add 40 copies of [valves.{op[1]}] (v0 ... v39)"
    if kind == "section":
        what = op[1]
        if what == "drop_valves":
            doc.pop("valves", None)
        elif what == "empty_valves":
            doc["valves"] = {}
        elif what == "drop_crank":
            doc.pop("crank", None)
        elif what == "drop_engine":
            doc.pop("engine", None)
        elif what == "add_crank":
            doc["crank"] = copy.deepcopy(TWO_STROKE_CRANK)
        elif what == "add_camshaft":
            doc["camshaft"] = copy.deepcopy(shaft_section())
        elif what == "add_two_stroke":
            two = tomllib.loads((EXAMPLES / "two-stroke-ports.toml").read_text(encoding="utf-8"))
            doc["two_stroke"] = two["two_stroke"]
        else:  # both a cycle and a (valid) pressure file
            crank = doc.setdefault("crank", copy.deepcopy(TWO_STROKE_CRANK))
            if not isinstance(crank, dict):
                return None
            crank["pressure_file"] = "pressure.csv"
            files["pressure.csv"] = PRESSURE_FILES["valid_p_phi"](_geometry(doc))
        return f"section change: {what}"
    if kind == "text":
        files["__text__"] = files.get("__text__", []) + [op[1]]
        return f"file bytes: {op[1]}"
    raise ValueError(f"unknown operation {op!r}")


def _text_op(data, what):
    if what == "bom":
        return b"\xef\xbb\xbf" + data
    if what == "bom_twice":
        return b"\xef\xbb\xbf\xef\xbb\xbf" + data
    if what == "crlf":
        return data.replace(b"\n", b"\r\n")
    if what == "truncate_half":
        return data[: len(data) // 2]
    if what == "truncate_end":
        return data[:-3]
    if what == "nul_byte":
        return data.replace(b"\n", b"\n\x00", 1)
    if what == "latin1_byte":
        return b"# \xe9\n" + data
    if what == "empty":
        return b""
    if what == "utf16":
        return data.decode("utf-8", errors="replace").encode("utf-16")
    if what == "duplicate_key":
        if b"[engine]\n" in data:
            return data.replace(b"[engine]\n", b"[engine]\nbore_mm = 1.0\n", 1)
        return data + b"a = 1\na = 2\n"
    raise ValueError(what)


def materialize(case, bases):
    """The bytes of the specification, its files ``{relative name: bytes}`` and the applied operations' descriptions
    (operations that no longer apply, in a replayed subset, are skipped)."""
    doc, files = bases[case["base"]]
    doc, files = copy.deepcopy(doc), dict(files)
    described = []
    for op in case["ops"]:
        d = _apply(doc, files, op)
        if d is not None:
            described.append(d)
    text = toml_dumps(_swap_nested(doc)).encode("utf-8")
    for what in files.pop("__text__", []):
        text = _text_op(text, what)
    return text, files, described


class _Raw(str):
    """Text written into the TOML file as it is (a deeply nested array)."""


def _swap_nested(x):
    if isinstance(x, dict):
        return {k: _swap_nested(v) for k, v in x.items()}
    if isinstance(x, list):
        return [_swap_nested(v) for v in x]
    if isinstance(x, _Nested):
        return _Raw("[" * x.depth + "1.0" + "]" * x.depth)
    return x


# ---------------------------------------------------------------------------------------------------------------
# The other commands: study, optimize, sweep and compare on a (mutated) specification, through the command line

COMMANDS = ("study", "optimize", "sweep", "compare", "tolerance")
COMMAND_EVERY = 4
"""One random case in COMMAND_EVERY runs one of the COMMANDS instead of ``run``."""

COMMAND_BASES = ("example", "examples/pushrod-dynamics.toml", "examples/marine-hydraulic-exhaust.toml",
                 "examples/measured-lobe.toml", "examples/v8-crank.toml")
"""The base specifications each command runs on unmutated: the built-in example, the dynamics and hydraulic
examples, a measured lobe and a file without valves."""

COMMAND_TIMEOUT = {"optimize": 4.0, "study": 2.0, "compare": 2.0, "sweep": 2.0, "tolerance": 4.0}
"""Multiples of ``--timeout`` a command's case may take (an optimisation designs dozens of cams)."""

VALVES_PER_TIMEOUT = 8
"""A design's work grows with its valve sections (each designed with its own sweep): a case of ``n`` sections may
take ``--timeout`` x max(1, n / 8).  The 41 sections of ``copy_many`` with the polydyne example's 200-speed dynamics
took 40.6 s at a load of 2 (2026-12-02): a linear cost, not a hang."""

GRID_VALUES = ["{a},{b}", "{a}", "{a},{a},{a}", '["VDSiCr"]', "{{x = 1}}", "nan,{a}", "inf", "abc", "", "1e300,{a}",
               "-1,{a}", "true,false", '"flat","roller"', "{a},,{b}"]
"""``--grid KEY=...`` texts: ``{a}`` and ``{b}`` are the key's value x 0.95 and x 1.05 (1 and 2 for text)."""

VARY_BOUNDS = ["{a},{b}", "{b},{a}", "-10,1e6", "1e300,1e301", "nan,1", "{a},{a}", "0,0", "{a}"]
"""``--vary KEY=...`` bounds, as :data:`GRID_VALUES`."""

OPTIMIZE_OPTIONS = [[], [], ["--objective", "time_area"], ["--no-jump", "0"], ["--no-jump", "3"],
                    ["--wheel-radius", "5"], ["--valve", "{valve}"], ["--valve", "nosuchvalve"]]

TOLERANCE_SPREADS = [0.001, 0.01, 0.05, 0.3, 2.0]
"""Half-ranges and sigmas of a drawn [[tolerances]] entry, shares of the key's value."""

TOLERANCE_CUTS = [None, None, 8.0, 20.0, 40.0, -40.0, "low_only_far", "inverted"]
"""Truncations of a normal entry: none (6 sigma), [mu + k sigma, mu + (k + 1) sigma] far in a tail (issue 36), a
lower end beyond the upper default, low above high."""

RECORD_DAMAGE = [None, None, "margin_text", "margin_nan", "short_entry", "checks_list", "passed_flipped",
                 "headlines_text", "status_other", "index_text", "folder", "header_other", "cut_short"]
"""How a tolerance case damages its records.jsonl before it runs the command again (None: it runs once)."""

TOLERANCE_OPTIONS = [[], [], ["--method", "lhs"], ["--method", "sobol"], ["--seed", "3"], ["--samples", "10000000"],
                     ["--max-samples", "1"]]


def draw_tolerances(pick, doc):
    """A ``tolerances`` operation: one or two [[tolerances]] entries on numeric keys of ``doc`` (dotted keys through
    tables, as ``study --grid`` names them), uniform or normal, a spread of :data:`TOLERANCE_SPREADS` of the value,
    a normal one truncated by :data:`TOLERANCE_CUTS`."""
    paths = [p for p in _numbers(doc) if all(isinstance(q, str) for q in p) and p[0] != "tolerances"]
    entries = []
    for path in {tuple(pick(paths)) for _ in range(pick([1, 1, 2]))} if paths else [("engine", "bore_mm")]:
        value = _get(doc, path)
        value = float(value) if isinstance(value, (int, float)) and math.isfinite(value) and value != 0 else 1.0
        spread = abs(value) * pick(TOLERANCE_SPREADS)
        if pick(["uniform", "normal"]) == "uniform":
            entries.append({"key": ".".join(path), "distribution": "uniform", "half_range": spread})
            continue
        entry = {"key": ".".join(path), "distribution": "normal", "sigma": spread}
        cut = pick(TOLERANCE_CUTS)
        if isinstance(cut, float):
            low = value + cut * spread if cut > 0 else value + (cut - 1.0) * spread
            entry.update(low=low, high=low + spread)
        elif cut == "low_only_far":
            entry["low"] = value + 8.0 * spread
        elif cut == "inverted":
            entry.update(low=value + spread, high=value - spread)
        entries.append(entry)
    return ["tolerances", entries]


def _near(value):
    if isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value):
        return {"a": f"{0.95 * value:.6g}", "b": f"{1.05 * value:.6g}"}
    return {"a": "1", "b": "2"}


def draw_command(pick, doc, command=None):
    """The command line (after the command's name and the file) of one command on ``doc``, e.g. ``["study",
    "--grid", "engine.bore_mm=76,84"]``; bounded runs: optimize with --maxiter 1, study grids of a few points.
    ``compare`` compares the file with its unmutated base (``<base>``)."""
    command = command or pick(COMMANDS)
    paths = leaves(doc) or [("engine", "bore_mm")]
    valves = _cams(doc) or ["intake"]
    if command == "study":
        args = ["study"]
        for _ in range(pick([1, 1, 2])):
            path = pick(paths)
            args += ["--grid", f"{dotted(path)}={pick(GRID_VALUES).format(**_near(_get(doc, path)))}"]
        return args
    if command == "optimize":
        args = ["optimize", "--maxiter", "1"]
        valve = pick(valves)
        under = [p for p in leaves(doc) if len(p) > 2 and p[0] == "valves" and p[1] == valve
                 and isinstance(_get(doc, p), (int, float)) and not isinstance(_get(doc, p), bool)]
        for _ in range(pick([0, 0, 1, 2])):
            if under:
                path = pick(under)
                key = dotted(path[2:])
                args += ["--vary", f"{key}={pick(VARY_BOUNDS).format(**_near(_get(doc, path)))}"]
        if len(args) > 5 and pick([True, False]):
            args += args[-2:]                                   # the same --vary twice
        return args + [a.format(valve=valve) for a in pick(OPTIMIZE_OPTIONS)]
    if command == "sweep":
        return ["sweep"] + pick([[], [], ["--valve", pick(valves)], ["--valve", "nosuchvalve"]])
    if command == "tolerance":
        damage = pick(RECORD_DAMAGE)
        return ["tolerance", "--samples", pick(["3", "4"])] + pick(TOLERANCE_OPTIONS) + (
            [f"<damage:{damage}>"] if damage else [])
    return ["compare", "<base>"]


def damage_records(out, how) -> bool:
    """Damage the records.jsonl of a tolerance study in ``out`` as :data:`RECORD_DAMAGE` names (the second line's
    record); False where there is no record to damage."""
    path = Path(out) / "records.jsonl"
    lines = path.read_text(encoding="utf-8").split("\n") if path.is_file() else []
    if len(lines) < 2 or not lines[1].strip():
        return False
    if how == "folder":
        path.unlink()
        path.mkdir()
        (path / "mine.txt").write_text("kept", encoding="utf-8")
        return True
    if how == "header_other":
        lines[0] = json.dumps({"fingerprint": "another study"})
    elif how == "cut_short":
        lines[1] = lines[1][: len(lines[1]) // 2]
    else:
        item = json.loads(lines[1])
        record = item["record"]
        checks = record["checks"]
        cid = next(iter(checks), None)
        if how == "margin_text" and cid:
            checks[cid][0] = "0.5"
        elif how == "margin_nan" and cid:
            checks[cid][0] = "NAN_HERE"
        elif how == "short_entry" and cid:
            checks[cid] = checks[cid][:2]
        elif how == "checks_list":
            record["checks"] = list(checks.items())
        elif how == "passed_flipped" and cid:
            checks[cid][1] = not checks[cid][1]
        elif how == "headlines_text":
            record["headlines"] = {"intake": "fast"}
        elif how == "status_other":
            record["status"] = "maybe"
        elif how == "index_text":
            item["index"] = "0"
        lines[1] = json.dumps(item).replace('"NAN_HERE"', "NaN")
    path.write_text("\n".join(lines), encoding="utf-8")
    return True


def tolerance_draw_problems(spec_file, options):
    """Draws of a tolerance study that are not finite or leave their range (nonsense), ``[(generic, text)]``: the
    samples as the command draws them (the same file, --samples, --method, --seed), checked independently of it."""
    from valvetrain.specification import load_spec
    from valvetrain.study import read_document
    from valvetrain.tolerance import ToleranceError, check_tolerances, draw, sample_range

    def option(name, default):
        return options[options.index(name) + 1] if name in options else default

    samples = int(option("--samples", "3"))
    if samples > 10_000:
        return []
    try:
        spec = load_spec(spec_file)
        centres = check_tolerances(read_document(spec_file), spec)
    except (SpecError, ToleranceError):
        return []
    values = draw(spec, centres, samples, option("--method", "mc"), int(option("--seed", "0")))
    out = []
    for j, (t, centre) in enumerate(zip(spec.tolerances, centres, strict=True)):
        low, high = sample_range(t, centre)
        x = values[:, j]
        if not np.all(np.isfinite(x)) or np.any((x < low) | (x > high)):
            out.append((f"draw outside [low, high] ({t.distribution})",
                        f"tolerances: {t.key}: draws {x.tolist()} against [{low:g}, {high:g}]"))
    return out


def _command_messages(output):
    """The refusal messages of a command's output: its ``error: `` lines and click's ``Error: `` line."""
    return [line.split(": ", 1)[1] for line in output.splitlines() if line.startswith(("error: ", "Error: "))]


def _json_problems(folder):
    """NaN and inf in the JSON files a command wrote: ``[(generic name, text)]``."""
    found = []
    for f in sorted(Path(folder).rglob("*.json")) if Path(folder).is_dir() else []:
        bad = []
        json.loads(f.read_text(encoding="utf-8"), parse_constant=bad.append)
        if bad:
            found.append((f"{f.name}: {bad[0]}", f"{f.name} holds {bad[0]} ({len(bad)} x)"))
    return found


OPTION = re.compile(r"(?<![\w-])--[a-z]|'--[a-z]")
"""An option of a command named in a message (click's own messages quote it: "Invalid value for '--grid'")."""

NAN_WORD = re.compile(r"(?<![\w.])-?(nan|inf)(?![\w.])", re.IGNORECASE)


def run_command(case, tmp, spec_file, base_file, timeout):
    """Run ``case["command"]`` through the command line in this process and classify it (updates of a record)."""
    from click.testing import CliRunner
    from valvetrain.cli import main as cli

    name, *rest = case["command"]
    out = Path(tmp) / "out"
    damage = next((a[len("<damage:"):-1] for a in rest if a.startswith("<damage:")), None)
    rest = [a for a in rest if not a.startswith("<damage:")]
    args = [name, str(spec_file)] + [str(base_file) if a == "<base>" else a for a in rest] + ["--out", str(out)]
    old = signal.signal(signal.SIGALRM, _alarm)
    signal.setitimer(signal.ITIMER_REAL, timeout * COMMAND_TIMEOUT[name])
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error", RuntimeWarning)
            result = CliRunner().invoke(cli, args, catch_exceptions=True)
            first = None
            if damage is not None and result.exit_code == 0 and (out / "tolerance.json").is_file():
                first = json.loads((out / "tolerance.json").read_text(encoding="utf-8"))
                if damage_records(out, damage):
                    result = CliRunner().invoke(cli, args, catch_exceptions=True)   # again, on damaged records
    except CaseTimeout as exc:
        own, inner = _frame(traceback.extract_tb(exc.__traceback__))
        return {"outcome": "hang", "signature": f"timeout in {name} at {own}",
                "detail": [f"still running after {timeout * COMMAND_TIMEOUT[name]:g} s; innermost frame {inner}"]}
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)
    output = result.output.replace(str(tmp), "<tmp>")
    if isinstance(result.exception, CaseTimeout):
        own, inner = _frame(traceback.extract_tb(result.exc_info[2]))
        return {"outcome": "hang", "signature": f"timeout in {name} at {own}",
                "detail": [f"still running after {timeout * COMMAND_TIMEOUT[name]:g} s; innermost frame {inner}"]}
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        exc = result.exception
        own, inner = _frame(traceback.extract_tb(result.exc_info[2]))
        return {"outcome": "traceback", "signature": f"{name}: {type(exc).__name__} at {own}",
                "detail": [f"{name}: {type(exc).__name__}: {_clip(str(exc).replace(str(tmp), '<tmp>'))}",
                           f"innermost frame {inner}"]}
    if result.exit_code == 2:
        messages = _command_messages(result.output)
        bad = [(m, message_problem(m, spec_file)) for m in messages]
        # a message about an option of the command (--grid, --vary, --valve) names the option instead of a key
        bad = [(m.replace(str(tmp), "<tmp>"), why) for m, why in bad
               if why and not (why == "no key path" and OPTION.search(m))]
        if not messages:
            return {"outcome": "bad_message", "signature": f"{name}: exit 2 without a message",
                    "detail": [_clip(output)]}
        if bad:
            m, why = bad[0]
            return {"outcome": "bad_message", "signature": f"{name}: {why}: {_message_template(m, why)}",
                    "detail": [f"{why}: {_clip(m)}" for m, why in bad[:5]]}
        return {"outcome": "refused", "detail": [_clip(m.replace(str(tmp), "<tmp>")) for m in messages[:5]]}
    if result.exit_code == 1 and name == "optimize" and INFEASIBLE.match(output):
        return {"outcome": "infeasible", "detail": [_clip(line) for line in output.splitlines()[:5]]}
    if result.exit_code != 0:
        return {"outcome": "traceback", "signature": f"{name}: exit status {result.exit_code}",
                "detail": [_clip(output)]}
    nans = _json_problems(out)
    printed = [line for line in output.splitlines() if NAN_WORD.search(line) and not line.startswith("note: ")]
    if name == "tolerance":
        wrong = tolerance_draw_problems(spec_file, rest)
        if first is not None and json.loads((out / "tolerance.json").read_text(encoding="utf-8")) != first:
            wrong.append((f"a damaged record trusted ({damage})", f"records.jsonl damaged ({damage}): the run again "
                          "gave other results than the first"))
        if wrong:
            return {"outcome": "nonsense", "signatures": [f"nonsense: tolerance: {wrong[0][0]}"],
                    "detail": [t for _, t in wrong[:5]]}
    if nans or printed:
        return {"outcome": "nan_output", "signatures": [f"nan_output: {name}: {k}" for k, _ in nans]
                + ([f"nan_output: {name}: printed {NAN_WORD.search(printed[0]).group(0)}"] if printed else []),
                "detail": [t for _, t in nans[:5]] + [_clip(line) for line in printed[:5]]}
    return {"outcome": "ok"}


# ---------------------------------------------------------------------------------------------------------------
# Running one case and classifying its outcome

class CaseTimeout(BaseException):
    """Raised in the worker when a case exceeds its time (a BaseException: ``except Exception`` does not eat it)."""


def _alarm(signum, frame):
    raise CaseTimeout()


MAX_MESSAGE = 300
KEY_PATH = re.compile(r"(?<![\w.])\[?(engine|valves|gas|crank|camshaft|two_stroke|breathing|output|accepted|tolerances)\b")
INTERNAL_TEXT = ("ill-posed", "ill-conditioned", "singular matrix", "traceback", "numpy", "scipy", "ndarray",
                 "dtype", "object has no attribute", "nonetype", "index out of", "division by zero",
                 "math domain", "not enough values", "too many values", "recursion", "operands could not",
                 "errors.pydantic.dev", "input_value", "f(a) and f(b)", "linprog", "brentq", "x must be",
                 "the number of derivatives", "iteration limit", "valueerror", "typeerror", "keyerror")


def message_problem(message, spec_file):
    """Why a refusal message breaks the contract (None when it is fine): no key path, library internals, too long.

    Messages about the file itself (unreadable, not TOML) are located by the file name and line instead of a key;
    an unknown key's message starts with that key."""
    if len(message) > MAX_MESSAGE:
        return "longer than 300 characters"
    low = message.lower()
    for text in INTERNAL_TEXT:
        if text in low:
            return f"internal text {text!r}"
    if not KEY_PATH.search(message) and ": unknown key" not in message and not message.startswith(str(spec_file)):
        return "no key path"
    return None


def _frame(tb_entries):
    """``valvetrain/path.py:line (function)`` of the innermost frame in the package, and the innermost frame."""
    def fmt(fr):
        name = fr.filename.replace("\\", "/")
        cut = name.rfind("/valvetrain/")
        short = name[cut + 1:] if cut >= 0 else name
        return f"{short}:{fr.lineno} ({fr.name})"

    tb_entries = [fr for fr in tb_entries if not fr.filename.endswith("fuzz_specs.py")]
    own = [fr for fr in tb_entries if "/valvetrain/" in fr.filename.replace("\\", "/")]
    return (fmt(own[-1]) if own else "(no valvetrain frame)"), (fmt(tb_entries[-1]) if tb_entries else "")


DOCUMENTED_NULLS = {
    # key (last part of the path, or the whole path made generic by _generic without its list indices, for a key
    # whose name other sections share) -> when a null (None or a non-finite number) is documented
    "rho_max_mm": "straight flanks", "rho_max_cam_deg": "straight flanks",
    "min_concave_radius_mm": "no concave stretch",
    "duration_deg": "a checking height the measured lift never reaches",
    "opens_deg_at_0.1mm": "a measured lift that never reaches 0.1 mm", "closes_deg_at_0.1mm": "the same",
    **dict.fromkeys(("opens_at_1mm_crank_deg", "closes_at_1mm_crank_deg", "duration_at_1mm_crank_deg",
                     "opens_at_0_050in_crank_deg", "closes_at_0_050in_crank_deg", "duration_at_0_050in_crank_deg",
                     "overlap_at_0_050in_crank_deg"), "a cam card's checking height the lift never reaches"),
    "nonuniformity": "a mean torque that is not positive", "torque_work_balance": "no indicated work",
    "low": "a check open below", "high": "a check open above",
    "valve": "a check of the engine or of a chapter",
    **dict.fromkeys(("pump_up_um", "held_open_um", "pumped_up_um", "valves.NAME.lash_adjuster.per_speed.revolutions",
                     "valves.NAME.lash_adjuster.per_speed.settled"),
                    "a speed without a simulated motion of the plunger (no [dynamics] on the valve)"),
    "min_contact_force_N": "the valve never leaves its seat (a drive too soft to overcome the preload)",
    **dict.fromkeys(("max_seating_velocity_m_s", "max_seating_velocity_speed_rpm"), "the valve seats at no speed "
                    "(of its error also: the refinement's work limit reached first)"),
    "jump_speed_rpm": "no follower separation in the speed range", "bounce_speed_rpm": "no bounce in the range",
    **dict.fromkeys(("jump_speed_step_rpm", "jump_speed_grid_rpm"), "the jump speed's error: no separation, or the "
                    "refinement's work limit reached first"),
    **dict.fromkeys(("bounce_speed_step_rpm", "bounce_speed_grid_rpm"), "the bounce onset's error: no bounce, or the "
                    "refinement's work limit reached first"),
    "rated_seating_velocity_m_s": "the valve does not seat at the rated speed (its seating velocity's error), or the "
                                  "refinement's work limit reached first",
    "rated_bounce_mm": "the refinement's work limit reached first (the rated speed's bounce height's error)",
    "coil_clash_speed_rpm": "no coil clash in the range",
    "cam_min_concave_radius_mm": "no concave stretch", "master_flat_lift_max_mm": "a master that is not convex",
    **dict.fromkeys(("max_wear_lift_error_mm", "max_wear_lift_error_cam_deg", "max_wear_lift_error_first_order_mm",
                     "max_wear_phase_shift_cam_deg", "master_rho_min_mm"), "a wheel that cannot grind the cam"),
    "seating_velocity_m_s": "a speed whose recorded revolution has no seating (dynamics), a hydraulic valve that "
                            "does not return to its seat within the revolution",
    **dict.fromkeys(("opening_delay_cam_deg", "closing_delay_cam_deg"),
                    "a hydraulic valve that stays shut (or, closing, does not return) within the revolution"),
    **dict.fromkeys(("lift_off_crank_deg", "cylinder_pressure_at_lift_off_MPa", "gas_force_at_lift_off_N",
                     "lift_off_pressure_MPa"), "a hydraulic valve that never leaves its seat against the gas force"),
    "solenoid_closes_crank_deg": "a lost-motion solenoid valve shut before the cam lifts (the key left out)",
    "valves.NAME.lost_motion.breathing.solenoid_opens_crank_deg": "the full lift's breathing (the solenoid valve shut)",
    **dict.fromkeys(("valve_closes_crank_deg", "full_lift_valve_closes_crank_deg", "full_lift_seating_velocity_m_s"),
                    "a lost-motion valve that does not return to its seat within the revolution"),
}
"""In memory a documented null may be NaN (numpy's "none"), which results.json writes as null."""

DOCUMENTED_EMPTY_CELLS = {"rho_mm"}
"""Table columns where an infinite value is written as a documented empty cell (a straight flank's radius)."""


def _walk(x, path=()):
    if isinstance(x, dict):
        for k, v in x.items():
            yield from _walk(v, path + (str(k),))
    elif isinstance(x, (list, tuple)):
        for i, v in enumerate(x):
            yield from _walk(v, path + (i,))
    elif isinstance(x, np.ndarray):
        for i, v in enumerate(x.tolist()):
            yield from _walk(v, path + (i,))
    else:
        yield path, x


def _generic(path, valve_names):
    """A key path with valve names, list indices and the names of warnings made generic (for signatures)."""
    parts = []
    for i, p in enumerate(path):
        if isinstance(p, int):
            parts.append("[]")
        elif i == 1 and path[0] == "valves" and p in valve_names:
            parts.append("NAME")
        else:
            parts.append(p)
    return ".".join(parts).replace(".[]", "[]")


def _unevaluated_check(data, path):
    """Whether ``path`` is the value or margin of a check record (``checks``, ``warnings``) that carries the reason
    its value cannot be had (valvetrain.checks: such a check is a failure)."""
    if len(path) != 3 or path[0] not in ("checks", "warnings") or path[2] not in ("value", "margin"):
        return False
    return bool(data[path[0]][path[1]].get("unevaluated"))


def _boundless_check(data, path):
    """Whether ``path`` is the margin of a full check record (``checks``) without bounds (range 'any'): it has no
    distance to a bound, its margin +inf in memory and null in results.json (the schema's rule)."""
    if len(path) != 3 or path[0] != "checks" or path[2] != "margin":
        return False
    record = data["checks"][path[1]]
    return "low" in record and "high" in record and record["low"] is None and record["high"] is None


def null_problems(data, valve_names):
    """Non-finite numbers and nulls of ``results.to_dict()`` (or of results.json) that are not documented:
    ``[(generic path, text)]``."""
    out = []
    for path, v in _walk(data):
        if _unevaluated_check(data, path):
            continue          # a check whose value cannot be had: null with its reason, margin -inf, a failure
        if _boundless_check(data, path) and (v is None or v == math.inf):
            continue          # a check without bounds: no margin
        if v is None or (isinstance(v, (float, np.floating)) and not math.isfinite(v)):
            # the key of a list's item is the list's own (its entries share its documentation)
            key = next((str(p) for p in reversed(path) if not isinstance(p, int)), "")
            documented = key in DOCUMENTED_NULLS or _generic(path, valve_names).replace("[]", "") in DOCUMENTED_NULLS
            if documented and (v is None or v != v):
                continue
            if len(path) > 1 and path[-2] == "margins" and v == math.inf:
                continue      # a spring's check switched off passes with an infinite margin
            out.append((_generic(path, valve_names), f"{dotted(path)} = {v!r}"))
    return out


def column_problems(name, columns):
    """Columns of a table with NaN/inf: ``[(generic name, text)]``."""
    out = []
    for col, values in columns.items():
        arr = np.asarray(values)
        if arr.dtype.kind in "fc" and col in DOCUMENTED_EMPTY_CELLS:
            arr = arr[~np.isinf(arr)]
        if arr.dtype.kind in "fc" and not np.all(np.isfinite(arr)):
            bad = arr[~np.isfinite(arr)]
            out.append((f"{name}:{col}", f"{name}: column {col} has {bad.size} non-finite of {arr.size} "
                                         f"(first {bad[0]!r})"))
    return out


def _table_max(path):
    """The largest lift of a measured table (read independently of the package)."""
    text = Path(path).read_text(encoding="utf-8")
    rows = [r for r in csv.reader(text.splitlines()) if r and not r[0].lstrip().startswith("#")]
    return max(float(r[1]) for r in rows[1:])


def plausibility(results):
    """Failed plausibility checks of an accepted design: ``[(check name, text)]``."""
    out = []
    for name, v in results.valves.items():
        spec_valve = results.spec.valves[name]
        law = spec_valve.cam.law
        s = v.summary
        event = s["cam"]["event_cam_deg"]
        if not event < 360.0:
            out.append((f"event_cam_deg >= 360 [law={law}]", f"valves.{name}.cam.event_cam_deg = {event:.6g}"))
        lift = s["flow"]["valve_lift_mm"]
        if law == "table":
            declared = _table_max(spec_valve.cam.table_file)
            if spec_valve.cam.table_lift_at == "tappet":   # the valve moves once the clearance is taken up
                declared = spec_valve.rocker_ratio * (declared - spec_valve.clearance_mm)
            what = "the table's maximum valve lift"
        else:
            declared, what = spec_valve.max_lift_mm, "max_lift_mm"
        # the dynamic cam lifts the valve to max_lift_mm elastically, at its design speed: its rigid lift differs by
        # the drive's deflection, at most (spring force at full lift + the inertia force)/c; the spring part alone
        # bounds it from above (the inertia at the nose pulls the other way)
        elastic = False
        if law == "dynamic":
            c = spec_valve.cam
            deflection = (c.spring_rate_N_per_mm * declared + c.spring_preload_N) / c.drive_stiffness_N_per_mm
            elastic = lift <= declared + deflection
        if not elastic and not abs(lift - declared) <= 0.01 * abs(declared):
            out.append((f"valve lift != declared [law={law}]",
                        f"valves.{name}.flow.valve_lift_mm = {lift:.6g}, {what} = {declared:.6g}"))
        table_top = float(np.max(v.table.valve_lift)) * 1e3
        if not table_top <= 1.01 * max(declared, lift):
            out.append((f"lift table above the valve lift [law={law}]",
                        f"valves.{name}: tables/{name}_lift.csv valve_lift_mm reaches {table_top:.6g}, "
                        f"valve_lift_mm = {lift:.6g}"))
        fullness = s["flow"]["fullness"]
        if not 0.0 < fullness <= 1.0:
            out.append((f"fullness outside (0, 1] [law={law}]", f"valves.{name}.flow.fullness = {fullness:.6g}"))
        out += _negative_magnitudes(name, s)
    return out + _unfailed(results)


NON_NEGATIVE = {
    # section of a valve's results -> keys that are magnitudes (a film, a roughness, a stiffness, a power, a leak)
    "lubrication": ("reduced_modulus_GPa", "composite_roughness_um", "min_film_parameter", "min_film_um",
                    "rated_friction_power_W", "rated_mean_friction_torque_N_m"),
    "lash_adjuster": ("chamber_pressure_MPa", "compression_um", "stiffness_N_per_mm", "stiffness_at_valve_N_per_mm",
                      "drive_stiffness_with_adjuster_N_per_mm", "rated_leak_down_um", "max_refill_share",
                      "max_pump_up_um", "max_held_open_um"),
    "spring": ("preload_N", "max_force_N", "rate_N_per_mm", "wire_mm", "free_length_mm", "installed_length_mm",
               "min_length_mm", "natural_frequency_Hz", "mass_kg"),
}
"""Results that cannot be negative: a negative film thickness or stiffness is no physical result."""


def _negative_magnitudes(name, summary):
    out = []
    for section, keys in NON_NEGATIVE.items():
        record = summary.get(section) or {}
        for key in keys:
            value = record.get(key)
            if isinstance(value, (int, float)) and not value >= 0.0:
                out.append((f"negative {section}.{key}", f"valves.{name}.{section}.{key} = {value:.6g}"))
    return out


def _unfailed(results):
    """Physically impossible designs that must be graded failures: an undercut profile, a spring whose coils touch
    before full lift, a follower separating below over_speed_ratio x the rated speed, a finger's pad off the valve
    tip, a camshaft twisted by more than 10 cam deg."""
    out = []
    engine = results.spec.engine
    failing = {(c.valve, c.code) for c in results.checks if c.severity == "failure" and not c.passed}
    for name, v in results.valves.items():
        s = v.summary
        if s["cam"].get("undercut") and not any(valve == name and code.startswith("profile.undercut")
                                                 for valve, code in failing):
            out.append(("undercut not a failure", f"valves.{name}.cam.undercut = true without a failing check"))
        spring = s.get("spring") or {}
        if isinstance(spring.get("min_pitch_mm"), float) and not spring["min_pitch_mm"] > spring["wire_mm"] \
                and not any(valve == name and code.startswith("spring.") for valve, code in failing):
            out.append(("coil bind not a failure", f"valves.{name}.spring.min_pitch_mm = {spring['min_pitch_mm']:.6g} "
                                                   f"<= wire_mm = {spring['wire_mm']:.6g} without a failing check"))
        finger = s["cam"].get("finger")
        if finger and not any(valve == name and code == "finger.tip_contact" for valve, code in failing):
            spec_valve = results.spec.valves[name]
            stem = spec_valve.parts.stem_diameter_mm or 0.2 * spec_valve.throat_diameter_mm
            if finger["tip_contact_max_mm"] > stem / 2.0:
                out.append(("finger pad off the valve tip not a failure",
                            f"valves.{name}.cam.finger.tip_contact_max_mm = {finger['tip_contact_max_mm']:.6g} beyond "
                            f"the tip's radius {stem / 2.0:.6g} mm without a failing check"))
        jump = (s.get("dynamics") or {}).get("jump_speed_rpm")
        if jump is not None and jump < engine.over_speed_ratio * engine.rated_speed_rpm * (1.0 - 1e-9) \
                and (name, "dynamics.jump_speed") not in failing:
            out.append(("separation below the over-speed not a failure",
                        f"valves.{name}.dynamics.jump_speed_rpm = {jump:.6g} below over_speed_ratio x rated = "
                        f"{engine.over_speed_ratio * engine.rated_speed_rpm:.6g} rpm without a failing check"))
    shaft = results.camshaft
    if shaft is not None and shaft.figures.twist_max > math.radians(10.0) and not any(
            code == "camshaft.twist_timing_error" for _, code in failing):
        out.append(("camshaft twist beyond 10 cam deg not a failure",
                    f"camshaft.largest_twist_cam_deg = {math.degrees(shaft.figures.twist_max):.6g} without a failing "
                    "check"))
    return out


def _in_memory_columns(results):
    out = {}
    for name, v in results.valves.items():
        out[f"tables/{name}_lift.csv"] = columns.lift_table_columns(v.table)
        out[f"contour/{name}.csv"] = columns.contour_columns(v)
        step = results.spec.output.export_step_deg
        out[f"contour/{name}_cartesian.csv"] = columns.cartesian_contour_columns(v, step)
        out[f"contour/{name}_lift.csv"] = columns.lift_export_columns(v, step)
    if results.crank is not None:
        out["tables/crank.csv"] = columns.crank_columns(results.crank)
        out["tables/engine_torque.csv"] = columns.engine_torque_columns(results.crank)
    if results.two_stroke is not None:
        out["tables/two_stroke_ports.csv"] = columns.two_stroke_columns(results.two_stroke)
        out["tables/two_stroke_time_area.csv"] = columns.two_stroke_speed_columns(results.two_stroke)
    return out


def _file_problems(out):
    """NaN/inf cells in the written CSV files: ``[(generic name, text)]``."""
    found = []
    for f in sorted(list((out / "tables").glob("*.csv")) + list((out / "contour").glob("*.csv"))):
        with open(f, newline="", encoding="utf-8") as fh:
            rows = list(csv.reader(fh))
        header, bad = rows[0], {}
        for row in rows[1:]:
            for col, cell in zip(header, row, strict=False):
                try:
                    x = float(cell)
                except ValueError:
                    continue
                if not math.isfinite(x):
                    bad.setdefault(col, cell)
        for col, cell in bad.items():
            found.append((f"{f.parent.name}/{f.name}:{col}", f"{f.parent.name}/{f.name}: column {col} has {cell!r}"))
    return found


def _generic_file(name, valve_names):
    for v in valve_names:
        name = name.replace(f"/{v}_", "/NAME_").replace(f"/{v}.csv", "/NAME.csv")
    return name


def check_results(results, tmp, write):
    """nan_output and nonsense findings of an accepted design (and of its written folder with ``write``)."""
    names = set(results.valves)
    data = results.to_dict()
    export.json_text(data)                      # must serialise (a TypeError here is a traceback)
    for w in results.warnings:                  # as `valvetrain run` prints them
        f"warning: {w.quantity} = {w.shown_value:.6g} {w.unit}, recommended {w.range} ({w.source})"  # noqa: B018
    nans = null_problems(data, names)
    for fname, cols in _in_memory_columns(results).items():
        nans += [(_generic_file(k, names), t) for k, t in column_problems(fname, cols)]
    if write:
        out = Path(tmp) / "out"
        export.write_outputs(results, out)
        nans += [(_generic_file(k, names), t) for k, t in _file_problems(out)]
        written = json.loads((out / "results.json").read_text(encoding="utf-8"))
        nans += [(k, t + " (results.json)") for k, t in null_problems(written, names)
                 if (k, t) not in null_problems(data, names)]
    return nans, plausibility(results)


def _group(key):
    """The signature of one NaN/nonsense finding: a measured table's timing record, list items and the cylinders'
    torque columns count once."""
    key = re.sub(r"^(valves\.NAME\.cam\.measured)\..*", r"\1", key)
    key = re.sub(r"_cyl\d+_", "_cylN_", key)          # engine_torque.csv: one column per cylinder
    return key.replace("[]", "")


def _signatures(pairs):
    """Distinct signatures of findings ``[(key, text)]``; ``warnings.value`` (a copy of a value found elsewhere)
    only when it is the only finding."""
    out = []
    for k, _ in pairs:
        g = _group(k)
        if g not in out:
            out.append(g)
    return [g for g in out if g != "warnings.value"] or out


API_FUNCTIONS = ("design", "sweep")
"""The functions of :mod:`valvetrain.api` an ``api`` case calls with the mutated dictionary."""


def run_api_case(case, bases, timeout=60.0):
    """Run one case through ``valvetrain.api.design`` and ``api.sweep`` with the mutated document as a dictionary
    (Python values TOML cannot hold, None, tuples, numpy numbers, reach the functions as they are) and classify it:
    an exception is a traceback, an error record without a key path or with library text a bad message, a result
    that is not strict JSON nan_output."""
    from valvetrain import api

    doc, files = copy.deepcopy(bases[case["base"]][0]), {}
    described = [d for d in (_apply(doc, files, op) for op in case["ops"]) if d is not None]
    rec = {"base": case["base"], "ops": case["ops"], "mutation": described + ["api: design, sweep"], "api": True}
    t0 = time.monotonic()
    old = signal.signal(signal.SIGALRM, _alarm)
    signal.setitimer(signal.ITIMER_REAL, timeout * len(API_FUNCTIONS))
    outcome, detail = "ok", []
    try:
        for name in API_FUNCTIONS:
            with warnings.catch_warnings():
                warnings.simplefilter("error", RuntimeWarning)
                out = getattr(api, name)(doc)
            if not out["ok"]:
                bad = [(e["text"] or e["message"], e["path"], message_problem(e["text"] or e["message"], ""))
                       for e in out["errors"]]
                bad = [(m, why) for m, path, why in bad if why and not (why == "no key path" and path)]
                if not out["errors"] or bad:
                    outcome = "bad_message"
                    rec["signature"] = f"api.{name}: " + (f"{bad[0][1]}: {_message_key(bad[0][0])}" if bad
                                                          else "not ok without an error record")
                    detail = [_clip(m) for m, _ in bad[:5]]
                    break
                outcome, detail = "refused", [_clip(e["text"] or e["message"]) for e in out["errors"][:5]]
                break
            try:
                json.dumps(out, allow_nan=False)
            except (TypeError, ValueError) as exc:
                outcome, rec["signature"], detail = "nan_output", f"api.{name}: not strict JSON", [_clip(str(exc))]
                break
    except CaseTimeout:
        outcome, rec["signature"] = "hang", f"api: timeout after {timeout * len(API_FUNCTIONS):g} s"
    except Exception as exc:  # noqa: BLE001 (every other exception is the finding)
        own, inner = _frame(traceback.extract_tb(exc.__traceback__))
        outcome, rec["signature"] = "traceback", f"api: {type(exc).__name__} at {own}"
        detail = [f"{type(exc).__name__}: {_clip(str(exc))}", f"innermost frame {inner}"]
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)
    rec.update(outcome=outcome, detail=detail, seconds=round(time.monotonic() - t0, 3))
    rec["signatures"] = [rec["signature"]] if "signature" in rec else []
    return rec


# ---------------------------------------------------------------------------------------------------------------
# The designer: its session's edit path (in this process) and `valvetrain serve`'s HTTP endpoints (a server process)

SESSION_EVERY = 10
"""One random case in SESSION_EVERY (not a command's) runs the designer's session on its specification."""

SERVE_EVERY = 40
"""One random case in SERVE_EVERY (not a command's nor a session's) serves its specification and requests pages."""

SESSION_ACTIONS = ["edit"] * 5 + ["drag"] * 3 + ["points", "pin", "report", "toml", "settle"]

DRAG_VALUES = [-200.0, -60.0, -10.0, -0.5, 0.0, 0.5, 10.0, 60.0, 200.0, math.nan, math.inf, 1e300, -1e300]

HTTP_REQUESTS = [("GET", "/"), ("GET", "/"), ("GET", "/?bokeh-session-id=x%00y"), ("GET", "/autoload.js"),
                 ("GET", "/static/js/bokeh.min.js"), ("GET", "/static/../../../../etc/passwd"), ("GET", "/no/such/page"),
                 ("POST", "/"), ("GET", "/ws"), ("HEAD", "/"), ("GET", "/" + "x" * 5000), ("GET", "/?%ff%fe=%00"),
                 ("PUT", "/static/x"), ("DELETE", "/"), ("GET", "/?" + "a=1&" * 2000)]
"""Requests a ``serve`` case sends (method, path)."""

SERVE_MODES = ["ok"] * 6 + ["port_taken", "bad_host"]
"""How a ``serve`` case starts the server: on a free port, on a port another socket listens on, on a host that does
not resolve."""


def _edit_value(pick, doc, path):
    value = _get(doc, path)
    if isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value):
        return _scaled(value, pick(FACTORS + GENTLE)) if pick([True, True, False]) else pick(SPECIALS)
    return pick(OTHER_TYPES[:8] + LITERALS.get(path[-1], []) + [None])


def draw_session(pick, doc):
    """The actions of a ``session`` case on ``doc``: one to four of :data:`SESSION_ACTIONS` (an edit of a key by the
    specification panel, a drag of a handle of a valve's plot, points of an inline table, the pin of the baseline,
    the report, the TOML download, the whole design with its sweeps)."""
    paths = [p for p in leaves(doc) if all(isinstance(q, str) for q in p)] or [("engine", "bore_mm")]
    valves = _cams(doc) or ["intake"]
    actions = []
    for _ in range(pick([1, 2, 3, 4])):
        kind = pick(SESSION_ACTIONS)
        if kind == "edit":
            path = pick(paths)
            actions.append(["edit", ".".join(path), _edit_value(pick, doc, path)])
        elif kind == "drag":
            actions.append(["drag", pick(valves), pick([0, 1, 2, 3, 4, 5]), pick(DRAG_VALUES), pick(DRAG_VALUES)])
        elif kind == "points":
            n = pick([0, 1, 5, 30])
            actions.append(["points", pick(valves), [pick(DRAG_VALUES) for _ in range(n)],
                            [pick(DRAG_VALUES) for _ in range(n)]])
        elif kind == "report":
            actions.append(["report", pick(["en", "ru"])])
        else:
            actions.append([kind])
    return actions


def draw_serve(pick):
    """A ``serve`` case: how the server starts (:data:`SERVE_MODES`) and two to four of :data:`HTTP_REQUESTS`."""
    return {"mode": pick(SERVE_MODES), "requests": [list(pick(HTTP_REQUESTS)) for _ in range(pick([2, 3, 4]))]}


def _problems_of(errors):
    """Bad messages of the designer's (or the api's) error records: ``[(message, why)]``."""
    bad = [(e["text"] or e["message"], e["path"], message_problem(e["text"] or e["message"], "")) for e in errors]
    return [(m, why) for m, path, why in bad if why and not (why == "no key path" and path)]


def _session_step(session, action, tmp):
    """One action of a session case; a finding ``(outcome, signature, detail)`` or None."""
    from valvetrain.specification import parse_spec
    from valvetrain.web.session import has_points

    kind = action[0]
    if kind == "edit":
        if not session.edit({action[1]: copy.deepcopy(action[2])}):
            bad = _problems_of(session.problems)
            if not session.problems:
                return "bad_message", "session.edit: not designed without a problem", []
            if bad:
                return "bad_message", f"session.edit: {bad[0][1]}: {_message_key(bad[0][0])}", [_clip(bad[0][0])]
    elif kind in ("drag", "points"):
        name = action[1]
        if name not in session.good_document.get("valves", {}):
            return None
        if kind == "drag":
            handles = session.handles(name)
            if handles:
                session.drag(name, handles[action[2] % len(handles)].name, action[3], action[4])
        elif has_points(session.good_document["valves"][name]["cam"]):
            session.set_points(name, action[2], action[3])
    elif kind == "pin":
        session.pin()
    elif kind == "report":
        session.report(action[1])
    elif kind == "toml":
        try:
            parse_spec(session.toml(), source_dir=tmp)
        except SpecError as err:
            return "nonsense", "session.toml: the download does not validate", [_clip(str(err))]
    elif kind == "settle":
        full = session.settle(session.good_document)
        session.settled(full)
        try:
            json.dumps(full, allow_nan=False)
        except (TypeError, ValueError) as exc:
            return "nan_output", "session.settle: not strict JSON", [_clip(str(exc))]
    return None


def run_session_case(case, bases, timeout=60.0):
    """Run one case through the designer's session (:class:`valvetrain.web.session.Session`, its edit path without a
    browser): start it on the mutated specification, then its actions (:func:`draw_session`); classified as
    :func:`run_case` classifies (an exception is a traceback, a problem without its key a bad message, a design or a
    whole design that is not strict JSON nan_output, a TOML download that does not validate nonsense)."""
    from valvetrain.web.session import Session

    text, files, described = materialize({**case, "ops": [op for op in case["ops"] if op[0] != "text"]}, bases)
    rec = {"base": case["base"], "ops": case["ops"], "session": case["session"],
           "mutation": described + [f"session: {_show(a)}" for a in case["session"]]}
    t0 = time.monotonic()
    outcome, signature, detail = "ok", None, []
    old = signal.signal(signal.SIGALRM, _alarm)
    signal.setitimer(signal.ITIMER_REAL, timeout * 2.0)
    with tempfile.TemporaryDirectory(prefix="vfs") as tmp:
        for name, content in files.items():
            (Path(tmp) / name).parent.mkdir(parents=True, exist_ok=True)
            (Path(tmp) / name).write_bytes(content)
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("error", RuntimeWarning)
                try:
                    session = Session.start(text.decode("utf-8"), tmp)
                except SpecError as err:
                    bad = [(m, message_problem(m, "")) for m in err.problems]
                    bad = [(m, why) for m, why in bad if why]
                    outcome = "bad_message" if bad else "refused"
                    signature = f"session.start: {bad[0][1]}: {_message_key(bad[0][0])}" if bad else None
                    detail = [_clip(m.replace(tmp, "<tmp>")) for m, _ in (bad or [(m, "") for m in err.problems])[:5]]
                else:
                    for action in case["session"]:
                        found = _session_step(session, action, tmp)
                        if found:
                            outcome, signature, detail = found
                            break
                    else:
                        try:
                            json.dumps(session.good, allow_nan=False)
                        except (TypeError, ValueError) as exc:
                            outcome, signature, detail = "nan_output", "session: not strict JSON", [_clip(str(exc))]
        except CaseTimeout as exc:
            own, _ = _frame(traceback.extract_tb(exc.__traceback__))
            outcome, signature = "hang", f"session: timeout at {own}"
        except Exception as exc:  # noqa: BLE001 (every other exception is the finding)
            own, inner = _frame(traceback.extract_tb(exc.__traceback__))
            outcome, signature = "traceback", f"session: {type(exc).__name__} at {own}"
            detail = [f"{type(exc).__name__}: {_clip(str(exc).replace(tmp, '<tmp>'))}", f"innermost frame {inner}"]
        finally:
            signal.setitimer(signal.ITIMER_REAL, 0)
            signal.signal(signal.SIGALRM, old)
    rec.update(outcome=outcome, detail=detail, seconds=round(time.monotonic() - t0, 3))
    rec["signatures"] = [signature] if signature else []
    if signature:
        rec["signature"] = signature
    return rec


def _serve_finding(proc, stderr, what):
    """A traceback printed by the server process (its standard error), as a finding, or None."""
    if "Traceback (most recent call last)" not in stderr:
        return None
    lines = stderr.splitlines()
    error = next((line for line in reversed(lines) if re.match(r"\w+(Error|Exception)\b", line)), "a traceback")
    frame = next((line.strip() for line in reversed(lines) if "/valvetrain/" in line and line.strip().startswith(
        "File")), "")
    return ("traceback", f"serve: {what}: {_message_key(error)}",
            [_clip(error), _clip(frame.replace(str(Path(valvetrain.__file__).parent), "valvetrain"))])


def run_serve_case(case, bases, timeout=60.0):
    """Run ``valvetrain serve`` on the mutated specification in a process of its own (:func:`draw_serve`: on a free
    port, a port taken or a host that does not resolve), send its requests, then Ctrl-C it: a traceback on its
    standard error, a reply of status 500 or more, no answer within ``timeout`` or a process that does not end on
    Ctrl-C are findings; a refusal (exit status 2) must name its key or option in one line."""
    import http.client
    import socket
    import subprocess

    text, files, described = materialize(case, bases)
    serve = case["serve"]
    rec = {"base": case["base"], "ops": case["ops"], "serve": serve,
           "mutation": described + [f"serve: {serve['mode']}: " + ", ".join(" ".join(r)[:60] for r in serve["requests"])]}
    t0 = time.monotonic()
    outcome, signature, detail = "ok", None, []
    with tempfile.TemporaryDirectory(prefix="vfw") as tmp, socket.socket() as taken:
        spec_file = Path(tmp) / "spec.toml"
        spec_file.write_bytes(text)
        for name, content in files.items():
            (Path(tmp) / name).parent.mkdir(parents=True, exist_ok=True)
            (Path(tmp) / name).write_bytes(content)
        taken.bind(("127.0.0.1", 0))
        taken.listen()
        args = {"ok": ["--port", "0"], "port_taken": ["--port", str(taken.getsockname()[1])],
                "bad_host": ["--host", "no.such.host.invalid", "--port", "0"]}[serve["mode"]]
        env = {**os.environ, "PYTHONPATH": os.pathsep.join(filter(None, [str(Path(valvetrain.__file__).parents[1]),
                                                                         os.environ.get("PYTHONPATH")]))}
        # Ctrl-C's default action in the server, even where this process ignores SIGINT (started in the background)
        proc = subprocess.Popen([sys.executable, "-u", "-m", "valvetrain", "serve", str(spec_file), "--no-show", *args],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env, cwd=tmp,
                                preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
        try:
            url, deadline = None, time.monotonic() + timeout
            while url is None and time.monotonic() < deadline:
                line = proc.stdout.readline()
                if not line:
                    break
                m = re.search(r"designer at (http://\S+)", line)
                url = m.group(1) if m else None
            if url is None:
                try:
                    proc.wait(timeout=max(deadline - time.monotonic(), 1.0))
                except subprocess.TimeoutExpired:
                    proc.kill()
                    proc.wait()
                    return {**rec, "outcome": "hang", "signature": "serve: no page and no end", "signatures":
                            ["serve: no page and no end"], "detail": [], "seconds": round(time.monotonic() - t0, 3)}
                stderr = proc.stderr.read().replace(tmp, "<tmp>")
                found = _serve_finding(proc, stderr, "start")
                if found:
                    outcome, signature, detail = found
                elif proc.returncode == 2:
                    messages = _command_messages(stderr)
                    bad = [(m, message_problem(m, str(spec_file).replace(tmp, "<tmp>"))) for m in messages]
                    bad = [(m, why) for m, why in bad if why and not (why == "no key path" and OPTION.search(m))]
                    outcome = "bad_message" if bad or not messages else "refused"
                    signature = (f"serve: {bad[0][1]}: {_message_key(bad[0][0])}" if bad else
                                 None if messages else "serve: exit 2 without a message")
                    detail = [_clip(m) for m in messages[:5]]
                else:
                    outcome, signature, detail = ("traceback", f"serve: exit status {proc.returncode} at start",
                                                  [_clip(stderr[-1500:])])
            else:
                host, port = url.removeprefix("http://").rstrip("/").rsplit(":", 1)
                for method, path in serve["requests"]:
                    conn = http.client.HTTPConnection(host, int(port), timeout=timeout)
                    try:
                        conn.request(method, path, body=b"x" * 100 if method in ("POST", "PUT") else None)
                        reply = conn.getresponse()
                        reply.read()
                    except (TimeoutError, socket.timeout):
                        outcome, signature = "hang", f"serve: no answer to {method} {path[:40]}"
                        break
                    except (ConnectionError, http.client.HTTPException) as exc:
                        outcome, signature = "traceback", f"serve: {type(exc).__name__} on {method} {path[:40]}"
                        break
                    finally:
                        conn.close()
                    if reply.status >= 500:
                        outcome, signature = "traceback", f"serve: HTTP {reply.status} on {method} {path[:40]}"
                        break
                proc.send_signal(signal.SIGINT)
                try:
                    proc.wait(timeout=30.0)
                except subprocess.TimeoutExpired:
                    proc.kill()
                    proc.wait()
                    outcome, signature = "hang", "serve: did not end on Ctrl-C"
                stderr = proc.stderr.read().replace(tmp, "<tmp>")
                found = _serve_finding(proc, stderr, "requests")
                if found:
                    outcome, signature, detail = found
                elif outcome == "ok" and proc.returncode not in (0, 130):
                    outcome, signature = "traceback", f"serve: exit status {proc.returncode} on Ctrl-C"
                detail = detail or [_clip(line) for line in stderr.splitlines()[-3:]]
        finally:
            if proc.poll() is None:
                proc.kill()
                proc.wait()
            proc.stdout.close()
            proc.stderr.close()
    rec.update(outcome=outcome, detail=detail, seconds=round(time.monotonic() - t0, 3))
    rec["signatures"] = [signature] if signature else []
    if signature:
        rec["signature"] = signature
    return rec


def run_case(case, bases, timeout=60.0, write=False):
    """Run one case through load_spec -> design.run (-> write_outputs) and classify it; a JSON-ready record (an
    ``api`` case through :func:`run_api_case`)."""
    if case.get("api"):
        return run_api_case(case, bases, timeout)
    if case.get("session"):
        return run_session_case(case, bases, timeout)
    if case.get("serve"):
        return run_serve_case(case, bases, timeout)
    text, files, described = materialize(case, bases)
    rec = {"base": case["base"], "ops": case["ops"], "mutation": described, "outcome": None}
    if case.get("command"):
        rec["command"] = case["command"]
        rec["mutation"] = described + [f"command: valvetrain {case['command'][0]} FILE {' '.join(case['command'][1:])}"]
    t0 = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="vf") as tmp:
        spec_file = Path(tmp) / "spec.toml"
        spec_file.write_bytes(text)
        for name, content in files.items():
            (Path(tmp) / name).parent.mkdir(parents=True, exist_ok=True)
            (Path(tmp) / name).write_bytes(content)
        if case.get("command"):
            base_text, base_files, _ = materialize({"base": case["base"], "ops": []}, bases)
            base_dir = Path(tmp) / "base"
            for name, content in {"spec.toml": base_text, **base_files}.items():
                (base_dir / name).parent.mkdir(parents=True, exist_ok=True)
                (base_dir / name).write_bytes(content)
            rec.update(run_command(case, tmp, spec_file, base_dir / "spec.toml", timeout))
            rec["seconds"] = round(time.monotonic() - t0, 3)
            rec["signatures"] = rec.get("signatures") or ([rec["signature"]] if "signature" in rec else [])
            if rec["signatures"]:
                rec["signature"] = rec["signatures"][0]
            return rec
        stage, allowed = "load_spec", timeout
        old = signal.signal(signal.SIGALRM, _alarm)
        signal.setitimer(signal.ITIMER_REAL, timeout)
        try:
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                warnings.simplefilter("error", RuntimeWarning)
                spec = load_spec(spec_file)
                allowed = timeout * max(1.0, len(spec.valves) / VALVES_PER_TIMEOUT)
                signal.setitimer(signal.ITIMER_REAL, allowed)
                stage = "design.run"
                results = run_design(spec)
                stage = "write_outputs" if write else "checks"
                nans, nonsense = check_results(results, tmp, write)
            signal.setitimer(signal.ITIMER_REAL, 0)
            rec["other_warnings"] = sorted({f"{w.category.__name__}: {str(w.message)[:120]}" for w in caught})
            if nans:
                rec.update(outcome="nan_output", signatures=[f"nan_output: {g}" for g in _signatures(nans)],
                           detail=[t for _, t in nans[:10]])
            elif nonsense:
                rec.update(outcome="nonsense", signatures=[f"nonsense: {g}" for g in _signatures(nonsense)],
                           detail=[t for _, t in nonsense[:10]])
            else:
                rec["outcome"] = "ok"
        except SpecError as err:
            signal.setitimer(signal.ITIMER_REAL, 0)
            bad = [(m, message_problem(m, spec_file)) for m in err.problems]
            bad = [(m, why) for m, why in bad if why]
            if not err.problems:
                rec.update(outcome="bad_message", signature="no message", detail=[])
            elif bad:
                m, why = bad[0]
                rec.update(outcome="bad_message", signature=f"{why}: {_message_template(m.replace(tmp, '<tmp>'), why)}",
                           detail=[f"{why}: {_clip(m.replace(tmp, '<tmp>'))}" for m, why in bad[:5]])
            else:
                rec.update(outcome="refused", detail=[_clip(m.replace(tmp, "<tmp>")) for m in err.problems[:5]])
        except CaseTimeout as exc:
            own, inner = _frame(traceback.extract_tb(exc.__traceback__))
            rec.update(outcome="hang", signature=f"timeout {allowed:g} s in {stage} at {own}",
                       detail=[f"still running after {allowed:g} s; innermost frame {inner}"])
        except Exception as exc:  # noqa: BLE001 (every other exception is the finding)
            signal.setitimer(signal.ITIMER_REAL, 0)
            own, inner = _frame(traceback.extract_tb(exc.__traceback__))
            rec.update(outcome="traceback", signature=f"{type(exc).__name__} at {own}",
                       detail=[f"{stage}: {type(exc).__name__}: {_clip(str(exc).replace(tmp, '<tmp>'))}",
                               f"innermost frame {inner}"])
        finally:
            signal.setitimer(signal.ITIMER_REAL, 0)
            signal.signal(signal.SIGALRM, old)
    rec["seconds"] = round(time.monotonic() - t0, 3)
    if "signature" in rec:
        rec["signatures"] = [rec["signature"]]
    elif "signatures" in rec:
        rec["signature"] = rec["signatures"][0]
    return rec


def _clip(text, n=400):
    return text if len(text) <= n else text[:n] + f"... ({len(text)} chars)"


def _message_template(message, why):
    """The signature of a bad message: its generic text; a message that is too long because it repeats the
    value it refuses is grouped by the text that follows the value."""
    if why.startswith("longer"):
        if ": unknown key (value " in message:
            return "KEY: unknown key (value VALUE): VALUE echoed in full"
        head, sep, rest = message.partition(" = ")
        if sep:
            text = rest.rsplit(": ", 1)[-1]
            if re.match(r"(Input|Tuple|List|Value|String|Dictionary)\b.* should", text):
                return "KEY = VALUE: pydantic's type message, VALUE echoed in full"
            return f"{_message_key(head)} = VALUE: {_message_key(text)}, VALUE echoed in full"
    return _message_key(message)


def _message_key(message):
    """A refusal message made generic for the signature: the valve names, quoted text, arrays and numbers replaced
    (``valves.NAME.cam.p = Q: Input should be ...``)."""
    text = re.sub(r"^valves\.[^.\s:]+", "valves.NAME", message)
    text = re.sub(r"'[^']*'|\"[^\"]*\"", "Q", text)
    text = re.sub(r"\[[\[\]\s\w.,+\-']*\]", "L", text)
    text = re.sub(r"<tmp>\S*|/\S+", "FILE", text)
    text = re.sub(r"\d+(\.\d*)?([eE][+-]?\d+)?", "N", text)
    return text[:100]


# ---------------------------------------------------------------------------------------------------------------
# Parallel running with a deadline per case

_BASES = None
_HANG_DIR = None


def _init_worker(hang_dir):
    global _BASES, _HANG_DIR
    _BASES, _HANG_DIR = base_specs(), hang_dir
    try:
        import resource
        limit = 6 * 1024 ** 3  # a runaway allocation becomes a MemoryError, not a stalled machine
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    except (ImportError, ValueError, OSError):
        pass


def allowed_seconds(case, bases, timeout):
    """The seconds :func:`run_case` allows ``case`` before it counts as a hang: ``timeout`` times the command's
    :data:`COMMAND_TIMEOUT`, twice for a session, once per function for an api case, the start, each request and
    Ctrl-C for a serve case, and x max(1, valve sections / :data:`VALVES_PER_TIMEOUT`) for a run."""
    if case.get("command"):
        return timeout * COMMAND_TIMEOUT[case["command"][0]]
    if case.get("session"):
        return timeout * 2.0
    if case.get("api"):
        return timeout * len(API_FUNCTIONS)
    if case.get("serve"):
        return timeout * (1 + len(case["serve"]["requests"])) + 30.0
    doc = copy.deepcopy(bases[case["base"]][0])
    for op in case["ops"]:
        _apply(doc, {}, op)
    valves = doc.get("valves")
    return timeout * max(1.0, (len(valves) if isinstance(valves, dict) else 0) / VALVES_PER_TIMEOUT)


def _worker(case, timeout, write):
    # the hard deadline, 30 s after the case's own: a case stuck in C code, where the SIGALRM of run_case cannot
    # interrupt it, ends the worker process after writing where it was stuck
    with open(Path(_HANG_DIR) / f"{os.getpid()}.txt", "w") as fh:
        faulthandler.dump_traceback_later(allowed_seconds(case, _BASES, timeout) + 30.0, exit=True, file=fh)
        try:
            return run_case(case, _BASES, timeout, write)
        finally:
            faulthandler.cancel_dump_traceback_later()


def _dead_worker_record(case, seconds, timeout, hang_dir):
    dumps = [p.read_text(errors="replace") for p in Path(hang_dir).glob("*.txt") if p.stat().st_size]
    frames = re.findall(r'File "([^"]*/valvetrain/[^"]*)", line (\d+) in (\S+)', "\n".join(dumps))
    frames = [f for f in frames if "/tools/" not in f[0]]
    where = f"{frames[0][0][frames[0][0].rfind('/valvetrain/') + 1:]}:{frames[0][1]} ({frames[0][2]})" if frames \
        else "(no valvetrain frame)"
    bases = base_specs()
    allowed = allowed_seconds(case, bases, timeout)
    hung = seconds >= allowed
    sig = f"hard timeout (C code) at {where}" if hung else f"worker process died at {where}"
    return {"base": case["base"], "ops": case["ops"], **_command_of(case), "mutation": materialize(case, bases)[2],
            "outcome": "hang" if hung else "traceback", "signature": sig, "signatures": [sig],
            "detail": [f"the worker did not return within {allowed:g} s + 30 s" if hung else
                       "the worker process died (crash or killed)"], "seconds": round(seconds, 3)}


def _run_isolated(case, timeout, write):
    """Run one case alone in a fresh worker: the culprit of a broken pool is found this way."""
    with tempfile.TemporaryDirectory(prefix="vfhang") as hang_dir:
        t0 = time.monotonic()
        with ProcessPoolExecutor(1, initializer=_init_worker, initargs=(hang_dir,)) as pool:
            fut = pool.submit(_worker, case, timeout, write)
            try:
                return fut.result()
            except BrokenProcessPool:
                return _dead_worker_record(case, time.monotonic() - t0, timeout, hang_dir)


def run_cases(cases, workers=2, timeout=60.0, write=False, progress=None):
    """Records of ``cases`` in their order; at most ``workers`` cases in flight so a dead worker names its suspects."""
    records = [None] * len(cases)
    todo = deque(range(len(cases)))
    done = 0
    while todo:
        suspects = []
        with tempfile.TemporaryDirectory(prefix="vfhang") as hang_dir, \
                ProcessPoolExecutor(workers, initializer=_init_worker, initargs=(hang_dir,)) as pool:
            inflight = {}
            try:
                while todo or inflight:
                    while todo and len(inflight) < workers:
                        inflight[pool.submit(_worker, cases[todo[0]], timeout, write)] = todo[0]
                        todo.popleft()
                    finished, _ = wait(inflight, return_when=FIRST_COMPLETED)
                    for fut in finished:
                        rec = fut.result()
                        i = inflight.pop(fut)
                        records[i] = rec
                        done += 1
                        if progress:
                            progress(done, len(cases), records[i])
            except BrokenProcessPool:
                suspects = sorted(inflight.values())
        for i in suspects:
            records[i] = _run_isolated(cases[i], timeout, write)
            done += 1
            if progress:
                progress(done, len(cases), records[i])
    return records


# ---------------------------------------------------------------------------------------------------------------
# Case lists, minimisation, the summary

def file_cases(bases):
    """Every malformed CSV file against the bases it belongs to (lift tables: the table law with either follower,
    valve and tappet lift, spline and harmonic fit; indicator diagrams: every base with a [crank])."""
    cases = []
    for name in LIFT_FILES:
        for base, lift_at, fit in (("law:table", "valve", "spline"), ("law:table+roller", "tappet", "harmonic")):
            cases.append({"base": base, "ops": [["lift_file", "intake", name, lift_at, fit]]})
    crank_bases = [b for b, (doc, _) in bases.items() if isinstance(doc.get("crank"), dict)
                   and b in ("example", "examples/v8-crank.toml", "two-stroke+crank")]
    for name in PRESSURE_FILES:
        for base in crank_bases:
            for method in (["exact", "brix"] if name.startswith("pv_") or name == "valid_p_v" else ["exact"]):
                cases.append({"base": base, "ops": [["pressure_file", name, method]]})
    return cases


def random_cases(count, seed, bases):
    """``count`` mutated specifications; case i draws from random.Random(f"{seed}:{i}") (reproducible one by one);
    one case in :data:`COMMAND_EVERY` runs a command of :data:`COMMANDS` on its specification instead of ``run`` (a
    ``tolerance`` command with [[tolerances]] drawn by :func:`draw_tolerances`), of the others one in
    :data:`SESSION_EVERY` the designer's session (:func:`run_session_case`) and one in :data:`SERVE_EVERY` ``valvetrain
    serve`` (:func:`run_serve_case`); every base specification runs once unmutated, and those of
    :data:`COMMAND_BASES` once with each command, once in a session and once served."""
    out = []
    for i in range(count):
        rng = random.Random(f"{seed}:{i}")
        pick = lambda seq, rng=rng: seq[rng.randrange(len(seq))]  # noqa: E731
        case = draw_case(pick, bases)
        if i % COMMAND_EVERY == COMMAND_EVERY - 1:
            doc = copy.deepcopy(bases[case["base"]][0])
            for op in case["ops"]:
                _apply(doc, {}, op)
            case["command"] = draw_command(pick, doc)
            if case["command"][0] == "tolerance":
                case["ops"].append(draw_tolerances(pick, doc))
        elif i % SESSION_EVERY == 1 or i % SERVE_EVERY == 2:
            doc = copy.deepcopy(bases[case["base"]][0])
            for op in case["ops"]:
                _apply(doc, {}, op)
            if i % SESSION_EVERY == 1:
                case["session"] = draw_session(pick, doc)
            else:
                case["serve"] = draw_serve(pick)
        case["id"] = f"{seed}:{i}"
        out.append(case)
    for b in bases:
        out.append({"base": b, "ops": [], "id": f"base:{b}"})
    for b in COMMAND_BASES:
        rng = random.Random(f"{seed}:designer:{b}")
        pick = lambda seq, rng=rng: seq[rng.randrange(len(seq))]  # noqa: E731
        out.append({"base": b, "ops": [], "id": f"base:{b}:session", "session": draw_session(pick, bases[b][0])})
        out.append({"base": b, "ops": [], "id": f"base:{b}:serve", "serve": {**draw_serve(pick), "mode": "ok"}})
    for command in COMMANDS:
        for b in COMMAND_BASES:
            rng = random.Random(f"{seed}:{command}:{b}")
            pick = lambda seq, rng=rng: seq[rng.randrange(len(seq))]  # noqa: E731
            doc = bases[b][0]
            ops = [draw_tolerances(pick, doc)] if command == "tolerance" else []
            out.append({"base": b, "ops": ops, "id": f"base:{b}:{command}",
                        "command": draw_command(pick, doc, command)})
    return out


def _command_of(rec):
    """What a case runs besides ``run``: its command, session actions or serve requests."""
    return {k: rec[k] for k in ("command", "session", "serve") if rec.get(k)}


def minimise(groups, workers, timeout, write, log):
    """For each signature, the representative with the fewest operations, reduced further by dropping operations
    one at a time while the signature stays the same."""
    reps = {}
    for sig, recs in groups.items():
        rep = min(recs, key=lambda r: (len(r["ops"]), len(json.dumps(r["ops"], default=str))))
        ops = list(rep["ops"])
        while len(ops) > 1:
            trials = [{"base": rep["base"], "ops": ops[:k] + ops[k + 1:], **_command_of(rep)} for k in range(len(ops))]
            got = run_cases(trials, workers, timeout, write)
            same = [t for t, g in zip(trials, got, strict=True) if sig in g.get("signatures", [])]
            if not same:
                break
            ops = same[0]["ops"]
        if ops != rep["ops"]:
            rep = run_cases([{"base": rep["base"], "ops": ops, **_command_of(rep)}], 1, timeout, write)[0]
            log(f"  minimised {sig[:90]} to {len(ops)} operation(s)")
        reps[sig] = rep
    return reps


def write_repro(folder, reps, bases):
    """Each signature's minimal specification and its files in ``folder/NN-class/``."""
    folder = Path(folder)
    for k, (sig, rep) in enumerate(sorted(reps.items(), key=lambda kv: (kv[1]["outcome"], kv[0])), start=1):
        text, files, described = materialize(rep, bases)
        d = folder / f"{k:02d}-{rep['outcome']}"
        d.mkdir(parents=True, exist_ok=True)
        (d / "spec.toml").write_bytes(text)
        for name, content in files.items():
            (d / name).parent.mkdir(parents=True, exist_ok=True)
            (d / name).write_bytes(content)
        (d / "README.txt").write_text(f"{sig}\nbase: {rep['base']}\n" + "\n".join(rep.get("mutation", described))
                                      + "\n\n"
                                      + "\n".join(rep.get("detail", [])) + "\n", encoding="utf-8")


def summary_text(records, reps, seconds, workers):
    counts = Counter(r["outcome"] for r in records)
    lines = [f"valvetrain {valvetrain.__version__} from {Path(valvetrain.__file__).parent}",
             f"{len(records)} specifications in {seconds:.0f} s ({workers} workers)", "",
             f"{'class':<12} {'count':>7} {'share':>7}"]
    for o in OUTCOMES:
        lines.append(f"{o:<12} {counts.get(o, 0):>7} {100.0 * counts.get(o, 0) / max(len(records), 1):>6.1f}%")
    lines += ["", "slowest cases:"]
    for r in sorted(records, key=lambda r: -r["seconds"])[:5]:
        lines.append(f"  {r['seconds']:7.1f} s  {r['outcome']:<11} {r['base']}: {'; '.join(r['mutation'])[:120]}")
    groups = Counter(s for r in records if r["outcome"] in FAILURES for s in r["signatures"])
    lines += ["", f"{len(groups)} distinct failure signatures (a case can carry several):"]
    for o in FAILURES:
        for sig, n in sorted(((s, n) for s, n in groups.items() if reps[s]["outcome"] == o), key=lambda x: -x[1]):
            rep = reps[sig]
            lines.append(f"\n[{o}] x{n}  {sig}")
            lines.append(f"    base: {rep['base']}")
            for d in rep["mutation"]:
                lines.append(f"    mutation: {d}")
            for d in rep.get("detail", [])[:3]:
                lines.append(f"    -> {d}")
    return "\n".join(lines)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--count", type=int, default=300, help="mutated specifications (default 300)")
    ap.add_argument("--seed", default="0", help="seed of the mutations (default 0)")
    ap.add_argument("--workers", type=int, default=2, help="worker processes (default 2)")
    ap.add_argument("--timeout", type=float, default=60.0, help="seconds per case before it counts as a hang")
    ap.add_argument("--write", action="store_true", help="also write every output folder (slow: plots, report)")
    ap.add_argument("--no-files", action="store_true", help="skip the malformed-CSV cases")
    ap.add_argument("--no-minimise", action="store_true", help="do not reduce the representative mutations")
    ap.add_argument("--report", help="write the JSON report here")
    ap.add_argument("--repro", help="write each failure signature's minimal specification into this folder")
    args = ap.parse_args(argv)

    bases = base_specs()
    cases = ([] if args.no_files else file_cases(bases)) + random_cases(args.count, args.seed, bases)
    t0 = time.monotonic()
    step = max(len(cases) // 20, 1)

    def progress(done, total, rec):
        if done % step == 0 or done == total:
            print(f"  {done}/{total} ({time.monotonic() - t0:.0f} s)", file=sys.stderr, flush=True)

    print(f"running {len(cases)} cases on {args.workers} workers", file=sys.stderr)
    records = run_cases(cases, args.workers, args.timeout, args.write, progress)
    for case, rec in zip(cases, records, strict=True):
        rec["id"] = case.get("id", "file")
    groups = {}
    for r in records:
        if r["outcome"] in FAILURES:
            for sig in r["signatures"]:
                groups.setdefault(sig, []).append(r)
    log = lambda m: print(m, file=sys.stderr, flush=True)  # noqa: E731
    reps = ({s: min(g, key=lambda r: len(r["ops"])) for s, g in groups.items()} if args.no_minimise
            else minimise(groups, args.workers, args.timeout, args.write, log))
    seconds = time.monotonic() - t0
    print(summary_text(records, reps, seconds, args.workers))
    if args.report:
        report = {
            "command": " ".join(sys.argv), "valvetrain": str(Path(valvetrain.__file__).parent),
            "seconds": round(seconds, 1), "specifications": len(records),
            "counts": {o: sum(r["outcome"] == o for r in records) for o in OUTCOMES},
            "signatures": [{"outcome": reps[s]["outcome"], "signature": s, "count": len(g),
                            "bases": sorted({r["base"] for r in g}), "base": reps[s]["base"],
                            "mutation": reps[s]["mutation"], "detail": reps[s].get("detail", [])}
                           for s, g in sorted(groups.items(), key=lambda kv: (reps[kv[0]]["outcome"], -len(kv[1])))],
            "cases": [{k: r[k] for k in ("id", "base", "mutation", "outcome", "seconds")}
                      | {k: r[k] for k in ("signatures", "detail", "other_warnings") if r.get(k)} for r in records],
        }
        Path(args.report).write_text(json.dumps(report, indent=1, default=str), encoding="utf-8")
    if args.repro:
        write_repro(args.repro, reps, bases)
    return 1 if groups else 0


if __name__ == "__main__":
    sys.exit(main())
