"""The hydraulic lash adjuster: leak-down through the plunger clearance, refill through the check valve, the
compliance of the oil with entrained air (the plunger's motion over the cycle is a state of the dynamics,
:class:`valvetrain.dynamics.models.Adjuster`).

SI units: m, s, N, Pa (gauge pressures unless said absolute), Pa s, m^3.  Pure functions over numpy arrays.
"""

import numpy as np

from .hydraulic_actuation.components import orifice_flow

ATMOSPHERE = 1.013e5
"""Absolute pressure of the atmosphere [Pa]: the reference of the entrained air's volume and the floor of a chamber
pressure (vacuum, -1 atm gauge)."""

OIL_DENSITY = 850.0
"""Density of an engine oil at its working temperature [kg/m^3] (the check valve's orifice flow): a typical value,
not from a cited source."""

DISCHARGE_COEFFICIENT = 0.6
"""Discharge coefficient of the check valve's seat, a sharp-edged orifice: a typical value (Merritt (1967) gives the
orifice equation it enters)."""


def plunger_area(diameter: float) -> float:
    """pi d^2 / 4 [m^2] of a plunger of diameter ``diameter`` [m]."""
    return np.pi * diameter**2 / 4.0


def eccentricity_factor(eccentricity) -> np.ndarray:
    """Leakage of an eccentric annular clearance over that of the concentric one, 1 + 1.5 epsilon^2 (1 to 2.5).

    Parameters
    ----------
    eccentricity : ndarray or float
        epsilon = e / c, the offset e of the plunger's axis from the bore's over the radial clearance c (0: concentric,
        1: the plunger touching the bore on one side).

    Notes
    -----
    The narrow gap's local height h = c (1 + epsilon cos theta) carries the plane Poiseuille flow h^3 / (12 mu)
    dp/dx per unit width; around the circumference

    .. math:: \\frac{1}{2\\pi}\\int_0^{2\\pi}(1 + \\varepsilon\\cos\\theta)^3\\,d\\theta
              = 1 + \\tfrac32\\,\\varepsilon^2

    the concentric plunger leaks least, a fully eccentric one 2.5 times as much.

    References
    ----------
    Merritt (1967), the leakage of an eccentric annular clearance; White (2006), the flow between eccentric
    cylinders (its exact solution in bipolar coordinates tends to this as c / r -> 0).

    >>> float(eccentricity_factor(0.0)), float(eccentricity_factor(1.0))
    (1.0, 2.5)
    """
    return 1.0 + 1.5 * np.asarray(eccentricity, dtype=float) ** 2


def annular_leakage(pressure_drop, diameter, clearance, length, viscosity, eccentricity=0.0) -> np.ndarray:
    """Laminar leakage through the plunger's annular clearance [m^3/s].

    Parameters
    ----------
    pressure_drop : ndarray
        Pressure across the clearance [Pa]; none flows back (clipped at 0: the check valve refills instead).
    diameter : float
        Plunger diameter [m].
    clearance : float
        Radial clearance c [m] (c << d).
    length : float
        Length of the sealing land L [m].
    viscosity : float
        Dynamic viscosity of the oil [Pa s].
    eccentricity : float
        epsilon = e / c of the plunger in its bore, 0 (concentric) to 1 (:func:`eccentricity_factor`).

    Notes
    -----
    .. math:: Q = \\frac{\\pi d c^3}{12 \\mu L}\\,(1 + 1.5\\,\\varepsilon^2)\\,\\Delta p

    The flow between parallel plates of width pi d, times :func:`eccentricity_factor`.

    References
    ----------
    Merritt (1967), the leakage of an annular clearance.

    >>> round(float(annular_leakage(1e6, 9e-3, 4e-6, 8e-3, 0.010, 1.0) / annular_leakage(1e6, 9e-3, 4e-6, 8e-3,
    ...                                                                                   0.010)), 12)
    2.5
    """
    return (np.pi * diameter * clearance**3 * eccentricity_factor(eccentricity) * np.clip(pressure_drop, 0.0, None)
            / (12.0 * viscosity * length))


def leak_down_time(force, stroke, diameter, clearance, length, viscosity, eccentricity=0.0) -> np.ndarray:
    """Time [s] a plunger takes to sink by ``stroke`` [m] under a constant ``force`` [N], supply pressure zero
    (``eccentricity`` as in :func:`annular_leakage`).

    Notes
    -----
    The chamber pressure F / A drives :func:`annular_leakage`; the plunger sinks at Q / A:

    .. math:: t = \\frac{12 \\mu L A^2 s}{\\pi d c^3 (1 + 1.5\\,\\varepsilon^2) F}

    the leak-down test of a lash adjuster.
    """
    area = plunger_area(diameter)
    return (12.0 * viscosity * length * area**2 * stroke
            / (np.pi * diameter * clearance**3 * eccentricity_factor(eccentricity) * force))


def chamber_compression(pressure, supply, volume, bulk_modulus, air_content) -> np.ndarray:
    """Volume [m^3] the oil of the high-pressure chamber loses when its pressure rises from ``supply`` to
    ``pressure`` (gauge) [Pa].

    Parameters
    ----------
    pressure, supply : ndarray or float
        Gauge pressures [Pa] (``pressure`` >= ``supply``).
    volume : float
        Chamber volume V [m^3].
    bulk_modulus : float
        Bulk modulus of the air-free oil beta [Pa].
    air_content : float
        Volume share a_0 of free air in the oil at atmospheric pressure, compressed isothermally.

    Notes
    -----
    With P = p + p_atm absolute, the air takes a_0 V p_atm / P:

    .. math:: \\Delta V = V\\left[\\frac{p - p_s}{\\beta} + a_0\\,p_{atm}\\left(\\frac1{P_s} - \\frac1{P}\\right)\\right]

    References
    ----------
    Merritt (1967), the effective bulk modulus of a liquid with entrained air.
    """
    absolute, supply_abs = pressure + ATMOSPHERE, supply + ATMOSPHERE
    return volume * ((pressure - supply) / bulk_modulus + air_content * ATMOSPHERE * (1.0 / supply_abs - 1.0 / absolute))


