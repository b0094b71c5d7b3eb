"""The checks of a valve's dynamics stage (:mod:`valvetrain.design.dynamics`): the largest seating velocity up to the
rated speed, the follower separation (jump speed), a valve that stays on its seat; and the note on speeds whose motion
did not repeat.
"""

from typing import Optional

import numpy as np

from ..checks import Check, check
from ..dynamics.events import BOUNCE_TOLERANCE
from ..dynamics.models import slowest_decay
from ..dynamics.sweep import STATE_TOLERANCE
from ..locale import NoteText, cited, note
from ..units import MM, rpm_to_rad_s, to_display

CHECK_SOURCE = "Shang Hanji (1988), ch. 3"
"""Short citation of the dynamics checks."""

SEATING_VELOCITY_MAX = 0.5
"""Working limit of the seating velocity [m/s] (0.3-0.5 m/s in the valve-train literature)."""

SETTLE_FROM = 1e-3
"""The amplitude [m] from which :func:`unsettled_note` counts the revolutions a vibration takes to fall to the
repetition's tolerance (:data:`~valvetrain.dynamics.sweep.STATE_TOLERANCE`)."""


def unsettled_note(result, speeds, network, revolutions, adjuster=False) -> Optional[NoteText]:
    """Why the speeds of a sweep whose motion did not repeat within ``revolutions`` did not; None where every speed
    repeated.

    Parameters
    ----------
    result : valvetrain.dynamics.sweep.SweepResult
    speeds : ndarray (S,)
        Its engine speeds [rad/s].
    network : valvetrain.dynamics.models.Network
        The train simulated.
    revolutions : int
        The most camshaft revolutions a speed ran.
    adjuster : bool
        The train has a hydraulic lash adjuster.

    Returns
    -------
    NoteText or None
        How many speeds and their range, and the reasons (codes of ``[notes]``, its English the record's text): at the speeds whose follower separates or whose valve
        bounces, a motion that need not repeat; at the others the lash adjuster's plunger (a slow state), or the
        slowest vibration of the train between the lifts (:func:`~valvetrain.dynamics.models.slowest_decay`, the
        clearance open, the valve on its seat): its decay exp(-sigma T) a revolution of T seconds at the highest of
        those speeds (where it decays least) and the revolutions ln(:data:`SETTLE_FROM` / tolerance) / (sigma T) it
        takes there from a millimetre to the repetition's tolerance; or, where no damping acts on it (sigma = 0: an
        undamped seat, ``seat_damping_ratio = 0``, with the clearance open), that it does not decay.
    """
    bad = ~result.converged
    if not bad.any():
        return None
    rpm = speeds / rpm_to_rad_s(1.0)
    events = result.events
    moving = bad & (events.jumped | (events.bounce_count > 0))
    rest = bad & ~moving
    counts = {"count": np.count_nonzero(bad), "speeds": bad.size, "revolutions": revolutions}
    if np.ptp(rpm[bad]) > 0.0:
        parts = note("dynamics.unsettled_range", low_rpm=rpm[bad].min(), high_rpm=rpm[bad].max(), **counts)
    else:
        parts = note("dynamics.unsettled_at", speed_rpm=rpm[bad].min(), **counts)
    if moving.any():
        parts += note("dynamics.unsettled_moving", count=np.count_nonzero(moving))
    if rest.any() and adjuster:
        parts += note("dynamics.unsettled_adjuster", count=np.count_nonzero(rest))
    elif rest.any():
        omega, sigma = slowest_decay(network, opened=("cam contact",) if network.lash > 0.0 else ())
        decay = sigma * 2.0 * np.pi / result.cam_speeds[rest].max()
        if sigma <= 1e-9 * omega:       # a damping ratio below the eigenvalues' rounding: no damper acts on it
            parts += note("dynamics.unsettled_undamped", count=np.count_nonzero(rest),
                          frequency_Hz=omega / (2 * np.pi))
        else:
            parts += note("dynamics.unsettled_decay", count=np.count_nonzero(rest), frequency_Hz=omega / (2 * np.pi),
                          factor=np.exp(-decay), speed_rpm=rpm[rest].max(),
                          settle_revolutions=np.log(SETTLE_FROM / STATE_TOLERANCE) / decay, from_mm=SETTLE_FROM / MM,
                          tolerance_nm=STATE_TOLERANCE * 1e9)
    return NoteText(parts)


CHECK_CODES = ("dynamics.seating_velocity", "dynamics.jump_speed", "dynamics.valve_opens")
"""The codes of the dynamics checks."""

CLOSED = NoteText(note("dynamics.closed"))
"""Why the seating velocity of a valve that stays on its seat cannot be had."""

