"""Outputs unchanged: every shipped example (the built-in one and examples/*.toml) is run and its results.json,
tables, contours and report text are compared with the fingerprints stored in tests/data/outputs/ (numbers to a
relative 1e-9, text exactly; tools/compare_outputs.py says how).  The stored fingerprints are the outputs of the
tree at the commit that wrote them; a deliberate change of the outputs refreshes them with

    PYTHONPATH=src python tools/compare_outputs.py expected tests/data/outputs

and its commit message says which values changed and why.
"""

import importlib.util
import json
import math
from pathlib import Path

import pytest

ROOT = Path(__file__).parents[1]
EXPECTED = Path(__file__).parent / "data" / "outputs"

_spec = importlib.util.spec_from_file_location("compare_outputs", ROOT / "tools" / "compare_outputs.py")
compare_outputs = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(compare_outputs)


@pytest.fixture(scope="module")
def made():
    """The fingerprints of this tree's outputs, every example run once."""
    return compare_outputs.fingerprints()


def test_every_example_has_expected_outputs(made):
    assert sorted(made) == sorted(p.stem for p in EXPECTED.glob("*.json"))


@pytest.mark.parametrize("name", sorted(p.stem for p in EXPECTED.glob("*.json")))
def test_outputs_unchanged(made, name):
    want = json.loads((EXPECTED / f"{name}.json").read_text(encoding="utf-8"))
    differences = compare_outputs.compare(want, made[name], name)
    assert not differences, "\n".join(differences[:40])


def test_compare_sees_a_change_in_the_tenth_digit():
    """The comparison itself: 60 and 60.0000001 differ (relative 1.7e-9 > 1e-9), 60 and 60 + 1e-13 do not; a text
    cell differs exactly; a sampled column whose unsampled rows change is caught by its sums."""
    assert compare_outputs.compare({"a": 60.0}, {"a": 60.0000001})
    assert not compare_outputs.compare({"a": 60.0}, {"a": 60.0 + 1e-13})
    assert compare_outputs.compare({"a": "ramp"}, {"a": "ramp opening"})
    column = [float(i) for i in range(100)]
    changed = column[:1] + [column[1] + 0.5] + column[2:]       # row 1 is not among the sampled rows (every 5th)
    assert compare_outputs.compare(compare_outputs._numbers(column), compare_outputs._numbers(changed))


def _bounds(made):
    for name, found in made.items():
        for c in found.get("results.json", {}).get("checks", []):
            for side in ("low", "high"):
                if c[side] is not None:
                    yield name, c["quantity"], side, c[side]


def _noisy(value):
    """A number at most 16 units in the last place away from a number of 12 significant digits, but not that number:
    the float noise of a unit conversion (60 deg -> rad -> 59.99999999999999 deg, one unit); 8/3 = 2.6666666666666665
    is 3e-13 (about 800 units) away from 2.66666666667 and no noise."""
    rounded = float(f"{value:.12g}")
    return rounded != value and abs(rounded - value) <= 16 * math.ulp(value)


def test_noise_is_recognised():
    assert _noisy(59.99999999999999) and _noisy(0.007999999999999998) and _noisy(121.80000000000001)
    assert not _noisy(60.0) and not _noisy(8.0 / 3.0) and not _noisy(1.0 / 3.6)


def test_bounds_carry_no_conversion_noise(made):
    """No bound of a check of any example carries the noise of a unit conversion (:func:`_noisy`): the bounds are
    shown as the sources and the specification write them (30 deg, not 29.999999999999996)."""
    noisy = [f"{name}: {quantity} {side} = {value!r}" for name, quantity, side, value in _bounds(made)
             if math.isfinite(value) and _noisy(value)]
    assert not noisy, "\n".join(noisy)
