"""The valve stages' recommended bands and checks: the bands of each drive layout and engine class, the law's,
flow's, timing's and profile's checks of a valve, the specific mass, the valve-to-piston gap and the finger's pad on
the valve tip (Valve-train practical works (n.d.), works 1, 2 and 5; Shang Hanji (1988), section 2.1).

The stages of :mod:`valvetrain.design.valve` compute; this module compares their results with the ranges.
"""

from dataclasses import dataclass, replace
import math
from typing import Optional


from .. import flow
from ..checks import Check, check
from ..layouts import LAYOUTS, layout
from ..locale import Note, cited, note, note_text
from ..units import DEG, MM


ACCELERATION_LIMITS = (3500.0, -1500.0)
"""Upper ends of the recommended bands of positive (1500-3500) and negative (500-1500) tappet
acceleration [m/s^2] (Valve-train practical works (n.d.), work 2)."""


@dataclass(frozen=True)
class Band:
    """A recommended range of one layout: bounds (SI, None open), its source and, where the source states it for
    another layout, the note that says so (:func:`valvetrain.locale.note`'s parts)."""

    low: float = None
    high: float = None
    source: str = ""
    note: Note = ()


_FOR_DIRECT = {"rocker": "band.acceleration_for_direct_rocker", "pushrod": "band.acceleration_for_direct_pushrod"}
"""The note of the acceleration band of each layout but direct drive, for which the source states it."""
_WORK_2 = "Valve-train practical works (n.d.), work 2"
_WORK_5 = "Valve-train practical works (n.d.), work 5"

LAYOUT_BANDS = {
    "tappet_acceleration.max": {
        layout: Band(high=ACCELERATION_LIMITS[0], source=cited(note("source.positive_acceleration", work=_WORK_2)),
                     note=() if layout == "direct" else note(_FOR_DIRECT[layout]))
        for layout in LAYOUTS},
    "tappet_acceleration.min": {
        layout: Band(low=ACCELERATION_LIMITS[1], source=cited(note("source.negative_acceleration", work=_WORK_2)),
                     note=() if layout == "direct" else note(_FOR_DIRECT[layout]))
        for layout in LAYOUTS},
    "drive.rocker_ratio": {
        layout: Band(1.4, 1.75, cited(note("source.rocker_ratio", work=_WORK_2))) for layout in ("rocker", "pushrod")
    },
    "drive.specific_mass": {
        "direct": Band(200.0, 300.0, cited(note("source.direct_specific_mass", work=_WORK_5))),
        "rocker": Band(200.0, 300.0, cited(note("source.direct_specific_mass", work=_WORK_5)),
                       note("band.specific_mass_rocker")),
        "pushrod": Band(400.0, 500.0, cited(note("source.pushrod_specific_mass", work=_WORK_5))),
    },
}
"""The recommended ranges that depend on the drive layout, ``check code -> {layout: Band}``; a layout missing from a
code's table has no such check (direct drive has no rocker: its ratio 1 is refused otherwise at validation).
The valve arrangement of Valve-train practical works (n.d.), work 1 (throat diameter / bore "при нижнем/верхнем расположении клапанов",
side valves or overhead valves) is the combustion chamber's, ``[engine] chamber``
(:data:`valvetrain.flow.THROAT_TO_BORE_RANGES`)."""


def layout_check(code, value, layout, **kw) -> Optional[Check]:
    """The check ``code`` against the band of ``layout`` (:data:`LAYOUT_BANDS`), or None where the layout has
    no such band; the band's note, if any, becomes the check's note."""
    band = LAYOUT_BANDS[code].get(layout)
    if band is None:
        return None
    return check(code, value, band.low, band.high, source=band.source, note=band.note or "", **kw)

PETROL_BANDS = ("timing.opening_advance", "timing.closing_lag", "valve.seat_angle", "valve.clearance",
                "drive.rocker_ratio")
"""The checks whose recommended bands are those of a petrol engine (Valve-train practical works (n.d.), works 1 and 2:
the manual designs a petrol engine's valve train, its appendix a Kurz cam for one)."""

