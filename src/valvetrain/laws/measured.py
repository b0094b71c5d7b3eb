"""Measured lift tables: reading, checking and trimming to the lobe, smoothing-spline and N-harmonic fits
(:mod:`.fits`), nose finding and false asymmetry, checking-height durations, and the measured cam as a lift law
(Shang Hanji (1988), sections 5.1-5.3; reconstructed in this package).

Angles inside are camshaft radians in the engine's cam frame (crank angle from the gas-exchange TDC / 2); a
table measured against the crank angle is halved, and one measured from the firing TDC is turned back by 360
crank deg.  Lifts are follower (tappet) lifts [m]; a table of valve lift is divided by the rocker ratio.
"""

from dataclasses import dataclass

import numpy as np

from ..checks import check
from ..errors import InputError
from ..locale import cited, note
from ..numerics import extremum, level_span
from ..units import DEG, MM
from .base import RampedLaw, Segment
from .errors import LawError
from .fits import binned, choose_fit, gcv_score, harmonic_order, smoothing_spline, spline_dof, symmetry_shift

CHECKING_HEIGHTS_MM = (0.1, 0.5, 1.0, 1.27)
"""Standard checking heights [mm]: 0.1, 0.5, 1.0 mm and 0.050 in = 1.27 mm."""

BASE_CIRCLE_ACCURACIES = 3.0
"""Half-width of the base-circle band in measurement accuracies: a lift within 3 x accuracy_mm of zero is the
base circle (noise and run-out of the measurement).  A table must start and end in the band and no row may lie
below it; a fit must stay within it below zero and above the table's largest lift."""

MOST_SCATTER = 0.05
"""Largest scatter of a table's rows (:func:`noise_level`) as a share of its largest lift.  A smooth lobe sampled
every 10 cam deg scatters by about 1.6 % of its lift in third differences (a 10 mm lobe over 120 cam deg: a third
derivative of about 1.6e-4 mm/deg^3 times 10^3 deg^3); a measurement scatters by hundredths of a per cent; a step
or a flat top, by tens of per cent: no lobe to fit."""

ROW_OFF_FIT = 20.0
"""Farthest a row may lie from the fit, in measurement accuracies (the larger of the accuracy and the rows' scatter,
:func:`noise_level`), unless within :data:`ROW_OFF_LIFT` of the lift: the fits follow the rows to about one accuracy
(RMS), the noise of a few hundred rows reaches about 3; a row further off is a wrong row (a typing error, a spike of
the gauge), which the fit would follow partly, above or below the lobe the other rows measure."""

ROW_OFF_LIFT = 0.01
"""Distance from the fit that a row may have whatever its accuracy, a share of the other rows' largest lift: the
agreement asked of ``max_lift_mm`` with a table (a smoothing fit of an exact table misses the foot of the lobe by
a few accuracies when the accuracy is far below the lift's)."""

MAX_LIFT_MM = 500.0
"""Largest lift a table may hold [mm], the bound of max_lift_mm: beyond it the table is not in millimetres."""

MIN_VALVE_LIFT_MM = 0.3
"""Smallest largest valve lift of a table [mm]: about the valve clearance (0.25-0.35 mm inlet, Valve-train practical works (n.d.), work 2);
a table that lifts the valve less holds a ramp or noise, not a cam lobe."""

FIT_POINTS = 1000
"""Most points a fit sees: a denser lobe is averaged in bins of equal angle (about 0.2 cam deg for a lobe with
its margin), which also lowers its noise by the square root of the rows in a bin."""

LOBE_MARGIN = 0.1
"""Base circle kept on either side of the lobe for the fits, as a fraction of the lobe's angle: the rows
further out do not change the analysis."""

