"""Valve flow sections, conditional gas velocities, time-area and fullness.

Valve-train practical works (n.d.), works 1 and 4; Shang Hanji (1988), section 2.1, eqs. (2.1)-(2.3).  SI units:
lengths in m, areas in m^2, time-area in m^2*s, velocities in m/s, angles in rad.
"""

import numpy as np

from .checks import Check, check
from .locale import cited, note
from .numerics import cumulative_integral, integrals

THROAT_TO_BORE_RANGES = {
    "side_valve": (0.38, 0.42),
    "overhead": (0.35, 0.52),
    "prechamber_diesel": (0.35, 0.40),
    "direct_injection_diesel": (0.38, 0.42),
    "wedge": (0.42, 0.46),
    "hemispherical": (0.46, 0.52),
}
"""Recommended inlet throat diameter / bore by combustion-chamber layout (Valve-train practical works (n.d.), work 1)."""

THROAT_VELOCITY_RANGE = {"intake": (50.0, 80.0), "exhaust": (70.0, 100.0)}
"""Recommended V' in m/s (Valve-train practical works (n.d.), work 1, eq. 1.1)."""

CURTAIN_VELOCITY_RANGE = {"intake": (80.0, 95.0)}
"""Recommended V'' in m/s for the inlet valve (Valve-train practical works (n.d.), work 1, eq. 1.2)."""

TIME_AREA_VELOCITY_RANGE = {"si": (90.0, 150.0), "diesel": (80.0, 120.0)}
"""Recommended V''' of the inlet valve in m/s (Valve-train practical works (n.d.), work 1, eq. 1.4)."""

MEAN_CHARGE_VELOCITY_RANGE = {"si": (90.0, 150.0), "diesel": (80.0, 120.0), "si_injected": (100.0, 170.0)}
"""Recommended mean charge velocity v_vp in m/s (Valve-train practical works (n.d.), work 4, eq. 4.3)."""

LIFT_TO_THROAT_RANGE = (0.18, 0.30)
"""Recommended valve lift / throat diameter (Valve-train practical works (n.d.), work 2, automotive; work 1 gives 0.23-0.30, corrections note 17)."""


def circle_area(diameter) -> float | np.ndarray:
    """Area of a circle of the given diameter, pi d^2 / 4 [m^2] (piston area F_p, throat area f_g)."""
    return np.pi * np.asarray(diameter) ** 2 / 4.0


def mean_piston_speed(stroke, speed_rpm) -> float:
    """Mean piston speed c_p = S n / 30 [m/s], stroke in m, speed in min^-1 (Valve-train practical works (n.d.), appendix)."""
    return stroke * speed_rpm / 30.0


def swept_volume(bore, stroke) -> float:
    """Swept volume of one cylinder V_h = pi D^2 S / 4 [m^3]."""
    return circle_area(bore) * stroke


def curtain_area(lift, throat_diameter, seat_angle) -> float | np.ndarray:
    """Valve curtain (flow) area as the lateral area of the frustum.

    Parameters
    ----------
    lift : array_like
        Valve lift y [m]; negative values (valve closed) give zero area.
    throat_diameter : float
        Throat diameter d [m].
    seat_angle : float
        Seat (facet) angle measured from the valve face plane [rad] (30 or 45 deg).

    Returns
    -------
    ndarray
        Curtain area [m^2].

    Notes
    -----
    .. math:: f = \\pi y\\,(d\\cos\\varphi + y\\sin\\varphi\\cos^2\\varphi)

    References
    ----------
    Valve-train practical works (n.d.), work 1, eq. (1.3); Shang Hanji (1988), eq. (2.1).

    Examples
    --------
    The appendix valve of Valve-train practical works (n.d.) (d = 36.8 mm, 45 deg, 10 mm lift): 928.56 mm^2.

    >>> round(float(curtain_area(0.010, 0.0368, np.pi / 4)) * 1e6, 2)
    928.56
    """
    y = np.clip(np.asarray(lift, dtype=float), 0.0, None)
    c = np.cos(seat_angle)
    return np.pi * y * (throat_diameter * c + y * np.sin(seat_angle) * c * c)


def throat_velocity(piston_speed, bore, throat_diameter, count) -> float:
    """First conditional gas velocity in the throat, V' = c_p F_p / (i f_g) [m/s].

    Parameters
    ----------
    piston_speed : float
        Mean piston speed c_p [m/s].
    bore : float
        Cylinder bore D [m].
    throat_diameter : float
        Throat diameter d_g [m].
    count : int
        Number of same-name valves per cylinder i.

    References
    ----------
    Valve-train practical works (n.d.), work 1, eq. (1.1).

    Examples
    --------
    The appendix of Valve-train practical works (n.d.): 85.07 m/s.

    >>> round(throat_velocity(18.0, 0.080, 0.0368, 1), 2)
    85.07
    """
    return float(piston_speed * circle_area(bore) / (count * circle_area(throat_diameter)))


