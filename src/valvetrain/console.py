"""The ``valvetrain`` program as the console script and ``python -m valvetrain`` start it.

Ctrl-C at any moment ends it with one line, ``error: interrupted``, and exit status 130.  While the command line
is being imported (click, pydantic, numpy: most of the start-up) a SIGINT is only recorded: an exception raised
into the import machinery or a library's schema building comes out as an error of theirs, or as an "Exception
ignored" text, instead of an interruption; the program ends once the imports are done.  Then, while a command runs,
the handler raises KeyboardInterrupt and remembers the SIGINT, so that an error a library makes of it is the
interruption too (:class:`valvetrain.cli._Main`).  This module imports nothing of the package at the top.
"""

import os
import signal
import sys


class Interruption:
    """Whether a SIGINT came (:attr:`seen`), and the two handlers: :meth:`record` it, or record it and
    :meth:`interrupt` with a KeyboardInterrupt."""

    seen = False

    @classmethod
    def record(cls, signum, frame):
        cls.seen = True

    @classmethod
    def interrupt(cls, signum, frame):
        cls.seen = True
        raise KeyboardInterrupt

    @classmethod
    def install(cls, handler):
        """Install ``handler`` unless the SIGINT is handled otherwise already (a caller's own handler, or ignored)."""
        if signal.getsignal(signal.SIGINT) in (signal.default_int_handler, cls.record, cls.interrupt):
            signal.signal(signal.SIGINT, handler)


def interrupted_while_starting():
    """End a program interrupted before it did anything: the message, then exit status 130 at once.

    :func:`os._exit` because a KeyboardInterrupt may have passed through an ``exec`` of a string in an imported
    library, after which CPython ends a normal exit by killing itself with SIGINT instead of the status; there is
    nothing to clean up yet."""
    sys.stderr.write("error: interrupted\n")
    sys.stderr.flush()
    os._exit(130)


def program():
    """Import the command line with the SIGINT recorded, end if it came, and run it (:func:`valvetrain.cli.program`)."""
    Interruption.install(Interruption.record)
    from .cli import program as command

    if Interruption.seen:
        interrupted_while_starting()
    command()
