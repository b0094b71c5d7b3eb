"""``python -m valvetrain`` is the ``valvetrain`` command."""

from .console import program

program()
