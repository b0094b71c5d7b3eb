"""The factor tables of the Power units manual (n.d.) (tables 1.1-1.3 and 2.3-2.6, as printed), read from
tests/data/seed001_factor_tables.csv for the crank tests."""

import csv
from pathlib import Path

import numpy as np

TABLES = Path(__file__).parent / "data" / "seed001_factor_tables.csv"


def table(name):
    """Table ``name`` ("1.1"...): crank angles [rad], lambda, the printed values and the values with their sign."""
    with open(TABLES, newline="") as fh:
        rows = [r for r in csv.reader(line for line in fh if not line.startswith("#"))][1:]
    out = [(float(r[1]), float(r[2]), float(r[3]), r[4]) for r in rows if r[0] == name]
    phi, lam, val, sign = (np.array(c) for c in zip(*out))
    signed = np.where(sign == "-", -val, val)
    return np.radians(phi), lam, val, signed
