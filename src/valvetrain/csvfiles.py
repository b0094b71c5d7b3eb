"""Reading two-column numeric CSV files with errors that name the file and the line."""

import csv
import io
from pathlib import Path
import re

import numpy as np

ECHO_CHARS = 40
"""Longest text of a file echoed in a message (a longer row or header is cut)."""


def _short(text):
    """``text`` cut to :data:`ECHO_CHARS` characters (a cut marked with '...')."""
    return text if len(text) <= ECHO_CHARS else text[:ECHO_CHARS] + "..."


def _text(path, error):
    try:
        return Path(path).read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise error(f"{path}: cannot read the file: {exc}") from None


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
    text = _text(path, error)
    rows = [(n, r) for n, r in enumerate(csv.reader(text.splitlines()), start=1)
            if r and not r[0].lstrip().startswith("#")]
    if not rows:
        raise error(f"{path}: the file is empty")
    n0, header = rows[0]
    key = tuple(h.strip() for h in header)
    if key not in headers:
        allowed = " or ".join(repr(",".join(h)) for h in headers)
        raise error(f"{path}:{n0}: header {_short(','.join(key))!r}: allowed {allowed}")
    out = []
    for n, r in rows[1:]:
        if len(r) != 2:
            raise error(f"{path}:{n}: expected 2 values, found {len(r)}")
        try:
            x, y = float(r[0]), float(r[1])
        except ValueError:
            raise error(f"{path}:{n}: {_short(','.join(r))!r} is not two numbers") from None
        if not (np.isfinite(x) and np.isfinite(y)):
            raise error(f"{path}:{n}: values must be finite")
        out.append((n, x, y))
    return key, out


_PLAIN = re.compile(r"[^\t\n\x20-\x7e]|\"")
"""A character that keeps a file off the fast path: a control character other than tab and newline (a lone
carriage return, a form feed: line breaks of :meth:`str.splitlines`), a non-ASCII character or a quote."""

_SKIPPED_LINE = re.compile(r"^[ \t]*(#|$)", re.MULTILINE)
"""A comment or blank line."""


def read_two_column_arrays(path, headers, error):
    """Read a file like :func:`read_two_columns`, returning the header and the two columns as arrays.

    A plain file (ASCII, no quotes, no comment or blank line after the header) is parsed by one call of
    :func:`numpy.loadtxt`: a table of 10^6 rows in a fraction of a second.  Any other file, and any file that
    call does not parse as two finite numbers a row, is read by :func:`read_two_columns`, whose messages name
    the line; both paths accept the same files and give the same numbers.

    Returns
    -------
    (tuple of str, ndarray, ndarray)
        The header found and the first and second values of the rows.
    """
    text = _text(path, error).replace("\r\n", "\n")
    head = re.search(r"^(?![ \t]*#).+$", text, re.MULTILINE)
    if head is not None and not _PLAIN.search(text):
        key = tuple(h.strip() for h in head.group().split(","))
        body = text[head.end():].strip("\n")
        if key in headers and body and not _SKIPPED_LINE.search(body):
            try:
                data = np.loadtxt(io.StringIO(body), delimiter=",", comments=None, ndmin=2)
            except ValueError:
                data = None
            if data is not None and data.shape[1] == 2 and np.all(np.isfinite(data)):
                return key, data[:, 0], data[:, 1]
    key, rows = read_two_columns(path, headers, error)
    values = np.array([(x, y) for _, x, y in rows], dtype=float).reshape(-1, 2)
    return key, values[:, 0], values[:, 1]
