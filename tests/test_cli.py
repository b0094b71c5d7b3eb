"""Command line: run, validate, example; bad files refused; atomic output."""

import json
import subprocess
import sys

from click.testing import CliRunner
import pytest

from valvetrain.cli import main
from valvetrain.specification import example_text

from appendix import PATH as APPENDIX, appendix_text

ARTEFACTS = ["results.json", "report.html", "tables/intake_lift.csv", "contour/intake.csv", "contour/intake.dxf",
             "plots/intake_kinematics.png", "plots/intake_contour.png", "plots/intake_dynamics_speed.png",
             "contour/exhaust.dxf", "plots/exhaust_kinematics.png", "plots/valve_timing.png"]

MAIN_FIGURES = {"intake_kinematics.png", "intake_contour.png", "valve_timing.png", "crank_torque.png"}
"""The figures of the appendix example that a run draws by default (README, ``--figures``)."""

ON_REQUEST = {"intake_time_area.png", "intake_curvature.png", "intake_spring.png", "intake_strength_speed.png",
              "crank_forces.png", "crank_pin_polar.png"}
"""Those drawn only with ``--figures all``."""


@pytest.fixture(scope="module")
def example_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("run") / "design"
    result = CliRunner().invoke(main, ["run", "--out", str(out)])
    assert result.exit_code == 0, result.output
    return out, result


def test_example_runs_and_writes_every_artefact(example_run):
    """`valvetrain run` without FILE designs the built-in example: both valves, every warning accepted in the file."""
    out, result = example_run
    for valve in ("intake", "exhaust"):
        for rel in ARTEFACTS:
            rel = rel.replace("intake", valve)
            assert (out / rel).is_file() and (out / rel).stat().st_size > 0, rel
    assert "open: failures 0, warnings 0, info 0; accepted in the specification: 6" in result.output
    data = json.loads((out / "results.json").read_text())
    assert {v["cam"]["law"] for v in data["valves"].values()} == {"kurz"}
    assert not list(out.parent.glob(".design.*"))  # no temporary folder left behind


def test_the_appendix_example_prints_its_warnings(tmp_path):
    """The manual's own example (appendix of Valve-train practical works (n.d.): V' = 18 x (80/36.8)^2 m/s, closing lag 78 crank deg, seat 45 deg)
    prints its warnings, each value in the unit of its range."""
    result = CliRunner().invoke(main, ["run", str(APPENDIX), "--out", str(tmp_path / "d"), "--figures", "none"])
    assert result.exit_code == 0, result.output
    assert "warning: intake: V' (throat velocity) = 85.0662 m/s, recommended 50...80 m/s" in result.output
    assert "warning: intake: closing lag = 78 crank deg, recommended 40...60 crank deg" in result.output
    assert "info: intake: seat angle = 45 deg, usual 30 deg" in result.output   # an informative comparison


def test_russian_report(tmp_path):
    out = tmp_path / "ru"
    assert CliRunner().invoke(main, ["run", "--out", str(out), "--lang", "ru"]).exit_code == 0
    html = (out / "report.html").read_text(encoding="utf-8")
    assert "Расчёт газораспределительного механизма" in html
    assert 'lang="ru"' in html


def test_example_command_prints_the_builtin_example():
    result = CliRunner().invoke(main, ["example"])
    assert result.exit_code == 0
    assert result.output == example_text()


def test_validate_accepts_the_example(tmp_path):
    f = tmp_path / "my-engine.toml"
    f.write_text(example_text())
    result = CliRunner().invoke(main, ["validate", str(f)])
    assert result.exit_code == 0
    assert "valid" in result.output


