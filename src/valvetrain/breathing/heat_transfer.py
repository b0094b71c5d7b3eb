"""Heat transfer between the cylinder's gas and its walls: Woschni's correlation.

SI units inside (Pa, K, m, m/s, W/(m^2 K)); the correlation's own units (kPa) are converted in the formula.
"""

import numpy as np
from numba import njit

WOSCHNI_C1 = {"gas_exchange": 6.18, "compression": 2.28, "combustion": 2.28}
"""Woschni's C1 of the characteristic gas velocity by period of the cycle (no swirl) (Woschni (1967); Heywood (1988),
section 12.4)."""

WOSCHNI_C2 = 3.24e-3
"""Woschni's C2 [m/(s K)] of the combustion-driven velocity, during combustion and expansion; 0 in the other periods
(Woschni (1967); Heywood (1988), section 12.4)."""


@njit(cache=True, nogil=True)
def woschni_coefficient(bore, pressure, temperature, velocity) -> float | np.ndarray:
    """Woschni's instantaneous heat-transfer coefficient h [W/(m^2 K)], spatially averaged over the chamber.

    Parameters
    ----------
    bore : float
        Cylinder bore B [m].
    pressure : float
        Cylinder pressure p [Pa].
    temperature : float
        Mean gas temperature T [K].
    velocity : float
        Characteristic gas velocity w [m/s] (:func:`woschni_velocity`).

    Notes
    -----
    .. math:: h = 3.26\\,B^{-0.2}\\,p^{0.8}\\,T^{-0.55}\\,w^{0.8}

    with B in m, p in kPa, T in K and w in m/s (Woschni's correlation Nu = 0.035 Re^0.8 with the gas's conductivity
    and viscosity as powers of T).

    References
    ----------
    Woschni (1967); Heywood (1988), section 12.4, eq. (12.19).

    Examples
    --------
    B = 0.1 m, p = 1 MPa, T = 800 K, w = 10 m/s:
    3.26 x 1.5849 x 251.19 x 0.025311 x 6.3096 = 207.3 W/(m^2 K):

    >>> round(float(woschni_coefficient(0.1, 1e6, 800.0, 10.0)), 1)
    207.3
    """
    return 3.26 * bore ** -0.2 * (pressure / 1000.0) ** 0.8 * temperature ** -0.55 * velocity ** 0.8


@njit(cache=True, nogil=True)
def woschni_velocity(c1, c2, mean_piston_speed, swept_volume, t_ref, p_ref, v_ref, pressure,
                     motored_pressure) -> float | np.ndarray:
    """Woschni's characteristic gas velocity w [m/s].

    Parameters
    ----------
    c1 : float
        :data:`WOSCHNI_C1` of the period.
    c2 : float
        :data:`WOSCHNI_C2` during combustion and expansion, else 0 [m/(s K)].
    mean_piston_speed : float
        [m/s].
    swept_volume : float
        V_d [m^3].
    t_ref, p_ref, v_ref : float
        Temperature [K], pressure [Pa] and volume [m^3] at a reference angle (the intake valve's closing).
    pressure, motored_pressure : float
        The cylinder pressure and the pressure the motored cycle would have at the same angle [Pa].

    Notes
    -----
    .. math:: w = C_1 \\bar S_p + C_2 \\frac{V_d T_r}{p_r V_r} (p - p_m)

    References
    ----------
    Woschni (1967); Heywood (1988), section 12.4, eq. (12.20).
    """
    return c1 * mean_piston_speed + c2 * swept_volume * t_ref / (p_ref * v_ref) * (pressure - motored_pressure)


def wall_area(volume, bore) -> float | np.ndarray:
    """Area of the walls a flat chamber's gas touches, A = 2 pi B^2 / 4 + pi B V / (pi B^2 / 4) [m^2].

    Parameters
    ----------
    volume : float or ndarray
        Cylinder volume V [m^3].
    bore : float
        [m].

    Notes
    -----
    Head and piston crown as flat discs of the bore and the liner up to the gas's height V / A_p, the pancake
    chamber's; a shaped chamber's head and crown add area this leaves out.

    Examples
    --------
    A cylinder 0.1 m across and as high: 2 x 7854 + 31416 mm^2:

    >>> round(float(wall_area(np.pi * 0.1**3 / 4, 0.1)) * 1e6, 1)
    47123.9
    """
    piston = np.pi * bore**2 / 4.0
    return 2.0 * piston + np.pi * bore * np.asarray(volume) / piston
