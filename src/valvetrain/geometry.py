"""Cam contour geometry for flat-faced and roller followers.

Conventions: camshaft angle ``theta`` [rad] from the cam nose as in
:mod:`valvetrain.laws.base`; lift ``h`` and its derivatives ``dh = dh/dtheta``,
``d2h`` from the law [m].  ``base_radius`` is the radius of the cam's heel circle on
which ``h = 0`` (for a law with a ramp of height h0 this is r_k = r0 - h0, Valve-train practical works (n.d.)).

The contour is given in a frame fixed to the cam: the follower axis points along
``u = (sin theta, cos theta)``, so the nose lies on +y and the cam turns
counter-clockwise as theta grows; ``t = du/dtheta = (cos theta, -sin theta)``.
Lengths in m, angles in rad.
"""

import numpy as np


def axes(theta) -> tuple[np.ndarray, np.ndarray]:
    """The follower axis u = (sin theta, cos theta) and t = du/dtheta = (cos theta, -sin theta), each (2, n)."""
    s, c = np.sin(theta), np.cos(theta)
    return np.stack([s, c]), np.stack([c, -s])


def flat_follower_contour(theta, base_radius, h, dh) -> np.ndarray:
    """Cam contour for a flat-faced translating follower.

    Parameters
    ----------
    theta : ndarray
        Camshaft angle [rad from the nose].
    base_radius : float
        Heel-circle radius [m].
    h, dh : ndarray
        Lift [m] and dh/dtheta [m/rad].

    Returns
    -------
    ndarray, shape (2, n)
        x, y of the contact point [m].

    Notes
    -----
    .. math:: \\mathbf p = (R_0 + h)\\,\\mathbf u + h'\\,\\mathbf t

    The contact point lies h' off the follower axis; the support function of the
    contour in the direction u is R0 + h, which is what a flat follower sees.

    References
    ----------
    Shang Hanji (1988), section 2.1, eq. (2.15) (same curve, rotated so that the nose is on +y).
    """
    u, t = axes(theta)
    return (base_radius + h) * u + dh * t


def flat_follower_curvature(base_radius, h, d2h) -> np.ndarray:
    """Radius of curvature of the cam for a flat-faced follower, rho = R0 + h + h'' [m].

    Negative or zero rho means the profile is undercut (a flat follower cannot follow it).

    References
    ----------
    Shang Hanji (1988), eq. (2.6); Valve-train practical works (n.d.), eq. (2.38) at the nose.

    Examples
    --------
    At the nose of the appendix of Valve-train practical works (n.d.) cam (r_k = 19.75 mm, h = 6.5 mm,
    h'' = 2 c32 = -14.365 mm/rad^2) rho_min = 11.885 mm (corrections note 2).

    >>> round(flat_follower_curvature(19.75, 6.5, 2 * -7.182502), 3)
    11.885
    """
    return base_radius + h + d2h


def roller_pitch_radius(base_radius, roller_radius, h) -> np.ndarray:
    """Polar radius of the roller-centre (pitch) curve, g = R0 + R_r + h [m] (Shang Hanji (1988), eq. 2.7)."""
    return base_radius + roller_radius + h


def roller_follower_contour(theta, base_radius, roller_radius, h, dh) -> np.ndarray:
    """Cam contour for a translating roller follower whose axis passes through the cam centre.

    Parameters
    ----------
    theta : ndarray
        Camshaft angle [rad from the nose].
    base_radius, roller_radius : float
        Heel-circle radius R0 and roller radius R_r [m].
    h, dh : ndarray
        Lift [m] and dh/dtheta [m/rad].

    Returns
    -------
    ndarray, shape (2, n)
        x, y of the contact point [m].

    Notes
    -----
    The roller centre runs on the pitch curve :math:`\\mathbf c = g\\,\\mathbf u`,
    :math:`g = R_0 + R_r + h`; the contour is the inner offset of the pitch curve by
    the roller radius along its outward normal
    :math:`\\mathbf n = (g\\,\\mathbf u - g'\\,\\mathbf t)/\\sqrt{g^2+g'^2}`.

    References
    ----------
    Shang Hanji (1988), section 2.1, eq. (2.16) (with R00 the roller radius, corrections
    note 33).
    """
    u, t = axes(theta)
    g = roller_pitch_radius(base_radius, roller_radius, h)
    n = (g * u - dh * t) / np.hypot(g, dh)
    return g * u - roller_radius * n


