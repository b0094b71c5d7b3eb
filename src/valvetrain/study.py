"""Design studies (``valvetrain study``): a grid of specification keys, one design per point, one table of results.

A grid is a list of ``(key, values)``: a dotted key of the specification file (``engine.rated_speed_rpm``,
``valves.intake.cam.shape_factor``) and the values it takes.  The points are the cartesian product of the values,
the first key varying slowest.  Each point is the file's TOML document with its keys replaced, validated like a
specification file and designed like ``valvetrain run``; :func:`evaluate_point` does it and is a pure function
(document in, record out), so the points can be evaluated in any order, in this process, in local processes or on a
Dask distributed cluster (:func:`evaluate`), and the tables are the same.

A key that the specification does not know, and a value that the key refuses whatever the other keys are (a wrong
type, a value outside the key's physical bounds), are errors of the grid (:class:`GridError`), found before any
point is computed.  A point that the specification or the design refuses in combination (angles that do not add up,
no spring that fits) is a row of the table with the refusal messages.

This module is part of the orchestration: it imports :mod:`valvetrain.design` and :mod:`valvetrain.specification`,
and only the command line imports it.
"""

from collections.abc import Iterator
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
import ctypes
import functools
import itertools
import math
import multiprocessing
import os
from pathlib import Path
import re
import time
import tomllib
from typing import Any

import pydantic
import tomli_w

from .design import run
from .errors import InputError, ValvetrainError
from .files import read_text, shown_path
from .interruption import Interruption
from .specification import LAWS, SpecError, set_keys, toml_tables, validate
from .specification.messages import location, message
from .specification.models import Spec
from .units import rpm_to_rad_s

VALVE_COLUMNS = [
    ("time_area_mm2_s", "time-area over the stroke, mm2 s"),
    ("fullness", "fullness"),
    ("max_acceleration_m_s2", "max tappet acceleration, m/s2"),
    ("min_acceleration_m_s2", "min tappet acceleration, m/s2"),
    ("rho_min_mm", "min radius of curvature, mm"),
    ("max_contact_stress_MPa", "max cam contact stress, MPa"),
    ("spring_wire_mm", "spring wire diameter, mm"),
    ("spring_preload_N", "spring preload, N"),
    ("spring_passes", "the spring passes all its checks"),
    ("jump_speed_rpm", "jump speed, engine rpm (empty: none in the swept range, or no [dynamics] section)"),
]
"""Columns of each valve of a point (``VALVE.KEY``), with their meanings."""

POINT_COLUMNS = [
    ("status", "'ok', 'refused' (the point is not a valid design; see message), 'failed' (the design stopped with "
               "an error of valvetrain, named in message), or 'not designed' (the study stopped before it)"),
    ("failures", "failed checks of severity failure (not counting those accepted in the file)"),
    ("warnings", "failed checks of severity warning"),
    ("message", "why the point was refused, one problem per line"),
]
"""Columns of every point after the grid values and the valves' columns, with their meanings."""


CONNECT_SECONDS = 20
"""How long :func:`evaluate` tries to reach a Dask scheduler."""


class GridError(InputError):
    """A grid that cannot be studied; the message is one line naming the key or the value."""


def split_values(text) -> list[str]:
    """The values of ``V1,V2,...``: split at the commas outside brackets, braces and quotes, so that a TOML array or
    inline table is one value (``["VDSiCr", "60S2A"],"60S2A"`` is two values)."""
    parts, depth, quote, start = [], 0, None, 0
    for i, ch in enumerate(text):
        if quote:
            quote = None if ch == quote and text[i - 1] != "\\" else quote
        elif ch in "\"'":
            quote = ch
        elif ch in "[{":
            depth += 1
        elif ch in "]}":
            depth = max(depth - 1, 0)
        elif ch == "," and depth == 0:
            parts.append(text[start:i])
            start = i + 1
    return [*parts, text[start:]]


