"""``python -m valvetrain`` is the ``valvetrain`` command."""

from .cli import main

main()
