#!/usr/bin/env python
"""The table of check codes and the entries of the message catalogue (src/valvetrain/locale/LANG.toml).

``python tools/check_codes.py`` writes docs/checks.md, the table of every design check's code and texts;
tests/locale/test_catalogue.py fails when the file is not the catalogue's table.  ``add`` puts a new check's texts into
every language's file and rewrites the table (a check added the old way, by its English text, is converted so)::

    PYTHONPATH=src python tools/check_codes.py
    PYTHONPATH=src python tools/check_codes.py add lash_adjuster.collapse "lash adjuster collapse" \\
        "lash adjuster collapse h_c" "просадка гидрокомпенсатора h_c"
"""

import argparse
import json
from pathlib import Path

from valvetrain.locale import LANGS, code_table

HEAD = """# Check codes

Every design check has a stable code; `[[accepted]]` names a check by its code (or by its record text, as printed
before the codes), and every check record of `results.json` carries `code`, `valve` (null for a check of the engine
or of a chapter) and `params`.  The texts are renderings of the code from the catalogue `src/valvetrain/locale/`
(`{name}` is a parameter).  This file is written by `python tools/check_codes.py`; do not edit it by hand.

"""

ROOT = Path(__file__).parents[1]
PATH = ROOT / "docs" / "checks.md"
LOCALE = ROOT / "src" / "valvetrain" / "locale"


def text():
    """The contents of docs/checks.md."""
    return HEAD + code_table() + "\n"


def insert(path, section, key, value):
    """``key = value`` appended to the table ``[section]`` of a catalogue file (its last entry's line)."""
    lines = path.read_text(encoding="utf-8").split("\n")
    start = lines.index(f"[{section}]")
    end = next((i for i in range(start + 1, len(lines)) if not lines[i].strip() or lines[i].startswith("[")),
               len(lines))
    lines.insert(end, f"{json.dumps(key, ensure_ascii=False)} = {json.dumps(value, ensure_ascii=False)}")
    path.write_text("\n".join(lines), encoding="utf-8")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = parser.add_subparsers(dest="command")
    add = sub.add_parser("add", help="a new check code with its record text and its report name in every language")
    add.add_argument("code")
    add.add_argument("record", help="the English text of the records (results.json quantity, [[accepted]])")
    add.add_argument("names", nargs=len(LANGS), help=f"the report's name in each language: {', '.join(LANGS)}")
    args = parser.parse_args()
    if args.command == "add":
        insert(LOCALE / "en.toml", "record", args.code, args.record)
        for lang, name in zip(LANGS, args.names, strict=True):
            insert(LOCALE / f"{lang}.toml", "checks", args.code, name)
    PATH.write_text(text(), encoding="utf-8")


if __name__ == "__main__":
    main()
