"""Outputs unchanged: every shipped example (the built-in one and examples/*.toml) is run and its results.json,
tables, contours and report text are compared with the fingerprints stored in tests/data/outputs/ (numbers to a
relative 1e-9, text exactly; tools/compare_outputs.py says how).  The stored fingerprints are the outputs of the
tree at the commit that wrote them; a deliberate change of the outputs refreshes them with

    PYTHONPATH=src python tools/compare_outputs.py expected tests/data/outputs

and its commit message says which values changed and why.

The outputs do not depend on the machine: a tie between equal extremes is decided by order, not by round-off
(valvetrain.numerics.first_largest), and the location of an extremum that Brent's method refines is compared to the
precision the method gives (tools/compare_outputs.py, EXTREMUM_ATOL).  test_outputs_do_not_depend_on_the_blas_kernel
runs the examples that were once sensitive with another OpenBLAS kernel; every example under every kernel this CPU
runs, and numba compiled for a generic CPU, is checked with

    PYTHONPATH=src python tools/compare_outputs.py machines
"""

import importlib.util
import json
import math
from pathlib import Path

from importlib.resources import files

import jsonschema
import pytest

ROOT = Path(__file__).parents[1]
EXPECTED = Path(__file__).parent / "data" / "outputs"

_spec = importlib.util.spec_from_file_location("compare_outputs", ROOT / "tools" / "compare_outputs.py")
compare_outputs = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(compare_outputs)

SCHEMA = json.loads(files("valvetrain").joinpath("data/results.schema.json").read_text(encoding="utf-8"))
"""The schema of results.json the package ships."""


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    """Every example run once, its outputs (but the figures) written into a folder of its name."""
    out = tmp_path_factory.mktemp("outputs")
    compare_outputs.write(out, report=True)
    return out


@pytest.fixture(scope="module")
def made(written):
    """The fingerprints of this tree's outputs."""
    return {d.name: compare_outputs.fingerprint(d) for d in sorted(written.iterdir())}


def test_every_example_has_expected_outputs(made):
    assert sorted(made) == sorted(p.stem for p in EXPECTED.glob("*.json"))


@pytest.mark.parametrize("name", sorted(p.stem for p in EXPECTED.glob("*.json")))
def test_outputs_unchanged(made, name):
    want = json.loads((EXPECTED / f"{name}.json").read_text(encoding="utf-8"))
    differences = compare_outputs.compare(want, made[name], name)
    assert not differences, "\n".join(differences[:40])


@pytest.mark.parametrize("name", sorted(p.stem for p in EXPECTED.glob("*.json")))
def test_every_example_s_results_json_validates_against_the_schema(written, name):
    """The results.json each example writes is an instance of the shipped schema (tests/specification/test_schema.py
    holds the schema to the generated one and shows that it refuses a wrong record)."""
    jsonschema.validate(json.loads((written / name / "results.json").read_text(encoding="utf-8")), SCHEMA)


def test_compare_sees_a_change_in_the_tenth_digit():
    """The comparison itself: 60 and 60.0000001 differ (relative 1.7e-9 > 1e-9), 60 and 60 + 1e-13 do not; a text
    cell differs exactly; a sampled column whose unsampled rows change is caught by its sums."""
    assert compare_outputs.compare({"a": 60.0}, {"a": 60.0000001})
    assert not compare_outputs.compare({"a": 60.0}, {"a": 60.0 + 1e-13})
    assert compare_outputs.compare({"a": "ramp"}, {"a": "ramp opening"})
    column = [float(i) for i in range(100)]
    changed = column[:1] + [column[1] + 0.5] + column[2:]       # row 1 is not among the sampled rows (every 5th)
    assert compare_outputs.compare(compare_outputs._numbers(column), compare_outputs._numbers(changed))


SENSITIVE = ("measured-lobe", "seed000-polydyne", "ukrsurt2019-diesel")
"""The examples whose outputs differed between OpenBLAS kernels (a symmetric cam's equal maxima, a duplicate spring
line, the polar contour across a jump of the velocity, flat extrema's locations)."""


def test_outputs_do_not_depend_on_the_blas_kernel(made):
    """The sensitive examples made in a subprocess with OpenBLAS's Prescott kernel (SSE3: another order of the sums
    of every matrix product than an AVX2 machine's, so other round-off) have the fingerprints of this run."""
    found = compare_outputs.fingerprints_with("OPENBLAS_CORETYPE=Prescott", list(SENSITIVE))
    differences = [line for name in SENSITIVE for line in compare_outputs.compare(made[name], found[name], name)]
    assert not differences, "\n".join(differences[:40])


def test_angles_and_extrema_locations_have_their_own_tolerance():
    """An angle near zero may differ by the round-off of the angles of a turn it comes from (7e-12 deg seen between
    two kernels), not by 1e-9 deg; the location of a Brent-refined extremum by sqrt(eps) of a turn (5.4e-6 deg),
    not by 1e-5 deg; any other number keeps RTOL and ATOL (a length near zero)."""
    assert not compare_outputs.compare({"crank_deg": -0.001628606305}, {"crank_deg": -0.001628606312})
    assert compare_outputs.compare({"crank_deg": -0.001628606305}, {"crank_deg": -0.001628608305})
    assert not compare_outputs.compare({"rho_min_cam_deg": 0.3510682389}, {"rho_min_cam_deg": 0.3510682949})
    assert compare_outputs.compare({"rho_min_cam_deg": 0.3510682389}, {"rho_min_cam_deg": 0.3510782389})
    assert compare_outputs.compare({"x_mm": -0.001628606305}, {"x_mm": -0.001628606312})
    column = {"sampled": [0.1, -0.001628606305, 2.0], "n": 3, "sum": 2.098371393695, "abs": 2.101628606305}
    moved = {**column, "sampled": [0.1, -0.001628606312, 2.0]}
    assert not compare_outputs.compare({"crank_deg": column}, {"crank_deg": moved})
    assert compare_outputs.compare({"x_mm": column}, {"x_mm": moved})


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
