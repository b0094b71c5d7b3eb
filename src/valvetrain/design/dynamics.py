"""The dynamics stage of a valve design: the elastic train over a speed range ([valves.NAME.dynamics]).

The stage builds a one-mass or a multi-mass train (:mod:`valvetrain.dynamics.models`) from the
valve's design (the reduced mass, the designed spring, the lash the ramp takes up, the part
masses and geometry of the specification), sweeps it over the engine speeds
(:func:`valvetrain.dynamics.sweep.sweep`), simulates the rated speed, refines the headline numbers
at the speeds that decide them and estimates their errors (:func:`valvetrain.dynamics.accuracy.refine`), and adds
the resonance analysis of the cam's harmonics (:mod:`valvetrain.dynamics.resonance`).  Every value the
specification leaves out is estimated and the estimate stated in ``parameters.estimates``.

Speeds in the results are engine (crank) speeds; the camshaft of a four-stroke turns at half.
"""

from dataclasses import replace
import math
from typing import Optional, Union

import numpy as np

from .. import lash_adjuster as hla
from ..checks import Check
from ..dynamics.coils import CoilSpring, coil_spring
from ..dynamics.models import (Adjuster, MultiMassTrain, OneMassTrain, VariableMass, camshaft_stiffness, natural_modes,
                               one_mass_train, series)
from ..dynamics.accuracy import refine
from ..dynamics.perturbation import perturbation_parameter
from ..dynamics.resonance import resonance
from ..dynamics.sweep import SweepResult, headline_sweep, sweep, sweep_size
from ..followers import follower_of
from ..layouts import chain, finger_inertia, layout, valve_arm
from ..locale import NoteText, cited, note
from ..specification import SpecError
from ..specification.messages import Problem
from ..strength import cam_force
from ..units import DEG, MM, cam_per_crank, rpm_to_rad_s
from .dynamics_checks import dynamics_checks, unsettled_note
from .dynamics_records import (AccuracyRecord, DynamicsParameters, DynamicsResult, Mode, PerSpeed, ResonanceRecord,
                               finite_or_none, speed_record, speed_records)

SOURCES = cited(note("source.train_models", work="Shang Hanji (1988), ch. 3"),
                note("source.resonant_harmonic", work="Valve-train dynamics article (n.d.)"))
"""The works the dynamics stage follows, as the report cites them."""

LINK_STIFFNESS = 45e6
"""Stiffness assumed for a drive link whose geometry the specification does not give, at the valve [N/m]:
three such links in series (camshaft, pushrod, rocker) make the 15000 N/mm of the one-mass worked example of
Shang Hanji (1988, ch. 3); published pushrod trains have 3000-20000 N/mm at the valve."""

SPEED_RANGE = (0.1, 1.25)
"""Default speed range as fractions of the rated speed: idle to over-speed."""

MAX_SWEEP_WORK = 2e9
"""Most integrator steps x network elements of a sweep without ``allow_large_sweep`` (about 30 s on one core of
this package's reference machine at 6.5e7 a second; the revolutions counted at their cap)."""

MAX_SWEEP_BYTES = 1e9
"""Most bytes of the recorded revolutions of a sweep without ``allow_large_sweep`` (1 GB)."""


def _link_estimates(valve, k):
    """The drive links of the layout from the cam (name, stiffness at the valve [N/m] or None) from the part geometry:
    the camshaft, each elastic link on the cam side of the valve's joint (its stiffness over k^2), the joint of the
    last lever to the valve, each elastic link at the valve (a valve bridge: ratio 1)."""
    parts = valve.parts
    cam = None
    if None not in (parts.camshaft_diameter, parts.camshaft_span, parts.cam_to_bearing):
        cam = camshaft_stiffness(parts.cam_to_bearing, parts.camshaft_span - parts.cam_to_bearing,
                                 parts.camshaft_diameter, parts.camshaft_bore, parts.camshaft_modulus) / k**2
    drive = chain(valve)

    def own(link):
        c = link.stiffness(parts)
        return link.label, None if c is None else c / (1.0 if link.at_valve else k**2)

    links = [("camshaft and cam contact", cam)]
    links += [own(link) for link in drive.links if link.elastic and not link.at_valve]
    links.append((drive.valve_joint, None))
    return links + [own(link) for link in drive.links if link.elastic and link.at_valve]


