"""The spring formulas (springs/formulas.py): stress, coils, rate, surge frequency and fatigue safety of a helical
valve spring (Valve-train practical works (n.d.), work 6), against a textbook example and the formulas of other works."""

import numpy as np
import pytest

from valvetrain import springs

from conftest import SEED000_OMEGA_EXACT


def test_bhandari_example_11_1():
    """V. B. Bhandari, Design of Machine Elements (Tata McGraw-Hill), Example 11.1: P = 1250 N, deflection
    30 mm, index 6, G = 81370 N/mm2, tau = 0.5 x 1090 = 545 N/mm2, square and ground ends.
    Printed results: Wahl K = 1.2525, d = 6.63 mm -> 7 mm, D = 42 mm, N = 7.91 -> 8 active coils."""
    k = float(springs.wahl_factor(6.0))
    assert k == pytest.approx(1.2525, abs=5e-5)
    # tau = K 8 P C / (pi d^2) = 545 MPa solved for d (eq. 6.1 with D = C d)
    d = np.sqrt(k * 8 * 1250.0 * 6.0 / (np.pi * 545e6))
    assert d * 1e3 == pytest.approx(6.63, abs=0.005)
    assert springs.shear_stress(1250.0, 6 * d, d, k) == pytest.approx(545e6, rel=1e-12)
    n = springs.active_coils(81370e6, 7e-3, 30e-3, 1250.0, 42e-3)
    assert n == pytest.approx(7.91, abs=0.005)
    # rate of the rounded spring: G d^4 / (8 D^3 N) with N = 8: 1250 N now deflects it 30 x 8/7.91 mm
    rate = springs.spring_rate(81370e6, 7e-3, 42e-3, 8.0)
    assert 1250.0 / rate * 1e3 == pytest.approx(30.0 * 8.0 / 7.911, abs=0.005)


def test_shape_factor_table_is_close_to_wahl():
    """The manual's chi table (eq. 6.1) lies below the formula of Wahl (1944): by 5.1 % at D/d = 3, by under 1.9 % from
    4 to 12 (independent evaluation of both)."""
    c, chi = springs.SHAPE_FACTOR_TABLE
    rel = chi / springs.wahl_factor(c) - 1.0
    assert np.all(rel < 0)
    assert rel[0] == pytest.approx(-0.0506, abs=1e-4)
    assert np.max(np.abs(rel[1:])) < 0.019
    assert float(springs.shape_factor_table(3.5)) == pytest.approx(1.44)  # linear interpolation of (3, 1.5), (4, 1.38)
    assert np.isnan(springs.shape_factor_table(2.5))


def test_natural_frequency_reading():
    """(6.13) reading [A] agrees within 1.2 % with Kolchin and Demidov (1980)'s n_c = 2.17e7 d/(i D^2) min^-1 (spec work
    6)."""
    d, D, i = 4e-3, 30e-3, 6.0
    w = springs.natural_frequency(d, D, i, 8.0e10, 7850.0)
    kolchin = 2.17e7 * 4.0 / (i * 30.0**2) * np.pi / 30.0
    assert w == pytest.approx(kolchin, rel=0.012)


def test_fatigue_without_mean_stress_factor():
    """Valve-train practical works (n.d.), corrections note 24: without a mean-stress reduction (psi_tau = 1) n = tau_-1/(tau_a + tau_m) = tau_-1/tau_max, below 1.2
    for tau_max > 333 MPa at tau_-1 = 400 MPa; psi_tau = 0.2 gives tau_-1/(tau_a + 0.2 tau_m)."""
    assert springs.fatigue_safety(340e6, 100e6, 400e6, 1.0) == pytest.approx(400 / 340)
    assert springs.fatigue_safety(340e6, 100e6, 400e6, 1.0) < 1.2
    assert springs.fatigue_safety(340e6, 100e6, 400e6, 0.2) == pytest.approx(400 / (120 + 0.2 * 220))


def test_surge_frequency_is_bought_with_stress():
    """omega_c1 = pi tau_max / (chi f_max sqrt(2 rho G)), from (6.1), (6.2) and (6.13) with the actual (rounded)
    coils, for every candidate of a grid; so a resonance ratio needs a stress independent of d and D."""
    line = springs.Characteristic(270.0, 58e3, 0.010)
    material = springs.SpringMaterial("VDSiCr")
    found = springs.evaluate_springs(line.preload, line.rate, line.lift, np.linspace(0.02, 0.034, 15)[:, None],
                                     springs.wire_series()[None, :], material, SEED000_OMEGA_EXACT)
    ok = np.isfinite(found.shape_factor)
    f_max = (found.preload + found.rate * line.lift) / found.rate
    stress = springs.resonance_stress(found.resonance_ratio, SEED000_OMEGA_EXACT, f_max, found.shape_factor,
                                      material.shear_modulus, material.density)
    assert np.allclose(stress[ok], found.tau_max[ok], rtol=1e-12)
