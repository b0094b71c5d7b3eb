"""Design constraints as functions of a computed valve design, for cam synthesis by optimisation.

Each function takes a :class:`~valvetrain.design.valve.ValveDesign` (the typed stage results of
:func:`~valvetrain.design.valve.design_valve`) and limits, and returns a :class:`~valvetrain.checks.Check`:
value, bounds, unit, source and the relative :attr:`~valvetrain.checks.Check.margin` (>= 0 when the
constraint holds), so that an optimiser takes its constraints from the margins.  A constraint that
does not apply to the design (a pressure angle on a flat follower) returns None.
:func:`constraints` gathers the applicable ones for a :class:`Limits`, :func:`worst_margin` the
smallest margin.

All values are SI; ``unit`` names how they are shown.
"""

from dataclasses import dataclass
import math

import numpy as np

from .. import strength
from ..checks import Check, check
from ..locale import cited, note
from ..design.dynamics_checks import CHECK_SOURCE
from ..layouts import finger_inertia_force
from ..numerics import extremum
from ..units import DEG, MM

SOURCE_SYNTHESIS = "UkrSURT Proceedings (2019)"
SOURCE_CRITERIA = "Shang Hanji (1988), section 2.1"
SOURCE_MANUAL = "Valve-train practical works (n.d.)"


@dataclass(frozen=True)
class Limits:
    """The limits of a synthesis (SI); None switches a constraint off.

    Attributes
    ----------
    max_pressure_angle : float
        Largest pressure angle of a roller follower [rad] (30 deg: UkrSURT Proceedings (2019)).
    grinding_wheel_radius : float
        Radius of the grinding wheel [m]: a concave stretch of the profile must have |R| >= it
        (170 mm: UkrSURT Proceedings (2019)).
    min_spring_reserve : float
        Smallest ratio of spring force to the train's inertia force where the acceleration is negative
        (2.2: UkrSURT Proceedings (2019); 1.5-2.25: Valve-train practical works (n.d.), eq. 5.3).
    max_acceleration, min_acceleration : float
        Band of the tappet acceleration [m/s^2].
    max_contact_stress : float
        Allowable Hertz stress [Pa] (1200 MPa: Valve-train practical works (n.d.), eqs. 7.4-7.5).
    cam_width : float
        Contact width of cam and follower [m], needed for the Hertz stress.
    top_speed : float
        Highest engine speed over the rated speed up to which the contact stress is checked (from standstill).
    contact_modulus : float
        Effective modulus E_m [Pa] (steel on steel: E).
    min_rho : float
        Smallest convex profile radius of the cam [m], either follower (2 mm: Shang Hanji (1988), section 2.1).
    ramp_velocity : tuple
        Band of the tappet velocity analogue at the end of the ramp [m/rad] (0.008-0.022 mm/deg:
        Valve-train practical works (n.d.), eq. 2.1).
    seating_velocity : tuple
        Band of the valve's seating (and opening) velocity at the rated speed [m/s] (a configurable default
        of at most 0.5 m/s; no primary source states it).
    no_jump_factor : float
        No follower separation up to this multiple of the rated speed (needs the valve's ``[dynamics]`` sweep to
        reach it), a failure as the design grades a separation.

    The design's own failure checks (the valve-to-piston clearance among them) are not limits of this class: they are
    checked on the full design as ``valvetrain run`` grades them (:func:`valvetrain.synthesis.optimize.final_checks`),
    so that an optimum passes what ``run`` passes.
    """

    max_pressure_angle: float = 30.0 * DEG
    grinding_wheel_radius: float = None
    min_spring_reserve: float = 1.5
    max_acceleration: float = None
    min_acceleration: float = None
    max_contact_stress: float = strength.LIMITS["cam_contact_stress"][0]
    cam_width: float = None
    top_speed: float = 1.0
    contact_modulus: float = strength.STEEL_MODULUS
    min_rho: float = 2.0 * MM
    ramp_velocity: tuple = (0.008 * MM / DEG, 0.022 * MM / DEG)
    seating_velocity: tuple = (0.0, 0.5)
    no_jump_factor: float = None

    @classmethod
    def article(cls, **kw) -> "Limits":
        """The limits of the 26/27 diesel of UkrSURT Proceedings (2019): pressure angle <= 30 deg, concave radius
        <= -170 mm, spring reserve >= 2.2 (its ramp ends at 6 mm/rad, outside the band of
        Valve-train practical works (n.d.), which is switched off)."""
        base = dict(max_pressure_angle=30.0 * DEG, grinding_wheel_radius=170.0 * MM, min_spring_reserve=2.2,
                    ramp_velocity=None)
        return cls(**{**base, **kw})


