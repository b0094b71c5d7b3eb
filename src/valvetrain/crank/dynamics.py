"""Crank-mechanism dynamics: reduced masses, gas and inertia forces, N, S, K, T and cylinder torque
(Power units manual (n.d.), section 2).

Sign conventions: forces along the cylinder axis positive towards the
crank axis; N positive when its moment opposes rotation; S positive compressing the
rod; K positive towards the shaft axis; T positive when its moment is in the direction
of rotation.  SI units: N, Pa, m, kg.
"""

from dataclasses import dataclass

import numpy as np

from .kinematics import acceleration, rod_angle


@dataclass(frozen=True)
class ReducedMasses:
    """Reciprocating and rotating masses of one crank mechanism [kg] (Power units manual (n.d.), eqs. 2.7-2.10)."""

    piston: float
    rod: float
    crank: float
    rod_pin: float        # m_sh.p, rod mass at the piston pin
    rod_crank: float      # m_sh.k, rod mass at the crank pin
    reciprocating: float  # m_j = m_p + m_sh.p
    rotating: float       # m_R = m_k + m_sh.k (x2 rods per pin in a V engine)


def reduced_masses(piston, rod, crank, rod_pin_fraction=0.275, rods_per_pin=1) -> ReducedMasses:
    """Split the connecting rod into two point masses and form m_j and m_R.

    Parameters
    ----------
    piston, rod, crank : float
        Piston group, connecting rod and unbalanced crank-throw masses [kg].
    rod_pin_fraction : float
        Share of the rod mass at the piston pin, m_sh.p = f m_sh (0.2-0.3, Power units manual (n.d.)).
    rods_per_pin : int
        1 for an inline engine, 2 for a V engine with two rods on one crank pin.

    Notes
    -----
    :math:`m_j = m_p + m_{sh.p}` (2.8); :math:`m_R = m_k + n\\,m_{sh.k}` (2.9)-(2.10).

    References
    ----------
    Power units manual (n.d.), eqs. (2.6)-(2.10).

    Examples
    --------
    >>> m = reduced_masses(0.5, 0.6, 0.4, 0.25)
    >>> round(m.reciprocating, 6), round(m.rotating, 6)
    (0.65, 0.85)
    """
    rod_pin = rod_pin_fraction * rod
    rod_crank = rod - rod_pin
    return ReducedMasses(piston, rod, crank, rod_pin, rod_crank, piston + rod_pin, crank + rods_per_pin * rod_crank)


def inertia_force(reciprocating_mass, piston_acceleration) -> np.ndarray:
    """Reciprocating inertia force P_j = -m_j j [N] (Power units manual (n.d.), eq. 2.11)."""
    return -reciprocating_mass * np.asarray(piston_acceleration)


def centrifugal_force(rotating_mass, radius, omega) -> float | np.ndarray:
    """Centrifugal force K_R = -m_R R omega^2 [N] (Power units manual (n.d.), eqs. 2.12-2.13; negative: away from the axis)."""
    return -rotating_mass * radius * omega**2


def force_factors(phi, lam, k=0.0) -> dict[str, np.ndarray]:
    """The factors of Tables 2.3-2.6 with the exact rod angle.

    Returns
    -------
    dict of ndarray
        ``tan_beta`` (2.16), ``sec_beta`` (2.17), ``radial`` = cos(phi+beta)/cos(beta) (2.18),
        ``tangential`` = sin(phi+beta)/cos(beta) (2.19).

    References
    ----------
    Power units manual (n.d.), Tables 2.3-2.6 (their printed values carry a small bias, corrections note 44).

    Examples
    --------
    At 90 deg the radial factor equals -tan(beta) and the tangential factor is 1:

    >>> f = force_factors(np.pi / 2, 0.25)
    >>> round(float(f["radial"] + f["tan_beta"]), 12), round(float(f["tangential"]), 12)
    (0.0, 1.0)
    """
    beta = rod_angle(phi, lam, k)
    cb = np.cos(beta)
    return {"tan_beta": np.tan(beta), "sec_beta": 1.0 / cb, "radial": np.cos(phi + beta) / cb,
            "tangential": np.sin(phi + beta) / cb}


def specific_forces(gas_gauge, inertia_specific, phi, lam, k=0.0) -> dict[str, np.ndarray]:
    """Specific forces on the piston pin and their components [Pa].

    Parameters
    ----------
    gas_gauge : ndarray
        Gauge gas pressure Delta p_g = p_g - p_0 [Pa] (2.3).
    inertia_specific : ndarray
        p_j = P_j / F_p [Pa] (2.15).
    phi : ndarray
        Crank angle [rad].

    Returns
    -------
    dict of ndarray
        ``p`` (2.15), ``p_N`` (2.16), ``p_S`` (2.17), ``p_K`` (2.18), ``p_T`` (2.19).

    References
    ----------
    Power units manual (n.d.), eqs. (2.14)-(2.19).
    """
    p = np.asarray(gas_gauge) + np.asarray(inertia_specific)
    f = force_factors(phi, lam, k)
    return {"p": p, "p_N": p * f["tan_beta"], "p_S": p * f["sec_beta"], "p_K": p * f["radial"],
            "p_T": p * f["tangential"]}


def cylinder_dynamics(phi, gas_pressure, ambient, bore, radius, lam, omega, masses, k=0.0, exact=True) -> dict[str, np.ndarray]:
    """Forces and torque of one cylinder over its cycle.

    Parameters
    ----------
    phi : ndarray
        Crank angle over the cycle [rad].
    gas_pressure : ndarray
        Absolute cylinder pressure at ``phi`` [Pa].
    ambient : float
        p_0 [Pa].
    bore, radius, lam, omega : float
        D [m], R [m], lambda, crank speed [rad/s].
    masses : ReducedMasses
    k : float
        Relative offset.
    exact : bool
        Exact or series piston acceleration (the rod angle is always exact, as Tables 2.3-2.6).

    Returns
    -------
    dict of ndarray
        ``p_gas`` gauge, ``p_j``, ``p``, ``p_N``, ``p_S``, ``p_K``, ``p_T`` [Pa], ``T`` [N], ``torque`` [N m],
        and the crank-pin load in the crank frame: ``pin_radial`` = K + K_R,rod and ``pin_tangential`` = T [N].

    Notes
    -----
    :math:`T = p_T F_p` (2.20), :math:`M = T R` (2.21).  The crank-pin load adds the
    centrifugal force of the rod's rotating part, K_R,sh = -m_sh.k R omega^2 (Kolchin).

    References
    ----------
    Power units manual (n.d.), eqs. (2.3)-(2.21).
    """
    area = np.pi * bore**2 / 4.0
    j = acceleration(phi, radius, lam, omega, k, exact)
    p_j = inertia_force(masses.reciprocating, j) / area
    gauge = np.asarray(gas_pressure) - ambient
    out = specific_forces(gauge, p_j, phi, lam, k)
    out["p_gas"], out["p_j"] = gauge, p_j
    out["T"] = out["p_T"] * area
    out["torque"] = out["T"] * radius
    out["pin_tangential"] = out["T"]
    out["pin_radial"] = out["p_K"] * area + centrifugal_force(masses.rod_crank, radius, omega)
    return out
