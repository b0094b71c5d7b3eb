"""Strength stage of a valve design: the loads of the drive parts over the engine speeds from the lowest to the
over-speed, the quasi-static force or the dynamics stage's contact force where it ran, and the strength checks at
each part's worst speed and cam angle (Valve-train practical works (n.d.), work 7; Shang Hanji (1988); Norton
(2009)).

:func:`strength_stage` takes the SI inputs, the law stage's cam and the drive stage's masses and springs
(:mod:`valvetrain.design.drive`) to a :class:`StrengthResult` and its checks; :func:`event_load_maps` and
:func:`contact_loads` give the loads of the cam contact to the stages that need them (lubrication, lash adjuster,
camshaft).
"""

from dataclasses import dataclass, replace
from typing import Any, Optional

import numpy as np

from .. import flow, strength
from ..checks import Check, check
from ..locale import NoteText, cited, note
from ..layouts import chain, finger_inertia, unused_part_checks
from ..links import Loads
from ..numerics import TIE_RTOL, first_largest
from ..specification.si import si_name
from ..units import to_display
from .dynamics import SPEED_RANGE
from .results import quantity


SHANG_2_1 = "Shang Hanji (1988), section 2.1"
NORTON = "Norton (2009)"
WORKS_7_1 = "Valve-train practical works (n.d.), work 7, eq. (7.1)"

IDLE_SPEED_RATIO = SPEED_RANGE[0]
"""Lowest speed of the strength checks as a fraction of the rated speed where neither ``[engine] idle_speed_rpm`` nor
a ``[dynamics]`` section gives one: the dynamics stage's default idle, 0.1.  At or below the idle of engines (700 rpm
idle for 7000 rpm rated is 0.1), and low enough that the inertia of the train is 1 % of its rated value: the spring
alone loads the nose, the worst case of the spring-dominated checks (Valve-train practical works (n.d.), eq. (7.1))."""

STRENGTH_SPEEDS = 41
"""Engine speeds of the quasi-static strength checks, evenly spaced over the range (the rated speed added): the
quasi-static force is linear in the square of the speed, so its extremes at every angle lie at the ends of the
range; the speeds between give the per-speed table."""

LOWEST_SPEED_SOURCES = (NoteText(note("strength.lowest_idle_given")), NoteText(note("strength.lowest_swept")),
                        NoteText(note("strength.lowest_default_idle", ratio=IDLE_SPEED_RATIO)))
"""Where the lowest speed of the strength checks comes from (:func:`strength_speed_range`)."""


@dataclass(frozen=True)
class StrengthPerSpeed:
    """The largest cam force and contact stress at each engine speed of the strength checks (SI)."""

    speed: tuple[float, ...] = quantity("speed_rpm", "rpm", "engine speed")
    load: tuple[str, ...] = quantity("load", label="the cam force at that speed: quasi-static or dynamic")
    cam_force_max: tuple[float, ...] = quantity("cam_force_max_N", "N", "largest cam force")
    cam_force_max_angle: tuple[float, ...] = quantity("cam_force_max_cam_deg", "cam deg", "where, from the nose")
    contact_stress: Optional[tuple[float, ...]] = quantity("cam_contact_stress_MPa", "MPa", "largest Hertz stress "
                                                           "of the cam contact", omit_none=True)
    contact_stress_angle: Optional[tuple[float, ...]] = quantity("cam_contact_stress_cam_deg", "cam deg",
                                                                 "where, from the nose", omit_none=True)


@dataclass(frozen=True)
class FingerLoads:
    """The largest loads of a finger follower over the speed range (:meth:`valvetrain.followers.PivotedFollower.loads`;
    Norton (2009))."""

    roller_load_max: float = quantity("finger_roller_load_max_N", "N", "largest load on the roller and its bearing")
    pivot_load_max: float = quantity("finger_pivot_load_max_N", "N", "largest load on the pivot (the lash adjuster)")
    bending_moment_max: float = quantity("finger_bending_moment_max_Nm", "N m",
                                         "largest bending moment of the finger at its critical section")
    bending_stress_max: Optional[float] = quantity("finger_bending_stress_max_MPa", "MPa", "largest bending stress of "
                                                   "the finger at its critical section", omit_none=True, default=None)


