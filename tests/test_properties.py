"""Invariants of every lift law over the recommended ranges (hypothesis property tests)."""

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings, strategies as st
from scipy.integrate import quad

from valvetrain import flow, geometry
from valvetrain.laws import KurzLaw

from strategies import kurz_params, laws

SETTINGS = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.filter_too_much])


def _interior_points(law, n=40, margin=1e-5):
    theta = np.linspace(law.start, law.end, n + 2)[1:-1] + 0.37 * (law.end - law.start) / (n + 1)
    theta = theta[theta < law.end]
    far = np.min(np.abs(theta[:, None] - law.breakpoints[None, :]), axis=1) > margin
    return theta[far]


@SETTINGS
@given(laws())
def test_closure(law):
    """Zero lift at both ends of the event, and zero velocity unless the ramp starts with a velocity step (a
    constant-velocity ramp); zero everywhere on the base circle."""
    d = law.derivatives(np.array([law.start, law.end]))
    assert np.abs(d[0]).max() < 1e-10 * law.lift_max
    ramp = getattr(law, "ramp", None)
    if ramp is None or ramp.starts_at_rest:
        assert np.abs(d[1]).max() < 1e-10 * law.lift_max
    outside = law.derivatives(np.array([law.start - 0.1, law.end + 0.1, np.pi]))
    assert not outside.any()


@SETTINGS
@given(laws())
def test_continuity_at_junctions(law):
    """h and its derivatives up to the law's continuity order are continuous across every junction (C2 laws:
    Valve-train practical works (n.d.), (2.11)-(2.19); constant-acceleration and arc cams: C1, spec sections 3-5)."""
    eps = 1e-10
    inner = law.breakpoints[1:-1]
    left, right = law.derivatives(inner - eps), law.derivatives(inner + eps)
    scale = np.abs(law.derivatives(np.linspace(law.start, law.end, 721))).max(axis=1)
    for k in range(law.continuity + 1):
        assert np.abs(left[k] - right[k]).max() <= 1e-6 * scale[k] + 10 * eps * scale[min(k + 1, 3)]


@SETTINGS
@given(laws())
def test_derivatives_are_derivatives(law):
    """Velocity is the derivative of lift, acceleration of velocity, jerk of acceleration (central differences)."""
    theta = _interior_points(law)
    d = 1e-6
    hi, lo, mid = law.derivatives(theta + d), law.derivatives(theta - d), law.derivatives(theta)
    scale = np.abs(law.derivatives(np.linspace(law.start, law.end, 721))).max(axis=1)
    for k in range(3):
        numeric = (hi[k] - lo[k]) / (2 * d)
        assert np.allclose(numeric, mid[k + 1], rtol=1e-5, atol=1e-5 * scale[k + 1])


@SETTINGS
@given(laws())
def test_symmetry(law):
    theta = np.linspace(0.0, law.end, 97)
    a, b = law.derivatives(theta), law.derivatives(-theta)
    assert np.allclose(a[0], b[0], rtol=0, atol=1e-15)
    assert np.allclose(a[1], -b[1], rtol=0, atol=1e-14)
    assert np.allclose(a[2], b[2], rtol=0, atol=1e-12)


@SETTINGS
@given(laws(), st.floats(1.5, 2.5))
def test_flat_contour_reproduces_lift(law, r0_over_lift):
    """The support function of the flat-follower contour equals R0 + h (Shang Hanji (1988), eq. 2.15)."""
    heel = r0_over_lift * law.lift_max * 1.6 - law.ramp_height
    theta = np.linspace(-np.pi, np.pi, 20001)
    h, dh, d2h, _ = law.derivatives(theta)
    assume(geometry.flat_follower_curvature(heel, h, d2h).min() > 0)  # convex profile (Valve-train practical works (n.d.), corrections note 26: not always)
    p = geometry.flat_follower_contour(theta, heel, h, dh)
    probe = np.linspace(law.start, law.end, 41)
    u = np.stack([np.sin(probe), np.cos(probe)])
    assert np.abs((p.T @ u).max(axis=0) - (heel + law.lift(probe))).max() < 1e-8


@SETTINGS
@given(laws(), st.floats(50.0, 400.0))
def test_time_area_against_adaptive_quadrature(law, omega):
    """Gauss-Legendre time-area equals scipy's adaptive quadrature of the same curtain area."""
    area = lambda t: flow.curtain_area(law.valve_lift(t, 1.5), 0.035, np.pi / 4)  # noqa: E731
    ta = flow.time_area(area, law.start, law.end, omega, law.breakpoints)
    ref = quad(lambda t: float(area(np.array([t]))[0]), law.start, law.end, points=law.breakpoints[1:-1],
               limit=400, epsabs=0, epsrel=1e-12)[0] / omega
    assert ta == pytest.approx(ref, rel=1e-9)


def _kurz_by_linear_solve(p):
    """Kurz coefficients solved numerically from the continuity system (2.10)-(2.22) (independent of (2.23)-(2.34))."""
    f1, f2, f3, Z, w, h = p["phi1"], p["phi2"], p["phi3"], p["shape_factor"], p["ramp_velocity"], p["lift"]
    m = np.pi / (2 * f2)
    # unknowns: c11 c12 c21 c22 c31 c32 c33
    a = np.array([
        [f1, 0, f2, 1, 0, 0, 1],                          # (2.10)
        [0, 0, 0, 0, f3**4, f3**2, 1],                    # (2.12)
        [1, -np.pi / f1, 0, 0, 0, 0, 0],                  # (2.14)
        [1, np.pi / f1, -1, -m, 0, 0, 0],                 # (2.16)
        [0, 0, 1, 0, 4 * f3**3, 2 * f3, 0],               # (2.18)
        [0, 0, 0, m**2, 12 * f3**2, 2, 0],                # (2.20)
        [0, 0, 0, m**2, 0, 2 * Z, 0],                     # (2.22): -c22 m^2 = 2 Z c32
    ])
    b = np.array([h, 0, w, 0, 0, 0, 0])
    return dict(zip(["c11", "c12", "c21", "c22", "c31", "c32", "c33"], np.linalg.solve(a, b)))


@SETTINGS
@given(kurz_params(), st.floats(100.0, 500.0))
def test_kurz_agrees_with_independent_solution(p, omega):
    """Closed-form coefficients and extremes agree with a numerical solution of the continuity system."""
    law = KurzLaw(**p)
    ref = _kurz_by_linear_solve(p)
    coef = law.coefficients()
    for key, val in ref.items():
        assert coef[key] * 1e-3 == pytest.approx(val, rel=1e-9, abs=1e-15)
    e = law.extremes(omega)
    # (2.35): max velocity at the end of Phi1; (2.37): min acceleration at the nose
    assert e.max_velocity == pytest.approx(omega * (ref["c11"] + ref["c12"] * np.pi / p["phi1"]), rel=1e-6)
    assert e.min_acceleration == pytest.approx(2 * omega**2 * ref["c32"], rel=1e-6)
    # (2.36), unless the cosine ramp starts with a larger acceleration w'^2/h0 (eq. 2.5 at phi = 0)
    j1 = omega**2 * ref["c12"] * (np.pi / p["phi1"]) ** 2
    assert e.max_acceleration == pytest.approx(max(j1, omega**2 * p["ramp_velocity"] ** 2 / p["clearance"]), rel=1e-6)
