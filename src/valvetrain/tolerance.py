"""Tolerance studies (``valvetrain tolerance``): the file's ``[[tolerances]]`` sampled, one design per sample, per
check the distribution of its margin, its probability of failure and the tolerances that drive it.

The samples are drawn in this process before any design (Monte Carlo: independent uniform numbers; Latin
hypercube: :class:`scipy.stats.qmc.LatinHypercube`; Saltelli's scheme on a Sobol' sequence, whose outputs give the
Sobol' indices, :mod:`valvetrain.sensitivity`), from one seed, and mapped to each tolerance's distribution by
its inverse distribution function; each sample is the file's TOML document with its keys replaced, designed by
:func:`evaluate_sample` (a pure function, document in, record out) through :func:`valvetrain.study.evaluate`, so the
records are the same serially, in local processes and on a Dask cluster.  The records are written one a line as they
arrive (:class:`RecordFile`), so that a study interrupted and run again with the same inputs designs only the samples
it lacks.

This module is part of the orchestration, like :mod:`valvetrain.study`.  :mod:`scipy.stats` is imported where it is
used, in the process that draws and sums up the samples: the processes that design them do not need it (it took
0.46 of the 1.5 s a worker process spent importing this module).
"""

import functools
import hashlib
import json
import math
from pathlib import Path
from typing import Any, Optional

from numba import get_num_threads, set_num_threads
import numpy as np

from .checks import SEVERITIES
from .design import run
from .errors import InputError
from .sensitivity import constant, is_power_of_two, saltelli_points, saltelli_size, sobol_indices
from .specification import SpecError
from .specification.messages import shown
from .specification.validate import spec_document
from .study import MMAP_THRESHOLD_BYTES, GridError, check_grid, failure_text, set_malloc
from .units import rpm_to_rad_s

NORMAL_TRUNCATION_SIGMA = 6.0
"""Where an untruncated normal tolerance is cut, in standard deviations (2e-9 of its probability lies outside)."""

CONFIDENCE_Z = 1.959963984540054
"""The standard normal quantile of the two-sided 95 % confidence interval of a failure probability."""

HISTOGRAM_BINS = 20
"""Bins of the histogram of a margin or a headline."""


class ToleranceError(InputError):
    """A tolerance that cannot be sampled; the message is one line naming the key."""


def nominal(spec, key) -> float:
    """The value of a dotted ``key`` in a validated specification (its default where the file leaves it out).

    Raises
    ------
    ToleranceError
        A key the specification does not have, naming a table, or without a number.
    """
    node = spec_document(spec)
    for part in key.split("."):
        if not isinstance(node, dict) or part not in node:
            raise ToleranceError(f"tolerances: {key}: no such key in the specification")
        node = node[part]
    if isinstance(node, dict):
        raise ToleranceError(f"tolerances: {key}: a table, not a value; give one of its keys")
    if isinstance(node, bool) or not isinstance(node, (int, float)):
        raise ToleranceError(f"tolerances: {key}: a tolerance needs a number; the file's value is {shown(node)} "
                             "(give the key a value)")
    return float(node)


def sample_range(tolerance, centre) -> tuple[float, float]:
    """The values a tolerance can take, ``(low, high)`` in the key's unit, about its nominal ``centre``.

    Uniform: ``centre -+ half_range`` or [``low``, ``high``]; normal: [``low``, ``high``] where given, else
    ``centre -+ 6 sigma`` (:data:`NORMAL_TRUNCATION_SIGMA`)."""
    if tolerance.distribution == "uniform" and tolerance.half_range is not None:
        return centre - tolerance.half_range, centre + tolerance.half_range
    cut = NORMAL_TRUNCATION_SIGMA * (tolerance.sigma or 0.0)
    return (centre - cut if tolerance.low is None else tolerance.low,
            centre + cut if tolerance.high is None else tolerance.high)