def drive_links(dyn, valve, k, at) -> tuple[tuple[Optional[float], ...], tuple[str, ...], list[str]]:
    """Link stiffnesses at the valve [N/m], their names, and the estimates stated.

    The total drive stiffness c is ``dynamics.drive_stiffness_N_per_mm``, else ``drive.stiffness_N_per_mm``;
    links with geometry in [parts] (camshaft bending, pushrod E A / L) take their estimate and the others share
    the rest of the compliance equally.  Without a total, a link without geometry is :data:`LINK_STIFFNESS`.
    """
    links = _link_estimates(valve, k)
    notes = [NoteText(note("dynamics.link_from_parts", link=name, stiffness_N_mm=c * MM)) for name, c in links
             if c is not None]
    total, key = dyn.drive_stiffness, "dynamics.drive_stiffness_N_per_mm"
    if total is None and valve.drive.stiffness is not None:
        total, key = valve.drive.stiffness, "drive.stiffness_N_per_mm"
        notes.append(NoteText(note("dynamics.drive_stiffness_given", stiffness_N_mm=total * MM)))
    unknown = [i for i, (_, c) in enumerate(links) if c is None]
    known = sum(1.0 / c for _, c in links if c is not None)
    named = sum((note("dynamics.link", link=links[i][0]) for i in unknown), ())
    if total is not None:
        rest = 1.0 / total - known
        if rest <= 0.0:
            raise SpecError([Problem(f"{at}.{key}", NoteText(note("spec.stiffer_than_links", series=1.0 / known * MM)),
                                     f"{total * MM:g}")])
        share = len(unknown) / rest
        notes.append(NoteText(note("dynamics.links_share", links=named, share_N_mm=share * MM, total_N_mm=total * MM)))
    else:
        share = LINK_STIFFNESS
        notes.append(NoteText(note("dynamics.links_assumed", links=named, share_N_mm=share * MM)))
    values = tuple(share if c is None else float(c) for _, c in links)
    return values, tuple(name for name, _ in links), notes


def _coil_springs(spring_record, coils):
    """The designed spring(s) as :class:`CoilSpring` (:func:`~valvetrain.dynamics.coils.coil_spring`: the active
    coils' mass in the coil masses, the end coils' with the retainer and the head, the closing gap from the installed
    and the solid length)."""
    recs = [spring_record.design] if spring_record.count == 1 else [spring_record.outer, spring_record.inner]
    return [coil_spring(r.rate, r.preload, r.mass, r.active_coils, r.wire_diameter, r.installed_length, int(coils),
                        r.total_coils - r.active_coils) for r in recs]


def multi_springs(dyn, spring_record, rate, preload) -> tuple[list[CoilSpring], list[str]]:
    """The springs of the multi-mass train and the notes on them: the designed spring(s), or one spring of the rate
    K [N/m] and preload F0 [N] of :func:`train_spring` when [dynamics] gives any of the spring's keys (its active-coil
    mass ``spring_mass_kg``, else the designed springs' together; its coil clash is then not monitored)."""
    designed = _coil_springs(spring_record, dyn.coils_per_spring)
    given = (dyn.spring_rate, dyn.spring_preload_N, dyn.spring_mass_kg)
    if all(v is None for v in given):
        return designed, [NoteText(note("dynamics.coil_masses", coils=dyn.coils_per_spring))]
    mass = sum(sp.mass for sp in designed) if dyn.spring_mass_kg is None else float(dyn.spring_mass_kg)
    told = "dynamics.one_spring_designed_coils" if dyn.spring_mass_kg is None else "dynamics.one_spring_given_coils"
    return [CoilSpring(rate, preload, mass, 0.0, int(dyn.coils_per_spring))], [
        NoteText(note(told, rate_N_mm=rate * MM, preload_N=preload, mass_kg=mass, coils=dyn.coils_per_spring))]


def nose_acceleration(law, cam_speed, rocker_ratio, points=3601) -> float:
    """Smallest valve acceleration of the lift event j_min = i_k omega_cam^2 min h''(theta) [m/s^2] (at the nose for
    a symmetric law), on ``points`` evenly spaced angles of the event."""
    theta = np.linspace(law.start, law.end, points)
    return float(rocker_ratio * cam_speed**2 * law.derivatives(theta)[2].min())


def train_spring(dyn, valve, law, line, mass, cam_speed, at) -> tuple[float, float, str]:
    """Rate K [N/m] and preload F0 [N] of the train (the spring of the one-mass train, or of the multi-mass train when
    [dynamics] gives it), and the note on where they come from.

    ``spring_rate_N_per_mm`` and ``spring_preload_N`` of [dynamics] replace the designed spring's; a preload given
    without a rate sizes the rate by Valve-train dynamics article (n.d.), step 4a: K = (K_3 M |j_min| - F0) / h_max at
    the rated camshaft speed, K_3 = drive.spring_reserve.
    """
    from ..dynamics.resonance import spring_rate

    if dyn.spring_rate is None and dyn.spring_preload_N is None:
        return line.rate, line.preload, NoteText(note("dynamics.spring_designed", rate_N_mm=line.rate * MM,
                                                      preload_N=line.preload))
    preload = line.preload if dyn.spring_preload_N is None else float(dyn.spring_preload_N)
    told = "dynamics.spring_given" if dyn.spring_preload_N is not None else "dynamics.spring_rate_given"
    if dyn.spring_rate is not None:
        return float(dyn.spring_rate), preload, NoteText(note(told, rate_N_mm=dyn.spring_rate * MM, preload_N=preload))
    reserve = valve.drive.spring_reserve
    lift = valve.rocker_ratio * law.lift_max
    rate = spring_rate(mass, nose_acceleration(law, cam_speed, valve.rocker_ratio), reserve, preload, lift)
    if rate <= 0.0:
        raise SpecError([Problem(f"{at}.dynamics.spring_preload_N", NoteText(note("spec.preload_above_need")),
                                 f"{preload:g}")])
    return rate, preload, NoteText(note("dynamics.spring_rate_sized", rate_N_mm=rate * MM, reserve=reserve,
                                        preload_N=preload))


