#!/usr/bin/env python
"""Write docs/checks.md, the table of every design check's code and texts, from the message catalogue
(src/valvetrain/locale/*.toml); tests/test_catalogue.py fails when the file is not the catalogue's table::

    PYTHONPATH=src python tools/check_codes.py
"""

from pathlib import Path

from valvetrain.locale import code_table

HEAD = """# Check codes

Every design check has a stable code; `[[accepted]]` names a check by its code (or by its record text, as printed
before the codes), and every check record of `results.json` carries `code`, `valve` (null for a check of the engine
or of a chapter) and `params`.  The texts are renderings of the code from the catalogue `src/valvetrain/locale/`
(`{name}` is a parameter).  This file is written by `python tools/check_codes.py`; do not edit it by hand.

"""

PATH = Path(__file__).parents[1] / "docs" / "checks.md"


def text():
    """The contents of docs/checks.md."""
    return HEAD + code_table() + "\n"


if __name__ == "__main__":
    PATH.write_text(text(), encoding="utf-8")
