"""The flat-faced follower (valvetrain.followers.flat): its contour, curvature, contact offset and pressure angle on an
eccentric disc against the disc itself, and its undercut rule."""

import numpy as np
import pytest

from valvetrain.followers import FLAT


def test_a_flat_face_on_an_eccentric_disc_touches_the_disc():
    """A disc of radius r whose centre c = e u(0) lies e off the camshaft axis lifts a flat face by its support
    function, R0 + h = r + e cos(theta) (R0 = r - e), so h' = -e sin(theta) and h'' = -e cos(theta).  By hand:
    p = (r + e cos) u - e sin t = (r sin, r cos + e), so every contour point lies on the disc, |p - c| = r; the
    radius of curvature R0 + h + h'' is r; the contact point is h' off the axis and the pressure angle is zero."""
    r, e = 0.020, 0.004
    theta = np.linspace(-np.pi, np.pi, 721)
    h, dh, d2h = r + e * np.cos(theta) - (r - e), -e * np.sin(theta), -e * np.cos(theta)
    p = FLAT.contour(theta, r - e, h, dh)
    assert np.hypot(p[0], p[1] - e) == pytest.approx(np.full(theta.size, r), rel=1e-14)
    assert FLAT.curvature(r - e, h, dh, d2h) == pytest.approx(np.full(theta.size, r), rel=1e-14)
    assert np.array_equal(FLAT.contact_offset(dh), dh) and not FLAT.pressure_angle(r - e, h, dh).any()


def test_undercut_rule():
    """Undercut at rho_min <= 0 (Shang Hanji (1988), eq. (2.6)): a flat face cannot follow a concave stretch."""
    assert FLAT.undercut(0.0) and FLAT.undercut(-1e-3) and not FLAT.undercut(1e-3)
    assert FLAT.concave(np.array([-0.030, 0.02])).tolist() == [False, False]
