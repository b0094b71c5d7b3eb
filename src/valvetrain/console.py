"""The ``valvetrain`` program as the console script and ``python -m valvetrain`` start it.

Ctrl-C at any moment ends it with one line, ``error: interrupted``, and exit status 130.  While the command line
is being imported (click, pydantic, numpy: most of the start-up) a SIGINT is only recorded: an exception raised
into the import machinery or a library's schema building comes out as an error of theirs, or as an "Exception
ignored" text, instead of an interruption; the program ends once the imports are done.  Then, while a command runs,
the handler raises KeyboardInterrupt and remembers the SIGINT, so that an error a library makes of it is the
interruption too (:class:`valvetrain.cli._Main`).  This module imports only :mod:`valvetrain.interruption` at
the top.
"""

from .interruption import Interruption, interrupted_while_starting


def program() -> None:
    """Import the command line with the SIGINT recorded, end if it came, and run it (:func:`valvetrain.cli.program`)."""
    Interruption.install(Interruption.record)
    from .cli import program as command

    if Interruption.seen:
        interrupted_while_starting()
    command()
