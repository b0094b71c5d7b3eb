"""Numerical helpers: the refined extremum of a sampled function."""

import numpy as np

from valvetrain.numerics import extremum


def test_extremum_refines_a_smooth_maximum():
    """sin on [0, 3] peaks at pi/2 with value 1 (analytic)."""
    x, y = extremum(np.sin, [0.0, 1.0, 3.0], "max")
    assert abs(x - np.pi / 2) < 1e-6 and abs(y - 1.0) < 1e-13


def test_extremum_steps_around_a_gap_of_non_finite_values():
    """1 - |x - 0.503| is not finite on (0.5015, 0.5045) (a pole or a concave stretch, as a profile radius can be),
    which lies between the samples 0.5 and 0.505: the refinement must neither produce NaN arithmetic (run with
    -W error) nor land in the gap; the supremum of the finite values is 1 - 0.0015 = 0.9985 at the gap's end."""
    def fn(x):
        return np.where((x > 0.5015) & (x < 0.5045), -np.inf, 1.0 - np.abs(x - 0.503))

    x, y = extremum(fn, [0.0, 1.0], "max", samples=201)
    assert not 0.5015 < x < 0.5045
    assert 0.998 <= y <= 0.9985 + 1e-12
