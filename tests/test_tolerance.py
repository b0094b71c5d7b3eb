"""valvetrain tolerance (issue 27 item 2): sampled tolerances, failure probabilities, the same on every backend."""

import json
from pathlib import Path
from types import SimpleNamespace

from click.testing import CliRunner
import numpy as np
import pytest
from scipy.stats import norm

from valvetrain import study as study_module
from valvetrain.cli import main
from valvetrain.tolerance import draw, unit_samples, wilson
from valvetrain.specification import load_spec
from valvetrain.specification.models import Tolerance

from appendix import appendix_text
from visible_text import Visible, english_words

ROOT = Path(__file__).resolve().parents[1]

THROAT = """
[[tolerances]]
key = "valves.intake.throat_diameter_mm"
distribution = "normal"
sigma = 0.4
"""

DYNAMICS = """
[[tolerances]]
key = "valves.intake.clearance_mm"
distribution = "uniform"
half_range = 0.05

[[tolerances]]
key = "valves.intake.drive.masses.valve_kg"
distribution = "normal"
sigma = 0.002
low = 0.05
high = 0.06
"""


def tolerance(spec_file, out, *extra, code=0):
    result = CliRunner().invoke(main, ["tolerance", str(spec_file), "--out", str(out), *extra])
    assert result.exit_code == code, result.output
    return result


def outputs(out):
    """The records (sorted by sample) and the results of a study folder."""
    lines = (out / "records.jsonl").read_text(encoding="utf-8").splitlines()
    records = sorted((json.loads(line) for line in lines[1:]), key=lambda r: r["index"])
    return records, json.loads((out / "tolerance.json").read_text(encoding="utf-8"))


def test_failure_probability_of_a_linear_margin(tmp_path):
    """throat diameter / bore >= 0.46 (hemispherical chamber): with the throat d ~ N(37.0 mm, 0.4 mm) and the bore 80
    mm, the check fails when d < 36.8 mm: P = Phi((36.8 - 37.0)/0.4) = Phi(-0.5) = 0.3085 (closed form); the
    study's estimate must hold it within its 95 % Wilson interval.  The margin (d/80 - 0.46)/0.46 rises with d
    alone: its rank correlation with the throat is 1."""
    path = tmp_path / "engine.toml"
    path.write_text(appendix_text().replace("throat_diameter_mm = 36.8", "throat_diameter_mm = 37.0") + THROAT,
                    encoding="utf-8")
    tolerance(path, tmp_path / "out", "--samples", "200", "--seed", "7")
    c = outputs(tmp_path / "out")[1]["checks"]["intake:flow.throat_to_bore"]
    exact = norm.cdf(-0.5)
    low, high = c["confidence_95"]
    assert c["samples"] == 200 and low <= exact <= high
    assert c["sensitivities"]["valves.intake.throat_diameter_mm"] == pytest.approx(1.0)


def test_a_check_the_file_accepts_is_shown_accepted_with_its_probability_of_failing(tmp_path):
    """Issue 36: the checks the file accepts ([[accepted]]) were reported as P(fail) = 1 like open ones while `run`
    reports them as accepted.  The throat check of test_failure_probability_of_a_linear_margin accepted in the file:
    marked accepted in tolerance.json, on the command line and in the report, its probability that of failing its
    limit, Phi(-0.5) = 0.3085 (closed form) within its Wilson interval; `run` of the nominal file lists it among the
    accepted (it fails at 36.8 mm < 0.46 x 80 mm)."""
    accept = ('\n[[accepted]]\nvalve = "intake"\nquantity = "flow.throat_to_bore"\nreason = "a port of the old head"\n')
    path = tmp_path / "engine.toml"
    path.write_text(appendix_text().replace("throat_diameter_mm = 36.8", "throat_diameter_mm = 37.0") + THROAT
                    + accept, encoding="utf-8")
    result = tolerance(path, tmp_path / "out", "--samples", "200", "--seed", "7")
    c = outputs(tmp_path / "out")[1]["checks"]["intake:flow.throat_to_bore"]
    low, high = c["confidence_95"]
    assert c["accepted"] and low <= norm.cdf(-0.5) <= high and 0.0 < c["probability"] < 1.0
    assert f"  accepted in the specification: intake: throat diameter / bore: P(fail) = {c['probability']:.4g}" in (
        result.output)
    assert "warning, accepted in the specification</td>" in (tmp_path / "out" / "tolerance.html").read_text("utf-8")
    nominal = tmp_path / "nominal.toml"
    nominal.write_text(appendix_text() + accept, encoding="utf-8")
    run = CliRunner().invoke(main, ["validate", str(nominal)])
    assert run.exit_code == 0 and "throat diameter / bore" not in run.output    # accepted: not an open warning