def toml_text(value) -> str:
    """A value as TOML text, an array or inline table on one line: how a grid value is written in study.csv.

    >>> toml_text(["VDSiCr", "60S2A"]), toml_text({"a": 1, "b c": [0.5, True]}), toml_text(6000)
    ('["VDSiCr", "60S2A"]', '{ a = 1, "b c" = [0.5, true] }', '6000')
    """
    if isinstance(value, list):
        return "[" + ", ".join(toml_text(v) for v in value) + "]"
    if isinstance(value, dict):
        return "{ " + ", ".join(f"{k if _BARE_KEY.match(k) else toml_text(k)} = {toml_text(v)}"
                                for k, v in value.items()) + " }"
    return tomli_w.dumps({"v": value}).removeprefix("v = ").rstrip("\n")


_BARE_KEY = re.compile(r"^[A-Za-z0-9_-]+$")
"""A TOML key written without quotes."""


def parse_value(text) -> Any:
    """A grid value: a TOML value (``6000``, ``0.5``, ``true``, ``"kurz"``), or else the text itself as a string."""
    try:
        return tomllib.loads(f"v = {text}")["v"]
    except (tomllib.TOMLDecodeError, RecursionError):    # the text (nested deeper than the parser goes)
        return text


def parse_grid(items) -> list[tuple[str, list[Any]]]:
    """Parse ``KEY=V1,V2,...`` items (the ``--grid`` options) into ``[(key, [values])]``.

    Parameters
    ----------
    items : iterable of str

    Returns
    -------
    list of (str, list)

    Raises
    ------
    GridError
        An item without ``=``, an empty key or value, a key given twice.
    """
    grid = []
    for item in items:
        key, sep, values = item.partition("=")
        key = key.strip()
        if not sep or not key:
            raise GridError(f"--grid {item!r}: expected KEY=V1,V2,... with a dotted key of the specification "
                            "(engine.rated_speed_rpm=6000,7000)")
        if any(not part.strip() for part in key.split(".")):
            raise GridError(f"--grid {key}: an empty name in the dotted key")
        texts = [t.strip() for t in split_values(values)]
        if any(not t for t in texts):
            raise GridError(f"--grid {key}={values}: an empty value; give V1,V2,... separated by single commas")
        if key in (k for k, _ in grid):
            raise GridError(f"--grid {key}: given twice; give all its values in one --grid")
        grid.append((key, [parse_value(t) for t in texts]))
    return grid


def read_document(path) -> dict[str, Any]:
    """The TOML document of a specification file as :func:`valvetrain.specification.load_spec` reads it (which has
    validated it), with ``source_dir`` set to its folder for the files it names."""
    return {**toml_tables(read_text(path), shown_path(path)), "source_dir": str(Path(path).resolve().parent)}


def with_values(document, values) -> dict[str, Any]:
    """The TOML ``document`` with the dotted keys of ``values`` (a dict) set
    (:func:`valvetrain.specification.set_keys`, which :meth:`Spec.replace` uses too).

    Raises
    ------
    GridError
        A valve the document does not have, a key through a value or naming a table.
    """
    try:
        return set_keys(document, values)
    except ValueError as exc:
        raise GridError(f"--grid {exc}") from None


def check_grid(document, grid) -> None:
    """Refuse a grid whose keys the specification does not know or whose values a key refuses on its own.

    Each value is set alone in the ``document`` and the document's fields are validated; a problem located at the
    key is the grid's (cross-checks between keys are left to the points).

    Raises
    ------
    GridError
    """
    for key, values in grid:
        for value in values:
            try:
                Spec.model_validate(with_values(document, {key: value}))
            except pydantic.ValidationError as exc:
                for err in exc.errors():
                    if location(err, LAWS) == key:
                        raise GridError(f"--grid {message(err, LAWS)}") from None


def count_points(grid) -> int:
    """The number of design points of a grid (the product of its numbers of values), without making them."""
    return math.prod(len(values) for _, values in grid)


