"""Reading two-column numeric CSV files with errors that name the file and the line."""

import csv
from pathlib import Path

import numpy as np


def read_two_columns(path, headers, error):
    """Read a CSV file of a header row and rows of two finite numbers; ``#`` lines are comments.

    Parameters
    ----------
    path : str or Path
        The file.
    headers : sequence of tuple of str
        Accepted headers, e.g. ``[("crank_deg", "pressure_MPa")]``.
    error : type
        Exception class raised with ``"FILE:LINE: message"``.

    Returns
    -------
    (tuple of str, list of (int, float, float))
        The header found and the rows as (line number, first value, second value).
    """
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise error(f"{path}: cannot read the file: {exc}") from None
    rows = [(n, r) for n, r in enumerate(csv.reader(text.splitlines()), start=1)
            if r and not r[0].lstrip().startswith("#")]
    if not rows:
        raise error(f"{path}: the file is empty")
    n0, header = rows[0]
    key = tuple(h.strip() for h in header)
    if key not in headers:
        allowed = " or ".join(repr(",".join(h)) for h in headers)
        raise error(f"{path}:{n0}: header {','.join(key)!r}: allowed {allowed}")
    out = []
    for n, r in rows[1:]:
        if len(r) != 2:
            raise error(f"{path}:{n}: expected 2 values, found {len(r)}")
        try:
            x, y = float(r[0]), float(r[1])
        except ValueError:
            raise error(f"{path}:{n}: {','.join(r)!r} is not two numbers") from None
        if not (np.isfinite(x) and np.isfinite(y)):
            raise error(f"{path}:{n}: values must be finite")
        out.append((n, x, y))
    return key, out