MIN_LOBE_CAM_DEG = 10.0
"""Shortest lobe a table may hold [camshaft deg], from its first to its last row above the base-circle band.

A table of radians read as degrees spans at most one camshaft revolution, 2 pi = 6.3 cam deg (4 pi = 12.6 "crank
deg"), its lobe less: the bound refuses every one.  No cam lobe comes near it.  Its ramps alone take up the
clearance, 0.25-0.35 mm at the valve (0.16 mm or more at the tappet with a rocker ratio up to 1.6), ending at
0.008-0.022 mm per cam deg (Valve-train practical works (n.d.), work 2): over 7 cam deg each; the main event of the
recommended timing, an inlet opened 20-30 crank deg before the TDC and closed 40-60 after the BDC (ibid.), lasts
120-135 cam deg.  A lobe without ramps (zero lash) is no shorter: rising a lift h within 5 cam deg (half the bound)
takes a peak acceleration of at least 4 h / (5 deg)^2 = 525 h per rad^2 (constant acceleration, the least peak of
any rise), 5800 m/s^2 for h = 1 mm at 1000 camshaft rpm, above the 1500-3500 m/s^2 recommended (ibid.), and at the
nose a flat follower needs a base radius above 524 h against undercut (the radius of curvature R0 + h + h'' > 0)."""

MIN_LOBE_POINTS = 20
"""Fewest rows of a lobe with its margin (the N-harmonic fit takes at least N = 4, nine coefficients)."""

HARMONIC_POINTS_PER_ORDER = 4
"""The harmonic order N is at most (points - 1) / 4: the 2N + 1 coefficients come from twice as many points."""


FITS = ("auto", "spline", "harmonic")
"""Fits of a table: the one of the two below that predicts left-out rows better (auto), the smoothing spline, or
the N-harmonic fit."""

ACCURACY_FLOOR_MM = 1e-4
"""Finest accuracy of a table [mm], the lower bound of accuracy_mm: 0.1 um, below any measurement of a lobe."""


def noise_level(lift) -> float:
    """Robust estimate of the random error of a table's rows, measurement noise and rounding [same unit as ``lift``].

    The third differences of a smooth curve sampled every 1-2 crank deg are small (its third derivative times the
    cube of the step); those of white noise of standard deviation sigma have the standard deviation sqrt(20) sigma
    (the sum of the squared binomial coefficients 1, 3, 3, 1).  Their median absolute deviation (scaled by 1.4826
    to a standard deviation) ignores the few rows where the curve bends sharply (the foot of a valve-lift table,
    where the valve leaves its seat), so a noiseless table with a step or a flat top gives zero.  Runs of four
    equal rows (a base circle printed as exact zeros) say nothing of the noise and are left out.  Second
    differences take in the curvature of the flanks at 2 crank deg: 1.8 um on a lobe rounded to 1 um, whose
    rounding error is 0.29 um (third differences: 0.33 um).

    Examples
    --------
    >>> rng = np.random.default_rng(1)
    >>> round(float(noise_level(np.sin(np.linspace(0, 3, 4000)) + rng.normal(0, 1e-3, 4000))) * 1e3, 1)
    1.0
    """
    h = np.asarray(lift, dtype=float)
    moving = np.ptp(np.lib.stride_tricks.sliding_window_view(h, 4), axis=1) > 0.0
    if not moving.any():
        return 0.0
    d3 = np.diff(h, 3)[moving]
    return float(1.4826 * np.median(np.abs(d3 - np.median(d3))) / np.sqrt(20.0))