def check_tolerances(document, spec) -> list[float]:
    """The nominal values of the tolerances of ``spec``; refuse a key the specification does not know, a key given
    twice, and a sample range whose ends the key refuses (:func:`valvetrain.study.check_grid`).

    Returns
    -------
    list of float

    Raises
    ------
    ToleranceError
    """
    if not spec.tolerances:
        raise ToleranceError("tolerances: the file has no [[tolerances]]; give at least one (key, distribution)")
    keys = [t.key for t in spec.tolerances]
    twice = sorted({k for k in keys if keys.count(k) > 1})
    if twice:
        raise ToleranceError(f"tolerances: {', '.join(twice)} given twice; give one distribution per key")
    centres = [nominal(spec, t.key) for t in spec.tolerances]
    for t, centre in zip(spec.tolerances, centres, strict=True):
        low, high = sample_range(t, centre)
        if not low < high:   # one end given beyond the other's default cut at 6 sigma
            raise ToleranceError(f"tolerances: {t.key}: the sample range [{low:g}, {high:g}] is empty: the end not "
                                 f"given is the nominal {centre:g} -+ {NORMAL_TRUNCATION_SIGMA:g} sigma; give both "
                                 "low and high")
        try:
            check_grid(document, [(t.key, [low, high])])
        except GridError as err:
            raise ToleranceError(f"tolerances: the sample range [{low:g}, {high:g}] of {t.key} leaves the key's "
                                 f"bounds: {str(err).removeprefix('--grid ')}") from None
    return centres


def sample_count(n, dimensions, method) -> int:
    """The samples of a study of ``--samples n``: ``n``, or with ``"sobol"`` the ``n (dimensions + 2)`` points of
    Saltelli's scheme of ``n`` base points (:func:`valvetrain.sensitivity.saltelli_size`).

    Raises
    ------
    ToleranceError
        ``"sobol"`` with an ``n`` that is not a power of two."""
    if method != "sobol":
        return n
    if not is_power_of_two(n):
        below = 2 ** max(1, n.bit_length() - 1)
        raise ToleranceError(f"--samples: {n} with --method sobol: the base points of Saltelli's scheme must be a "
                             f"power of two (2, 4, 8, ..., 1024, ...), e.g. {below} or {2 * below}")
    return saltelli_size(n, dimensions)


def unit_samples(n, dimensions, method, seed) -> np.ndarray:
    """Points of the unit hypercube, ``(samples, dimensions)``: ``n`` independent uniform numbers (``"mc"``), a Latin
    hypercube of ``n`` points (``"lhs"``, McKay, Beckman and Conover (1979)), both from
    :class:`numpy.random.Generator` seeded with ``seed``, or Saltelli's scheme of ``n`` base points (``"sobol"``,
    ``n (dimensions + 2)`` points, :func:`valvetrain.sensitivity.saltelli_points`)."""
    from scipy.stats import qmc

    if method == "sobol":
        return saltelli_points(n, dimensions, seed)
    rng = np.random.default_rng(seed)
    if method == "lhs":
        return qmc.LatinHypercube(dimensions, seed=rng).random(n)
    return rng.random((n, dimensions))


def inverse_cdf(u, tolerance, centre) -> np.ndarray:
    """The values of a tolerance at the probabilities ``u`` (its inverse distribution function), key's unit.

    Notes
    -----
    Uniform on [a, b]: x = a + u (b - a).  Normal N(mu, sigma) truncated to [a, b]:
    x = mu + sigma Phi^-1(Phi(alpha) + u (Phi(beta) - Phi(alpha))), alpha = (a - mu)/sigma, beta = (b - mu)/sigma
    (the inverse transform of the truncated normal), evaluated by :data:`scipy.stats.truncnorm`'s inverse, which
    stays accurate in the far tails: written as above, Phi(alpha) and Phi(beta) round to the same number (or to 1)
    a few sigma out and the draws became inf or left [a, b] (8 sigma and more).  A range so far out that the
    inverse overflows (beyond ~1e300 sigma) is concentrated at its end nearest the mean; every draw is in [a, b].

    References
    ----------
    Devroye (1986), section II.2 (the inversion method).
    """
    from scipy import stats

    low, high = sample_range(tolerance, centre)
    if tolerance.distribution == "uniform":
        return low + u * (high - low)
    s = tolerance.sigma
    alpha, beta = (low - centre) / s, (high - centre) / s
    x = centre + s * stats.truncnorm.ppf(u, alpha, beta)
    near = low if alpha > 0.0 else high if beta < 0.0 else centre
    return np.clip(np.where(np.isfinite(x), x, near), low, high)


