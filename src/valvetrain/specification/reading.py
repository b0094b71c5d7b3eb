"""Reading a specification: TOML text or a parsed document, a file, the built-in example; and writing it back.

Every problem in a file becomes one message naming the key, the value and what is allowed;
:func:`load_spec` raises :class:`SpecError` carrying them all.
"""

from importlib.resources import files
from pathlib import Path
import re
import tomllib

import tomli_w

from ..files import read_text, shown_path
from ..locale import NoteText, note
from .messages import WHOLE_FILE, Problem, SpecError, shown
from .engine_sections import resolve_path
from .models import Spec, validate


def input_files(spec) -> list[Path]:
    """Every file the specification names (each ``..._file`` key: lift tables, indicator diagrams), resolved."""
    def named(node):
        if isinstance(node, dict):
            for key, value in node.items():
                if key.endswith("_file") and isinstance(value, str):
                    yield resolve_path(spec, value)
                else:
                    yield from named(value)
        elif isinstance(node, list):
            for value in node:
                yield from named(value)

    return sorted(set(named(spec.model_dump())))


MAX_SPEC_CHARACTERS = 1_000_000
"""Largest specification text read (the largest shipped example has about 6,000 characters; a lift table or an
indicator diagram belongs in a file of its own)."""


_AT_LINE = re.compile(r"\(at line (\d+), column \d+\)$")
"""Where :mod:`tomllib` says its error is, at the end of its message."""

_DECIMAL_COMMA = re.compile(r"=\s*[-+]?\d+,\d+\s*(#.*)?$")
"""A value written with a decimal comma (``max_lift_mm = 10,5``)."""


def _quoted_line(text, error) -> str:
    """The line of ``text`` that :mod:`tomllib`'s ``error`` names, as appended to its message (``: 'the line'``, and
    what a decimal comma should be), or ``""`` where it names none."""
    found = _AT_LINE.search(str(error))
    lines = text.removeprefix("\ufeff").split("\n")  # tomllib counts the newlines
    if found is None or not 0 < int(found.group(1)) <= len(lines):
        return ""
    line = lines[int(found.group(1)) - 1].strip()
    hint = "; a number's decimals follow a point, not a comma" if _DECIMAL_COMMA.search(line) else ""
    return f": {shown(line)}{hint}"


def toml_tables(text, source="<string>") -> dict:
    """The tables of the TOML text of a specification (:func:`tomllib.loads`, a leading byte-order mark dropped).

    Raises
    ------
    SpecError
        Text longer than :data:`MAX_SPEC_CHARACTERS`, not TOML, or nested deeper than the parser's recursion, named
        by ``source``; a ``[valves]`` table naming no valve (the valves' tables left out under it: a file without
        valves leaves out ``[valves]``).
    """
    if len(text) > MAX_SPEC_CHARACTERS:
        raise SpecError([Problem(source, f"{len(text):,} characters; allowed at most {MAX_SPEC_CHARACTERS:,} for a "
                                 "specification (put long tables in a CSV file: cam.table_file, crank.pressure_file)")])
    try:
        tables = tomllib.loads(text.removeprefix("\ufeff"))
    except tomllib.TOMLDecodeError as exc:
        raise SpecError([Problem(source, NoteText(note("spec.not_toml", error=f"{exc}{_quoted_line(text, exc)}")))]) \
            from None
    except RecursionError:
        raise SpecError([Problem(source, NoteText(note("spec.nested_too_deeply")))]) from None
    if tables.get("valves") == {}:
        raise SpecError([Problem("valves", NoteText(note("spec.empty_valves")))])
    return tables


def parse_spec(text, source="<string>", source_dir=None) -> Spec:
    """Parse and validate a specification: TOML text, or a document already parsed (a dict of its tables, as
    :func:`tomllib.loads` gives it); relative file names in it are read from ``source_dir``."""
    if isinstance(text, dict):
        return validate(text if source_dir is None else {**text, "source_dir": str(source_dir)})
    if not isinstance(text, str):
        raise SpecError([Problem(source, "a specification is TOML text or a dict of its tables, not a "
                                 f"{type(text).__name__}")])
    data = toml_tables(text, source)
    if source_dir is not None and isinstance(data, dict):
        data["source_dir"] = str(source_dir)
    try:
        return validate(data)
    except SpecError as err:
        raise SpecError([Problem(source, p.message, p.value) if p.path == WHOLE_FILE else p
                         for p in err.problems]) from None


def load_spec(path) -> Spec:
    """Read and validate a specification file."""
    try:
        text = read_text(path)
    except OSError as exc:
        said = NoteText(note("spec.unreadable", error=f"{exc.strerror or exc}"))
        raise SpecError([Problem(shown_path(path), said)]) from None
    except UnicodeDecodeError as exc:
        raise SpecError([Problem(shown_path(path), NoteText(note("spec.not_utf8", reason=exc.reason)))]) from None
    return parse_spec(text, shown_path(path), Path(path).resolve().parent)


def example_text() -> str:
    """The built-in example specification (the engine of the appendix of Valve-train practical works (n.d.)), as TOML text."""
    return files("valvetrain").joinpath("data/example.toml").read_text(encoding="utf-8")


def example_spec() -> Spec:
    """The built-in example, validated."""
    return parse_spec(example_text(), "built-in example")


def spec_toml(spec) -> str:
    """The specification as TOML text with every default written out and every file named by its absolute path:
    what a run used, saved beside its results (``spec.toml``), which ``valvetrain run`` reads back."""
    def absolute(node):
        if isinstance(node, dict):
            return {k: str(resolve_path(spec, v).resolve()) if k.endswith("_file") and isinstance(v, str)
                    else absolute(v) for k, v in node.items()}
        if isinstance(node, list):
            return [absolute(v) for v in node]
        return node

    from .. import __version__

    header = (f"# The specification of a valvetrain {__version__} run, every default written out and every file "
              "named by its\n# absolute path: `valvetrain run spec.toml` repeats the run.\n\n")
    empty = set() if spec.valves else {"valves"}  # a design without valves: no [valves] table (toml_tables)
    return header + tomli_w.dumps(absolute(spec.model_dump(exclude_none=True, exclude={"source_dir"} | empty)))
