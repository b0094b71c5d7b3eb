"""A cam without a ramp takes up the valve clearance on its flanks (laws/takeup.py): the valve leaves and meets its
seat where the follower's lift reaches the clearance, at the flank's velocity there (Valve-train practical works
(n.d.), work 2: the ramp exists to limit that velocity)."""

import numpy as np
import pytest

from valvetrain.laws.convex import ThreeArcLaw
from valvetrain.laws.errors import LawError
from valvetrain.laws.kurz import KurzLaw
from valvetrain.laws.takeup import ClearanceTakeUp

R0, H, HALF, R2, H0 = 0.01975, 0.0065, np.radians(71.0), 0.004, 0.00025


def _flank_offset():
    """r1 - r0 of the three-arc cam by hand: the flank circle's centre lies r1 - r0 behind the cam's centre along the
    direction of the base circle's end (angle phi_p0 from the nose) and touches the nose circle (centre a = r0 + h - r2
    on the nose axis) from inside, |o1 - A| = r1 - r2.  Squared, with u = r1 - r0:
    u^2 + 2 a u cos(phi_p0) + a^2 = (u + r0 - r2)^2, so u = ((r0 - r2)^2 - a^2) / (2 (a cos(phi_p0) - (r0 - r2)))."""
    a = R0 + H - R2
    return ((R0 - R2) ** 2 - a**2) / (2.0 * (a * np.cos(HALF) - (R0 - R2)))


def test_the_clearance_is_taken_up_on_the_flank_arc_where_its_lift_reaches_it():
    """On the flank arc a flat follower's lift is the support function of that circle less r0:
    h(alpha) = u (1 - cos alpha), alpha from the base circle's end, u = r1 - r0 (14.519 mm).  So the valve opens at
    alpha_0 = arccos(1 - h0 / u) = 10.648 deg after the cam event starts, at dh/dtheta = u sin(alpha_0) per rad, and by
    symmetry closes as far before its end."""
    law = ClearanceTakeUp(ThreeArcLaw(R0, H, HALF, R2), H0)
    u = _flank_offset()
    assert u * 1e3 == pytest.approx(14.519, abs=5e-4)
    alpha0 = np.arccos(1.0 - H0 / u)
    assert np.degrees(alpha0) == pytest.approx(10.648, abs=5e-4)
    assert law.ramp_angle == pytest.approx(alpha0, rel=1e-9)
    assert law.valve_opens == pytest.approx(-HALF + alpha0, rel=1e-9)
    assert law.valve_closes == pytest.approx(HALF - alpha0, rel=1e-9)
    h, dh = law.derivatives(np.array([law.valve_opens]))[:2, 0]
    assert (h, dh) == pytest.approx((H0, u * np.sin(alpha0)), rel=1e-9)
    coefficients = law.coefficients()
    assert coefficients["take_up_opening_cam_deg"] == pytest.approx(np.degrees(alpha0), rel=1e-9)
    assert coefficients["take_up_closing_cam_deg"] == pytest.approx(np.degrees(alpha0), rel=1e-9)


def test_the_valve_lift_above_the_clearance_and_the_segments_split_there():
    law = ClearanceTakeUp(ThreeArcLaw(R0, H, HALF, R2), H0)
    assert law.lift_max == pytest.approx(H - H0, rel=1e-12) and law.ramp_height == H0
    names = [s.name for s in law.segments]
    assert names[0] == "clearance take-up opening" and names[-1] == "clearance take-up closing"
    assert law.segments[0].end == pytest.approx(law.valve_opens, rel=1e-12)
    assert law.segments[-1].start == pytest.approx(law.valve_closes, rel=1e-12)
    assert law.valve_lift(np.array([0.0]), 1.6)[0] == pytest.approx(1.6 * (H - H0), rel=1e-12)


def test_a_law_with_a_ramp_or_a_clearance_beyond_the_lift_is_refused():
    kurz = KurzLaw(6.25e-3, 0.25e-3, 0.02e-3 / np.radians(1.0), *np.radians([27.0, 6.0, 38.0]))
    with pytest.raises(ValueError, match="it has a ramp"):
        ClearanceTakeUp(kurz, H0)
    with pytest.raises(LawError):
        ClearanceTakeUp(ThreeArcLaw(R0, H, HALF, R2), H)
