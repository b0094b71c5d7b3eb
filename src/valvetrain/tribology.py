"""Lubrication and friction of the cam/follower line contact: film thickness, film parameter, regime, friction,
flash temperature.

SI units: m, s, rad, N, Pa, Pa s, K.  Pure functions over numpy arrays; the curvature of the cam comes from
:mod:`valvetrain.geometry` (through the law), the Hertz half-width from :mod:`valvetrain.strength`.

Velocities are those of each surface relative to the contact point, along the common tangent: their mean is the
entraining velocity that builds the film, their difference the sliding velocity that heats and rubs it.
"""

import numpy as np

POISSON = 0.3
"""Poisson's ratio behind the package's Hertz constant 0.418 (:func:`valvetrain.strength.hertz_line_stress`); the
reduced modulus of the film thickness formula is E' = E_m / (1 - nu^2)."""

REGIME_BANDS = (1.0, 3.0)
"""Film parameter lambda below which the contact runs in boundary lubrication and above which in full film
(Hamrock, Schmid and Jacobson (2004), ch. 1: mixed between)."""

BLOK_LINE = 1.11
"""Blok's constant of the largest flash temperature of a line contact under a semi-elliptic (Hertzian) heat source
over the full contact width 2b, both Peclet numbers large (Blok (1937))."""


def reduced_modulus(contact_modulus: float) -> float:
    """E' = E_m / (1 - nu^2) [Pa], the reduced modulus of the elastohydrodynamic formulas.

    Parameters
    ----------
    contact_modulus : float
        Effective modulus E_m = 2 E_1 E_2 / (E_1 + E_2) of :func:`valvetrain.strength.effective_modulus` [Pa].

    Notes
    -----
    With equal Poisson ratios nu, 2 / E' = (1 - nu^2)/E_1 + (1 - nu^2)/E_2 = 2 (1 - nu^2) / E_m; nu = :data:`POISSON`.

    References
    ----------
    Hamrock, Schmid and Jacobson (2004), ch. 17 (effective elastic modulus).
    """
    return contact_modulus / (1.0 - POISSON**2)


def flat_follower_velocities(omega, base_radius, h, d2h) -> tuple[np.ndarray, np.ndarray]:
    """Surface velocities of cam and flat-faced follower relative to the contact point [m/s].

    Parameters
    ----------
    omega : float or ndarray
        Camshaft angular speed [rad/s].
    base_radius : float
        Heel-circle radius R0 [m].
    h, d2h : ndarray
        Tappet lift [m] and its second derivative by the camshaft angle [m/rad^2].

    Returns
    -------
    (ndarray, ndarray)
        u_cam = omega (R0 + h + h'') = omega rho and u_follower = omega h'' [m/s].

    Notes
    -----
    The contact point lies h' from the follower axis and moves along the face at omega h''; the cam surface there
    moves at omega (R0 + h) the other way.  Relative to the contact point:

    .. math:: u_{cam} = \\omega (R_0 + h + h''), \\quad u_f = \\omega h'', \\quad
              u_e = \\tfrac12 (u_{cam} + u_f) = \\tfrac12\\omega (R_0 + h + 2h''), \\quad u_s = \\omega (R_0 + h)

    The entraining velocity vanishes where R0 + h + 2 h'' = 0, on the nose of most cams: there the steady film
    thickness is zero (the squeeze film, not modelled, carries the load through it).

    References
    ----------
    Dowson, Harrison and Taylor (1986), the kinematics of a cam and flat follower; Shang Hanji (1988), eq. (2.6)
    (rho = R0 + h + h'').
    """
    return omega * (base_radius + h + d2h), omega * d2h


