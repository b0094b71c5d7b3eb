"""The output folder (issue 9, item 1): ``--out`` never deletes a file that a valvetrain run did not write, refuses
unusable paths before computing, replaces a previous output atomically (also when killed) and follows the umask."""

import json
import os
from pathlib import Path
import random
import shutil
import signal
import subprocess
import sys
import time

from click.testing import CliRunner
import pytest

import valvetrain
from valvetrain.cli import main
from valvetrain.outfolder import MARKER, OutFolderError, atomic_folder, check_out, exchange, written_files
from valvetrain.specification import example_text

EXAMPLES = Path(__file__).parents[1] / "examples"
APPENDIX = EXAMPLES / "seed000-appendix-kurz.toml"
SRC = str(Path(valvetrain.__file__).parents[1])
"""The package under test, for the command run as a separate process."""


def command(tmp_path, *args):
    """``python -m valvetrain ARGS`` as a separate process in ``tmp_path`` (the package under test)."""
    return subprocess.Popen([sys.executable, "-m", "valvetrain", *args], cwd=tmp_path, text=True,
                            env={**os.environ, "PYTHONPATH": SRC}, stdout=subprocess.PIPE, stderr=subprocess.PIPE)


@pytest.fixture(scope="module")
def previous_run(tmp_path_factory):
    """A previous output of the appendix example (English report), and how long the command took to write it [s]."""
    folder = tmp_path_factory.mktemp("previous")
    start = time.monotonic()
    proc = command(folder, "run", str(APPENDIX), "--out", "design")
    _, err = proc.communicate(timeout=120)
    assert proc.returncode == 0, err
    return folder / "design", time.monotonic() - start


@pytest.fixture(scope="module")
def previous(previous_run):
    """A previous output of the appendix example (English report)."""
    return previous_run[0]


