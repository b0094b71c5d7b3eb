"""The convex cams of arcs (laws/convex.py; the constructions of Kolchin and Demidov (1980)): the three-arc cam and
the tangent cam."""

import numpy as np
import pytest

from valvetrain import geometry
from valvetrain.laws.convex import TangentLaw, ThreeArcLaw


def _arcs(law, n=20001):
    """Points of the three-arc contour built from its circles (independent of the lift formulas)."""
    t = np.linspace(-np.pi, np.pi, n)
    pts = []
    nose = np.abs(t) <= law.phi2
    pts.append(np.stack([law.r2 * np.sin(t[nose]), law.a + law.r2 * np.cos(t[nose])]))
    for side in (1, -1):
        d0 = np.array([side * np.sin(law.phi_p0), np.cos(law.phi_p0)])
        o1 = -(law.r1 - law.r0) * d0
        tt = t[(np.abs(t) >= law.phi2) & (np.abs(t) <= law.phi_p0) & (side * t > 0)]
        pts.append(o1[:, None] + law.r1 * np.stack([np.sin(tt), np.cos(tt)]))
    base = np.abs(t) >= law.phi_p0
    pts.append(law.r0 * np.stack([np.sin(t[base]), np.cos(t[base])]))
    return np.concatenate(pts, axis=1)


def test_three_arc_worked_example_and_support_function():
    """Kolchin and Demidov (1980), worked example (spec section 3): r0 20, h 8, phi_p0 60 deg, r2 5: a 23, r1 63.4286,
    phi1 19.9320 deg; the flat follower's lift is the support function of the arc contour (spec: max error 6e-8 mm)."""
    law = ThreeArcLaw(20.0, 8.0, np.radians(60), 5.0)
    assert (law.a, law.r1) == pytest.approx((23.0, 63.4286), abs=1e-4)
    assert np.degrees(law.phi1) == pytest.approx(19.9320, abs=1e-4)
    pts = _arcs(law)
    probe = np.linspace(-np.pi, np.pi, 181)
    u = np.stack([np.sin(probe), np.cos(probe)])
    support = (pts.T @ u).max(axis=0)
    assert np.abs(support - (20.0 + law.lift(probe))).max() < 1e-5
    # radius of curvature from Shang Hanji (1988), eq. (2.6): r1 on the flank, r2 on the nose
    rho = geometry.flat_follower_curvature(20.0, law.lift(np.radians([-50.0, -5.0])), law.derivatives(
        np.radians([-50.0, -5.0]))[2])
    assert rho == pytest.approx([law.r1, law.r2], rel=1e-12)
    # nose lift = h_max, contour radius r0 + h at the nose (spec: 28.000000)
    assert 20.0 + law.lift(0.0) == pytest.approx(28.0, abs=1e-12)


def test_three_arc_from_flank_angle_and_radius():
    """Kolchin and Demidov (1980), worked example (spec section 3): from_phi1(25 deg) gives r2 2.02655, r1 55.2511; from
    the flank radius back to the same cam."""
    law = ThreeArcLaw.from_flank_angle(20.0, 8.0, np.radians(60), np.radians(25))
    assert (law.r2, law.r1) == pytest.approx((2.02655, 55.2511), abs=1e-4)
    again = ThreeArcLaw.from_flank_radius(20.0, 8.0, np.radians(60), law.r1)
    assert again.r2 == pytest.approx(law.r2, rel=1e-9)


def test_tangent_cam_roller_centre_distance():
    """Kolchin and Demidov (1980), worked example (spec section 4): r0 20, h 8, phi_p0 60 deg, r_r 10: r2 12, junction
    24.7913 deg, h there 3.04542; the roller centre stays one roller radius from the profile built of base circle,
    tangent lines and nose arc (spec: max error 4.3e-7 mm)."""
    law = TangentLaw(20.0, 8.0, np.radians(60), 10.0)
    assert law.r2 == pytest.approx(12.0, abs=1e-12)
    assert np.degrees(law.junction) == pytest.approx(24.7913, abs=1e-4)
    assert law.lift(-law.half_angle + law.junction) == pytest.approx(3.04542, abs=1e-5)
    t = np.linspace(-np.pi, np.pi, 40001)
    profile = [law.r0 * np.stack([np.sin(t), np.cos(t)])[:, np.abs(t) >= law.phi_p0]]
    nose = np.abs(t) <= law.phi_p0
    profile.append(np.stack([law.r2 * np.sin(t[nose]), law.a + law.r2 * np.cos(t[nose])]))
    for side in (1, -1):
        d0 = np.array([side * np.sin(law.phi_p0), np.cos(law.phi_p0)])
        a0, a2 = law.r0 * d0, np.array([0.0, law.a]) + law.r2 * d0
        s = np.linspace(0, 1, 4001)
        profile.append(a0[:, None] + (a2 - a0)[:, None] * s[None, :])
    pts = np.concatenate(profile, axis=1)
    probe = np.linspace(-law.half_angle, law.half_angle, 121)
    centres = (law.r0 + law.rr + law.lift(probe)) * np.stack([np.sin(probe), np.cos(probe)])
    dist = np.hypot(pts[0][None, :] - centres[0][:, None], pts[1][None, :] - centres[1][:, None]).min(axis=1)
    assert np.abs(dist - law.rr).max() < 2e-4


def test_tangent_cam_flanks_are_straight():
    """On the flank the pitch curve is a straight line offset by the roller radius, so rho_p is infinite (Kolchin and
    Demidov (1980); spec section 4); round-off must not turn it into a huge radius of either sign (which read as a
    concave flank)."""
    law = TangentLaw(20.0, 8.0, np.radians(60), 10.0)
    flank = np.linspace(-law.half_angle + 1e-3, -law.half_angle + law.junction - 1e-3, 2001)
    h, dh, d2h, _ = law.derivatives(flank)
    assert np.all(geometry.roller_pitch_curvature(law.r0, law.rr, h, dh, d2h) == np.inf)
    # the nose: the pitch curve is the nose arc r2 + r_r = 22 mm about its centre
    nose = np.linspace(-0.3, 0.3, 11)
    h, dh, d2h, _ = law.derivatives(nose)
    assert geometry.roller_pitch_curvature(law.r0, law.rr, h, dh, d2h) == pytest.approx(np.full(11, 22.0), rel=1e-9)
