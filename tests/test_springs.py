"""Valve springs: characteristic (seed 000 work 5) and design (work 6), with a textbook spring example."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from valvetrain import masses, springs

from conftest import SEED000_OMEGA_EXACT, seed000_law


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
    """The manual's chi table (eq. 6.1) lies below Wahl's formula: by 5.1 % at D/d = 3, by under 1.9 % from 4 to 12
    (independent evaluation of both)."""
    c, chi = springs.SHAPE_FACTOR_TABLE
    rel = chi / springs.wahl_factor(c) - 1.0
    assert np.all(rel < 0)
    assert rel[0] == pytest.approx(-0.0506, abs=1e-4)
    assert np.max(np.abs(rel[1:])) < 0.019
    assert float(springs.shape_factor_table(3.5)) == pytest.approx(1.44)  # linear interpolation of (3, 1.5), (4, 1.38)
    assert np.isnan(springs.shape_factor_table(2.5))


def test_natural_frequency_reading():
    """(6.13) reading [A] agrees within 1.2 % with Kolchin's n_c = 2.17e7 d/(i D^2) min^-1 (spec work 6)."""
    d, D, i = 4e-3, 30e-3, 6.0
    w = springs.natural_frequency(d, D, i, 8.0e10, 7850.0)
    kolchin = 2.17e7 * 4.0 / (i * 30.0**2) * np.pi / 30.0
    assert w == pytest.approx(kolchin, rel=0.012)


def test_fatigue_without_mean_stress_factor():
    """E24: without a mean-stress reduction (psi_tau = 1) n = tau_-1/(tau_a + tau_m) = tau_-1/tau_max, below 1.2
    for tau_max > 333 MPa at tau_-1 = 400 MPa; psi_tau = 0.2 gives tau_-1/(tau_a + 0.2 tau_m)."""
    assert springs.fatigue_safety(340e6, 100e6, 400e6, 1.0) == pytest.approx(400 / 340)
    assert springs.fatigue_safety(340e6, 100e6, 400e6, 1.0) < 1.2
    assert springs.fatigue_safety(340e6, 100e6, 400e6, 0.2) == pytest.approx(400 / (120 + 0.2 * 220))


def test_gas_force():
    # eq. (5.4): pi/4 * 0.031^2 * (0.106 - 0.085) MPa = 15.85 N; no force when the cylinder pressure is higher
    assert springs.gas_opening_force(0.031, 0.106e6, 0.085e6) == pytest.approx(15.85, abs=0.01)
    assert springs.gas_opening_force(0.031, 0.100e6, 0.115e6) == 0.0


def test_characteristic_relations():
    """(5.6)-(5.9): f_max = f_min + h; the nested split keeps the sums (5.10)-(5.12)."""
    c = springs.Characteristic(300.0, 60e3, 0.010)
    assert c.max_force == pytest.approx(900.0)
    assert c.max_deflection == pytest.approx(c.preload_deflection + 0.010)
    outer, inner = c.split(0.4)
    assert outer.preload + inner.preload == pytest.approx(c.preload)
    assert outer.rate + inner.rate == pytest.approx(c.rate)
    assert inner.max_force == pytest.approx(0.4 * c.max_force)


def _requirement(law, mass, reserve=1.8, ratio=1.6):
    theta = np.linspace(law.valve_opens, law.valve_closes, 2001)
    y = law.valve_lift(theta, ratio)
    a = ratio * SEED000_OMEGA_EXACT**2 * law.derivatives(theta)[2]
    return y, springs.required_spring_force(mass, a, reserve)


@settings(max_examples=40, deadline=None)
@given(st.floats(0.05, 0.4), st.floats(1.5, 2.25), st.floats(0.0, 400.0))
def test_envelope_property(mass, reserve, gas):
    """The line is above the requirement everywhere and touches it at least once (issue 3)."""
    y, req = _requirement(seed000_law(), mass, reserve)
    p0, c = springs.enveloping_line(y, req, min_preload=gas)
    line = p0 + c * y
    assert np.all(line >= req - 1e-6 * req.max())
    touching = np.min(line - req) <= 1e-6 * req.max()
    assert touching or p0 == pytest.approx(gas)
    ratio = (p0 + c * y.max()) / p0
    assert 1.6 - 1e-9 <= ratio <= 3.2 + 1e-9
    assert p0 >= gas - 1e-9