PETROL_ONLY = {"automotive_diesel": "band.petrol_only_automotive_diesel", "heavy_duty": "band.petrol_only_heavy_duty"}
"""The note of a petrol engine's band for an engine of another class (``[engine] engine_class``): the cited works
give none for it, the check a remark."""


def engine_class(engine) -> str:
    """The engine class whose recommended bands apply: ``[engine] engine_class``, else an automotive diesel for
    ``type = "diesel"`` and an automotive petrol engine otherwise."""
    if engine.engine_class is not None:
        return engine.engine_class
    return "automotive_diesel" if engine.type == "diesel" else "automotive_petrol"


def for_engine_class(checks, engine) -> list[Check]:
    """The checks with the petrol engine's bands (:data:`PETROL_BANDS`) made remarks (info) with a note where the
    engine is of another class: a rocker ratio of 1 or a 40 crank deg advance of a locomotive diesel is no warning
    against a petrol engine's band.  (These checks' own notes are codes or empty: the remark joins their parts.)"""
    cls = engine_class(engine)
    if cls == "automotive_petrol":
        return checks
    remark = note(PETROL_ONLY[cls])
    return [replace(c, severity="info", note=note_text(c.note_parts + remark), note_parts=c.note_parts + remark)
            if c.code in PETROL_BANDS and c.severity == "warning" else c for c in checks]


TIMING_RANGES = {"intake": ((20.0 * DEG, 30.0 * DEG), (40.0 * DEG, 60.0 * DEG))}
"""Recommended inlet opening advance and closing lag [crank rad] (Valve-train practical works (n.d.), work 2: 20-30 and 40-60 crank deg)."""

CLEARANCE_RANGES = {"intake": (0.25 * MM, 0.35 * MM), "exhaust": (0.35 * MM, 0.50 * MM)}
"""Recommended valve clearance h0 [m] (Valve-train practical works (n.d.), work 2)."""

SEAT_ANGLE_USUAL = {"intake": (30.0 * DEG, 30.0 * DEG), "exhaust": (45.0 * DEG, 45.0 * DEG)}
"""Usual seat angles [rad] (Valve-train practical works (n.d.), work 1: 30 deg inlet, 45 deg exhaust)."""

BASE_RADIUS_TO_LIFT_RANGE = (1.5, 4.0)
"""r0 / valve lift: 1.5-2.0 naturally aspirated, up to 3.0-4.0 supercharged (Valve-train practical works (n.d.), work 2)."""

RHO_MIN = 2.0 * MM
"""Smallest recommended radius of curvature of the cam profile [m] (Shang Hanji (1988), section 2.1)."""

SEATING_VELOCITY_MAX = 0.5
"""Working limit of the valve's seating velocity at rated speed [m/s] (no primary source;
0.3-0.5 m/s is working guidance)."""

SEATING_VELOCITY_SOURCE = cited(note("source.seating_guidance", work=_WORK_2))

THROAT_AREA_SHARE_RANGE = (0.25, 0.40)
"""Inlet plus exhaust throat areas as a share of the piston area (Valve-train practical works (n.d.), work 1)."""

PISTON_CLEARANCE_MIN = {"intake": 0.080 * 25.4 * MM, "exhaust": 0.100 * 25.4 * MM}
"""Smallest recommended valve-to-piston gap [m]: 0.080 in intake, 0.100 in exhaust (the exhaust valve is hotter and
chased by the rising piston); Shang's (2.13) only demands a gap > 0."""

PISTON_CLEARANCE_SOURCE = cited(note("source.piston_clearance_rule"),
                                note("source.piston_gap", work="Shang Hanji (1988), section 2.1, eqs. (2.13)-(2.14)"))

MAX_LIFT_TO_THROAT = 0.5
"""Largest valve lift / throat diameter a design may have.  The curtain area pi d y equals the throat area at
y = d/4 (Valve-train practical works (n.d.), eq. 1.3 with the seat cone neglected), the recommended lift is 0.18-0.30 d (Valve-train practical works (n.d.), work 2); a
lift of more than half the throat is no valve design."""