def listing(folder):
    """Every file under ``folder`` with its content."""
    return {p.relative_to(folder).as_posix(): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


def hidden(folder, name):
    """The hidden siblings ``.NAME.*`` of an output folder (temporary folders)."""
    return sorted(p.name for p in folder.glob(f".{name}.*"))


def complete(out):
    """``out`` holds a whole output: exactly the files its marker lists, results.json readable, report.html."""
    files = {p.relative_to(out).as_posix() for p in out.rglob("*") if p.is_file()} - {MARKER}
    assert files == written_files(out)
    assert "valves" in json.loads((out / "results.json").read_text(encoding="utf-8"))
    assert (out / "report.html").stat().st_size > 0


def write_folder(out, **options):
    """A small output written by :func:`atomic_folder` (no design computed)."""
    with atomic_folder(out, **options) as tmp:
        (tmp / "plots").mkdir()
        (tmp / "results.json").write_text('{"valves": {}}')
        (tmp / "report.html").write_text("<html></html>")


@pytest.fixture
def no_design(monkeypatch):
    """The design must not be computed: a refusal comes before it."""
    import valvetrain.design

    monkeypatch.setattr(valvetrain.design, "run", lambda spec: pytest.fail("the design was computed"))


def foreign_folder(tmp_path):
    """``docs/``: a folder of the user's files, one of them in a subfolder."""
    docs = tmp_path / "docs"
    (docs / "sub").mkdir(parents=True)
    (docs / "notes.txt").write_text("mine")
    (docs / "sub" / "data.csv").write_text("1,2\n")
    return docs


@pytest.mark.parametrize("args", [["run"], ["compare", str(EXAMPLES / "seed000-appendix-kurz.toml")]],
                         ids=["run", "compare"])
def test_a_folder_of_other_files_is_refused(tmp_path, no_design, args):
    docs = foreign_folder(tmp_path)
    before = listing(docs)
    result = CliRunner().invoke(main, [*args, "--out", str(docs)])
    assert result.exit_code == 2
    assert result.output.splitlines() == [f"error: --out {docs}: holds notes.txt, which valvetrain did not write; "
                                          "allowed: a new or empty folder or a previous valvetrain output; choose "
                                          "another folder or pass --force to replace this one and everything in it"]
    assert listing(docs) == before
    assert hidden(tmp_path, "docs") == []


def test_a_file_added_to_a_previous_output_is_kept(tmp_path, no_design, previous):
    """A file the user put into an output folder is not the run's: the folder is refused like a foreign one."""
    out = tmp_path / "design"
    shutil.copytree(previous, out)
    (out / "tables" / "my-notes.txt").write_text("mine")
    result = CliRunner().invoke(main, ["run", "--out", str(out)])
    assert result.exit_code == 2
    assert "holds tables/my-notes.txt, which valvetrain did not write" in result.output
    assert (out / "tables" / "my-notes.txt").read_text() == "mine"


def test_force_replaces_a_folder_of_other_files(tmp_path):
    docs = foreign_folder(tmp_path)
    result = CliRunner().invoke(main, ["run", "--out", str(docs), "--force"])
    assert result.exit_code == 0, result.output
    assert not (docs / "notes.txt").exists()
    complete(docs)
    assert hidden(tmp_path, "docs") == []


def test_an_empty_folder_is_used(tmp_path):
    out = tmp_path / "empty"
    (out / "nothing-here").mkdir(parents=True)  # folders only: no file to lose
    write_folder(out)
    complete(out)


def test_force_never_deletes_the_specification(tmp_path, no_design):
    docs = foreign_folder(tmp_path)
    spec = docs / "engine.toml"
    spec.write_text(example_text())
    result = CliRunner().invoke(main, ["run", str(spec), "--out", str(docs), "--force"])
    assert result.exit_code == 2
    assert result.output.splitlines() == [f"error: --out {docs}: contains the input file {spec}, which replacing the "
                                          "folder would delete; allowed: a folder that holds no input file (even "
                                          "with --force)"]
    assert spec.read_text() == example_text()


def test_force_never_deletes_a_table_the_specification_reads(tmp_path, no_design, monkeypatch):
    """examples/measured-lobe.toml reads data/measured-intake-lobe.csv: --out data --force is refused."""
    shutil.copytree(EXAMPLES / "data", tmp_path / "data")
    shutil.copy(EXAMPLES / "measured-lobe.toml", tmp_path / "lobe.toml")
    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(main, ["run", "lobe.toml", "--out", "data", "--force"])
    assert result.exit_code == 2
    assert f"contains the input file {tmp_path / 'data' / 'measured-intake-lobe.csv'}" in result.output
    assert listing(tmp_path / "data") == listing(EXAMPLES / "data")


BAD_OUT = [
    (".", "is the current folder or contains it; allowed: a folder outside the current one"),
    ("..", "is the current folder or contains it; allowed: a folder outside the current one"),
    ("/proc/x", "lies in /proc, a kernel file system; allowed: a folder on a disk"),
    ("file/sub", "{cwd}/file is a file; allowed: a path whose every parent is a folder"),
    ("file", "is a file; allowed: a folder (new, empty or a previous valvetrain output)"),
]


@pytest.mark.parametrize("out,message", BAD_OUT)
@pytest.mark.parametrize("cmd", ["run", "compare"])
def test_an_unusable_out_is_refused_before_computing(tmp_path, monkeypatch, no_design, cmd, out, message):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "file").write_text("not a folder")
    spec = tmp_path / "spec.toml"
    spec.write_text(example_text())
    result = CliRunner().invoke(main, [cmd, str(spec), "--out", out, "--force"])
    assert result.exit_code == 2
    assert result.output.splitlines() == [f"error: --out {out}: {message.format(cwd=tmp_path)}"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["file", "spec.toml"]
    assert (tmp_path / "file").read_text() == "not a folder"


@pytest.mark.parametrize("cmd", ["run", "compare", "tolerance"])
def test_an_empty_out_is_refused_as_empty(tmp_path, monkeypatch, no_design, cmd):
    """``--out ''`` (a shell variable left empty) is named as empty; it was refused as ``error: --out : is the current
    folder or contains it`` (tolerance: ``error: --out : holds files ...``), which names nothing (a fuzz finding)."""
    monkeypatch.chdir(tmp_path)
    spec = tmp_path / "spec.toml"
    spec.write_text(example_text())
    result = CliRunner().invoke(main, [cmd, str(spec), "--out", ""] + (["--samples", "4"] if cmd == "tolerance" else []))
    assert (result.exit_code, result.output) == (2, "error: --out '': is empty; allowed: the path of a folder\n")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["spec.toml"]


def test_a_folder_where_one_cannot_write_is_refused(tmp_path, monkeypatch):
    """The tests may run as root, for whom every folder is writable: os.access is made to deny it."""
    monkeypatch.setattr(os, "access", lambda path, mode: Path(path) != tmp_path)
    with pytest.raises(OutFolderError) as err:
        check_out(tmp_path / "design")
    assert str(err.value) == (f"{tmp_path / 'design'}: cannot create a folder in {tmp_path} (no write permission); "
                              "allowed: a folder where you can write")


@pytest.mark.parametrize("umask,mode", [(0o022, 0o755), (0o077, 0o700)])
def test_the_folder_follows_the_umask(tmp_path, umask, mode):
    old = os.umask(umask)
    try:
        write_folder(tmp_path / "design")
    finally:
        os.umask(old)
    assert (tmp_path / "design").stat().st_mode & 0o777 == mode
    assert (tmp_path / "design" / "plots").stat().st_mode & 0o777 == mode


def dead_pid():
    """The id of a process that has ended."""
    proc = subprocess.Popen([sys.executable, "-c", ""])
    proc.wait()
    return proc.pid


def test_the_next_run_removes_what_killed_runs_left(tmp_path):
    """Only ``.design.valvetrain-PID.XXXXXXXX.tmp`` folders of a process that is gone are removed."""
    dead, alive = dead_pid(), os.getpid()
    leftover = tmp_path / f".design.valvetrain-{dead}.0123abcd.tmp"
    (leftover / "plots").mkdir(parents=True)
    (leftover / "results.json").write_text("{}")
    kept = [f".design.valvetrain-{alive}.0123abcd.tmp",  # a run that is still running
            f".other.valvetrain-{dead}.0123abcd.tmp",  # beside another output folder
            f".design.valvetrain-{dead}.mine.tmp",  # not a name valvetrain makes
            ".design.backup"]
    for name in kept:
        (tmp_path / name).mkdir()
        (tmp_path / name / "keep.txt").write_text("keep")
    (tmp_path / f".design.valvetrain-{dead}.4567cdef.tmp").write_text("a file, not a folder")
    kept.append(f".design.valvetrain-{dead}.4567cdef.tmp")
    write_folder(tmp_path / "design")
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(kept + ["design"])
    assert all((tmp_path / name / "keep.txt").read_text() == "keep" for name in kept[:-1])


@pytest.mark.skipif(sys.platform != "linux", reason="renameat2 is Linux's")
def test_exchange_swaps_two_folders(tmp_path):
    a, b = tmp_path / "a", tmp_path / "b"
    a.mkdir()
    b.mkdir()
    (a / "x").write_text("in a")
    (b / "y").write_text("in b")
    assert exchange(a, b) is True
    assert [p.name for p in a.iterdir()] == ["y"] and [p.name for p in b.iterdir()] == ["x"]


@pytest.mark.skipif(sys.platform != "linux", reason="renameat2 is Linux's")
def test_on_linux_the_folder_is_never_absent(tmp_path, monkeypatch, previous):
    """The previous output is exchanged with the new one, not renamed away first (os.rename is not called)."""
    out = tmp_path / "design"
    shutil.copytree(previous, out)
    monkeypatch.setattr(os, "rename", lambda *a: pytest.fail(f"os.rename{a}"))
    write_folder(out)
    assert written_files(out) == {"results.json", "report.html"}
    assert hidden(tmp_path, "design") == []


def test_a_rerun_replaces_a_previous_output(tmp_path, previous):
    """A file of the previous output that the rerun does not write goes (a previous run with an exhaust valve)."""
    out = tmp_path / "design"
    shutil.copytree(previous, out)
    (out / "tables" / "exhaust_lift.csv").write_text("written by a previous run with an exhaust valve")
    with (out / MARKER).open("a", encoding="utf-8") as fh:
        fh.write("tables/exhaust_lift.csv\n")
    result = CliRunner().invoke(main, ["run", str(APPENDIX), "--out", str(out), "--lang", "ru"])
    assert result.exit_code == 0, result.output
    assert not (out / "tables" / "exhaust_lift.csv").exists()
    assert 'lang="ru"' in (out / "report.html").read_text(encoding="utf-8")
    complete(out)
    assert hidden(tmp_path, "design") == []


def test_without_rename_exchange_two_renames_replace_the_folder(tmp_path, monkeypatch, previous):
    import valvetrain.outfolder

    monkeypatch.setattr(valvetrain.outfolder, "exchange", lambda a, b: False)
    out = tmp_path / "design"
    shutil.copytree(previous, out)
    write_folder(out)
    assert written_files(out) == {"results.json", "report.html"}
    complete(out)
    assert hidden(tmp_path, "design") == []


def test_compare_replaces_a_previous_comparison(tmp_path):
    out = tmp_path / "cmp"
    for _ in range(2):
        result = CliRunner().invoke(main, ["compare", str(EXAMPLES / "seed000-appendix-kurz.toml"), "--out", str(out)])
        assert result.exit_code == 0, result.output
    assert written_files(out) == {"compare.csv", "compare.json", "plots/compare_lift.png", "plots/compare_velocity.png",
                                  "plots/compare_acceleration.png", "plots/compare_jerk.png",
                                  "plots/compare_dynamics.png"}
    assert hidden(tmp_path, "cmp") == []


@pytest.mark.parametrize("sig", [signal.SIGKILL, signal.SIGINT], ids=["SIGKILL", "SIGINT"])
def test_an_interrupted_run_keeps_a_whole_output(tmp_path, previous_run, sig):
    """Three runs over a previous output, each sent ``sig`` at a random moment (seeded) between 0.1 s (after Python's
    own start) and the run's duration: ``--out`` holds the previous or the whole new output after each; a SIGINT
    ends the command with one line and its temporary folder removed; the next run leaves no temporary folder.

    The status after a SIGINT is 130, or death by SIGINT (which a shell shows as 130): ``python -m`` ends that way,
    after a clean exit, when the KeyboardInterrupt passed through an ``exec`` of a string (scipy's imports have
    one; CPython's Py_RunMain and its unhandled_keyboard_interrupt mark)."""
    previous, seconds = previous_run
    out = tmp_path / "design"
    shutil.copytree(previous, out)
    moments = random.Random(9).sample(range(100, int(seconds * 1000)), 3)
    for ms in moments:
        proc = command(tmp_path, "run", str(APPENDIX), "--out", "design", "--lang", "ru")
        time.sleep(ms / 1000)
        proc.send_signal(sig)
        _, err = proc.communicate(timeout=120)
        complete(out)
        if sig == signal.SIGINT:
            assert (proc.returncode, err) in ((130, "error: interrupted\n"), (-signal.SIGINT, "error: interrupted\n"),
                                              (0, "")), (ms, err)
            assert hidden(tmp_path, "design") == [], ms
        else:
            assert proc.returncode in (-signal.SIGKILL, 0), (ms, err)
    proc = command(tmp_path, "run", str(APPENDIX), "--out", "design")
    _, err = proc.communicate(timeout=120)
    assert proc.returncode == 0, err
    complete(out)
    assert hidden(tmp_path, "design") == []
