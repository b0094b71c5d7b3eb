"""The constant-acceleration cam (laws/constant_acceleration.py; the method of Shang Hanji (1988), section 2.4)."""

import numpy as np
import pytest

from valvetrain.laws.constant_acceleration import ConstantAccelerationLaw


def test_constant_acceleration_worked_example():
    """Shang Hanji (1988), section 2.4, worked example (spec section 5): h_max 8, h0 0.35, alpha_r 20 deg
    (constant-acceleration ramp, f = 0.5), 18/20/12 deg, kappa 0.6: A1 54.142, A2 38.646 mm/rad2, v0 1.3369 mm/rad (23.3
    um/deg), closure exact, acceleration levels {54.142, 7.66, 0, -23.187, -38.646}."""
    v0 = 0.35 / (np.radians(20) * 0.75)
    assert v0 == pytest.approx(1.3369, abs=1e-4)
    law = ConstantAccelerationLaw(7.65, 0.35, v0, *np.radians([18, 20, 12]), kappa=0.6,
                                  ramp_kind="constant_acceleration", ramp_fraction=0.5)
    assert (law.a1, law.a2) == pytest.approx((54.142, 38.646), abs=1e-3)
    nose = law.derivatives(np.array([0.0]))[:, 0]
    assert nose[0] == pytest.approx(8.0, abs=1e-12)
    assert nose[1] == pytest.approx(0.0, abs=1e-12)
    levels = np.unique(np.round(law.derivatives(np.linspace(law.start, 0, 4001))[2], 3))
    assert set(levels) <= {54.142, 7.66, -23.188, -23.187, -38.646, 0.0}
    assert {54.142, 7.66, -38.646} <= set(levels)
