"""valvetrain study (issue 12 item 4): a grid of keys, one table, the same on every backend."""

import json
import os
from pathlib import Path
import signal

from click.testing import CliRunner
import pytest

from valvetrain import study as study_module
from valvetrain.cli import main
from valvetrain.study import evaluate_point, parse_grid, toml_text

from appendix import appendix_text

ROOT = Path(__file__).resolve().parents[1]
GRID = ["--grid", "valves.intake.cam.shape_factor=0.55,0.6,0.65", "--grid", "engine.rated_speed_rpm=6000,7000"]


@pytest.fixture(scope="module")
def spec_file(tmp_path_factory):
    """The pushrod example with a short one-mass sweep, so that the jump speed is a column."""
    text = (ROOT / "examples" / "pushrod-dynamics.toml").read_text(encoding="utf-8").replace("speeds = 200", "speeds = 12")
    path = tmp_path_factory.mktemp("study") / "engine.toml"
    path.write_text(text, encoding="utf-8")
    return path


def study(spec_file, out, *extra):
    result = CliRunner().invoke(main, ["study", str(spec_file), *GRID, "--out", str(out), *extra])
    assert result.exit_code == 0, result.output
    return (out / "study.csv").read_text(encoding="utf-8"), json.loads((out / "study.json").read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def serial(spec_file, tmp_path_factory):
    return study(spec_file, tmp_path_factory.mktemp("serial") / "out")


def test_serial_table(serial):
    csv, data = serial
    points = data["points"]
    assert len(points) == 6 and len(csv.splitlines()) == 7
    assert [(p["valves.intake.cam.shape_factor"], p["engine.rated_speed_rpm"]) for p in points][:3] == [
        (0.55, 6000), (0.55, 7000), (0.6, 6000)]
    for p in points:
        assert p["status"] == "ok" and p["message"] == ""
        assert p["intake.time_area_mm2_s"] > 0 and 0 < p["intake.fullness"] < 1
        assert p["intake.max_acceleration_m_s2"] > 0 > p["intake.min_acceleration_m_s2"]
        assert p["intake.spring_wire_mm"] > 0 and p["intake.spring_preload_N"] > 0
        assert isinstance(p["intake.spring_passes"], bool)
        assert p["intake.rho_min_mm"] > 0 and p["intake.max_contact_stress_MPa"] > 0
        assert isinstance(p["failures"], int) and isinstance(p["warnings"], int)
        assert p["intake.jump_speed_rpm"] > 0
    # a higher rated speed: higher accelerations, a smaller time-area
    assert points[1]["intake.max_acceleration_m_s2"] > points[0]["intake.max_acceleration_m_s2"]
    assert points[1]["intake.time_area_mm2_s"] < points[0]["intake.time_area_mm2_s"]


def test_local_processes_give_the_same_table(spec_file, serial, tmp_path):
    assert study(spec_file, tmp_path / "out", "--workers", "2") == serial


def test_dask_cluster_gives_the_same_table(spec_file, serial, tmp_path, monkeypatch):
    """On a two-worker cluster in tasks of 3 points (one task per worker thread: 6 points / 2 threads), the table of
    the serial study."""
    distributed = pytest.importorskip("distributed")
    monkeypatch.setattr(study_module, "DASK_TASKS_PER_THREAD", 1)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        assert study(spec_file, tmp_path / "out", "--scheduler", cluster.scheduler_address) == serial


def test_the_options_and_the_out_folder_are_refused_before_a_design_is_timed(spec_file, tmp_path, monkeypatch):
    """A fuzz run (fuzz8): --workers with --scheduler, and an --out holding a user's file, were refused after the
    design of FILE timed for the estimate of the study's time (seconds for a file with dynamics)."""
    def timed(point, document):
        raise AssertionError("a design timed before the options were checked")

    monkeypatch.setattr(study_module, "_timed", timed)
    (tmp_path / "mine").mkdir()
    (tmp_path / "mine" / "notes.txt").write_text("mine\n", encoding="utf-8")
    for options, said in ((["--workers", "2", "--scheduler", "tcp://127.0.0.1:1"], "error: --workers and --scheduler"),
                          (["--out", str(tmp_path / "mine")], "holds notes.txt, which valvetrain did not write")):
        result = CliRunner().invoke(main, ["study", str(spec_file), *GRID, "--out", str(tmp_path / "o"), *options])
        assert result.exit_code == 2 and said in result.output, result.output
    assert not (tmp_path / "o").exists() and (tmp_path / "mine" / "notes.txt").read_text(encoding="utf-8") == "mine\n"


def test_scheduler_without_dask_is_an_error(spec_file, tmp_path, monkeypatch):
    import sys

    monkeypatch.setitem(sys.modules, "distributed", None)
    result = CliRunner().invoke(main, ["study", str(spec_file), *GRID, "--out", str(tmp_path / "o"),
                                       "--scheduler", "tcp://127.0.0.1:1"])
    assert result.exit_code == 2
    assert "pip install 'valvetrain[dask]'" in result.output
    assert not (tmp_path / "o").exists()


@pytest.mark.parametrize("grid, said", [
    ("valves.intake.cam.shape_fctor=0.5", "valves.intake.cam.shape_fctor: unknown key"),
    ("valves.intake.cam.shape_factor=0.5,7", "valves.intake.cam.shape_factor = 7: allowed"),
    ("engine.rated_speed_rpm=6000,fast", "engine.rated_speed_rpm = 'fast'"),
    ("valves.exhaust.cam.shape_factor=0.5", "no valve 'exhaust'"),
    ("valves.intake.cam=0.5", "valves.intake.cam: a table"),
    ("engine.rated_speed_rpm", "expected KEY=V1,V2,..."),
    ("engine.rated_speed_rpm=6000,,7000", "engine.rated_speed_rpm=6000,,7000: an empty value"),
])
def test_invalid_grid_is_refused(tmp_path, grid, said):
    f = tmp_path / "engine.toml"
    f.write_text(appendix_text(), encoding="utf-8")
    result = CliRunner().invoke(main, ["study", str(f), "--grid", grid, "--out", str(tmp_path / "o")])
    assert result.exit_code == 2
    (line,) = result.output.splitlines()
    assert line.startswith("error: --grid ") and said in line
    assert not (tmp_path / "o").exists()


def test_a_bad_grid_value_is_refused_before_a_design_is_timed(tmp_path, monkeypatch):
    """fuzz8: a grid of 1000 points with a value its key refuses timed a design of the file for the estimate of its
    time (seconds) before it said so."""
    f = tmp_path / "engine.toml"
    f.write_text(appendix_text(), encoding="utf-8")
    monkeypatch.setattr(study_module, "_timed", lambda *args: pytest.fail("a design was timed"))
    values = ",".join(f"{0.5 + i * 1e-4:.4f}" for i in range(999)) + ",7"
    result = CliRunner().invoke(main, ["study", str(f), "--grid", f"valves.intake.cam.shape_factor={values}",
                                       "--out", str(tmp_path / "o")])
    assert result.exit_code == 2 and "valves.intake.cam.shape_factor = 7: allowed" in result.output, result.output
    assert not (tmp_path / "o").exists()


def test_invalid_point_is_a_row(tmp_path):
    f = tmp_path / "engine.toml"
    f.write_text(appendix_text(), encoding="utf-8")
    out = tmp_path / "o"
    result = CliRunner().invoke(main, ["study", str(f), "--grid", "valves.intake.cam.phi1_deg=27,40", "--out", str(out)])
    assert result.exit_code == 0, result.output
    assert "2 design points (1 refused)" in result.output
    ok, refused = json.loads((out / "study.json").read_text(encoding="utf-8"))["points"]
    assert ok["status"] == "ok" and ok["intake.fullness"] > 0
    assert refused["status"] == "refused" and refused["intake.fullness"] is None
    assert "phi1_deg + phi2_deg + phi3_deg = 84 cam deg must equal the half-angle" in refused["message"]
    assert "refused" in (out / "study.csv").read_text(encoding="utf-8").splitlines()[2]


def test_a_point_whose_design_raises_an_error_is_a_failed_row_and_the_study_finishes(tmp_path, monkeypatch):
    """Issue 36: an error inside one point's design (a ValueError of the finger's linkage met one) stopped the whole
    study with a traceback; the point is a row with status 'failed' and the error named, the others are designed."""
    f = tmp_path / "engine.toml"
    f.write_text(appendix_text(), encoding="utf-8")
    design = study_module.run

    def raises_at_7000(spec, **kw):
        if spec.engine.rated_speed_rpm == 7000:
            raise ValueError("the valve pad at 0.01 m from the pivot cannot give a valve lift of 0.0135 m")
        return design(spec, **kw)

    monkeypatch.setattr(study_module, "run", raises_at_7000)
    out = tmp_path / "o"
    result = CliRunner().invoke(main, ["study", str(f), "--grid", "engine.rated_speed_rpm=6000,7000", "--out",
                                       str(out)])
    assert result.exit_code == 0, result.output
    assert "2 design points (0 refused, 1 failed with an error of valvetrain: the design stopped" in result.output
    ok, failed = json.loads((out / "study.json").read_text(encoding="utf-8"))["points"]
    assert ok["status"] == "ok" and failed["status"] == "failed" and failed["intake.fullness"] is None
    assert "(ValueError: the valve pad at 0.01 m" in failed["message"]


def test_unreachable_scheduler_is_one_line(spec_file, tmp_path):
    pytest.importorskip("distributed")
    result = CliRunner().invoke(main, ["study", str(spec_file), *GRID, "--out", str(tmp_path / "o"),
                                       "--scheduler", "nonsense://x"])
    assert result.exit_code == 2
    assert result.output.splitlines()[-1].startswith("error: --scheduler nonsense://x: cannot connect")
    assert not (tmp_path / "o").exists()


def _dies_at_one_point(document):
    """A point's design whose process is killed (as by the kernel's out-of-memory killer) at the grid point that
    ``VALVETRAIN_TEST_DIES_AT`` names (``shape_factor,rated_speed_rpm``; the spawned processes inherit it)."""
    shape, speed = map(float, os.environ["VALVETRAIN_TEST_DIES_AT"].split(","))
    if document["engine"]["rated_speed_rpm"] == speed and document["valves"]["intake"]["cam"]["shape_factor"] == shape:
        os.kill(os.getpid(), signal.SIGKILL)
    return evaluate_point(document)


@pytest.mark.parametrize("dies_at, number", [("0.65,7000", 6), ("0.6,6000", 3)])
def test_a_worker_that_dies_stops_the_study_keeping_the_points_done(tmp_path, monkeypatch, dies_at, number):
    """Issue 21 traceback 7: a worker killed at the grid's last point (6 of 6) or at a middle one (3) ends the study
    with one line naming the points in progress or waiting then, exit 1, and the table with every point before
    them designed, the points named not designed.  Each of the two processes is given two points at a time
    (study.POINTS_PER_PROCESS): at most four are named, and a point is named only once every point before the
    first of them was given to a process."""
    f = tmp_path / "engine.toml"
    f.write_text(appendix_text(), encoding="utf-8")
    monkeypatch.setenv("VALVETRAIN_TEST_DIES_AT", dies_at)
    monkeypatch.setattr(study_module, "evaluate_point", _dies_at_one_point)
    out = tmp_path / "o"
    result = CliRunner().invoke(main, ["study", str(f), *GRID, "--out", str(out), "--workers", "2"])
    assert result.exit_code == 1, result.output
    error = result.output.splitlines()[-1]
    assert error.startswith("error: a worker process died (killed, or out of memory) with th")
    shape, speed = dies_at.split(",")
    assert f"point {number} (valves.intake.cam.shape_factor = {shape}, engine.rated_speed_rpm = {speed})" in error
    import re

    lost = {int(n) for n in re.findall(r"point (\d) \(", error)}
    more = re.search(r" and (\d) more;", error)
    assert number in lost and len(lost) + (int(more.group(1)) if more else 0) <= study_module.POINTS_PER_PROCESS * 2
    rows = json.loads((out / "study.json").read_text(encoding="utf-8"))["points"]
    statuses = [r["status"] for r in rows]
    assert all(statuses[i - 1] == "not designed" for i in lost)
    assert statuses[:min(lost) - 1] == ["ok"] * (min(lost) - 1)
    assert set(statuses) <= {"ok", "not designed"}
    assert all(r["intake.fullness"] > 0 for r in rows if r["status"] == "ok")


def test_a_toml_array_grid_value_is_one_value_written_as_toml(tmp_path):
    """Issue 21 traceback 1: a grid value that is a TOML array (a spring's list of materials) is one value, designed,
    and written to study.csv as its TOML text."""
    f = tmp_path / "engine.toml"
    f.write_text(appendix_text(), encoding="utf-8")
    out = tmp_path / "o"
    result = CliRunner().invoke(main, ["study", str(f), "--grid",
                                       'valves.intake.spring.material=["VDSiCr", "60S2A"],"60S2A"', "--out", str(out)])
    assert result.exit_code == 0, result.output
    lines = (out / "study.csv").read_text(encoding="utf-8").splitlines()
    assert [line.split(",")[0] for line in lines] == ["valves.intake.spring.material", '"[""VDSiCr""', "60S2A"]
    assert lines[1].startswith('"[""VDSiCr"", ""60S2A""]",')   # the CSV quoting of the TOML text ["VDSiCr", "60S2A"]
    assert "2 design points (0 refused)" in result.output


def test_grid_values_split_outside_arrays_tables_and_strings():
    assert parse_grid(['k=[1, 2],{ a = "x,y" },"p,q",3']) == [("k", [[1, 2], {"a": "x,y"}, "p,q", 3])]
    # TOML's own text of each (TOML v1.0.0: arrays, inline tables, basic strings)
    assert [toml_text(v) for v in ([1, 2], {"a": "x,y", "b c": True}, "p,q", 3.5)] == [
        "[1, 2]", '{ a = "x,y", "b c" = true }', '"p,q"', "3.5"]


def test_a_huge_grid_is_refused_before_any_point_is_built(tmp_path, monkeypatch):
    """Issue 21 traceback 6: 1000 x 1000 points are counted, not made: refused with exit 2, the count and an estimate
    over an hour (issue 38), in about the time of two designs; --max-points allows a grid up to its value and refuses
    more."""
    f = tmp_path / "engine.toml"
    f.write_text(appendix_text(), encoding="utf-8")
    made = []
    monkeypatch.setattr(study_module, "with_values", lambda d, v: made.append(v) or d)
    shape = ",".join(f"{0.5 + i * 1e-4:.4f}" for i in range(1000))
    speed = ",".join(str(5000 + i) for i in range(1000))
    result = CliRunner().invoke(main, ["study", str(f), "--grid", f"valves.intake.cam.shape_factor={shape}",
                                       "--grid", f"engine.rated_speed_rpm={speed}", "--out", str(tmp_path / "o")])
    assert result.exit_code == 2
    (line,) = result.output.splitlines()
    assert line.startswith("error: --grid: 1,000,000 design points: about ") and " in 1 process at the " in line
    assert line.endswith(", over the 60 minutes a study may take unless --max-points 1000000 is given")
    # each value was validated alone (check_grid: one key each), no point (both keys) made
    assert [v for v in made if len(v) == 2] == [] and not (tmp_path / "o").exists()
    result = CliRunner().invoke(main, ["study", str(f), "--grid", "valves.intake.cam.shape_factor=0.55,0.6,0.65",
                                       "--max-points", "2", "--out", str(tmp_path / "o")])
    assert result.exit_code == 2 and "3 design points" in result.output
    assert result.output.rstrip().endswith("--max-points 2 allows at most 2 points; give --max-points 3")
    result = CliRunner().invoke(main, ["study", str(f), "--grid", "valves.intake.cam.shape_factor=0.55,0.6,0.65",
                                       "--max-points", "3", "--out", str(tmp_path / "o")])
    assert result.exit_code == 0, result.output


class Clock:
    """A clock for too_large that a design moves on: ``first`` seconds for the first design, ``each`` after."""

    def __init__(self, first, each):
        self.now, self.first, self.each, self.designs = 0.0, first, each, 0

    def monotonic(self):
        return self.now

    def design(self, document):
        self.now += self.first if self.designs == 0 else self.each
        self.designs += 1


@pytest.mark.parametrize("total, processes, allowed, first, refused, designs", [
    (20_000, 1, None, 0.1, False, 1),      # 2000 s: under the hour, though over the 10,000 points refused before
    (1_000, 1, None, 5.0, False, 2),       # the first design (5 s) gives 5000 s; the second (0.1 s) 100 s
    (40_000, 1, None, 0.1, True, 2),       # 4000 s
    (40_000, 2, None, 0.1, False, 1),      # 2000 s in two processes
    (40_000, 1, 50_000, 0.1, False, 0),    # allowed by the option: not timed
    (40_000, 1, 30_000, 0.1, True, 2),     # more than the option allows
])
def test_a_study_is_refused_by_its_estimated_time(monkeypatch, total, processes, allowed, first, refused, designs):
    """Issue 38: a study is refused where its estimate, the count times a design's time over the processes, is over
    an hour (3600 s); the first design of a process loads what designs need, so where its time gives more than an
    hour a second design is timed and gives the estimate; --max-points N allows up to N points however long."""
    clock = Clock(first, 0.1)
    monkeypatch.setattr(study_module, "time", clock)
    why = study_module.too_large(total, allowed, {}, processes, "design points", "--max-points", clock.design)
    assert (why is not None) is refused and clock.designs == designs
    if refused and allowed is None:
        assert why == ("40,000 design points: about 66.7 minutes in 1 process at the 0.1 s that a design of the file "
                       "takes, over the 60 minutes a study may take unless --max-points 40000 is given")
    elif refused:
        assert why.endswith("; --max-points 30000 allows at most 30,000 points; give --max-points 40000")


def test_dask_tasks_hold_several_points():
    """Points per task = ceil(points / (8 tasks x threads)), between 1 and 32: 1000 points on 2 threads -> 63, capped
    at 32; 300 points -> ceil(300 / 16) = 19; 5 points -> 1."""
    assert [study_module.dask_chunk(n, 2) for n in (1000, 300, 5)] == [32, 19, 1]
