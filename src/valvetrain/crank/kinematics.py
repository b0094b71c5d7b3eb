"""Piston kinematics of the central slider-crank mechanism (seed 001, section 1; seed 002, eq. 2.14)."""

import numpy as np


def piston_displacement(crank_angle, crank_radius, rod_length, exact=True):
    """Piston travel from TDC of a central crank mechanism [m].

    Parameters
    ----------
    crank_angle : array_like
        Crank angle from TDC [rad].
    crank_radius : float
        Crank radius r = S/2 [m].
    rod_length : float
        Connecting-rod length l [m], > r.
    exact : bool
        True: the exact slider-crank formula; False: the textbook series truncated
        after the second harmonic.

    Notes
    -----
    Exact: :math:`s = r(1-\\cos\\varphi) + l\\left(1 - \\sqrt{1-\\lambda^2\\sin^2\\varphi}\\right)`,
    series: :math:`s = r\\left[(1-\\cos\\varphi) + \\frac{\\lambda}{4}(1-\\cos 2\\varphi)\\right]`,
    with :math:`\\lambda = r/l`.

    References
    ----------
    seed 002, eq. (2.14) (series); seed 001, section 1 (exact and series).

    Examples
    --------
    At BDC both forms give the full stroke.

    >>> round(float(piston_displacement(np.pi, 0.04, 0.14)), 12)
    0.08
    """
    phi = np.asarray(crank_angle, dtype=float)
    lam = crank_radius / rod_length
    if exact:
        return crank_radius * (1.0 - np.cos(phi)) + rod_length * (1.0 - np.sqrt(1.0 - (lam * np.sin(phi)) ** 2))
    return crank_radius * ((1.0 - np.cos(phi)) + lam / 4.0 * (1.0 - np.cos(2.0 * phi)))