@dataclass(frozen=True)
class StrengthResult:
    """The cam load over the speed range and the strength checks of the drive parts at their worst (Valve-train
    practical works (n.d.), work 7)."""

    speed_range: tuple[float, ...] = quantity("speed_range_rpm", "rpm", "engine speeds checked: the lowest to the "
                                              "over-speed")
    lowest_speed_source: str = quantity("lowest_speed_source", label="where the lowest speed comes from")
    cam_force_max: float = quantity("cam_force_max_N", "N", "largest force between cam and follower P_T max")
    cam_force_max_angle: float = quantity("cam_force_max_cam_deg", "cam deg", "where the cam force is largest")
    cam_force_max_speed: float = quantity("cam_force_max_speed_rpm", "rpm", "engine speed of the largest cam force")
    valve_force_max: float = quantity("valve_force_max_N", "N", "P_T max / i_k")
    gas_force_at_opening: float = quantity("gas_force_at_opening_N", "N", "gas force on the exhaust valve head at "
                                           "opening (eq. 7.1)")
    contact_stress_angle: Optional[float] = quantity("cam_contact_stress_cam_deg", "cam deg",
                                                     "where the contact stress is largest", omit_none=True)
    contact_stress_speed: Optional[float] = quantity("cam_contact_stress_speed_rpm", "rpm",
                                                     "engine speed of the largest contact stress", omit_none=True)
    side_force_max: Optional[float] = quantity("roller_side_force_max_N", "N", "largest side force of the roller "
                                               "follower on its guide, P_T tan(alpha)", omit_none=True)
    side_force_angle: Optional[float] = quantity("roller_side_force_cam_deg", "cam deg",
                                                 "where the side force is largest", omit_none=True)
    side_force_speed: Optional[float] = quantity("roller_side_force_speed_rpm", "rpm",
                                                 "engine speed of the largest side force", omit_none=True)
    per_speed: StrengthPerSpeed = quantity("per_speed", label="the largest cam force and contact stress at each speed")
    checks: tuple[Check, ...] = ()     # the strength checks (quantity with underscores)
    not_checked: tuple[str, ...] = ()  # the checks whose parts are not given, each with the keys missing
    rated_speed: float = 0.0       # the engine's rated speed [rad/s] (for the plot)
    finger: Optional[FingerLoads] = quantity("finger", flatten=True, default=None)
    contact_force: Optional[float] = quantity("cam_contact_force_N", "N", "cam force where the contact stress is "
                                              "largest", omit_none=True, default=None)


@dataclass(frozen=True)
class LoadMap:
    """The force between cam and follower over engine speeds x camshaft angles (SI)."""

    kind: str                      # "quasi-static" or "dynamic"
    speeds: np.ndarray             # engine speeds [rad/s], (S,)
    theta: np.ndarray              # camshaft angles [rad from the nose], (n,)
    force: np.ndarray              # force at the cam [N], (S, n)


@dataclass(frozen=True)
class Worst:
    """The largest value of a quantity over the load maps, and where: engine speed [rad/s], cam angle [rad]; the cam
    force there [N]."""

    value: float
    speed: float
    angle: float
    kind: str
    force: float




def strength_speed_range(engine, swept=None) -> tuple[float, float, str]:
    """The engine speeds the strength is checked over [rad/s]: the lowest, the highest and where the lowest comes from.

    The highest is the over-speed, ``[engine] over_speed_ratio`` x the rated speed.  The lowest is ``[engine]
    idle_speed_rpm``; without it the low end of ``swept``, the valve's ``[dynamics]`` speed range (low, high)
    [rad/s], else :data:`IDLE_SPEED_RATIO` x the rated speed (the dynamics stage's default idle).  Never above the
    rated speed.
    """
    if engine.idle_speed is not None:
        low, source = engine.idle_speed, LOWEST_SPEED_SOURCES[0]
    elif swept is not None:
        low, source = swept[0], LOWEST_SPEED_SOURCES[1]
    else:
        low, source = IDLE_SPEED_RATIO * engine.rated_speed, LOWEST_SPEED_SOURCES[2]
    return min(low, engine.rated_speed), engine.over_speed_ratio * engine.rated_speed, source


