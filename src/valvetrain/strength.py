"""Strength checks of the drive parts (Valve-train practical works (n.d.), work 7; Shang Hanji (1988), eq. 2.5).

SI units: N, m, Pa.  Each check is a pure function; :func:`verdict` makes its value a
:class:`~valvetrain.checks.Check` against the allowable limit and its source.
"""

import numpy as np

from .checks import Check, check
from .locale import NoteText, cited, note as locale_note

DEFLECTION_COEFFICIENT = 64.0 / (3.0 * np.pi)
"""Camshaft deflection coefficient of (7.3): 64/(3 pi) = 6.79 from beam theory; the printed 0.8 is wrong (corrections note 20)."""

STEEL_MODULUS = 2.1e11
"""Young's modulus of steel [Pa]; the manual's 1.1e5 MPa for steel pushrods is wrong (corrections note 21)."""

LIMITS = {
    "camshaft_deflection": (0.05e-3, "max", "mm", "Valve-train practical works (n.d.), eq. (7.3): 0.02-0.05 mm"),
    "cam_contact_stress": (1200e6, "max", "MPa", "Valve-train practical works (n.d.), eqs. (7.4)-(7.5): 600-1200 MPa"),
    "tappet_side_pressure": (10e6, "max", "MPa", "Valve-train practical works (n.d.), eq. (7.6): < 10 MPa"),
    "pushrod_buckling_margin": (2.0, "min", "", "Valve-train practical works (n.d.), eq. (7.8): n = 2-5"),
    "ball_socket_stress": (2000e6, "max", "MPa", "Valve-train practical works (n.d.), eqs. (7.11), (7.14): <= 2000 MPa"),
    "pushrod_head_pressure": (100e6, "max", "MPa", "Valve-train practical works (n.d.), eq. (7.12): <= 80-100 MPa"),
    "rocker_pad_stress": (2000e6, "max", "MPa", "Valve-train practical works (n.d.), eq. (7.13): <= 2000 MPa"),
    "rocker_pivot_stress": (2000e6, "max", "MPa", cited(locale_note(
        "source.pivot_ball", work="Valve-train practical works (n.d.), eqs. (7.11), (7.14)"))),
    "rocker_shaft_bending": (150e6, "max", "MPa", "Valve-train practical works (n.d.), eq. (7.15): <= 150 MPa"),
    "rocker_shaft_shear": (90e6, "max", "MPa", "Valve-train practical works (n.d.), eq. (7.17): <= 90 MPa"),
    "rocker_shaft_bearing": (80e6, "max", "MPa", "Valve-train practical works (n.d.), eq. (7.18): <= 80 MPa"),
    "finger_bending": (150e6, "max", "MPa", cited(locale_note(
        "source.finger_bending", work="Valve-train practical works (n.d.), eq. (7.15)",
        book="Shigley's Mechanical Engineering Design, 9th ed. (2011)"))),
    "bridge_bending": (150e6, "max", "MPa", cited(locale_note(
        "source.bridge_bending", work="Valve-train practical works (n.d.), eq. (7.15)",
        book="Shigley's Mechanical Engineering Design, 9th ed. (2011), Table A-9"))),
}
"""Allowable values: the limit SI (the less strict end of the source's range), its kind, the unit it is shown in
and its source."""


HERTZ_LINE = 0.418
"""The factor of Hertz's line-contact stress, sqrt(1 / (2 pi (1 - mu^2))) with Poisson's ratio mu = 0.3."""


def verdict(check_name, value, note="", unevaluated="") -> Check:
    """The :class:`~valvetrain.checks.Check` of one of the checks of :data:`LIMITS` (severity ``failure``: the
    part cannot carry the load), its value SI (NaN with ``unevaluated``, why it cannot be had)."""
    limit, kind, unit, source = LIMITS[check_name]
    bounds = {"high": limit} if kind == "max" else {"low": limit}
    return check(f"strength.{check_name}", value, **bounds, unit=unit, source=source, severity="failure", note=note,
                 unevaluated=unevaluated)


