"""The textbook's worked example, examples/seed000-appendix-kurz.toml: the engine and inlet valve of the appendix of
Valve-train practical works (n.d.).  Tests that reproduce the manual's numbers, or edit its keys, start from this
file; the built-in example (:func:`valvetrain.specification.example_text`) is a whole engine of its own."""

import tomllib
from pathlib import Path

from valvetrain.design import run
from valvetrain.specification import load_spec, validate

PATH = Path(__file__).parents[1] / "examples" / "seed000-appendix-kurz.toml"


def appendix_text():
    """The appendix example's specification text."""
    return PATH.read_text(encoding="utf-8")


def appendix_spec():
    """The appendix example's specification."""
    return load_spec(PATH)


def appendix_data(**changes):
    """The appendix example as a dict, with ``changes`` applied: ``{"valves__intake__parts__cam_width_mm": 3.0}``;
    ``accepted`` is a list of tables."""
    data = tomllib.loads(appendix_text())
    for path, value in changes.items():
        *keys, last = path.split("__")
        node = data
        for k in keys:
            node = node.setdefault(k, {})
        node[last] = value
    return data


def appendix_design(**changes):
    """The design of :func:`appendix_data` with ``changes``."""
    return run(validate(appendix_data(**changes)))


def appendix_with(*replacements):
    """The appendix example's text with each (old, new) replaced once; each old text must be there."""
    text = appendix_text()
    for old, new in replacements:
        assert old in text, old
        text = text.replace(old, new, 1)
    return text


def appendix_cam():
    """The appendix example's [valves.intake.cam] table, as its text."""
    text = appendix_text()
    return text[text.index("[valves.intake.cam]"):text.index("# Drive, springs")]