def quasi_static_loads(law, rocker_ratio, theta, spring_force, mass, speeds, to_cam, finger=0.0) -> LoadMap:
    """The quasi-static cam force over engine speeds x camshaft angles, :class:`LoadMap`.

    Parameters
    ----------
    law : LiftLaw
    rocker_ratio : float
        i_k.
    theta : ndarray (n,)
        Camshaft angles of the open event [rad from the nose].
    spring_force : ndarray (n,)
        Spring force at the valve at those angles [N].
    mass : float
        Reduced mass at the valve m_v [kg].
    finger : ndarray (n,) or float
        What a finger's inertia by its variable ratio adds at those angles per camshaft speed squared
        [N s^2/rad^2] (:func:`~valvetrain.layouts.finger_inertia`).
    speeds : ndarray (S,)
        Engine speeds [rad/s].
    to_cam : float
        Camshaft per crank revolution (1/2 for a four-stroke).

    Notes
    -----
    :math:`P_T(n, \\theta) = i_k\\,(P_{spr}(\\theta) + m_v\\,i_k\\,\\omega_{cam}(n)^2\\,h''(\\theta))`, (7.1) at every
    speed (and a finger's ``finger`` omega_cam^2 at the valve, its inertia by its variable ratio): the inertia of the
    rigid train grows with the square of the speed, so the spring carries the nose alone at low speed.

    References
    ----------
    Valve-train practical works (n.d.), work 7, eqs. (7.1)-(7.2).
    """
    omega = np.asarray(speeds, dtype=float)[:, None] * to_cam
    inertia = mass * rocker_ratio * omega**2 * law.derivatives(theta)[2]
    inertia += omega**2 * finger     # in place: a load map's array is large (strength.hertz_line_stress)
    force = strength.cam_force(spring_force, inertia, rocker_ratio)
    return LoadMap("quasi-static", np.asarray(speeds, dtype=float), theta, force)


def dynamic_loads(dynamics, low, high) -> Optional[LoadMap]:
    """The dynamics stage's simulated cam force at its speeds within [low, high] (and the rated speed), a
    :class:`LoadMap`, or None where none of its speeds lies in the range."""
    speeds = np.append(np.asarray(dynamics.per_speed.speed, dtype=float), dynamics.at_rated_speed.speed)
    force = np.vstack([dynamics.sweep.contact_force, dynamics.rated.contact_force[None, :]])
    keep = (speeds >= low * (1.0 - 1e-12)) & (speeds <= high * (1.0 + 1e-12))
    if not keep.any():
        return None
    rows = np.flatnonzero(keep)[np.argsort(speeds[keep], kind="stable")]    # one copy of the large force map
    return LoadMap("dynamic", speeds[rows], dynamics.sweep.theta, force[rows])


def load_maps(valve, engine, cam, theta, spring_force, mass, dynamics=None) -> tuple[list[LoadMap], tuple[float, float, str]]:
    """The cam force over the strength speed range, a list of :class:`LoadMap`, and the range (low, high, source).

    With the dynamics stage, its simulated force at its speeds in the range and the quasi-static force at the
    speeds of the range it does not sweep; without it, the quasi-static force at :data:`STRENGTH_SPEEDS` speeds
    and the rated speed.
    """
    low, high, source = strength_speed_range(engine, None if dynamics is None else dynamics.speed_range)
    speeds = np.unique(np.append(np.linspace(low, high, STRENGTH_SPEEDS), engine.rated_speed))
    maps = []
    if dynamics is not None:
        swept = dynamics.speed_range
        maps.append(dynamic_loads(dynamics, low, high))
        speeds = speeds[(speeds < swept[0]) | (speeds > swept[1])]
    if speeds.size:
        to_cam = cam.cam_speed / engine.rated_speed
        maps.append(quasi_static_loads(cam.law, cam.rocker_ratio, theta, spring_force, mass, speeds, to_cam,
                                       finger_inertia(valve, cam.law, theta)))
    return [m for m in maps if m is not None], (low, high, source)


