"""Fixtures of the lost-motion tests (tests/design/test_lost_motion.py, test_lost_motion_breathing.py): the
lost-motion example and its design, made once per session."""

from pathlib import Path

import pytest

from valvetrain.design import run
from valvetrain.specification.reading import load_spec

EXAMPLE = Path(__file__).parents[2] / "examples" / "lost-motion-intake.toml"


@pytest.fixture(scope="session")
def spec():
    """examples/lost-motion-intake.toml, read."""
    return load_spec(EXAMPLE)


@pytest.fixture(scope="session")
def design(spec):
    """Its design (with the breathing)."""
    return run(spec)