def points(grid) -> Iterator[dict[str, Any]]:
    """The design points of a grid, made one at a time: dicts ``key -> value``, the cartesian product, the first key
    varying slowest."""
    keys = [k for k, _ in grid]
    return (dict(zip(keys, combo, strict=True)) for combo in itertools.product(*(v for _, v in grid)))


def point_text(point) -> str:
    """A point as shown in a message: ``key = value, ...`` (values as TOML text)."""
    return ", ".join(f"{key} = {toml_text(value)}" for key, value in point.items())


def _valve_record(v):
    s = v.summary
    stress = s["strength"]["checks"].get("cam_contact_stress")
    spring = s["spring"]
    return {
        "time_area_mm2_s": s["flow"]["time_area_mm2_s"],
        "fullness": s["flow"]["fullness"],
        "max_acceleration_m_s2": s["cam"]["max_acceleration_m_s2"],
        "min_acceleration_m_s2": s["cam"]["min_acceleration_m_s2"],
        "rho_min_mm": s["cam"]["rho_min_mm"],
        "max_contact_stress_MPa": stress["value"] if stress else None,
        "spring_wire_mm": spring.get("wire_mm"),
        "spring_preload_N": spring["preload_N"],
        "spring_passes": spring.get("passes_all_checks"),
        "jump_speed_rpm": None if v.dynamics is None else _rpm(v.dynamics.jump_speed),
    }


def _rpm(speed):
    return None if speed != speed else speed / rpm_to_rad_s(1.0)


def evaluate_point(document) -> dict[str, Any]:
    """Validate and design one point; the record of its figures, or of its refusal.

    Parameters
    ----------
    document : dict
        A specification as a parsed TOML document (with ``source_dir`` where it names files).

    Returns
    -------
    dict
        ``status`` ('ok', 'refused' or 'failed': the design stopped with an error, :func:`failure_text`),
        ``valves`` (name -> the figures of :data:`VALVE_COLUMNS`), ``failures`` and ``warnings`` (counts of the
        failed checks not accepted in the file), ``message`` (the refusal's problems, one a line, or the error;
        empty for a design).
    """
    try:
        results = run(validate(document))
    except SpecError as err:
        return {"status": "refused", "valves": {}, "failures": None, "warnings": None,
                "message": "\n".join(err.problems)}
    except Exception as exc:  # noqa: BLE001 - one point that cannot be designed must not stop the study
        return {"status": "failed", "valves": {}, "failures": None, "warnings": None, "message": failure_text(exc)}
    severities = [w.severity for w in results.warnings]
    return {"status": "ok", "valves": {name: _valve_record(v) for name, v in results.valves.items()},
            "failures": severities.count("failure"), "warnings": severities.count("warning"), "message": ""}


def failure_text(exc) -> str:
    """The message of a point (or sample) whose design stopped with an error of valvetrain, not a refusal of its
    specification: the point is recorded as failed, the study goes on.  An interruption (Ctrl-C) that a library
    made into an error is raised again (:class:`valvetrain.interruption.Interruption`)."""
    if Interruption.seen:
        raise exc
    return (f"the design stopped with an error of valvetrain, not a refusal of the file ({type(exc).__name__}: "
            f"{str(exc)[:200]}); please report it with the file")


class StudyStopped(ValvetrainError, RuntimeError):
    """A study that could not design every point (a worker process died); ``records`` holds the points designed
    before (None for the others), ``lost`` the indices of the points that were in progress or waiting (given to a
    process or a task, not designed)."""

    def __init__(self, message, records, lost):
        super().__init__(message)
        self.records, self.lost = records, lost


MAX_SECONDS = 3600.0
"""Longest estimated time of a study (or a tolerance study) that runs without ``--max-points`` (``--max-samples``):
an hour."""


def duration(seconds) -> str:
    """A duration in the unit that reads best: seconds, minutes, hours or days.

    >>> duration(30.0), duration(7200.0), duration(3e6)
    ('30 s', '2 hours', '34.7 days')
    """
    for unit, size in (("days", 86400.0), ("hours", 3600.0), ("minutes", 60.0)):
        if seconds >= 2.0 * size:
            return f"{seconds / size:.3g} {unit}"
    return f"{seconds:.2g} s"


