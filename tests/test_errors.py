"""Every error valvetrain raises on purpose derives from one base (issue 41)."""

import builtins
import importlib
import inspect
from pathlib import Path
import pickle
import pkgutil
import re

import pytest

import valvetrain
from valvetrain.errors import InputError, ValvetrainError


def _modules():
    for info in pkgutil.walk_packages(valvetrain.__path__, "valvetrain."):
        if info.name == "valvetrain.__main__":   # runs the program when imported
            continue
        if info.name.startswith("valvetrain.web"):
            pytest.importorskip("bokeh")
        yield importlib.import_module(info.name)


def test_every_error_class_of_the_package_derives_from_the_base():
    """An exception class defined anywhere in the package is a ValvetrainError: a caller catches every error raised
    on purpose with one except clause (issue 41, 'one error base')."""
    errors = {f"{cls.__module__}.{cls.__qualname__}": cls for module in _modules()
              for _, cls in inspect.getmembers(module, inspect.isclass)
              if issubclass(cls, BaseException) and cls.__module__ == module.__name__}
    assert len(errors) >= 14   # the package's own error classes when this test was written
    assert [name for name, cls in errors.items() if not issubclass(cls, ValvetrainError)] == []


def test_the_key_path_survives_a_worker_process():
    """Errors cross process boundaries in study and tolerance: the key goes with the message."""
    err = pickle.loads(pickle.dumps(InputError("must be positive (got -1.0)", key="valves.intake.clearance_mm")))
    assert (str(err), err.key, isinstance(err, ValueError)) == (
        "must be positive (got -1.0)", "valves.intake.clearance_mm", True)
    assert ValvetrainError("no key").key is None


def test_an_error_no_command_handles_is_one_line_not_a_traceback(monkeypatch, tmp_path):
    """An error raised on purpose deep in a design reaches the user as its one line led by its key, exit status 1."""
    from click.testing import CliRunner

    import valvetrain.design
    from valvetrain.cli import main

    def refuse(spec, progress=None):
        raise InputError("must be below 50 mm (got 80.0)", key="valves.intake.lift_mm")

    monkeypatch.setattr(valvetrain.design, "run", refuse)
    result = CliRunner().invoke(main, ["run", "--out", str(tmp_path / "design"), "--figures", "none"])
    assert (result.exit_code, result.stderr) == (1, "error: valves.intake.lift_mm: must be below 50 mm (got 80.0)\n")


def test_no_builtin_error_is_raised_on_purpose():
    """The source raises no bare ValueError, RuntimeError, KeyError or Exception: each error made on purpose is a
    ValvetrainError (an InputError for a value refused).  Allowed, where a protocol asks for them: the
    NotImplementedError of an interface's abstract method, the TypeError of json's default encoder, the
    AttributeError of a module's lazy ``__getattr__``, the KeyboardInterrupt of Ctrl-C, the ImportError of a missing
    optional extra and an OSError (or its kind) that mirrors the system's."""
    protocol = {"NotImplementedError", "TypeError", "AttributeError", "KeyboardInterrupt", "ImportError"}
    builtin = {name for name in dir(builtins) if isinstance(getattr(builtins, name), type)
               and issubclass(getattr(builtins, name), BaseException)
               and not issubclass(getattr(builtins, name), OSError)} - protocol
    root = Path(valvetrain.__file__).parent
    found = [f"{p.relative_to(root)}:{i}: {line.strip()}" for p in sorted(root.rglob("*.py"))
             for i, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1)
             if (m := re.search(r"\braise (\w+)\b", line)) and m.group(1) in builtin]
    assert found == [], found