def curtain_velocity(piston_speed, bore, max_curtain_area, count) -> float:
    """Second conditional gas velocity at full lift, V'' = c_p F_p / (i f_max) [m/s].

    References
    ----------
    Valve-train practical works (n.d.), work 1, eq. (1.2).

    Examples
    --------
    The appendix of Valve-train practical works (n.d.) with the geometric curtain area 928.56 mm^2: 97.44 m/s (corrections note 7).

    >>> round(curtain_velocity(18.0, 0.080, 928.56e-6, 1), 2)
    97.44
    """
    return float(piston_speed * circle_area(bore) / (count * max_curtain_area))


def time_area_velocity(swept, time_area, count) -> float:
    """Third conditional gas velocity V''' = V_h / (i * integral f dt) [m/s].

    Parameters
    ----------
    swept : float
        Swept volume V_h [m^3].
    time_area : float
        Time-area of one valve over the intake stroke (TDC to BDC) [m^2*s].
    count : int
        Number of same-name valves per cylinder i.

    References
    ----------
    Valve-train practical works (n.d.), work 1, eq. (1.4) (t1 = TDC, t2 = BDC; the integration is over time,
    corrections note 51).

    Examples
    --------
    The appendix of Valve-train practical works (n.d.): 2.8564 mm^2 s gives 135.75 m/s.

    >>> round(time_area_velocity(3.8776e-4, 2.8564e-6, 1), 1)
    135.8
    """
    return float(swept / (count * time_area))


def mean_charge_velocity(swept, time_area, count=1) -> float:
    """Mean charge velocity from the time-area, v_vp = V_h / (i integral F dt) [m/s].

    Parameters
    ----------
    swept : float
        Swept volume V_h [m^3].
    time_area : float
        Time-area of one valve [m^2*s].
    count : int
        Number of same-name valves per cylinder i: the charge flows through all of them.

    Notes
    -----
    The manual's work 4 is written for one valve per cylinder and does not divide by i (corrections
    note 29); with i valves the charge passes through i curtains, so the time-area is
    i times that of one valve, as in V''' of work 1.

    References
    ----------
    Valve-train practical works (n.d.), work 4, eq. (4.3).

    Examples
    --------
    Two valves halve the velocity of one:

    >>> round(mean_charge_velocity(3.8776e-4, 1.5e-6, 2) * 2 - mean_charge_velocity(3.8776e-4, 1.5e-6), 9)
    0.0
    """
    return float(swept / (count * time_area))


def cumulative_time_area(area, cam_angle, cam_speed, breakpoints=()) -> np.ndarray:
    """Running time-area of a valve, integral of f dt with dt = d(cam angle) / omega_cam.

    Parameters
    ----------
    area : callable
        ``area(cam_angle) -> curtain area [m^2]``, vectorised.
    cam_angle : array_like
        Increasing camshaft angles [rad] at which the running value is wanted.
    cam_speed : float
        Camshaft angular velocity omega_cam [rad/s].
    breakpoints : array_like
        Camshaft angles [rad] where the lift law changes segment.

    Returns
    -------
    ndarray
        Running time-area [m^2*s], zero at ``cam_angle[0]``.

    Notes
    -----
    .. math:: Z(\\varphi) = \\frac{1}{\\omega_{cam}}\\int_{\\varphi_0}^{\\varphi} f(\\varphi')\\,d\\varphi'

    The integral is evaluated with Gauss-Legendre quadrature between the segment
    junctions of the analytic lift law, which replaces the graphical evaluation
    M_t M_F F_ABCD of eq. (4.2) (that linearises the curtain area, see corrections note 29).

    References
    ----------
    Valve-train practical works (n.d.), work 4, eq. (4.1); Shang Hanji (1988), eq. (2.2).
    """
    return cumulative_integral(area, cam_angle, breakpoints) / cam_speed


def time_area(area, start, end, cam_speed, breakpoints=()) -> float:
    """Time-area integral of f dt between two camshaft angles [m^2*s] (Valve-train practical works (n.d.), eq. 4.1)."""
    return float(time_areas(lambda x, _: area(x), [start], [end], cam_speed, [breakpoints])[0])


def time_areas(area, starts, ends, cam_speed, breakpoints) -> np.ndarray:
    """Time-areas of several valves at once, each between its own camshaft angles [m^2*s] (:func:`time_area`).

    Parameters
    ----------
    area : callable
        ``area(cam_angle, member) -> curtain area [m^2]`` of valve ``member[k]`` at ``cam_angle[k]``.
    starts, ends : array_like
        Camshaft angles [rad] between which each valve's time-area is taken, shape (n,).
    cam_speed : float
        Camshaft angular velocity omega_cam [rad/s].
    breakpoints : sequence of array_like
        Each valve's segment junctions [rad].

    Returns
    -------
    ndarray
        Shape (n,) [m^2*s]: the quadrature of :func:`cumulative_time_area` for each valve, all nodes in one call.
    """
    return integrals(area, starts, ends, breakpoints) / cam_speed


