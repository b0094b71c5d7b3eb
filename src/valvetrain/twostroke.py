"""Two-stroke piston-controlled port timing, port areas and time-area (Valve-train practical works (n.d.), work 8).

Angles: ``phi`` is the crank angle from TDC [rad]; port timings are also given as the
angle from BDC, since the phases are symmetric about BDC.  Lengths in m, areas in m^2,
time-area in m^2 s, crank speeds omega in rad/s.
"""

import numpy as np

from .crank.kinematics import crank_angle_at, displacement
from .errors import InputError

PORT_SIZE_RANGES = {"exhaust": ((0.26, 0.28), (0.20, 0.24)), "transfer": ((0.18, 0.22), (0.24, 0.28)),
                    "inlet": ((0.18, 0.32), (0.22, 0.30))}
"""Recommended port height / stroke and width / bore (Valve-train practical works (n.d.), Table 8.1)."""


def port_angle_series(sigma, lam) -> float | np.ndarray:
    """Opening (= closing) angle of a port from BDC for the lambda/4 kinematics [rad].

    Parameters
    ----------
    sigma : float
        Relative port height h / S.
    lam : float
        lambda = R / L.

    Notes
    -----
    .. math:: \\cos\\varphi = \\frac{1}{\\lambda}\\left[1 - \\sqrt{1 - 2\\lambda + \\lambda^2 + 4\\lambda\\sigma}\\right]

    References
    ----------
    Valve-train practical works (n.d.), work 8, eq. (8.1) (sigma = 0.27, lambda = 0.25 gives 69.49 deg).

    Examples
    --------
    >>> round(float(np.degrees(port_angle_series(0.27, 0.25))), 2)
    69.49
    """
    return np.arccos((1.0 - np.sqrt(1.0 - 2.0 * lam + lam**2 + 4.0 * lam * sigma)) / lam)


def port_angle(sigma, lam, exact=True) -> float:
    """Port opening angle from BDC [rad]: the piston's top edge is at the port's upper edge.

    With ``exact=True`` the exact slider-crank is solved in closed form
    (:func:`~valvetrain.crank.kinematics.crank_angle_at`), otherwise the closed form (8.1) of
    the lambda/4 kinematics.

    Examples
    --------
    Valve-train practical works (n.d.), work 8: 69.60 deg exactly for sigma = 0.27, lambda = 0.25.

    >>> round(float(np.degrees(port_angle(0.27, 0.25))), 2)
    69.6
    """
    if not exact:
        return port_angle_series(sigma, lam)
    if not 0.0 < sigma < 1.0:
        raise InputError(f"relative port height {sigma!r}: allowed (0, 1)")
    # piston travel from TDC reaches S - h at alpha = pi - phi (unit stroke)
    return np.pi - float(crank_angle_at(1.0 - sigma, 0.5, lam))


def port_height(angle_from_bdc, lam, exact=True) -> float:
    """Relative port height sigma = h / S that opens at ``angle_from_bdc`` (the inverse of :func:`port_angle`)."""
    return 1.0 - float(displacement(np.pi - angle_from_bdc, 0.5, lam, exact=exact))


def top_port_area(phi, height, width, stroke, lam, exact=True) -> np.ndarray:
    """Open area of an exhaust or transfer port uncovered by the piston crown [m^2].

    Notes
    -----
    :math:`F = (h - S + S_p)\\,b`, clipped to [0, h b].

    References
    ----------
    Valve-train practical works (n.d.), work 8, eqs. (8.2)-(8.3).
    """
    s = displacement(phi, stroke / 2.0, lam, exact=exact)
    return np.clip(height - stroke + s, 0.0, height) * width


def skirt_port_area(phi, lower_edge, height, piston_height, width, stroke, lam, exact=True) -> np.ndarray:
    """Open area of an inlet port controlled by the piston skirt [m^2].

    Parameters
    ----------
    lower_edge : float
        Depth of the port's lower edge below the crown position at TDC, h_in [m].
    height : float
        Port height [m]; the open height is clipped to it.
    piston_height : float
        Piston height from crown to skirt edge h_p [m].

    Notes
    -----
    :math:`F = (h_{in} - S_p - h_p)\\,b`, clipped to [0, height x b].

    References
    ----------
    Valve-train practical works (n.d.), work 8, eq. (8.4), as read in corrections note 49 (the
    manual's figure 8.2 is missing; its caption misnames the port, corrections note 22).
    """
    s = displacement(phi, stroke / 2.0, lam, exact=exact)
    return np.clip(lower_edge - s - piston_height, 0.0, height) * width


def time_area_numeric(phi, area, speed) -> float:
    """Time-area Z = integral of F dt = (1/omega) integral of F dphi [m^2 s] by the trapezoidal rule, crank speed
    omega [rad/s] (Valve-train practical works (n.d.), eq. 8.5: (1/(6 n)) integral of F d(phi in deg), n in min^-1)."""
    return float(np.trapezoid(area, phi) / speed)


def time_area_analytic(bore, stroke, sigma, lam, width_share, speed) -> float:
    """Time-area of a top port in closed form, Z = K1 K2 / n [m^2 s], at the crank speed omega [rad/s].

    Parameters
    ----------
    width_share : float
        psi = sum of the port widths / (pi D).

    Notes
    -----
    :math:`K_1 = 30 D S` (8.7), :math:`K_2 = \\psi[\\varphi(2\\sigma - 1 + \\lambda/4) + \\sin\\varphi
    - \\frac{\\lambda}{8}\\sin2\\varphi]` (8.8) with phi from (8.1).  Exact for the lambda/4
    kinematics when psi is the width share of the circumference (corrections note 50).  With n = 30 omega / pi
    [min^-1], K1 / n = pi D S / omega.

    References
    ----------
    Valve-train practical works (n.d.), work 8, eqs. (8.6)-(8.8).
    """
    phi = port_angle_series(sigma, lam)
    k2 = width_share * (phi * (2.0 * sigma - 1.0 + lam / 4.0) + np.sin(phi) - lam / 8.0 * np.sin(2.0 * phi))
    return float(np.pi * bore * stroke * k2 / speed)
