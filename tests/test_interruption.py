"""The SIGINT of the ``valvetrain`` program (valvetrain.interruption): the handlers record a SIGINT or interrupt with
it, leave a caller's own handler alone, and deliver a KeyboardInterrupt again that Python could not raise."""

import signal
import subprocess
import sys

import pytest

from valvetrain.interruption import Interruption


@pytest.fixture
def sigint():
    """The default SIGINT handling for the test, and the process's own (handler, unraisable hook, record) after it."""
    saved = signal.getsignal(signal.SIGINT), sys.unraisablehook, Interruption.seen
    signal.signal(signal.SIGINT, signal.default_int_handler)
    Interruption.seen = False
    yield
    signal.signal(signal.SIGINT, saved[0])
    sys.unraisablehook, Interruption.seen = saved[1:]


def test_the_recording_handler_records_and_does_not_interrupt(sigint):
    Interruption.install(Interruption.record)
    assert signal.getsignal(signal.SIGINT) == Interruption.record and sys.unraisablehook is not Interruption.redeliver
    signal.raise_signal(signal.SIGINT)
    assert Interruption.seen


def test_the_interrupting_handler_records_interrupts_and_redelivers(sigint):
    Interruption.install(Interruption.record)
    Interruption.install(Interruption.interrupt)
    assert sys.unraisablehook == Interruption.redeliver
    with pytest.raises(KeyboardInterrupt):
        signal.raise_signal(signal.SIGINT)
    assert Interruption.seen


def test_a_callers_own_handling_of_the_sigint_stays(sigint):
    """A caller that ignores the SIGINT (or handles it itself) keeps it so: neither handler is installed."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    Interruption.install(Interruption.interrupt)
    assert signal.getsignal(signal.SIGINT) == signal.SIG_IGN and sys.unraisablehook is not Interruption.redeliver


SIGINT_IN_A_CALLBACK = """
import signal, sys, time, weakref
from valvetrain.interruption import Interruption
Interruption.install(Interruption.interrupt)
class Part:
    pass
part = Part()
ref = weakref.ref(part, lambda _: signal.raise_signal(signal.SIGINT))
try:
    del part           # the callback runs now, and the SIGINT's KeyboardInterrupt is raised inside it
    time.sleep(5)      # the command's work goes on
    sys.exit("not interrupted")
except KeyboardInterrupt:
    print("interrupted")
"""


def test_a_sigint_during_a_weakref_callback_still_interrupts():
    """A SIGINT that came while the garbage collector ran a weakref callback was printed as 'Exception ignored ...
    KeyboardInterrupt' and lost: the run went on and ended with status 0 (seen in test_outfolder's interrupted
    runs). Provoked deterministically here: the KeyboardInterrupt is delivered again and interrupts the work."""
    proc = subprocess.run([sys.executable, "-c", SIGINT_IN_A_CALLBACK], capture_output=True, text=True, timeout=60)
    assert (proc.returncode, proc.stdout, proc.stderr) == (0, "interrupted\n", "")


@pytest.mark.parametrize("stdout", ["Broken", "None"])
def test_an_interrupted_program_ends_with_130_whatever_its_stdout(stdout):
    """end_interrupted ends the program with status 130 and its one line even where the output cannot be flushed:
    its reader gone (the flush raises BrokenPipeError, as after Ctrl-C to a pipeline ``valvetrain ... | head``) or
    no standard output at all; it never returns."""
    code = f"""
import io, sys
from valvetrain.interruption import end_interrupted
class Broken(io.StringIO):
    def flush(self):
        raise BrokenPipeError(32, "Broken pipe")
sys.stdout = {"Broken()" if stdout == "Broken" else "None"}
end_interrupted()
print("returned", file=sys.stderr)
"""
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert (proc.returncode, proc.stderr) == (130, "error: interrupted\n")