def cam_force(spring_force, valve_inertia_force, rocker_ratio) -> np.ndarray:
    """Force between cam and follower, reduced to the tappet [N].

    Parameters
    ----------
    spring_force : ndarray
        Spring force at the valve at the instantaneous lift [N] (plus any gas force on the valve head).
    valve_inertia_force : ndarray
        m_v j_v, the inertia force of the train reduced to the valve [N].
    rocker_ratio : float
        i_k = l_v / l_t.

    Notes
    -----
    .. math:: P_T = i_k\\,(P_{spr} + P_{gas}) + m_t j_T,\\quad m_t j_T = i_k\\,m_v j_v

    Valve-train practical works (n.d.)'s (7.1) evaluates this at the opening with the inertia term of a circular-arc
    cam; for an analytic law the inertia term is m_t j_T along the whole profile (corrections note 23).

    References
    ----------
    Valve-train practical works (n.d.), work 7, eqs. (7.1)-(7.2).
    """
    force = np.add(spring_force, valve_inertia_force)
    force *= rocker_ratio      # in place, as in :func:`hertz_line_stress`
    return force


def camshaft_deflection(force, l1, l2, diameter, bore=0.0, modulus=STEEL_MODULUS, coefficient=DEFLECTION_COEFFICIENT) -> float | np.ndarray:
    """Deflection of the camshaft under the cam load between two bearings [m].

    Parameters
    ----------
    force : float
        Cam load P_T max [N].
    l1, l2 : float
        Distances of the cam from the two bearings [m]; span l = l1 + l2.
    diameter, bore : float
        Outer and inner diameter of the shaft [m].
    modulus : float
        Young's modulus [Pa].
    coefficient : float
        64/(3 pi) = 6.79 for a simply supported beam (default); the manual prints 0.8 (corrections note 20).

    Notes
    -----
    .. math:: f = \\frac{k\\,P\\,l_1^2 l_2^2}{E\\,l\\,(d^4 - \\delta^4)}

    References
    ----------
    Valve-train practical works (n.d.), work 7, eq. (7.3), with the coefficient corrected (corrections note 20).

    Examples
    --------
    Equals P l1^2 l2^2 / (3 E I l) with I = pi (d^4 - delta^4)/64:

    >>> P, a, b, d = 5000.0, 0.03, 0.05, 0.025
    >>> I = np.pi * d**4 / 64
    >>> bool(np.isclose(camshaft_deflection(P, a, b, d), P * a**2 * b**2 / (3 * 2.1e11 * I * (a + b))))
    True
    """
    return coefficient * force * l1**2 * l2**2 / (modulus * (l1 + l2) * (diameter**4 - bore**4))


def effective_modulus(e1, e2) -> float:
    """E_m = 2 E_1 E_2 / (E_1 + E_2) [Pa] (Shang Hanji (1988), eq. 2.5)."""
    return 2.0 * e1 * e2 / (e1 + e2)


def hertz_line_stress(force, width, curvature_sum, modulus) -> np.ndarray:
    """Hertz contact stress of two cylinders in line contact [Pa] (Hertz (1882)).

    Parameters
    ----------
    force : ndarray
        Contact force [N].
    width : float
        Contact (cam) width b [m].
    curvature_sum : ndarray
        1/rho_1 + 1/rho_2 [1/m] (1/rho_2 = 0 for a flat follower; a concave cam radius is negative).
    modulus : float
        Effective modulus E_m [Pa] (equal materials: E).

    Notes
    -----
    .. math:: \\sigma = 0.418\\sqrt{\\frac{F E_m}{b}\\left(\\frac1{\\rho_1} + \\frac1{\\rho_2}\\right)}

    0.418 = sqrt(1 / (2 pi (1 - mu^2))) with Poisson's ratio 0.3.

    References
    ----------
    Shang Hanji (1988), eqs. (2.4)-(2.5), (2.11); Valve-train practical works (n.d.), eqs. (7.4)-(7.5).
    """
    # in place: a new array per operation would have its pages faulted in afresh (0.2 ms each on a load map of 41
    # speeds x 2005 angles)
    stress = _clipped(force, curvature_sum)
    unloaded = ~(stress > 0.0)
    with np.errstate(invalid="ignore"):
        np.multiply(stress, np.clip(curvature_sum, 0.0, None), out=stress)
    # an unloaded point carries no stress, even where the profile has a cusp (infinite curvature: 0 x inf, replaced)
    np.copyto(stress, 0.0, where=unloaded)
    stress *= modulus
    stress /= width
    np.sqrt(stress, out=stress)
    stress *= HERTZ_LINE
    return stress if stress.ndim else stress[()]


