"""Woschni's heat transfer (valvetrain.breathing.heat_transfer): hand calculations of Heywood (1988), eqs. (12.19),
(12.20)."""

import numpy as np
import pytest

from valvetrain.breathing import heat_transfer as ht


def test_woschni_coefficient_by_hand():
    """h = 3.26 B^-0.2 p^0.8 T^-0.55 w^0.8 (kPa) at B = 0.092 m, p = 2 MPa, T = 700 K, w = 5 m/s."""
    expected = 3.26 * 0.092**-0.2 * 2000.0**0.8 * 700.0**-0.55 * 5.0**0.8
    assert ht.woschni_coefficient(0.092, 2e6, 700.0, 5.0) == pytest.approx(expected, rel=1e-14)


def test_woschni_velocity_by_hand():
    """Compression: w = 2.28 S_p; combustion adds C2 V_d T_r (p - p_m) / (p_r V_r)."""
    assert ht.woschni_velocity(2.28, 0.0, 10.0, 5e-4, 330.0, 1e5, 5e-4, 3e6, 2e6) == pytest.approx(22.8)
    w = ht.woschni_velocity(2.28, ht.WOSCHNI_C2, 10.0, 5e-4, 330.0, 1e5, 5.5e-4, 3e6, 2e6)
    assert w == pytest.approx(22.8 + 3.24e-3 * 5e-4 * 330.0 / (1e5 * 5.5e-4) * 1e6)


def test_wall_area_of_a_flat_chamber():
    """Two discs of the bore and the liner up to V / A_p."""
    bore, volume = 0.092, 300e-6
    piston = np.pi * bore**2 / 4
    assert ht.wall_area(volume, bore) == pytest.approx(2 * piston + np.pi * bore * volume / piston)
