"""The ``valvetrain`` program as the console script and ``python -m valvetrain`` start it.

Ctrl-C at any moment ends it with one line, ``error: interrupted``, and exit status 130.  The SIGINT handler is
installed here, before the command line is imported (click, pydantic, numpy: most of the start-up), which is why
this module imports nothing of the package at the top.  A library may turn the KeyboardInterrupt into an error of
its own (pydantic building a schema, a compiled extension, a callback that catches it), so the handler remembers
the SIGINT and any error after it is the interruption too; the command group does the same while a command runs
(:class:`valvetrain.cli._Main`).
"""

import os
import signal
import sys


class Interruption:
    """Whether a SIGINT came (:attr:`seen`), and the handler that records it and raises KeyboardInterrupt."""

    seen = False

    @classmethod
    def handler(cls, signum, frame):
        cls.seen = True
        raise KeyboardInterrupt

    @classmethod
    def install(cls):
        """Install :meth:`handler` unless the SIGINT is handled otherwise already (a caller's own, or ignored)."""
        if signal.getsignal(signal.SIGINT) is signal.default_int_handler:
            signal.signal(signal.SIGINT, cls.handler)


def interrupted_while_starting():
    """End a program interrupted before it did anything: the message, then exit status 130 at once.

    :func:`os._exit` because the interruption may have passed through an ``exec`` of a string in an imported
    library, after which CPython ends a normal exit by killing itself with SIGINT instead of the status; there is
    nothing to clean up yet."""
    sys.stderr.write("error: interrupted\n")
    sys.stderr.flush()
    os._exit(130)


def program():
    """Import the command line, interruptible, and run it (:func:`valvetrain.cli.program`)."""
    Interruption.install()
    try:
        from .cli import program as command
    except BaseException:
        if not Interruption.seen:
            raise
        interrupted_while_starting()
    command()