def interpolation_error(x, y, per_step=8) -> tuple[float, float]:
    """How far the lift between a table's rows may leave the range of the rows, below and above [same unit as
    ``y``]: the interpolation error of the angle step, as the rows show it.

    The cubic spline through the rows (scipy's not-a-knot :class:`~scipy.interpolate.CubicSpline`) is the
    smoothest curve through them; where it goes below the lowest row, no fit that follows the rows can be asked to
    stay inside.  At the foot of a valve-lift table, where the valve leaves its seat with the velocity of the ramp,
    the lift has a kink: the spline through rows 2 crank deg apart swings below the base circle by about 8 % of the
    lift the kink's slope makes in one step (1.7 um of tappet lift for the built-in example's valve-lift table,
    0.02 mm/cam deg at the tappet), and so does any smooth fit.  Above, a cam's nose is smooth: between the rows the
    lift exceeds the highest row by at most a parabola's, |second difference| / 8 at the highest row (the smallest
    over a run of equal highest rows), and by no more than the spline does; a table with a flat top or a step at
    its top (no cam's nose) is allowed nothing.

    Parameters
    ----------
    x, y : ndarray
        Angles [rad], increasing, and lifts.
    per_step : int
        Points per step at which the spline is evaluated.

    Returns
    -------
    below, above : float
        The allowed excursion below the lowest row and above the highest, 0 if none.

    Examples
    --------
    A parabolic nose sampled every step: the lift between the rows exceeds the highest row by a quarter step's
    squared curvature, h = 10 - (u - 0.5)^2 peaks 0.25 above the rows at u = 0 and 1 (9.75):

    >>> u = np.arange(-5.0, 6.0)
    >>> [round(e, 6) for e in interpolation_error(u, 10.0 - (u - 0.5) ** 2)]
    [0.0, 0.25]
    """
    from scipy.interpolate import CubicSpline   # imported where used: importing the package costs no scipy

    spline = CubicSpline(x, y)
    between = spline(np.linspace(x[0], x[-1], per_step * (x.size - 1) + 1))
    top = np.flatnonzero(y == y.max())
    top = top[(top > 0) & (top < y.size - 1)]
    nose = np.abs(y[top - 1] - 2.0 * y[top] + y[top + 1]).min() / 8.0 if top.size else 0.0
    return float(max(y.min() - between.min(), 0.0)), float(min(max(between.max() - y.max(), 0.0), nose))


def lift_resolution(lift_mm, most_decimals=6) -> float:
    """The step to which a table's lifts are rounded [mm]: the largest q = n x 10^-k mm (k <= ``most_decimals``)
    of which every lift is a whole multiple; 0 where there is none (the lifts are not rounded).

    Examples
    --------
    >>> lift_resolution([0.0, 0.897, 6.25]), lift_resolution([0.0, 0.002, 0.104]), lift_resolution([0.1 / 3])
    (0.001, 0.002, 0.0)
    """
    h = np.asarray(lift_mm, dtype=float)
    for k in range(most_decimals + 1):
        counts = h * 10.0**k
        whole = np.round(counts)
        if np.all(np.abs(counts - whole) <= 1e-6 * np.maximum(1.0, np.abs(counts))):
            return float(np.gcd.reduce(np.abs(whole).astype(np.int64))) / 10.0**k
    return 0.0


def table_accuracy(lift_mm) -> float:
    """The accuracy of a table's lifts as its rows show it [mm]: the default of ``accuracy_mm``.

    A table is no more accurate than its resolution and its noise.  Its rows differ from the true lift by the
    measurement noise and by the rounding to the table's step q (:func:`lift_resolution`); a value rounded to q
    carries an error uniform over +-q/2, of standard deviation q / sqrt(12).  Where the lift changes by more than
    q from row to row both errors are random, and :func:`noise_level` measures their sum from the rows; where it
    changes less (the base circle, the nose) the rounding error is not random and the differences miss it, so
    q / sqrt(12) is the floor:

        accuracy = max(noise_level(lift), q / sqrt(12), ACCURACY_FLOOR_MM)

    an RMS error of a row, as the smoothing spline and the N-harmonic order read it.  A table printed to 1 um
    without noise has 0.29 um, one with 2 um of noise about 2 um.  The lift between the rows carries also the
    interpolation error of the angle step; that is no error of the rows and is judged where the fits are checked
    between the rows (:class:`TableLaw`).

    Parameters
    ----------
    lift_mm : ndarray
        The lifts of the table [mm], in the order of their angles.

    Returns
    -------
    float
        The accuracy [mm].

    References
    ----------
    Sheppard (1898), the variance q^2/12 of values rounded to a grid of step q.
    """
    return max(noise_level(lift_mm), lift_resolution(lift_mm) / np.sqrt(12.0), ACCURACY_FLOOR_MM)