REVOLUTIONS = {False: 3, True: 20}
"""The default of ``[dynamics] revolutions``, the most camshaft revolutions a speed runs, without and with a slow
state (a lash adjuster, or the coil masses of a multi-mass train).  A one-mass mechanical train repeats within two
revolutions from rest; the plunger of a hydraulic adjuster is a slow state: where the follower's force falls to the
adjuster's push near the valve's closing (from about 0.85 x the rated speed of the modern example) the plunger extends
and leaks the extension back under load over several revolutions, its periodic state approached by about a factor of
0.1-0.3 a revolution (the modern example: 3 to 8 revolutions between 0.84 and 1.19 x the rated speed, 14 of its 40
speeds unsettled at 3; above its float speed, 1.2 x, the plunger pumps up at every revolution and the speed stays
unsettled).  The surge a lift leaves in the coils decays by exp(-zeta_1 omega_1 T) a revolution of T seconds (the first
surge mode's damping ratio zeta_1 = :data:`~valvetrain.dynamics.coils.COIL_DAMPING_RATIO` at omega_1): 0.37 at
8750 rpm for the pushrod example's 580 Hz, some 14 revolutions from a millimetre to the 1 nm the repetition asks.  20 is
the key's largest value."""


def revolutions(dyn, valve) -> int:
    """``[dynamics] revolutions`` as given, else :data:`REVOLUTIONS` of the valve (with or without a lash adjuster or
    a multi-mass train)."""
    slow = valve.lash_adjuster is not None or dyn.model == "multi"
    return REVOLUTIONS[slow] if dyn.revolutions is None else int(dyn.revolutions)


def adjuster_reference_force(valve, law, drive, cam_speed: float, ratio: float) -> float:
    """The largest quasi-static force on a lash adjuster of motion ratio ``ratio`` at the camshaft speed
    ``cam_speed`` [rad/s] [N]: spring and inertia of the rigid train over the open event, (7.1) of
    :func:`valvetrain.strength.cam_force` reduced from the valve."""
    theta = np.linspace(law.valve_opens, law.valve_closes, 2001)
    k = valve.rocker_ratio
    spring = drive.lines.chosen.force(k * law.lift(theta))
    force = cam_force(spring, drive.masses.at_valve * k * cam_speed**2 * law.derivatives(theta)[2]
                      + cam_speed**2 * finger_inertia(valve, law, theta), k)
    return float(force.max()) / k * ratio


def lever_ratio(valve, law) -> float:
    """The valve's lever ratio on the heel circle: rocker_ratio x the follower's own there (a finger's G(psi_0) / L_r
    from its geometry, whose law is the valve's and rocker_ratio 1)."""
    return valve.rocker_ratio * follower_of(valve.cam).rest_ratio(valve.cam.base_radius - law.ramp_height)


def adjuster_ratio(valve, law) -> float:
    """The lash adjuster's motion ratio: at the pivot of a finger given by its geometry, its linkage on the heel circle
    with the adjuster's axis (``axis_angle_deg``, default the valve's; :func:`valvetrain.lash_adjuster.pivot_motion_ratio`);
    else :func:`valvetrain.lash_adjuster.motion_ratio` with the :func:`lever_ratio`."""
    la = valve.lash_adjuster
    linkage = None if la.location != "pivot" else follower_of(valve.cam).pivot_linkage(
        valve.cam.base_radius - law.ramp_height, la.axis_angle)
    if linkage is None:
        return hla.motion_ratio(la.location, lever_ratio(valve, law))
    return hla.pivot_motion_ratio(*linkage)


def adjuster_load(valve, law, drive, cam_speed: float, at: str) -> tuple[float, float]:
    """The lash adjuster's motion ratio and :func:`adjuster_reference_force` [N], refused where the adjuster cannot
    work: a motion ratio <= 0 (at the pivot of a lever ratio <= 1, or of a finger whose linkage along the adjuster's
    axis moves the valve against the plunger, the message naming that axis), or a largest force on it no more than its own push
    F_s + p_s A, which would hold the valve open and leave the oil column uncompressed (no finite stiffness)."""
    la = valve.lash_adjuster
    ratio = adjuster_ratio(valve, law)
    if ratio <= 0.0 and follower_of(valve.cam).pivot_linkage(valve.cam.base_radius - law.ramp_height) is None:
        raise SpecError([Problem(f"{at}.lash_adjuster.location",
                                 NoteText(note("spec.pivot_lever", ratio=lever_ratio(valve, law))), '"pivot"', " ")])
    if ratio <= 0.0:   # a finger's linkage along the adjuster's axis: its lever ratio alone does not decide
        linkage = note("spec.pivot_linkage", ratio=ratio, lever=lever_ratio(valve, law))
        if la.axis_angle is None:
            raise SpecError([Problem(f"{at}.lash_adjuster.location",
                                     NoteText(note("spec.valve_axis", linkage=linkage)), '"pivot"')])
        raise SpecError([Problem(f"{at}.lash_adjuster.axis_angle_deg", NoteText(linkage),
                                 f"{math.degrees(la.axis_angle):g}")])
    force = adjuster_reference_force(valve, law, drive, cam_speed, ratio)
    supply = la.supply_pressure * hla.plunger_area(la.plunger_diameter)
    if force <= la.plunger_spring_N + supply:
        raise SpecError([Problem(f"{at}.lash_adjuster.plunger_spring_N",
                                 NoteText(note("spec.adjuster_pushes", supply=supply, force=force, ratio=ratio,
                                               most=max(force - supply, 0.0))), f"{la.plunger_spring_N:g}")])
    return ratio, force


