"""The figures drawn in forked processes (report/drawing.py): what the drawers write is what write_plots writes in
the process itself (the reference), the request's other files are written first, and an answer that cannot be
pickled still reaches the caller.  (The errors of a drawer and the request's shared memory: tests/test_export.py.)"""

from functools import partial
from multiprocessing import Pipe
from pathlib import Path
import sys

import pytest

from valvetrain.design import run
from valvetrain.report.drawing import FigureProcess, _send
from valvetrain.report.plots import write_plots

from appendix import appendix_spec

linux = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="the figures are drawn in forked processes "
                                                                         "on Linux only")


@linux
def test_two_drawers_write_the_figures_write_plots_writes(tmp_path):
    """The appendix example's main figures, shared by two forked drawers, against the same figures drawn by
    write_plots in this process: the same files, byte for byte, and the same answer; the ``also`` callable has
    written its file in the first drawer before the figures."""
    results = run(appendix_spec())
    here, there = tmp_path / "here", tmp_path / "there"
    here.mkdir()
    there.mkdir()
    expected = write_plots(results, here, "en", "main")
    with FigureProcess(processes=2) as drawer:
        drawer.submit(results, there, "en", "main", also=partial(Path.write_text, there / "also.txt", "written"))
        answer = drawer.result()
    assert answer == expected
    drawn = sorted(p.name for p in here.iterdir())
    assert len(drawn) >= 2 and sorted(p.name for p in there.iterdir()) == sorted(drawn + ["also.txt"])
    assert all((here / name).read_bytes() == (there / name).read_bytes() for name in drawn)
    assert (there / "also.txt").read_text() == "written"


def test_an_answer_that_cannot_be_pickled_arrives_as_an_error_naming_it():
    """An exception holding a lambda cannot be pickled: the caller gets a RuntimeError with its repr instead of a
    drawer that dies in send()."""
    class Unpicklable(Exception):
        pass

    error = Unpicklable(lambda: None)
    mine, theirs = Pipe()
    _send(theirs, (False, error))
    ok, got = mine.recv()
    assert not ok and isinstance(got, RuntimeError) and str(got) == f"drawing the figures: {error!r}"
    _send(theirs, (True, {"intake": {"lift": "intake_lift.png"}}))
    assert mine.recv() == (True, {"intake": {"lift": "intake_lift.png"}})


def test_an_answer_no_one_reads_any_more_is_dropped_quietly():
    """Issue 36: the first process killed (SIGKILL) while the figures are drawn: the drawer's answer met a closed pipe
    and the drawer printed a BrokenPipeError traceback; _send says the answer is not wanted instead."""
    mine, theirs = Pipe()
    mine.close()
    assert _send(theirs, (True, {"intake": {"lift": "intake_lift.png"}})) is False


@linux
def test_drawers_whose_first_process_has_gone_end_without_a_traceback(tmp_path, capfd):
    """The first process's ends of the pipes closed once the request is sent, as its SIGKILL closes them: the drawers
    end (the first of them ends the others) and print nothing."""
    results = run(appendix_spec())
    drawer = FigureProcess(processes=2)
    drawer.submit(results, tmp_path, "en", "main")
    drawer._sending.join()
    for conn in drawer._conns:
        conn.close()
    drawer._process.join(120.0)
    assert not drawer._process.is_alive()
    assert "Traceback" not in capfd.readouterr().err


def _children(pid):
    """The processes ``pid`` forked (Linux's /proc)."""
    return [int(c) for c in Path(f"/proc/{pid}/task/{pid}/children").read_text().split()]


@linux
def test_stopping_ends_a_drawer_that_did_not_take_its_sigterm(monkeypatch):
    """A drawer just forked may lose the SIGTERM of the first process ending it (the signal comes while it still
    holds the first's handler and is run after it reset the handler): the first then waited for it for ever, and the
    run (a design refused with status 2, which stops the drawers before sending them anything) hung in CI.  Here the
    drawer sets SIGTERM to be ignored instead of the default (SIG_DFL patched in the process that forks it), which
    loses every SIGTERM: stop() must still return, and no drawer be left."""
    import signal
    import threading
    import time

    monkeypatch.setattr(signal, "SIG_DFL", signal.SIG_IGN)
    process = FigureProcess()
    first = process._process.pid
    deadline = time.monotonic() + 60.0
    while not _children(first) and time.monotonic() < deadline:   # the drawer forked after matplotlib's import
        time.sleep(0.01)
    drawers = _children(first)
    assert drawers, "the first process forked no drawer within 60 s"
    time.sleep(0.2)                                               # the drawer has set its SIGTERM by now
    stopping = threading.Thread(target=process.stop, daemon=True)
    stopping.start()
    stopping.join(30.0)
    assert not stopping.is_alive(), "stop() waited for a drawer that did not take its SIGTERM"
    assert not any(Path(f"/proc/{pid}").exists() and "Z" not in Path(f"/proc/{pid}/stat").read_text().split()[2]
                   for pid in drawers)


def test_the_lift_over_the_cycle_is_the_valve_timing_of_the_specification():
    """ValveDesign.cycle_lift, the timing diagram's lifts: the appendix example's inlet valve
    (examples/seed000-appendix-kurz.toml: max_lift_mm = 10, opens 26 crank deg before TDC, closes 78 after BDC, its
    Kurz lobe symmetric about the nose) lifts from -26 to 180 + 78 = 258 crank deg and nowhere else, and reaches its
    10 mm at the middle, (-26 + 258) / 2 = 116 crank deg."""
    import numpy as np

    from valvetrain.design.valve import CYCLE_CRANK

    valve = run(appendix_spec()).valves["intake"]
    crank = np.degrees(CYCLE_CRANK)
    lifting = crank[valve.cycle_lift > 0.0]
    assert lifting.min() == pytest.approx(-26.0) and lifting.max() == pytest.approx(258.0)
    assert valve.cycle_lift.max() == pytest.approx(10e-3, rel=1e-12)
    assert valve.cycle_lift[np.argmin(np.abs(crank - 116.0))] == pytest.approx(10e-3, rel=1e-12)


def test_a_drawer_draws_the_main_figures_without_loading_compiled_laws(tmp_path):
    """The figure inputs carry each valve's lift over the cycle (the one law the main figures evaluated): a new
    process that unpickles them and draws the appendix example's main figures never calls a compiled lift law, so
    the drawers, forked before the first process loads numba's compiled code, need not load it (0.2 s of processor
    time; the first call of a kernel imports numba's array-math module, numba.np.arraymath, which is the sign looked
    for).  Before the inputs carried it, the timing diagram evaluated the Kurz law's kernel in the drawer."""
    import pickle
    import subprocess

    from valvetrain.report.drawing import figure_inputs

    (tmp_path / "plots").mkdir()
    (tmp_path / "inputs.pickle").write_bytes(pickle.dumps(figure_inputs(run(appendix_spec()), "main")))
    script = ("import pickle, sys\n"
              "from pathlib import Path\n"
              "from valvetrain.report.plots import write_plots\n"
              f"folder = Path({str(tmp_path)!r})\n"
              "drawn = write_plots(pickle.loads((folder / 'inputs.pickle').read_bytes()), folder / 'plots', 'en', 'main')\n"
              "print(drawn['(timing)'], 'numba.np.arraymath' in sys.modules)\n")
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=True).stdout.split()
    assert out == ["valve_timing.png", "False"]
