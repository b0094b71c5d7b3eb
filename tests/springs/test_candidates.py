"""Candidate springs designed as arrays (springs/candidates.py): the array checks agree with the check records, a
zero minimum switches a check off, a property given replaces the grade's."""

import numpy as np
import pytest

from valvetrain import springs
from valvetrain.errors import InputError

from conftest import SEED000_OMEGA_EXACT


def test_a_zero_minimum_switches_a_check_off():
    """min_resonance_ratio = 0 is allowed (the check off): its margin is infinite, never a division by zero."""
    line = springs.Characteristic(150.0, 25e3, 0.009)
    s = springs.evaluate_spring(line, 0.03, 0.004, springs.SpringMaterial(min_resonance_ratio=0.0), 300.0)
    assert s.margins["resonance_ratio"] == np.inf
    assert s.binding_check != "resonance_ratio"


def test_array_checks_agree_with_the_check_records():
    """Pass and margin of every candidate's checks as arrays are those of the valvetrain.checks.Check records."""
    line = springs.Characteristic(270.0, 58e3, 0.010)
    found = springs.evaluate_springs(line.preload, line.rate, line.lift, np.linspace(0.02, 0.034, 29)[:, None],
                                     springs.wire_series((2.0, 7.0), 0.25)[None, :], springs.SpringMaterial("VDCrV"),
                                     SEED000_OMEGA_EXACT, max_installed_length=0.06)
    for i in range(len(found)):
        design = found.design(i)
        assert design.passes == found.passed[i]
        assert min(design.margins.values()) == pytest.approx(found.worst_margin[i], rel=1e-12)


def test_the_working_coils_check_grades_the_coils_the_spring_is_made_with():
    """Issue 36: the check said 3.633 (the exact coils of eq. (6.2)) where the spring, and the report's table, have
    the 3.5 coils it is made with (rounded down to half coils); one number.  The verdict is the same: floor(2 i) / 2
    >= 2 exactly where i >= 2 (i = 1.99, 2.01, 2.49, 3.633 against 1.5, 2.0, 2.0, 3.5 by hand)."""
    g, rho = 7.9e10, 7850.0
    d, big_d, lift = 0.004, 0.03, 0.009
    one_coil = g * d**4 / (8.0 * big_d**3)              # the rate of one working coil, eq. (6.2)'s K
    for exact, made in ((1.99, 1.5), (2.01, 2.0), (2.49, 2.0), (3.633, 3.5)):
        rate = one_coil / exact
        found = springs.evaluate_springs(150.0, rate, lift, big_d, d, springs.SpringMaterial(
            "VDSiCr", shear_modulus=g, density=rho), 300.0)
        check = found.design(0).checks["working_coils"]
        assert found.coils[0] == pytest.approx(made, rel=1e-12) and check.value == pytest.approx(made, rel=1e-12)
        assert check.passed == (exact >= 2.0)


def test_a_property_given_replaces_the_grade_s():
    material = springs.SpringMaterial("vd-sicr", shear_modulus=8.1e10, allowable_stress=600e6)
    assert material.grade == "VDSiCr" and material.shear_modulus == 8.1e10
    allowable, endurance, _ = material.limits(np.array([3e-3, 5e-3]))
    assert np.all(allowable == 600e6) and endurance[0] < endurance[1]
    with pytest.raises(InputError, match="allowed '60S2A', 'VDSiCr', 'VDCrV'"):
        springs.SpringMaterial("65G")