def adjuster_element(la, ratio: float) -> Adjuster:
    """The kernels' :class:`~valvetrain.dynamics.models.Adjuster` of ``[lash_adjuster]`` (SI view ``la``) at the motion
    ratio ``ratio``: its leak coefficient pi d c^3 (1 + 1.5 epsilon^2) / (12 mu L) [m^3/(s Pa)] at the plunger's
    eccentricity epsilon (:func:`valvetrain.lash_adjuster.annular_leakage` per pascal) and its largest extension
    velocity, the check valve's flow under :func:`valvetrain.lash_adjuster.refill_pressure` over the plunger area
    [m/s]."""
    area = hla.plunger_area(la.plunger_diameter)
    leak = hla.annular_leakage(1.0, la.plunger_diameter, la.radial_clearance, la.leak_length, la.oil_viscosity,
                               la.plunger_eccentricity)
    refill = hla.check_valve_flow(hla.refill_pressure(la.supply_pressure, la.plunger_spring_N, area),
                                  la.check_valve_diameter) / area
    return Adjuster(float(ratio), float(la.plunger_spring_N), float(area), float(la.supply_pressure), float(leak),
                    float(refill), float(la.plunger_travel))


def adjuster_link(valve, law, drive, cam_speed: float, at: str) -> tuple[float, str, Adjuster]:
    """The lash adjuster's oil column reduced to the valve [N/m] (in series with the cam contact), the note that
    says so (its secant stiffness under :func:`adjuster_reference_force` over the square of the motion ratio), and its
    :func:`adjuster_element`, whose plunger extension the kernels carry from revolution to revolution."""
    la = valve.lash_adjuster
    ratio, force = adjuster_load(valve, law, drive, cam_speed, at)
    stiffness = hla.secant_stiffness(force, la.plunger_spring_N, hla.plunger_area(la.plunger_diameter),
                                     la.supply_pressure, la.chamber_volume, la.bulk_modulus, la.air_content)[0]
    at_valve = stiffness / ratio**2
    return at_valve, NoteText(note("dynamics.adjuster_link", stiffness_N_mm=at_valve / 1e3, force_N=force)), \
        adjuster_element(la, ratio)


def inertia_arm(valve, law, drive) -> tuple[Optional[float], Optional[str]]:
    """The valve arm that reduces the rocker's inertia to the valve in the dynamics model [m], and a note (None but
    for a finger of given inertia): ``[drive] valve_arm_mm``, or a finger's effective arm G(psi) = dv/dpsi at the valve
    lift of the largest required spring force (:attr:`DriveResult.required_force`, where the train first leaves the
    cam as the speed rises).

    A finger's J / G(psi)^2 at that lift is the reference value of its node (the modes, the dampings, the
    perturbation parameter); the integration takes its change over the lift (:func:`finger_mass`); the note gives
    its range.
    """
    parts = valve.drive.masses
    arm = follower_of(valve.cam).valve_arms(drive.lift, valve.cam.base_radius - law.ramp_height)
    if arm is None:
        return valve.drive.valve_arm, None
    at = int(np.argmax(drive.required_force))
    if parts is None or parts.rocker_inertia == 0.0:
        return float(arm[at]), None
    reduced, heel_circle = parts.rocker_inertia / arm**2, parts.rocker_inertia / valve_arm(valve)**2
    return float(arm[at]), NoteText(note("dynamics.finger_reference", reduced_g=reduced[at] * 1e3,
                                         lift_mm=drive.lift[at] / MM, heel_g=heel_circle * 1e3,
                                         lightest_g=reduced.min() * 1e3, heaviest_g=reduced.max() * 1e3))


FINGER_MASS_POINTS = 257
"""Positions of the table of a finger's reduced mass over the lift (:func:`finger_mass`); the cubic Hermite of the
kernels between them is within 7e-13 of J / G^2 at the midpoints on the shipped finger
(examples/modern-dohc-roller-finger.toml)."""

FINGER_MASS_BELOW = 1e-3
"""How far below the shut valve's lift the table of a finger's reduced mass starts [m] (the valve pressed into its
seat, a node behind a lash)."""