def test_wilson_interval_against_newcombe():
    """Newcombe (1998), Table I, method 3 (the score interval): 81/263 ->
    0.2553-0.3662, 15/148 -> 0.0624-0.1605, 0/20 -> 0-0.1611."""
    for k, n, expected in ((81, 263, (0.2553, 0.3662)), (15, 148, (0.0624, 0.1605)), (0, 20, (0.0, 0.1611))):
        assert wilson(k, n) == pytest.approx(expected, abs=5e-5)


def test_latin_hypercube_strata():
    """A Latin hypercube of n points has exactly one point in each of the n equal strata of every coordinate
    (McKay, Beckman and Conover (1979)); Monte Carlo samples in general do not."""
    n = 50
    u = unit_samples(n, 3, "lhs", seed=3)
    for j in range(3):
        assert sorted(np.floor(u[:, j] * n).astype(int)) == list(range(n))
    mc = unit_samples(n, 3, "mc", seed=3)
    assert sorted(np.floor(mc[:, 0] * n).astype(int)) != list(range(n))


def test_normal_tolerance_is_stratified_in_probability(tmp_path):
    """A normal tolerance drawn by its inverse distribution function from a Latin hypercube: Phi((x - mu)/sigma)
    has one value in each of the n strata of (0, 1)."""
    path = tmp_path / "engine.toml"
    path.write_text(appendix_text() + THROAT, encoding="utf-8")
    x = draw(load_spec(path), [36.8], 40, "lhs", seed=1)[:, 0]
    strata = np.floor(norm.cdf((x - 36.8) / 0.4) * 40).astype(int)
    assert sorted(strata) == list(range(40))


@pytest.mark.parametrize("k", [8.0, 20.0, 40.0, -40.0])
def test_a_normal_truncated_far_in_its_tail_is_drawn_inside_its_range(tmp_path, k):
    """Issue 36: a normal throat tolerance (sigma 0.01 mm) truncated to [mu + k sigma, mu + (k + 1) sigma] drew inf
    from 8 sigma on (Phi(alpha) and Phi(beta) round to 1) and draws outside the range; every draw is now finite and in
    the range, and at its probability u: the truncated normal's distribution function at the draw, F(x) = (Q(alpha) -
    Q(x)) / (Q(alpha) - Q(beta)) with Q the upper tail, evaluated in logarithms (scipy.special.log_ndtr, an
    independent forward evaluation), returns the u of the Latin hypercube (to 1e-9)."""
    from scipy.special import log_ndtr

    mu, sigma = 36.8, 0.01
    low, high = (mu + k * sigma, mu + (k + 1) * sigma) if k > 0 else (mu + (k - 1) * sigma, mu + k * sigma)
    path = tmp_path / "engine.toml"
    path.write_text(appendix_text() + f"""
[[tolerances]]
key = "valves.intake.throat_diameter_mm"
distribution = "normal"
sigma = {sigma}
low = {low!r}
high = {high!r}
""", encoding="utf-8")
    x = draw(load_spec(path), [mu], 200, "lhs", seed=5)[:, 0]
    u = unit_samples(200, 1, "lhs", seed=5)[:, 0]
    assert np.all(np.isfinite(x)) and np.all((x >= low) & (x <= high))
    z, a, b = (x - mu) / sigma, (low - mu) / sigma, (high - mu) / sigma
    if k > 0:   # upper tail Q(t) = Phi(-t)
        q = log_ndtr(-z) - log_ndtr(-a)
        f = np.expm1(q) / np.expm1(log_ndtr(-b) - log_ndtr(-a))
    else:       # the mirror: the lower tail Phi(t)
        f = np.expm1(log_ndtr(z) - log_ndtr(b)) / np.expm1(log_ndtr(a) - log_ndtr(b))
        f = 1.0 - f
    np.testing.assert_allclose(f, u, atol=1e-9)


@pytest.fixture(scope="module")
def spec_file(tmp_path_factory):
    """The pushrod example with a short one-mass sweep (the dynamics headlines are in the records)."""
    text = (ROOT / "examples" / "pushrod-dynamics.toml").read_text(encoding="utf-8").replace("speeds = 200", "speeds = 12")
    path = tmp_path_factory.mktemp("tolerance") / "engine.toml"
    path.write_text(text + DYNAMICS, encoding="utf-8")
    return path


ARGS = ["--samples", "6", "--method", "lhs", "--seed", "11"]


