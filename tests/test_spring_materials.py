"""Spring wire grades (spring_materials.py): tensile strength A/d^m, allowable stress and the Goodman line of each
grade (Shigley's Mechanical Engineering Design, 9th ed. (2011), Tables 10-4 and 10-6, section 10-9)."""

import numpy as np
import pytest

from valvetrain import spring_materials, springs


def test_wire_grades():
    """60S2A is the manual's steel with the middle of its ranges (Valve-train practical works (n.d.), work 6); the VD
    grades follow Shigley's Mechanical Engineering Design, 9th ed. (2011), Table 10-4 (R_m = A/d^m), Table 10-6 ([tau] =
    0.5 R_m) and section 10-9 (S_su = 0.67 R_m, Goodman line through Zimmerli's peened point): the manual's n of eq.
    (6.12) is 1 exactly at that point (tau_m = 534 MPa, tau_a = 398 MPa, i.e. tau_max = 932 MPa, tau_min = 136 MPa) for
    every wire."""
    seed = springs.SpringMaterial()
    allowable, endurance, psi = seed.limits(np.array([2.8e-3, 6e-3]))
    assert (seed.shear_modulus, seed.density) == (8e10, 7850.0)
    assert np.all(allowable == 500e6) and np.all(endurance == 370e6) and np.all(psi == 0.2)
    d = springs.wire_series()
    for grade, a, m in (("VDSiCr", 1974.0, 0.108), ("VDCrV", 2005.0, 0.168)):
        material = springs.SpringMaterial(grade)
        assert material.shear_modulus == 79.5e9
        allowable, endurance, psi = material.limits(d)
        rm = a / (d * 1e3) ** m * 1e6
        assert np.allclose(allowable, 0.5 * rm, rtol=1e-12)
        assert np.allclose(springs.fatigue_safety(932e6, 136e6, endurance, psi), 1.0, rtol=1e-12)
        # a thinner wire is stronger: a higher [tau]; the Goodman line through the fixed point then runs flatter
        assert np.all(np.diff(allowable) < 0) and np.all(np.diff(psi) > 0)
    # chrome-silicon is the stronger wire, by 7 % at 4 mm: 1974/4^0.108 against 2005/4^0.168
    assert spring_materials.GRADES["VDSiCr"].tensile_strength(4e-3) / 1e6 == pytest.approx(1699.5, abs=0.1)
    assert spring_materials.GRADES["VDCrV"].tensile_strength(4e-3) / 1e6 == pytest.approx(1588.4, abs=0.1)
