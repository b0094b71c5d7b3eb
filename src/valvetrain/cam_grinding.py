"""Cam grinding: the grinding-wheel centre path, the copy grinder's master cam and the lift error of wheel wear.

A copy (master-cam) grinder turns the cam and its master on one spindle; a follower riding on the
master moves the wheel head so that the wheel centre traces, in the cam frame, the offset of the cam
contour by the wheel radius ``R_w`` along its outward normal.  The master follower (a roller of radius
``r_m``) moves ``i`` times as far as the wheel centre (``i`` the bar ratio of the head); the head's
travel is taken as straight along the line through the spindle axis (the arc of a rocking bar is not
modelled).  A worn wheel (radius ``R_w - w``) on the same centre path grinds a cam that is the outer
offset of the design cam by ``w``: a flat follower sees the same lift on a base circle larger by
``w``; a roller follower sees a lift error and a phase shift.

Conventions of :mod:`valvetrain.geometry`: cam frame with the follower axis along
``u = (sin theta, cos theta)``, nose on +y, polar angles measured from +y towards +x; ``derivs`` is a
callable ``theta -> (h, h', h'', ...)`` (a law's ``derivatives``) [m, m/rad, m/rad^2]; ``heel`` the heel
(base) circle radius of the cam [m].  Every function is vectorised over the angles; lengths in m,
angles in rad.

References
----------
Shang Hanji (1988), ch. 6 (the master-cam calculation of a cam grinder and the effect of the wheel
radius on the cam profile; only the book's table of contents is at hand, the formulas here are derived
from the contour geometry of its section 2.1, eqs. (2.6)-(2.7), (2.15)-(2.16)).
"""

import numpy as np

from .followers import FLAT
from .numerics import invert_angle


def _pitch_curve(derivs, theta, heel, follower):
    """The follower's pitch curve of the law ``derivs`` (:meth:`valvetrain.followers.Follower.pitch_curve`)."""
    theta = np.asarray(theta, dtype=float)
    h, dh, d2h = derivs(theta)[:3]
    return follower.pitch_curve(theta, heel, h, dh, d2h)


