"""Quasi-steady compressible flow through a restriction (a valve, an orifice), choked or not, in either direction.

The flow is isentropic from the upstream stagnation state to the throat, where the static pressure is the
downstream pressure, or the critical pressure when that is lower (choked flow); the real flow's losses are the
discharge coefficient's, which the effective area A_E = C_D A_R carries (Heywood (1988), Appendix C).  SI units:
Pa, K, kg/s, m^2.
"""

import numpy as np
from numba import njit


@njit(cache=True, nogil=True)
def critical_pressure_ratio(gamma) -> float | np.ndarray:
    """Throat-to-stagnation pressure ratio of sonic (choked) flow, (2 / (gamma + 1))^(gamma / (gamma - 1)).

    References
    ----------
    Heywood (1988), Appendix C.
    """
    return (2.0 / (gamma + 1.0)) ** (gamma / (gamma - 1.0))


@njit(cache=True, nogil=True)
def mass_flux(p0, t0, p, gamma, r) -> float:
    """Mass flow per unit effective area [kg/(s m^2)] from the upstream stagnation state to a back pressure.

    Parameters
    ----------
    p0, t0 : float
        Upstream stagnation pressure [Pa] and temperature [K].
    p : float
        Downstream (back) pressure [Pa]; no flow where p >= p0.
    gamma, r : float
        Ratio of specific heats and gas constant [J/(kg K)] of the upstream gas.

    Returns
    -------
    float
        m / A_E >= 0 (compiled for scalars: the cycle's kernel calls it; :func:`mass_flow` takes arrays).

    Notes
    -----
    .. math:: \\frac{\\dot m}{A_E} = \\frac{p_0}{\\sqrt{R T_0}} \\left(\\frac{p_T}{p_0}\\right)^{1/\\gamma}
              \\left\\{\\frac{2\\gamma}{\\gamma - 1}\\left[1 - \\left(\\frac{p_T}{p_0}\\right)^{(\\gamma-1)/\\gamma}
              \\right]\\right\\}^{1/2},

    with the throat pressure :math:`p_T = \\max(p, p_0\\,(2/(\\gamma+1))^{\\gamma/(\\gamma-1)})`: at and below the
    critical ratio the flow is choked, :math:`\\dot m / A_E = \\frac{p_0}{\\sqrt{R T_0}}\\gamma^{1/2}
    (2/(\\gamma+1))^{(\\gamma+1)/(2(\\gamma-1))}` (the same expression at the critical ratio).

    References
    ----------
    Heywood (1988), Appendix C.
    """
    if p >= p0 or p0 <= 0.0:
        return 0.0
    ratio = p / p0
    critical = critical_pressure_ratio(gamma)
    if ratio < critical:
        ratio = critical
    power = ratio ** (1.0 / gamma)      # and ratio^((gamma-1)/gamma) = ratio / power
    return p0 / np.sqrt(r * t0) * power * np.sqrt(2.0 * gamma / (gamma - 1.0) * (1.0 - ratio / power))


def choked_mass_flux(p0, t0, gamma, r) -> float | np.ndarray:
    """Mass flow per unit effective area of choked flow [kg/(s m^2)], independent of the back pressure.

    Notes
    -----
    .. math:: \\frac{\\dot m}{A_E} = \\frac{p_0\\sqrt{\\gamma}}{\\sqrt{R T_0}}
              \\left(\\frac{2}{\\gamma + 1}\\right)^{(\\gamma+1)/(2(\\gamma-1))}

    References
    ----------
    Heywood (1988), Appendix C.

    Examples
    --------
    Air (R = 287 J/(kg K), gamma = 1.4) from 1 bar and 300 K: 0.0404 p0 / sqrt(T0) kg/(s m^2), the textbook's
    constant of choked air flow:

    >>> round(float(choked_mass_flux(1e5, 300.0, 1.4, 287.0) * np.sqrt(300.0) / 1e5), 4)
    0.0404
    """
    return (np.asarray(p0) * np.sqrt(gamma / (r * np.asarray(t0)))
            * (2.0 / (gamma + 1.0)) ** ((gamma + 1.0) / (2.0 * (gamma - 1.0))))


def mass_flow(area_ab, area_ba, pa, ta, pb, tb, gamma_a, gamma_b, ra, rb) -> float | np.ndarray:
    """Mass flow from side a to side b through a restriction [kg/s], negative when the gas flows from b to a.

    Parameters
    ----------
    area_ab, area_ba : float or ndarray
        Effective areas C_D A_R for flow from a to b and from b to a [m^2] (a valve's forward and reverse).
    pa, ta, pb, tb : float or ndarray
        Stagnation pressure [Pa] and temperature [K] of each side (each side taken at rest).
    gamma_a, gamma_b, ra, rb : float or ndarray
        Each side's ratio of specific heats and gas constant [J/(kg K)].

    Returns
    -------
    float or ndarray

    Notes
    -----
    The upstream side is the one of the higher pressure: :math:`\\dot m = A_{ab}\\,\\Phi(p_a, T_a, p_b)` for
    :math:`p_a > p_b`, else :math:`-A_{ba}\\,\\Phi(p_b, T_b, p_a)` (:func:`mass_flux` is Phi).

    References
    ----------
    Heywood (1988), Appendix C.

    Examples
    --------
    Flow from b to a is negative, through the reverse area:

    >>> float(mass_flow(1e-4, 2e-4, 1e5, 300.0, 2e5, 300.0, 1.4, 1.4, 287.0, 287.0)) < 0
    True
    """
    flux = np.vectorize(mass_flux, otypes=[float])
    out = area_ab * flux(pa, ta, pb, gamma_a, ra) - area_ba * flux(pb, tb, pa, gamma_b, rb)
    return float(out) if np.ndim(out) == 0 else out