def pressure_angle(design, limit) -> Check | None:
    """Largest pressure angle of a roller follower against ``limit`` [rad]; None for a flat follower.

    References
    ----------
    Shang Hanji (1988), section 2.1; UkrSURT Proceedings (2019) (beta_max <= 30 deg).
    """
    limited = design.follower_model.limited_contact(design.profile.contact)
    if limited is None:
        return None
    return check("profile.pressure_angle.max", limited[0], high=limit, unit="deg",
                 source=SOURCE_SYNTHESIS, severity="failure")


def concave_radius(design, wheel_radius) -> Check | None:
    """The grinding wheel against the concave stretches of a roller follower's cam: wheel radius / |R_min| <= 1.

    Parameters
    ----------
    wheel_radius : float
        Grinding wheel radius [m].

    Returns
    -------
    Check or None
        The ratio (0 where the profile has no concave stretch, so the margin is continuous); None for a flat
        follower, whose cam has no concave stretch that is not an undercut.

    Notes
    -----
    R_min is the concave profile radius closest to zero (Shang Hanji (1988), eq. 2.7); the wheel fits into the
    concave stretch when |R_min| >= its radius, UkrSURT Proceedings (2019) (R_min <= -170 mm).
    """
    limited = design.follower_model.limited_contact(design.profile.contact)
    if limited is None:
        return None
    radius = limited[1]
    ratio = 0.0 if radius is None else wheel_radius / abs(radius)
    return check("synthesis.concave_radius", ratio, high=1.0, source=SOURCE_SYNTHESIS,
                 severity="failure", note=note("synthesis.no_concave_stretch") if radius is None else "")


def spring_reserve_value(design, preload=None, rate=None) -> float:
    """Smallest ratio of the spring force to the train's inertia force where the valve decelerates.

    Parameters
    ----------
    design : ValveDesign
    preload, rate : float, optional
        A spring of the caller's own at the valve [N, N/m]; default the design's chosen spring.

    Returns
    -------
    float
        min over the open event with j_v < 0 of (P_0 + C y) / (m_v |j_v|); +inf if the valve never decelerates.

    Notes
    -----
    k_зп = min (P_0 + C (S - S_b)) / (M omega^2 |a|) (UkrSURT Proceedings (2019); Valve-train practical works
    (n.d.), eq. 5.3 for the reserve K_z).
    """
    drive = design.drive
    line = drive.lines.chosen
    force = line.force(drive.lift) if preload is None else preload + rate * drive.lift
    inertia = drive.inertia_force
    loaded = inertia > 0.0
    if not np.any(loaded):
        return math.inf
    return float(np.min(force[loaded] / inertia[loaded]))


def spring_reserve(design, low, preload=None, rate=None) -> Check:
    """:func:`spring_reserve_value` against the smallest reserve ``low``."""
    return check("synthesis.spring_reserve", spring_reserve_value(design, preload, rate), low=low,
                 source=SOURCE_SYNTHESIS, severity="failure")


def acceleration_band(design, low=None, high=None) -> list[Check]:
    """Largest and smallest tappet acceleration at the rated speed against a band [m/s^2]: two checks (a finger's:
    its roller's, :meth:`~valvetrain.followers.Follower.acceleration_range`, as the design grades it)."""
    smallest, largest = design.cam.follower_model.acceleration_range(design.cam)
    out = []
    if high is not None:
        out.append(check("tappet_acceleration.max", largest, high=high, unit="m/s2", source=SOURCE_MANUAL))
    if low is not None:
        out.append(check("tappet_acceleration.min", smallest, low=low, unit="m/s2", source=SOURCE_MANUAL))
    return out