def lobe_table(angle_deg, lift_mm, angle="crank", zero="gas_exchange_tdc", accuracy_mm=0.005,
               min_lift_mm=MIN_VALVE_LIFT_MM) -> tuple[np.ndarray, np.ndarray, float]:
    """The lobe of a lift table in the engine's cam frame: checked, trimmed and bounded in size for the fits.

    The table must cover at most one camshaft revolution, rise from the base circle (within
    ``BASE_CIRCLE_ACCURACIES`` x ``accuracy_mm`` of zero) to at least ``min_lift_mm`` and hold one lobe: one
    region of lift, of at least :data:`MIN_LOBE_CAM_DEG`; rows at the base circle separate regions (a single such
    row between lifted rows is noise).  A table of a whole revolution may cut the lobe at its ends; it is turned to start in the middle of
    its base circle.  The angles are moved into the engine's cam frame (firing TDC = gas-exchange TDC + 360
    crank deg; the highest row within (-180, 180] cam deg), the rows are trimmed to the lobe and
    ``LOBE_MARGIN`` of its angle of base circle on either side (the analysis does not depend on how much base
    circle the table holds) and, beyond ``FIT_POINTS`` rows, averaged in bins of equal angle.

    Parameters
    ----------
    angle_deg, lift_mm : ndarray
        The table: strictly increasing angles [deg] and lifts [mm].
    angle : {"crank", "cam"}
        What the angles measure.
    zero : {"gas_exchange_tdc", "firing_tdc"}
        The table's zero: the TDC that starts the intake stroke, or the firing TDC (360 crank deg later).
    accuracy_mm : float
        Measurement accuracy [mm].
    min_lift_mm : float
        Least largest lift of a lobe, in the table's lift [mm].

    Returns
    -------
    (ndarray, ndarray, float)
        Camshaft angles [rad] in the engine's cam frame, lifts [mm] as in the table, and the table rows per
        point (1 unless binned).

    Raises
    ------
    ValueError
        Naming the rows, their values and what is allowed.

    References
    ----------
    Shang Hanji (1988), section 5.1 (a measured table of the lobe); this project's reading of what a table of one
    lobe is.
    """
    revolution = 720.0 if angle == "crank" else 360.0
    unit = f"{angle} deg"
    a, h = np.asarray(angle_deg, dtype=float), np.asarray(lift_mm, dtype=float)
    if a[-1] - a[0] > revolution:
        raise LawError("table_span", start=a[0] * DEG, end=a[-1] * DEG, span=(a[-1] - a[0]) * DEG,
                       revolution=revolution * DEG, unit=unit)
    band = BASE_CIRCLE_ACCURACIES * accuracy_mm
    low, top = int(np.argmin(h)), int(np.argmax(h))
    if h[low] < -band:
        raise LawError("below_base_circle", lift=h[low] * MM, angle=a[low] * DEG, least=-band * MM)
    if h[top] < min_lift_mm:
        raise LawError("lift_too_small", lift=h[top] * MM, angle=a[top] * DEG, valve_least=MIN_VALVE_LIFT_MM * MM,
                       least=min_lift_mm * MM)
    if h[top] > MAX_LIFT_MM:
        raise LawError("lift_too_large", lift=h[top] * MM, angle=a[top] * DEG, most=MAX_LIFT_MM * MM)
    a, h = _whole_lobe(a, h, band, revolution, unit)
    first, last = _one_lobe(a, h, band)
    least = MIN_LOBE_CAM_DEG * revolution / 360.0
    if a[last] - a[first] < least:
        raise LawError("lobe_too_short", band=band * MM, start=a[first] * DEG, end=a[last] * DEG,
                       span=(a[last] - a[first]) * DEG, least=least * DEG, cam_least=MIN_LOBE_CAM_DEG, unit=unit)
    cam = (a + (0.5 * revolution if zero == "firing_tdc" else 0.0)) * (360.0 / revolution)
    cam -= 360.0 * np.ceil((cam[np.argmax(h)] - 180.0) / 360.0)
    margin = LOBE_MARGIN * (cam[last] - cam[first])
    keep = (cam >= cam[first] - margin) & (cam <= cam[last] + margin)
    if keep.sum() < MIN_LOBE_POINTS:
        raise LawError("too_few_rows", band=band * MM, start=a[first] * DEG, end=a[last] * DEG, rows=int(keep.sum()),
                       least=MIN_LOBE_POINTS)
    x, y, per_point = binned(cam[keep], h[keep], FIT_POINTS)
    return np.radians(x), y, per_point