def roller_follower_velocities(omega, base_radius, roller_radius, h, dh, rho,
                               slip=0.0) -> tuple[np.ndarray, np.ndarray]:
    """Surface velocities of cam and roller relative to the contact point [m/s], with the roller's slip.

    Parameters
    ----------
    omega : float or ndarray
        Camshaft angular speed [rad/s].
    base_radius, roller_radius : float
        Heel-circle radius R0 and roller radius R_r [m].
    h, dh : ndarray
        Tappet lift [m] and its derivative by the camshaft angle [m/rad].
    rho : ndarray
        Radius of curvature of the cam profile [m] (:func:`valvetrain.geometry.roller_follower_curvature`).
    slip : float
        Share of the cam's surface velocity the roller's surface lags behind it (0: pure rolling).

    Returns
    -------
    (ndarray, ndarray)
        u_cam and u_roller [m/s].

    Notes
    -----
    In the cam's frame the roller centre runs along the pitch curve at omega sqrt(g^2 + h'^2), g = R0 + R_r + h;
    the contact point runs along the profile at rho / (rho + R_r) of that:

    .. math:: u_{cam} = \\omega \\sqrt{g^2 + h'^2}\\,\\frac{\\rho}{\\rho + R_r}, \\qquad u_r = (1 - s)\\,u_{cam}

    References
    ----------
    Shang Hanji (1988), eq. (2.7) (pitch curve, rho_p = rho + R_r).
    """
    g = base_radius + roller_radius + h
    u_cam = omega * np.hypot(g, dh) / (1.0 + roller_radius / rho)    # rho / (rho + R_r), 1 on a straight flank
    return u_cam, (1.0 - slip) * u_cam


def film_thickness_line(entraining, radius, load_per_width, viscosity, pressure_viscosity,
                        reduced) -> np.ndarray:
    """Minimum film thickness of a lubricated line contact, Dowson and Higginson [m].

    Parameters
    ----------
    entraining : ndarray
        Entraining velocity u = (u_1 + u_2)/2 [m/s]; its magnitude is used.
    radius : ndarray
        Reduced radius of curvature R = 1 / (1/rho_1 + 1/rho_2) [m].
    load_per_width : ndarray
        Load per unit contact width w' = F / b [N/m] (> 0).
    viscosity : float
        Dynamic viscosity of the oil at the inlet temperature and ambient pressure eta_0 [Pa s].
    pressure_viscosity : float
        Pressure-viscosity coefficient alpha [1/Pa].
    reduced : float
        Reduced modulus E' [Pa] (:func:`reduced_modulus`).

    Notes
    -----
    .. math:: \\frac{h_{min}}{R} = 2.65\\,U^{0.70} G^{0.54} W^{-0.13}, \\quad U = \\frac{\\eta_0 u}{E' R},\\;
              G = \\alpha E',\\; W = \\frac{w'}{E' R}

    Isothermal, fully flooded, steady: the squeeze film of a load that changes along the cam and the inlet heating
    are not in it.

    References
    ----------
    Dowson and Higginson (1977), the minimum film thickness formula; Hamrock, Schmid and Jacobson (2004), ch. 21.
    """
    u = viscosity * np.abs(entraining) / (reduced * radius)
    w = load_per_width / (reduced * radius)
    return 2.65 * radius * u**0.70 * (pressure_viscosity * reduced) ** 0.54 * w ** -0.13


def film_parameter(film, roughness_1, roughness_2) -> np.ndarray:
    """lambda = h_min / sqrt(R_q1^2 + R_q2^2), the film thickness over the composite roughness.

    Parameters
    ----------
    film : ndarray
        Minimum film thickness [m].
    roughness_1, roughness_2 : float
        RMS roughness R_q of the two surfaces [m].

    References
    ----------
    Hamrock, Schmid and Jacobson (2004), ch. 1 (film parameter and lubrication regimes).
    """
    return film / np.hypot(roughness_1, roughness_2)


def regime(lam) -> np.ndarray:
    """The lubrication regime of film parameters ``lam``: 0 boundary, 1 mixed, 2 full film (:data:`REGIME_BANDS`).

    >>> regime(np.array([0.5, 1.0, 2.9, 3.0])).tolist()
    [0, 1, 1, 2]
    """
    return np.searchsorted(np.asarray(REGIME_BANDS), lam, side="right")