BAD = [
    ("bore_mm = 80.0", "", ["engine.bore_mm: required key is missing"]),
    # a unit string was 'Input should be a valid number', without the range (fuzz8)
    ("bore_mm = 80.0", 'bore_mm = "80"',
     ["engine.bore_mm = '80': must be a number, without quotes or a unit; allowed [5, 2000] mm"]),
    ("bore_mm = 80.0", "bore_mm = -80.0", ["engine.bore_mm = -80.0: allowed [5, 2000] mm"]),
    ("phi2_deg = 6.0", "phi2_deg = 7.0", ["valves.intake.cam: phi1_deg + phi2_deg + phi3_deg = 72 cam deg must "
                                          "equal the half-angle phi_p0"]),
    ('law = "kurz"', 'law = "cosine"', ["valves.intake.cam.law = 'cosine': allowed 'kurz', 'polydyne'"]),
    ("seat_angle_deg = 45.0", "seat_angle_deg = 45.0\nseat_angel = 30", ["valves.intake.seat_angel: unknown key"]),
    # an empty key is named as TOML writes it (the fuzzer's "" key: the line began ': unknown key', then with no path)
    ("[engine]", '"" = 1\n[engine]', ['"": unknown key (value 1)']),
    ("[engine]", "[engine", ["not valid TOML"]),
    ("clearance_mm = 0.25", "clearance_mm = 0.0", ["valves.intake.clearance_mm = 0: the cam's ramp"]),
    ("strokes = 4", "strokes = 2", ["engine.strokes = 2: the valve timing"]),
    ("phi3_deg = 38.0", "phi3_deg = 38.0\nphi1_deg = 2.0", ["not valid TOML"]),  # duplicate key
    # the key path names the key as written, without the law tag pydantic puts after "cam"
    ("phi1_deg = 27.0", "phi1_deg = -1.0", ["valves.intake.cam.phi1_deg = -1.0: allowed"]),
]


def test_a_valve_named_like_a_law_keeps_its_name(refused):
    text = appendix_text().replace("valves.intake", "valves.kurz").replace("phi1_deg = 27.0", "phi1_deg = -1.0")
    assert "valves.kurz.cam.phi1_deg = -1.0: allowed" in refused(text)


def test_phi3_omitted_needs_room(tmp_path, refused):
    assert "leaves no room for phi3" in refused(appendix_text().replace("phi3_deg = 38.0", "")
                                                .replace("phi1_deg = 27.0", "phi1_deg = 66.0"))
    f = tmp_path / "ok.toml"
    f.write_text(appendix_text().replace("phi3_deg = 38.0", ""))
    assert CliRunner().invoke(main, ["validate", str(f)]).exit_code == 0


@pytest.mark.parametrize("old,new,messages", BAD)
@pytest.mark.parametrize("command", ["validate", "run"])
def test_bad_files_are_refused(tmp_path, old, new, messages, command):
    f = tmp_path / "bad.toml"
    f.write_text(appendix_text().replace(old, new, 1))
    out = tmp_path / "out"
    args = [command, str(f)] + (["--out", str(out)] if command == "run" else [])
    result = CliRunner().invoke(main, args)
    assert result.exit_code == 2
    for m in messages:
        assert m in result.output
    assert not out.exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.toml"]


def test_several_problems_each_get_a_message(tmp_path):
    f = tmp_path / "bad.toml"
    f.write_text(appendix_text().replace("bore_mm = 80.0", "bore_mm = 0").replace("count = 1                    # same", "count = 0 # same")
                 .replace("throat_diameter_mm = 36.8", ""))
    result = CliRunner().invoke(main, ["validate", str(f)])
    assert result.exit_code == 2
    lines = [ln for ln in result.output.splitlines() if ln.startswith("error:")]
    assert len(lines) == 3
    assert any("engine.bore_mm = 0" in ln for ln in lines)
    assert any("valves.intake.count = 0" in ln for ln in lines)
    assert any("valves.intake.throat_diameter_mm: required key is missing" in ln for ln in lines)


def test_missing_file(tmp_path):
    result = CliRunner().invoke(main, ["validate", str(tmp_path / "nope.toml")])
    assert result.exit_code == 2
    assert "cannot read the file" in result.output


def test_failed_run_leaves_no_folder(tmp_path, monkeypatch):
    """A failure while writing leaves neither the output folder nor a temporary one."""
    import valvetrain.report.html as html

    def boom(*a, **k):
        raise RuntimeError("disk full")

    monkeypatch.setattr(html, "render_report", boom)
    out = tmp_path / "design"
    result = CliRunner().invoke(main, ["run", "--out", str(out)])
    assert result.exit_code == 1
    assert list(tmp_path.iterdir()) == []