def test_envelope_is_steepest_line_through_full_lift_when_ratio_allows():
    """With the ratio bound slack the optimum goes through c' (full lift) and is tangent below it (Fig. 5.1)."""
    y, req = _requirement(seed000_law(), 0.16)
    p0, c = springs.enveloping_line(y, req, ratio_range=(1.0, 100.0))
    top = np.argmax(y)
    assert p0 + c * y[top] == pytest.approx(req[top], rel=1e-9)
    below = y < y[top] - 1e-9
    # the linear programme meets its constraints to HiGHS's feasibility tolerance, not to round-off
    assert c == pytest.approx(np.min((req[top] - req[below]) / (y[top] - y[below])), rel=1e-4)


def test_closed_form_envelope_is_the_linear_programme():
    """The closed-form line of enveloping_line is the optimum of the linear programme of its docstring, solved
    independently with scipy's HiGHS: the same smallest P_max and, of the optimal lines, the steepest (largest
    C at that P_max).  Requirements of the seed 000 appendix cam at random masses, reserves and gas forces."""
    from scipy.optimize import linprog

    rng = np.random.default_rng(10)
    law = seed000_law()
    for _ in range(20):
        y, req = _requirement(law, rng.uniform(0.05, 0.4), rng.uniform(1.5, 2.25))
        gas = rng.choice([0.0, rng.uniform(0.0, 600.0)])
        ratios = tuple(rng.choice([(1.6, 3.2), (1.0, 100.0), (2.0, 2.5)]))
        p0, c = springs.enveloping_line(y, req, ratios, gas)
        h = y.max()
        a_ub = np.vstack([np.column_stack([-np.ones_like(y), -y]), [[ratios[0] - 1.0, -h], [1.0 - ratios[1], h]]])
        b_ub = np.concatenate([-req, [0.0, 0.0]])
        bounds = [(gas, None), (0.0, None)]
        lp = linprog([1.0, h], A_ub=a_ub, b_ub=b_ub, bounds=bounds, method="highs")
        assert p0 + c * h == pytest.approx(lp.fun, rel=1e-6)
        steep = linprog([0.0, -1.0], A_ub=np.vstack([a_ub, [[1.0, h]]]), b_ub=np.append(b_ub, lp.fun * (1 + 1e-9)),
                        bounds=bounds, method="highs")
        # HiGHS meets the constraints to its feasibility tolerance, not to round-off
        assert c == pytest.approx(steep.x[1], rel=1e-4)


def test_design_picks_the_lightest_passing_spring():
    line = springs.Characteristic(150.0, 25e3, 0.009)
    material = springs.SpringMaterial(min_resonance_ratio=5.0)
    best, n_pass = springs.design_spring(line, 0.034, material, 300.0)
    assert n_pass > 0 and best.passes
    # every lighter candidate of the search space fails a check
    for D in np.arange(0.7 * 0.034, 0.9 * 0.034, 0.5e-3):
        for d in springs.WIRE_SERIES_MM:
            s = springs.evaluate_spring(line, D, d * 1e-3, material, 300.0)
            if s is not None and s.mass < best.mass - 1e-12:
                assert not s.passes
    # the actual line (rounded coils) still envelops the required one
    assert best.characteristic.rate >= line.rate
    assert best.characteristic.preload == pytest.approx(line.preload)
    assert best.binding_check in best.checks


def test_a_zero_minimum_switches_a_check_off():
    """min_resonance_ratio = 0 is allowed (the check off): its margin is infinite, never a division by zero."""
    line = springs.Characteristic(150.0, 25e3, 0.009)
    s = springs.evaluate_spring(line, 0.03, 0.004, springs.SpringMaterial(min_resonance_ratio=0.0), 300.0)
    assert s.margins["resonance_ratio"] == np.inf
    assert s.binding_check != "resonance_ratio"


def test_spring_mass_and_reduced_masses():
    # rho (pi d^2 / 4) pi D i: 7850 * pi/4 * 0.004^2 * pi * 0.03 * 8
    assert masses.spring_mass(0.03, 0.004, 8, 7850.0) == pytest.approx(7850 * np.pi**2 / 4 * 16e-6 * 0.03 * 8)
    m_v = masses.reduced_mass_at_valve(0.05, 0.02, 0.005, 0.045, 0.06, 0.04, 4e-5, 0.04, 1.6)
    # (5.2) term by term; (7.2) = (5.2) x i_k^2
    assert m_v == pytest.approx(0.05 + 0.02 + 0.005 + 0.015 + 4e-5 / 0.04**2 + 0.1 / 1.6**2)
    assert masses.reduced_mass_at_tappet(m_v, 1.6) == pytest.approx(
        0.06 + 0.04 + 4e-5 / 0.025**2 + (0.05 + 0.02 + 0.005 + 0.015) * 1.6**2)
