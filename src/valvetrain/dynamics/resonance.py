"""Valve-train dynamics article (n.d.): resonant harmonic of the cam excitation and the distortion of the valve motion.

The train is one mass m on the drive stiffness C_mgr and the spring C_pr; its natural
frequency omega_0 meets the harmonic k = int(omega_0 / omega_cam) of the cam excitation
C_mgr i_k h_T(theta).  That harmonic's amplitude F, over the damping xi = 0.107 m omega_0,
gives the elastic amplitude Delta = F / (xi omega_0); the distortion delta compares it with the
RMS valve lift.  The corrections notes 35-38 are applied:
J / l_k^2 (not J / i_k^2), N samples per camshaft revolution, xi in N s/m.  A single
harmonic is fragile (piecewise-trigonometric profiles have exact spectral zeros), so the
spectrum over k +- 2 is returned too.
"""

from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from ..springs import required_spring_force

DAMPING_FACTOR = 0.107
"""xi / (m omega_0) for trains with the camshaft in the block (Valve-train dynamics article (n.d.), step 4i; a damping ratio of 0.0535)."""


def reduced_mass(valve_mass, spring_mass, rocker_inertia, valve_arm, pushrod_mass, rocker_ratio, pushrod_stiffness,
                 rocker_stiffness, rigid_pushrod=False) -> float:
    """Reduced mass of the train at the valve, Valve-train dynamics article (n.d.) step 4c [kg].

    Parameters
    ----------
    valve_mass, spring_mass, pushrod_mass : float
        [kg].
    rocker_inertia : float
        J about the rocker shaft [kg m^2].
    valve_arm : float
        Valve-side rocker arm l_k [m].
    rocker_ratio : float
        i_k.
    pushrod_stiffness, rocker_stiffness : float
        C_sht and C_kor [N/m].
    rigid_pushrod : bool
        Take the pushrod as m_sht / i_k^2 instead of the printed term.

    Notes
    -----
    .. math:: m = m_{kl} + \\frac{m_{pr}}{3} + \\frac{J_{kor}}{l_k^2}
              + \\frac13\\frac{m_{sht}}{(i_k + C_{sht}/(i_k C_{kor}))^2}

    The last term is kept as printed (its intended meaning is unclear, corrections note 35).

    References
    ----------
    Valve-train dynamics article (n.d.), step 4c, with J / l_k^2 (corrections note 35).
    """
    if rigid_pushrod:
        pushrod = pushrod_mass / rocker_ratio**2
    else:
        pushrod = pushrod_mass / (3.0 * (rocker_ratio + pushrod_stiffness / (rocker_ratio * rocker_stiffness)) ** 2)
    return valve_mass + spring_mass / 3.0 + rocker_inertia / valve_arm**2 + pushrod


def drive_stiffness(pushrod_stiffness, rocker_stiffness, rocker_ratio) -> float:
    """C_mgr = C_sht C_kor / (i_k^2 C_kor + C_sht) [N/m] (Valve-train dynamics article (n.d.), step 4e).

    Examples
    --------
    A worked example, C_sht = 8000 N/mm, C_kor = 12000 N/mm, i_k = 1.5: 2742.9 N/mm.

    >>> round(drive_stiffness(8000e3, 12000e3, 1.5) / 1e3, 1)
    2742.9
    """
    return pushrod_stiffness * rocker_stiffness / (rocker_ratio**2 * rocker_stiffness + pushrod_stiffness)


def spring_rate(mass, min_valve_acceleration, reserve, preload, valve_lift) -> float:
    """Spring rate of Valve-train dynamics article (n.d.) step 4a/4e, C_pr = (K_3 m |j_min| - P_0) / h_kl max [N/m].

    Parameters
    ----------
    mass : float
        Reduced mass m [kg].
    min_valve_acceleration : float
        Valve acceleration at the nose j_min < 0 [m/s^2].
    reserve : float
        K_3.
    preload : float
        P_0 [N].
    valve_lift : float
        h_kl max [m].
    """
    return (float(required_spring_force(mass, min_valve_acceleration, reserve)) - preload) / valve_lift


def natural_frequency(spring_rate, drive_stiffness, mass) -> float:
    """omega_0 = sqrt((C_pr + C_mgr) / m) [rad/s] (Valve-train dynamics article (n.d.), step 4e)."""
    return np.sqrt((spring_rate + drive_stiffness) / mass)


def resonant_harmonic(omega0, cam_speed) -> int:
    """k = int(omega_0 / omega_cam), the harmonic of the camshaft revolution nearest below omega_0 (step 4zh); the
    first where omega_0 lies below the camshaft speed itself (no harmonic lies below it: a train that slow is far
    beyond its separation, which the dynamics grade).

    The printed 0.5 omega is the camshaft speed when omega is the crankshaft's (corrections note 36).
    """
    return max(int(omega0 / cam_speed), 1)


