"""Ramps (laws/ramps.py): the cosine, constant-velocity and constant-acceleration ramps end on their height and
velocity with zero acceleration, over the lengths of their closed forms."""

import numpy as np
import pytest

from valvetrain.laws.ramps import make_ramp


@pytest.mark.parametrize("kind", ["cosine", "constant_velocity", "constant_acceleration"])
def test_ramps_end_on_height_velocity_and_zero_acceleration(kind):
    r = make_ramp(kind, 0.3e-3, 0.6e-3, 0.4)
    end = r.evaluate(np.array([r.length]))[:, 0]
    assert end[:3] == pytest.approx([0.3e-3, 0.6e-3, 0.0], abs=1e-15)
    start = r.evaluate(np.array([0.0]))[:, 0]
    assert start[0] == 0.0
    # lengths: cosine pi h0 / (2 v0) (Valve-train practical works (n.d.), work 2, eq. (2.1)), constant velocity
    # h0 / v0, constant acceleration h0 / (v0 (1 - f/2)) (its acceleration integrated twice; spec section 2)
    expected = {"cosine": np.pi * 0.3 / 1.2, "constant_velocity": 0.5, "constant_acceleration": 0.3 / (0.6 * 0.8)}
    assert r.length == pytest.approx(expected[kind], rel=1e-12)