@pytest.fixture(scope="module")
def serial(spec_file, tmp_path_factory):
    out = tmp_path_factory.mktemp("serial") / "out"
    tolerance(spec_file, out, *ARGS)
    return outputs(out)


def test_serial_records(serial):
    records, results = serial
    assert [r["index"] for r in records] == list(range(6))
    assert all(r["record"]["status"] == "ok" for r in records)
    head = results["headlines"]["intake"]
    assert head["jump_speed_rpm"]["n"] + head["max_seating_velocity_m_s"]["n"] > 0
    assert {t["key"] for t in results["tolerances"]} == {"valves.intake.clearance_mm",
                                                         "valves.intake.drive.masses.valve_kg"}


def test_local_processes_give_the_same_records(spec_file, serial, tmp_path):
    tolerance(spec_file, tmp_path / "out", *ARGS, "--workers", "2")
    assert outputs(tmp_path / "out") == serial


def test_dask_cluster_gives_the_same_records(spec_file, serial, tmp_path, monkeypatch):
    """A threaded local cluster, tasks of 3 samples (one task per worker thread)."""
    distributed = pytest.importorskip("distributed")
    monkeypatch.setattr(study_module, "DASK_TASKS_PER_THREAD", 1)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=False, dashboard_address=None) as c:
        tolerance(spec_file, tmp_path / "out", *ARGS, "--scheduler", c.scheduler_address)
    assert outputs(tmp_path / "out") == serial


def test_resume_after_interruption(spec_file, serial, tmp_path):
    """A records file cut after three samples and half a line (a run killed while writing): the run again designs
    the three samples missing and gives the results of the uninterrupted run."""
    out = tmp_path / "out"
    tolerance(spec_file, out, *ARGS)
    lines = (out / "records.jsonl").read_text(encoding="utf-8").splitlines()
    (out / "records.jsonl").write_text("\n".join(lines[:4]) + "\n" + lines[4][:40], encoding="utf-8")
    (out / "tolerance.json").unlink()
    result = tolerance(spec_file, out, *ARGS)
    assert "3 samples designed (3 kept from before)" in result.output
    assert outputs(out) == serial


def test_lines_that_are_no_records_are_designed_again(spec_file, serial, tmp_path):
    """Fuzzer: a records file with a line of JSON that is no record, one of another index and one not UTF-8 (a
    damaged disk, an edit) stopped the run with a traceback; they are left out and their samples designed again,
    to the results of the uninterrupted run."""
    out = tmp_path / "out"
    tolerance(spec_file, out, *ARGS)
    lines = (out / "records.jsonl").read_bytes().split(b"\n")
    lines[2] = b'{"not": "a record"}'
    lines[3] = lines[3].replace(b'"index": 2', b'"index": 99')
    lines[4] = b"\xff\xfe" + lines[4]
    (out / "records.jsonl").write_bytes(b"\n".join(lines))
    (out / "tolerance.json").unlink()
    result = tolerance(spec_file, out, *ARGS)
    assert "3 samples designed (3 kept from before)" in result.output
    assert outputs(out) == serial
    # a header that is JSON but no header is another study's file
    (out / "records.jsonl").write_text("[1]\n", encoding="utf-8")
    assert "records of another study" in tolerance(spec_file, out, *ARGS, code=2).output


def _damage(index, record, how):
    """A sample's record (parsed) damaged as the fuzz campaign of issue 36 damaged records.jsonl: fields of the wrong
    type, a margin that is not finite, an entry cut short, a flag that no longer agrees with the margin."""
    cid, row = next(iter(record["checks"].items()))
    if how == "margin_text":
        row[0] = "0.5"
    elif how == "margin_nan":
        return json.dumps({"index": index, "record": record}).replace(json.dumps(row[0]), "NaN", 1)
    elif how == "short_entry":
        record["checks"][cid] = row[:2]
    elif how == "checks_list":
        record["checks"] = list(record["checks"].items())
    elif how == "passed_flipped":
        cid, row = next((c, r) for c, r in record["checks"].items() if r[0] is not None and r[0] > 0.01)
        row[1] = False
    elif how == "headlines_text":
        record["headlines"] = {"intake": "fast"}
    elif how == "status_other":
        record["status"] = "maybe"
    elif how == "made_unevaluated":     # a passing check made an unevaluated failure: no field tells, the hash does
        cid, row = next((c, r) for c, r in record["checks"].items() if r[1])
        row[0], row[1] = None, False
    return None


