"""The SIGINT of the ``valvetrain`` program: whether one came, and the handlers that record it or interrupt.

Python raises a SIGINT's KeyboardInterrupt wherever the main thread is; :class:`Interruption` remembers that it
came, so that an error a library makes of it is the interruption too, and delivers it again where Python could not
raise it.  :mod:`valvetrain.console` installs the recording handler before the command line is imported,
:mod:`valvetrain.cli` the interrupting one once a command runs.  This module imports nothing of the package.
"""

import _thread
import os
import signal
import sys
from typing import NoReturn


class Interruption:
    """Whether a SIGINT came (:attr:`seen`), and the two handlers: :meth:`record` it, or record it and
    :meth:`interrupt` with a KeyboardInterrupt."""

    seen = False

    @classmethod
    def record(cls, signum, frame) -> None:
        cls.seen = True

    @classmethod
    def interrupt(cls, signum, frame) -> NoReturn:
        cls.seen = True
        raise KeyboardInterrupt

    @classmethod
    def redeliver(cls, unraisable) -> None:
        """``sys.unraisablehook``: a KeyboardInterrupt raised where Python cannot pass it on (the SIGINT came while a
        weakref callback or a finaliser ran, e.g. in the garbage collector) is sent to the main thread again, so that
        it interrupts at the next statement instead of being printed as "Exception ignored" and lost.  Sent from a
        new thread: sent from this one, the handler would run inside this hook and be lost again."""
        if isinstance(unraisable.exc_value, KeyboardInterrupt):
            _thread.start_new_thread(_thread.interrupt_main, ())
        else:
            sys.__unraisablehook__(unraisable)

    @classmethod
    def install(cls, handler) -> None:
        """Install ``handler`` unless the SIGINT is handled otherwise already (a caller's own handler, or ignored);
        with :meth:`interrupt`, also :meth:`redeliver` for the KeyboardInterrupts Python cannot raise."""
        if signal.getsignal(signal.SIGINT) in (signal.default_int_handler, cls.record, cls.interrupt):
            signal.signal(signal.SIGINT, handler)
            if handler == cls.interrupt:
                sys.unraisablehook = cls.redeliver


def end_interrupted() -> NoReturn:
    """End an interrupted program: what it printed flushed, the message, then exit status 130 at once.

    Called before the program did anything, or once the command's own ``with`` blocks have cleaned up (the output
    folder's temporary folder removed, the drawing processes and the threads ended).  :func:`os._exit` because the
    interpreter's ending is not safe after an interruption: a KeyboardInterrupt that passed through an ``exec`` of a
    string in an imported library makes CPython end a normal exit by killing itself with SIGINT instead of the status,
    and the finalisation of a run interrupted in the middle of its work once ended in a SIGSEGV after the message (a
    test of the continuous integration, not reproduced in 140 interrupted runs here)."""
    for say in (lambda: sys.stdout.flush(), lambda: sys.stderr.write("error: interrupted\n"),
                lambda: sys.stderr.flush()):
        try:
            say()
        except (OSError, ValueError, AttributeError):   # a reader gone (a broken pipe), a stream closed or None
            pass
    os._exit(130)
