"""The measured-lobe example, examples/measured-lobe.toml, and its table: the tests of the table law and of the
browser designer's control points start from them."""

from pathlib import Path
import re

EXAMPLE = Path(__file__).parents[1] / "examples" / "measured-lobe.toml"
EXAMPLE_TABLE = EXAMPLE.parent / "data" / "measured-intake-lobe.csv"
"""Valve lift every 2 crank deg from -70 to 300: the lobe of the appendix of Valve-train practical works (n.d.) x 1.6, 3 crank deg late, 2 um noise."""


def inline_text(angle, lift, text=None):
    """The measured-lobe example (or ``text``) with its table inline (``table_angles_deg``, ``table_lifts_mm``)
    instead of its file."""
    lines = (f"table_angles_deg = [{', '.join(f'{a:g}' for a in angle)}]\n"
             f"table_lifts_mm = [{', '.join(f'{h:.4f}' for h in lift)}]")
    return re.sub(r"^table_file = .*$", lambda _: lines, text or EXAMPLE.read_text(), flags=re.MULTILINE)