def test_failed_rerun_keeps_previous_results(tmp_path, monkeypatch, example_run):
    import shutil

    import valvetrain.report.html as html

    out = tmp_path / "design"
    shutil.copytree(example_run[0], out)
    before = (out / "results.json").read_text()
    monkeypatch.setattr(html, "render_report", lambda *a, **k: 1 / 0)
    assert CliRunner().invoke(main, ["run", "--out", str(out)]).exit_code == 1
    assert (out / "results.json").read_text() == before
    assert [p.name for p in tmp_path.iterdir()] == ["design"]


def test_module_entry_point():
    result = subprocess.run([sys.executable, "-m", "valvetrain", "--version"], capture_output=True, text=True)
    assert result.returncode == 0
    assert "valvetrain" in result.stdout


def test_array_keys_are_accepted(tmp_path, refused):
    f = tmp_path / "e.toml"
    f.write_text(appendix_text().replace("min_resonance_ratio = 10.0", "min_resonance_ratio = 10.0\n"
                                        "mean_diameter_ratio = [0.75, 0.85]"))
    assert CliRunner().invoke(main, ["validate", str(f)]).exit_code == 0
    assert "mean_diameter_ratio" in refused(appendix_text().replace("min_resonance_ratio = 10.0",
                                                                   "min_resonance_ratio = 10.0\n"
                                                                   "mean_diameter_ratio = [0.85, 0.75]"))


def test_a_throat_no_spring_can_serve_is_refused(refused):
    """D = 0.7...0.9 d_g must meet the wire range's 3 x 2.0 ... 12 x 7.0 = 6...84 mm (index 3...12, Valve-train practical works (n.d.),
    work 6): a 5 mm throat (D 3.5...4.5 mm) is refused at validation, not by a failure in the middle of the run."""
    assert "valves.intake.spring.mean_diameter_ratio = [0.7, 0.9] with throat_diameter_mm = 5 gives spring mean " \
           "diameters 3.5...4.5 mm; wire of 2...7 mm makes 6...84 mm" in \
           refused(appendix_text().replace("throat_diameter_mm = 36.8", "throat_diameter_mm = 5.0"))


def test_a_pair_without_room_for_the_inner_spring_exits_2(refused):
    """The polydyne example of Valve-train practical works (n.d.) as a nested pair with an 11.04 mm throat and 5 mm lift: the outer springs (D
    = 0.7...0.9 d_g = 7.7...9.9 mm) leave an outside diameter of at most 9.9 - 2.0 - 2 x 1 = 5.9 mm for the
    inner one, less than the smallest spring of the wire range (D + d = 4 x 2.0 = 8 mm at index 3, Valve-train practical works (n.d.)
    work 6); the run stops with exit 2 and one message, writing nothing."""
    from pathlib import Path

    text = (Path(__file__).parent.parent / "examples" / "seed000-polydyne.toml").read_text()
    text = text.replace("throat_diameter_mm = 36.8", "throat_diameter_mm = 11.04").replace(
        "max_lift_mm = 10.0", "max_lift_mm = 5.0").replace("count = 1\n# count = 2", "count = 2\n#")
    for command in ("validate", "run"):
        assert "valves.intake.spring: no spring of the wire range 2...7 mm fits inside the outer spring" in \
               refused(text, command)


@pytest.mark.parametrize("figures, drawn", [(None, MAIN_FIGURES), ("all", MAIN_FIGURES | ON_REQUEST),
                                             ("none", set())])
def test_the_figures_drawn_are_those_asked_for(tmp_path, figures, drawn):
    """--figures main (the default), all or none: the plots written are those of the README's list, the report embeds
    each of them and names the command that draws each of the others."""
    out = tmp_path / "d"
    option = [] if figures is None else ["--figures", figures]
    assert CliRunner().invoke(main, ["run", str(APPENDIX), "--out", str(out), *option]).exit_code == 0
    assert {p.name for p in (out / "plots").iterdir()} == drawn
    html = (out / "report.html").read_text(encoding="utf-8")
    assert html.count('src="data:image/png;base64,') == len(drawn)
    assert html.count("valvetrain run --figures all") == len(MAIN_FIGURES | ON_REQUEST) - len(drawn)


def test_a_run_without_figures_does_without_matplotlib(tmp_path):
    """--figures none draws nothing, so the run never imports matplotlib (a third of a second)."""
    code = ("import sys; from valvetrain.cli import main; "
            f"main(['run', '--out', {str(tmp_path / 'd')!r}, '--figures', 'none'], standalone_mode=False); "
            "print('matplotlib' in sys.modules)")
    found = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert found.stdout.splitlines()[-1] == "False"


