"""The worked examples in the docstrings are tests too (seed values named in each docstring)."""

import doctest
import importlib
import pkgutil

import pytest

import valvetrain

MODULES = sorted(m.name for m in pkgutil.walk_packages(valvetrain.__path__, "valvetrain.")
                 if m.name not in ("valvetrain.__main__",))


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples(name):
    module = importlib.import_module(name)
    result = doctest.testmod(module, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert result.failed == 0


def test_the_examples_exist():
    """The physics modules carry worked examples (a docstring example is a test that can fail)."""
    total = sum(doctest.testmod(importlib.import_module(n), report=False).attempted
                for n in ["valvetrain.flow", "valvetrain.geometry", "valvetrain.laws.kurz", "valvetrain.laws.polydyne"])
    assert total >= 15