STRAIGHT_TOLERANCE = 1e-10
"""Relative size of the curvature terms' difference below which the pitch curve counts as straight."""


def roller_pitch_curvature(base_radius, roller_radius, h, dh, d2h) -> np.ndarray:
    """Radius of curvature of the pitch curve [m]; the cam profile's is this minus the roller radius.

    Notes
    -----
    .. math:: \\rho_p = \\frac{(g^2 + g'^2)^{3/2}}{g^2 + 2g'^2 - g g''}

    Positive where the pitch curve is convex, negative where concave, infinite on a straight
    stretch (the flank of a tangent cam).

    References
    ----------
    Shang Hanji (1988), eq. (2.7) (corrected: the subtracted radius is the roller radius).

    Examples
    --------
    A circle of radius 30 mm (no lift) has rho_p = 30 mm.

    >>> float(roller_pitch_curvature(20.0, 10.0, 0.0, 0.0, 0.0))
    30.0
    """
    g = roller_pitch_radius(base_radius, roller_radius, h)
    first, second = g * g + 2.0 * dh * dh, g * d2h
    den = first - second
    # on a straight pitch line (tangent cam flank) the two terms cancel to round-off: the radius is infinite, not a
    # huge number of either sign (beyond 1e10 pitch radii the line is straight to the precision of the terms)
    straight = np.abs(den) <= STRAIGHT_TOLERANCE * (np.abs(first) + np.abs(second))
    return np.where(straight, np.inf, (g * g + dh * dh) ** 1.5 / np.where(straight, 1.0, den))


def roller_follower_curvature(base_radius, roller_radius, h, dh, d2h) -> np.ndarray:
    """Radius of curvature of the cam profile for a roller follower, rho = rho_p - R_r [m] (Shang Hanji (1988), eq. 2.7)."""
    return roller_pitch_curvature(base_radius, roller_radius, h, dh, d2h) - roller_radius


def roller_pressure_angle(base_radius, roller_radius, h, dh) -> np.ndarray:
    """Pressure angle of a central translating roller follower, tan beta = h' / g [rad].

    The angle between the contact normal and the follower axis; UkrSURT Proceedings (2019) limits it to
    30 deg (corrections note 41).

    Examples
    --------
    >>> round(float(np.rad2deg(roller_pressure_angle(20.0, 10.0, 0.0, 30.0))), 6)
    45.0
    """
    return np.arctan2(dh, roller_pitch_radius(base_radius, roller_radius, h))


def undercut_flat(rho) -> bool:
    """Mask of the angles where a flat follower's cam is undercut: rho <= 0 (Shang Hanji (1988), section 2.1).

    Judge a profile by its smallest radius refined on the contour (the profile stage's ``rho_min``), not by the
    samples of a table: an undercut may lie between them.
    """
    return np.asarray(rho) <= 0.0


def undercut_roller(pitch_rho, roller_radius) -> bool:
    """Mask of the angles where a roller follower's cam is undercut: 0 < rho_pitch <= R_r (Shang Hanji (1988), 2.1).

    Judge a profile by its smallest convex radius refined on the contour (the profile stage's ``rho_min`` plus R_r),
    not by the samples of a table: an undercut may lie between them.
    """
    pitch_rho = np.asarray(pitch_rho)
    return (pitch_rho > 0.0) & (pitch_rho <= roller_radius)


def valve_piston_clearance(piston_displacement, valve_lift, tdc_gap) -> np.ndarray:
    """Distance between valve head and piston crown, D_s = s + y0 - y [m].

    Parameters
    ----------
    piston_displacement : ndarray
        Piston travel from TDC s [m] at the same crank angles as ``valve_lift``.
    valve_lift : ndarray
        Valve lift y [m].
    tdc_gap : float
        Gap y0 between the closed valve and the piston crown at TDC [m].

    Notes
    -----
    The valve axis is taken parallel to the cylinder axis, as in the source.

    References
    ----------
    Shang Hanji (1988), section 2.1, eqs. (2.13)-(2.14).
    """
    return piston_displacement + tdc_gap - valve_lift