def friction_coefficient(lam, boundary, full_film) -> np.ndarray:
    """A Stribeck-type friction coefficient of the film parameter lambda.

    Parameters
    ----------
    lam : ndarray
        Film parameter.
    boundary, full_film : float
        Friction coefficient in boundary lubrication (lambda <= 1) and in full film (lambda >= 3).

    Notes
    -----
    mu = mu_b for lambda <= 1, mu_f for lambda >= 3 and linear in lambda across the mixed band between: the
    falling branch of the Stribeck curve in terms of lambda, with the bands of :data:`REGIME_BANDS`.  The rise of
    a thick film's viscous friction with speed is not in it (the cam contact stays far below that).

    >>> friction_coefficient(np.array([0.0, 2.0, 5.0]), 0.12, 0.04).round(6).tolist()
    [0.12, 0.08, 0.04]

    References
    ----------
    Hamrock, Schmid and Jacobson (2004), ch. 1 (the Stribeck curve and the bands of lambda).
    """
    low, high = REGIME_BANDS
    share = np.clip((np.asarray(lam, dtype=float) - low) / (high - low), 0.0, 1.0)
    return boundary + (full_film - boundary) * share


def flash_temperature(friction, load_per_width, u_1, u_2, half_width, effusivity_1,
                      effusivity_2) -> np.ndarray:
    """Largest flash temperature rise of a sliding line contact, Blok [K].

    Parameters
    ----------
    friction : ndarray
        Friction coefficient.
    load_per_width : ndarray
        w' = F / b [N/m].
    u_1, u_2 : ndarray
        Surface velocities relative to the contact [m/s]; their magnitudes enter the heat partition.
    half_width : ndarray
        Hertz half-width a of the contact [m] (:func:`valvetrain.strength.hertz_half_width`).
    effusivity_1, effusivity_2 : float
        Thermal effusivity sqrt(k rho c) of each body [W s^0.5 / (m^2 K)].

    Notes
    -----
    .. math:: \\Delta T_f = \\frac{1.11\\,\\mu\\,w'\\,|u_1 - u_2|}
              {\\sqrt{2a}\\,(\\beta_1\\sqrt{|u_1|} + \\beta_2\\sqrt{|u_2|})}

    The heat mu w' |u_1 - u_2| is shared so that both surfaces reach the same flash temperature, each taken as a
    half-space under a fast-moving source; zero where both surfaces stand still relative to the contact.

    References
    ----------
    Blok (1937); Hamrock, Schmid and Jacobson (2004), ch. 1 (flash temperature).
    """
    heat = BLOK_LINE * friction * load_per_width * np.abs(u_1 - u_2)
    sink = np.sqrt(2.0 * half_width) * (effusivity_1 * np.sqrt(np.abs(u_1)) + effusivity_2 * np.sqrt(np.abs(u_2)))
    return np.divide(heat, sink, out=np.zeros(np.broadcast(heat, sink).shape), where=sink > 0.0)


def friction_torque(force, friction, sliding, rolling_friction, rolling, omega) -> np.ndarray:
    """Camshaft torque of the contact's friction [N m]: the power it dissipates over the camshaft speed.

    Parameters
    ----------
    force : ndarray
        Normal force of the contact [N].
    friction : ndarray
        Sliding friction coefficient.
    sliding : ndarray
        Sliding velocity |u_1 - u_2| [m/s].
    rolling_friction : float
        Rolling resistance of a roller (its bearing's moment over its radius per unit load); 0 for a flat follower.
    rolling : ndarray
        Velocity at which the roller's surface rolls relative to the contact [m/s] (0 for a flat follower).
    omega : float
        Camshaft angular speed [rad/s] (> 0).

    Notes
    -----
    .. math:: T_f = F\\,(\\mu\\,|u_s| + \\mu_r\\,|u_r|) / \\omega

    For a flat follower u_s = omega (R0 + h): T_f = mu F (R0 + h), the friction force along the face times its
    distance from the camshaft axis.
    """
    return force * (friction * np.abs(sliding) + rolling_friction * np.abs(rolling)) / omega