def finger_mass(follower, inertia, heel, top, node, rest=0.0, offset=0.0,
                points=FINGER_MASS_POINTS) -> VariableMass:
    """A node of a finger's inertia by its variable ratio: m(x) = m_0 + J / G(psi(x + x_0))^2 over its positions x.

    Parameters
    ----------
    follower : valvetrain.followers.PivotedFollower
    inertia : float
        J, the finger's moment of inertia about its pivot [kg m^2].
    heel : float
        The heel radius of the cam [m].
    top : float
        The law's largest lift (lift and ramp) [m]: the table runs from :data:`FINGER_MASS_BELOW` below the shut
        valve, at most halfway to the pad's reach below it (:meth:`~valvetrain.followers.PivotedFollower.reach_below`,
        where G -> 0), to 1.5 x ``top``, at most halfway from ``top`` to the pad's reach (where G -> 0).
    node : str
        The node's name.
    rest : float
        m_0, the node's mass beside the finger's [kg].
    offset : float
        x_0, the law's lift at the node's position 0 [m] (the lash of a one-mass train's valve node).
    points : int

    Returns
    -------
    VariableMass

    Notes
    -----
    :meth:`~valvetrain.followers.PivotedFollower.reduced_inertia` and its slope
    :meth:`~valvetrain.followers.PivotedFollower.reduced_inertia_slope`; the kernels add the velocity-squared force
    (1/2) m'(x) x_dot^2 of Lagrange's equation (:class:`~valvetrain.dynamics.models.VariableMass`).

    References
    ----------
    Norton (2009), the chapter on the dynamics of follower trains.
    """
    high = min(1.5 * top, top + 0.5 * (follower.reach(heel) - top))
    h = np.linspace(-min(FINGER_MASS_BELOW, 0.5 * follower.reach_below(heel)), high, points)
    return VariableMass(node, h - offset, rest + follower.reduced_inertia(inertia, heel, h),
                        follower.reduced_inertia_slope(inertia, heel, h))


def build_train(dyn, valve, law, drive, at, cam_speed=None) -> tuple[Union[OneMassTrain, MultiMassTrain], DynamicsParameters]:
    """The train of a valve: (train, DynamicsParameters).  ``drive`` is the drive stage's DriveResults.

    ``cam_speed`` (rated camshaft speed [rad/s]) is needed when [dynamics] gives a preload without a rate.
    """
    k = valve.rocker_ratio
    lash = 0.0 if valve.lash_adjuster is not None else k * law.ramp_height   # a hydraulic quieting ramp lifts the valve
    line = drive.lines.chosen
    links, names, notes = drive_links(dyn, valve, lever_ratio(valve, law), at)
    element = None
    if valve.lash_adjuster is not None:
        adjuster, adjuster_note, element = adjuster_link(valve, law, drive, cam_speed, at)
        links = (float(series(links[0], adjuster)),) + links[1:]
        notes.append(adjuster_note)
    c = float(series(*links))
    arm, arm_note = inertia_arm(valve, law, drive)
    variable = None
    if dyn.mass_kg is None:
        mass = float(drive.masses.at_valve)
        if arm_note:
            inertia = valve.drive.masses.rocker_inertia
            mass += inertia / arm**2 - inertia / valve_arm(valve)**2
            if dyn.model == "1dof":
                variable = _finger_node(valve, law, "valve", mass - inertia / arm**2, lash)
        notes.insert(0, NoteText(note("dynamics.mass_of_spring_design_finger" if arm_note else
                                      "dynamics.mass_of_spring_design", mass_kg=mass)))
    else:
        mass = float(dyn.mass_kg)
        notes.insert(0, NoteText(note("dynamics.mass_given", mass_kg=mass)))
    if arm_note:
        notes.insert(1, arm_note)
        if dyn.model == "multi":
            variable = _finger_node(valve, law, next(link.name for link in chain(valve).links if link.lever))
        if variable is not None:
            lightest, heaviest = variable.mass.min() * 1e3, variable.mass.max() * 1e3
            notes.insert(2, NoteText(note("dynamics.finger_node_mass", lightest_g=lightest, heaviest_g=heaviest)))
    rate, preload, spring_note = train_spring(dyn, valve, law, line, mass, cam_speed, at)
    notes.append(spring_note)
    notes.append(NoteText(note("dynamics.lash", lash_mm=lash / MM))
                 if valve.lash_adjuster is None or law.ramp_height == 0.0 else
                 NoteText(note("dynamics.no_lash", ramp_mm=law.ramp_height / MM)))
    kw = dict(damping_ratio=dyn.damping_ratio, seat_stiffness=dyn.seat_stiffness,
              seat_damping_ratio=dyn.seat_damping_ratio)
    nodes = None
    if dyn.model == "1dof":
        train = one_mass_train(mass, c, rate, preload, k, lash, **kw)
    else:
        springs, spring_notes = multi_springs(dyn, drive.spring, rate, preload)
        train = _multi_train(valve, links, springs, lash, kw, at, arm)
        net = train.network()
        nodes = {n: float(m) for n, m in zip(net.names, net.mass, strict=True)}
        notes.extend(spring_notes)
    train = replace(train, adjuster=element, variable_mass=variable)
    params = DynamicsParameters(dyn.model, layout(valve), mass, c, dyn.damping_ratio, rate, preload, k, lash,
                                dyn.seat_stiffness, dyn.seat_damping_ratio, revolutions(dyn, valve), dyn.step,
                                dyn.coils_per_spring, links, names, nodes, tuple(notes))
    return train, params


def _finger_node(valve, law, node, rest=0.0, offset=0.0) -> VariableMass:
    """:func:`finger_mass` of the valve's finger (SI view) on its law's heel circle, r0 - the ramp height."""
    return finger_mass(follower_of(valve.cam), valve.drive.masses.rocker_inertia,
                       valve.cam.base_radius - law.ramp_height, law.lift_max + law.ramp_height, node, rest, offset)


