"""The fits of a measured lift table: binning, the N-harmonic least squares and its order, the false asymmetry of
its origin, Reinsch's smoothing spline, generalised cross-validation and the choice between the two fits
(Shang Hanji (1988), sections 5.2-5.3; Reinsch (1967); Craven and Wahba (1979)).

Angles are camshaft radians, lifts metres; :mod:`valvetrain.laws.measured` builds the measured cam from them.
"""

from collections.abc import Callable

import numpy as np

from ..errors import InputError
from ..numerics import extremum

HARMONIC_RCOND = 1e-8
"""Relative cut-off of the singular values in the harmonic least squares: the combinations of harmonics the
window of data does not determine (they live in the part of the period without data) are left out instead of
being fitted to the noise with huge coefficients."""

SMOOTHING_XTOL = 1e-3
"""Tolerance of the smoothing parameter of the spline, as a relative change of lambda: its residual RMS is the
target to about 0.1 %."""


def binned(x, y, points) -> tuple[np.ndarray, np.ndarray, float]:
    """Rows averaged in at most ``points`` bins of equal width in x; empty bins are dropped.

    Averaging the angle with the lift keeps the points on the curve to second order (the bias is h'' w^2 / 24
    for a bin of width w, below 0.02 um for 0.2 cam deg bins of a lobe); the noise falls by the square root of
    the rows in a bin.

    Returns
    -------
    (ndarray, ndarray, float)
        Mean x and y of the bins, and the mean number of rows in a bin (1 when ``x`` has no more than ``points``
        rows: returned as they are).
    """
    if x.size <= points:
        return x, y, 1.0
    bins = np.minimum(((x - x[0]) / (x[-1] - x[0]) * points).astype(int), points - 1)
    count = np.bincount(bins, minlength=points)
    full = count > 0
    return (np.bincount(bins, x, points)[full] / count[full], np.bincount(bins, y, points)[full] / count[full],
            x.size / full.sum())


def harmonic_fit(theta, lift, harmonics, period_half) -> tuple[np.ndarray, np.ndarray, float]:
    """Least-squares N-harmonic approximation h = a0 + sum a_k cos(k w t) + b_k sin(k w t), w = pi / L.

    Parameters
    ----------
    theta : ndarray
        Angles [rad] measured from a trial origin.
    lift : ndarray
        Lifts [m].
    harmonics : int
        N.
    period_half : float
        L, somewhat larger than half the working angle [rad].

    Returns
    -------
    (ndarray, ndarray, float)
        a_0..a_N, b_0..b_N (b_0 = 0) and w.

    References
    ----------
    Shang Hanji (1988), section 5.2 (approximation of a measured table; reconstructed).
    """
    w = np.pi / period_half
    k = np.arange(harmonics + 1)
    design = np.hstack([np.cos(np.outer(theta, k * w)), np.sin(np.outer(theta, k[1:] * w))])
    coef = np.linalg.lstsq(design, lift, rcond=HARMONIC_RCOND)[0]
    return coef[: harmonics + 1], np.concatenate([[0.0], coef[harmonics + 1:]]), w


def harmonic_lift(theta, a, b, w) -> np.ndarray:
    """The N-harmonic series sum a_k cos(k w t) + b_k sin(k w t) at angles theta [rad]."""
    k = np.arange(a.size) * w
    return np.cos(np.outer(theta, k)) @ a + np.sin(np.outer(theta, k)) @ b


