"""docs/architecture.md describes every package of valvetrain and every module at the package's top; the tests are laid
out like the package."""

import re
from pathlib import Path

import valvetrain

ROOT = Path(valvetrain.__file__).parent
TEXT = (Path(__file__).parents[1] / "docs" / "architecture.md").read_text(encoding="utf-8")
TESTS = Path(__file__).parent

NO_TEST_FILE_YET = ()
"""Modules whose tests are not yet in the file named after them (issue 23): this allowance only shrinks; a new
module comes with its test file."""


def test_every_package_and_top_module_is_described():
    packages = [p.name for p in ROOT.iterdir() if (p / "__init__.py").exists()] + ["data"]
    missing = [f"{name}/" for name in packages if f"`{name}/" not in TEXT]
    missing += [p.name for p in ROOT.glob("*.py") if f"`{p.name}`" not in TEXT]
    assert not missing, missing


def _test_file(module):
    """Where the tests of ``module`` (a path below the package) are: design/drive.py -> tests/design/test_drive.py."""
    return TESTS.joinpath(*module.parts[:-1], f"test_{module.name}")


def test_every_module_has_its_test_file():
    """A contributor changing design/drive.py finds its tests by name, in tests/design/test_drive.py: every module of
    the package (but __init__ and __main__) has the test file of its name at its place, holding tests."""
    modules = sorted(p.relative_to(ROOT) for p in ROOT.rglob("*.py") if p.name not in ("__init__.py", "__main__.py"))
    missing = [m.as_posix() for m in modules if not _test_file(m).exists()]
    assert not set(missing) - set(NO_TEST_FILE_YET), "add the test file of each module: " + ", ".join(
        f"{m} -> {_test_file(Path(m)).relative_to(TESTS.parent)}" for m in missing if m not in NO_TEST_FILE_YET)
    stale = sorted(set(NO_TEST_FILE_YET) - set(missing))
    assert not stale, f"these have their test file now, remove them from NO_TEST_FILE_YET: {stale}"
    empty = [m.as_posix() for m in modules if _test_file(m).exists()
             and not re.search(r"^\s*def test_", _test_file(m).read_text(encoding="utf-8"), flags=re.M)]
    assert not empty, f"test files without a test: {empty}"



def test_the_map_is_a_page():
    """Issue 41: the architecture map is a page a newcomer reads in five minutes (at most 1,200 words); the detail is
    in each package's docstring."""
    assert len(TEXT.split()) <= 1200