def worst_seating(d, engine) -> tuple[float, float]:
    """The largest |seating velocity| [m/s] of the rated speed and of the speeds swept up to it, and its engine speed
    [rad/s]; (NaN, NaN) where the valve does not seat at the rated speed (the check is then unevaluated, a failure).

    Notes
    -----
    The band of the sources (0.3-0.5 m/s) is stated at the rated speed; the motion of an elastic train is not
    monotonic in speed (a harmonic of the cam meeting the train's natural frequency raises the seating velocity at
    a lower speed), so every speed of the running range up to the rated one is graded by it.  The speeds above the
    rated one (to ``[engine] over_speed_ratio`` x it) are transient and graded by the separation check instead.
    """
    if not np.isfinite(d.at_rated_speed.seating_velocity):
        return np.nan, np.nan
    speeds = np.append(d.records.speed, engine.rated_speed)
    velocity = np.abs(np.append(d.records.seating_velocity, d.at_rated_speed.seating_velocity))
    velocity[speeds > engine.rated_speed * (1 + 1e-9)] = np.nan
    worst = int(np.nanargmax(velocity))
    return float(velocity[worst]), float(speeds[worst])


def dynamics_checks(d, engine, adjuster_ratio=0.0) -> list[Check]:
    """The largest seating velocity up to the rated speed (:func:`worst_seating`; a warning above its band) and
    the follower separation: a failure
    below ``[engine] over_speed_ratio`` x the rated speed; a valve that stays on its seat at a speed swept, a failure
    (:func:`opening_check`; ``adjuster_ratio`` the lash adjuster's motion ratio, 0 without one).

    Without a separation in the range the check takes the top of the range: a range that stops below the over-speed
    has not shown the valve keeps its cam there, and fails.
    """
    top = d.speed_range[1]
    jump = d.jump_speed if np.isfinite(d.jump_speed) else top
    no_jump = "" if np.isfinite(d.jump_speed) else note("dynamics.no_separation", speed_rpm=to_display(top, "rpm"))
    opened = float(d.rated.lift.max()) > BOUNCE_TOLERANCE
    seating, where = worst_seating(d, engine)
    if not np.isfinite(where):
        at = ""
    elif where < engine.rated_speed * (1 - 1e-9):
        at = note("dynamics.seating_largest_at", speed_rpm=to_display(where, "rpm")) + note(
            "dynamics.seating_at_rated", velocity_m_s=abs(d.at_rated_speed.seating_velocity))
    else:
        at = note("dynamics.seating_largest_at_rated")
    return [check(CHECK_CODES[0], seating, high=SEATING_VELOCITY_MAX, unit="m/s", note=at,
                  source=cited(CHECK_SOURCE, note("source.usual_seating_graded")),
                  unevaluated="" if opened else CLOSED),
            check(CHECK_CODES[1], jump / engine.rated_speed, low=engine.over_speed_ratio, severity="failure",
                  note=no_jump, source=cited(note("source.no_separation", work=CHECK_SOURCE)))] + opening_check(d, adjuster_ratio)


def opening_check(d, adjuster_ratio=0.0) -> list[Check]:
    """The check of a valve that stays on its seat at a speed swept (none where it opens at every speed).

    Parameters
    ----------
    d : DynamicsResult
    adjuster_ratio : float
        The lash adjuster's motion ratio i_a (valve motion per plunger motion; 0: none).

    Returns
    -------
    list of Check
        ``dynamics.valve_opens``: the smallest over the speeds swept of the valve's largest lift in the revolution
        [m], a failure not above :data:`~valvetrain.dynamics.events.BOUNCE_TOLERANCE` (below it the valve rocks on the
        seat's elasticity: it has not opened); its note names the speed and the reasons found: the drive's deflection
        under the spring preload F0 / c no less than the cam's lift at the valve (quasi-statically the cam cannot lift
        the valve off its seat), else with a lash adjuster its plunger giving way: a shut valve carries no more than
        its preload, so the drive deflects no more than F0 / c and the plunger's sink takes the rest of the cam's
        lift (the leak-down sinks it as fast as the cam lifts); its travel over the revolution at the valve,
        i_a (z_max - z_min), is said.
    """
    lifts = d.sweep.lift.max(axis=1)
    worst = int(np.argmin(lifts))
    if lifts[worst] > BOUNCE_TOLERANCE:
        return []
    p = d.parameters
    rigid = float(d.sweep.kinematic_lift.max())
    reasons = note("dynamics.rigid_lift", speed_rpm=to_display(d.per_speed.speed[worst], "rpm"), lift_mm=rigid / MM)
    deflection_mm = p.preload / p.drive_stiffness / MM
    if p.preload / p.drive_stiffness >= rigid:
        reasons += note("dynamics.preload_deflection", deflection_mm=deflection_mm, preload_N=p.preload)
    elif adjuster_ratio > 0.0:
        travel = adjuster_ratio * float(np.ptp(d.sweep.adjuster_extension[worst]))
        reasons += note("dynamics.adjuster_gives_way", deflection_mm=deflection_mm, travel_mm=travel / MM)
    return [check(CHECK_CODES[2], float(lifts[worst]), low=BOUNCE_TOLERANCE, unit="mm", severity="failure",
                  note=reasons, source=cited(note("source.seat_rocking", work=CHECK_SOURCE,
                                                       tolerance_mm=BOUNCE_TOLERANCE / MM)))]


__all__ = ["CHECK_CODES", "dynamics_checks", "opening_check", "unsettled_note", "worst_seating"]
