"""Valve springs in the coil-mass model of the multi-mass trains (:mod:`.models`): the spring's active coils as a
chain of masses and stiffnesses, whose first surge mode tends to the coil's wave equation's, and an assumed damping.

SI units: kg, N/m, N s/m, N, m.
"""

from dataclasses import dataclass

import numpy as np

from ..masses import spring_mass
from ..springs import length_at_pitch, spring_rate

COIL_DAMPING_RATIO = 0.02
"""Damping ratio of a spring's first surge mode (material and inter-coil friction; an assumption in the usual
0.01-0.03 range of spring-surge studies): the coil segments' damping is proportional to their stiffness, so that the
first mode has this ratio whatever the number of coil masses (:meth:`CoilSpring.segment_damping`)."""


@dataclass(frozen=True)
class CoilSpring:
    """A valve spring for the coil-mass model (SI).

    Attributes
    ----------
    rate : float
        Spring rate K [N/m].
    preload : float
        Installed force F0 [N].
    mass : float
        Mass of the active coils m_s [kg], the coils whose deflection gives the rate.
    closing_gap : float
        Sum of the gaps between the active coils at the installed length [m]: the spring goes solid
        when compressed by this much (0: not monitored).
    coils : int
        Coil masses N of the model (0: a massless spring with a third of the whole spring's mass, m_s + 2 m_e, on the
        valve, as in Valve-train practical works (n.d.) eq. 5.2).
    damping_ratio : float
        zeta_1 of the spring's first surge mode (:meth:`segment_damping`).
    dead_mass : float
        m_e, the mass of the inactive (closed) end coils at each end [kg]: those at the retainer move with the valve,
        those at the head rest on it (:func:`coil_spring`).
    """

    rate: float
    preload: float
    mass: float
    closing_gap: float = 0.0
    coils: int = 8
    damping_ratio: float = COIL_DAMPING_RATIO
    dead_mass: float = 0.0

    @property
    def whole_mass(self) -> float:
        """The spring's mass, its active and both ends' inactive coils, m_s + 2 m_e [kg]."""
        return self.mass + 2.0 * self.dead_mass

    def surge_frequency(self, mode=1) -> float:
        r"""Natural frequency of the j-th surge mode of the N coil masses between fixed ends [rad/s] (0 without
        coil masses).

        Notes
        -----
        N masses m_s / (N + 1) on N + 1 segments of rate (N + 1) K between fixed ends, a uniform chain whose modes
        are :math:`\omega_j = 2 (N + 1) \sqrt{K / m_s} \sin(j \pi / (2 (N + 1)))`, j = 1...N.

        References
        ----------
        Den Hartog (1956), the chapter on many degrees of freedom (the uniform chain of masses and springs).

        Examples
        --------
        One coil mass (N = 1): m_s / 2 between two segments of 2 K, sqrt(4 K / (m_s / 2)).

        >>> bool(np.isclose(CoilSpring(50e3, 300.0, 0.04, coils=1).surge_frequency(), np.sqrt(4 * 50e3 / 0.02)))
        True
        """
        n = self.coils
        if n == 0:
            return 0.0
        return float(2.0 * (n + 1) * np.sqrt(self.rate / self.mass) * np.sin(mode * np.pi / (2.0 * (n + 1))))

    def segment_damping(self) -> float:
        r"""Damping of each coil segment [N s/m]: proportional to its stiffness, :math:`C = 2 \zeta_1 (N + 1) K /
        \omega_1`, so that the first surge mode (:meth:`surge_frequency`) has the damping ratio
        :math:`\zeta_1` and the j-th :math:`\zeta_1 \omega_j / \omega_1` (a damping matrix proportional to the stiffness
        matrix has the modal ratios :math:`c \omega_j / 2`), whatever the number of coil masses.
        """
        return 2.0 * self.damping_ratio * (self.coils + 1) * self.rate / self.surge_frequency()


