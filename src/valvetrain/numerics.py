"""Numerical helpers shared by the physics modules.

Only what numpy and scipy do not offer directly lives here.
"""

import math

import numpy as np

from .errors import InputError

_GAUSS_ORDER = 16
_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(_GAUSS_ORDER)


def cumulative_integral(fn, grid, breakpoints=()) -> np.ndarray:
    """Running integral of a piecewise-smooth function, exact to round-off for smooth pieces.

    The interval ``[grid[0], grid[-1]]`` is cut at every grid point and at every
    breakpoint inside it (where ``fn`` or a derivative may jump); each piece is
    integrated with a 16-point Gauss-Legendre rule, which is exact for polynomials of
    degree 31 and converges exponentially for analytic pieces.  All nodes are
    evaluated in one vectorised call of ``fn``.

    Parameters
    ----------
    fn : callable
        ``fn(x) -> ndarray``, vectorised over a 1-D array ``x``.
    grid : array_like
        Increasing abscissae where the running integral is wanted.
    breakpoints : array_like
        Abscissae where ``fn`` is not smooth (segment junctions of a lift law).

    Returns
    -------
    ndarray
        ``I[k] = integral of fn from grid[0] to grid[k]``; ``I[0] = 0``.

    Examples
    --------
    >>> float(cumulative_integral(np.sin, [0.0, np.pi])[-1])  # doctest: +ELLIPSIS
    2.0000000000...
    """
    grid, edges, half, nodes = _gauss_pieces(grid, breakpoints)
    values = np.asarray(fn(nodes.ravel()), dtype=float).reshape(nodes.shape)
    return _running(values, half, edges, grid)


def _gauss_pieces(grid, breakpoints):
    """(grid, edges, half widths, nodes shape (pieces, order)) of :func:`cumulative_integral`'s pieces."""
    grid = np.asarray(grid, dtype=float)
    if grid.ndim != 1 or grid.size < 2 or np.any(np.diff(grid) <= 0):
        raise InputError("grid must be a strictly increasing 1-D array of at least two points")
    bp = np.asarray(breakpoints, dtype=float)
    bp = bp[(bp > grid[0]) & (bp < grid[-1])]
    edges = np.unique(np.concatenate([grid, bp]))
    a, b = edges[:-1], edges[1:]
    half = 0.5 * (b - a)
    return grid, edges, half, (0.5 * (a + b))[:, None] + half[:, None] * _NODES[None, :]


def _running(values, half, edges, grid):
    """The running integral at ``grid`` from the function's ``values`` at the nodes of :func:`_gauss_pieces`."""
    pieces = half * (values @ _WEIGHTS)
    running = np.concatenate([[0.0], np.cumsum(pieces)])
    return running[np.searchsorted(edges, grid)]


def integrals(fn, starts, ends, breakpoints) -> np.ndarray:
    """Integrals of several piecewise-smooth functions, each over its own interval, all nodes in one call of ``fn``.

    Parameters
    ----------
    fn : callable
        ``fn(x, member) -> ndarray``: function ``member[k]`` at ``x[k]`` (1-D arrays).
    starts, ends : array_like
        The interval of each function, shape (n,).
    breakpoints : sequence of array_like
        Each function's abscissae where it is not smooth.

    Returns
    -------
    ndarray
        Shape (n,): the integral of function i from ``starts[i]`` to ``ends[i]``, that of :func:`cumulative_integral`
        on the grid ``[starts[i], ends[i]]`` (the same pieces and nodes, so the same number).
    """
    pieces = [_gauss_pieces([a, b], bp) for a, b, bp in zip(starts, ends, breakpoints, strict=True)]
    sizes = [p[3].size for p in pieces]
    values = np.asarray(fn(np.concatenate([p[3].ravel() for p in pieces]), np.repeat(np.arange(len(pieces)), sizes)),
                        dtype=float)
    parts = np.split(values, np.cumsum(sizes)[:-1])
    return np.array([_running(v.reshape(nodes.shape), half, edges, grid)[-1]
                     for v, (grid, edges, half, nodes) in zip(parts, pieces, strict=True)])


TIE_RTOL = 16.0 * np.finfo(float).eps
"""Relative difference within which two values are a tie for :func:`first_largest`: 16 units in the last place.
The two equal maxima of a symmetric function (a symmetric cam's flanks, the lobes of a multi-cylinder camshaft)
come out a few units apart, in a direction that depends on the machine (the BLAS kernel of a matrix product); a
value further from the largest than this is not its equal."""


