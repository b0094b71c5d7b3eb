"""Boundary fuzzing of the newer features (tools/fuzz_bounds.py): the finger follower's keys, [lash_adjuster],
[lubrication] and [camshaft] at, just inside and just outside their declared bounds, and as NaN, inf, zero and huge,
through ``load_spec -> design.run`` and through ``valvetrain.api``; each case runs to finite, plausible results or is
refused with messages naming their keys.  A bounded draw here (a few seconds); ``python tools/fuzz_bounds.py`` runs
every case."""

import math

from hypothesis import given, settings, strategies as st
import pytest

from fuzz_contract import BASES, FUZZ, assert_contract, fuzz_bounds

FINGER = "examples/modern-dohc-roller-finger.toml"
PUSHROD = "examples/pushrod-dynamics.toml"
NEW_SECTIONS = ("lash_adjuster", "lubrication", "camshaft", "finger_pad_arm_mm", "finger_pivot_y_mm",
                "finger_valve_angle_deg")
CASES = [c for part in NEW_SECTIONS for base in (FINGER, PUSHROD)
         for c in fuzz_bounds.bound_cases(base, BASES[base][0], part)]
API_CASES = [c for part in ("lash_adjuster", "lubrication") for c in fuzz_bounds.api_cases(FINGER, BASES[FINGER][0],
                                                                                           part)]


def _assert_contract(case):
    assert_contract(case, timeout=120.0)


def test_the_fields_carry_the_models_bounds():
    """The bounds read from the models: air_content [0, 0.5] and oil_viscosity_mPa_s (0.1, 2000] of
    models.LashAdjuster, finger_valve_angle_deg [-180, 180] of the cam, drive_pitch_radius_mm [2, 1000] of
    [camshaft]; the keys the file leaves at their defaults are there too (bulk_modulus_GPa, finger_tip_offset_mm)."""
    fields = {p: b for p, b, _ in fuzz_bounds.numeric_fields(BASES[FINGER][0])}
    lash = ("valves", "intake", "lash_adjuster")
    assert fields[lash + ("air_content",)] == (0.0, 0.5, False, False)
    assert fields[lash + ("oil_viscosity_mPa_s",)] == (0.1, 2000.0, True, False)
    assert fields[lash + ("bulk_modulus_GPa",)] == (0.1, 5.0, True, False)
    assert fields[("valves", "intake", "cam", "finger_valve_angle_deg")] == (-180.0, 180.0, False, False)
    assert ("valves", "intake", "cam", "finger_tip_offset_mm") in fields
    pushrod = {p: b for p, b, _ in fuzz_bounds.numeric_fields(BASES[PUSHROD][0])}
    assert pushrod[("camshaft", "drive_pitch_radius_mm")] == (2.0, 1000.0, False, False)


def test_edge_values_reach_just_outside_the_bounds():
    """[0, 0.5] gives 0 and 0.5 (inside) and -1e-6 and 0.5005 (outside: 1e-3 of the bound, at least 1e-6); an open
    lower bound 0.1 gives 0.1001 inside and 0.1 itself outside."""
    def has(values, *wanted):
        return all(any(v == pytest.approx(w, rel=1e-12) for v in values) for w in wanted)

    values = fuzz_bounds.edge_values((0.0, 0.5, False, False), "float", 0.02)
    assert has(values, 0.0, 0.5, -1e-6, 0.5005, 0.01, 0.04) and any(math.isnan(v) for v in values)
    assert has(fuzz_bounds.edge_values((0.1, 2000.0, True, False), "float", 8.0), 0.1001, 0.0999, 0.1)


@settings(FUZZ, max_examples=8)
@given(st.sampled_from(CASES))
def test_a_key_at_its_bounds_runs_or_is_refused(case):
    _assert_contract(case)


@settings(FUZZ, max_examples=12)
@given(st.sampled_from(API_CASES))
def test_the_api_takes_a_key_at_its_bounds_or_names_it(case):
    _assert_contract(case)
