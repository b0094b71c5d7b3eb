"""Piston kinematics of the central and offset slider-crank mechanism (Power units manual (n.d.), section 1).

Conventions: crank angle ``phi`` [rad]
from the crank position parallel to the cylinder axis (TDC for a central mechanism),
positive in the direction of rotation; displacement, velocity and acceleration along
the cylinder axis, positive from TDC towards the crankshaft.  The offset ``k = a/R`` is
positive when the cylinder axis is displaced towards the side where the crank pin is at
phi = 90 deg: sin(beta) = lambda (sin(phi) - k).

Every quantity has the exact slider-crank form (default) and the textbook series of the
manual (``exact=False``).
"""

from functools import lru_cache

import numpy as np

from ..errors import InputError
from ..locale import NoteText, note
from ..numerics import extremum


def rod_angle(phi, lam, k=0.0) -> float | np.ndarray:
    """Connecting-rod angle beta = arcsin(lambda (sin phi - k)) [rad] (Power units manual (n.d.), section 2, exact)."""
    return np.arcsin(lam * (np.sin(phi) - k))


def displacement(phi, radius, lam, k=0.0, exact=True) -> float | np.ndarray:
    """Piston displacement s [m].

    Parameters
    ----------
    phi : array_like
        Crank angle [rad].
    radius : float
        Crank radius R [m].
    lam : float
        lambda = R / L.
    k : float
        Relative offset a / R.
    exact : bool
        Exact slider-crank (measured from the true TDC) or the manual's series
        (1.2)/(1.3) (measured from the phi = 0 position, as the manual does).

    Notes
    -----
    Series: :math:`s = R[(1-\\cos\\varphi) + \\frac{\\lambda}{4}(1-\\cos2\\varphi) - k\\lambda\\sin\\varphi]`.
    Exact: :math:`s = \\sqrt{(L+R)^2 - a^2} - R\\cos\\varphi - L\\cos\\beta`.

    References
    ----------
    Power units manual (n.d.), eqs. (1.2)-(1.3); the exact form of the slider-crank.

    Examples
    --------
    Central mechanism at BDC: the stroke 2R in both forms.

    >>> round(float(displacement(np.pi, 0.04, 0.25)), 15), round(float(displacement(np.pi, 0.04, 0.25, exact=False)), 15)
    (0.08, 0.08)
    """
    phi = np.asarray(phi, dtype=float)
    if not exact:
        return radius * ((1.0 - np.cos(phi)) + lam / 4.0 * (1.0 - np.cos(2.0 * phi)) - k * lam * np.sin(phi))
    rod = radius / lam
    top = np.sqrt((rod + radius) ** 2 - (k * radius) ** 2)
    return top - radius * np.cos(phi) - rod * np.sqrt(1.0 - (lam * (np.sin(phi) - k)) ** 2)


def velocity(phi, radius, lam, omega, k=0.0, exact=True) -> float | np.ndarray:
    """Piston velocity v [m/s] at crank speed omega [rad/s].

    Notes
    -----
    Series (1.5)/(1.6): :math:`v = \\omega R(\\sin\\varphi + \\frac{\\lambda}{2}\\sin2\\varphi - k\\lambda\\cos\\varphi)`.
    Exact: :math:`v = \\omega R\\sin(\\varphi+\\beta)/\\cos\\beta`.

    References
    ----------
    Power units manual (n.d.), eqs. (1.5)-(1.6); the exact form of the slider-crank.
    """
    phi = np.asarray(phi, dtype=float)
    if not exact:
        return omega * radius * (np.sin(phi) + lam / 2.0 * np.sin(2.0 * phi) - k * lam * np.cos(phi))
    u = np.sin(phi) - k
    return omega * radius * (np.sin(phi) + lam * u * np.cos(phi) / np.sqrt(1.0 - (lam * u) ** 2))


