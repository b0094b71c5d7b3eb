"""The fits of a measured lift table (valvetrain.laws.fits)."""

import numpy as np
import pytest

from valvetrain.laws.fits import binned, gcv_score, harmonic_fit, harmonic_lift, harmonic_order, smoothing_spline, symmetry_shift

from conftest import sampled_kurz as _sampled


def test_harmonic_fit_residual_on_a_smooth_law():
    """An N-harmonic approximation of the Kurz lift of Valve-train practical works (n.d.): the residual falls with N, below 1 um by N = 30."""
    _, theta, lift = _sampled()
    rms = []
    for n in (8, 16, 30):
        a, b, w = harmonic_fit(theta, lift, n, 1.15 * theta.max())
        k = np.arange(n + 1)
        fit = np.cos(np.outer(theta, k * w)) @ a + np.sin(np.outer(theta, k * w)) @ b
        rms.append(np.sqrt(np.mean((fit - lift) ** 2)))
    assert rms[0] > rms[1] > rms[2]
    assert rms[2] < 1e-6


def test_nose_finding_does_not_depend_on_the_order():
    """A lobe 2.5 deg off the origin with 2 um noise (spec section 10): the axis found from fits of order 8 to 60 is
    the known shift to 0.01 deg. A fit of high order over a window shorter than its period has large coefficients
    that cancel inside the data; the odd part is therefore measured over the data, not by sum b_k^2."""
    _, theta, lift = _sampled(2.5, noise=2e-6)
    top = int(np.argmax(lift))
    for n in (8, 25, 40, 60):
        a, b, w = harmonic_fit(theta - theta[top], lift, n, 1.15 * (theta[-1] - theta[top]))
        shift, odd = symmetry_shift(a, b, w, theta[top] - theta[0])
        assert np.degrees(theta[top] + shift) == pytest.approx(2.5, abs=0.01)
        assert odd < 2e-6   # the remaining odd part is below the noise


def test_the_spline_residual_is_the_accuracy():
    """Reinsch's spline of a table with 2 um noise: smoothed to an RMS residual of 5 um, 3 um (to 0.1 %, the
    tolerance of lambda); asked for 0.5 um, finer than the noise, it keeps the residual of generalised
    cross-validation (below the noise: GCV follows part of it)."""
    _, theta, lift = _sampled(noise=2e-6)
    for accuracy in (5e-6, 3e-6):
        _, how, rms, _ = smoothing_spline(theta, lift, accuracy)
        assert how == "accuracy" and rms == pytest.approx(accuracy, rel=1e-3)
    _, how, rms, _ = smoothing_spline(theta, lift, 0.5e-6)
    assert how == "gcv" and 0.5e-6 < rms < 2e-6


def test_the_gcv_score_of_a_straight_line_fit():
    """The GCV score n RSS / (n - p)^2 of a least-squares line (p = 2) through n points: the leave-one-out
    prediction error to first order; an analytic identity checked against the formula by hand."""
    assert gcv_score(1.0, 2, 10) == pytest.approx(10 * 10 * 1.0 / 64)
    assert np.isnan(gcv_score(1.0, 10, 10))


def test_binning_keeps_a_straight_line():
    """Means of angle and lift in a bin lie on a straight line through the rows (an analytic identity); 10,000 rows
    into 100 bins of 100 rows each, their noise falls tenfold."""
    x = np.linspace(0.0, 1.0, 10_000)
    noise = np.random.default_rng(1).normal(0.0, 1.0, x.size)
    bx, by, per = binned(x, 2.0 * x + 1.0, 100)
    assert per == 100.0 and bx.size == 100
    assert np.abs(by - (2.0 * bx + 1.0)).max() < 1e-12
    assert np.std(binned(x, noise, 100)[1]) == pytest.approx(0.1, rel=0.2)


def test_the_harmonic_order_is_the_smallest_that_meets_the_accuracy():
    """Doubling and bisection find the order a scan of every order finds (spec section 9: the smallest N whose RMS
    residual meets the accuracy), for accuracies the example's lobe meets at different orders."""
    _, theta, lift = _sampled(noise=2e-6)
    top = int(np.argmax(lift))
    x, period_half = theta - theta[top], 1.15 * (theta[-1] - theta[top])
    for accuracy in (3e-5, 1e-5, 3e-6):
        n = harmonic_order(x, lift, accuracy, 46, period_half)[0]
        scan = next(k for k in range(4, 47) if np.sqrt(np.mean(
            (lift - harmonic_lift(x, *harmonic_fit(x, lift, k, period_half))) ** 2)) <= accuracy)
        assert n == scan