def _multi_train(valve, links, springs, lash, kw, at, arm):
    """The multi-mass train of the valve's layout from its links, from the cam: each link's node (:meth:`Link.node
    <valvetrain.links.Link.node>`, the part masses of [drive.masses] reduced to the valve, a rocker's inertia on the
    valve arm ``arm`` [m] of :func:`inertia_arm`, a valve bridge's mass per valve), then the valve's; between them the
    drive's stiffnesses ``links`` at the valve in the order of :func:`drive_links` (the camshaft, each elastic link's
    on the cam side, the last lever's joint to the valve, each elastic link's at the valve) in series, an elastic
    link's as two halves of twice its stiffness on either side of its node."""
    m, drive = valve.drive.masses, chain(valve)
    need = drive.train_masses
    if m is None:
        raise SpecError([Problem(f"{at}.dynamics.model",
                                 NoteText(note("spec.multi_masses", at=at, keys=", ".join(need))), '"multi"', " ")])
    missing = [key for link in drive.links for key in link.missing(m, arm)]
    if missing:
        raise SpecError([Problem(f"{at}.dynamics.model", NoteText(note("spec.multi_missing", layout=drive.name,
                                                                       keys=", ".join(missing))), '"multi"', " ")])
    k = valve.rocker_ratio
    values = iter(links)
    nodes, stiffness, between = [], [], [next(values)]   # between: the stiffnesses since the last node [N/m at the valve]
    joined = False                                        # the last lever's joint to the valve taken
    for link in drive.links:
        if link.at_valve and not joined:
            between.append(next(values))
            joined = True
        node = link.node(m, k, arm)
        own = [next(values)] if link.elastic else []
        if node is None:
            between += own
            continue
        half = [2.0 * c for c in own]   # an elastic link's mass at its middle between two halves of twice its stiffness
        nodes.append(node)
        stiffness.append(series(*between, *half))
        between = half
    if not joined:
        between.append(next(values))
    nodes.append(("valve", m.valve_kg + m.retainer_kg + m.cotters_kg))
    stiffness.append(series(*between))
    return MultiMassTrain(drive.name, tuple(nodes), tuple(stiffness), tuple(springs), float(k), float(lash), **kw)


POOR_FILM_BAND = (0.4, 0.6)
"""Band of the lubrication characteristic gamma around 0.5 where (2.12) gives no film (Shang Hanji (1988), eq. (2.12):
h_min vanishes at gamma = 0.5); the width of the band is this package's choice."""


def rated_contact(r, law, heel_radius, follower, width, modulus) -> dict[str, float]:
    """The cam contact at one speed under the simulated force: Hertz stress, lubrication characteristic, drive torque.

    Parameters
    ----------
    r : valvetrain.dynamics.sweep.SpeedResult
    law : LiftLaw
    heel_radius : float
        Circle the law's lift starts from [m].
    follower : valvetrain.followers.Follower
        The cam's follower (the lubrication characteristic where it has one).
    width : float or None
        Cam width [m]; None: no stress.
    modulus : float
        Effective contact modulus E_m [Pa].

    Returns
    -------
    dict
        Fields of :class:`SpeedRecord` (SI): stress [Pa] and its angle [rad], gamma at the nose, at the largest stress,
        the angle [rad] of loaded contact with gamma in :data:`POOR_FILM_BAND`, and the largest, smallest and mean
        drive torque [N m].

    References
    ----------
    Shang Hanji (1988), eqs. (2.5), (2.12) and section 3.4 (the dynamic force); the torque F dh/dtheta from the power
    balance of a frictionless follower.
    """
    from ..dynamics.contact import dynamic_contact_stress, lubrication_characteristic

    theta, force = r.theta, r.contact_force
    out = {"max_drive_torque": float(r.torque.max()), "min_drive_torque": float(r.torque.min()),
           "mean_drive_torque": float(r.torque.mean())}
    j = None
    if width is not None:
        sigma = dynamic_contact_stress(law, theta, force, heel_radius, width, modulus, follower)
        j = int(np.argmax(sigma))
        out.update(max_contact_stress=float(sigma[j]), max_contact_stress_angle=float(theta[j]))
    gamma = lubrication_characteristic(law, theta, heel_radius, follower)
    if gamma is not None:
        loaded = (force > 0.0) & (law.lift(theta) > 0.0)
        poor = loaded & (gamma >= POOR_FILM_BAND[0]) & (gamma <= POOR_FILM_BAND[1])
        step = float(theta[-1] - theta[0]) / (theta.size - 1)   # not theta[1] - theta[0], the difference at -pi
        out.update(lubrication_gamma_nose=float(gamma[int(np.argmin(np.abs(theta)))]),
                   lubrication_near_half=float(poor.sum() * step))
        if j is not None:
            out["lubrication_gamma_at_max_stress"] = float(gamma[j])
    return out


def swept_range(dyn, engine) -> tuple[float, float]:
    """The engine speeds [rad/s] a ``[dynamics]`` section sweeps, (low, high): its ``speed_range``, else
    :data:`SPEED_RANGE` of the rated speed."""
    if dyn.speed_range is None:
        return tuple(f * engine.rated_speed for f in SPEED_RANGE)
    return tuple(dyn.speed_range)


