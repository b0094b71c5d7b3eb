"""``python -m valvetrain`` is the ``valvetrain`` command."""

import sys

try:
    from .cli import program
except KeyboardInterrupt:  # Ctrl-C while the command line is being imported
    print("error: interrupted", file=sys.stderr)
    sys.exit(130)

program()