def draw(spec, centres, n, method, seed) -> np.ndarray:
    """The samples of a study, ``(samples, tolerances)`` in the keys' units (:func:`unit_samples` mapped by
    :func:`inverse_cdf`), the same for the same arguments."""
    u = unit_samples(n, len(centres), method, seed)
    return np.column_stack([inverse_cdf(u[:, j], t, c)
                            for j, (t, c) in enumerate(zip(spec.tolerances, centres, strict=True))])


def check_id(c) -> str:
    """The name of a check in a tolerance study: ``VALVE:CODE`` (or ``CODE`` of the engine's), its parameters after
    it in brackets (``intake:spring.safety_factor[spring=outer]``)."""
    params = ",".join(f"{k}={v}" for k, v in c.params)
    return f"{c.valve + ':' if c.valve else ''}{c.code}{f'[{params}]' if params else ''}"


def split_id(cid) -> dict[str, Any]:
    """The ``valve`` (None: the engine's), ``code`` and ``params`` (dict) of a :func:`check_id`."""
    valve, _, rest = cid.rpartition(":")
    code, _, params = rest.partition("[")
    return {"valve": valve or None, "code": code,
            "params": dict(p.split("=", 1) for p in params.rstrip("]").split(",") if p)}


def _finite(x):
    return float(x) if math.isfinite(x) else None


TRIM_THRESHOLD_BYTES = 128 * 2**20
"""Free memory at the top of the heap that glibc keeps in a process designing samples (see :func:`keep_heap`)."""


@functools.cache
def keep_heap() -> None:
    """Let glibc keep the arrays of a sample's design in the heap when they are freed, once per process: arrays up
    to :data:`~valvetrain.study.MMAP_THRESHOLD_BYTES` come from the heap, and up to :data:`TRIM_THRESHOLD_BYTES` of
    freed memory stays there for the next sample.

    A design allocates and frees the same arrays of a few MB a sample (the sweep's maps, the load maps); mapped
    afresh each time, their pages are zeroed on first touch: measured on the built-in example, 0.13 against 0.10 s
    of processor time a sample (and 8.3 against 1.0 ms for joining two sweeps' maps, :func:`~.dynamics.sweep.merged`).
    Without glibc nothing is done."""
    set_malloc(MMAP_THRESHOLD_BYTES, TRIM_THRESHOLD_BYTES)


DESIGNS = {}
"""The valves' designs of the last sample this process designed, by valve (:func:`valvetrain.design.run`'s
``memo``)."""