def acceleration(phi, radius, lam, omega, k=0.0, exact=True) -> float | np.ndarray:
    """Piston acceleration j [m/s^2] at constant crank speed omega [rad/s].

    Notes
    -----
    Series (1.8)/(1.9): :math:`j = \\omega^2R(\\cos\\varphi + \\lambda\\cos2\\varphi + k\\lambda\\sin\\varphi)`.
    Exact: :math:`j = \\omega^2R\\left[\\cos\\varphi + \\lambda\\frac{\\cos^2\\varphi - u\\sin\\varphi +
    \\lambda^2u^3\\sin\\varphi}{(1-\\lambda^2u^2)^{3/2}}\\right]`, :math:`u = \\sin\\varphi - k`.

    References
    ----------
    Power units manual (n.d.), eqs. (1.8)-(1.9); the exact form of the slider-crank.

    Examples
    --------
    At TDC both forms give j_max = omega^2 R (1 + lambda) (1.10).

    >>> float(acceleration(0.0, 0.04, 0.25, 100.0)), float(acceleration(0.0, 0.04, 0.25, 100.0, exact=False))
    (500.0, 500.0)
    """
    phi = np.asarray(phi, dtype=float)
    if not exact:
        return omega**2 * radius * (np.cos(phi) + lam * np.cos(2.0 * phi) + k * lam * np.sin(phi))
    s, c = np.sin(phi), np.cos(phi)
    u = s - k
    return omega**2 * radius * (c + lam * (c * c - u * s + lam**2 * u**3 * s) / (1.0 - (lam * u) ** 2) ** 1.5)


def textbook_extremes(radius, lam, omega) -> dict[str, float]:
    """The manual's closed forms for a central mechanism: (1.7) v_max, (1.10) j_max, (1.11) j_min and its angle.

    Returns
    -------
    dict
        ``v_max`` [m/s], ``j_max``, ``j_min`` [m/s^2], ``j_min_angle`` [rad] (the first of the
        pair 180 deg -+ arccos(1/(4 lambda)); 180 deg for lambda <= 1/4).

    References
    ----------
    Power units manual (n.d.), eqs. (1.7), (1.10), (1.11) (the minus sign of (1.11) is lost in the extraction).
    """
    out = {"v_max": omega * radius * np.sqrt(1.0 + lam**2), "j_max": omega**2 * radius * (1.0 + lam)}
    if lam > 0.25:
        out["j_min"] = -omega**2 * radius * (lam + 1.0 / (8.0 * lam))
        out["j_min_angle"] = np.pi - np.arccos(1.0 / (4.0 * lam))
    else:
        out["j_min"] = -omega**2 * radius * (1.0 - lam)
        out["j_min_angle"] = np.pi
    return out


def extremes(radius, lam, omega, k=0.0, exact=True) -> dict[str, float]:
    """Extremes of the piston velocity and acceleration found on the chosen formulas over a revolution.

    Returns
    -------
    dict
        ``v_max``, ``v_max_angle``, ``j_max``, ``j_max_angle``, ``j_min``, ``j_min_angle``
        (SI; angles in rad in [0, 2 pi)).

    Notes
    -----
    Found once for each set of arguments a process meets (the last 64): the samples of a tolerance study design the
    same crank again and again, and its six Brent searches were 4 % of a sample of the built-in example.
    """
    return dict(_extremes(float(radius), float(lam), float(omega), float(k), bool(exact)))


@lru_cache(maxsize=64)
def _extremes(radius, lam, omega, k, exact) -> tuple[tuple[str, float], ...]:
    """:func:`extremes` of plain floats, as the items of its dict."""
    edges = np.linspace(0.0, 2.0 * np.pi, 9)
    xv, v = extremum(lambda p: velocity(p, radius, lam, omega, k, exact), edges, "max")
    xa, a_max = extremum(lambda p: acceleration(p, radius, lam, omega, k, exact), edges, "max")
    xn, a_min = extremum(lambda p: acceleration(p, radius, lam, omega, k, exact), edges, "min")
    return (("v_max", v), ("v_max_angle", xv % (2 * np.pi)), ("j_max", a_max), ("j_max_angle", xa % (2 * np.pi)),
            ("j_min", a_min), ("j_min_angle", xn % (2 * np.pi)))


