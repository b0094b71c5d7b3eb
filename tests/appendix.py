"""The textbook's worked example, examples/seed000-appendix-kurz.toml: the engine and inlet valve of the appendix of
Valve-train practical works (n.d.).  Tests that reproduce the manual's numbers, or edit its keys, start from this
file; the built-in example (:func:`valvetrain.specification.example_text`) is a whole engine of its own."""

from pathlib import Path

from valvetrain.specification import load_spec

PATH = Path(__file__).parents[1] / "examples" / "seed000-appendix-kurz.toml"


def appendix_text():
    """The appendix example's specification text."""
    return PATH.read_text(encoding="utf-8")


def appendix_spec():
    """The appendix example's specification."""
    return load_spec(PATH)
