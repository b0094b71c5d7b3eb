"""Formulas of a helical valve spring (Valve-train practical works (n.d.), work 6): stress, Wahl and shape
factors, working coils and rate, surge frequency, fatigue safety, pitches and lengths, and the stress a
resonance ratio needs.

SI units: N, m, Pa, kg, rad/s.
"""

import numpy as np

SHAPE_FACTOR_TABLE = (np.array([3, 4, 5, 6, 7, 8, 9, 10, 11, 12], dtype=float),
                      np.array([1.5, 1.38, 1.3, 1.23, 1.2, 1.17, 1.15, 1.13, 1.11, 1.1]))
"""Spring index D/d and shape factor chi (Valve-train practical works (n.d.), work 6, table of eq. 6.1)."""


def shape_factor_table(index) -> np.ndarray:
    """Shape factor chi from the manual's table, linear interpolation in D/d (Valve-train practical works (n.d.), work 6, eq. 6.1).

    >>> round(float(shape_factor_table(5.5)), 6)
    1.265
    """
    return np.interp(index, *SHAPE_FACTOR_TABLE, left=np.nan, right=np.nan)


def wahl_factor(index) -> float | np.ndarray:
    """Wahl's curvature and direct-shear factor, (4c - 1)/(4c - 4) + 0.615/c.

    Engineering literature (Wahl (1944)); printed beside the
    manual's table, which lies below it by 5 % at D/d = 3 and by under 2 % from 4 to 12.

    >>> round(float(wahl_factor(6.0)), 4)
    1.2525
    """
    c = np.asarray(index, dtype=float)
    return (4.0 * c - 1.0) / (4.0 * c - 4.0) + 0.615 / c


def shear_stress(force, mean_diameter, wire_diameter, factor) -> np.ndarray:
    """Maximum shear stress in the wire, tau = 8 chi P D / (pi d^3) [Pa] (Valve-train practical works (n.d.), eq. 6.1)."""
    return 8.0 * factor * force * mean_diameter / (np.pi * wire_diameter**3)


def active_coils(shear_modulus, wire_diameter, max_deflection, max_force, mean_diameter) -> np.ndarray:
    """Working coils i_p = G d^4 f_max / (8 P_max D^3) (Valve-train practical works (n.d.), eq. 6.2).

    Examples
    --------
    V. B. Bhandari, Design of Machine Elements, Example 11.1 (G = 81370 MPa, d = 7 mm,
    deflection 30 mm at 1250 N, D = 42 mm): 7.91 coils.

    >>> round(active_coils(81370e6, 7e-3, 30e-3, 1250.0, 42e-3), 2)
    7.91
    """
    return shear_modulus * wire_diameter**4 * max_deflection / (8.0 * max_force * mean_diameter**3)


def spring_rate(shear_modulus, wire_diameter, mean_diameter, coils) -> np.ndarray:
    """Rate of a helical spring, C = G d^4 / (8 D^3 i_p) [N/m] (inverse of eq. 6.2)."""
    return shear_modulus * wire_diameter**4 / (8.0 * mean_diameter**3 * coils)


def natural_frequency(wire_diameter, mean_diameter, coils, shear_modulus, density) -> np.ndarray:
    """First natural (surge) frequency of a spring fixed at both ends, omega_c1 [rad/s].

    Notes
    -----
    .. math:: \\omega_{c1} = \\frac{d}{D^2 i_p}\\sqrt{\\frac{G}{2\\rho}}

    which is the manual's 10^6 d/(D^2 i_p) sqrt(G/(2 rho)) with d, D in mm and G in MPa.

    References
    ----------
    Valve-train practical works (n.d.), work 6, eq. (6.13), as read in corrections note 47
    (the alternative reading is 4.44 times smaller); agrees within 1.2 % with Kolchin and Demidov (1980),
    n_c = 2.17e7 d/(i_p D^2) min^-1.
    """
    return wire_diameter / (mean_diameter**2 * coils) * np.sqrt(shear_modulus / (2.0 * density))


def fatigue_safety(tau_max, tau_min, endurance, mean_stress_factor) -> np.ndarray:
    """Fatigue safety factor n = tau_-1 / (tau_a + psi_tau tau_m) (Valve-train practical works (n.d.), eqs. 6.9-6.12).

    The manual defines no mean-stress coefficient psi_tau (corrections note 24); 0.1-0.2 is usual in the
    engineering literature, and the design takes it from the specification.
    """
    tau_m = 0.5 * (tau_max + tau_min)
    tau_a = 0.5 * (tau_max - tau_min)
    return endurance / (tau_a + mean_stress_factor * tau_m)


