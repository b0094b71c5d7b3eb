"""docs/architecture.md describes every package of valvetrain and every module at the package's top."""

from pathlib import Path

import valvetrain

ROOT = Path(valvetrain.__file__).parent
TEXT = (Path(__file__).parents[1] / "docs" / "architecture.md").read_text(encoding="utf-8")


def test_every_package_and_top_module_is_described():
    packages = [p.name for p in ROOT.iterdir() if (p / "__init__.py").exists()] + ["data"]
    missing = [f"{name}/" for name in packages if f"`{name}/" not in TEXT]
    missing += [p.name for p in ROOT.glob("*.py") if f"`{p.name}`" not in TEXT]
    assert not missing, missing
