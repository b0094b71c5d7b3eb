"""Reading the files a specification names: measured lift tables and indicator diagrams (CSV).

The one place where the package reads data files.  Every reader returns arrays in the file's
units (degrees, millimetres, MPa, cm3) with the file's errors named by file and line; the
specification's SI view converts them, the physics takes arrays.
"""

import csv
from dataclasses import dataclass
import errno
import io
from pathlib import Path
import re

import numpy as np

from .crank.pressure import MIN_PRESSURE_MPA, PressureFileError
from .errors import InputError
from .locale import NoteText, note

ECHO_CHARS = 40
"""Longest text of a file echoed in a message (a longer row or header is cut)."""


def _short(text):
    """``text`` cut to :data:`ECHO_CHARS` characters (a cut marked with '...')."""
    return text if len(text) <= ECHO_CHARS else text[:ECHO_CHARS] + "..."


def shown_path(path, limit=120) -> str:
    """A file name as shown in a message: whole, or its start and end around '...' when longer than ``limit``."""
    text = str(path)
    return text if len(text) <= limit else f"{text[:40]}...{text[-(limit - 43):]}"


MAX_FILE_CHARACTERS = 50_000_000
"""Most characters read from a file (about 50 MB): a measured lift table of a million rows has about 20 million; a
device that never ends (/dev/zero) or a file of another kind is refused instead of taking the machine's memory."""


def read_text(path) -> str:
    """The UTF-8 text of ``path`` (newlines as text mode reads them), of at most :data:`MAX_FILE_CHARACTERS`.

    Raises
    ------
    OSError
        The file cannot be read, or is longer (``strerror`` says so).
    UnicodeDecodeError
        The file is not UTF-8 text.
    """
    with open(path, encoding="utf-8") as f:
        text = f.read(MAX_FILE_CHARACTERS + 1)
    if len(text) > MAX_FILE_CHARACTERS:
        raise OSError(errno.EFBIG, f"over {MAX_FILE_CHARACTERS:,} characters, more than a specification or a table "
                                   "holds")
    return text


def _text(path, error):
    """The text of a data file (:func:`read_text`) without a leading byte-order mark (a spreadsheet's "CSV UTF-8"
    starts with one), or ``error`` naming the file."""
    try:
        return read_text(path).removeprefix("\ufeff")
    except OSError as exc:
        raise error(NoteText.of("file.unreadable", where=shown_path(path), error=f"{exc.strerror or exc}")) from None
    except UnicodeDecodeError as exc:
        raise error(NoteText.of("file.not_utf8", where=shown_path(path), reason=exc.reason)) from None


def read_columns(path, headers, error) -> tuple[tuple[str, ...], list[tuple[int, ...]]]:
    """Read a CSV file of a header row and rows of finite numbers, as many as the header names; ``#`` lines are
    comments.

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
    (tuple of str, list of tuple)
        The header found and the rows as (line number, value, value, ...).
    """
    path = Path(path)
    text = _text(path, error)
    rows = [(n, r) for n, r in enumerate(csv.reader(text.splitlines()), start=1)
            if r and not r[0].lstrip().startswith("#")]
    if not rows:
        raise error(NoteText.of("file.empty", where=shown_path(path)))
    n0, header = rows[0]
    key = tuple(h.strip() for h in header)
    if key not in headers:
        allowed = " or ".join(repr(",".join(h)) for h in headers)
        raise error(NoteText.of("file.header", where=shown_path(path), line=n0, header=repr(_short(",".join(key))),
                                allowed=allowed))
    out = []
    for n, r in rows[1:]:
        if len(r) != len(key):
            raise error(NoteText.of("file.row_values", where=shown_path(path), line=n, row=repr(_short(",".join(r))),
                                    count=len(r), expected=len(key), header=_short(",".join(key))))
        try:
            values = tuple(float(v) for v in r)
        except ValueError:
            count = {2: "two", 3: "three"}.get(len(key), str(len(key)))
            raise error(NoteText.of("file.not_numbers", where=shown_path(path), line=n, row=repr(_short(",".join(r))),
                                    count=count)) from None
        if not all(np.isfinite(values)):
            raise error(NoteText.of("file.not_finite", where=shown_path(path), line=n))
        out.append((n, *values))
    return key, out


def read_two_columns(path, headers, error) -> tuple[tuple[str, str], list[tuple[int, float, float]]]:
    """Read a CSV file of a header row and rows of two finite numbers (:func:`read_columns` of two-column headers).

    Returns
    -------
    (tuple of str, list of (int, float, float))
        The header found and the rows as (line number, first value, second value).
    """
    return read_columns(path, headers, error)


_PLAIN = re.compile(r"[^\t\n\x20-\x7e]|\"")
"""A character that keeps a file off the fast path: a control character other than tab and newline (a lone
carriage return, a form feed: line breaks of :meth:`str.splitlines`), a non-ASCII character or a quote."""