def first_largest(values, axis=None, atol=0.0) -> int | np.ndarray:
    """The index of the largest value, of the values within :data:`TIE_RTOL` of it (relative, plus ``atol``) the
    first: a tie is decided by the order of ``values`` (along ``axis``), not by the round-off of its members.

    Parameters
    ----------
    values : array_like
        The values; NaN is never the largest.
    axis : int, optional
        The axis along which to search (None: the flattened array, as :func:`numpy.argmax`).
    atol : float
        An absolute part of the tie (the unit of ``values``), for values that are differences of larger numbers
        (the distance of a grid point from an angle).

    Returns
    -------
    int or ndarray
        The index (an array of them along ``axis``, as :func:`numpy.argmax`).

    Examples
    --------
    The two maxima of a symmetric cam, one unit in the last place apart: the first wins, whichever is larger.

    >>> force = np.array([1.0, 3.0, 2.0, 3.0 * (1.0 + 2.2e-16), 1.0])
    >>> int(first_largest(force)), int(np.argmax(force))
    (1, 3)
    """
    values = np.asarray(values, dtype=float)
    if axis is None:
        values, axis = values.ravel(), 0
    top = np.nanmax(values, axis=axis, keepdims=True)
    tied = values >= top - np.where(np.isfinite(top), TIE_RTOL * np.abs(top) + atol, 0.0)
    return np.argmax(tied, axis=axis) if values.ndim > 1 else int(np.argmax(tied))


def extremum(fn, edges, kind="max", samples=65) -> tuple[float, float]:
    """Global extremum of a piecewise-smooth scalar function on an interval.

    Each piece between consecutive ``edges`` is sampled at ``samples`` points (its
    ends included); the best sample is then refined with bounded Brent iteration
    (:func:`bounded_minimum`) between its neighbours, and the better of
    the sample and the refined point is returned; of samples equal to round-off (the two extrema of a symmetric
    function) the first, the smallest ``x``, is refined (:func:`first_largest`).  An extremum at a junction (a kink)
    is found exactly because the junctions are sampled.  Where the function is not
    finite next to the best sample (a masked region), the sample itself is returned.

    Parameters
    ----------
    fn : callable
        Vectorised ``fn(x) -> ndarray``.
    edges : array_like
        Increasing piece boundaries, at least two.
    kind : {"max", "min"}
    samples : int
        Samples per piece.

    Returns
    -------
    (float, float)
        ``(x, fn(x))`` at the extremum.

    Examples
    --------
    >>> x, y = extremum(np.sin, [0.0, 3.0], "max")
    >>> round(x, 6), round(y, 12)  # a smooth extremum's place is fixed only to ~sqrt(eps)
    (1.570796, 1.0)
    """
    sign = 1.0 if kind == "max" else -1.0
    edges = np.asarray(edges, dtype=float)
    t = np.linspace(0.0, 1.0, samples)
    xs = np.unique((edges[:-1, None] + (edges[1:] - edges[:-1])[:, None] * t[None, :]).ravel())
    ys = sign * np.asarray(fn(xs), dtype=float)
    i = first_largest(ys)
    j, k = max(i - 1, 0), min(i + 1, xs.size - 1)
    lo, hi = xs[j], xs[k]
    best_x, best_y = xs[i], ys[i]
    if hi > lo and np.all(np.isfinite(ys[j:k + 1])):
        worst = float(-ys[j:k + 1].min())

        def objective(x):  # a value that is not finite between the samples (a pole, a cusp) is no extremum
            y = sign * float(fn(np.array([x]))[0])
            return -y if math.isfinite(y) else worst

        x, fx = bounded_minimum(objective, lo, hi, 1e-13 * max(1.0, abs(hi)))
        if -fx > best_y:
            best_x, best_y = x, -fx
    return float(best_x), float(sign * best_y)