def evaluate_sample(document) -> dict[str, Any]:
    """Validate and design one sample; its record.

    The design is :func:`valvetrain.design.run` with ``headlines_only``: each one-mass ``[dynamics]`` sweep simulates
    only the speeds that decide its jump speed, its largest seating velocity and its largest cam force
    (:func:`valvetrain.dynamics.sweep.headline_sweep`), without the diagnosis of a spring that fails (a search per
    remedy, about a second, for words the record does not keep), on one thread of the compiled kernels: the samples
    are what runs in parallel, and one thread splits a sweep into the same blocks of speeds in every backend; the
    process keeps its freed arrays in the heap (:func:`keep_heap`).  A valve whose inputs (its SI view, the engine's,
    ``[gas]``'s, ``[output]``'s) equal those of the last sample this process designed takes that sample's design
    (:data:`DESIGNS`): a study that tolerances one valve's keys designs the others once per process.

    Returns
    -------
    dict
        ``status`` ('ok', 'refused' or 'failed': the design stopped with an error,
        :func:`valvetrain.study.failure_text`), ``message`` (the refusal's problems, one a line, or the error),
        ``checks`` (check id -> ``[margin, passed, quantity, severity, accepted]``, the margin None where it is not
        a finite number, accepted whether the file's ``[[accepted]]`` names the check) and
        ``headlines`` (valve -> ``jump_speed_rpm`` (engine rpm, None: no separation in the range swept) and
        ``max_seating_velocity_m_s``) of the valves with a [dynamics] section.
    """
    keep_heap()
    threads = get_num_threads()
    set_num_threads(1)   # numba's setting is the calling thread's own
    try:
        results = run(document, headlines_only=True, diagnose=False, memo=DESIGNS)   # validated there, once
    except SpecError as err:
        return {"status": "refused", "message": "\n".join(err.problems), "checks": {}, "headlines": {}}
    except Exception as exc:  # noqa: BLE001 - one sample that cannot be designed must not stop the study
        return {"status": "failed", "message": failure_text(exc), "checks": {}, "headlines": {}}
    finally:
        set_num_threads(threads)
    checks = {check_id(c): [_finite(c.margin), c.passed, c.quantity, c.severity, c.accepted] for c in results.checks}
    headlines = {name: {"jump_speed_rpm": _finite(v.dynamics.jump_speed / rpm_to_rad_s(1.0)),
                        "max_seating_velocity_m_s": _finite(v.dynamics.max_seating_velocity)}
                 for name, v in results.valves.items() if v.dynamics is not None}
    return {"status": "ok", "message": "", "checks": checks, "headlines": headlines}


def fresh_sample(document) -> dict[str, Any]:
    """:func:`evaluate_sample` of ``document`` with no design kept from an earlier sample (:data:`DESIGNS` emptied
    first): what the estimate of a study's time times (:func:`valvetrain.study.too_large`, which may design the file
    twice; the second design, taken from :data:`DESIGNS`, took about a thirtieth of the time)."""
    DESIGNS.clear()
    return evaluate_sample(document)


def fingerprint(document, method, seed, samples) -> str:
    """What makes a study's records: the document (its tolerances too), the method, the seed and the samples (a
    hash, hex)."""
    text = json.dumps({"document": document, "method": method, "seed": seed, "samples": samples.tolist()},
                      sort_keys=True, default=str)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


RECORDS = "records.jsonl"
"""The records of a study in its folder: a header line, then one ``{"index": i, "record": {...}, "hash": h}`` a
line (:func:`record_problem`)."""