def worst_cam_force(spring_force, mass, rocker_ratio, top_acceleration, finger=0.0) -> np.ndarray:
    """The largest cam force over the engine speeds from standstill up to a top speed [N].

    Parameters
    ----------
    spring_force : ndarray
        Spring force at the valve [N].
    mass : float
        Mass of the train reduced to the valve [kg].
    rocker_ratio : float
        i_k.
    top_acceleration : ndarray
        Tappet acceleration at the top speed [m/s^2].
    finger : ndarray or float
        What a finger's inertia by its variable ratio adds at the valve at the top speed [N]
        (:func:`~valvetrain.layouts.finger_inertia_force` times omega^2; 0 for another follower).

    Notes
    -----
    P_T = i_k (P_spr + m_v i_k j) (Valve-train practical works (n.d.), eq. 7.1) is linear in omega^2: its largest
    value over the speeds is the standstill's (j = 0) where the tappet decelerates and the top speed's where it
    accelerates (a finger's inertia force by its variable ratio counted with m_v i_k j).
    """
    return strength.cam_force(spring_force, np.clip(mass * rocker_ratio * top_acceleration + finger, 0.0, None),
                              rocker_ratio)


def contact_stress_value(design, width, modulus=strength.STEEL_MODULUS, top=1.0, valve=None) -> float | np.ndarray:
    """Largest Hertz stress between cam and follower along the open event [Pa], refined on the contour.

    Parameters
    ----------
    design : ValveDesign
    width : float
        Contact (cam) width [m].
    modulus : float
        Effective modulus E_m [Pa].
    top : float
        Highest engine speed over the rated speed: the stress is the largest from standstill up to it.
    valve : SI view of the valve, optional
        With it a finger's inertia by its variable ratio counts in the force
        (:func:`~valvetrain.layouts.finger_inertia_force`).

    Notes
    -----
    The cam force of :func:`worst_cam_force` with the design's chosen spring, carried to the cam by the follower
    (:meth:`~valvetrain.followers.Follower.force_ratio`: a finger's cam carries G / (L_r cos beta) of the force at
    the valve, Norton (2009)), and the instantaneous profile radius at each camshaft angle of the open event
    (:meth:`valvetrain.followers.Follower.contact_stress`; Shang Hanji (1988), eqs. 2.4-2.5); its largest value
    is refined between the samples of each piece of the law (:func:`valvetrain.numerics.extremum`), so that a sharp
    nose between the table's angles is not missed.
    """
    law, cam, drive = design.law, design.cam, design.drive
    line, omega, follower = drive.lines.chosen, cam.cam_speed * top, cam.follower_model

    def stress(theta):
        h, dh, d2h, _ = law.derivatives(theta)
        finger = 0.0 if valve is None else omega**2 * finger_inertia_force(valve, cam.heel_radius, h, dh, d2h)
        force = worst_cam_force(line.force(cam.valve_lift(theta)), drive.masses.at_valve, cam.rocker_ratio,
                                omega**2 * d2h, finger) * follower.force_ratio(cam.heel_radius, h, dh)
        return follower.contact_stress(force, law.curvature(theta, cam.heel_radius, follower), width, modulus)

    bp = law.breakpoints
    edges = np.unique(np.concatenate([[law.valve_opens], bp[(bp > law.valve_opens) & (bp < law.valve_closes)],
                                      [law.valve_closes]]))
    return extremum(stress, edges, "max")[1]


def contact_stress(design, high, width, modulus=strength.STEEL_MODULUS, top=1.0, valve=None) -> Check:
    """:func:`contact_stress_value` against the allowable ``high`` [Pa]."""
    return check("synthesis.contact_stress", contact_stress_value(design, width, modulus, top, valve), high=high,
                 unit="MPa",
                 source=SOURCE_MANUAL + ", eqs. (7.4)-(7.5)", severity="failure",
                 note=note("synthesis.cam_width", width_mm=width / MM, top=top))


