"""The ``valvetrain`` program as the console script and ``python -m valvetrain`` start it.

Ctrl-C at any moment ends it with one line, ``error: interrupted``, and exit status 130.  While the command line
is being imported (click, pydantic, numpy: most of the start-up) a SIGINT is only recorded: an exception raised
into the import machinery or a library's schema building comes out as an error of theirs, or as an "Exception
ignored" text, instead of an interruption; the program ends once the imports are done.  Then, while a command runs,
the handler raises KeyboardInterrupt and remembers the SIGINT, so that an error a library makes of it is the
interruption too (:class:`valvetrain.cli._Main`).  This module imports only :mod:`gc`, :mod:`os` and
:mod:`valvetrain.interruption` at the top.

The program's linear algebra runs in one thread of numpy's and scipy's OpenBLAS (:data:`BLAS_THREADS`, unless
``OPENBLAS_NUM_THREADS`` is set): its matrices are a few rows by a few, and its parallel work is done by the speed
sweeps' threads and the drawing processes.

The garbage collector does not run while the command line is imported, and then freezes what was imported
(``gc.freeze``): the command's collections do not look through the modules' objects again (a full collection of them
took about 0.2 s of processor time in a run of the built-in example).
"""

import gc
import os

from .interruption import Interruption, end_interrupted

BLAS_THREADS = {"OPENBLAS_NUM_THREADS": "1"}
"""The environment the program sets before numpy is imported, where not set already: OpenBLAS starts a thread a core
when it is loaded, which waits for work spinning, at the start and after each call (0.2-0.4 s of processor time in a
run of the built-in example, taken from the drawing processes' cores); the numbers are the same."""


def program() -> None:
    """Import the command line with the SIGINT recorded, end if it came, and run it (:func:`valvetrain.cli.program`)."""
    for name, value in BLAS_THREADS.items():
        os.environ.setdefault(name, value)
    Interruption.install(Interruption.record)
    gc.disable()
    from .cli import program as command
    gc.freeze()
    gc.enable()

    if Interruption.seen:
        end_interrupted()
    command()