def coil_spring(rate, preload, mass, active_coils, wire_diameter, installed_length, coils=8, end_coils=2.0,
                damping_ratio=COIL_DAMPING_RATIO) -> CoilSpring:
    r"""A :class:`CoilSpring` of a designed spring: its active coils as masses, its end coils with the retainer and the
    head, and its closing gap from the spring's own lengths.

    Parameters
    ----------
    rate, preload : float
        K [N/m] over the active coils and F0 [N].
    mass : float
        The whole spring's mass, its i_p + i_0 coils [kg] (Valve-train dynamics article (n.d.), step 3).
    active_coils, end_coils : float
        i_p and i_0, the inactive end coils of both ends together (2: one closed coil at each end).
    wire_diameter : float
        d [m].
    installed_length : float
        l_0 at the closed valve [m] (Valve-train practical works (n.d.), eqs. 6.4-6.5).
    coils, damping_ratio :
        As in :class:`CoilSpring`.

    Notes
    -----
    One geometry for the rate, the masses and the coil closing (the convention of this function):

    * the rate :math:`K = G d^4 / (8 D^3 i_p)` counts the active coils alone, so only they deflect and only they
      surge: the coil masses share :math:`m_s = m\,i_p / (i_p + i_0)`, and the :math:`i_0 / 2` closed end coils at
      each end, :math:`m_e = m\,i_0 / (2 (i_p + i_0))`, move with the retainer (on the valve) or rest on the head;
    * the spring is solid at the length (6.4) of its coils at the pitch t = d
      (:func:`~valvetrain.springs.length_at_pitch`), and its closed end coils are at that pitch already, so the active
      coils close when the spring is compressed from the installed length by :math:`l_0 - l_s = (i_p + 2)(t_0 - d)`:
      the gap the design's lengths leave, all of it between the active coils (the manual's t_0 of (6.6) spreads it
      over i_p + 2 coils).

    The first surge mode of the coil masses is then that of the active coils, :math:`\omega_{c1} = \pi \sqrt{K /
    m_s}` (Valve-train practical works (n.d.), eq. 6.13), in the limit of many coil masses.

    Examples
    --------
    The pushrod example's spring: d = 5.1 mm, i_p = 3, l_0 = 43.66 mm, 0.0814 kg: 13.06 mm of closing gap, 3/5 of
    the mass in the active coils and a fifth at each end.

    >>> s = coil_spring(66.5e3, 311.4, 0.0814, 3.0, 5.1e-3, 43.66e-3)
    >>> round(s.closing_gap * 1e3, 9), round(s.mass, 9), round(s.dead_mass, 9)
    (13.06, 0.04884, 0.01628)
    """
    total = active_coils + end_coils
    closing = installed_length - length_at_pitch(wire_diameter, wire_diameter, active_coils, end_coils)
    return CoilSpring(float(rate), float(preload), float(mass * active_coils / total), float(closing), int(coils),
                      float(damping_ratio), float(mass * end_coils / (2.0 * total)))


def coil_spring_from_geometry(wire_diameter, mean_diameter, active_coils, preload, installed_length, coils=8,
                              shear_modulus=8.0e10, density=7850.0, damping_ratio=COIL_DAMPING_RATIO,
                              end_coils=2.0) -> CoilSpring:
    r"""A :class:`CoilSpring` from the wire and coil geometry (:func:`coil_spring`).

    Parameters
    ----------
    wire_diameter, mean_diameter : float
        d and D [m].
    active_coils : float
        Working coils i_p.
    preload : float
        Installed force F0 [N].
    installed_length : float
        l_0 at the closed valve [m] (Valve-train practical works (n.d.), eqs. 6.4-6.5).
    coils : int
        Coil masses of the model.
    shear_modulus, density : float
        G [Pa] and rho [kg/m^3] (Valve-train practical works (n.d.), work 6 defaults).
    end_coils : float
        i_0, the inactive end coils of both ends together.

    Notes
    -----
    Rate :math:`K = G d^4 / (8 D^3 i_p)` (Valve-train practical works (n.d.), eq. 6.2); mass of the whole spring
    :math:`\rho \pi d^2/4\,\pi D\,(i_p + i_0)` (Valve-train dynamics article (n.d.), step 3).
    """
    return coil_spring(spring_rate(shear_modulus, wire_diameter, mean_diameter, active_coils), preload,
                       spring_mass(mean_diameter, wire_diameter, active_coils + end_coils, density), active_coils,
                       wire_diameter, installed_length, coils, end_coils, damping_ratio)