def sweep_excess(network, cam_speeds, revs, step_deg) -> tuple | None:
    """``None`` where a sweep of ``network`` at ``cam_speeds`` [rad/s] for ``revs`` revolutions at ``step_deg``
    [cam deg] is within :data:`MAX_SWEEP_WORK` and :data:`MAX_SWEEP_BYTES`, else what it would take against them
    (a note: ``"about 1e+10 integrator steps x elements (allowed 2e+09) and ..."``), said in every refusal of a
    sweep."""
    work, size = sweep_size(network, cam_speeds, revs, step_deg)
    if work <= MAX_SWEEP_WORK and size <= MAX_SWEEP_BYTES:
        return None
    return note("spec.sweep_size", work=work, most_work=MAX_SWEEP_WORK, megabytes=size / 1e6,
                most_megabytes=MAX_SWEEP_BYTES / 1e6)


def refuse_large_sweep(dyn, train, cam_speeds, revs, key, asked) -> None:
    """Refuse a sweep of ``train`` at ``cam_speeds`` [rad/s] for ``revs`` revolutions at the step of ``[dynamics]``
    ``dyn`` estimated above :data:`MAX_SWEEP_WORK` or :data:`MAX_SWEEP_BYTES` (:func:`sweep_excess`) without
    ``allow_large_sweep``: a :class:`SpecError` under ``key`` that says what ``asked`` for it (``"speeds = 200"``)."""
    step_deg = dyn.step / DEG
    excess = None if dyn.allow_large_sweep else sweep_excess(train.network(), cam_speeds, revs, step_deg)
    if excess:
        raise SpecError([Problem(key, NoteText(note("spec.large_sweep", asked=asked, revolutions=revs, step=step_deg,
                                                    excess=excess)))])


def valve_motion(dyn, valve, engine, law, drive, speeds, at, key) -> SweepResult:
    """The motion of a valve's ``[dynamics]`` train at each engine speed of ``speeds`` [rad/s], the train built as
    :func:`dynamics_stage` builds it: one :func:`~valvetrain.dynamics.sweep.sweep`, each speed integrated until its
    revolution repeats (its last revolution recorded), with the drive's deflection, the follower's separation and the
    valve's bounce.

    Parameters
    ----------
    dyn, valve, engine : SI views of ``[valves.NAME.dynamics]``, the valve and the engine.
    law : LiftLaw
        The valve's cam.
    drive : DriveResults
        The drive stage (reduced mass, designed spring).
    speeds : array_like
        Engine speeds [rad/s].
    at : str
        The valve's key (``valves.NAME``: a train that cannot be built).
    key : str
        The key that asks for the speeds, named where the sweep is too large (:func:`refuse_large_sweep`).

    Returns
    -------
    SweepResult
        Camshaft speeds and angles [rad from the nose]; ``lift`` per speed [m].
    """
    to_cam = cam_per_crank(engine.strokes)
    train, params = build_train(dyn, valve, law, drive, at, engine.rated_speed * to_cam)
    cam_speeds = np.asarray(speeds, dtype=float) * to_cam
    refuse_large_sweep(dyn, train, cam_speeds, params.revolutions, key, f"{cam_speeds.size} speeds")
    return sweep(law, train, cam_speeds, params.revolutions, dyn.step / DEG)


