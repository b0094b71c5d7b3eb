"""Masses of the train (masses.py): the spring's mass and the masses reduced to the valve and to the tappet."""

import numpy as np
import pytest

from valvetrain import masses


def test_spring_mass_and_reduced_masses():
    # rho (pi d^2 / 4) pi D i: 7850 * pi/4 * 0.004^2 * pi * 0.03 * 8
    assert masses.spring_mass(0.03, 0.004, 8, 7850.0) == pytest.approx(7850 * np.pi**2 / 4 * 16e-6 * 0.03 * 8)
    m_v = masses.reduced_mass_at_valve(0.05, 0.02, 0.005, 0.045, 0.06, 0.04, 4e-5, 0.04, 1.6)
    # (5.2) term by term; (7.2) = (5.2) x i_k^2
    assert m_v == pytest.approx(0.05 + 0.02 + 0.005 + 0.015 + 4e-5 / 0.04**2 + 0.1 / 1.6**2)
    assert masses.reduced_mass_at_tappet(m_v, 1.6) == pytest.approx(
        0.06 + 0.04 + 4e-5 / 0.025**2 + (0.05 + 0.02 + 0.005 + 0.015) * 1.6**2)
