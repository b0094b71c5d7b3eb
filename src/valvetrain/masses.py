"""Masses of the valve train reduced to the valve axis and to the tappet (Valve-train practical works (n.d.), works 5 and 7).

SI units: kg, m, kg*m^2.  ``rocker_ratio`` i_k = l_v / l_t (valve arm over tappet arm).
"""

import numpy as np

from .locale import NoteText, note

SPECIFIC_MASS_DEFAULT = {"direct": 125.0, "rocker": 105.0, "pushrod": 135.0}
"""Default reduced mass at the valve per inlet throat area m' [kg/m^2], used where no part masses are given.

Derived from the part masses of the built-in example (the appendix of Valve-train practical works (n.d.) valve, d_g = 36.8 mm, f_g =
1063.6 mm^2; illustrative figures of a pushrod drive of that size): valve 55 g, retainer 15 g, cotters
4 g, a third of its 64 g VDSiCr spring, tappet 40 g, pushrod 45 g, rocker 25 kg mm^2 at a 40 mm valve arm
(15.6 g), i_k = 1.6 (eq. 5.2):

* pushrod drive: 74 + 21.3 + 15.6 + (45 + 40) / 1.6^2 = 144.1 g, 135.5 kg/m^2 -> 135;
* overhead-cam rocker (no pushrod, no tappet): 74 + 21.3 + 15.6 = 110.9 g, 104.3 kg/m^2 -> 105;
* direct drive (the 40 g tappet on the valve, i_k = 1): 74 + 21.3 + 40 = 135.3 g, 127.2 kg/m^2 -> 125.

Valve-train practical works (n.d.) (work 5) gives 200-300 kg/m^2 for direct and 400-500 kg/m^2 for pushrod drives: 1.6-3.7 times
these, so that the same engine needed 861 N of spring force from its parts and 2952 N from the estimate
(issue 10).  The source does not say which parts or masses its figures stand for; a design with its
own part masses gives them in ``[valves.NAME.drive.masses]``, and ``specific_mass_kg_m2`` sets any other
figure."""


SPECIFIC_MASS_NOTES = {"direct": "masses.specific_default_direct", "rocker": "masses.specific_default_rocker",
                       "pushrod": "masses.specific_default_pushrod"}
"""The ``[notes]`` code of the source of a default specific mass, by the layout."""


def reduced_mass_at_valve(valve, retainer, cotters, spring, pushrod=0.0, tappet=0.0, rocker_inertia=0.0,
                          valve_arm=1.0, rocker_ratio=1.0) -> float:
    """Mass of the valve train reduced to the valve axis [kg].

    Parameters
    ----------
    valve, retainer, cotters, spring, pushrod, tappet : float
        Part masses [kg]; one third of the spring moves with the valve.
    rocker_inertia : float
        Rocker moment of inertia about its shaft [kg m^2].
    valve_arm : float
        Valve-side rocker arm l_v [m] (only used with a rocker inertia).
    rocker_ratio : float
        i_k = l_v / l_t.

    Notes
    -----
    .. math:: m_v = m_{valve} + m_{ret} + m_{cot} + \\frac{m_{spr}}{3} + \\frac{I_r}{l_v^2}
              + (m_{pushrod} + m_{tappet})\\left(\\frac{l_t}{l_v}\\right)^2

    References
    ----------
    Valve-train practical works (n.d.), work 5, eq. (5.2).

    Examples
    --------
    >>> round(reduced_mass_at_valve(0.05, 0.02, 0.005, 0.045, 0.06, 0.04, 4e-5, 0.04, 1.6), 5)
    0.15406
    """
    rocker = rocker_inertia / valve_arm**2 if rocker_inertia else 0.0
    return valve + retainer + cotters + spring / 3.0 + rocker + (pushrod + tappet) / rocker_ratio**2


def reduced_mass_at_tappet(mass_at_valve, rocker_ratio=1.0) -> float:
    """Mass reduced to the tappet, m_t = m_v i_k^2 [kg].

    Equal term by term to Valve-train practical works (n.d.) eq. (7.2) written from the parts, since every part of
    (5.2) is moved to the tappet by the square of the lever ratio.

    References
    ----------
    Valve-train practical works (n.d.), work 7, eq. (7.2).
    """
    return mass_at_valve * rocker_ratio**2


def mass_from_specific(specific_mass, throat_area) -> float:
    """Reduced mass at the valve estimated from the specific (constructive) mass, m_v = m' f_g [kg].

    References
    ----------
    Valve-train practical works (n.d.), work 5 (m' = 200-300 kg/m^2 direct drive, 400-500 kg/m^2 pushrod drive; the defaults of
    this package, :data:`SPECIFIC_MASS_DEFAULT`, are lower).

    Examples
    --------
    the appendix of Valve-train practical works (n.d.) valve (f_g = 1063.6 mm^2) with 450 kg/m^2: 0.479 kg.

    >>> round(mass_from_specific(450.0, 1063.6e-6), 3)
    0.479
    """
    return specific_mass * throat_area


def spring_mass(mean_diameter, wire_diameter, total_coils, density) -> np.ndarray:
    """Mass of a helical spring, m = rho (pi d^2/4) pi D i_total [kg] (Valve-train dynamics article (n.d.), step 3)."""
    return density * np.pi * wire_diameter**2 / 4.0 * np.pi * mean_diameter * total_coils


def reduced_mass(throat_area, layout, rocker_ratio, parts=None, specific_mass=None, valve_arm=None, spring_mass=0.0) -> tuple[float, str]:
    """Reduced mass of a valve train at the valve [kg], from its parts or from a specific mass, and how.

    Parameters
    ----------
    throat_area : float
        Throat area of the valve f_g [m^2].
    layout : {"direct", "rocker", "pushrod"}
        Drive layout (selects the default specific mass).
    rocker_ratio : float
        i_k = l_v / l_t.
    parts : object, optional
        Part masses with the attributes ``valve_kg``, ``retainer_kg``, ``cotters_kg``, ``spring_kg`` (None: the
        designed spring's mass ``spring_mass``), ``pushrod_kg``, ``tappet_kg`` and ``rocker_inertia`` [kg m^2]
        (the SI view of a ``[valves.NAME.drive.masses]`` section).
    specific_mass : float, optional
        m' [kg/m^2] when no parts are given; default :data:`SPECIFIC_MASS_DEFAULT` of the layout.
    valve_arm : float, optional
        Valve-side rocker arm [m] for the rocker's inertia.
    spring_mass : float
        Mass of the designed spring(s) [kg].

    Returns
    -------
    (float, NoteText)
        The mass and its source (a note, :class:`valvetrain.locale.NoteText`).

    References
    ----------
    Valve-train practical works (n.d.), work 5: eq. (5.2) from the parts, m' f_g otherwise.
    """
    if parts is not None:
        spring = parts.spring_kg if parts.spring_kg is not None else spring_mass
        value = reduced_mass_at_valve(parts.valve_kg, parts.retainer_kg, parts.cotters_kg, spring, parts.pushrod_kg,
                                      parts.tappet_kg, parts.rocker_inertia, valve_arm or 1.0, rocker_ratio)
        return value, NoteText(note("masses.parts") + (() if parts.spring_kg is not None else
                                                       note("masses.spring_of_design")))
    specific = specific_mass or SPECIFIC_MASS_DEFAULT[layout]
    given = "masses.specific_given" if specific_mass else SPECIFIC_MASS_NOTES[layout]
    return mass_from_specific(specific, throat_area), NoteText(note(given, specific_kg_m2=specific))
