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

import copy
from concurrent.futures import ProcessPoolExecutor, as_completed
import itertools
import multiprocessing
from pathlib import Path
import tomllib

import pydantic

from .design import run
from .specification import LAWS, SpecError, validate
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
    ("status", "'ok', or 'refused' (the point is not a valid design; see message)"),
    ("failures", "failed checks of severity failure (not counting those accepted in the file)"),
    ("warnings", "failed checks of severity warning"),
    ("message", "why the point was refused, one problem per line"),
]
"""Columns of every point after the grid values and the valves' columns, with their meanings."""


CONNECT_SECONDS = 20
"""How long :func:`evaluate` tries to reach a Dask scheduler."""


class GridError(ValueError):
    """A grid that cannot be studied; the message is one line naming the key or the value."""


def parse_value(text):
    """A grid value: a TOML value (``6000``, ``0.5``, ``true``, ``"kurz"``), or else the text itself as a string."""
    try:
        return tomllib.loads(f"v = {text}")["v"]
    except tomllib.TOMLDecodeError:
        return text


def parse_grid(items):
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
        texts = [t.strip() for t in values.split(",")]
        if any(not t for t in texts):
            raise GridError(f"--grid {key}={values}: an empty value; give V1,V2,... separated by single commas")
        if key in (k for k, _ in grid):
            raise GridError(f"--grid {key}: given twice; give all its values in one --grid")
        grid.append((key, [parse_value(t) for t in texts]))
    return grid


def read_document(path):
    """The TOML document of a specification file (already validated by
    :func:`valvetrain.specification.load_spec`), with ``source_dir`` set to its folder for the files it names."""
    text = Path(path).read_text(encoding="utf-8").removeprefix("\ufeff")
    return {**tomllib.loads(text), "source_dir": str(Path(path).resolve().parent)}


def with_values(document, values):
    """A deep copy of the TOML ``document`` with the dotted keys of ``values`` (a dict) set; missing tables are
    made, except a valve that the document does not have."""
    out = copy.deepcopy(document)
    for key, value in values.items():
        parts = key.split(".")
        node = out
        for i, part in enumerate(parts[:-1]):
            if part not in node:
                if i == 1 and parts[0] == "valves":
                    raise GridError(f"--grid {key}: the file has no valve {part!r} (valves: "
                                    f"{', '.join(node) or 'none'})")
                node[part] = {}
            node = node[part]
            if not isinstance(node, dict):
                raise GridError(f"--grid {key}: {'.'.join(parts[:i + 1])} is a value, not a table")
        if isinstance(node.get(parts[-1]), dict):
            raise GridError(f"--grid {key}: a table, not a value; give one of its keys")
        node[parts[-1]] = value
    return out


def check_grid(document, grid):
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


def points(grid):
    """The design points of a grid: dicts ``key -> value``, the cartesian product, the first key varying slowest."""
    keys = [k for k, _ in grid]
    return [dict(zip(keys, combo, strict=True)) for combo in itertools.product(*(v for _, v in grid))]


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


def evaluate_point(document):
    """Validate and design one point; the record of its figures, or of its refusal.

    Parameters
    ----------
    document : dict
        A specification as a parsed TOML document (with ``source_dir`` where it names files).

    Returns
    -------
    dict
        ``status`` ('ok' or 'refused'), ``valves`` (name -> the figures of :data:`VALVE_COLUMNS`), ``failures``
        and ``warnings`` (counts of the failed checks not accepted in the file), ``message`` (the refusal's
        problems, one a line; empty for a design).
    """
    try:
        results = run(validate(document))
    except SpecError as err:
        return {"status": "refused", "valves": {}, "failures": None, "warnings": None,
                "message": "\n".join(err.problems)}
    severities = [w.severity for w in results.warnings]
    return {"status": "ok", "valves": {name: _valve_record(v) for name, v in results.valves.items()},
            "failures": severities.count("failure"), "warnings": severities.count("warning"), "message": ""}


def evaluate(documents, workers=None, scheduler=None, progress=None):
    """Evaluate documents with :func:`evaluate_point`: serially, in local processes, or on a Dask cluster.

    Parameters
    ----------
    documents : list of dict
    workers : int, optional
        Local processes (:class:`concurrent.futures.ProcessPoolExecutor`, started with ``spawn``); None or 1:
        this process.
    scheduler : str, optional
        Address of a running Dask distributed scheduler (``tcp://host:8786``); needs the ``dask`` extra.
    progress : callable, optional
        ``progress(done, total)`` after each point (and ``progress(0, total)`` first).

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
    """
    total = len(documents)
    records = [None] * total
    tick = progress or (lambda done, total: None)
    tick(0, total)
    if scheduler is not None:
        try:
            from distributed import Client, as_completed as dask_completed
        except ImportError:
            raise ImportError("--scheduler needs Dask's distributed package: pip install 'valvetrain[dask]'") from None
        try:
            client = Client(scheduler, timeout=CONNECT_SECONDS)
        except (OSError, ValueError, TypeError) as exc:
            raise ConnectionError(f"--scheduler {scheduler}: cannot connect to a Dask scheduler there ({exc})") from None
        with client:
            futures = client.map(evaluate_point, documents, pure=False)
            index = {f.key: i for i, f in enumerate(futures)}
            for done, future in enumerate(dask_completed(futures), 1):
                records[index[future.key]] = future.result()
                tick(done, total)
    elif workers and workers > 1:
        # fresh interpreters: a fork of a process whose compiled kernels run OpenMP threads is unsafe
        with ProcessPoolExecutor(workers, mp_context=multiprocessing.get_context("spawn")) as pool:
            futures = {pool.submit(evaluate_point, d): i for i, d in enumerate(documents)}
            for done, future in enumerate(as_completed(futures), 1):
                records[futures[future]] = future.result()
                tick(done, total)
    else:
        for i, d in enumerate(documents):
            records[i] = evaluate_point(d)
            tick(i + 1, total)
    return records


def table(grid, point_values, records):
    """The study's rows: the grid values, the valves' figures (``VALVE.KEY``) and the point columns.

    Returns
    -------
    dict
        Column name -> list of values (None for an empty cell), in the order of the points.
    """
    valves = list(dict.fromkeys(name for r in records for name in r["valves"]))
    columns = {key: [p[key] for p in point_values] for key, _ in grid}
    for name in valves:
        for key, _ in VALVE_COLUMNS:
            columns[f"{name}.{key}"] = [r["valves"].get(name, {}).get(key) for r in records]
    for key, _ in POINT_COLUMNS:
        columns[key] = [r[key] for r in records]
    return columns