def offset_curve(derivs, theta, heel, distance, follower=FLAT) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The offset of the cam contour by ``distance`` along its outward normal [m].

    Parameters
    ----------
    derivs : callable
        ``theta -> (h, h', h'', ...)`` of the lift law [m, m/rad, m/rad^2].
    theta : ndarray
        Camshaft angles [rad from the nose] (the parameter of the contour).
    heel : float
        Heel circle radius of the cam [m].
    distance : float
        Offset along the outward normal [m] (the wheel radius gives the wheel-centre path).
    follower : valvetrain.followers.Follower
        The cam's follower (default flat).

    Returns
    -------
    points, derivative, normal, radius : ndarray
        Points (2, n) [m], their derivative d/dtheta (2, n) [m/rad], the outward unit normal (2, n) and the
        radius of curvature of the offset curve [m] (positive convex, negative concave, inf straight).

    Notes
    -----
    The contour is an offset of a base curve B by a depth d0 (the contour itself, d0 = 0, for a
    flat follower; the roller pitch curve, d0 = -R_r, for a roller). An offset by d along the unit
    normal n keeps the normal, and

    .. math:: \\mathbf c = \\mathbf B + (d_0 + d)\\,\\mathbf n,\\qquad
              \\mathbf c' = \\mathbf B'\\left(1 + \\frac{d_0 + d}{\\rho_B}\\right),\\qquad
              \\rho_c = \\rho_B + d_0 + d

    The offset is regular while :math:`1 + (d_0+d)/\\rho_B > 0`; where it is not, the offset loops
    (a concave stretch of radius smaller than the offset).

    References
    ----------
    Shang Hanji (1988), section 2.1, eqs. (2.6)-(2.7), (2.15)-(2.16), for the contour, its normal and
    curvature.
    """
    base, dbase, rho, normal, depth = _pitch_curve(derivs, theta, heel, follower)
    d = depth + distance
    return base + d * normal, dbase * (1.0 + d / rho), normal, rho + d


def wheel_centre_path(derivs, theta, heel, wheel_radius, follower=FLAT) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The grinding-wheel centre in the cam frame while the wheel grinds the contour point of ``theta``.

    Returns
    -------
    points : ndarray, shape (2, n)
        Wheel centre [m].
    radius, angle : ndarray
        Its polar radius L [m] and polar angle psi from the nose direction [rad].

    Notes
    -----
    For a flat follower

    .. math:: \\mathbf C = (R_0 + h + R_w)\\,\\mathbf u + h'\\,\\mathbf t,\\quad
              L = \\sqrt{(R_0+h+R_w)^2 + h'^2},\\quad \\psi = \\theta + \\arctan\\frac{h'}{R_0+h+R_w}

    and for a roller follower the pitch curve offset by R_w - R_r (:func:`offset_curve`).

    References
    ----------
    Shang Hanji (1988), ch. 6 (wheel-centre path), section 2.1 (contour).

    Examples
    --------
    A cam with no lift (a circle of 20 mm) and a wheel of 300 mm: the centre runs on a circle of 320 mm.

    >>> import numpy as np
    >>> flat = lambda t: np.zeros((3, np.size(t)))
    >>> c, L, psi = wheel_centre_path(flat, np.array([0.0, 1.0]), 20.0, 300.0)
    >>> L.tolist()
    [320.0, 320.0]
    """
    c = offset_curve(derivs, theta, heel, wheel_radius, follower)[0]
    return c, np.hypot(*c), np.arctan2(*c)


def wheel_centre_radius(derivs, psi, heel, wheel_radius, follower=FLAT) -> np.ndarray:
    """The wheel centre's polar radius L [m] at polar angles ``psi`` of the cam frame [rad from the nose].

    This is the motion the master must give the wheel head while the spindle turns: at spindle angle
    psi the wheel centre lies on the fixed line of the head at distance L(psi) from the axis. Solved on the
    analytic path (not interpolated); the path must be regular (:func:`grindable`).

    References
    ----------
    Shang Hanji (1988), ch. 6.
    """
    theta = invert_angle(lambda t: wheel_centre_path(derivs, t, heel, wheel_radius, follower)[2], psi)
    return wheel_centre_path(derivs, theta, heel, wheel_radius, follower)[1]


def master_follower_lift(derivs, psi, heel, wheel_radius, bar_ratio, follower=FLAT) -> np.ndarray:
    """Lift of the master follower at spindle angles ``psi`` [rad from the nose], s_m = i (L - L_min) [m].

    Notes
    -----
    .. math:: s_m(\\psi) = i\\,[L(\\psi) - L_{min}],\\qquad L_{min} = R_0 + R_w

    with ``i`` the bar ratio (master follower travel / wheel-centre travel) and R_0 the cam's heel radius.

    References
    ----------
    Shang Hanji (1988), ch. 6 (master follower lift).
    """
    return bar_ratio * (wheel_centre_radius(derivs, psi, heel, wheel_radius, follower) - (heel + wheel_radius))


def default_master_base_radius(heel, wheel_radius, bar_ratio, master_roller) -> float:
    """The master's heel radius that makes its pitch curve the wheel-centre path scaled by the bar ratio,
    R_m0 = i (R_0 + R_w) - r_m [m]; with i = 1 and r_m = R_w the master is the cam itself."""
    return bar_ratio * (heel + wheel_radius) - master_roller


def master_pitch(derivs, theta, heel, wheel_radius, bar_ratio, master_base, master_roller, follower=FLAT) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The master follower's centre curve (master pitch curve) in the master frame, parametrised by the cam angle.

    Returns
    -------
    points, derivative, normal : ndarray, shape (2, n)
        Pitch points [m], their derivative d/dtheta [m/rad] and the outward unit normal.

    Notes
    -----
    The master turns with the cam and its follower sits on the wheel's line, so the pitch point lies
    in the direction of the wheel centre C at the radius

    .. math:: g_m = R_{m0} + r_m + i\\,(L - L_{min}),\\qquad \\mathbf M = g_m\\,\\mathbf C / L,\\qquad
              \\mathbf M' = i L'\\,\\hat{\\mathbf C} + g_m\\,(\\mathbf C' - L'\\hat{\\mathbf C})/L,\\quad
              L' = \\hat{\\mathbf C}\\cdot\\mathbf C'

    References
    ----------
    Shang Hanji (1988), ch. 6 (master cam) and eq. (2.16) (contour from the pitch radius).
    """
    c, dc = offset_curve(derivs, theta, heel, wheel_radius, follower)[:2]
    length = np.hypot(*c)
    unit = c / length
    dl = np.sum(unit * dc, axis=0)
    g = master_base + master_roller + bar_ratio * (length - (heel + wheel_radius))
    dm = bar_ratio * dl * unit + g * (dc - dl * unit) / length
    speed = np.hypot(*dm)
    return g * unit, dm, np.stack([-dm[1], dm[0]]) / speed


def master_contour(derivs, theta, heel, wheel_radius, bar_ratio, master_base, master_roller, follower=FLAT) -> np.ndarray:
    """The master cam's contour [m], shape (2, n): the pitch curve offset inwards by the master roller radius.

    References
    ----------
    Shang Hanji (1988), ch. 6, with eq. (2.16) for a roller follower.
    """
    m, _, n = master_pitch(derivs, theta, heel, wheel_radius, bar_ratio, master_base, master_roller, follower)
    return m - master_roller * n


def master_pitch_curvature(derivs, theta, heel, wheel_radius, bar_ratio, master_base, master_roller, follower=FLAT) -> np.ndarray:
    """Radius of curvature of the master pitch curve [m] (positive convex) on the angles ``theta``, by
    differentiating the analytic derivative numerically (second-order differences on the given angles, which
    should be dense and include the law's breakpoints). The master contour's radius is this minus r_m."""
    dm = master_pitch(derivs, theta, heel, wheel_radius, bar_ratio, master_base, master_roller, follower)[1]
    d2m = np.gradient(dm, theta, axis=1)
    cross = dm[0] * d2m[1] - dm[1] * d2m[0]
    with np.errstate(divide="ignore"):
        return np.where(cross == 0.0, np.inf, -np.hypot(*dm) ** 3 / np.where(cross == 0.0, 1.0, cross))


def master_polar_radius(derivs, psi, heel, wheel_radius, bar_ratio, master_base, master_roller, follower=FLAT) -> np.ndarray:
    """Polar radius of the master contour [m] at polar angles ``psi`` of the master frame [rad from the nose
    direction], solved on the analytic contour (the contour point's polar angle inverted to round-off).

    References
    ----------
    Shang Hanji (1988), ch. 6 (master cam).
    """
    args = (heel, wheel_radius, bar_ratio, master_base, master_roller, follower)
    theta = invert_angle(lambda t: np.arctan2(*master_contour(derivs, t, *args)), psi)
    return np.hypot(*master_contour(derivs, theta, *args))


def master_flat_lift(derivs, phi, heel, wheel_radius, bar_ratio, master_base, master_roller, follower=FLAT) -> np.ndarray:
    """Flat-follower lift of a convex master [m] in the directions ``phi`` [rad from the nose direction]: its support
    function less its heel radius, for making the master on a surface grinder.

    Notes
    -----
    A flat face pressed against a convex contour touches it where the contour's normal n points along the face
    normal u(phi), at the distance H(phi) = p . n there (the support function); the contact is found by inverting
    the direction of the master's normal to round-off. On a master with a concave stretch the result is
    meaningless: a flat face cannot reach into it (:func:`master_pitch_curvature` tells).

    References
    ----------
    Shang Hanji (1988), eq. (2.15) (the flat follower's contact) and ch. 6 (machining the master on a surface
    grinder, whose wheel face acts as a flat follower).
    """
    args = (heel, wheel_radius, bar_ratio, master_base, master_roller, follower)
    theta = invert_angle(lambda t: np.arctan2(*master_pitch(derivs, t, *args)[2]), phi)
    normal = master_pitch(derivs, theta, *args)[2]
    return np.sum(master_contour(derivs, theta, *args) * normal, axis=0) - master_base


def grindable(derivs, theta, heel, wheel_radius, follower=FLAT) -> tuple[bool, float]:
    """Whether a wheel of ``wheel_radius`` [m] grinds the contour without cutting into it, and the smallest
    factor 1 + R_w / rho of the contour (the wheel path's regularity) on ``theta``.

    A concave stretch whose radius |rho| is not larger than the wheel radius cannot be ground: the wheel
    centre path loops there and the wheel removes the neighbouring profile.

    References
    ----------
    UkrSURT Proceedings (2019) (the wheel radius must not exceed the concave radius of the cam); Shang Hanji
    (1988), ch. 6.
    """
    base, dbase, rho, normal, depth = _pitch_curve(derivs, theta, heel, follower)
    factor = 1.0 + (depth + wheel_radius) / rho
    worst = float(np.min(factor))
    return worst > 0.0, worst


def worn_wheel_lift(derivs, theta, heel, wheel_radius, wear, follower=FLAT, infeed=False) -> np.ndarray:
    """Follower lift [m] of the cam ground by a worn wheel (radius R_w - w) on the design wheel-centre path,
    from the cam's own base circle (R_0 + w), exactly: by re-enveloping the path with the worn wheel.

    With ``infeed`` the head is fed in by w to restore the base circle: the wheel centre runs at L(psi) - w on the
    head's line, and the lift is from the design base circle R_0.

    Parameters
    ----------
    theta : ndarray
        Camshaft angles of the follower [rad from the nose].
    wheel_radius, wear : float
        Design wheel radius R_w and its loss w [m] (w > 0 for a worn wheel).

    Returns
    -------
    lift : ndarray
        [m]; the lift error is this minus the design lift.

    Notes
    -----
    With infeed the path is C - w C/|C|, its derivative C' - w (C' - L' C/L)/L with L' = C . C'/L.
    The worn wheel touches its envelope along the path's normal n_C (from the path's own derivative):
    E = C - (R_w - w) n_C. A flat follower at theta touches E where n_C points along u(theta),
    lift = E . u(theta) - (R_0 + w); a roller's centre runs on Q = E + R_r n_C, and at theta it is the point
    of Q on the follower axis, lift = |Q| - (R_0 + w + R_r). Both contacts are solved by bisection on the
    parameter of the path, to round-off.

    References
    ----------
    Shang Hanji (1988), ch. 6 (the effect of the wheel radius on the cam profile), derived here.
    """
    def path(tau):
        c, dc = offset_curve(derivs, tau, heel, wheel_radius, follower)[:2]
        if infeed:
            length = np.hypot(*c)
            unit = c / length
            dc = dc - wear * (dc - np.sum(unit * dc, axis=0) * unit) / length
            c = c - wear * unit
        n = np.stack([-dc[1], dc[0]]) / np.hypot(*dc)
        return c - (wheel_radius - wear) * n, n

    base = heel if infeed else heel + wear
    return follower.lift_on_path(path, np.asarray(theta, dtype=float), base)


def wear_error_first_order(derivs, theta, heel, wear, follower=FLAT, wheel_radius=None, infeed=False) -> tuple[np.ndarray, np.ndarray]:
    """First-order lift error and phase shift of a cam ground by a wheel worn by ``wear`` [m].

    Returns
    -------
    error : ndarray
        Lift error from the cam's own base circle [m].
    phase : ndarray
        Phase shift delta [rad]: the worn cam's lift at theta is the design lift at theta + delta plus
        d cos(beta) less the base change; positive delta means the lift comes earlier on the opening flank.

    Notes
    -----
    On the design centre path the worn cam is the outer offset of the design cam by d = w and its base circle
    grows by w. With ``infeed`` (the head fed in by w to restore the base circle; ``wheel_radius`` needed) the
    offset varies, d = w (1 - cos gamma), gamma the angle between the wheel centre's radius and the contact
    normal, and the base circle is kept. A flat follower's lift is the support function, which grows by d:
    the error is d less the base change and there is no phase shift. A roller's centre curve is the pitch curve
    offset by d; with the pressure angle beta (tan beta = h'/g, g = R_0 + R_r + h):

    .. math:: \\delta = \\frac{d\\sin\\beta}{g},\\qquad
              \\Delta h \\approx h(\\theta+\\delta) + d\\cos\\beta - h(\\theta) - \\Delta_0
              \\approx d\\sec\\beta - \\Delta_0

    with the base change :math:`\\Delta_0` = w on the design path, 0 with infeed: w (sec beta - 1) on the design
    path.

    References
    ----------
    Shang Hanji (1988), ch. 6 (the effect of the wheel radius on the cam profile), first order derived here.
    """
    theta = np.asarray(theta, dtype=float)
    offset, base = np.full_like(theta, wear), wear
    if infeed:
        c, _, n, _ = offset_curve(derivs, theta, heel, wheel_radius, follower)
        offset, base = wear * (1.0 - np.sum(c * n, axis=0) / np.hypot(*c)), 0.0
    h, dh = derivs(theta)[:2]
    return follower.wear_error(offset, base, heel, h, dh)


__all__ = ["default_master_base_radius", "grindable", "master_contour", "master_follower_lift", "master_pitch",
           "master_flat_lift", "master_pitch_curvature", "master_polar_radius",
           "offset_curve", "wear_error_first_order", "wheel_centre_path",
           "wheel_centre_radius", "worn_wheel_lift"]