def _timed(point, document) -> float:
    """Seconds of one design of ``document`` by ``point``."""
    start = time.monotonic()
    point(document)
    return time.monotonic() - start


def too_large(total, allowed, document, processes, what, option, point=None) -> str | None:
    """Why a study of ``total`` designs in ``processes`` processes is refused, or None: with ``allowed`` (the value of
    ``option``, ``--max-points`` or ``--max-samples``) where ``total`` is more; without it where the estimate of its
    time is over :data:`MAX_SECONDS`.  ``what`` names the designs (``design points``).

    The estimate is ``total`` times the time of a design of ``document`` by ``point`` (default
    :func:`evaluate_point`) over ``processes``.  The first design of a process also loads what designs need (the
    imports, the compiled kernels) and takes longer: where its time gives more than the limit, or the count is over
    ``allowed``, a second design is timed and gives the estimate.  A count within ``allowed`` is not timed."""
    if allowed is not None and total <= allowed:
        return None
    point = point or evaluate_point
    if _timed(point, document) * total / processes <= MAX_SECONDS and allowed is None:
        return None
    each = _timed(point, document)
    seconds = each * total / processes
    if allowed is None and seconds <= MAX_SECONDS:
        return None
    estimate = (f"{total:,} {what}: about {duration(seconds)} in {processes} process{'es' if processes > 1 else ''} "
                f"at the {each:.2g} s that a design of the file takes")
    if allowed is None:
        return f"{estimate}, over the {duration(MAX_SECONDS)} a study may take unless {option} {total} is given"
    return f"{estimate}; {option} {allowed} allows at most {allowed:,} {what.split()[-1]}; give {option} {total}"


DASK_TASKS_PER_THREAD = 8
"""Tasks of a Dask study per worker thread: enough to even out the load, few enough that the scheduler's own
3-6 ms a task stays a small part of the work."""

DASK_MAX_CHUNK = 32
"""Most points in one Dask task."""

POINTS_PER_PROCESS = 2
"""Points given to each local worker process at a time (``--workers``): one designed, one waiting, so that a process
that ends a point starts the next at once instead of waiting for this process to take its record and send another
(600 tolerance samples of the built-in example, 37 ms each, with two processes on two cores: 14.2 against 15.0-15.5 s
with one point each)."""


MMAP_THRESHOLD_BYTES = 32 * 2**20
"""glibc's mmap threshold set in a Dask worker (its largest value on 64-bit systems, 32 MiB): see :func:`heap_arrays`."""


@functools.cache
def heap_arrays() -> None:
    """Let glibc serve arrays below :data:`MMAP_THRESHOLD_BYTES` from the heap again, in a process whose environment
    sets ``MALLOC_TRIM_THRESHOLD_`` (a Dask nanny starts its workers so); once per process.

    Setting that variable also stops glibc from raising its mmap threshold as arrays are freed (its "dynamic"
    threshold), so every array above 128 KiB is mapped and unmapped afresh, its pages zeroed on first touch: a
    design then takes about 1.5 times the CPU time of a plain process (measured: 57 against 38 ms for the built-in
    example).  ``mallopt(M_MMAP_THRESHOLD, ...)`` restores the threshold; the trimming the variable asks for stays.
    Elsewhere (no such variable, no glibc) nothing is done."""
    if "MALLOC_TRIM_THRESHOLD_" in os.environ:
        set_malloc(mmap_threshold=MMAP_THRESHOLD_BYTES)


def set_malloc(mmap_threshold, trim_threshold=None) -> None:
    """glibc's ``mallopt``: arrays up to ``mmap_threshold`` [bytes] from the heap, and up to ``trim_threshold``
    [bytes] of freed memory kept at its top (None: left as it is).  Without glibc nothing is done."""
    try:
        libc = ctypes.CDLL("libc.so.6")
    except OSError:
        return
    m_trim_threshold, m_mmap_threshold = -1, -3   # glibc's malloc.h
    libc.mallopt(m_mmap_threshold, mmap_threshold)
    if trim_threshold is not None:
        libc.mallopt(m_trim_threshold, trim_threshold)


