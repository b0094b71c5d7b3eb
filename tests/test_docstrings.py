"""The worked examples in the docstrings are tests too (seed values named in each docstring); every public function
and public method says what it returns."""

import ast
import doctest
import importlib
from pathlib import Path
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


def test_every_public_function_has_a_return_annotation():
    """A function of a module of the package whose name has no leading underscore (a stage, a formula, a command, a
    compiled kernel), and a public method of a public class (a law's, a follower's, a result's), says what it returns
    in its signature; found by reading the source, so that a decorator (click, numba, a cache, a property) hides
    none."""
    def public(nodes):
        return [n for n in nodes if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef)) and not n.name.startswith("_")]

    missing = []
    for path in sorted(Path(valvetrain.__file__).parent.rglob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        classes = [c for c in ast.walk(tree) if isinstance(c, ast.ClassDef) and not c.name.startswith("_")]
        functions = public(tree.body) + [f for c in classes for f in public(c.body)]
        missing += [f"{path.relative_to(Path(valvetrain.__file__).parent)}:{f.lineno} {f.name}"
                    for f in functions if f.returns is None]
    assert missing == []