def piston_stroke(radius, lam, k=0.0) -> float:
    """Piston stroke of the exact slider-crank, sqrt((L+R)^2 - a^2) - sqrt((L-R)^2 - a^2) [m] (2R for k = 0).

    References
    ----------
    Exact slider-crank geometry of the offset mechanism (derived in this package).

    Examples
    --------
    2R for a central mechanism; k = 0.1, lambda = 0.285 gives 2R x 1.00044.

    >>> round(float(piston_stroke(0.04, 0.25)), 15), round(float(piston_stroke(1.0, 0.285, 0.1)) / 2, 5)
    (0.08, 1.00044)
    """
    rod, a = radius / lam, k * radius
    return np.sqrt((rod + radius) ** 2 - a**2) - np.sqrt((rod - radius) ** 2 - a**2)


def crank_angle_at(travel, radius, lam, k=0.0, exact=True, upstroke=False) -> float | np.ndarray:
    """Crank angle at which the piston has travelled ``travel`` from TDC: the inverse of :func:`displacement`.

    Parameters
    ----------
    travel : array_like
        Piston travel from TDC s [m], 0 <= s <= stroke (:func:`piston_stroke`; 2R for the series).
    radius : float
        Crank radius R [m].
    lam : float
        lambda = R / L.
    k : float
        Relative offset a / R (exact kinematics only).
    exact : bool
        Exact slider-crank or the manual's series (1.2) of a central mechanism.
    upstroke : bool
        The angle on the way back from BDC to TDC, in [phi_BDC, 2 pi + phi_TDC], instead of the
        angle on the way down, in [phi_TDC, phi_BDC] (:func:`dead_centres`).

    Returns
    -------
    ndarray
        Crank angle phi [rad] in the convention of :func:`displacement`.

    Raises
    ------
    ValueError
        For a travel outside the stroke, or an offset with the series (measured from the
        phi = 0 position, not from TDC, and a quartic in cos phi).

    Notes
    -----
    Exact: the crank pin lies at R from the crank centre O and at L from the piston pin P,
    which is at :math:`d = \\sqrt{a^2 + x^2}` from O, :math:`x = \\sqrt{(L+R)^2 - a^2} - s`.
    The angle between OP and the crank follows from the triangle O-crank pin-P,

    .. math:: \\tan^2\\frac{\\psi}{2} = \\frac{1-\\cos\\psi}{1+\\cos\\psi}
              = \\frac{p\\,(2L - p)}{q\\,(2L + q)},\\quad p = L + R - d,\\ q = d - (L - R),

    with p and q written without cancellation, :math:`p = s(2x_T - s)/(L + R + d)`,
    :math:`q = (x - x_B)(x + x_B)/(d + L - R)` (:math:`x_T, x_B` the pin positions at TDC and BDC);
    OP leans by :math:`\\delta = \\arctan(a/x)` from the cylinder axis, so
    :math:`\\varphi = \\delta + \\psi` on the way down and :math:`2\\pi + \\delta - \\psi` on the way back.

    Series: (1.2) is a quadratic in cos phi; with :math:`u = s/R` and :math:`w = 2 - u`,

    .. math:: 1 - \\cos\\varphi = \\frac{2u}{1 + \\lambda + \\sqrt{(1+\\lambda)^2 - 2\\lambda u}},\\quad
              1 + \\cos\\varphi = \\frac{2w}{1 - \\lambda + \\sqrt{(1-\\lambda)^2 + 2\\lambda w}},

    and :math:`\\varphi = 2\\arctan\\sqrt{(1-\\cos\\varphi)/(1+\\cos\\varphi)}`; both forms keep
    full precision at the dead centres.

    References
    ----------
    Power units manual (n.d.), eq. (1.2) and section 1; the exact slider-crank
    (solved for phi here); the series form is (8.1) of Valve-train practical works (n.d.), work 8, for s = 2R (1 - sigma).

    Examples
    --------
    Half the stroke of a central mechanism, lambda = 0.25: 82.8 deg with the exact form, the
    series gives cos phi = (sqrt(1.5625 - 0.5) - 1) / 0.25 (1.2):

    >>> round(float(np.degrees(crank_angle_at(0.04, 0.04, 0.25))), 4)
    82.8192
    >>> bool(np.isclose(np.cos(crank_angle_at(0.04, 0.04, 0.25, exact=False)), (np.sqrt(1.0625) - 1) / 0.25))
    True
    """
    s = np.asarray(travel, dtype=float)
    full = piston_stroke(radius, lam, k) if exact else 2.0 * radius
    if np.any(s < 0.0) or np.any(s > full):
        raise InputError(f"piston travel from TDC: allowed 0 ... {full:g} m (the stroke)")
    if exact:
        rod, a = radius / lam, k * radius
        top, bottom = np.sqrt((rod + radius) ** 2 - a**2), np.sqrt((rod - radius) ** 2 - a**2)
        x = top - s
        d = np.hypot(a, x)
        p = s * (2.0 * top - s) / (rod + radius + d)
        q = (x - bottom) * (x + bottom) / (d + rod - radius)
        psi = 2.0 * np.arctan2(np.sqrt(p * (2.0 * rod - p)), np.sqrt(q * (2.0 * rod + q)))
        delta = np.arctan2(a, x)
    else:
        if k != 0.0:
            raise InputError(NoteText(note("crank.offset_series")))
        u = s / radius
        w = 2.0 - u
        one_minus_cos = 2.0 * u / (1.0 + lam + np.sqrt((1.0 + lam) ** 2 - 2.0 * lam * u))
        one_plus_cos = 2.0 * w / (1.0 - lam + np.sqrt((1.0 - lam) ** 2 + 2.0 * lam * w))
        psi = 2.0 * np.arctan2(np.sqrt(one_minus_cos), np.sqrt(one_plus_cos))
        delta = 0.0
    return 2.0 * np.pi + delta - psi if upstroke else delta + psi