_SKIPPED_LINE = re.compile(r"^[ \t]*(#|$)", re.MULTILINE)
"""A comment or blank line."""


def read_two_column_arrays(path, headers, error) -> tuple[tuple[str, str], np.ndarray, np.ndarray]:
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


def check_ranges(path, columns, ranges, line_of, error) -> None:
    """Refuse the first value of a file outside its column's range, naming the file, the line, the value and the range.

    Parameters
    ----------
    path : str or Path
        The file (for the message).
    columns : dict
        Column name -> array of its values, in the file's order.
    ranges : dict
        Column name -> ``(low, high, why)``: the closed range of the values and what it is (a code of ``[notes]``).
    line_of : callable
        ``line_of(i)``: the line of the file of the i-th value.
    error : type
        Exception class raised.
    """
    for name, (low, high, why) in ranges.items():
        values = columns[name]
        bad = np.flatnonzero((values < low) | (values > high))
        if bad.size:
            i = int(bad[0])
            raise error(NoteText.of("file.out_of_range", where=shown_path(path), line=line_of(i), name=name,
                                    value=values[i], low=low, high=high, why=note(why)))


LIFT_TABLE_RANGES = {
    "angle_deg": (-3600.0, 3600.0, "file.table_angles"),
    "lift_mm": (-500.0, 500.0, "file.table_lifts"),
}
"""The values a lift table may hold at all: beyond them a value is a unit slip or a corrupt file, refused before
any fit.  The fit's checks (:func:`valvetrain.laws.measured.lobe_table`) then hold the table to one camshaft
revolution and its rows below the base circle to the measurement noise, with messages of their own."""

MAX_TABLE_ROWS = 1_000_000
"""Most rows of a lift table (10^6: a row every 0.0007 crank deg over a whole revolution)."""


class TableFileError(InputError):
    """A lift-table file that cannot be used; the message names the file and the line."""


def read_lift_table(path) -> tuple[np.ndarray, np.ndarray]:
    """Read a CSV lift table with the header ``angle_deg,lift_mm``; ``#`` lines are comments.

    Returns
    -------
    (ndarray, ndarray)
        Angles [deg] (strictly increasing) and lifts [mm], as in the file.

    Raises
    ------
    TableFileError
        Naming the file and line of the first problem; also for more than :data:`MAX_TABLE_ROWS` rows.
    """
    _, angles, lifts = read_two_column_arrays(path, [("angle_deg", "lift_mm")], TableFileError)
    check_ranges(path, {"angle_deg": angles, "lift_mm": lifts}, LIFT_TABLE_RANGES,
                 lambda i: read_two_columns(path, [("angle_deg", "lift_mm")], TableFileError)[1][i][0], TableFileError)
    back = np.flatnonzero(np.diff(angles) <= 0.0)
    if back.size:
        i = int(back[0]) + 1
        line = read_two_columns(path, [("angle_deg", "lift_mm")], TableFileError)[1][i][0]
        raise TableFileError(NoteText.of("file.increasing", where=shown_path(path), line=line, name="angle_deg",
                                         value=angles[i], previous=angles[i - 1]))
    if angles.size < 10:
        raise TableFileError(NoteText.of("file.few_lift_rows", where=shown_path(path), rows=angles.size))
    if angles.size > MAX_TABLE_ROWS:
        raise TableFileError(NoteText.of("file.many_rows", where=shown_path(path), rows=angles.size,
                                         most=MAX_TABLE_ROWS))
    return angles, lifts


@dataclass(frozen=True)
class IndicatorTable:
    """A read indicator diagram: either ``angle`` [rad] or ``volume`` [m^3] against ``pressure`` [Pa]."""

    kind: str                  # "angle" or "volume"
    x: np.ndarray
    pressure: np.ndarray
    source: str


_HEADERS = {("crank_deg", "pressure_MPa"): "angle", ("volume_cm3", "pressure_MPa"): "volume"}

MAX_PRESSURE_MPA = 100.0
"""Largest absolute pressure of an indicator diagram [MPa]: over three times the highest peak firing pressures of
engines (about 30 MPa in the heavy-duty diesels of the 2010s); a larger value is a unit slip (kPa, bar read as MPa)
or a corrupt file."""

MAX_VOLUME_CM3 = 1e8
"""Largest cylinder volume of a p-V diagram [cm3]: eight times the largest swept volume the specification admits
(bore 2000 mm x stroke 4000 mm: 1.26e7 cm3)."""