@pytest.mark.parametrize("how", ["margin_text", "margin_nan", "short_entry", "checks_list", "passed_flipped",
                                 "headlines_text", "status_other", "made_unevaluated"])
def test_a_damaged_record_is_designed_again(spec_file, serial, tmp_path, how):
    """Issue 36: a records file with the right header and a record of the wrong shape stopped the run with an
    AttributeError, IndexError or ValueError, or was taken with other results (a check that passes counted failed);
    the record is designed again (a note names its line) and the results are those of the uninterrupted run."""
    out = tmp_path / "out"
    tolerance(spec_file, out, *ARGS)
    lines = (out / "records.jsonl").read_text(encoding="utf-8").split("\n")
    item = json.loads(lines[1])
    lines[1] = _damage(item["index"], item["record"], how) or json.dumps(item)   # the hash kept: now wrong
    (out / "records.jsonl").write_text("\n".join(lines), encoding="utf-8")
    (out / "tolerance.json").unlink()
    result = tolerance(spec_file, out, *ARGS)
    assert "1 samples designed (5 kept from before)" in result.output
    assert f"records.jsonl line 2: the record of sample {item['index']}" in result.output or (
        "records.jsonl line 2: not a line of JSON" in result.output)
    assert outputs(out) == serial


def test_a_records_file_that_is_a_folder_is_refused(spec_file, tmp_path):
    """Issue 36: records.jsonl (or tolerance.json) a folder: IsADirectoryError; refused, exit 2, nothing in it
    touched."""
    for name in ("records.jsonl", "tolerance.json"):
        out = tmp_path / name.replace(".", "_")
        (out / name).mkdir(parents=True)
        (out / name / "mine.txt").write_text("kept", encoding="utf-8")
        result = tolerance(spec_file, out, *ARGS, code=2)
        assert result.output.splitlines()[-1].startswith("error: ")
        assert name in result.output or "did not write" in result.output
        assert (out / name / "mine.txt").read_text(encoding="utf-8") == "kept"


def test_a_sample_whose_design_raises_an_error_is_recorded_and_not_designed_again(spec_file, tmp_path,
                                                                                   monkeypatch):
    """Issue 36: an error inside one sample's design stopped the study with a traceback, and the run again met the
    same sample; the sample is recorded as failed (its error named), the study finishes, and the run again keeps
    the record."""
    from valvetrain import tolerance as tolerance_module

    design, calls = tolerance_module.run, []

    def raises_once(spec, **kw):
        calls.append(1)
        if len(calls) == 2:
            raise ValueError("the valve pad at 0.01 m from the pivot cannot give a valve lift of 0.0135 m")
        return design(spec, **kw)

    monkeypatch.setattr(tolerance_module, "run", raises_once)
    out = tmp_path / "out"
    result = tolerance(spec_file, out, *ARGS)
    assert "1 refused (1 of them failed with an error of valvetrain: the design stopped" in result.output
    records, results = outputs(out)
    assert [r["record"]["status"] for r in records].count("failed") == 1
    assert results["failed"]["samples"] == 1 and "ValueError: the valve pad" in results["failed"]["messages"][0]
    assert "0 samples designed (6 kept from before)" in tolerance(spec_file, out, *ARGS).output


def test_other_inputs_in_the_folder_are_refused(spec_file, serial, tmp_path):
    out = tmp_path / "out"
    tolerance(spec_file, out, *ARGS)
    before = (out / "records.jsonl").read_text(encoding="utf-8")
    result = tolerance(spec_file, out, "--samples", "6", "--method", "lhs", "--seed", "12", code=2)
    assert "records of another study" in result.output
    assert (out / "records.jsonl").read_text(encoding="utf-8") == before