def dynamics_stage(dyn, valve, engine, law, drive, name="valve", progress=None, cam=None,
                   load_range=None) -> tuple[DynamicsResult, list[Check]]:
    """Sweep the elastic train of a valve over its speed range and simulate the rated speed.

    Parameters
    ----------
    dyn : SI view of ``[valves.NAME.dynamics]``.
    valve, engine : SI views of the valve and the engine.
    law : LiftLaw
        The valve's cam.
    drive : DriveResults
        The drive stage (reduced mass, designed spring).
    name : str
        The valve's name (the CSV table's name and the messages' keys).
    progress : callable, optional
        ``progress(done, total)`` after each chunk of speeds.
    cam : CamResult, optional
        The law stage (heel and roller radii): with it the rated speed has the dynamic contact stress, the
        lubrication characteristic and the drive torque.
    load_range : (float, float), optional
        The engine speeds [rad/s] whose cam force loads the parts (the strength stage's range).  Given, a one-mass
        train simulates only the speeds of its range that decide the jump speed, the largest seating velocity (of
        the range and up to the rated speed) and the largest cam force in ``load_range``
        (:func:`~valvetrain.dynamics.sweep.headline_sweep`, the rated speed in its first sweep; a tolerance study's
        samples): the per-speed table and the maps then have those speeds alone, the bounce onset speed is theirs,
        not refined (no check reads it), and ``progress`` is not called.  A multi-mass train is swept in full:
        with coil surge its separations and forces come and go from one speed to the next (the built-in example's,
        200 speeds: a first separation 20 % below the one the coarse grid finds, a cam stress 7 % above the largest
        it finds).

    Returns
    -------
    (DynamicsResult, list of Check)

    Raises
    ------
    SpecError
        A multi-mass train without the part masses it needs, a drive stiffness above that of its parts, or a sweep
        estimated above :data:`MAX_SWEEP_WORK` or :data:`MAX_SWEEP_BYTES` without ``allow_large_sweep``.
    """
    at = f"valves.{name}"
    to_cam = cam_per_crank(engine.strokes)
    train, params = build_train(dyn, valve, law, drive, at, engine.rated_speed * to_cam)
    notes = list(params.estimates)
    low, high = swept_range(dyn, engine)
    if dyn.speed_range is None:
        notes.append(NoteText(note("dynamics.speed_range", low_rpm=low / rpm_to_rad_s(1.0),
                                   high_rpm=high / rpm_to_rad_s(1.0), low_share=SPEED_RANGE[0],
                                   high_share=SPEED_RANGE[1])))
    params = replace(params, estimates=tuple(notes))
    speeds = np.linspace(low, high, dyn.speeds)
    step_deg = dyn.step / DEG
    revs = params.revolutions
    refuse_large_sweep(dyn, train, speeds * to_cam, revs, f"{at}.dynamics", f"speeds = {dyn.speeds}")
    few = load_range is not None and dyn.model == "1dof"
    if few:
        result, rated_sweep = headline_sweep(law, train, speeds * to_cam, revs, step_deg,
                                             load_range=tuple(s * to_cam for s in load_range),
                                             seating_top=engine.rated_speed * to_cam,
                                             extra=[engine.rated_speed * to_cam],
                                             levels=() if train.adjuster is None else
                                             (train.adjuster.push * valve.rocker_ratio,))
        speeds = result.cam_speeds / to_cam
    else:
        if progress is not None:
            progress(0, dyn.speeds)
        result = sweep(law, train, speeds * to_cam, revs, step_deg, progress=progress)
        rated_sweep = sweep(law, train, [engine.rated_speed * to_cam], revs, step_deg)
    rated = rated_sweep.speed(0)
    refined = refine(law, train, result, revs, step_deg, seating_top=engine.rated_speed * to_cam, extra=rated_sweep,
                     onset=not few)
    m, c, kk = params.mass, params.drive_stiffness, params.spring_rate
    eps = perturbation_parameter(m, c, kk, speeds * to_cam)
    per = speed_records(result, speeds, eps, refined.events)
    head = refined.headline
    res = resonance(law, engine.rated_speed * to_cam, m, kk, c, valve.rocker_ratio)
    reson = ResonanceRecord(res.omega0 / (2 * np.pi), res.order, res.force, res.amplitude, 100 * res.distortion,
                            tuple(int(o) for o in res.orders), tuple(100 * float(d) for d in res.spectrum_distortion))
    table = PerSpeed(tuple(per.speed.tolist()), tuple(per.min_contact_force.tolist()),
                     tuple(finite_or_none(v) for v in per.seating_velocity.tolist()), tuple(per.bounce.tolist()),
                     tuple(per.bounce_count.tolist()), tuple(per.jump.tolist()), tuple(per.max_lift_error.tolist()),
                     tuple(per.revolutions.tolist()))
    net = train.network()
    omegas, shapes = natural_modes(net, opened=("seat",))
    modes = tuple(Mode(float(w / (2 * np.pi)), {n: float(x) for n, x in zip(net.names, shapes[:, j], strict=True)})
                  for j, w in enumerate(omegas))

    def crank(cam_speed):
        return float(cam_speed / to_cam)

    eps_rated = float(perturbation_parameter(m, c, kk, engine.rated_speed * to_cam))
    fine = refined.extra
    rated_record = replace(speed_record(rated, engine.rated_speed, eps_rated),
                           seating_velocity=float(fine.seating_velocity[0]), bounce=float(fine.bounce_height[0]),
                           bounce_count=int(fine.bounce_count[0]))
    a = refined.accuracy
    accuracy = AccuracyRecord(crank(a.jump_speed), crank(a.jump_speed_step), crank(a.jump_speed_grid),
                              crank(a.bounce_onset), crank(a.bounce_onset_step), crank(a.bounce_onset_grid),
                              a.max_seating_velocity, float(refined.extra_seating_error[0]),
                              float(refined.extra_bounce_error[0]), a.step)
    if cam is not None:
        rated_record = replace(rated_record, **rated_contact(rated, law, cam.heel_radius, cam.follower_model,
                                                             valve.parts.cam_width, valve.parts.contact_modulus))
    out = DynamicsResult(
        dyn.model, params, (float(low), float(high)), int(dyn.speeds), crank(head["jump_speed"]),
        crank(head["bounce_onset_speed"]), head["max_seating_velocity"], crank(head["max_seating_velocity_speed"]),
        crank(head["coil_clash_speed"]) if dyn.model == "multi" else None, eps_rated,
        modes[0].frequency, tuple(mode.frequency for mode in modes), modes,
        int(result.revolutions.max()), int(np.count_nonzero(~result.converged)),
        unsettled_note(result, speeds, net, revs, train.adjuster is not None), accuracy, rated_record, reson, table,
        f"tables/{name}_dynamics.csv", result, per, rated, refined)
    return out, dynamics_checks(out, engine, 0.0 if train.adjuster is None else train.adjuster.motion_ratio)


__all__ = ["build_train", "drive_links", "dynamics_stage", "rated_contact", "refuse_large_sweep", "sweep_excess",
           "swept_range", "valve_motion"]