FROZEN_DURING_THE_RUN = """
import gc, sys
from valvetrain import cli, console, export
design, write = cli._design, export.write_outputs
def among_collected(*objects):
    ids = {id(o) for o in objects}
    return [id(o) in ids for o in gc.get_objects()].count(True)
def _design(spec, progress=None):
    print("design", gc.isenabled(), among_collected(vars(cli), vars(sys.modules["numba"]), spec))
    return design(spec, progress)
def write_outputs(results, *args):
    print("write", gc.isenabled(), among_collected(results, results.valves))
    return write(results, *args)
cli._design, export.write_outputs = _design, write_outputs
sys.argv = ["valvetrain", "run", "--out", sys.argv[1], "--figures", "none"]
console.program()
"""


def test_the_runs_collections_leave_out_the_modules_and_the_results(tmp_path):
    """A full collection of the garbage collector looks through every object it tracks: during the design of the
    built-in example that was the imported modules' (about 0.2 s of processor time, once), during the writing also the
    results.  The program freezes them (gc.freeze) once imported and once designed, with the collector enabled: the
    design's collections track none of the command line's and numba's module dictionaries and the specification, the
    writer's not the results and their valves (counted by identity among gc.get_objects(); without the freezes 3
    and 2)."""
    found = subprocess.run([sys.executable, "-c", FROZEN_DURING_THE_RUN, str(tmp_path / "d")], capture_output=True,
                           text=True, check=True)
    assert [line for line in found.stdout.splitlines() if line.startswith(("design", "write"))] == \
        ["design True 0", "write True 0"]


def test_a_run_in_a_callers_process_freezes_nothing(tmp_path):
    """``run`` called in another program's process (a test, a notebook) leaves its garbage collector as it found it:
    nothing frozen, so the caller's objects stay collectable (the program freezes only after it froze its imports)."""
    code = ("import gc; from valvetrain.cli import main; "
            f"main(['run', '--out', {str(tmp_path / 'd')!r}, '--figures', 'none'], standalone_mode=False); "
            "print(gc.get_freeze_count())")
    found = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert found.stdout.splitlines()[-1] == "0"


def test_importing_the_command_line_imports_no_heavy_library():
    """``valvetrain validate`` or ``--help`` need no solver, spline, DXF writer or plotting: importing the command
    line leaves scipy.optimize, scipy.interpolate, ezdxf and matplotlib unimported (together about half a second;
    each is imported where it is used)."""
    heavy = ("scipy.optimize", "scipy.interpolate", "ezdxf", "matplotlib")
    code = f"import sys; import valvetrain.cli; print([m for m in {heavy!r} if m in sys.modules])"
    found = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert found.stdout.splitlines()[-1] == "[]"


def test_the_report_is_one_file(example_run):
    """Every figure is embedded in report.html (a PNG data URI), so the report can be mailed alone."""
    out, _ = example_run
    html = (out / "report.html").read_text(encoding="utf-8")
    assert html.count('src="data:image/png;base64,') == len(list((out / "plots").glob("*.png")))
    assert 'src="plots/' not in html


def test_a_progress_bar_is_drawn_on_a_terminal_and_erased_at_its_end(monkeypatch):
    """A long step's bar goes to a terminal's standard error and is erased when the step ends (the line cleared, no
    newline left), so that an error printed next stands alone; a pipe gets nothing."""
    import io

    from valvetrain import cli

    class Terminal(io.StringIO):
        def isatty(self):
            return True

    monkeypatch.setattr(cli._Progress, "AFTER", 0.0)
    for stream, drawn in ((Terminal(), True), (io.StringIO(), False)):
        monkeypatch.setattr(sys, "stderr", stream)
        progress = cli._Progress()
        progress("intake", 0, 4)
        progress("intake", 2, 4)
        assert ("intake: speed sweep" in stream.getvalue()) is drawn
        progress("intake", 4, 4)
        assert stream.getvalue().endswith("\r\x1b[K") if drawn else stream.getvalue() == ""
        assert "\n" not in stream.getvalue()