class RecordFile:
    """The records of a study, appended one a line as they arrive; read back to resume.

    The first line is ``{"fingerprint": ...}`` (:func:`fingerprint`); a file of other inputs is refused.  A last
    line cut short (the process killed while writing it), or any line that is no record, is ignored and its sample
    designed again.
    """

    def __init__(self, folder, stamp):
        self.path = Path(folder) / RECORDS
        self.stamp = stamp

    def read(self, samples) -> dict:
        """The records written before, index -> record (empty for a new file); a line that is no record of one of
        the ``samples`` (cut short, damaged, not UTF-8, a field of the wrong type or out of its range: what
        :func:`evaluate_sample` cannot have written, :func:`record_problem`) is left out, its sample designed again;
        :attr:`damaged` lists those lines, ``(line number, why)``.

        Raises
        ------
        ToleranceError
            A file written for other inputs; a folder where the file would be.
        """
        self.damaged = []
        if self.path.is_dir():
            raise ToleranceError(f"{self.path} is a folder, not the records of a study; give another --out")
        if not self.path.exists():
            return {}
        lines = self.path.read_bytes().decode("utf-8", errors="replace").split("\n")
        try:
            header = json.loads(lines[0])
        except json.JSONDecodeError:
            header = {}
        if not isinstance(header, dict) or header.get("fingerprint") != self.stamp:
            raise ToleranceError(f"{self.path} holds the records of another study (another file, tolerances, "
                                 "method, seed or number of samples); give another --out")
        done = {}
        for number, line in enumerate(lines[1:], start=2):
            if not line.strip():
                continue
            try:
                item = json.loads(line, parse_constant=_no_constant)
            except (json.JSONDecodeError, ValueError) as exc:
                self.damaged.append((number, f"not a line of JSON ({str(exc)[:60]})"))
                continue
            why = record_problem(item, samples)
            if why:
                self.damaged.append((number, why))
            else:
                done[item["index"]] = item["record"]
        return done

    def open(self, done) -> "RecordFile":
        """Start appending after the ``done`` records (the file rewritten with them, so a line cut short goes)."""
        self.path.parent.mkdir(parents=True, exist_ok=True)
        tmp = self.path.with_suffix(".tmp")
        with tmp.open("w", encoding="utf-8") as f:
            f.write(json.dumps({"fingerprint": self.stamp}) + "\n")
            for i in sorted(done):
                f.write(_line(i, done[i]))
        tmp.replace(self.path)
        self.file = self.path.open("a", encoding="utf-8")
        return self

    def keep(self, index, record) -> None:
        """Append one record and flush it to the disk."""
        self.file.write(_line(index, record))
        self.file.flush()

    def close(self) -> None:
        self.file.close()


RECORD_KEYS = {"status", "message", "checks", "headlines"}
"""The keys of a sample's record (:func:`evaluate_sample`)."""

HEADLINE_KEYS = {"jump_speed_rpm", "max_seating_velocity_m_s"}
"""The keys of a valve's headlines in a sample's record."""


def _no_constant(name):
    raise InputError(f"{name} is no number of a record")


def _number(x, finite=True):
    return type(x) in (int, float) and (not finite or math.isfinite(x))


def _check_row_problem(cid, row):
    """Why ``row`` is not a check's entry ``[margin, passed, quantity, severity, accepted]`` of a record, or None."""
    if not isinstance(row, list) or len(row) != 5:
        return f"check {cid[:60]!r} is not [margin, passed, quantity, severity, accepted]"
    margin, passed, quantity, severity, accepted = row
    if not (margin is None or _number(margin)) or type(passed) is not bool or type(accepted) is not bool:
        return f"check {cid[:60]!r}: a margin that is not a finite number or null, or a flag that is not true/false"
    if not isinstance(quantity, str) or severity not in SEVERITIES:
        return f"check {cid[:60]!r}: its text or its severity is not one of a check"
    if margin is not None and (margin < -1e-6 if passed else margin > 1e-6):
        return f"check {cid[:60]!r}: passed = {str(passed).lower()} with the margin {margin:.6g}"
    try:
        split_id(cid)
    except ValueError:
        return f"check {cid[:60]!r}: not VALVE:CODE[PARAMETERS]"
    return None