def bounded_minimum(fn, a, b, xatol, max_evaluations=500) -> tuple[float, float]:
    """A local minimum of a scalar function on ``[a, b]`` by Brent's method (golden section and parabolic
    interpolation), the iteration of :func:`scipy.optimize.minimize_scalar` ``method="bounded"``, step for step.

    Parameters
    ----------
    fn : callable
        ``fn(x) -> float`` of one float.
    a, b : float
        Bounds, ``a <= b`` (finite).
    xatol : float
        Absolute tolerance of the abscissa (the unit of ``a``).
    max_evaluations : int
        Bound on the calls of ``fn``.

    Returns
    -------
    (float, float)
        ``(x, fn(x))`` at the best point found.

    Notes
    -----
    The same arithmetic as SciPy's ``_minimize_scalar_bounded`` on plain floats (``abs`` and ``max``
    instead of numpy's scalar functions, which cost a microsecond each), so the points and the result are the same
    to the bit; a refinement of :func:`extremum` calls ``fn`` some 45 times.

    References
    ----------
    SciPy, ``scipy/optimize/_optimize.py``, ``_minimize_scalar_bounded``: Brent's minimisation without derivatives
    in the form of the procedure fmin of Forsythe, Malcolm and Moler.
    """
    sqrt_eps = math.sqrt(2.2e-16)
    golden_mean = 0.5 * (3.0 - math.sqrt(5.0))
    fulc = a + golden_mean * (b - a)
    nfc, xf = fulc, fulc
    rat = e = 0.0
    fx = fn(xf)
    num = 1
    ffulc = fnfc = fx
    xm = 0.5 * (a + b)
    tol1 = sqrt_eps * abs(xf) + xatol / 3.0
    tol2 = 2.0 * tol1
    while abs(xf - xm) > tol2 - 0.5 * (b - a):
        golden = True
        if abs(e) > tol1:   # a parabola through the three best points
            golden = False
            r = (xf - nfc) * (fx - ffulc)
            q = (xf - fulc) * (fx - fnfc)
            p = (xf - fulc) * q - (xf - nfc) * r
            q = 2.0 * (q - r)
            if q > 0.0:
                p = -p
            q = abs(q)
            r = e
            e = rat
            if abs(p) < abs(0.5 * q * r) and p > q * (a - xf) and p < q * (b - xf):
                rat = (p + 0.0) / q
                x = xf + rat
                if (x - a) < tol2 or (b - x) < tol2:
                    rat = tol1 * _sign_or_one(xm - xf)
            else:
                golden = True
        if golden:
            e = (a - xf) if xf >= xm else (b - xf)
            rat = golden_mean * e
        x = xf + _sign_or_one(rat) * max(abs(rat), tol1)
        fu = fn(x)
        num += 1
        if fu <= fx:
            if x >= xf:
                a = xf
            else:
                b = xf
            fulc, ffulc = nfc, fnfc
            nfc, fnfc = xf, fx
            xf, fx = x, fu
        else:
            if x < xf:
                a = x
            else:
                b = x
            if fu <= fnfc or nfc == xf:
                fulc, ffulc = nfc, fnfc
                nfc, fnfc = x, fu
            elif fu <= ffulc or fulc == xf or fulc == nfc:
                fulc, ffulc = x, fu
        xm = 0.5 * (a + b)
        tol1 = sqrt_eps * abs(xf) + xatol / 3.0
        tol2 = 2.0 * tol1
        if num >= max_evaluations:
            break
    return float(xf), float(fx)


def _sign_or_one(x):
    """The sign of ``x``, 1 for zero (SciPy's ``np.sign(x) + (x == 0)``)."""
    return 1.0 if x >= 0.0 else -1.0


def bracketed_roots(fn, a, b, fa, fb, max_iterations=100, brackets=False) -> np.ndarray | tuple[np.ndarray, ...]:
    """Roots of a function in many brackets at once, by the Illinois variant of regula falsi.

    Every bracket is refined in the same vectorised call of ``fn`` per iteration until it
    is as narrow as round-off allows (4 eps of its abscissa, or of its first width near
    zero) or ``fn`` vanishes at the new point.  A jump of ``fn`` across zero (a kink of its
    antiderivative) is located like a root.

    Parameters
    ----------
    fn : callable
        ``fn(x) -> ndarray`` with ``fn(x)[i]`` the function of bracket ``i`` at ``x[i]``
        (``x`` holds one abscissa per bracket, in the order of ``a``).
    a, b : array_like
        Ends of the brackets.
    fa, fb : array_like
        ``fn`` at the ends, of opposite signs (neither zero).
    max_iterations : int
        Bound on the iterations (the Illinois method converges superlinearly, in some 10
        iterations from a bracket of a hundredth of the abscissa).
    brackets : bool
        Return the last brackets too.

    Returns
    -------
    ndarray, or (ndarray, ndarray, ndarray) with ``brackets``
        One root per bracket (and the ends a, b of the last brackets, ``fn`` of opposite signs at them: at a jump
        of ``fn`` across zero, its two sides).

    Notes
    -----
    The new point is the secant's zero :math:`c = b - f_b (b - a)/(f_b - f_a)`; it replaces the
    end whose value has its sign, and when the same end is replaced twice in a row the value
    kept at the other end is halved, which keeps the bracket shrinking from both sides.

    References
    ----------
    Dowell and Jarratt (1971).

    Examples
    --------
    >>> x = bracketed_roots(np.cos, [1.0, 4.0], [2.0, 5.0], np.cos([1.0, 4.0]), np.cos([2.0, 5.0]))
    >>> bool(np.allclose(x, [np.pi / 2, 3 * np.pi / 2], rtol=0, atol=1e-15))
    True
    """
    a, b = np.array(a, dtype=float), np.array(b, dtype=float)
    fa, fb = np.array(fa, dtype=float), np.array(fb, dtype=float)
    tol = 4.0 * np.finfo(float).eps * np.maximum(np.maximum(np.abs(a), np.abs(b)), np.abs(b - a))
    x = 0.5 * (a + b)
    side = np.zeros(a.size)               # +1: b was replaced last, -1: a was replaced last
    active = np.abs(b - a) > tol
    for _ in range(max_iterations):
        i = np.flatnonzero(active)
        if i.size == 0:
            break
        x[i] = b[i] - fb[i] * (b[i] - a[i]) / (fb[i] - fa[i])
        fx = np.asarray(fn(x), dtype=float)[i]
        same_b = np.sign(fx) == np.sign(fb[i])
        same_a = np.sign(fx) == np.sign(fa[i])
        j, k = i[same_b], i[same_a]
        fa[j[side[j] > 0]] *= 0.5
        fb[k[side[k] < 0]] *= 0.5
        b[j], fb[j], side[j] = x[j], fx[same_b], 1.0
        a[k], fa[k], side[k] = x[k], fx[same_a], -1.0
        active[i] = (fx != 0.0) & (np.abs(b[i] - a[i]) > tol[i])
    return (x, a, b) if brackets else x