def check_valve_flow(pressure_drop, diameter: float) -> np.ndarray:
    """Flow through the open check valve [m^3/s]: C_d (pi d^2 / 4) sqrt(2 dp / rho).

    Parameters
    ----------
    pressure_drop : ndarray
        Supply minus chamber pressure [Pa] (clipped at 0: the valve closes).
    diameter : float
        Seat bore of the check valve [m].

    References
    ----------
    Merritt (1967), the orifice equation; :data:`DISCHARGE_COEFFICIENT`, :data:`OIL_DENSITY`.
    """
    return orifice_flow(plunger_area(diameter), np.clip(pressure_drop, 0.0, None), OIL_DENSITY, DISCHARGE_COEFFICIENT)


def refill_pressure(supply: float, plunger_spring: float, area: float) -> float:
    """Pressure drop across the check valve [Pa] while the unloaded plunger extends: the supply less the chamber,
    whose pressure its spring draws to -F_s / A (no lower than a vacuum)."""
    return supply + min(plunger_spring / area, ATMOSPHERE)


def motion_ratio(location: str, rocker_ratio: float) -> float:
    """Valve motion per adjuster motion, and the adjuster's force per valve force (virtual work).

    At the pivot of an end-pivot finger (``"pivot"``; pivot, roller at a, valve at L = i a): with the roller held on
    the cam a pivot motion s moves the valve by (i - 1) s; in the tappet (``"tappet"``): i.

    >>> round(motion_ratio("pivot", 1.6), 12), motion_ratio("tappet", 1.6)
    (0.6, 1.6)
    """
    return rocker_ratio - 1.0 if location == "pivot" else rocker_ratio


def pivot_motion_ratio(pivot, centre, valve_arm: float, roller_arm: float, valve_angle: float,
                       axis_angle: float) -> float:
    """Valve motion per plunger extension of a lash adjuster at the pivot of a finger, from its geometry on the heel
    circle and the adjuster's axis (and the adjuster's force per valve force, by virtual work).

    Parameters
    ----------
    pivot, centre : ndarray (2,)
        The pivot P and the roller centre C on the heel circle, from the cam centre [m] (the follower on +y).
    valve_arm : float
        G = dv/dpsi of the finger on the heel circle [m/rad].
    roller_arm : float
        L_r = |C - P| [m].
    valve_angle : float
        alpha [rad]: the valve opens along a = (sin alpha, cos alpha).
    axis_angle : float
        phi [rad]: the adjuster's axis, from +y clockwise; the extending plunger moves the pivot along
        u = -(sin phi, cos phi), towards the cam's side of the finger (the side that takes up the lash).

    Notes
    -----
    The roller stays on the heel circle, |C| = R_0 + R_r, while the pivot moves by s u: C = P + L_r e(psi) and
    d|C|^2 = 2 C . (s u + L_r e_perp dpsi) = 0 give dpsi = -s (C . u) / (L_r C . e_perp), e_perp the unit normal of
    C - P (counter-clockwise).  The pad's centre B = P + L_b e(psi + beta) moves along the valve by
    s u . a + G dpsi, so

    .. math:: i_a = \\mathbf u\\cdot\\mathbf a - \\frac{G\\,(\\mathbf C\\cdot\\mathbf u)}{L_r\\,(\\mathbf C\\cdot
              \\mathbf e_\\perp)}

    With the axis along the valve and the roller's normal (u = -a, C along e_perp) it is G / L_r - 1 = i - 1, the
    straight lever of :func:`motion_ratio`; a tilt of the axis or of the finger changes both terms.  The kinematics of
    the finger: Norton (2009); Wang (2007).

    >>> round(pivot_motion_ratio(np.array([-0.02, 0.025]), np.array([0.0, 0.025]), 0.032, 0.02, 0.0, 0.0), 12)
    0.6
    """
    u = -np.array([np.sin(axis_angle), np.cos(axis_angle)])
    a = np.array([np.sin(valve_angle), np.cos(valve_angle)])
    e = (np.asarray(centre) - np.asarray(pivot)) / roller_arm
    normal = np.array([-e[1], e[0]])
    return float(u @ a - valve_arm * (centre @ u) / (roller_arm * (centre @ normal)))


def secant_stiffness(force: float, plunger_spring: float, area: float, supply: float, volume: float,
                     bulk_modulus: float, air_content: float) -> tuple[float, float, float]:
    """Secant stiffness [N/m] of the oil column under ``force`` [N] on the plunger, its compression [m] and the chamber
    pressure [Pa, gauge] (the plunger spring ``plunger_spring`` [N] carries its share; no less than ``supply``).

    Notes
    -----
    p = max((F - F_s) / A, p_s); the plunger sinks by :func:`chamber_compression` / A; K = F / sink (inf without
    compression).
    """
    pressure = max((force - plunger_spring) / area, supply)
    sink = chamber_compression(pressure, supply, volume, bulk_modulus, air_content) / area
    return (force / sink if sink > 0.0 else np.inf), sink, pressure