def test_a_folder_with_user_files_is_refused(spec_file, tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    (out / "notes.txt").write_text("mine", encoding="utf-8")
    result = tolerance(spec_file, out, *ARGS, code=2)
    assert "did not write" in result.output and "--force to write beside them" in result.output
    assert sorted(p.name for p in out.iterdir()) == ["notes.txt"]
    # fuzz8: tolerance had no --force as run, sweep, optimize, study and compare have; it writes beside the user's
    # files and leaves them as they are (it never replaces the folder)
    tolerance(spec_file, out, *ARGS, "--force")
    assert (out / "notes.txt").read_text(encoding="utf-8") == "mine" and (out / "tolerance.json").is_file()


@pytest.mark.parametrize("place, said", [("spec", "is a file; allowed: a path whose every parent is a folder"),
                                         ("/proc/x", "lies in /proc, a kernel file system")])
def test_a_folder_that_cannot_be_made_is_refused(spec_file, place, said):
    """--out under a file or in /proc is refused as run refuses it, before anything is designed (fuzz6: a
    NotADirectoryError or FileNotFoundError traceback from the records' mkdir; fails before)."""
    out = spec_file / "out" if place == "spec" else Path(place)
    result = tolerance(spec_file, out, *ARGS, code=2)
    assert f"error: --out {out}: " in result.output and said in result.output


def test_ten_million_samples_are_refused_with_an_estimate(tmp_path, monkeypatch):
    """Issue 36: --samples 10000000 started weeks of work without a word; issue 38: a study whose estimated time is
    over an hour (as study's grids) is refused with exit 2, the estimate from timed designs of the file (none drawn:
    the samples are not drawn before) and the option that allows it; --max-samples allows a study up to its value,
    and refuses more.  Each design timed is a fresh one, not the one the process keeps of the last sample
    (tolerance.DESIGNS, which made the second a thirtieth of a design)."""
    from valvetrain import design as design_module
    from valvetrain import tolerance as tolerance_module

    path = tmp_path / "engine.toml"
    path.write_text(appendix_text() + THROAT, encoding="utf-8")
    drawn, designed, real = [], [], design_module.design_valve
    monkeypatch.setattr(tolerance_module, "unit_samples", lambda *a: drawn.append(a))
    monkeypatch.setattr(design_module, "design_valve", lambda name, *a, **k: designed.append(name) or real(name, *a,
                                                                                                           **k))
    result = tolerance(path, tmp_path / "out", "--samples", "10000000", code=2)
    assert sorted(designed) == sorted(2 * list(load_spec(path).valves))
    (line,) = result.output.splitlines()
    assert line.startswith("error: --samples: 10,000,000 samples: about ") and " in 1 process at the " in line
    assert line.endswith(", over the 60 minutes a study may take unless --max-samples 10000000 is given")
    assert drawn == [] and not (tmp_path / "out").exists()
    (line,) = tolerance(path, tmp_path / "out", "--samples", "3", "--max-samples", "2", code=2).output.splitlines()
    assert line.startswith("error: --samples: 3 samples: about ")
    assert line.endswith("; --max-samples 2 allows at most 2 samples; give --max-samples 3")
    monkeypatch.undo()
    tolerance(path, tmp_path / "out", "--samples", "3", "--max-samples", "3")


@pytest.mark.parametrize("entry, said", [
    ('key = "valves.intake.no_such_mm"\ndistribution = "uniform"\nhalf_range = 0.1',
     "valves.intake.no_such_mm: no such key"),
    ('key = "valves.intake.clearance_mm"\ndistribution = "uniform"\nhalf_range = 0.3',
     "valves.intake.clearance_mm"),
    ('key = "engine.bore_mm"\ndistribution = "normal"\nsigma = 1.0\nlow = 70.0\nhigh = 3000.0',
     "engine.bore_mm"),
    ('key = "valves.intake.spring"\ndistribution = "uniform"\nhalf_range = 0.1',
     "valves.intake.spring: a table, not a value; give one of its keys\n"),
    # issue 36: low beyond the default cut nominal + 6 sigma (80 + 6 x 1): an empty range
    ('key = "engine.bore_mm"\ndistribution = "normal"\nsigma = 1.0\nlow = 90.0',
     "engine.bore_mm: the sample range [90, 86] is empty"),
])
def test_bad_tolerances_are_refused_before_sampling(entry, said, tmp_path):
    """Clearance 0.25 -+ 0.3 mm reaches -0.05 mm (allowed 0 or 0.01-5 mm); a bore truncated at 3000 mm leaves
    5-2000 mm."""
    path = tmp_path / "engine.toml"
    path.write_text(appendix_text() + "\n[[tolerances]]\n" + entry + "\n", encoding="utf-8")
    result = tolerance(path, tmp_path / "out", "--samples", "4", code=2)
    assert said in result.output and "error: " in result.output
    assert not (tmp_path / "out").exists()


def test_distribution_parameters_are_checked(tmp_path):
    path = tmp_path / "engine.toml"
    path.write_text(appendix_text() + '\n[[tolerances]]\nkey = "engine.bore_mm"\ndistribution = "normal"\n'
                    'half_range = 1.0\n', encoding="utf-8")
    result = tolerance(path, tmp_path / "out", "--samples", "4", code=2)
    assert "engine.bore_mm: a normal distribution takes sigma" in result.output


@pytest.mark.parametrize("lang, word", [("en", "Tolerance study"), ("ru", "Расчёт влияния допусков")])
def test_report_has_a_row_and_a_histogram_per_failing_check(serial, lang, word):
    """One table row and one margin histogram per check that fails in some sample, one histogram per dynamics
    headline with values; the check named in the report's language from the catalogue."""
    from valvetrain.locale import check_text
    from valvetrain.report.tolerance import report_html

    results = serial[1]
    html = report_html(results, lang)
    failing = [c for c in results["checks"].values() if c["failures"]]
    heads = [d for hs in results["headlines"].values() for d in hs.values() if d is not None]
    assert word in html
    assert html.count("<svg") == len(failing) + len(heads) and html.count("<tr>") == 1 + len(
        results["tolerances"]) + 1 + len(failing)
    for c in failing:
        assert check_text(c["code"], c["params"], lang) in html


def test_russian_report_has_no_english_words(serial):
    """tolerance.html in Russian: the keys by their names (names.py), the headlines, the method; only the valves'
    names, the keys as the file gives them and the citations stay as they are (tests/report/test_i18n.py)."""
    from valvetrain.report.tolerance import report_html

    parser = Visible()
    parser.feed(report_html(serial[1], "ru"))
    assert english_words(parser.texts) == []
    text = " ".join(parser.texts)
    assert "тепловой зазор h0, мм" in text and "масса клапана, кг" in text


def test_samples_have_the_full_designs_checks():
    """A sample's design simulates only the speeds that decide the dynamics headlines and loads (run with
    headlines_only): on the built-in example its jump speed and largest seating velocity equal the full sweep's, every
    check has the full design's verdict, and every margin is within 0.1 % of it (the strength checks read the cam
    force at the speeds simulated; the seating velocity check, the largest up to the rated speed, the speeds near
    the coarse grid's largest there), with fewer than half the speeds simulated (81 and 89 of 200; 53 before the seating
    velocity was graded below the rated speed)."""
    from valvetrain.design import run
    from valvetrain.specification import example_spec

    full, part = run(example_spec()), run(example_spec(), headlines_only=True)
    for name, v in full.valves.items():
        d, p = v.dynamics, part.valves[name].dynamics
        assert len(p.per_speed.speed) < 0.5 * len(d.per_speed.speed)
        assert (p.jump_speed, p.max_seating_velocity) == (d.jump_speed, d.max_seating_velocity)
        # the bounce onset of the few speeds, which no check reads, is not refined (its rounds were most of the
        # intake's refinement): no error estimated
        assert np.isfinite(d.accuracy.bounce_speed) and np.isnan(p.accuracy.bounce_speed)
    assert [(c.code, c.valve, c.passed) for c in part.checks] == [(c.code, c.valve, c.passed) for c in full.checks]
    for a, b in zip(full.checks, part.checks, strict=True):
        assert b.margin == pytest.approx(a.margin, rel=1e-3, abs=1e-12, nan_ok=True), a.code


def test_a_lash_adjusters_sample_has_the_full_designs_checks():
    """A sample of examples/modern-dohc-roller-finger.toml (hydraulic lash adjusters: their stage reads the plunger's
    extension at each speed of the headline sweep, whose maps are joined when read, dynamics.sweep.merged): every
    check has the full design's verdict, its margin within 0.1 % (as the built-in example's above)."""
    import tomllib

    from valvetrain.design import run
    from valvetrain.specification import validate

    spec = validate(tomllib.loads((ROOT / "examples" / "modern-dohc-roller-finger.toml").read_text(encoding="utf-8")))
    full, part = run(spec), run(spec, headlines_only=True)
    assert all(v.lash_adjuster is not None for v in part.valves.values())
    assert [(c.code, c.valve, c.passed) for c in part.checks] == [(c.code, c.valve, c.passed) for c in full.checks]
    for a, b in zip(full.checks, part.checks, strict=True):
        assert b.margin == pytest.approx(a.margin, rel=1e-3, abs=1e-12, nan_ok=True), a.code


def test_multi_mass_trains_are_swept_in_full():
    """A multi-mass train's separations come and go with the speed (coil surge): a sample sweeps it at every speed
    of its range, as valvetrain run does."""
    import tomllib

    from valvetrain.design import run
    from valvetrain.specification import example_text

    document = tomllib.loads(example_text())
    for valve in document["valves"].values():
        valve["dynamics"].update(model="multi", speeds=60)
    part = run(document, headlines_only=True)
    assert [len(v.dynamics.per_speed.speed) for v in part.valves.values()] == [60, 60]


BORE = """
[[tolerances]]
key = "engine.bore_mm"
distribution = "uniform"
half_range = 0.5
"""


@pytest.fixture(scope="module")
def sobol_study(tmp_path_factory):
    """The appendix engine (no dynamics: a sample designs in about 0.1 s) with the throat and the bore toleranced,
    by Saltelli's scheme of 8 base points: 8 x (2 + 2) = 32 samples."""
    folder = tmp_path_factory.mktemp("sobol")
    path = folder / "engine.toml"
    path.write_text(appendix_text().replace("throat_diameter_mm = 36.8", "throat_diameter_mm = 37.0") + THROAT + BORE,
                    encoding="utf-8")
    result = tolerance(path, folder / "out", "--samples", "8", "--method", "sobol", "--seed", "5")
    return path, folder / "out", result


def test_sobol_study_end_to_end(sobol_study):
    """Issue 38: `--method sobol --samples 8` designs the 8 (D + 2) = 32 samples of Saltelli's scheme and gives every
    check's Sobol' indices.  Exact properties of the estimators: a margin that does not depend on a tolerance (the
    lift / throat and the specific mass of the drive do not depend on the bore, the stroke / bore not on the throat)
    has A = A_B^(j) for it, so both its indices are 0 exactly, and the tolerance it depends on alone takes all the
    variance: its total index is 1 within its interval; a margin that neither changes has no indices, the reason
    said ('constant'), nothing NaN.  The command run again designs nothing: the same samples, the same records file
    (its fingerprint), the same results."""
    path, out, result = sobol_study
    records, results = outputs(out)
    assert [r["index"] for r in records] == list(range(32)) and results["samples"] == 32
    assert "32 samples designed (0 kept from before)" in result.output
    checks, throat, bore = results["checks"], "valves.intake.throat_diameter_mm", "engine.bore_mm"
    for cid, alone, other in (("intake:flow.lift_to_throat", throat, bore), ("intake:drive.specific_mass", throat, bore),
                              ("engine.stroke_to_bore", bore, throat)):
        s = checks[cid]["sobol"]
        assert s["blocks"] == 8 and s["reason"] is None
        assert s["indices"][other] == {"first": 0.0, "first_95": 0.0, "total": 0.0, "total_95": 0.0}, cid
        e = s["indices"][alone]
        assert abs(e["total"] - 1.0) <= e["total_95"], cid
    assert checks["intake:valve.seat_angle"]["sobol"] == {"blocks": 8, "reason": "constant", "indices": None}
    assert results["headline_sobol"] == {}
    text = (out / "tolerance.json").read_text(encoding="utf-8")
    assert "NaN" not in text and "Infinity" not in text
    again = tolerance(path, out, "--samples", "8", "--method", "sobol", "--seed", "5")
    assert "0 samples designed (32 kept from before)" in again.output
    assert outputs(out) == (records, results)


@pytest.mark.parametrize("lang, title", [("en", "Sobol' sensitivity indices"), ("ru", "Индексы чувствительности Соболя")])
def test_sobol_report(sobol_study, lang, title):
    """The report of a Sobol' study: a row per tolerance of each check that fails in some sample, its indices +- the
    half-widths of their intervals and their bars; the Russian report without English words."""
    from valvetrain.report.tolerance import report_html

    results = outputs(sobol_study[1])[1]
    html = report_html(results, lang)
    failing = [c for c in results["checks"].values() if c["failures"]]
    e = results["checks"]["intake:flow.throat_to_bore"]["sobol"]["indices"]["engine.bore_mm"]
    assert title in html and f"<td>{e['first']:.3f} ± {e['first_95']:.3f}</td>" in html
    assert html.count('<svg width="200"') == 2 * sum(c["sobol"]["indices"] is not None for c in failing)
    if lang == "ru":
        parser = Visible()
        parser.feed(html)
        assert english_words(parser.texts) == []


@pytest.mark.parametrize("samples", ["6", "12", "1000"])
def test_sobol_needs_a_power_of_two(tmp_path, samples):
    """Saltelli's scheme takes a power of two base points (the Sobol' sequence's balance): another --samples is
    refused before any design, naming the option and the values allowed."""
    path = tmp_path / "engine.toml"
    path.write_text(appendix_text() + THROAT, encoding="utf-8")
    (line,) = tolerance(path, tmp_path / "out", "--samples", samples, "--method", "sobol", code=2).output.splitlines()
    assert line.startswith(f"error: --samples: {samples} with --method sobol: ") and "a power of two" in line
    assert not (tmp_path / "out").exists()


def test_sobol_summary_of_headlines_with_a_refused_sample():
    """summary's Sobol' indices of the dynamics headlines, on records written here: 4 base points of 2 tolerances
    (16 samples), the jump speed 6000 + 1000 x1 rpm (x1 the first tolerance's value), the seating velocity constant,
    one sample refused: its block is left out (3 blocks), the second tolerance's indices 0 exactly, the first's
    total index 1 within its interval; the seating velocity has no indices ('constant')."""
    from valvetrain.tolerance import summary

    spec = SimpleNamespace(tolerances=[Tolerance(key="a.x_mm", distribution="uniform", half_range=0.5),
                                       Tolerance(key="a.y_mm", distribution="uniform", half_range=0.5)])
    x = draw(spec, [0.0, 0.0], 4, "sobol", seed=1)
    records = [{"status": "ok", "message": "", "checks": {"c": [1.0 + v[0], True, "q", "warning", False]},
                "headlines": {"intake": {"jump_speed_rpm": 6000.0 + 1000.0 * v[0], "max_seating_velocity_m_s": 0.3}}}
               for v in x]
    records[5] = {"status": "refused", "message": "no", "checks": {}, "headlines": {}}
    result = summary(spec, [0.0, 0.0], x, records, "sobol", 1)
    jump = result["headline_sobol"]["intake"]["jump_speed_rpm"]
    assert jump["blocks"] == 3 and jump["indices"]["a.y_mm"]["total"] == 0.0
    assert abs(jump["indices"]["a.x_mm"]["total"] - 1.0) <= jump["indices"]["a.x_mm"]["total_95"]
    assert result["headline_sobol"]["intake"]["max_seating_velocity_m_s"] == {"blocks": 3, "reason": "constant",
                                                                              "indices": None}
    assert result["checks"]["c"]["sobol"]["blocks"] == 3 and result["samples"] == 16


def test_random_samples_have_the_full_designs_answers():
    """The fast path of a sample (evaluate_sample: headlines_only, the designs kept between samples) against the full
    design of the same document (valvetrain run's: every speed of both sweeps, the bounce onset refined too), on two
    Latin-hypercube samples of the built-in example with both valves' clearances (+-0.03 mm) and masses (sigma 1 g)
    toleranced: the same checks with the same verdicts, and the jump speeds, the largest seating velocities and every
    check's margin within 1e-6 of the full design's (relative; 1e-9 absolute about zero).  Why so tight: the fast path
    simulates a subset of the full grid's speeds, each an independent problem on the same excitation samples and
    step, refined at the same speeds; a speed's last revolution can differ only where its block of speeds stops after
    another revolution, by at most STATE_TOLERANCE (1 nm against millimetres of lift).  Measured on 8 such samples:
    equal to 2e-16."""
    import tomllib

    from valvetrain.design import run
    from valvetrain.specification import example_text, validate
    from valvetrain.study import with_values
    from valvetrain.tolerance import DESIGNS, check_id, evaluate_sample

    document = tomllib.loads(example_text())
    keys = [f"valves.{v}.{k}" for k in ("clearance_mm", "drive.masses.valve_kg") for v in ("intake", "exhaust")]
    nominal = [document["valves"][k.split(".")[1]]["clearance_mm"] if k.endswith("clearance_mm")
               else document["valves"][k.split(".")[1]]["drive"]["masses"]["valve_kg"] for k in keys]
    spread = np.array([0.03, 0.03, 0.001, 0.001])
    u = unit_samples(2, 4, "lhs", 3)
    DESIGNS.clear()
    for row in np.asarray(nominal) + spread * np.where(np.arange(4) < 2, 2 * u - 1, norm.ppf(u)):
        sample = with_values(document, dict(zip(keys, map(float, row), strict=True)))
        fast, full = evaluate_sample(sample), run(validate(sample))
        assert fast["status"] == "ok"
        for name, v in full.valves.items():
            h = fast["headlines"][name]
            assert h["jump_speed_rpm"] == pytest.approx(v.dynamics.jump_speed * 30 / np.pi, rel=1e-6)
            assert h["max_seating_velocity_m_s"] == pytest.approx(v.dynamics.max_seating_velocity, rel=1e-6)
        assert set(fast["checks"]) == {check_id(c) for c in full.checks}
        for c in full.checks:
            margin, passed = fast["checks"][check_id(c)][:2]
            assert passed == c.passed, check_id(c)
            if margin is None:   # a margin that is not a finite number is recorded as None
                assert not np.isfinite(c.margin), check_id(c)
            else:
                assert margin == pytest.approx(c.margin, rel=1e-6, abs=1e-9), check_id(c)
