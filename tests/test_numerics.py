"""Numerical helpers: the refined extremum of a sampled function, roots in many brackets at once."""

import numpy as np
import pytest

from valvetrain.numerics import bounded_minimum, bracketed_roots, extremum, level_span


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


def test_bracketed_roots_of_several_brackets_at_once():
    """cos vanishes at pi/2 and 3 pi/2 (analytic), x^3 - x / 1000 at 0 and 1/sqrt(1000); a jump of a step function
    across zero is located like a root; each to round-off."""
    x = bracketed_roots(np.cos, [1.0, 4.0], [2.0, 5.0], np.cos([1.0, 4.0]), np.cos([2.0, 5.0]))
    assert np.abs(x - [np.pi / 2, 3 * np.pi / 2]).max() <= 4 * np.finfo(float).eps * 5

    def cubic(t):
        return t**3 - 1e-3 * t

    a, b = np.array([-0.02, 0.01]), np.array([0.01, 0.5])
    x = bracketed_roots(cubic, a, b, cubic(a), cubic(b))
    assert abs(x[0]) < 1e-18 and x[1] == pytest.approx(np.sqrt(1e-3), rel=1e-15)
    x = bracketed_roots(lambda t: np.where(t < 0.3, -1.0, 2.0), [0.0], [1.0], [-1.0], [2.0])
    assert x[0] == pytest.approx(0.3, rel=1e-15)


@pytest.mark.parametrize("fn, a, b", [
    (lambda x: (x - 0.3) ** 2, 0.0, 1.0),                 # a parabola: the interpolation steps
    (lambda x: abs(x - 0.7), 0.0, 1.0),                     # a kink: golden-section steps
    (lambda x: -np.sin(x), 0.0, 3.0),                       # a smooth maximum
    (lambda x: x, -2.0, 5.0),                               # the minimum at a bound
    (lambda x: np.cos(40.0 * x) + 0.1 * x, -0.2, 0.3),      # several minima
    (lambda x: 1e-9 * (x - 0.013) ** 4, 0.0125, 0.0135),    # a flat bottom on a narrow bracket
])
def test_bounded_minimum_takes_scipys_steps(fn, a, b):
    """The reference is SciPy's own bounded Brent iteration (``minimize_scalar(method="bounded")``): the same
    minimum and the same value, to the bit, and the same number of calls."""
    from scipy.optimize import minimize_scalar

    xatol = 1e-13 * max(1.0, abs(b))
    calls = []

    def counted(x):
        calls.append(x)
        return float(fn(x))

    x, fx = bounded_minimum(counted, a, b, xatol)
    ref = minimize_scalar(fn, bounds=(a, b), method="bounded", options={"xatol": xatol})
    assert (x, fx) == (float(ref.x), float(ref.fun))
    assert len(calls) == ref.nfev


def test_integrals_of_several_functions_each_over_its_interval():
    """numerics.integrals: f_i = sin(k_i x) over [a_i, b_i] with breakpoints inside is (cos k a - cos k b) / k
    (closed form), and each equals cumulative_integral's on [a_i, b_i] (the same pieces and nodes)."""
    from valvetrain.numerics import cumulative_integral, integrals

    k = np.array([1.0, 2.0, 3.0])
    a, b = np.array([0.0, -1.0, 0.5]), np.array([np.pi, 2.0, 0.9])
    breakpoints = [[], [0.0, 1.0], [0.7, 5.0]]
    got = integrals(lambda x, member: np.sin(k[member] * x), a, b, breakpoints)
    np.testing.assert_allclose(got, (np.cos(k * a) - np.cos(k * b)) / k, rtol=1e-14)
    for i in range(3):
        one = cumulative_integral(lambda x, i=i: np.sin(k[i] * x), [a[i], b[i]], breakpoints[i])[-1]
        assert got[i] == pytest.approx(one, rel=1e-15)


def test_level_span_solves_both_crossings_to_round_off():
    """sin x = 0.5 on [0, pi]: x = arcsin 0.5 = pi/6 and pi - pi/6 (closed form), to a few units in the last place."""
    rise, fall = level_span(np.sin, 0.0, np.pi, 0.5)
    assert rise == pytest.approx(np.pi / 6.0, rel=4e-16)
    assert fall == pytest.approx(5.0 * np.pi / 6.0, rel=4e-16)


def test_level_span_takes_a_sample_on_the_level():
    """1 - |x| = 0.5 at x = -0.5 and 0.5 (closed form), both of them samples of the five on [-1, 1]: the crossing is
    the sample itself (no bracket with a sign change to refine)."""
    assert level_span(lambda x: 1.0 - np.abs(x), -1.0, 1.0, 0.5, samples=5) == (-0.5, 0.5)


def test_level_span_is_nan_where_the_level_is_not_crossed_twice():
    """Never above the level, or above it at an end of the interval: no span."""
    assert np.isnan(level_span(np.sin, 0.0, np.pi, 2.0)).all()
    assert np.isnan(level_span(np.cos, 0.0, np.pi, 0.5)).all()


def test_extremum_of_a_symmetric_function_is_the_first_of_its_equal_peaks():
    """3 - (x^2 - 1)^2 peaks at -1 and +1 with the value 3 (analytic); the right peak made larger by two units in the
    last place (round-off, which another BLAS kernel may put on the other side) must not move the answer from the
    first peak, -1 (before: +1)."""
    def fn(x):
        return (3.0 - (x**2 - 1.0) ** 2) * np.where(x > 0.0, 1.0 + 4.4e-16, 1.0)

    assert fn(np.array([1.0]))[0] > fn(np.array([-1.0]))[0]
    x, y = extremum(fn, [-2.0, 0.0, 2.0], "max")
    assert abs(x + 1.0) < 1e-6 and y == 3.0


def test_first_largest_decides_a_tie_by_order():
    """Values within 16 units in the last place of the largest are its equals: the first of them is taken along an
    axis too; a value larger by more than that wins."""
    from valvetrain.numerics import TIE_RTOL, first_largest

    row = np.array([1.0, 5.0, 2.0, 5.0 * (1.0 + 8 * np.finfo(float).eps)])
    assert first_largest(row) == 1 and int(np.argmax(row)) == 3
    assert first_largest(np.array([1.0, 5.0, 5.0 * (1.0 + 4 * TIE_RTOL)])) == 2
    assert list(first_largest(np.vstack([row, row[::-1]]), axis=1)) == [1, 0]
    assert first_largest([0.3, -np.inf, np.inf, np.inf]) == 2
