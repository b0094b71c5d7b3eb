"""Ramps (clearance take-up segments) of lift laws.

A ramp lifts the follower through the valve clearance h0 at a small, controlled
velocity so that the valve opens and seats softly.
"""

import numpy as np


def cosine_ramp_length(height, end_velocity):
    """Length of a cosine ramp, Phi_0 = pi h0 / (2 w') [rad].

    Parameters
    ----------
    height : float
        Ramp height (the clearance h0) [m].
    end_velocity : float
        Follower velocity at the end of the ramp per camshaft radian, w' = dh/dphi [m/rad].

    Notes
    -----
    .. math:: \\Phi_0 = \\frac{\\pi h_0}{2\\,\\omega'_{T0K}}

    The manual's form with w' in mm/deg has pi^2 / (2 * 180) in front.

    References
    ----------
    seed 000, work 2, eq. (2.1).

    Examples
    --------
    Seed 000 appendix: h0 = 0.25 mm, w' = 0.02 mm/deg gives 19.635 deg.

    >>> round(float(np.rad2deg(cosine_ramp_length(0.25e-3, 0.02e-3 * 180 / np.pi))), 3)
    19.635
    """
    return np.pi * height / (2.0 * end_velocity)


def cosine_ramp(phi, height, length):
    """Cosine ramp: lift and its first three derivatives with respect to camshaft angle.

    Parameters
    ----------
    phi : ndarray
        Camshaft angle from the start of the ramp, 0 <= phi <= length [rad].
    height : float
        Ramp height h0 [m].
    length : float
        Ramp length Phi_0 [rad].

    Returns
    -------
    ndarray, shape (4, n)
        h [m], dh/dphi [m/rad], d2h/dphi2 [m/rad^2], d3h/dphi3 [m/rad^3].

    Notes
    -----
    .. math:: h = h_0\\left(1-\\cos\\frac{\\pi\\varphi}{2\\Phi_0}\\right)

    The end acceleration is zero and the end velocity is pi h0 / (2 Phi0).

    References
    ----------
    seed 000, work 2, eq. (2.5).
    """
    k = np.pi / (2.0 * length)
    s, c = np.sin(k * phi), np.cos(k * phi)
    return np.stack([height * (1.0 - c), height * k * s, height * k**2 * c, -height * k**3 * s])