def rho_min(design, low) -> Check:
    """Smallest convex profile radius of the cam against ``low`` [m], refined on the contour (the profile stage's).

    A roller follower's cam needs it as a flat follower's does: at a radius near zero the cam is pointed (and at zero
    or less undercut), whatever the roller.

    References
    ----------
    Shang Hanji (1988), section 2.1 (rho_min >= 2 mm).
    """
    return check("profile.rho_min", design.profile.rho_min, low=low, unit="mm", source=SOURCE_CRITERIA,
                 severity="failure")


def ramp_velocity(design, band) -> Check | None:
    """Tappet velocity analogue at the end of the ramp dh/dphi [m/rad] against ``band`` (shown in mm/deg);
    None for a law without a ramp."""
    law = design.law
    if law.ramp_angle <= 0.0:
        return None
    v = float(abs(law.derivatives(np.array([law.valve_opens]))[1][0]))
    return check("ramp.end_velocity", v, *band, unit="mm/deg", source=SOURCE_MANUAL + ", eq. (2.1)")


def seating_velocity(design, band) -> Check:
    """The valve's seating velocity at the rated speed against ``band`` [m/s] (a configurable default)."""
    return check("synthesis.seating_velocity", design.cam.seating_velocity, *band, unit="m/s",
                 source=cited(note("source.configurable_default")))


def no_jump(design, factor) -> Check | None:
    """No follower separation up to ``factor`` x the rated speed, from the design's ``[dynamics]`` speed sweep.

    Returns
    -------
    Check or None
        The lowest engine speed with separation over the rated speed, low = ``factor``; without separation in the
        sweep, the top of the swept range over the rated speed (noted).  None when the valve has no
        ``[dynamics]`` section (no sweep was run).

    References
    ----------
    Shang Hanji (1988), chapter 3 (the dynamic jump criterion); the 1-DOF or multi-mass train of
    :mod:`valvetrain.design.dynamics`.
    """
    d = design.dynamics
    if d is None:
        return None
    rated = d.at_rated_speed.speed
    jumps = np.isfinite(d.jump_speed)
    value = (d.jump_speed if jumps else d.speed_range[1]) / rated
    return check("dynamics.jump_speed", value, low=factor, severity="failure",
                 source=cited(note("source.no_separation_factor", work=CHECK_SOURCE, factor=factor)),
                 note="" if jumps else note("synthesis.swept_top"))


def constraints(design, limits=Limits(), valve=None) -> list[Check]:
    """Every constraint of ``limits`` that applies to ``design``: a list of :class:`~valvetrain.checks.Check`
    (``valve``, the valve's SI view: a finger's inertia by its variable ratio in the contact stress,
    :func:`contact_stress_value`).

    Examples
    --------
    >>> from valvetrain.synthesis.constraints import Limits
    >>> sorted(f.name for f in __import__("dataclasses").fields(Limits))[:3]
    ['cam_width', 'contact_modulus', 'grinding_wheel_radius']
    """
    L = limits
    out = acceleration_band(design, L.min_acceleration, L.max_acceleration)
    if L.cam_width is not None and L.max_contact_stress is not None:
        out.append(contact_stress(design, L.max_contact_stress, L.cam_width, L.contact_modulus, L.top_speed, valve))
    for key, constraint in SINGLE_LIMITS:
        if getattr(L, key) is not None:
            out.append(constraint(design, getattr(L, key)))
    return [c for c in out if c is not None]


def worst_margin(checks) -> float:
    """The smallest :attr:`~valvetrain.checks.Check.margin` of ``checks`` (+inf for none)."""
    return min((c.margin for c in checks), default=math.inf)


SINGLE_LIMITS = (("max_pressure_angle", pressure_angle), ("grinding_wheel_radius", concave_radius),
                 ("min_spring_reserve", spring_reserve), ("min_rho", rho_min), ("ramp_velocity", ramp_velocity),
                 ("seating_velocity", seating_velocity), ("no_jump_factor", no_jump))
"""The limits of :class:`Limits` that one constraint function checks alone: (field, function)."""