def harmonic_order(theta, lift, accuracy, most, period_half) -> tuple[int, np.ndarray, np.ndarray, float, float]:
    """The smallest order N <= ``most`` whose N-harmonic fit meets the accuracy, and its fit (
    choose N by the residual against the measurement accuracy, not the largest N that fits).

    The residual falls with N (the fits are nested), so N is bracketed by doubling from 4 and then found by
    bisection: about 2 log2(N) fits instead of one per order.  If even ``most`` does not meet the accuracy,
    N = ``most``.

    Returns
    -------
    (int, ndarray, ndarray, float, float)
        N, a_0..a_N, b_0..b_N, w (see :func:`harmonic_fit`) and the RMS residual [m].
    """
    def fit(n):
        a, b, w = harmonic_fit(theta, lift, n, period_half)
        return n, a, b, w, float(np.sqrt(np.mean((lift - harmonic_lift(theta, a, b, w)) ** 2)))

    low, best = 3, fit(min(4, most))      # orders <= low miss the accuracy
    while best[4] > accuracy and best[0] < most:
        low, best = best[0], fit(min(2 * best[0], most))
    while best[4] <= accuracy and best[0] - low > 1:
        trial = fit((low + best[0]) // 2)
        if trial[4] <= accuracy:
            best = trial
        else:
            low = trial[0]
    return best


def symmetry_shift(a, b, w, half_width, search=0.2, samples=801) -> tuple[float, float]:
    """Origin shift delta [rad] that best removes the odd part of a harmonic fit, and the odd part left.

    Shifting the origin by delta turns the sine coefficients into b_k(delta) = b_k cos(k w delta) -
    a_k sin(k w delta), and the odd part of the fit into o(t) = sum b_k(delta) sin(k w t).  The
    criterion, min sum b_k(delta)^2, is the energy of o over a whole half-period; here the energy is
    taken over the measured window |t| <= T (T = ``half_width`` less the searched shift), which is the
    same criterion where the basis is orthogonal and stays meaningful where it is not: a fit of high
    order over a window shorter than its period has large coefficients that cancel inside the data,
    and their b_k(delta)^2 would place the axis degrees away.  The axis is searched on a grid over
    |delta| <= ``search`` T and refined (:func:`~valvetrain.numerics.extremum`).

    Parameters
    ----------
    a, b : ndarray
        Cosine and sine coefficients a_0..a_N, b_0..b_N from :func:`harmonic_fit` [m].
    w : float
        Base frequency pi / L [1/rad].
    half_width : float
        The smaller of the table's extents on either side of the trial origin [rad].
    search : float
        Largest shift searched, as a fraction of ``half_width``.
    samples : int
        Points of the window at which the odd part is evaluated.

    Returns
    -------
    (float, float)
        delta [rad] and the RMS of the remaining odd part over the window [m]: the true asymmetry
        (the removed part was the false asymmetry of a wrong origin).

    References
    ----------
    Shang Hanji (1988), section 5.3 (reconstructed; criterion restricted to
    the measured window: this project's reading).
    """
    k = np.arange(a.size)
    span = search * half_width
    sines = np.sin(np.outer(np.linspace(0.0, half_width - span, samples), k * w))

    def odd_rms(d):
        coef = b * np.cos(np.outer(d, k * w)) - a * np.sin(np.outer(d, k * w))
        return np.sqrt(np.mean((coef @ sines.T) ** 2, axis=1))

    return extremum(odd_rms, [-span, span], "min", samples=401)


def _spline_rms(x, y, lam):
    """The smoothing spline with parameter ``lam`` and its RMS residual."""
    from scipy.interpolate import make_smoothing_spline

    try:
        spline = make_smoothing_spline(x, y, lam=lam)
    except (ValueError, np.linalg.LinAlgError):
        raise InputError(f"the smoothing spline cannot be fitted to the {x.size} points of the lobe") from None
    return spline, float(np.sqrt(np.mean((spline(x) - y) ** 2)))


def smoothing_spline(x, y, accuracy, stated=True) -> tuple[Callable[[np.ndarray], np.ndarray], str, float, float]:
    """Reinsch's smoothing spline whose RMS residual is the measurement accuracy, or the GCV spline's if that is
    larger and the accuracy was stated (the table is noisier than stated).

    Among all curves whose RMS residual is at most ``accuracy`` the cubic smoothing spline with that residual has
    the least integral of the squared second derivative (Reinsch's formulation): it follows the table to its
    stated accuracy and no closer, so the noise of the rows does not pass into the acceleration.  Generalised
    cross-validation alone (:func:`scipy.interpolate.make_smoothing_spline` without ``lam``) follows 2 um of noise
    on a table every 2 crank deg into an acceleration 30 % too large; it is kept where its residual exceeds the
    stated accuracy, which the table then does not meet.  An accuracy derived from the rows themselves
    (:func:`valvetrain.laws.measured.table_accuracy`) is their noise, Reinsch's own choice of the residual: the spline is smoothed to it even
    where generalised cross-validation smooths more, as it does around a kink (the foot of a valve-lift table
    every 2 crank deg, whose durations at 0.1 mm it shortens by 0.2 crank deg).  The residual grows with lambda,
    so lambda is found by Brent's method on log(lambda) after bracketing by decades.

    Parameters
    ----------
    x, y : ndarray
        Angles [rad], increasing, and lifts [m].
    accuracy : float
        Measurement accuracy, as an RMS error [m].
    stated : bool
        Whether the accuracy was stated (a bound the table may not meet) or derived from the rows (their noise).

    Returns
    -------
    (BSpline, str, float, float)
        The spline, how its smoothing was chosen (``"accuracy"`` or ``"gcv"``), its RMS residual [m] and lambda.

    Raises
    ------
    ValueError
        Where no spline can be fitted, in the terms of the table.

    References
    ----------
    Reinsch (1967), the smoothing spline; Craven and Wahba (1979), generalised cross-validation.
    """
    from scipy.interpolate import make_smoothing_spline
    from scipy.optimize import brentq

    try:
        gcv = make_smoothing_spline(x, y)
    except (ValueError, np.linalg.LinAlgError):
        raise InputError(f"the smoothing spline cannot be fitted to the {x.size} points of the lobe (generalised "
                         "cross-validation finds no smoothing for them)") from None
    gcv_rms = float(np.sqrt(np.mean((gcv(x) - y) ** 2)))
    how, target = ("gcv", gcv_rms) if stated and gcv_rms >= accuracy else ("accuracy", accuracy)

    def excess(log_lam):
        return _spline_rms(x, y, np.exp(log_lam))[1] - target

    low = high = np.log(1e-6 * np.ptp(x) ** 3)     # lambda carries the unit of x^3
    while excess(high) < 0.0 and high < low + 80.0:
        high += np.log(10.0)
    while excess(low) > 0.0 and low > high - 80.0:
        low -= np.log(10.0)
    if low == high:
        low -= np.log(10.0)
    if excess(low) > 0.0 or excess(high) < 0.0:     # no lambda reaches the target: keep the GCV spline
        return gcv, "gcv", gcv_rms, float("nan")
    lam = float(np.exp(brentq(excess, low, high, xtol=SMOOTHING_XTOL)))
    spline, rms = _spline_rms(x, y, lam)
    return spline, how, rms, lam


def spline_dof(x, lam) -> float:
    """Degrees of freedom of the smoothing spline with parameter ``lam``: the trace of its hat matrix, from the
    splines of the unit vectors (one banded solve with n right-hand sides).  NaN for an unknown lambda."""
    from scipy.interpolate import make_smoothing_spline

    if not np.isfinite(lam):
        return float("nan")
    return float(np.trace(make_smoothing_spline(x, np.eye(x.size), lam=lam)(x)))


def gcv_score(rms, dof, points) -> float:
    """Generalised cross-validation score n RSS / (n - dof)^2 [m^2] of a linear fit with RMS residual ``rms``.

    The mean squared error with which the fit predicts a row left out of it, to first order (Craven and Wahba
    1979, see :func:`smoothing_spline`); it compares fits of different kinds on the same rows.  NaN when the fit
    has as many degrees of freedom as rows, or an unknown number.
    """
    if not np.isfinite(dof) or dof >= points:
        return float("nan")
    return points * points * rms**2 / (points - dof) ** 2


def choose_fit(fit, bounded, meets, gcv) -> tuple[str, tuple[str, float]]:
    """The fit a law evaluates and why: ``(fit, (code, ratio))``.

    The codes: ``"given"`` (``fit`` is not ``"auto"``), ``"harmonic_swings"`` (the N-harmonic fit leaves the table's
    range), ``"harmonic_misses"`` (it does not meet the accuracy), ``"harmonic_gcv"`` and ``"spline_gcv"`` (the one
    with the smaller score, ``ratio`` its score / the other's); the report words them
    (:func:`valvetrain.locale.wording.fit_reason`).

    ``"auto"`` compares the two fits where both are admissible, the N-harmonic fit meeting the stated accuracy and
    staying within the table's range, by their generalised cross-validation scores (``gcv``, :func:`gcv_score`):
    both follow the table to its accuracy, and the one that predicts left-out rows better carries less noise.
    Otherwise it takes the smoothing spline.
    """
    if fit != "auto":
        return fit, ("given", float("nan"))
    if not bounded:
        return "spline", ("harmonic_swings", float("nan"))
    if not meets:
        return "spline", ("harmonic_misses", float("nan"))
    ratio = gcv["harmonic"] / gcv["spline"]
    if not np.isfinite(ratio) or ratio <= 1.0:
        return "harmonic", ("harmonic_gcv", ratio)
    return "spline", ("spline_gcv", 1.0 / ratio)