STEM_TO_THROAT = 0.2
"""The valve stem's diameter over the throat's where ``parts.stem_diameter_mm`` is not given: a stated default, not a
source's (5.5-6 mm stems of 28-30 mm car throats, 10-11 mm of 45-50 mm truck throats; the smaller share, so that the
tip is not overstated)."""

TIP_EDGE_MARGIN = 0.5e-3
"""How far inside the valve tip's edge the pad's contact must stay [m]: the tip's chamfer and the contact's own
half-width (an engineering limit of this package; no published limit of the contact's place was found)."""


def tip_contact_check(finger, valve) -> Check:
    """The finger's pad on the valve tip (a failure): the largest distance of its contact point from the valve axis
    over the lift (:class:`~valvetrain.followers.finger.FingerKinematics` ``tip_reach``, which bounds its travel, the scrub) against the tip's
    radius, half the stem's diameter, less :data:`TIP_EDGE_MARGIN`.

    Parameters
    ----------
    finger : FingerKinematics
    valve : SI view of the valve (its ``parts.stem_diameter`` [m], else :data:`STEM_TO_THROAT` x the throat).

    Notes
    -----
    The contact point is :math:`L_b(\\cos\\chi - \\cos\\chi_0) + x_0` across the valve axis
    (:meth:`~valvetrain.followers.PivotedFollower.tip_contact`; Wang (2007), the contact travel on the valve tip);
    a pad that pushes beyond the tip's flat face presses on its chamfer or beside the valve: no working finger.  The
    limit is an engineering one, stated: the tip's radius less 0.5 mm.
    """
    given = valve.parts.stem_diameter
    stem = given if given is not None else STEM_TO_THROAT * valve.throat_diameter
    where = (note("finger.stem_given", stem_mm=stem / MM) if given is not None else
             note("finger.stem_default", stem_mm=stem / MM, share=STEM_TO_THROAT))
    return check("finger.tip_contact", finger.tip_reach, high=max(stem / 2.0 - TIP_EDGE_MARGIN, 0.0), unit="mm",
                 severity="failure", source=cited(note("source.tip_edge", margin_mm=TIP_EDGE_MARGIN / MM),
                              note("source.contact_travel", work="Wang (2007)")),
                 note=where + note("finger.tip_travel", scrub_mm=finger.scrub / MM, shut_mm=finger.tip_contact[0] / MM,
                                   open_mm=finger.tip_contact[1] / MM))


def clearance_check(kind, gap, angle, window=None) -> Check:
    """The check of a valve-to-piston gap [m] at a crank angle [rad] against :data:`PISTON_CLEARANCE_MIN`, over the
    open event or, with ``window`` (crank rad from the gas-exchange TDC), over the valve overlap.  A gap below the
    minimum is a failure: the valve may touch the piston at over-speed, with lash or with valve float."""
    said = (note("piston.smallest_at", crank_deg=math.degrees(angle)) if window is None else
            note("piston.smallest_at_overlap", crank_deg=math.degrees(angle), from_deg=math.degrees(window[0]),
                 to_deg=math.degrees(window[1])))
    return check("piston.clearance" if window is None else "piston.clearance_overlap", gap,
                 low=PISTON_CLEARANCE_MIN[kind], unit="mm", source=PISTON_CLEARANCE_SOURCE, severity="failure",
                 note=said)


def overlap_clearance_checks(valves) -> list[Check]:
    """The valve-to-piston gap of each valve over the overlap, from the first intake opening to the last exhaust
    closing (crank angles from the gas-exchange TDC), where the piston is nearest the open valves.

    ``valves`` maps names to :class:`~valvetrain.design.valve.ValveDesign`; no check without an intake and an exhaust valve that overlap.
    """
    opens = [v.cam.valve_opens for v in valves.values() if v.kind == "intake"]
    closes = [v.cam.valve_closes for v in valves.values() if v.kind == "exhaust"]
    if not opens or not closes or min(opens) >= max(closes):
        return []
    window = (min(opens), max(closes))
    out = []
    for name, v in valves.items():
        found = None if v.clearance is None else v.clearance.within(*window)
        if found is not None:
            out.append(clearance_check(v.kind, *found, window).of_valve(name))
    return out


