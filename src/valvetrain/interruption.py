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


def interrupted_while_starting() -> NoReturn:
    """End a program interrupted before it did anything: the message, then exit status 130 at once.

    :func:`os._exit` because a KeyboardInterrupt may have passed through an ``exec`` of a string in an imported
    library, after which CPython ends a normal exit by killing itself with SIGINT instead of the status; there is
    nothing to clean up yet."""
    sys.stderr.write("error: interrupted\n")
    sys.stderr.flush()
    os._exit(130)