def _clipped(force, other):
    """A new float array of the shape of ``force`` and ``other`` broadcast together: the force where positive, else
    0 [N]."""
    out = np.empty(np.broadcast_shapes(np.shape(force), np.shape(other)))
    return np.clip(force, 0.0, None, out=out)


def hertz_half_width(force, width, curvature_sum, modulus) -> np.ndarray:
    """Half-width of the Hertz contact band of two cylinders in line contact [m].

    Parameters
    ----------
    force : ndarray
        Contact force [N] (a force <= 0 gives no band).
    width : float
        Contact (cam) width b [m].
    curvature_sum : ndarray
        1/rho_1 + 1/rho_2 [1/m], > 0.
    modulus : float
        Effective modulus E_m [Pa] (equal materials: E).

    Notes
    -----
    The load is spread elliptically over the band, :math:`F/b = \\pi a \\sigma / 2`; with the stress of
    :func:`hertz_line_stress`,

    .. math:: a = \\frac{2F}{\\pi b \\sigma} = \\frac{2}{0.418\\pi}\\sqrt{\\frac{F}{b E_m (1/\\rho_1 + 1/\\rho_2)}}

    (Poisson's ratio 0.3), the same as :math:`a = \\sqrt{4 F R / (\\pi b E^*)}` with
    :math:`1/E^* = 2 (1 - \\mu^2) / E_m`.

    References
    ----------
    Johnson (1985), ch. 4 (two-dimensional Hertz contact);
    Shang Hanji (1988), section 2.1, eqs. (2.4)-(2.5).

    Examples
    --------
    A steel cylinder of 10 mm radius on a flat, 1000 N over 10 mm: a = 0.105 mm.

    >>> round(float(hertz_half_width(1000.0, 0.01, 100.0, 2.1e11)) * 1e3, 4)
    0.1051
    """
    half = _clipped(force, curvature_sum)     # in place, as in :func:`hertz_line_stress`
    np.divide(half, width * modulus * np.asarray(curvature_sum), out=half)
    np.sqrt(half, out=half)
    half *= 2.0 / (HERTZ_LINE * np.pi)
    return half if half.ndim else half[()]


def roller_side_force(axial_force, pressure_angle) -> np.ndarray:
    """Side (lateral) force of a roller follower on its guide, F_n sin(alpha) = F_a tan(alpha) [N].

    Parameters
    ----------
    axial_force : ndarray
        Force along the follower axis, P_T [N] (a force <= 0 gives none).
    pressure_angle : ndarray
        Pressure angle alpha between the contact normal and the follower axis [rad].

    Notes
    -----
    The contact normal carries :math:`F_n = F_a / \\cos\\alpha`; its component across the axis,
    :math:`F_s = F_n \\sin\\alpha = F_a \\tan\\alpha`, is taken by the follower guide.

    References
    ----------
    Norton (2009) (pressure angle and
    follower side load).

    Examples
    --------
    >>> round(float(roller_side_force(1000.0, np.radians(30.0))), 1)
    577.4
    """
    return np.clip(axial_force, 0.0, None) * np.tan(np.abs(pressure_angle))


def tappet_side_pressure(force, offset, tappet_diameter, guide_length) -> float:
    """Side pressure of a flat tappet in its guide, q = 6 P b / (d l^2) [Pa] (Valve-train practical works (n.d.), eqs. 7.6-7.7).

    ``offset`` b is the largest distance of the contact point from the tappet axis,
    max dh/dtheta for a flat tappet (= omega_T max / omega_cam).
    """
    return 6.0 * force * offset / (tappet_diameter * guide_length**2)


def second_moment(diameter, bore=0.0) -> float:
    """Second moment of area of a solid or tubular round section, pi (D^4 - d^4)/64 [m^4] (eqs. 7.9-7.10)."""
    return np.pi * (diameter**4 - bore**4) / 64.0


def euler_load(modulus, second_moment_area, length) -> float:
    """Euler critical load of a pin-ended strut, pi^2 E J / l^2 [N] (Valve-train practical works (n.d.), eq. 7.8).

    >>> round(euler_load(2.1e11, second_moment(0.008), 0.25) / 1e3, 2)  # 8 mm steel rod, 250 mm
    6.67
    """
    return np.pi**2 * modulus * second_moment_area / length**2