def event_load_maps(valve, engine, cam, drive, dynamics=None) -> tuple[np.ndarray, list[LoadMap],
                                                                  tuple[float, float, str]]:
    """The cam force over the strength speed range on the open event: its camshaft angles [rad from the nose] (2001
    and the law's breakpoints), the list of :class:`LoadMap` and the range (low, high, source) of :func:`load_maps`
    with the drive stage's chosen spring and reduced mass."""
    law = cam.law
    theta = np.unique(np.concatenate([np.linspace(law.valve_opens, law.valve_closes, 2001), law.breakpoints]))
    theta = theta[(theta >= law.valve_opens) & (theta <= law.valve_closes)]
    maps, span = load_maps(valve, engine, cam, theta, drive.lines.chosen.force(cam.valve_lift(theta)),
                           drive.masses.at_valve, dynamics)
    return theta, maps, span


def contact_loads(cam, maps) -> list[LoadMap]:
    """The load maps as the force between cam and follower: each map's force (along the law's lift) times the
    follower's :meth:`~valvetrain.followers.Follower.force_ratio` at its angles (1 for a translating follower; a
    finger's cam carries G / (L_r cos beta) of the force at the valve, Norton (2009))."""
    follower = cam.follower_model
    out = []
    for m in maps:
        h, dh = cam.law.derivatives(m.theta)[:2]
        out.append(replace(m, force=m.force * follower.force_ratio(cam.heel_radius, h, dh)))
    return out


def _worst(maps, values):
    """The largest of ``values`` (one array (S, n) per load map) over every map: a :class:`Worst`; of values equal
    to round-off (a symmetric cam's two flanks) the first map's, at the lowest speed, at the smallest angle
    (:func:`~valvetrain.numerics.first_largest`)."""
    best = None
    for m, q in zip(maps, values, strict=True):
        i, j = np.unravel_index(first_largest(q), q.shape)
        if best is None or q[i, j] > best.value + TIE_RTOL * abs(best.value):
            best = Worst(float(q[i, j]), float(m.speeds[i]), float(m.theta[j]), m.kind, float(m.force[i, j]))
    return best


def strength_stage(valve, gas, engine, cam, drive, dynamics=None) -> tuple[StrengthResult, list[Check]]:
    """Work 7 over the speed range: every strength check the layout and the given dimensions allow, at its worst.

    Parameters
    ----------
    valve, gas, engine : SI views of the valve, ``[gas]`` and ``[engine]``.
    cam : CamResult
        The law stage.
    drive : DriveResult
        The drive stage (reduced mass, chosen spring line).
    dynamics : DynamicsResult, optional
        The dynamics stage: its simulated contact force replaces the quasi-static one at its speeds.

    Returns
    -------
    (StrengthResult, list of Check)
        The strength checks (quantity with spaces), the follower checks and a warning for every key of the parts
        that no part of the valve's layout reads (:func:`valvetrain.layouts.unused_part_checks`).

    Notes
    -----
    The cam force :math:`P_T(n, \\theta)` is evaluated on a grid of engine speeds x camshaft angles from the lowest
    speed to the over-speed (:func:`strength_speed_range`); each check takes its worst point.  The checks loaded by
    :math:`P_{T\\,max}` (camshaft deflection, tappet side pressure, pushrod buckling and ball, rocker pad and shaft)
    follow the largest force, on the opening flank at the highest speed for a rigid train; the Hertz stress follows
    force and curvature together, at the nose at the lowest speed, where the inertia no longer unloads the nose.

    References
    ----------
    Valve-train practical works (n.d.), work 7, eqs. (7.1)-(7.18); Shang Hanji (1988), eq. (2.5) and section 3.4
    (the contact stress under the dynamic force).
    """
    law = cam.law
    theta, maps, (low, high, source) = event_load_maps(valve, engine, cam, drive, dynamics)
    found = []
    p_open = 0.0
    if valve.kind == "exhaust":
        p_open, gas_check = _exhaust_gas_force(valve, gas)
        found.append(gas_check)
        for m in maps:
            # the nearest angle; of two as near to the round-off of the angles, the first
            m.force[:, first_largest(-np.abs(m.theta - law.valve_opens), atol=TIE_RTOL * np.pi)] += \
                cam.rocker_ratio * p_open
    result, checks = _strength(valve, cam, theta, contact_loads(cam, maps), p_open, _worst(maps, [m.force for m in maps]))
    lever = finger_loads(cam, maps)
    if lever is not None:
        finger, bending = finger_bending(valve.parts, *lever)
        result = replace(result, finger=finger, checks=result.checks + bending[0], not_checked=result.not_checked
                         + bending[1])
    result = replace(result, speed_range=(float(low), float(high)), lowest_speed_source=source,
                     rated_speed=engine.rated_speed)
    return result, list(result.checks) + found + checks + unused_part_checks(valve)