def harmonic_force(tappet_lift, drive_stiffness, rocker_ratio, orders) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Amplitudes of harmonics of the excitation C_mgr i_k h_T over one period of N samples (Valve-train dynamics article (n.d.), step 4z).

    Parameters
    ----------
    tappet_lift : ndarray (N,)
        h_T [m] sampled evenly over the period (a camshaft revolution, or the event for the printed variant).
    drive_stiffness : float
        C_mgr [N/m].
    rocker_ratio : float
        i_k.
    orders : array_like of int
        Harmonic numbers k.

    Returns
    -------
    a, b, f : ndarray
        A_k, B_k and F = sqrt(A_k^2 + B_k^2) [N].

    Notes
    -----
    .. math:: A_k, B_k = \\frac2N\\sum_i C_{mgr} i_k h_{T,i}\\,\\{\\cos, \\sin\\}\\frac{2\\pi k i}{N}

    Examples
    --------
    A pure cosine of amplitude 1 mm at order 3 on C_mgr i_k = 1 N/mm gives F_3 = 1 N and F_2 = 0:

    >>> i = np.arange(360)
    >>> np.round(harmonic_force(1e-3 * np.cos(2 * np.pi * 3 * i / 360), 1e3, 1.0, [2, 3])[2], 12).tolist()
    [0.0, 1.0]
    """
    h = np.asarray(tappet_lift, dtype=float)
    phase = 2.0 * np.pi * np.outer(np.asarray(orders), np.arange(h.size)) / h.size
    scale = 2.0 / h.size * drive_stiffness * rocker_ratio
    a, b = scale * np.cos(phase) @ h, scale * np.sin(phase) @ h
    return a, b, np.hypot(a, b)


def elastic_amplitude(force, mass, omega0, damping_factor=DAMPING_FACTOR) -> np.ndarray:
    """Delta = F / (xi omega_0) with xi = 0.107 m omega_0 [m] (Valve-train dynamics article (n.d.), step 4i; xi in N s/m, corrections note 38)."""
    return force / (damping_factor * mass * omega0**2)


def distortion(amplitude, valve_lift) -> np.ndarray:
    """delta = Delta / (sqrt(2) h_rms), h_rms the RMS valve lift over the event (step 4k), a fraction (x 100: %).

    Parameters
    ----------
    amplitude : float or ndarray
        Delta [m].
    valve_lift : ndarray
        Valve lift i_k h_T samples [m]; the RMS is taken over the positive ones (the event), the reading that
        reproduces this package's worked example.
    """
    lift = np.asarray(valve_lift, dtype=float)
    lift = lift[lift > 0.0]
    return amplitude / (np.sqrt(2.0) * np.sqrt(np.mean(lift**2)))


@dataclass(frozen=True)
class Resonance:
    """Resonance analysis of the Valve-train dynamics article (n.d.) for one cam at one speed (SI).

    Attributes
    ----------
    omega0 : float
        Natural frequency [rad/s].
    order : int
        Resonant harmonic k.
    force, amplitude, distortion : float
        F_k [N], Delta [m] and delta (fraction) at the order k.
    orders : ndarray
        k - span ... k + span.
    spectrum_force, spectrum_amplitude, spectrum_distortion : ndarray
        The same quantities at those orders.
    """

    omega0: float
    order: int
    force: float
    amplitude: float
    distortion: float
    orders: np.ndarray
    spectrum_force: np.ndarray
    spectrum_amplitude: np.ndarray
    spectrum_distortion: np.ndarray


def resonance(law, cam_speed, mass, spring_rate, drive_stiffness, rocker_ratio, samples=3600, period="revolution",
              span=2, damping_factor=DAMPING_FACTOR) -> Resonance:
    """Resonance analysis of the Valve-train dynamics article (n.d.) for a lift law (steps 4e-4k).

    Parameters
    ----------
    law : valvetrain.laws.base.LiftLaw
        The cam; h_T is its tappet lift.
    cam_speed : float
        Camshaft speed omega_cam = pi n / 60 for crankshaft rpm n [rad/s].
    mass, spring_rate, drive_stiffness : float
        m [kg], C_pr and C_mgr [N/m].
    rocker_ratio : float
        i_k.
    samples : int
        Samples N per period.
    period : {"revolution", "event"}
        A camshaft revolution (the corrected reading) or the event alone (the printed N = t_k / dt).
    span : int
        Orders k - span ... k + span of the spectrum.

    Returns
    -------
    Resonance

    References
    ----------
    Valve-train dynamics article (n.d.), steps 4e-4k (corrected: corrections notes 35-38).
    """
    omega0 = float(natural_frequency(spring_rate, drive_stiffness, mass))
    k = resonant_harmonic(omega0, cam_speed)
    if period == "revolution":
        theta = -np.pi + 2.0 * np.pi * np.arange(samples) / samples
    elif period == "event":
        theta = law.start + (law.end - law.start) * np.arange(samples) / samples
    else:
        raise InputError(f"period must be 'revolution' or 'event', not {period!r}")
    lift = law.lift(theta)
    orders = np.arange(max(k - span, 1), k + span + 1)
    force = harmonic_force(lift, drive_stiffness, rocker_ratio, orders)[2]
    amplitude = elastic_amplitude(force, mass, omega0, damping_factor)
    delta = distortion(amplitude, rocker_ratio * lift)
    at = int(np.flatnonzero(orders == k)[0])
    return Resonance(omega0, k, float(force[at]), float(amplitude[at]), float(delta[at]), orders, force, amplitude,
                     delta)
