"""The combined-function cam (laws/combined.py): segments of named functions joined with continuous lift, velocity
and acceleration."""

import numpy as np
import pytest

from valvetrain.laws.combined import CombinedLaw
from valvetrain.laws.kurz import KurzLaw

DEG = np.pi / 180


def test_combined_rebuilds_kurz():
    """The combined-function mechanism with Kurz's segments (half-sine, quarter-sine, parabola to the nose, Z = 5/8) is
    the Kurz law of Valve-train practical works (n.d.) to round-off (Shang Hanji (1988), section 2.5: Kurz is a
    combined-function cam; spec section 6)."""
    w = 0.02e-3 / DEG
    kurz = KurzLaw(6.25e-3, 0.25e-3, w, *np.radians([27, 6, 38]))
    combined = CombinedLaw(6.25e-3, 0.25e-3, w, [("half_sine", np.radians(27)), ("quarter_sine", np.radians(6)),
                                                  ("parabola_to_nose", np.radians(38))], ratios=[(1, 0.625)])
    theta = np.linspace(-kurz.half_angle, kurz.half_angle, 2001)
    scale = np.abs(kurz.derivatives(theta)).max(axis=1)
    assert np.all(np.abs(kurz.derivatives(theta) - combined.derivatives(theta)).max(axis=1) < 1e-12 * scale)
    # the first amplitude is c12 (pi/Phi1)^2 of (2.6)
    assert combined.amplitude(0)[0] * 1e3 == pytest.approx(kurz.coefficients()["c12"] * (np.pi / np.radians(27)) ** 2)


def test_combined_needs_a_square_system():
    with pytest.raises(ValueError, match="unknown amplitudes"):
        CombinedLaw(6e-3, 0.25e-3, 1e-3, [("half_sine", 0.5), ("linear", 0.4), ("parabola_to_nose", 0.3)])