def dead_centres(lam, k=0.0) -> tuple[float, float]:
    """Crank angles of TDC and BDC of an offset mechanism [rad]: arcsin(k lambda/(1+lambda)),
    pi + arcsin(k lambda/(1-lambda)) (exact slider-crank geometry)."""
    return np.arcsin(k * lam / (1.0 + lam)), np.pi + np.arcsin(k * lam / (1.0 - lam))


def brix_displacement(phi, radius, lam) -> float | np.ndarray:
    """Piston displacement of Brix's graphical construction [m].

    Notes
    -----
    A ray from O', offset from the circle centre by the Brix correction e = R lambda / 2
    (eq. 2.1) towards BDC, parallel to the crank, meets the crank circle; its projection on
    the stroke axis gives
    :math:`s = R + e\\sin^2\\varphi - \\cos\\varphi\\sqrt{R^2 - e^2\\sin^2\\varphi}`, equal to (1.2)
    to O(lambda^2).

    References
    ----------
    Power units manual (n.d.), eq. (2.1).
    """
    phi = np.asarray(phi, dtype=float)
    e = radius * lam / 2.0
    return radius + e * np.sin(phi) ** 2 - np.cos(phi) * np.sqrt(radius**2 - (e * np.sin(phi)) ** 2)


def brix_crank_angle(travel, radius, lam, upstroke=False) -> float | np.ndarray:
    """Crank angle at which Brix's construction puts the piston at ``travel`` from TDC [rad]: the inverse
    of :func:`brix_displacement`.

    Parameters
    ----------
    travel : array_like
        Piston travel from TDC s [m], 0 <= s <= 2R.
    radius, lam : float
        Crank radius R [m] and lambda = R / L.
    upstroke : bool
        The angle in [pi, 2 pi] (BDC back to TDC) instead of [0, pi].

    Notes
    -----
    The point of the crank circle above the travel s is :math:`(R - s, \\sqrt{s(2R - s)})` from
    the circle centre; the ray to it from O', e = R lambda / 2 towards BDC, is parallel to the
    crank, so

    .. math:: \\varphi = \\arctan\\frac{\\sqrt{s(2R - s)}}{R + e - s}.

    References
    ----------
    Power units manual (n.d.), eq. (2.1) (solved for phi here).

    Examples
    --------
    The ray to the top of the circle (s = R) from O' at e = R lambda / 2:

    >>> bool(np.isclose(brix_crank_angle(0.04, 0.04, 0.25), np.arctan2(1.0, 0.125)))
    True
    """
    s = np.asarray(travel, dtype=float)
    if np.any(s < 0.0) or np.any(s > 2.0 * radius):
        raise InputError(f"piston travel from TDC: allowed 0 ... {2.0 * radius:g} m (the stroke)")
    phi = np.arctan2(np.sqrt(s * (2.0 * radius - s)), radius + radius * lam / 2.0 - s)
    return 2.0 * np.pi - phi if upstroke else phi