def length_at_pitch(pitch, wire_diameter, coils, end_coils=2) -> np.ndarray:
    """Length of a valve spring whose coils lie at the pitch t, l = t (i_p + 2) + d (i_0 - 1) [m] (Valve-train
    practical works (n.d.), eq. 6.4, as read in corrections note 46); at t = d it is the solid length, at which the
    active coils close.

    >>> round(float(length_at_pitch(5.1e-3, 5.1e-3, 3.0)) * 1e3, 9)
    30.6
    """
    return pitch * (coils + 2.0) + wire_diameter * (end_coils - 1.0)


def spring_lengths(wire_diameter, coils, lift, preload_deflection, gap_factor, end_coils=2, installed_length=None) -> dict[str, np.ndarray]:
    """Pitches and lengths of a valve spring (Valve-train practical works (n.d.), eqs. 6.3-6.8).

    Parameters
    ----------
    installed_length : float, optional
        Imposed installed length l_0 [m] (the inner spring of a nested pair sits between
        the same seat and retainer as the outer one); l_min = l_0 - h then, and t_min
        follows from (6.4).

    Returns
    -------
    dict
        ``min_pitch`` t_min = d + Delta_min (6.3); ``min_length`` (valve fully open)
        l_min = t_min (i_p + 2) + d (i_0 - 1) (6.4, as read in corrections note 46); ``installed_length``
        l_0 = l_min + h (6.5); ``installed_pitch`` t_0 (6.6); ``free_length``
        l_free = l_0 + f_min (6.7); ``free_pitch`` t_free (6.8) [m].
    """
    d = wire_diameter
    if installed_length is None:
        t_min = d * (1.0 + gap_factor)
        l_min = length_at_pitch(t_min, d, coils, end_coils)
    else:
        l_min = installed_length - lift
        t_min = (l_min - d * (end_coils - 1.0)) / (coils + 2.0)
    l_0 = l_min + lift
    l_free = l_0 + preload_deflection
    return {"min_pitch": t_min, "min_length": l_min, "installed_length": l_0,
            "installed_pitch": (l_0 - d * (end_coils - 1.0)) / (coils + 2.0), "free_length": l_free,
            "free_pitch": (l_free - d * (end_coils - 1.0)) / (coils + 2.0)}

def resonance_stress(ratio, camshaft_speed, max_deflection, shape_factor, shear_modulus, density) -> np.ndarray:
    """Shear stress at full lift of a spring whose surge frequency is ``ratio`` x omega_cam [Pa].

    Notes
    -----
    Eliminating d, D and i_p between (6.1), (6.2) and (6.13):

    .. math:: \\omega_{c1} = \\frac{\\pi \\tau_{max}}{\\chi f_{max} \\sqrt{2 \\rho G}}

    so that a resonance ratio R needs
    :math:`\\tau_{max} = R \\omega_{cam} \\chi f_{max} \\sqrt{2 \\rho G} / \\pi`, whatever the
    wire and mean diameters: at a given f_max (fixed by the line, f_max = h r / (r - 1))
    the frequency can only be bought with stress.

    References
    ----------
    Valve-train practical works (n.d.), eqs. (6.1), (6.2), (6.13) (as read in corrections note 47).

    Examples
    --------
    the appendix of Valve-train practical works (n.d.) speed and lift, f_max/f_min = 3.2 (f_max = 14.545 mm), chi = 1.1 (D/d = 12),
    60S2A: 10 x omega_cam needs 661.5 MPa.

    >>> round(float(resonance_stress(10.0, np.pi * 3500 / 30, 0.010 * 3.2 / 2.2, 1.1, 8e10, 7850.0)) / 1e6, 1)
    661.5
    """
    return ratio * camshaft_speed * shape_factor * max_deflection * np.sqrt(2.0 * density * shear_modulus) / np.pi


def fatigue_stress_limit(endurance, mean_stress_factor, ratio, min_safety) -> np.ndarray:
    """Largest tau_max with a fatigue safety of ``min_safety`` when tau_min = tau_max / ratio [Pa].

    Notes
    -----
    From (6.10)-(6.12) with :math:`\\tau_{min} = \\tau_{max} / r` (r = f_max / f_min):

    .. math:: \\tau_{max} = \\frac{2 \\tau_{-1}}{n [(1 - 1/r) + \\psi_\\tau (1 + 1/r)]}

    Examples
    --------
    >>> tau = fatigue_stress_limit(370e6, 0.2, 3.2, 1.3)
    >>> round(float(fatigue_safety(tau, tau / 3.2, 370e6, 0.2)), 12)
    1.3
    """
    return 2.0 * endurance / (min_safety * ((1.0 - 1.0 / ratio) + mean_stress_factor * (1.0 + 1.0 / ratio)))
