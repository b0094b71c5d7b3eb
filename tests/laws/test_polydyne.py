"""Polydyne cam: closed forms of Valve-train practical works (n.d.), work 3, end conditions, the ramp junction."""

from fractions import Fraction

import numpy as np
import pytest

from valvetrain.laws import PolydyneLaw, PolynomialLaw, default_exponents, polydyne_coefficients
from valvetrain.laws.polydyne import _falling, polynomial_junction_coefficients

from conftest import SEED000_OMEGA_EXACT


@pytest.mark.parametrize("p", [6, 8, 10, 12, 14, 16, 7.5])
def test_end_conditions_and_sum(p):
    """h(1) = h'(1) = h''(1) = h'''(1) = h''''(1) = 0 and 1 + sum C = 0 (Valve-train practical works (n.d.), (3.4)-(3.8))."""
    k = np.array((2.0,) + default_exponents(p))
    c = np.array(polydyne_coefficients(*default_exponents(p)))
    assert 1.0 + c.sum() == pytest.approx(0.0, abs=1e-12)
    for j in range(1, 5):
        assert float((c * _falling(k, j)).sum()) == pytest.approx(0.0, abs=1e-9 * float(np.abs(c * _falling(k, j)).max()))
    # alternating signs: C2 < 0, Cp > 0, Cq < 0, Cr > 0, Cs < 0 (Valve-train practical works (n.d.), work 3)
    assert list(np.sign(c)) == [-1, 1, -1, 1, -1]


def test_law_closes_at_the_ends():
    law = PolydyneLaw(6.25e-3, np.deg2rad(71.0), 8)
    d = law.derivatives(np.array([law.start, law.end]))
    assert np.abs(d).max() < 1e-12


def test_seed000_inputs():
    """Polydyne p = 8 on the appendix inputs (Valve-train practical works (n.d.), work 3; spec/valvetrain-works-1-8.md,
    4.5)."""
    law = PolydyneLaw(6.25e-3, np.deg2rad(71.0), 8)
    c = law.coefficients()
    expected = {"C2": -1.87243, "Cp": 1.87243, "Cq": -1.60494, "Cr": 0.74897, "Cs": -0.14403}
    for key, val in expected.items():
        assert c[key] == pytest.approx(val, abs=5e-6)
    assert (c["p"], c["q"], c["r"], c["s"]) == (8, 14, 20, 26)
    e = law.extremes(SEED000_OMEGA_EXACT)
    assert e.max_velocity == pytest.approx(3.4385, abs=1e-4)
    assert e.max_acceleration == pytest.approx(4585.5, abs=0.1)
    # at x = 0.809 measured from the nose
    assert abs(e.max_acceleration_angle) / law.main_half_angle == pytest.approx(0.809, abs=1e-3)
    assert e.min_acceleration == pytest.approx(-2047.6, abs=0.1)
    # closed form at the nose: j = 2 C2 h omega^2 / phi_p0^2 (Valve-train practical works (n.d.), eq. 3.3 at x = 0)
    assert e.min_acceleration == pytest.approx(2 * c["C2"] * 6.25e-3 * SEED000_OMEGA_EXACT**2 / np.deg2rad(71.0) ** 2,
                                               rel=1e-9)


def test_larger_p_raises_acceleration():
    """Spec 4.5, effect of p: j_max 3786, 4585, 5447, 6333 and j_min -2691, -2048, -1770, -1617 for p = 6...12."""
    jmax = {6: 3786, 8: 4585, 10: 5447, 12: 6333}
    jmin = {6: -2691, 8: -2048, 10: -1770, 12: -1617}
    for p in jmax:
        e = PolydyneLaw(6.25e-3, np.deg2rad(71.0), p).extremes(SEED000_OMEGA_EXACT)
        assert e.max_acceleration == pytest.approx(jmax[p], abs=1.0)
        assert e.min_acceleration == pytest.approx(jmin[p], abs=1.0)


def test_junction_solver_reduces_to_closed_form():
    """With no ramp the 5x5 junction system gives h_max x (3.4)-(3.8) (spec methods, section 7: 2.2e-14)."""
    exps = default_exponents(10)
    a = polynomial_junction_coefficients((2.0,) + exps, 7.0, 0.0, 0.0)
    assert np.allclose(a, 7.0 * np.array(polydyne_coefficients(*exps)), rtol=1e-10, atol=1e-12)


def _exact_solution(matrix, rhs):
    """The solution of ``matrix x = rhs`` (floats, read as the exact binary fractions they are) by Gauss-Jordan
    elimination in rational arithmetic, each x the fraction it is exactly."""
    a = [[Fraction(v) for v in row] + [Fraction(b)] for row, b in zip(matrix, rhs, strict=True)]
    n = len(a)
    for i in range(n):
        pivot = next(r for r in range(i, n) if a[r][i] != 0)
        a[i], a[pivot] = a[pivot], a[i]
        for r in range(n):
            if r != i:
                f = a[r][i] / a[i][i]
                a[r] = [x - f * y for x, y in zip(a[r], a[i], strict=True)]
    return [a[i][n] / a[i][i] for i in range(n)]


@pytest.mark.parametrize("exponents", [(2.0, 8.0, 14.0, 20.0, 26.0), (2.0, 10.0, 18.0, 26.0, 34.0),
                                       (2.0, 6.5, 11.0, 15.5, 20.0, 24.5)])
