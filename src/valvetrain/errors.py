"""The one base of the errors valvetrain raises on purpose.

Every error the package raises for a reason it can name (an input outside its range, a file it cannot read, a design
that admits no solution) is a :class:`ValvetrainError`, so that a program calling valvetrain catches them all with
one ``except ValvetrainError`` and tells them from the bugs (any other exception).  Where the error concerns a key of
the specification, ``key`` holds its dotted path (``valves.intake.cam.kurz.phi1_deg``), else None.

The errors of bad values are also ``ValueError`` (:class:`InputError` and the errors of files, laws and tables), so
that the pydantic validators of the specification, which turn a ``ValueError`` into a problem of the file, and the
callers that catch ``ValueError`` keep working.

Examples
--------
>>> from valvetrain.errors import InputError, ValvetrainError
>>> err = InputError("must be positive (got -1.0)", key="valves.intake.clearance_mm")
>>> isinstance(err, ValvetrainError), isinstance(err, ValueError), err.key
(True, True, 'valves.intake.clearance_mm')
"""

from typing import Optional


class ValvetrainError(Exception):
    """An error valvetrain raises on purpose; ``key`` is the dotted key path of the specification it concerns, or
    None."""

    key: Optional[str] = None

    def __init__(self, *args, key: Optional[str] = None):
        super().__init__(*args)
        if key is not None:
            self.key = key


class InputError(ValvetrainError, ValueError):
    """A value a function of valvetrain does not accept: the message names the quantity, the value and the range
    allowed."""