def record_problem(item, samples) -> Optional[str]:
    """Why a line's JSON value ``item`` is not ``{"index": i, "record": {...}, "hash": h}`` of one of ``samples``
    samples as :func:`evaluate_sample` and :class:`RecordFile` write it (None where it is): the index, the record's
    keys, the status and message, each check's entry (a finite margin or null, agreeing with passed; the flags true
    or false; a severity of :data:`valvetrain.checks.SEVERITIES`), each valve's headlines (a finite number or null),
    and the line's hash of its index and record (a change of any value: a flag flipped where no margin tells).  A
    record that fails is designed again, never trusted."""
    if not isinstance(item, dict) or set(item) != {"index", "record", "hash"}:
        return "not {\"index\": i, \"record\": {...}, \"hash\": ...}"
    index, record = item["index"], item["record"]
    if type(index) is not int or not 0 <= index < samples:
        return f"index {str(index)[:20]}: allowed a whole number 0 ... {samples - 1}"
    if not isinstance(record, dict) or set(record) != RECORD_KEYS:
        return f"the record of sample {index} has not the keys {sorted(RECORD_KEYS)}"
    status, checks, headlines = record["status"], record["checks"], record["headlines"]
    if status not in ("ok", "refused", "failed") or not isinstance(record["message"], str):
        return f"the record of sample {index}: its status or message is not one of a record"
    if not isinstance(checks, dict) or not isinstance(headlines, dict) or (status == "ok") != bool(checks) or (
            status != "ok" and headlines):
        return f"the record of sample {index}: its checks are not those of a {status} sample"
    for cid, row in checks.items():
        why = _check_row_problem(cid, row)
        if why:
            return f"the record of sample {index}: {why}"
    for valve, h in headlines.items():
        if not isinstance(h, dict) or set(h) != HEADLINE_KEYS or not all(v is None or _number(v) for v in h.values()):
            return f"the record of sample {index}: the headlines of {str(valve)[:40]!r} are not those of a valve"
    if item["hash"] != _digest(index, record):
        return f"the record of sample {index} was changed after it was written (its hash does not match)"
    return None


def _digest(index, record) -> str:
    """The hash a record's line carries: of its index and record as canonical JSON (sorted keys), hex."""
    text = json.dumps({"index": index, "record": record}, sort_keys=True, allow_nan=False)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


def _line(index, record):
    return json.dumps({"index": index, "record": record, "hash": _digest(index, record)}, allow_nan=False) + "\n"


def wilson(failures, n, z=CONFIDENCE_Z) -> tuple[float, float]:
    """The Wilson score interval of a binomial proportion, ``(low, high)``.

    Notes
    -----
    p_hat = k/n; centre (p_hat + z^2/(2n)) / (1 + z^2/n), half-width
    z sqrt(p_hat (1 - p_hat)/n + z^2/(4 n^2)) / (1 + z^2/n).

    References
    ----------
    Wilson (1927); Newcombe (1998), method 3.
    """
    if n == 0:
        return 0.0, 1.0
    p = failures / n
    d = 1.0 + z * z / n
    centre = (p + z * z / (2 * n)) / d
    half = z * math.sqrt(p * (1.0 - p) / n + z * z / (4.0 * n * n)) / d
    return max(0.0, centre - half), min(1.0, centre + half)


def distribution(values) -> Optional[dict[str, Any]]:
    """Quantiles, mean, standard deviation and histogram of the finite ``values`` (None where none)."""
    x = np.asarray([v for v in values if v is not None], dtype=float)
    if x.size == 0:
        return None
    low, high = x.min(), x.max()
    if constant(low, high):   # one value (to rounding): one bin about it
        low, high = low - 1e-6 * max(1.0, abs(low)), high + 1e-6 * max(1.0, abs(high))
    counts, edges = np.histogram(x, bins=HISTOGRAM_BINS, range=(low, high))
    q = np.quantile(x, [0.0, 0.01, 0.05, 0.5, 0.95, 0.99, 1.0])
    return {"n": int(x.size), "mean": float(x.mean()), "std": float(x.std()),
            "quantiles": dict(zip(("min", "p01", "p05", "p50", "p95", "p99", "max"), map(float, q), strict=True)),
            "histogram": {"edges": edges.tolist(), "counts": counts.tolist()}}


def sensitivities(samples, values, keys) -> dict[str, Optional[float]]:
    """Spearman's rank correlation of each tolerance with ``values`` (None where the values do not vary or are
    missing), over the samples whose value is a number."""
    from scipy import stats

    ok = np.array([v is not None for v in values])
    y = np.array([v for v in values if v is not None], dtype=float)
    out = {}
    for j, key in enumerate(keys):
        x = samples[ok, j]
        varies = y.size > 2 and np.ptp(y) > 0.0 and np.ptp(x) > 0.0
        out[key] = float(stats.spearmanr(x, y).statistic) if varies else None
    return out