WHERE = {"quasi-static": ("strength.where_quasi_static", "strength.side_quasi_static",
                          "strength.edge_quasi_static_hertz", "strength.edge_quasi_static_no_width"),
         "dynamic": ("strength.where_dynamic", "strength.side_dynamic", "strength.edge_dynamic_hertz",
                     "strength.edge_dynamic_no_width")}
"""The notes of a worst value's place by the kind of its force (:class:`LoadMap`): where it is, where with the pressure
angle, the flat follower's contact offset there with and without the Hertz half-width (:mod:`valvetrain.locale`)."""


def _where(w, which=0, **params):
    """Where a worst value occurs, for a check's note (:data:`WHERE`'s note ``which`` of its force, with ``params``)."""
    return note(WHERE[w.kind][which], speed_rpm=to_display(w.speed, "rpm"), cam_deg=to_display(w.angle, "cam deg"),
                **params)


def finger_loads(cam, maps) -> Optional[tuple[FingerLoads, Worst]]:
    """The :class:`FingerLoads` of a finger under the force at the valve of the load maps (before
    :func:`contact_loads`), at their worst, and where its bending moment is largest (:class:`Worst`); None for a
    follower that is no lever (:meth:`~valvetrain.followers.Follower.loads`)."""
    follower, heel = cam.follower_model, cam.heel_radius
    found = []
    for m in maps:
        h, dh = cam.law.derivatives(m.theta)[:2]
        found.append(follower.loads(m.force, heel, h, dh))
    if found[0] is None:
        return None
    return (FingerLoads(*(max(float(np.max(f[k])) for f in found) for k in range(3))),
            _worst(maps, [f[2] for f in found]))


def not_given(check, keys) -> NoteText:
    """The note of a ``check`` not made because the ``[parts]`` ``keys`` (their names in the specification) are not
    given: ``"camshaft_deflection: not checked, parts.cam_width_mm not given"``, kept as its codes
    (``strength.not_checked``) for the report to name the check and the keys in its language."""
    return NoteText(note("strength.not_checked", check=check,
                         keys=sum((note("strength.part_key", key=key) for key in keys), ())))


def finger_bending(parts, loads, moment) -> tuple[FingerLoads, tuple[tuple[Check, ...], tuple[str, ...]]]:
    """The finger's bending stress at its critical section under its largest bending moment ``moment``
    (:class:`Worst`, :meth:`~valvetrain.followers.PivotedFollower.loads`) on the rectangular section of
    ``parts.finger_section_width_mm`` x ``finger_section_height_mm``
    (:func:`valvetrain.strength.rectangle_bending_stress`): ``loads`` with the stress, and (its check,) or the note that the section is not given."""
    keys = ("finger_section_width_mm", "finger_section_height_mm")
    missing = [key for key in keys if getattr(parts, si_name(key)[0]) is None]
    if missing:
        return loads, ((), (not_given("finger_bending", missing),))
    stress = strength.rectangle_bending_stress(moment.value, parts.finger_section_width, parts.finger_section_height)
    width, height = (to_display(x, "mm") for x in (parts.finger_section_width, parts.finger_section_height))
    said = _where(moment) + note("strength.finger_section", moment_Nm=moment.value, width_mm=width, height_mm=height)
    return (replace(loads, bending_stress_max=float(stress)),
            ((strength.verdict("finger_bending", float(stress), said),), ()))