def evaluate_points(documents, point=None) -> list[dict[str, Any]]:
    """``point`` (:func:`evaluate_point`) of each document of a list (one Dask task, :func:`heap_arrays` first): the
    list of records."""
    heap_arrays()
    return [(point or evaluate_point)(d) for d in documents]


def dask_chunk(total, threads) -> int:
    """Points per Dask task: :data:`DASK_TASKS_PER_THREAD` tasks per worker thread, at most :data:`DASK_MAX_CHUNK`."""
    return max(1, min(DASK_MAX_CHUNK, math.ceil(total / (DASK_TASKS_PER_THREAD * max(threads, 1)))))


def evaluate(documents, total, workers=None, scheduler=None, progress=None, describe=str, point=None,
             keep=None) -> list[dict[str, Any]]:
    """Evaluate documents with :func:`evaluate_point`: serially, in local processes, or on a Dask cluster.

    The documents are taken from the iterable as they are needed (a few per worker at a time), so a large study
    never holds them all.

    Parameters
    ----------
    documents : iterable of dict
    total : int
        The number of documents.
    workers : int, optional
        Local processes (:class:`concurrent.futures.ProcessPoolExecutor`, started with ``spawn``),
        :data:`POINTS_PER_PROCESS` points each at a time; None or 1: this process.
    scheduler : str, optional
        Address of a running Dask distributed scheduler (``tcp://host:8786``); needs the ``dask`` extra.  The points
        go in tasks of :func:`dask_chunk` points.
    progress : callable, optional
        ``progress(done, total)`` after each point or task (and ``progress(0, total)`` first).
    describe : callable, optional
        ``describe(index)``: a point as a message names it.
    point : callable, optional
        The pure function document -> record (default :func:`evaluate_point`) (a module-level function, so that processes can be given it):
        :func:`evaluate_point`, or another record of the design (:func:`valvetrain.tolerance.evaluate_sample`).
    keep : callable, optional
        ``keep(index, record)`` as each record arrives (to write it at once, so that an interrupted run keeps it).

    Returns
    -------
    list of dict
        The records, in the order of ``documents`` whatever the order they were computed in.

    Raises
    ------
    ImportError
        ``scheduler`` without dask's distributed package installed.
    ConnectionError
        No Dask scheduler answers at ``scheduler`` within :data:`CONNECT_SECONDS`.
    StudyStopped
        A worker process died (killed, out of memory); the records designed before it are kept.
    """
    point = point or evaluate_point   # looked up at the call, so that a test can replace it
    records = _Records(total, keep)
    tick = progress or (lambda done, total: None)
    tick(0, total)
    if scheduler is not None:
        _on_dask(enumerate(documents), total, scheduler, records, tick, describe, point)
    elif workers and workers > 1:
        _in_processes(enumerate(documents), workers, records, tick, describe, point)
    else:
        for i, d in enumerate(documents):
            records[i] = point(d)
            tick(i + 1, total)
    return list(records)


class _Records(list):
    """The records of a study, None until designed; ``keep(index, record)`` is told of each as it is set."""

    def __init__(self, total, keep):
        super().__init__([None] * total)
        self.keep = keep

    def __setitem__(self, index, record):
        super().__setitem__(index, record)
        if self.keep is not None:
            self.keep(index, record)


def _stopped(records, lost, describe, why):
    """The :class:`StudyStopped` of a study whose points ``lost`` (indices) were in progress or waiting when ``why``
    happened."""
    shown = "; ".join(f"point {i + 1} ({describe(i)})" for i in lost[:3]) + (
        f" and {len(lost) - 3} more" if len(lost) > 3 else "")
    done = sum(r is not None for r in records)
    return StudyStopped(f"{why} with {'these points' if len(lost) > 1 else 'this point'} in progress or waiting: "
                        f"{shown}; the study stopped with {done} of {len(records)} points designed", records, lost)