def sobol_entry(values, keys, seed) -> dict[str, Any]:
    """The Sobol' indices of an output over the samples of Saltelli's scheme (:func:`valvetrain.sensitivity.
    sobol_indices`; ``values`` in the samples' order, None where a sample has none): ``blocks`` (the base points
    used), ``reason`` (None, ``"constant"`` or ``"too_few_samples"``) and ``indices`` (None with a reason, else per
    tolerance ``first``, ``first_95``, ``total``, ``total_95``: the indices and the half-widths of their 95 %
    intervals)."""
    s = sobol_indices([math.nan if v is None else v for v in values], len(keys), seed)
    return {"blocks": s["blocks"], "reason": s["reason"],
            "indices": None if s["reason"] else {
                key: {name: s[name][j] for name in ("first", "first_95", "total", "total_95")}
                for j, key in enumerate(keys)}}


def summary(spec, centres, samples, records, method, seed) -> dict[str, Any]:
    """The results of a study (``tolerance.json``): the tolerances, per check its margin's distribution, its
    failures, probability of failure (of its limit: a check the file accepts, ``accepted``, fails it all the same,
    as ``run`` lists it among the accepted) with the Wilson 95 % interval and the rank correlations of the tolerances
    with its margin; per valve with dynamics the distribution of the headlines; the samples not designed (``refused``:
    refused by the specification's checks or the design, or ``failed``: stopped by an error of valvetrain, counted
    among them and apart).  With ``"sobol"`` also the Sobol' indices (:func:`sobol_entry`) of every check's margin
    (``sobol`` of each check) and of each headline (``headline_sobol``: valve -> headline -> indices); every sample
    of Saltelli's scheme has the tolerances' distribution, so the probabilities are over all of them."""
    keys = [t.key for t in spec.tolerances]
    n = len(records)
    ok = [r for r in records if r["status"] == "ok"]
    okx = samples[[r["status"] == "ok" for r in records]]
    ids = list(dict.fromkeys(c for r in ok for c in r["checks"]))
    checks = {}
    for cid in ids:
        rows = [r["checks"].get(cid) for r in ok]
        failures = sum(1 for row in rows if row is not None and not row[1])
        first = next(row for row in rows if row is not None)
        margins = [None if row is None else row[0] for row in rows]
        checks[cid] = {"quantity": first[2], **split_id(cid), "severity": first[3],
                       "accepted": any(row is not None and row[4] for row in rows),
                       "samples": sum(row is not None for row in rows),
                       "failures": failures, "probability": failures / len(ok),
                       "confidence_95": list(wilson(failures, len(ok))), "margin": distribution(margins),
                       "sensitivities": sensitivities(okx, margins, keys)}
        if method == "sobol":
            checks[cid]["sobol"] = sobol_entry([r["checks"].get(cid, [None])[0] if r["status"] == "ok" else None
                                                for r in records], keys, seed)
    valves = list(dict.fromkeys(v for r in ok for v in r["headlines"]))
    names = ("jump_speed_rpm", "max_seating_velocity_m_s")
    headlines = {v: {h: distribution([r["headlines"].get(v, {}).get(h) for r in ok]) for h in names} for v in valves}
    more = {"headline_sobol": {v: {h: sobol_entry([r["headlines"].get(v, {}).get(h) for r in records], keys, seed)
                                   for h in names} for v in valves}} if method == "sobol" else {}
    refused = n - len(ok)
    failed = [r for r in records if r["status"] == "failed"]
    return {"method": method, "seed": seed, "samples": n,
            "tolerances": [{**t.model_dump(exclude_none=True), "nominal": c}
                           for t, c in zip(spec.tolerances, centres, strict=True)],
            "refused": {"samples": refused, "probability": refused / n if n else 0.0,
                        "confidence_95": list(wilson(refused, n)),
                        "messages": sorted({r["message"] for r in records if r["status"] != "ok"})[:10]},
            "failed": {"samples": len(failed), "messages": sorted({r["message"] for r in failed})[:10]},
            "checks": checks, "headlines": headlines, **more}