def level_span(fn, a, b, level, samples=4001) -> tuple[float, float]:
    """First upward and last downward crossing of ``level`` by a function on [a, b].

    ``fn`` is sampled at ``samples`` points; both crossings are then refined together by
    :func:`bracketed_roots` between their neighbouring samples, to round-off (no SciPy import on the path of a
    design).

    Parameters
    ----------
    fn : callable
        Vectorised ``fn(x) -> ndarray``.
    a, b : float
        The interval.
    level : float
        The level to cross.

    Returns
    -------
    (float, float)
        The two crossings; ``(nan, nan)`` when ``fn`` never exceeds ``level`` or already
        exceeds it at an end of the interval.

    Examples
    --------
    >>> [round(x, 9) for x in level_span(np.sin, 0.0, np.pi, 0.5)]
    [0.523598776, 2.617993878]
    """
    x = np.linspace(a, b, samples)
    f = np.asarray(fn(x), dtype=float) - level
    above = np.flatnonzero(f > 0.0)
    if above.size == 0 or above[0] == 0 or above[-1] == x.size - 1:
        return float("nan"), float("nan")
    lo, hi = np.array([above[0] - 1, above[-1]]), np.array([above[0], above[-1] + 1])
    roots = np.where(f[lo] == 0.0, x[lo], x[hi])      # a sample on the level is the crossing itself
    inside = (f[lo] != 0.0) & (f[hi] != 0.0)
    if inside.any():
        roots[inside] = bracketed_roots(lambda t: np.asarray(fn(t), dtype=float) - level, x[lo][inside],
                                        x[hi][inside], f[lo][inside], f[hi][inside])
    return float(roots[0]), float(roots[1])


def invert_angle(angle_of, target, samples=4097, brackets=False) -> np.ndarray | tuple[np.ndarray, ...]:
    """The parameters theta in [-pi, pi] at which an angle ``angle_of(theta)`` [rad] that grows by 2 pi over the
    revolution equals each ``target`` [rad], all at once.

    Each target is bracketed on ``samples`` parameters and the bracket refined by :func:`bracketed_roots` to the
    round-off of the angle (a polar angle of a contour point, the direction of a normal): exact, not interpolated.
    A target that the angle jumps over (a gap of a contour) gives the parameter of the jump; with ``brackets``
    the ends of the last brackets are returned too (of the shape of ``target``), the jump's two sides.

    Examples
    --------
    >>> theta = invert_angle(lambda t: t + 0.1 * np.sin(t), 1.0)   # Kepler's equation, e = 0.1, M = 1
    >>> round(float(theta), 6), round(float(theta + 0.1 * np.sin(theta)), 12)
    (0.920415, 1.0)
    """
    target = np.asarray(target, dtype=float)
    goal = target.ravel()
    theta = np.linspace(-np.pi, np.pi, samples)
    a = np.unwrap(angle_of(theta))
    wrapped = (goal - a[0]) % (2.0 * np.pi) + a[0]
    k = np.clip(np.searchsorted(a, wrapped), 1, samples - 1)
    lo, hi = theta[k - 1], theta[k]

    def miss(t):
        return np.angle(np.exp(1j * (angle_of(t) - goal)))

    f_lo, f_hi = miss(lo), miss(hi)
    # a root on a bracket's end may show no sign change by round-off: take the nearer end (an empty bracket)
    edge = np.sign(f_lo) == np.sign(f_hi)
    at = np.where(np.abs(f_lo) <= np.abs(f_hi), lo, hi)
    lo, hi = np.where(edge, at, lo), np.where(edge, at, hi)
    found = bracketed_roots(miss, lo, hi, miss(lo), miss(hi), brackets=brackets)
    return tuple(f.reshape(target.shape) for f in found) if brackets else found.reshape(target.shape)