def _in_processes(numbered, workers, records, tick, describe, point):
    """Local processes, each with :data:`POINTS_PER_PROCESS` points at a time: when one dies, the points in progress
    or waiting are known (not designed, named in the error)."""
    # fresh interpreters: a fork of a process whose compiled kernels run OpenMP threads is unsafe
    with ProcessPoolExecutor(workers, mp_context=multiprocessing.get_context("spawn")) as pool:
        running, done, why = {}, 0, "a worker process died (killed, or out of memory)"
        while True:
            for i, d in itertools.islice(numbered, POINTS_PER_PROCESS * workers - len(running)):
                try:
                    running[pool.submit(point, d)] = i
                except BrokenProcessPool:   # a process died since the last wait: this point is not designed either
                    raise _stopped(records, sorted([*running.values(), i]), describe, why) from None
            if not running:
                return
            finished, _ = wait(running, return_when=FIRST_COMPLETED)
            for future in sorted(finished, key=lambda f: isinstance(f.exception(), BrokenProcessPool)):
                if isinstance(future.exception(), BrokenProcessPool):
                    raise _stopped(records, sorted(running.values()), describe, why)
                records[running.pop(future)] = future.result()
                done += 1
            tick(done, len(records))


def _on_dask(numbered, total, scheduler, records, tick, describe, point):
    """A Dask cluster: tasks of :func:`dask_chunk` points, two tasks per worker thread submitted at a time."""
    try:
        from distributed import Client, KilledWorker, as_completed as dask_completed
    except ImportError:
        raise ImportError("--scheduler needs Dask's distributed package: pip install 'valvetrain[dask]'") from None
    try:
        client = Client(scheduler, timeout=CONNECT_SECONDS)
    except (OSError, ValueError, TypeError) as exc:
        raise ConnectionError(f"--scheduler {scheduler}: cannot connect to a Dask scheduler there ({exc})") from None
    with client:
        threads = max(sum(client.nthreads().values()), 1)
        size = dask_chunk(total, threads)
        chunks = iter(lambda: list(itertools.islice(numbered, size)), [])
        indices, queue, done = {}, dask_completed(), 0

        def submit():
            for chunk in itertools.islice(chunks, 1):
                future = client.submit(evaluate_points, [d for _, d in chunk], point, pure=False)
                indices[future] = [i for i, _ in chunk]
                queue.add(future)

        for _ in range(2 * threads):
            submit()
        for future in queue:
            lost = indices.pop(future)
            try:
                results = future.result()
            except KilledWorker:
                raise _stopped(records, lost, describe, "a Dask worker died (killed, or out of memory)") from None
            for i, record in zip(lost, results, strict=True):
                records[i] = record
            done += len(lost)
            tick(done, total)
            submit()


NOT_DESIGNED = {"status": "not designed", "valves": {}, "failures": None, "warnings": None,
                "message": "the study stopped before this point was designed"}
"""The record of a point that a stopped study did not design."""


def table(grid, records) -> dict[str, list[Any]]:
    """The study's rows: the grid values, the valves' figures (``VALVE.KEY``) and the point columns.

    A grid value that is a TOML array or inline table is its TOML text (:func:`toml_text`); a record that is None
    (a point that a stopped study did not design) is :data:`NOT_DESIGNED`.

    Returns
    -------
    dict
        Column name -> list of values (None for an empty cell), in the order of the points.
    """
    records = [NOT_DESIGNED if r is None else r for r in records]
    columns = {key: [] for key, _ in grid}
    for point in points(grid):
        for key, value in point.items():
            columns[key].append(toml_text(value) if isinstance(value, (list, dict)) else value)
    valves = list(dict.fromkeys(name for r in records for name in r["valves"]))
    for name in valves:
        for key, _ in VALVE_COLUMNS:
            columns[f"{name}.{key}"] = [r["valves"].get(name, {}).get(key) for r in records]
    for key, _ in POINT_COLUMNS:
        columns[key] = [r[key] for r in records]
    return columns