def sphere_socket_stress(force, modulus, ball_radius, socket_radius) -> float:
    """Contact stress of a ball in a concave socket, 0.388 (P E^2 (1/r1 - 1/r2)^2)^(1/3) [Pa] (Valve-train practical works (n.d.), 7.11/7.14)."""
    return 0.388 * np.cbrt(force * modulus**2 * (1.0 / ball_radius - 1.0 / socket_radius) ** 2)


def sphere_socket_verdict(check_name, force, modulus, ball_radius, socket_radius, note="") -> Check:
    """The :func:`verdict` of :func:`sphere_socket_stress` (``check_name`` of :data:`LIMITS`), unevaluated where the
    Hertz contact it assumes would be wider than the ball: a socket so close to the ball's radius that the formula's
    stress (towards 0 as r2 -> r1) cannot be the contact's.

    Notes
    -----
    Hertz's contact of spheres has the mean pressure P / (pi a^2) = 2/3 of its peak sigma, so its radius is
    a = sqrt(3 P / (2 pi sigma)) (Johnson (1985), section 4.2); a circle of a >= r1 does not fit on the ball.

    Examples
    --------
    2000 N on a 5 mm ball in a 6 mm socket: sigma = 1789 MPa, a = 0.73 mm, evaluated; in a 5.000001 mm socket the
    formula's 0.2 MPa would need a contact of 69 mm radius.

    >>> round(sphere_socket_verdict("ball_socket_stress", 2000.0, 2.1e11, 0.005, 0.006).value / 1e6)
    1789
    >>> sphere_socket_verdict("ball_socket_stress", 2000.0, 2.1e11, 0.005, 0.005000001).unevaluated
    "the socket conforms to the ball: Hertz's contact circle of 68.8 mm radius would be wider than the ball of 5 mm radius"
    """
    stress = sphere_socket_stress(force, modulus, ball_radius, socket_radius)
    contact = np.sqrt(3.0 * force / (2.0 * np.pi * stress))
    if contact < ball_radius:
        return verdict(check_name, stress, note)
    why = locale_note("strength.socket_conforms", contact_mm=contact * 1e3, ball_mm=ball_radius * 1e3)
    return verdict(check_name, float("nan"), note, NoteText(why))


def rocker_pad_stress(force, modulus, width, radius) -> float:
    """Contact stress of the rocker pad on the valve stem, 0.418 sqrt(P E / (b r)) [Pa] (Valve-train practical works (n.d.), eq. 7.13)."""
    return HERTZ_LINE * np.sqrt(force * modulus / (width * radius))


def section_modulus(diameter, bore=0.0) -> float:
    """Bending section modulus of a tube, W = pi (D^4 - d^4)/(32 D) [m^3] (Valve-train practical works (n.d.), eq. 7.16)."""
    return np.pi * (diameter**4 - bore**4) / (32.0 * diameter)


def rectangle_bending_stress(moment, width, height) -> float | np.ndarray:
    """Bending stress of a rectangular section, sigma = M / W, W = b h^2 / 6 [Pa], under the moment ``moment`` [N m],
    ``width`` b and ``height`` h [m] (h in the plane of bending).

    References
    ----------
    Shigley's Mechanical Engineering Design, 9th ed. (2011), the section on beams in bending (sigma = M c / I).

    >>> round(rectangle_bending_stress(10.0, 0.006, 0.008) / 1e6, 4)
    156.25
    """
    return 6.0 * moment / (width * height**2)


def rocker_shaft_stresses(force, span, rocker_width, diameter, bore=0.0) -> dict[str, float]:
    """Stresses of the rocker shaft under the rocker load [Pa].

    Returns
    -------
    dict
        ``bending`` P (l - b)/(8 W) (7.15, built-in beam, corrections note 48); ``bending_simply_supported``
        P (2l - b)/(8 W), the alternative reading; ``shear`` P / (2 f) (7.17) with f the
        cross-section area; ``bearing`` P / (b D) (7.18).

    Notes
    -----
    The manual loads the shaft with P_T max; the physical reaction is the vector sum of
    the pushrod and valve forces (corrections note 25), which the design notes but does not change.
    """
    w = section_modulus(diameter, bore)
    area = np.pi * (diameter**2 - bore**2) / 4.0
    return {"bending": force * (span - rocker_width) / (8.0 * w),
            "bending_simply_supported": force * (2.0 * span - rocker_width) / (8.0 * w),
            "shear": force / (2.0 * area), "bearing": force / (rocker_width * diameter)}