def test_junction_coefficients_are_the_exact_solution_rounded(exponents):
    """The junction system solved exactly (Fractions, an independent method) and rounded to the nearest floats gives
    the package's coefficients bit for bit: LAPACK in double precision differed in the 14th digit, and by the BLAS
    kernel of the processor (OPENBLAS_CORETYPE=Haswell against an AVX-512 machine's own), which moved the breathing
    results of examples/phaser.toml in the 5th digit."""
    k = np.array(exponents)
    matrix = [_falling(k, j).tolist() for j in range(k.size)]
    rhs = [0.3 - 9.0, -0.5] + [0.0] * (k.size - 2)
    want = [float(x) for x in _exact_solution(matrix, rhs)]
    assert polynomial_junction_coefficients(exponents, 9.0, 0.3, -0.5).tolist() == want


def test_ramp_junction_worked_example():
    """Shang Hanji (1988), section 2.6, worked example (spec section 7): h_max 8, h0 0.3, v0 0.4 mm/rad, alpha_B 55 deg,
    exponents 2, 10, 18, 26, 34: junction values (0.3, -0.4, 0, 0, 0), h'' in [-26.77, 80.59] mm/rad^2."""
    law = PolydyneLaw(7.7e-3, np.deg2rad(55.0), 10, 18, 26, 34, ramp_height=0.3e-3, ramp_velocity=0.4e-3)
    junction = law.end - law.ramp_angle
    h, dh, d2h, _ = law.derivatives(np.array([junction - 1e-12, junction + 1e-12])) * 1e3
    assert h == pytest.approx([0.3, 0.3], abs=1e-9)
    assert dh == pytest.approx([-0.4, -0.4], abs=1e-6)
    assert d2h == pytest.approx([0.0, 0.0], abs=1e-6)
    e = law.extremes(1.0)
    assert e.max_acceleration * 1e3 == pytest.approx(80.59, abs=0.01)
    assert e.min_acceleration * 1e3 == pytest.approx(-26.77, abs=0.01)


def test_bad_exponents_refused():
    with pytest.raises(ValueError, match="3 <= p < q < r < s"):
        PolydyneLaw(6e-3, 1.0, 8, q=7)
    with pytest.raises(ValueError, match="jerk infinite"):
        PolydyneLaw(6e-3, 1.0, 2.5)


@pytest.mark.parametrize("exponents", [(2, 8, 14, 20, 26), (2, 6.5, 13.0, 17.25, 30.0), (3, 6, 10)])
def test_law_against_an_independent_polynomial_evaluation(exponents):
    """Independent computation: h = h_nose + sum a_k x^k and its theta-derivatives term by term (x = |theta| /
    phi_p0, odd derivatives odd in theta) in 80-bit arithmetic, for integer and fractional exponent steps, and the
    cosine ramp (2.5) of Valve-train practical works (n.d.); the compiled law agrees to 1e-13 of each row's scale (the round-off of the
    alternating sum)."""
    law = PolynomialLaw(6.0e-3, np.deg2rad(65.0), exponents, ramp_height=0.3e-3, ramp_velocity=0.015e-3 * 180 / np.pi)
    theta = np.linspace(-law.main_half_angle, law.main_half_angle, 4001)[1:-1]  # the jerk jumps at the ramp
    L = np.longdouble
    x = np.abs(theta).astype(L) / L(law.phi_p0)
    rows = [np.full(x.size, L(law.lift_max + law.ramp_height))] + [np.zeros(x.size, dtype=L) for _ in range(3)]
    for a, k in zip(law._a.astype(L), np.array(exponents, dtype=L), strict=True):
        for j in range(4):
            rows[j] += a * _falling(k, j) * x ** (k - j) if k >= j else 0.0
    ref = np.array([r / L(law.phi_p0) ** j * L(np.sign(t) if j % 2 else 1.0) for j, (r, t) in
                    enumerate(zip(rows, [theta] * 4, strict=True))], dtype=float)
    got = law.derivatives(theta)
    assert np.all(np.abs(got - ref).max(axis=1) <= 1e-13 * np.abs(ref).max(axis=1))
    ramp = law.derivatives(np.array([law.start + 0.3 * law.ramp_angle]))[:, 0]
    k = np.pi / (2.0 * law.ramp_angle)
    h0, s, c = law.ramp_height, np.sin(0.3 * np.pi / 2), np.cos(0.3 * np.pi / 2)
    assert ramp == pytest.approx([h0 * (1 - c), h0 * k * s, h0 * k**2 * c, -h0 * k**3 * s], rel=1e-14)


def test_polynomial_generalises_polydyne():
    """The 5-exponent polynomial law with (2, p, q, r, s) is the polydyne law (Shang Hanji (1988), section 2.6; spec
    section 7)."""
    a = PolynomialLaw(6.25e-3, np.radians(71), [2, 8, 14, 20, 26])
    b = PolydyneLaw(6.25e-3, np.radians(71), 8)
    theta = np.linspace(-1.3, 1.3, 101)
    assert np.allclose(a.derivatives(theta), b.derivatives(theta), rtol=1e-9, atol=1e-15)
    # seven exponents: lift, slope and five more derivatives vanish at the start
    c = PolynomialLaw(6e-3, np.radians(65), [2, 6, 10, 14, 18, 22, 26])
    scale = np.abs(c.derivatives(np.linspace(c.start, c.end, 721))).max(axis=1)
    assert np.all(np.abs(c.derivatives(np.array([c.start]))[:, 0]) < 1e-10 * scale)
    with pytest.raises(ValueError, match="each 2 or >= 3"):
        PolynomialLaw(6e-3, 1.0, [2, 2.5, 8])
