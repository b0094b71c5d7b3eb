"""Two-stroke port timing, areas and time-area (Valve-train practical works (n.d.), work 8)."""

import numpy as np
import pytest
from scipy.optimize import brentq

from valvetrain import twostroke
from valvetrain.crank.kinematics import displacement


def test_port_angle_closed_form_against_root_finding():
    """(8.1) and the exact closed form equal the root of S_p(alpha) = S - h (lambda/4 series and exact slider-crank),
    found independently; the spec's example sigma = 0.27, lambda = 0.25 gives 69.49 deg, and 69.60 deg with the
    exact kinematics."""
    for sigma in (0.18, 0.22, 0.27, 0.32):
        for lam in (0.24, 0.28, 0.31):
            for exact in (False, True):
                alpha = brentq(lambda a, lam=lam, sigma=sigma, exact=exact: displacement(a, 0.5, lam, exact=exact)
                               - (1 - sigma), 0, np.pi, xtol=1e-15)
                assert twostroke.port_angle(sigma, lam, exact) == pytest.approx(np.pi - alpha, abs=1e-12)
    assert np.degrees(twostroke.port_angle_series(0.27, 0.25)) == pytest.approx(69.49, abs=0.005)
    assert np.degrees(twostroke.port_angle(0.27, 0.25)) == pytest.approx(69.60, abs=0.005)


def test_port_height_inverts_angle():
    for exact in (True, False):
        a = twostroke.port_angle(0.26, 0.29, exact)
        assert twostroke.port_height(a, 0.29, exact) == pytest.approx(0.26, abs=1e-12)


def test_time_area_closed_form():
    """Z = K1 K2 / n (8.6)-(8.8) equals the integral of the area (8.2) with the lambda/4 kinematics (spec: 6e-9)."""
    D, S, lam, n = 0.056, 0.060, 0.25, 6000.0 * np.pi / 30.0   # omega of 6000 rpm [rad/s]
    for sigma, psi in ((0.27, 0.22), (0.20, 0.26)):
        phi = np.linspace(0, 2 * np.pi, 400001)
        area = twostroke.top_port_area(phi, sigma * S, psi * np.pi * D, S, lam, exact=False)
        z = twostroke.time_area_numeric(phi, area, n)
        assert twostroke.time_area_analytic(D, S, sigma, lam, psi, n) == pytest.approx(z, rel=1e-8)


def test_port_areas():
    S, lam = 0.06, 0.25
    phi = np.radians([0.0, 180.0])
    a = twostroke.top_port_area(phi, 0.016, 0.04, S, lam)
    assert a.tolist() == pytest.approx([0.0, 0.016 * 0.04])  # closed at TDC, fully open at BDC
    # skirt-controlled inlet: open around TDC when the skirt is above the port's lower edge
    s = twostroke.skirt_port_area(phi, 0.09, 0.015, 0.07, 0.03, S, lam)
    assert s.tolist() == pytest.approx([0.015 * 0.03, 0.0])
