"""Strength of the drive parts (Valve-train practical works (n.d.), work 7) against analytic identities."""

import numpy as np
import pytest
from scipy.integrate import solve_bvp

from valvetrain import strength


def test_camshaft_deflection_is_beam_theory():
    """(7.3) with 64/(3 pi) equals the deflection under the load of a simply supported beam, obtained here
    independently by integrating EI w'' = -M(x) with scipy's boundary-value solver (Valve-train practical works (n.d.), corrections note 20)."""
    P, a, b, d, E = 6000.0, 0.03, 0.07, 0.026, 2.1e11
    L = a + b
    EI = E * np.pi * d**4 / 64

    def moment(x):
        return np.where(x <= a, P * b / L * x, P * a / L * (L - x))

    sol = solve_bvp(lambda x, w: np.vstack([w[1], -moment(x) / EI]), lambda wa, wb: np.array([wa[0], wb[0]]),
                    np.linspace(0, L, 401), np.zeros((2, 401)), tol=1e-10, max_nodes=100000)
    assert strength.camshaft_deflection(P, a, b, d) == pytest.approx(float(sol.sol(a)[0]), rel=1e-5)
    # the printed coefficient 0.8 underestimates by 64/(3 pi)/0.8 = 8.5 (Valve-train practical works (n.d.), corrections note 20)
    assert strength.DEFLECTION_COEFFICIENT / 0.8 == pytest.approx(8.49, abs=0.01)


def test_hertz_constant():
    """0.418 = sqrt(1 / (2 pi (1 - 0.3^2))) for equal moduli with E_m = 2E1E2/(E1+E2) (Shang Hanji (1988), eq. 2.5)."""
    assert np.sqrt(1.0 / (2 * np.pi * (1 - 0.3**2))) == pytest.approx(0.418, abs=5e-4)
    assert strength.effective_modulus(2.1e11, 2.1e11) == pytest.approx(2.1e11)
    # Hertz for two cylinders: sigma = sqrt(F E* / (pi b R)) with 1/E* = 2 (1 - nu^2)/E and 1/R = 1/r1 + 1/r2
    F, b, r1, r2, E = 2000.0, 0.015, 0.012, 0.010, 2.1e11
    e_star = E / (2 * (1 - 0.09))
    exact = np.sqrt(F * e_star * (1 / r1 + 1 / r2) / (np.pi * b))
    assert strength.hertz_line_stress(F, b, 1 / r1 + 1 / r2, E) == pytest.approx(exact, rel=2e-3)


def test_hertz_unloaded_cusp_carries_no_stress():
    """sigma ~ sqrt(F/rho): zero force gives zero stress even where the profile has a cusp (1/rho infinite), and a
    loaded cusp is infinitely stressed; 0 * inf must not turn into NaN."""
    sigma = strength.hertz_line_stress(np.array([0.0, 100.0, 0.0]), 0.015, np.array([np.inf, np.inf, 50.0]), 2.1e11)
    assert sigma[0] == 0.0 and sigma[1] == np.inf and sigma[2] == 0.0


def test_euler_load_and_sections():
    # pi^2 E I / l^2 with I = pi d^4 / 64; a tube loses (d_i/d)^4 of it
    d, di, l, E = 0.008, 0.005, 0.25, 2.1e11
    assert strength.euler_load(E, strength.second_moment(d), l) == pytest.approx(np.pi**3 * E * d**4 / (64 * l**2))
    assert strength.second_moment(d, di) / strength.second_moment(d) == pytest.approx(1 - (di / d) ** 4)
    assert strength.section_modulus(0.02) == pytest.approx(np.pi * 0.02**3 / 32)


def test_rocker_shaft_readings():
    """(7.15) built-in P(l - b)/(8W) and the simply supported alternative P(2l - b)/(8W) (spec section 6)."""
    st = strength.rocker_shaft_stresses(2000.0, 0.045, 0.018, 0.02, 0.01)
    w = np.pi * (0.02**4 - 0.01**4) / (32 * 0.02)
    assert st["bending"] == pytest.approx(2000 * 0.027 / (8 * w))
    assert st["bending_simply_supported"] == pytest.approx(2000 * 0.072 / (8 * w))
    assert st["shear"] == pytest.approx(2000 / (2 * np.pi * (0.02**2 - 0.01**2) / 4))
    assert st["bearing"] == pytest.approx(2000 / (0.018 * 0.02))


def test_sphere_socket_and_pad():
    # (7.11): equal radii give zero stress (conforming contact); (7.13) scales with sqrt(P)
    assert strength.sphere_socket_stress(1000.0, 2.1e11, 0.004, 0.004) == 0.0
    assert strength.rocker_pad_stress(4000.0, 2.1e11, 0.009, 0.015) == pytest.approx(
        2 * strength.rocker_pad_stress(1000.0, 2.1e11, 0.009, 0.015))


def test_verdict_records():
    """A strength verdict is a Check against the limit of Valve-train practical works (n.d.), work 7, shown in its unit."""
    v = strength.verdict("pushrod_buckling_margin", 1.5)
    assert not v.passed and v.range == ">= 2" and v.severity == "failure"
    assert v.margin == pytest.approx(1.5 / 2.0 - 1.0)
    stress = strength.verdict("cam_contact_stress", 900e6)
    assert stress.passed and stress.range == "<= 1200 MPa" and stress.shown_value == pytest.approx(900.0)


def test_hertz_half_width_is_johnson_s_line_contact_band():
    """a = sqrt(4 F R / (pi b E*)) with 1/E* = 2 (1 - 0.3^2) / E (K. L. Johnson, Contact Mechanics, 1985, ch. 4),
    an independent computation; the 0.418 of Shang Hanji (1988)'s stress rounds the constant by 0.05 %."""
    force, width, radius, modulus = 1500.0, 0.016, 0.012, 2.1e11
    e_star = modulus / (2.0 * (1.0 - 0.3**2))
    a = np.sqrt(4.0 * force * radius / (np.pi * width * e_star))
    assert strength.hertz_half_width(force, width, 1.0 / radius, modulus) == pytest.approx(a, rel=1e-3)
    # the load over the band is the elliptic pressure's: F / b = pi a sigma / 2
    sigma = strength.hertz_line_stress(force, width, 1.0 / radius, modulus)
    assert np.pi * strength.hertz_half_width(force, width, 1.0 / radius, modulus) * sigma / 2.0 == pytest.approx(
        force / width)
    assert strength.hertz_half_width(-10.0, width, 1.0 / radius, modulus) == 0.0


def test_roller_side_force_is_the_normal_force_across_the_axis():
    """F_side = F_n sin(alpha) with F_n = F_axial / cos(alpha) (analytic identity), either sign of alpha."""
    alpha = np.radians([-25.0, 0.0, 10.0, 30.0])
    normal = 800.0 / np.cos(alpha)
    assert strength.roller_side_force(800.0, alpha) == pytest.approx(normal * np.abs(np.sin(alpha)))