def _whole_lobe(a, h, band, revolution, unit):
    """The table, turned to start in the middle of its base circle if it covers a whole revolution and its
    lobe runs over its ends; otherwise it must start and end on the base circle."""
    lifted = h > band
    if not (lifted[0] or lifted[-1]):
        return a, h
    whole = revolution - (a[-1] - a[0]) <= 2.0 * np.median(np.diff(a))
    if whole and not lifted.all():
        if a[-1] - a[0] >= revolution * (1.0 - 1e-12):   # the last row repeats the first
            a, h, lifted = a[:-1], h[:-1], lifted[:-1]
        base = np.flatnonzero(~lifted)
        m = base[base.size // 2]
        return np.concatenate([a[m:], a[:m] + revolution]), np.concatenate([h[m:], h[:m]])
    end, i = ("first", 0) if lifted[0] else ("last", -1)
    raise LawError("end_row_lifted", end=end, angle=a[i] * DEG, lift=h[i] * MM, band=band * MM,
                   revolution=revolution * DEG, unit=unit)


def _one_lobe(a, h, band):
    """First and last row of the lobe, the region of lift around the highest row; a second region that rises
    above twice the base-circle band (well above the noise) is a second lobe."""
    rows = np.flatnonzero(h > band)
    regions = np.split(rows, np.flatnonzero(np.diff(rows) > 2) + 1)
    top = int(np.argmax(h))
    lobe = next(r for r in regions if r[0] <= top <= r[-1])
    for r in regions:
        if r is not lobe and h[r].max() > 2.0 * band:
            raise LawError("second_lobe", start=a[r[0]] * DEG, end=a[r[-1]] * DEG, lift=h[r].max() * MM,
                           lobe_start=a[lobe[0]] * DEG, lobe_end=a[lobe[-1]] * DEG)
    return int(lobe[0]), int(lobe[-1])


def lift_event(fn, a, b, level, samples=4001) -> tuple[float, float]:
    """Where a fitted lift leaves the base circle and returns to it, within [a, b].

    The lobe is the stretch around the fit's highest point that stays above ``level`` (the noise band of the
    base circle); on either side the event ends at the nearest point where the fit reaches zero, so that the
    fitted lift inside the event is positive and its ends carry lift and velocity of the order of the noise.
    Where the fit stays above zero up to the edge of the window, the event ends at its lowest point there.

    Parameters
    ----------
    fn : callable
        Vectorised fitted lift ``fn(theta)`` [m].
    a, b : float
        The window of the data [rad].
    level : float
        Half-width of the base-circle band [m].
    samples : int
        Grid on which the crossings are located before Brent's method refines them.

    Returns
    -------
    (float, float)
        Start and end of the event [rad].
    """
    from scipy.optimize import brentq

    x = np.linspace(a, b, samples)
    h = fn(x)
    top = int(np.argmax(h))
    quiet = np.flatnonzero(h <= level)
    i = quiet[quiet < top].max(initial=0)
    j = quiet[quiet > top].min(initial=samples - 1)

    def root(k):  # the zero of the fit between x[k] and x[k + 1], where its sign changes
        if h[k] == 0.0 or h[k + 1] == 0.0:
            return x[k] if h[k] == 0.0 else x[k + 1]
        return brentq(lambda t: float(fn(np.array([t]))[0]), x[k], x[k + 1], xtol=1e-14)

    zero = np.flatnonzero(h[:i + 1] <= 0.0)
    start = root(int(zero[-1])) if zero.size else x[int(np.argmin(h[:i + 1]))]
    zero = np.flatnonzero(h[j:] <= 0.0)
    end = root(j + int(zero[0]) - 1) if zero.size else x[j + int(np.argmin(h[j:]))]
    return float(start), float(end)


@dataclass
class FitQuality:
    """How well a fit reproduces the table and how clean its derivatives are."""

    rms_residual: float        # [m]
    max_residual: float        # [m]
    jerk_sign_changes: int     # sign changes of d3h/dtheta3 over the lift event: wiggles
    jerk_total_variation: float  # [m/rad^3]


class TableLaw(RampedLaw):
    """A measured lift table as a lift law, through a smoothing spline or an N-harmonic fit, each following the
    table to its stated accuracy.

    The event is where the fit leaves the base circle and returns to it (:func:`lift_event`): outside it the
    lift is zero, inside it the fitted lift is positive, so the law never dips below the base circle and its
    event does not depend on how much base circle the table holds.

    Parameters
    ----------
    angles : ndarray
        Camshaft angles of the lobe's rows [rad] in the engine's cam frame (crank angle from the
        gas-exchange TDC / 2), as :func:`lobe_table` gives them.
    lift : ndarray
        Follower lift [m].
    fit : {"auto", "spline", "harmonic"}
        The curve the law evaluates: Reinsch's smoothing spline whose RMS residual is the stated accuracy
        (:func:`.fits.smoothing_spline`; generalised cross-validation's where the table is noisier), the stand-in of this
        package for Shang's 回弹法 fairing, or the N-harmonic fit of the smallest order that meets the accuracy;
        ``"auto"`` takes the one with the smaller generalised cross-validation score where the N-harmonic fit meets
        the accuracy and stays within the table's range, else the spline (:func:`.fits.choose_fit`).
    accuracy : float
        Measurement accuracy [m]: the harmonic order N is the smallest whose RMS residual
        meets it (choose N by the residual, not the largest N that fits); the base-circle
        band is ``BASE_CIRCLE_ACCURACIES`` times it.
    max_harmonics : int
        Upper bound of N; N is also at most (points - 1) / ``HARMONIC_POINTS_PER_ORDER``.
    ramp_height : float
        Lift the follower makes before the valve moves [m]: the clearance in a table of tappet lift, which
        holds the cam's ramps; 0 for a table of valve lift.
    rows_per_point : float
        Table rows averaged into each point (see :func:`.fits.binned`), for the record.
    accuracy_stated : bool
        Whether the accuracy was given (``accuracy_mm``) or derived from the table (:func:`table_accuracy`).

    Attributes
    ----------
    centre : float
        The lobe centre (symmetry axis) in the table's cam frame [rad], after the false-asymmetry correction.
    fit : str
        The fit the law evaluates, ``"spline"`` or ``"harmonic"``.
    choice : (str, float)
        Why: a code of :func:`.fits.choose_fit` and the ratio of the generalised cross-validation scores.
    smoothing : str
        How the spline's smoothing was chosen, ``"accuracy"`` or ``"gcv"`` (:func:`.fits.smoothing_spline`).

    Raises
    ------
    ValueError
        For ``fit = "harmonic"`` when the fit leaves the band [-3 accuracy, largest lift + 3 accuracy] between
        the rows (the message suggests the spline), for a spline that cannot be fitted, and for a row further from
        the fit than :data:`ROW_OFF_FIT` accuracies and :data:`ROW_OFF_LIFT` of the lift (a wrong row).
    """

    name = "table"
    source = cited("Shang Hanji (1988), sections 5.1-5.3",
                   note("source.measured", spline="Reinsch (1967)", validation="Craven and Wahba (1979)"))

    def __init__(self, angles, lift, fit="auto", accuracy=5e-6, max_harmonics=60, ramp_height=0.0,
                 rows_per_point=1.0, accuracy_stated=True):
        if fit not in FITS:
            raise InputError(f"fit = {fit!r}: allowed {', '.join(repr(f) for f in FITS)}")
        x, y = np.asarray(angles, dtype=float), np.asarray(lift, dtype=float)
        scatter = noise_level(y)
        if scatter > MOST_SCATTER * y.max():
            raise LawError("rows_scatter", scatter=scatter, share=scatter / y.max(), most=MOST_SCATTER)
        self.angles, self.values, self.accuracy = x, y, float(accuracy)
        self.rows_per_point, self.accuracy_stated = float(rows_per_point), bool(accuracy_stated)
        # N-harmonic fit about the highest point, the smallest N meeting the accuracy
        top = int(np.argmax(y))
        most = max(4, min(max_harmonics, (x.size - 1) // HARMONIC_POINTS_PER_ORDER))
        n, a, b, w, self.harmonic_rms = harmonic_order(x - x[top], y, self.accuracy, most,
                                                       1.15 * max(x[top] - x[0], x[-1] - x[top]))
        shift, self.asymmetry_rms = symmetry_shift(a, b, w, min(x[top] - x[0], x[-1] - x[top]))
        self.centre = float(x[top] + shift)
        self.harmonics = int(n)
        cos, sin = np.cos(np.arange(n + 1) * w * shift), np.sin(np.arange(n + 1) * w * shift)
        self._harmonic = (a * cos + b * sin, b * cos - a * sin, w)
        self._spline, self.smoothing, self.spline_rms, lam = smoothing_spline(x - self.centre, y, self.accuracy,
                                                                                   self.accuracy_stated)
        window = (float(x[0] - self.centre), float(x[-1] - self.centre))
        band = BASE_CIRCLE_ACCURACIES * self.accuracy
        below, above = interpolation_error(x, y)     # how far the lift may go beyond the rows between them
        swing = self.fitted(np.linspace(*window, 8001), "harmonic")[0]
        bounded = swing.min() >= -(band + below) and swing.max() <= y.max() + band + above
        if fit == "harmonic" and not bounded:
            raise LawError("harmonic_fit_swings", harmonics=n, low=swing.min(), high=swing.max(), least=-(band + below),
                           most=y.max() + band + above)
        self.gcv = {"harmonic": gcv_score(self.harmonic_rms, 2 * n + 1, x.size),
                    "spline": gcv_score(self.spline_rms, spline_dof(x - self.centre, lam), x.size)}
        self.fit, self.choice = choose_fit(fit, bounded, self.harmonic_rms <= self.accuracy, self.gcv)
        fit = self.fit
        # between the rows the fit used stays within the table's range and reaches its top, as far as it departs
        # from the rows, the noise of the measurement and the interpolation error of the step allow
        off = self.fitted(x - self.centre)[0] - y
        worst = int(np.argmax(np.abs(off)))
        most = max(ROW_OFF_FIT * max(self.accuracy, scatter), ROW_OFF_LIFT * np.delete(y, worst).max())
        if abs(off[worst]) > most:
            raise LawError("row_off_fit", off=abs(off[worst]), fit=fit, angle=x[worst], lift=y[worst], most=most,
                           times=ROW_OFF_FIT, share=ROW_OFF_LIFT)
        resid = abs(off[worst])
        noise = BASE_CIRCLE_ACCURACIES * max(self.accuracy, scatter)
        tol = noise + resid
        swing = self.fitted(np.linspace(*window, 8001))[0]
        # above the highest row only the noise and the nose's parabola: a smoothing fit may flatten the nose by its
        # residual, but a lift above what the rows and a smooth nose allow is not what was measured
        if swing.min() < -(tol + below) or y.max() - swing.max() > tol or swing.max() - y.max() > noise + above:
            raise LawError("fit_leaves_table", fit=fit, low=swing.min(), high=swing.max(), top=y.max(),
                           below=-(tol + below), above=noise + above)
        self.start_angle, self.end_angle = lift_event(lambda t: self.fitted(t)[0], *window, band)
        self._top = extremum(lambda t: self.fitted(t)[0], [self.start_angle, 0.0, self.end_angle], "max")[1]
        self._ramp_height = float(ramp_height)
        self._valve_span = (self.start_angle, self.end_angle)
        if ramp_height > 0.0:
            self._valve_span = level_span(lambda t: self.fitted(t)[0], self.start_angle, self.end_angle, ramp_height)
            if not np.isfinite(self._valve_span[0]):
                raise LawError("valve_never_opens", ramp=ramp_height)

    def _harmonic_derivatives(self, t):
        a, b, w = self._harmonic
        k = np.arange(a.size) * w
        c, s = np.cos(np.outer(t, k)), np.sin(np.outer(t, k))
        return np.array([c @ a + s @ b, -s @ (a * k) + c @ (b * k), -c @ (a * k**2) - s @ (b * k**2),
                         s @ (a * k**3) - c @ (b * k**3)])

    def fitted(self, theta, kind=None) -> np.ndarray:
        """Lift and three derivatives of a fit at angles from the lobe centre, shape (4, n)."""
        theta = np.asarray(theta, dtype=float)
        if (kind or self.fit) == "harmonic":
            return self._harmonic_derivatives(theta)
        return np.array([self._spline(theta, nu) for nu in range(4)])

    def derivatives(self, theta) -> np.ndarray:
        theta = np.asarray(theta, dtype=float)
        flat = theta.ravel()
        out = np.zeros((4, flat.size))
        inside = (flat >= self.start_angle) & (flat <= self.end_angle)
        out[:, inside] = self.fitted(flat[inside])
        out[0] = np.maximum(out[0], 0.0)    # the round-off of the event's ends (the fit is positive inside)
        return out.reshape((4,) + theta.shape)

    def quality(self, kind) -> FitQuality:
        """:class:`FitQuality` of the ``"spline"`` or ``"harmonic"`` fit against the table."""
        t = self.angles - self.centre
        d = self.fitted(t, kind)
        resid = self.values - d[0]
        event = self.values > 0.02 * self.values.max()
        fine = np.linspace(t[event][0], t[event][-1], 4001)
        jerk = self.fitted(fine, kind)[3]
        changes = int(np.sum(np.diff(np.sign(jerk[np.abs(jerk) > 1e-12 * np.abs(jerk).max()])) != 0))
        return FitQuality(float(np.sqrt(np.mean(resid**2))), float(np.abs(resid).max()), changes,
                          float(np.sum(np.abs(np.diff(jerk)))))

    @property
    def segments(self) -> list[Segment]:
        return [Segment("measured opening", self.start_angle, 0.0), Segment("measured closing", 0.0, self.end_angle)]

    @property
    def lift_max(self) -> float:
        """The largest fitted lift above the ramp [m] (a lobe's top need not lie on its symmetry axis)."""
        return self._top - self._ramp_height

    @property
    def ramp_height(self) -> float:
        return self._ramp_height

    @property
    def ramp_angle(self) -> float:
        """Opening ramp: from the start of the event to where the valve opens [rad]."""
        return self._valve_span[0] - self.start_angle

    @property
    def valve_opens(self) -> float:
        """Where the fitted lift exceeds the ramp height (the clearance) on the opening flank [rad]."""
        return self._valve_span[0]

    @property
    def valve_closes(self) -> float:
        """Where the fitted lift falls back to the ramp height on the closing flank [rad]."""
        return self._valve_span[1]

    @property
    def main_half_angle(self) -> float:
        return 0.5 * (self.end_angle - self.start_angle)

    def checks(self) -> list:
        """The N-harmonic fit must meet the stated measurement accuracy by ``max_harmonics``; if it does not, the
        table is noisier than stated (or the accuracy finer than the instrument's).  An accuracy derived from the
        rows (:func:`table_accuracy`) is not finer than their noise: an N-harmonic fit that misses it cannot follow
        the lobe (a kink at the valve's foot), which matters only where that fit is the one used."""
        if not (self.accuracy_stated or self.fit == "harmonic"):
            return []
        return [check("law.measured.residual", self.harmonic_rms, high=self.accuracy,
                      unit="mm", source=cited(note("source.harmonics_needed", work="Shang Hanji (1988), section 5.2",
                                                    harmonics=self.harmonics)))]

    def coefficients(self) -> dict:
        """The fit used, the harmonic order, the remaining (true) asymmetry, the lobe centre and the points fitted
        (with the table rows averaged into each)."""
        return {"fit": self.fit, "harmonics": self.harmonics, "asymmetry_rms_mm": self.asymmetry_rms * 1e3,
                "lobe_centre_cam_deg": float(np.degrees(self.centre)), "points": int(self.angles.size),
                "rows_per_point": self.rows_per_point}


