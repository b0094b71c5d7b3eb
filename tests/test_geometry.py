"""Cam contours: independent geometric checks of Shang Hanji (1988), section 2.1 formulas."""

import numpy as np
import pytest

from valvetrain import geometry
from valvetrain.crank.kinematics import displacement

from conftest import seed000_law

HEEL = 19.75e-3


def _dense(law, n=20001):
    theta = np.linspace(-np.pi, np.pi, n)
    return theta, law.derivatives(theta)


def test_flat_contour_support_function_is_the_lift():
    """A flat follower at angle theta touches the contour's supporting line: max p.u = R0 + h."""
    law = seed000_law()
    theta, (h, dh, d2h, _) = _dense(law)
    p = geometry.flat_follower_contour(theta, HEEL, h, dh)
    probe = np.linspace(-1.5, 1.5, 61)
    u = np.stack([np.sin(probe), np.cos(probe)])
    support = (p.T @ u).max(axis=0)
    expected = HEEL + law.lift(probe)
    # dense sampling: error of order (R * dtheta^2) ~ 1e-9 m
    assert np.abs(support - expected).max() < 1e-8


def test_flat_curvature_matches_contour():
    """rho = R0 + h + h'' (Shang Hanji (1988), eq. 2.6) against the curvature of the sampled contour."""
    law = seed000_law()
    theta = np.linspace(-1.2, 1.2, 200001)
    h, dh, d2h, _ = law.derivatives(theta)
    x, y = geometry.flat_follower_contour(theta, HEEL, h, dh)
    dx, dy = np.gradient(x, theta), np.gradient(y, theta)
    ddx, ddy = np.gradient(dx, theta), np.gradient(dy, theta)
    numeric = (dx**2 + dy**2) ** 1.5 / np.abs(dx * ddy - dy * ddx)
    rho = geometry.flat_follower_curvature(HEEL, h, d2h)
    inner = slice(1000, -1000)
    smooth = np.abs(np.diff(d2h, append=d2h[-1]))[inner] < 1e-6
    assert np.allclose(numeric[inner][smooth], rho[inner][smooth], rtol=1e-4)


def test_roller_contour_is_at_roller_radius_from_pitch_curve():
    """Every pitch point (roller centre) lies exactly one roller radius from the contour."""
    law = seed000_law()
    rr = 12e-3
    theta, (h, dh, d2h, _) = _dense(law, 8001)
    p = geometry.roller_follower_contour(theta, HEEL, rr, h, dh)
    g = geometry.roller_pitch_radius(HEEL, rr, h)
    c = g * np.stack([np.sin(theta), np.cos(theta)])
    idx = slice(0, None, 80)
    dist = np.hypot(p[0][None, :] - c[0][idx, None], p[1][None, :] - c[1][idx, None]).min(axis=1)
    assert np.allclose(dist, rr, atol=2e-8)


def test_roller_curvature_and_pressure_angle_of_circle_offset():
    """An eccentric circle cam (h = e(1 - cos)) has pitch radius R + R_r everywhere... for e = 0 it is the circle."""
    assert geometry.roller_follower_curvature(20.0, 10.0, 0.0, 0.0, 0.0) == pytest.approx(20.0)
    # tan(beta) = h'/g: h' = g gives 45 deg (definition, UkrSURT Proceedings (2019) via spec section 2)
    assert np.rad2deg(geometry.roller_pressure_angle(20.0, 10.0, 0.0, 30.0)) == pytest.approx(45.0)


def test_roller_pitch_curvature_matches_sampled_pitch_curve():
    law = seed000_law()
    rr = 10e-3
    theta = np.linspace(-1.2, 1.2, 200001)
    h, dh, d2h, _ = law.derivatives(theta)
    g = geometry.roller_pitch_radius(HEEL, rr, h)
    x, y = g * np.sin(theta), g * np.cos(theta)
    dx, dy = np.gradient(x, theta), np.gradient(y, theta)
    ddx, ddy = np.gradient(dx, theta), np.gradient(dy, theta)
    numeric = (dx**2 + dy**2) ** 1.5 / (dy * ddx - dx * ddy)
    formula = geometry.roller_pitch_curvature(HEEL, rr, h, dh, d2h)
    inner = slice(1000, -1000)
    smooth = np.abs(np.diff(d2h, append=d2h[-1]))[inner] < 1e-6
    assert np.allclose(numeric[inner][smooth], formula[inner][smooth], rtol=1e-4)


def test_undercut_masks():
    assert geometry.undercut_flat(np.array([1.0, 0.0, -1.0])).tolist() == [False, True, True]
    assert geometry.undercut_roller(np.array([15.0, 10.0, 5.0, -5.0]), 10.0).tolist() == [False, True, True, False]


def test_valve_piston_clearance_identity():
    """D_s = s + y0 - y (Shang Hanji (1988), eqs. 2.13-2.14): at TDC with the valve closed the gap is y0."""
    s = displacement(np.array([0.0, np.pi]), 0.04, 0.04 / 0.14)
    assert geometry.valve_piston_clearance(s, np.array([0.0, 0.01]), 0.002).tolist() == pytest.approx([0.002, 0.072])


