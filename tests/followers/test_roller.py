"""The roller follower (valvetrain.followers.roller): internal Hertz contact in a concave stretch, its undercut rule
and its pitch curve against the curvature of its sampled points."""

import numpy as np
import pytest

from valvetrain.followers import FLAT, RollerFollower

from conftest import seed000_law

E = 2.1e11
"""Steel on steel [Pa]."""


def test_a_roller_in_a_concave_stretch_is_internal_hertz_contact():
    """A roller of 10 mm in a hollow of 30 mm: the relative radius of internal contact is R1 R2 / (R1 - R2) =
    30 x 10 / 20 = 15 mm (Hertz), the stress of a flat face on a 15 mm convex radius; a hollow narrower than the
    roller gives no line contact (zero) and is no concave stretch it follows."""
    roller = RollerFollower(0.010)
    assert roller.contact_stress(800.0, -0.030, 0.012, E) == pytest.approx(FLAT.contact_stress(800.0, 0.015, 0.012, E),
                                                                         rel=1e-12)
    assert roller.contact_stress(800.0, -0.005, 0.012, E) == 0.0
    assert roller.concave(np.array([-0.030, -0.005, 0.02])).tolist() == [True, False, False]


def test_undercut_rule():
    """Undercut where the pitch curve's radius rho_min + R_r is positive but at most the roller's (Shang Hanji (1988),
    section 2.1)."""
    roller = RollerFollower(0.010)
    assert roller.undercut(-0.002) and roller.undercut(0.0) and not roller.undercut(0.001)


def test_the_roller_pitch_curve_radius_against_its_sampled_points():
    """The pitch curve's radius of curvature against the curvature of its points, by second differences."""
    law = seed000_law()
    roller = RollerFollower(0.012)
    theta = np.linspace(-0.5, -0.2, 2001)
    h, dh, d2h, _ = law.derivatives(theta)
    points, _, rho, _, depth = roller.pitch_curve(theta, 0.01975, h, dh, d2h)
    x, y = points
    dx, dy = np.gradient(x, theta), np.gradient(y, theta)
    ddx, ddy = np.gradient(dx, theta), np.gradient(dy, theta)
    numeric = (dx**2 + dy**2) ** 1.5 / (dx * ddy - dy * ddx)
    inner = slice(2, -2)
    assert depth == -0.012
    assert np.allclose(np.abs(numeric[inner]), np.abs(rho[inner]), rtol=1e-5)