def _strength(valve, cam, theta, maps, p_open, valve_load):
    """Work 7 on the load maps (the force at the cam): every check the layout and the given dimensions allow, at its
    worst point; ``valve_load`` is the largest force along the law's lift (:class:`Worst`), which i_k takes to the
    valve."""
    i_k = cam.rocker_ratio
    parts, drive, follower = valve.parts, chain(valve), cam.follower_model
    notes, verdicts = [], []
    load = _worst(maps, [m.force for m in maps])
    p_max, at_load = load.value, _where(load)

    def need(keys, name):
        """Whether the parts' keys (spec names) are given; a note names those missing."""
        missing = [key for key in keys if getattr(parts, si_name(key)[0]) is None]
        if missing:
            notes.append(not_given(name, missing))
        return not missing

    e_contact = parts.contact_modulus
    width = stress = stresses = None
    if need(["camshaft_diameter_mm", "camshaft_span_mm", "cam_to_bearing_mm"], "camshaft_deflection"):
        l1 = parts.cam_to_bearing
        f = strength.camshaft_deflection(p_max, l1, parts.camshaft_span - l1, parts.camshaft_diameter,
                                         parts.camshaft_bore, parts.camshaft_modulus,
                                         parts.camshaft_deflection_coefficient)
        verdicts.append(strength.verdict("camshaft_deflection", f, at_load + note(
            "strength.deflection_coefficient", coefficient=parts.camshaft_deflection_coefficient)))
    if need(["cam_width_mm"], "cam_contact_stress"):
        # Shang Hanji (1988), eqs. (2.6)-(2.7): the profile's radius of curvature along the open event
        if not np.all(follower.line_contact(cam.law.curvature(theta, cam.heel_radius, follower))):
            notes.append(NoteText(note("strength.undercut_not_checked")))
        else:
            width = parts.cam_width
            stresses = [follower.contact_stress(m.force, cam.law.curvature(m.theta, cam.heel_radius, follower), width,
                                                e_contact) for m in maps]
            stress = _worst(maps, stresses)
            verdicts.append(strength.verdict("cam_contact_stress", stress.value,
                                             _where(stress) + note("strength.along_profile")))
    face = follower.face_offset(cam.law.derivatives(theta)[1])
    loads = Loads(parts, p_max, valve_load.value / i_k, e_contact, i_k, at_load,
                  None if face is None else float(np.max(face)), need)
    for link in drive.links:
        verdicts += link.checks(loads)
    side, found = _roller_side_force(cam, follower, maps, drive)
    if face is not None:
        found += _edge_loading(parts, drive, cam, follower, maps, width, notes)
    return StrengthResult(
        (0.0, 0.0), "", load.value, load.angle, load.speed, valve_load.value / i_k, p_open,
        None if stress is None else stress.angle, None if stress is None else stress.speed,
        None if side is None else side.value, None if side is None else side.angle,
        None if side is None else side.speed, _per_speed(maps, stresses),
        tuple(verdicts), tuple(notes), contact_force=None if stress is None else stress.force), found


def _per_speed(maps, stresses=None):
    """The largest cam force and contact stress (``stresses``: one array (S, n) per load map, None: not checked) at
    every speed of the load maps, a :class:`StrengthPerSpeed` in increasing speed; of values equal to round-off the
    one at the smallest angle (:func:`~valvetrain.numerics.first_largest`)."""
    def largest(m, values):
        j = first_largest(values, axis=1)
        return values[np.arange(j.size), j], m.theta[j]

    def column(rows):
        return tuple(float(x) for x in np.concatenate(rows)[order])

    speeds = np.concatenate([m.speeds for m in maps])
    order = np.argsort(speeds, kind="stable")
    kinds = tuple(np.concatenate([[m.kind] * m.speeds.size for m in maps])[order])
    force, force_at = zip(*(largest(m, m.force) for m in maps), strict=True)
    stress = (None, None)
    if stresses is not None:
        stress = [column(c) for c in zip(*(largest(m, q) for m, q in zip(maps, stresses, strict=True)), strict=True)]
    return StrengthPerSpeed(column([speeds]), kinds, column(force), column(force_at), *stress)


def _exhaust_gas_force(valve, gas):
    """Gas force on the closed exhaust valve head as it opens [N] (7.1) and its record.

    Without ``parts.head_diameter_mm`` the throat diameter stands in for the head's: the head is larger than
    the throat, so the force is a lower bound, and the record says so.
    """
    head = valve.parts.head_diameter
    diameter = valve.throat_diameter if head is None else head
    force = float(flow.circle_area(diameter)) * max(gas.exhaust_opening_pressure - gas.exhaust_back_pressure, 0.0)
    said = (note("strength.head_diameter", head_mm=to_display(head, "mm")) if head is not None else
            note("strength.throat_for_head", throat_mm=to_display(diameter, "mm")))
    return force, check("gas_force.exhaust_opening", force, unit="N", severity="info",
                        source=WORKS_7_1, note=said)


