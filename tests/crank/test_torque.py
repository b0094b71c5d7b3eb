"""Total torque of a multi-cylinder engine (Power units manual (n.d.), section 2.5): firing angles of the layouts and
the sum of the cylinders' torques."""

import numpy as np
import pytest

from valvetrain.crank import torque


def test_multicylinder_layouts():
    """Spec section 5: inline 4 even at 180; cross-plane V8 even at 90; 90-deg V6 with shared pins 90/150;
    90-deg V-twin 90/630."""
    f4 = torque.even_firing([1, 3, 4, 2], 4)
    assert np.degrees(f4).tolist() == [0, 540, 180, 360]
    v8 = torque.layout_firing([1, 5, 4, 2, 6, 3, 7, 8], np.radians([0, 90, 270, 180] * 2),
                              np.radians([0] * 4 + [90] * 4), 4)
    assert torque.is_even(v8, 4)
    assert np.allclose(np.diff(np.sort(np.degrees(v8))), 90)
    v6 = torque.layout_firing([1, 4, 2, 5, 3, 6], np.radians([0, 120, 240] * 2), np.radians([0] * 3 + [90] * 3), 4)
    assert np.diff(np.sort(np.degrees(v6))).tolist() == pytest.approx([90, 150, 90, 150, 90])
    vt = torque.layout_firing([1, 2], [0, 0], [0, np.pi / 2], 4)
    assert np.degrees(vt).tolist() == pytest.approx([0, 90])


def test_total_torque_sum_and_period():
    """A cylinder torque of harmonics of orders 0, 1/2, 1 and 2 (per crank revolution) on an even-firing inline four:
    the orders 1/2 and 1 cancel over the four cylinders 180 deg apart, so the total is 4 (M0 + M2 sin 2 psi) (the
    sum of the shifted series, by hand)."""
    phi = np.radians(np.arange(0.0, 720.0, 1.0))
    m0, m2 = 40.0, 90.0
    one = m0 + 300.0 * np.sin(phi) + 120.0 * np.cos(phi / 2) + m2 * np.sin(2 * phi)
    firing = torque.even_firing([1, 3, 4, 2], 4)
    each, total = torque.engine_torque(phi, (phi, one), firing, 4)
    assert np.allclose(total, 4 * (m0 + m2 * np.sin(2 * phi)), rtol=0, atol=1e-9)
    # cylinder 3 fires 180 deg after cylinder 1: its curve is cylinder 1's shifted by 180 deg
    assert np.allclose(each[2], np.roll(each[0], 180))
    stats = torque.torque_statistics(total[:180])
    assert stats["nonuniformity"] == pytest.approx(2 * m2 / m0, rel=1e-4)
    # the same closed form: the largest |torque| is 4 (m0 + m2), so the mean's share of it is m0 / (m0 + m2)
    assert stats["mean_share"] == pytest.approx(m0 / (m0 + m2), rel=1e-4)
