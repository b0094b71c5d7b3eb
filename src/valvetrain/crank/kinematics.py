"""Piston kinematics of the central and offset slider-crank mechanism (seed 001, section 1).

Conventions (spec/crank-kinematics-dynamics.md, section 2): crank angle ``phi`` [rad]
from the crank position parallel to the cylinder axis (TDC for a central mechanism),
positive in the direction of rotation; displacement, velocity and acceleration along
the cylinder axis, positive from TDC towards the crankshaft.  The offset ``k = a/R`` is
positive when the cylinder axis is displaced towards the side where the crank pin is at
phi = 90 deg: sin(beta) = lambda (sin(phi) - k).

Every quantity has the exact slider-crank form (default) and the textbook series of the
manual (``exact=False``).
"""

import numpy as np

from ..numerics import extremum


def rod_angle(phi, lam, k=0.0):
    """Connecting-rod angle beta = arcsin(lambda (sin phi - k)) [rad] (seed 001, section 2, exact)."""
    return np.arcsin(lam * (np.sin(phi) - k))


def displacement(phi, radius, lam, k=0.0, exact=True):
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
    seed 001, eqs. (1.2)-(1.3); exact form from spec/crank-kinematics-dynamics.md, section 3.

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


def velocity(phi, radius, lam, omega, k=0.0, exact=True):
    """Piston velocity v [m/s] at crank speed omega [rad/s].

    Notes
    -----
    Series (1.5)/(1.6): :math:`v = \\omega R(\\sin\\varphi + \\frac{\\lambda}{2}\\sin2\\varphi - k\\lambda\\cos\\varphi)`.
    Exact: :math:`v = \\omega R\\sin(\\varphi+\\beta)/\\cos\\beta`.

    References
    ----------
    seed 001, eqs. (1.5)-(1.6); spec/crank-kinematics-dynamics.md, section 3.
    """
    phi = np.asarray(phi, dtype=float)
    if not exact:
        return omega * radius * (np.sin(phi) + lam / 2.0 * np.sin(2.0 * phi) - k * lam * np.cos(phi))
    u = np.sin(phi) - k
    return omega * radius * (np.sin(phi) + lam * u * np.cos(phi) / np.sqrt(1.0 - (lam * u) ** 2))


def acceleration(phi, radius, lam, omega, k=0.0, exact=True):
    """Piston acceleration j [m/s^2] at constant crank speed omega [rad/s].

    Notes
    -----
    Series (1.8)/(1.9): :math:`j = \\omega^2R(\\cos\\varphi + \\lambda\\cos2\\varphi + k\\lambda\\sin\\varphi)`.
    Exact: :math:`j = \\omega^2R\\left[\\cos\\varphi + \\lambda\\frac{\\cos^2\\varphi - u\\sin\\varphi +
    \\lambda^2u^3\\sin\\varphi}{(1-\\lambda^2u^2)^{3/2}}\\right]`, :math:`u = \\sin\\varphi - k`.

    References
    ----------
    seed 001, eqs. (1.8)-(1.9); spec/crank-kinematics-dynamics.md, section 3.

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


def textbook_extremes(radius, lam, omega):
    """The manual's closed forms for a central mechanism: (1.7) v_max, (1.10) j_max, (1.11) j_min and its angle.

    Returns
    -------
    dict
        ``v_max`` [m/s], ``j_max``, ``j_min`` [m/s^2], ``j_min_angle`` [rad] (the first of the
        pair 180 deg -+ arccos(1/(4 lambda)); 180 deg for lambda <= 1/4).

    References
    ----------
    seed 001, eqs. (1.7), (1.10), (1.11) (the minus sign of (1.11) is lost in the extraction).
    """
    out = {"v_max": omega * radius * np.sqrt(1.0 + lam**2), "j_max": omega**2 * radius * (1.0 + lam)}
    if lam > 0.25:
        out["j_min"] = -omega**2 * radius * (lam + 1.0 / (8.0 * lam))
        out["j_min_angle"] = np.pi - np.arccos(1.0 / (4.0 * lam))
    else:
        out["j_min"] = -omega**2 * radius * (1.0 - lam)
        out["j_min_angle"] = np.pi
    return out


def extremes(radius, lam, omega, k=0.0, exact=True):
    """Extremes of the piston velocity and acceleration found on the chosen formulas over a revolution.

    Returns
    -------
    dict
        ``v_max``, ``v_max_angle``, ``j_max``, ``j_max_angle``, ``j_min``, ``j_min_angle``
        (SI; angles in rad in [0, 2 pi)).
    """
    edges = np.linspace(0.0, 2.0 * np.pi, 9)
    xv, v = extremum(lambda p: velocity(p, radius, lam, omega, k, exact), edges, "max")
    xa, a_max = extremum(lambda p: acceleration(p, radius, lam, omega, k, exact), edges, "max")
    xn, a_min = extremum(lambda p: acceleration(p, radius, lam, omega, k, exact), edges, "min")
    return {"v_max": v, "v_max_angle": xv % (2 * np.pi), "j_max": a_max, "j_max_angle": xa % (2 * np.pi),
            "j_min": a_min, "j_min_angle": xn % (2 * np.pi)}


def dead_centres(lam, k=0.0):
    """Crank angles of TDC and BDC of an offset mechanism [rad]: arcsin(k lambda/(1+lambda)),
    pi + arcsin(k lambda/(1-lambda)) (spec/crank-kinematics-dynamics.md, section 3)."""
    return np.arcsin(k * lam / (1.0 + lam)), np.pi + np.arcsin(k * lam / (1.0 - lam))


def brix_displacement(phi, radius, lam):
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
    seed 001, eq. (2.1); spec/crank-kinematics-dynamics.md, section 4.
    """
    phi = np.asarray(phi, dtype=float)
    e = radius * lam / 2.0
    return radius + e * np.sin(phi) ** 2 - np.cos(phi) * np.sqrt(radius**2 - (e * np.sin(phi)) ** 2)