def fullness(lift, start, end, max_lift, breakpoints=()) -> float:
    """Fullness (filling) coefficient of a lift diagram.

    Parameters
    ----------
    lift : callable
        ``lift(angle) -> valve lift [m]``, vectorised.
    start, end : float
        Angles [rad] where the valve opens and closes.
    max_lift : float
        Maximum valve lift [m].
    breakpoints : array_like
        Angles where the law changes segment.

    Returns
    -------
    float
        xi, the ratio of the area under the lift curve to the circumscribed rectangle.

    Notes
    -----
    .. math:: \\xi = \\frac{\\int_a^{\\alpha_a} y\\,d\\alpha}{y_{max}(\\alpha_a - a)}

    References
    ----------
    Shang Hanji (1988), section 2.1, eq. (2.3).

    Examples
    --------
    A half-sine lift has fullness 2/pi.

    >>> round(fullness(np.sin, 0.0, np.pi, 1.0), 6)
    0.63662
    """
    return float(fullnesses(lambda x, _: lift(x), [start], [end], [max_lift], [breakpoints])[0])


def fullnesses(lift, starts, ends, max_lifts, breakpoints) -> np.ndarray:
    """Fullness coefficients of several lift diagrams at once (:func:`fullness`).

    Parameters
    ----------
    lift : callable
        ``lift(angle, member) -> valve lift [m]`` of diagram ``member[k]`` at ``angle[k]``.
    starts, ends : array_like
        Angles [rad] where each valve opens and closes, shape (n,).
    max_lifts : array_like
        Maximum valve lift of each [m].
    breakpoints : sequence of array_like
        Each diagram's angles where its law changes segment.

    Returns
    -------
    ndarray
        Shape (n,): xi of each diagram, its area by the quadrature of :func:`fullness` (all nodes in one call).
    """
    starts, ends = np.asarray(starts, dtype=float), np.asarray(ends, dtype=float)
    return integrals(lift, starts, ends, breakpoints) / (np.asarray(max_lifts, dtype=float) * (ends - starts))


def check_flow(kind, *, bore, throat_diameter, max_lift, v1, v2, v3, charge_velocity, engine_type, chamber, count=1) -> list[Check]:
    """Compare a valve's flow figures with the recommended ranges of Valve-train practical works (n.d.), works 1 and 4.

    Parameters
    ----------
    kind : {"intake", "exhaust"}
        Valve kind; the velocity ranges of the sources differ.
    bore, throat_diameter, max_lift : float
        Bore, throat diameter and valve lift [m].
    v1, v2, v3, charge_velocity : float
        V', V'', V''' and v_vp [m/s].
    engine_type : {"si", "si_injected", "diesel"}
        Selects the V''' and v_vp ranges.
    chamber : str
        Key of :data:`THROAT_TO_BORE_RANGES` for the throat/bore range.
    count : int
        Same-name valves per cylinder i.

    Returns
    -------
    list of Check
        Every check, passed or not.

    Notes
    -----
    The throat/bore ranges of Valve-train practical works (n.d.) are stated for one inlet valve.  With i valves the
    total throat area is compared: the equivalent diameter sqrt(i) d of one valve of the same
    area (this project's reading for multi-valve heads).
    """
    out = []
    if kind == "intake":
        code = "flow.throat_to_bore" if count == 1 else "flow.equivalent_throat_to_bore"
        out.append(check(code, np.sqrt(count) * throat_diameter / bore, *THROAT_TO_BORE_RANGES[chamber],
                         source=cited(note("source.chamber", work="Valve-train practical works (n.d.), work 1", chamber=chamber)),
                         params={} if count == 1 else {"count": count}))
    out.append(check("flow.lift_to_throat", max_lift / throat_diameter, *LIFT_TO_THROAT_RANGE,
                     source=cited(note("source.automotive", work="Valve-train practical works (n.d.), work 2"))))
    out.append(check("flow.throat_velocity", v1, *THROAT_VELOCITY_RANGE[kind], source="Valve-train practical works (n.d.), work 1, eq. (1.1)",
                     unit="m/s"))
    if kind == "intake":
        out.append(check("flow.curtain_velocity", v2, *CURTAIN_VELOCITY_RANGE[kind],
                         source="Valve-train practical works (n.d.), work 1, eq. (1.2)", unit="m/s"))
        v3_range = TIME_AREA_VELOCITY_RANGE["diesel" if engine_type == "diesel" else "si"]
        out.append(check("flow.time_area_velocity", v3, *v3_range, source="Valve-train practical works (n.d.), work 1, eq. (1.4)", unit="m/s"))
        out.append(check("flow.charge_velocity", charge_velocity, *MEAN_CHARGE_VELOCITY_RANGE[engine_type],
                         source="Valve-train practical works (n.d.), work 4, eq. (4.3)", unit="m/s"))
    return out