def read_indicator(path, strokes) -> IndicatorTable:
    """Read an indicator diagram from a CSV file.

    The header is ``crank_deg,pressure_MPa`` (absolute pressure against the cycle angle,
    0...720 for a four-stroke with the firing TDC at 360; rows increasing, not
    necessarily evenly spaced) or ``volume_cm3,pressure_MPa`` (a p-V diagram, rows in the
    order of the cycle from its first TDC, one monotone branch of volume per stroke).
    Lines starting with ``#`` are comments.

    Raises
    ------
    PressureFileError
        With the file name and line number of the first problem.
    """
    where = shown_path(path)
    key, rows = read_two_columns(path, list(_HEADERS), PressureFileError)
    kind = _HEADERS[key]
    xs, ps = [], []
    for n, x, p in rows:
        if kind == "angle":
            if not 0.0 <= x <= 180.0 * strokes:
                raise PressureFileError(NoteText.of("file.cycle_angle", where=where, line=n, value=x,
                                                    most=180 * strokes, strokes=strokes))
            if xs and x <= xs[-1]:
                raise PressureFileError(NoteText.of("file.increasing", where=where, line=n, name="crank_deg", value=x,
                                                    previous=xs[-1]))
        elif x <= 0.0:
            raise PressureFileError(NoteText.of("file.volume", where=where, line=n, value=x))
        xs.append(x)
        ps.append(p)
    check_ranges(path, {"pressure_MPa": np.array(ps), "volume_cm3": np.array(xs)},
                 {"pressure_MPa": (MIN_PRESSURE_MPA, MAX_PRESSURE_MPA, "file.absolute_pressure"),
                  **({"volume_cm3": (0.0, MAX_VOLUME_CM3, "file.cylinder_volume")} if kind == "volume" else {})},
                 lambda i: rows[i][0], PressureFileError)
    if len(xs) < 4:
        raise PressureFileError(NoteText.of("file.few_data_rows", where=where, rows=len(xs)))
    x = np.radians(xs) if kind == "angle" else np.array(xs) * 1e-6
    return IndicatorTable(kind, np.asarray(x), np.array(ps) * 1e6, where)


class BreathingFileError(InputError):
    """A valve-lift or discharge-coefficient file of ``[breathing]`` that cannot be used; ``key`` is the key that
    names it (``lift_file``, ``cd_file``), the message names the file and the line."""

    def __init__(self, key, message):
        super().__init__(message, key=key)


VALVE_LIFT_RANGES = {
    "crank_deg": (-1440.0, 1440.0, "file.lift_angles"),
    "lift_mm": (0.0, 200.0, "file.valve_lifts"),
}
"""The values a measured valve lift may hold."""


def read_valve_lift(path) -> tuple[np.ndarray, np.ndarray]:
    """Read a measured valve lift: CSV with the header ``crank_deg,lift_mm`` (crank degrees from the gas-exchange
    TDC, strictly increasing, spanning less than a cycle; the valve shut outside the rows).

    Returns
    -------
    (ndarray, ndarray)
        Crank angles [deg] and lifts [mm], as in the file.

    Raises
    ------
    BreathingFileError
        Naming the file and line of the first problem (key ``lift_file``).
    """
    def error(text):
        return BreathingFileError("lift_file", text)

    _, rows = read_columns(path, [("crank_deg", "lift_mm")], error)
    lines = [r[0] for r in rows]
    angles, lifts = (np.array([r[k] for r in rows], dtype=float) for k in (1, 2))
    check_ranges(path, {"crank_deg": angles, "lift_mm": lifts}, VALVE_LIFT_RANGES, lambda i: lines[i], error)
    back = np.flatnonzero(np.diff(angles) <= 0.0)
    if back.size:
        i = int(back[0]) + 1
        raise error(NoteText.of("file.increasing", where=shown_path(path), line=lines[i], name="crank_deg",
                                value=angles[i], previous=angles[i - 1]))
    if angles.size < 4:
        raise error(NoteText.of("file.few_rows", where=shown_path(path), rows=angles.size))
    if angles[-1] - angles[0] >= 720.0:
        raise error(NoteText.of("file.span", where=shown_path(path), span=angles[-1] - angles[0]))
    return angles, lifts


def read_cd_table(path) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Read a discharge-coefficient table: CSV with the header ``l_over_d,cd_forward,cd_reverse`` (or ``l_over_d,cd``,
    the same both ways); L/D strictly increasing, every C_D within 0...1.

    Returns
    -------
    (ndarray, ndarray, ndarray)
        L/D, forward and reverse C_D.

    Raises
    ------
    BreathingFileError
        Naming the file and line of the first problem (key ``cd_file``): a table that is not a function of L/D, a
        coefficient outside 0...1.
    """
    from .breathing.valves import CdTableError, check_table

    def error(text):
        return BreathingFileError("cd_file", text)

    key, rows = read_columns(path, [("l_over_d", "cd_forward", "cd_reverse"), ("l_over_d", "cd")], error)
    x = np.array([r[1] for r in rows], dtype=float)
    forward = np.array([r[2] for r in rows], dtype=float)
    reverse = np.array([r[-1] for r in rows], dtype=float)
    try:
        check_table(x, forward, reverse, "port", shown_path(path))
    except CdTableError as exc:
        raise error(exc.args[0]) from None
    return x, forward, reverse