def _edge_loading(parts, drive, cam, follower, maps, width, notes):
    """The flat follower's contact against the edge of its face: max(|dh/dphi| + Hertz half-width) <= face radius.

    The contact point of a flat follower lies dh/dphi from its axis (Shang's contour, eq. 2.15); the contact
    band reaches a half-width further where the cam width is given (``width`` [m], None: not given or undercut),
    under the force of each speed.  The face is ``tappet_face_diameter_mm``, else, for a tappet in a guide,
    ``tappet_diameter_mm`` (a bucket tappet's face is its diameter).
    """
    if parts.tappet_face_diameter is not None:
        face, key = parts.tappet_face_diameter, "strength.face_given"
    elif drive.links[0].face_diameter(parts) is not None:
        face, key = drive.links[0].face_diameter(parts), "strength.face_of_bucket"
    else:
        notes.append(not_given("flat_follower_edge_loading", ["tappet_face_diameter_mm"]))
        return []

    def reach(m):
        offset = follower.face_offset(cam.law.derivatives(m.theta)[1])
        if width is None:
            return np.broadcast_to(offset, m.force.shape)
        curvature = follower.contact_curvature(cam.law.curvature(m.theta, cam.heel_radius, follower))
        reach = strength.hertz_half_width(m.force, width, curvature, parts.contact_modulus)
        reach += offset     # in place: a load map's array is large (strength.hertz_line_stress)
        return reach

    w = _worst(maps, [reach(m) for m in maps])
    offset = abs(float(cam.law.derivatives(np.array([w.angle]))[1, 0]))
    band = (_where(w, 2, offset_mm=to_display(offset, "mm"), half_width_mm=to_display(w.value - offset, "mm"))
            if width is not None else _where(w, 3, offset_mm=to_display(offset, "mm")))
    return [check("follower.edge_loading", w.value, high=face / 2.0, unit="mm",
                  severity="failure", source=cited(f"{SHANG_2_1}, eq. (2.15)", note("source.face_width", work=NORTON)),
                  note=band + note(key))]


def _roller_side_force(cam, follower, maps, drive):
    """The largest side force of a roller follower over the speeds, P_T tan(alpha)
    (:meth:`~valvetrain.followers.Follower.side_force`), carried by the layout's first link: a :class:`Worst` and
    [its (info) record]; None and [] for a follower without one (a flat face, a finger on its pivot)."""
    sides = [follower.side_force(m.force, cam.heel_radius, *cam.law.derivatives(m.theta)[:2]) for m in maps]
    if sides[0] is None:
        return None, []
    w = _worst(maps, sides)
    h, dh = cam.law.derivatives(np.array([w.angle]))[:2]
    beta = abs(float(follower.pressure_angle(cam.heel_radius, h, dh)[0]))
    return w, [check(
        "follower.roller_side_force", w.value, unit="N", severity="info",
        source=cited(note("source.side_load", work=NORTON)),
        note=_where(w, 1, pressure_deg=to_display(beta, "deg")) + note(drive.links[0].carrier))]


def strength_limit(c) -> tuple[str, float]:
    """The side and the bound of a strength check in its display unit: ``("<=", high)`` or ``(">=", low)``."""
    return ("<=", to_display(c.high, c.unit)) if c.high is not None else (">=", to_display(c.low, c.unit))


def strength_allowed(c) -> str:
    """The allowed range of a strength check as results.json and the report write it (``"<= 1200"``)."""
    side, limit = strength_limit(c)
    return f"{side} {limit:g}"


def strength_record(c) -> dict[str, Any]:
    """results.json record of a strength check: value and limit in its unit, pass, source (and a note)."""
    out = {"value": c.shown_value, "allowed": strength_allowed(c), "limit": strength_limit(c)[1], "unit": c.unit,
           "pass": c.passed, "source": c.source}
    if c.note:
        out["note"] = c.note
    return out