def valve_checks(cam, flow_result, profile, valve, engine, timing) -> list[Check]:
    """The recommended-range checks of the law, the flow, the timing and the profile (every check, passed or not).

    ``timing`` is the opening advance and closing lag [crank rad] of the main lift (None where not defined).  The
    acceleration and rocker-ratio bands are those of the valve's drive layout (:data:`LAYOUT_BANDS`); the petrol
    engine's bands are remarks for an engine of another class (:func:`for_engine_class`).
    """
    law, i_k = cam.law, cam.rocker_ratio
    out = law.checks()
    out += flow.check_flow(valve.kind, bore=engine.bore, throat_diameter=valve.throat_diameter,
                           max_lift=flow_result.valve_lift, v1=flow_result.v1, v2=flow_result.v2, v3=flow_result.v3,
                           charge_velocity=flow_result.charge_velocity, engine_type=engine.type,
                           chamber=engine.chamber, count=valve.count)
    drive, follower = layout(valve), cam.follower_model
    low, high = follower.acceleration_range(cam)
    out.append(layout_check("tappet_acceleration.max", high, drive, unit="m/s2"))
    out.append(layout_check("tappet_acceleration.min", low, drive, unit="m/s2"))
    if valve.kind in TIMING_RANGES:
        for label, angle, (lo, hi) in zip(("timing.opening_advance", "timing.closing_lag"), timing, TIMING_RANGES[valve.kind],
                                          strict=True):
            if angle is not None:
                out.append(check(label, angle, lo, hi, source="Valve-train practical works (n.d.), work 2", unit="crank deg"))
    if law.clearance_on_flank:
        out.append(check("seating_velocity.without_ramp", cam.seating_velocity,
                         high=SEATING_VELOCITY_MAX, source=SEATING_VELOCITY_SOURCE, unit="m/s",
                         note=note("valve.ramp_not_clearance", clearance_mm=valve.clearance / MM)))
    out.append(check("valve.seat_angle", valve.seat_angle, *SEAT_ANGLE_USUAL[valve.kind],
                     source=cited(note("source.usual_seat_angles", work="Valve-train practical works (n.d.), work 1")), unit="deg", severity="info"))
    if valve.lash_adjuster is None:  # a hydraulic lash adjuster leaves no clearance (validated: clearance_mm = 0)
        out.append(check("valve.clearance", valve.clearance, *CLEARANCE_RANGES[valve.kind],
                         source="Valve-train practical works (n.d.), work 2", unit="mm"))
    ratio = layout_check("drive.rocker_ratio", i_k * follower.rest_ratio(cam.heel_radius), drive)
    if ratio is not None:
        out.append(ratio)
    out.append(check("cam.base_radius_to_lift", cam.base_radius / flow_result.valve_lift, *BASE_RADIUS_TO_LIFT_RANGE,
                     source=cited(note("source.base_radius_to_lift", work=_WORK_2))))
    if profile.undercut:
        out.append(check(follower.undercut_code, profile.rho_min, low=0.0, strict_low=True,
                         source=follower.undercut_source, unit="mm", severity="failure"))
    out += follower.profile_checks(profile.contact)
    if not profile.undercut:
        out.append(check("profile.rho_min", profile.rho_min, low=RHO_MIN, source="Shang Hanji (1988), section 2.1",
                         unit="mm"))
    if profile.finger is not None:
        out.append(tip_contact_check(profile.finger, valve))
    return for_engine_class(out, engine)


def mass_checks(valve, mass, throat_area) -> list[Check]:
    """The specific mass of the drive m' = m_v / f_g [kg/m2] against the band of the valve's layout (Valve-train practical works (n.d.), work 5),
    an ``info`` check: only where the masses or m' are given (the default m' is this project's, not the source's,
    whose bands are 1.6-3.7 times the masses of the example's parts)."""
    d = valve.drive
    if d.masses is None and d.specific_mass_kg_m2 is None:
        return []
    c = layout_check("drive.specific_mass", mass / throat_area, layout(valve), unit="kg/m2",
                     severity="info")
    return [] if c is None else [c]
