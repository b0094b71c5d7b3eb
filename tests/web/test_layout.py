"""The designer's page built (web/layout.py) without a browser."""

from pathlib import Path

import pytest

pytest.importorskip("bokeh")

from valvetrain.web.draw import WORDS  # noqa: E402

from designer_page import _designer  # noqa: E402

EXAMPLES = Path(__file__).parents[2] / "examples"


def test_a_specification_without_valves_opens_with_its_engine_and_checks():
    path = EXAMPLES / "v8-crank.toml"
    d = _designer(path.read_text(encoding="utf-8"), path.parent)
    assert d.valve is None and [p.title for p in d.spec_tabs.tabs] == ["Engine"]
    assert any(k.startswith("crank") or "torque" in k for k in d.checks.data["key"])
    assert d.status.text == WORDS["en"]["no_valves"]
