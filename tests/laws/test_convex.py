"""The further laws of issue 5: ramps, polynomial, constant acceleration, three-arc and tangent cams."""

import numpy as np
import pytest

from valvetrain import geometry
from valvetrain.checks import failed
from valvetrain.laws import (CombinedLaw, ConstantAccelerationLaw, DynamicLaw, HarmonicLaw, KurzLaw, PolydyneLaw, PolynomialLaw, TangentLaw, ThreeArcLaw,
                             harmonic_limit, make_ramp)

DEG = np.pi / 180


@pytest.mark.parametrize("kind", ["cosine", "constant_velocity", "constant_acceleration"])
def test_ramps_end_on_height_velocity_and_zero_acceleration(kind):
    r = make_ramp(kind, 0.3e-3, 0.6e-3, 0.4)
    end = r.evaluate(np.array([r.length]))[:, 0]
    assert end[:3] == pytest.approx([0.3e-3, 0.6e-3, 0.0], abs=1e-15)
    start = r.evaluate(np.array([0.0]))[:, 0]
    assert start[0] == 0.0
    # lengths (spec section 2): cosine pi h0 / (2 v0), constant velocity h0 / v0, constant acceleration h0 / (v0 (1 - f/2))
    expected = {"cosine": np.pi * 0.3 / 1.2, "constant_velocity": 0.5, "constant_acceleration": 0.3 / (0.6 * 0.8)}
    assert r.length == pytest.approx(expected[kind], rel=1e-12)


def test_kurz_with_another_ramp_keeps_its_coefficients():
    """(2.28)-(2.34) depend on the ramp's end velocity only (Valve-train practical works (n.d.)): a constant-velocity ramp changes Phi0 only."""
    args = (6.25e-3, 0.25e-3, 0.02e-3 / DEG, *np.radians([27, 6, 38]))
    a, b = KurzLaw(*args), KurzLaw(*args, ramp_kind="constant_velocity")
    assert a.coefficients() == b.coefficients()
    assert b.ramp_angle == pytest.approx(0.25e-3 / (0.02e-3 / DEG))
    j = b.start + b.ramp_angle
    d = b.derivatives(np.array([j - 1e-12, j + 1e-12]))
    assert np.allclose(d[:3, 0], d[:3, 1], atol=1e-9)


def test_constant_acceleration_worked_example():
    """spec/methods-seeds-002-004.md section 5: h_max 8, h0 0.35, alpha_r 20 deg (constant-acceleration ramp,
    f = 0.5), 18/20/12 deg, kappa 0.6: A1 54.142, A2 38.646 mm/rad2, v0 1.3369 mm/rad (23.3 um/deg), closure exact,
    acceleration levels {54.142, 7.66, 0, -23.187, -38.646}."""
    v0 = 0.35 / (np.radians(20) * 0.75)
    assert v0 == pytest.approx(1.3369, abs=1e-4)
    law = ConstantAccelerationLaw(7.65, 0.35, v0, *np.radians([18, 20, 12]), kappa=0.6,
                                  ramp_kind="constant_acceleration", ramp_fraction=0.5)
    assert (law.a1, law.a2) == pytest.approx((54.142, 38.646), abs=1e-3)
    nose = law.derivatives(np.array([0.0]))[:, 0]
    assert nose[0] == pytest.approx(8.0, abs=1e-12)
    assert nose[1] == pytest.approx(0.0, abs=1e-12)
    levels = np.unique(np.round(law.derivatives(np.linspace(law.start, 0, 4001))[2], 3))
    assert set(levels) <= {54.142, 7.66, -23.188, -23.187, -38.646, 0.0}
    assert {54.142, 7.66, -38.646} <= set(levels)


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
    """spec section 3: r0 20, h 8, phi_p0 60 deg, r2 5: a 23, r1 63.4286, phi1 19.9320 deg; the flat follower's lift is
    the support function of the arc contour (spec: max error 6e-8 mm)."""
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
    """spec section 3: from_phi1(25 deg) gives r2 2.02655, r1 55.2511; from the flank radius back to the same cam."""
    law = ThreeArcLaw.from_flank_angle(20.0, 8.0, np.radians(60), np.radians(25))
    assert (law.r2, law.r1) == pytest.approx((2.02655, 55.2511), abs=1e-4)
    again = ThreeArcLaw.from_flank_radius(20.0, 8.0, np.radians(60), law.r1)
    assert again.r2 == pytest.approx(law.r2, rel=1e-9)


def test_tangent_cam_roller_centre_distance():
    """spec section 4: r0 20, h 8, phi_p0 60 deg, r_r 10: r2 12, junction 24.7913 deg, h there 3.04542; the roller
    centre stays one roller radius from the profile built of base circle, tangent lines and nose arc
    (spec: max error 4.3e-7 mm)."""
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
    """On the flank the pitch curve is a straight line offset by the roller radius, so rho_p is infinite (spec
    section 4); round-off must not turn it into a huge radius of either sign (which read as a concave flank)."""
    law = TangentLaw(20.0, 8.0, np.radians(60), 10.0)
    flank = np.linspace(-law.half_angle + 1e-3, -law.half_angle + law.junction - 1e-3, 2001)
    h, dh, d2h, _ = law.derivatives(flank)
    assert np.all(geometry.roller_pitch_curvature(law.r0, law.rr, h, dh, d2h) == np.inf)
    # the nose: the pitch curve is the nose arc r2 + r_r = 22 mm about its centre
    nose = np.linspace(-0.3, 0.3, 11)
    h, dh, d2h, _ = law.derivatives(nose)
    assert geometry.roller_pitch_curvature(law.r0, law.rr, h, dh, d2h) == pytest.approx(np.full(11, 22.0), rel=1e-9)


def test_extremes_of_a_law_with_an_acceleration_jump():
    """A tangent cam's acceleration jumps at the flank-nose junction (continuity 1) from its largest value (flank
    side) to its smallest (nose side) for r0 20, h 10, phi_p0 50 deg, r_r 10 mm: both are found, as the one-sided
    limits.  Independent computation: the law sampled on 200001 angles and 1e-9 rad either side of the junction
    (1e-8 of the values there); no sample beats the extremes, and they lie within 1e-7 of the samples'."""
    law = TangentLaw(20e-3, 10e-3, np.radians(50), 10e-3)
    e = law.extremes(1.0)
    junction = -law.half_angle + law.junction
    sides = law.derivatives(junction + np.array([-1e-9, 1e-9]))[2]
    theta = np.concatenate([np.linspace(law.start, law.end, 200001), junction + np.array([-1e-9, 1e-9])])
    _, v, a, _ = law.derivatives(theta)
    assert v[theta <= 0].max() <= e.max_velocity <= v[theta <= 0].max() * (1 + 1e-7)
    assert a.max() <= e.max_acceleration <= a.max() * (1 + 1e-7)
    assert a.min() * (1 + 1e-7) <= e.min_acceleration <= a.min()
    assert (e.max_acceleration, e.min_acceleration) == pytest.approx(sides, rel=1e-7)
    # on the flank side of a junction and on the nose side (the law is symmetric: either junction)
    assert abs(junction) <= abs(e.max_acceleration_angle) < abs(junction) + 1e-12
    assert abs(junction) - 1e-12 < abs(e.min_acceleration_angle) < abs(junction)


def test_polynomial_generalises_polydyne():
    """The 5-exponent polynomial law with (2, p, q, r, s) is the polydyne law (spec section 7)."""
    a = PolynomialLaw(6.25e-3, np.radians(71), [2, 8, 14, 20, 26])
    b = PolydyneLaw(6.25e-3, np.radians(71), 8)
    theta = np.linspace(-1.3, 1.3, 101)
    assert np.allclose(a.derivatives(theta), b.derivatives(theta), rtol=1e-9, atol=1e-15)
    # seven exponents: lift, slope and five more derivatives vanish at the start
    c = PolynomialLaw(6e-3, np.radians(65), [2, 6, 10, 14, 18, 22, 26])
    scale = np.abs(c.derivatives(np.linspace(c.start, c.end, 721))).max(axis=1)
    assert np.all(np.abs(c.derivatives(np.array([c.start]))[:, 0]) < 1e-10 * scale)
    with pytest.raises(ValueError, match="each 2 or >= 3"):
        PolynomialLaw(6e-3, 1.0, [2, 2.5, 8])


def test_combined_rebuilds_kurz():
    """The combined-function mechanism with Kurz's segments (half-sine, quarter-sine, parabola to the nose,
    Z = 5/8) is the Kurz law of Valve-train practical works (n.d.) to round-off (spec section 6: Kurz is a combined-function cam)."""
    w = 0.02e-3 / DEG
    kurz = KurzLaw(6.25e-3, 0.25e-3, w, *np.radians([27, 6, 38]))
    combined = CombinedLaw(6.25e-3, 0.25e-3, w, [("half_sine", np.radians(27)), ("quarter_sine", np.radians(6)),
                                                  ("parabola_to_nose", np.radians(38))], ratios=[(1, 0.625)])
    theta = np.linspace(-kurz.half_angle, kurz.half_angle, 2001)
    scale = np.abs(kurz.derivatives(theta)).max(axis=1)
    assert np.all(np.abs(kurz.derivatives(theta) - combined.derivatives(theta)).max(axis=1) < 1e-12 * scale)
    # the first amplitude is c12 (pi/Phi1)^2 of (2.6)
    assert combined.amplitude(0)[0] * 1e3 == pytest.approx(kurz.coefficients()["c12"] * (np.pi / np.radians(27)) ** 2)


def test_combined_needs_a_square_system():
    with pytest.raises(ValueError, match="unknown amplitudes"):
        CombinedLaw(6e-3, 0.25e-3, 1e-3, [("half_sine", 0.5), ("linear", 0.4), ("parabola_to_nose", 0.3)])


def _polydyne_target():
    """The spec's section 7 cam: h_max 8, h0 0.3, v0 0.4 mm/rad, 55 deg, exponents 2, 10, 18, 26, 34."""
    return PolydyneLaw(7.7e-3, np.radians(55), 10, 18, 26, 34, ramp_height=0.3e-3, ramp_velocity=0.4e-3)


@pytest.mark.parametrize("n,m", [(12, 1), (20, 2), (30, 2)])
def test_harmonic_cam_constraints(n, m):
    """spec section 9: h(0) = h_max and the even derivatives up to 2m vanish at +-alpha_W (odd ones by
    construction), the fit residual small against the lift."""
    target = _polydyne_target()
    law = HarmonicLaw(target, n, m)
    assert law.lift(0.0) == pytest.approx(8e-3, abs=1e-15)
    ends = law.derivatives(np.array([law.start, law.end]))
    assert np.abs(ends).max() < 1e-12
    k = np.arange(n + 1)
    for j in range(m + 1):  # h^(2j)(alpha_W) = sum a_k (-1)^j (k pi / alpha_W)^(2j) (-1)^k
        assert abs(np.sum(law.a * (-1.0) ** k * law.w ** (2 * j))) < 1e-9 * np.abs(law.a * law.w ** (2 * j)).sum()
    assert law.deviation < 0.05e-3


def test_harmonic_fit_improves_with_n():
    target = _polydyne_target()
    devs = [HarmonicLaw(target, n, 2).deviation for n in (10, 20, 40)]
    assert devs[0] > devs[1] > devs[2]


def test_harmonic_limit_rule():
    """N < alpha_W omega_n / (pi omega) (spec section 9): with epsilon = 0.00164 and alpha_W = 70 deg, N < 9.6."""
    eps = 0.00164
    assert harmonic_limit(np.radians(70), 1.0 / np.sqrt(eps), 1.0) == pytest.approx(9.6, abs=0.05)


def _dynamic():
    """spec sections 2 and 8: c = 15000 N/mm, F0 = 400 N, k = 1.5, x0 = 0.30 mm, design seating velocity 0.3 m/s at
    3000 rpm (camshaft); K = 67.5 N/mm and a constant-acceleration ramp (f = 0.5) reproduce the spec's ramp of
    26.03 deg at 11.16 um/deg."""
    omega = 3000 * np.pi / 30
    return DynamicLaw(8e-3, np.radians(55), [2, 10, 18, 26, 34], 0.3 / omega, 15e6, 0.25, 67.5e3, 400.0, omega,
                      1.5, 0.3e-3, "constant_acceleration", 0.5), omega


def test_dynamic_cam_ramp():
    law, _ = _dynamic()
    # ramp height (x0 + F0/c)/k = (0.30 + 400/15000)/1.5 = 0.21778 mm (spec section 2, worked example)
    assert law.ramp_height * 1e3 == pytest.approx(0.21778, abs=1e-5)
    assert law.ramp.end_velocity * 1e6 * DEG == pytest.approx(11.16, abs=0.01)
    assert np.degrees(law.ramp_angle) == pytest.approx(26.03, abs=0.02)
    j = law.start + law.ramp_angle
    d = law.derivatives(np.array([j - 1e-12, j + 1e-12]))
    assert np.allclose(d[:3, 0], d[:3, 1], rtol=1e-6, atol=1e-9)


def test_dynamic_cam_needs_a_stiff_enough_drive():
    """k h = x0 + y + (M omega^2 y'' + K y + F0)/c (spec section 8): the spec's drive gives a cam that rises to the
    nose; with c 100 times softer the negative y'' near the nose makes the cam dip (a warning); with c 10^4 times
    softer the nose falls below the ramp's end (no cam: an error naming the remedy)."""
    law, omega = _dynamic()
    assert law.fall_before_nose() == 0.0 and failed(law.checks()) == []
    args = (8e-3, np.radians(55), [2, 10, 18, 26, 34], 0.3 / omega)
    soft = DynamicLaw(*args, 15e4, 0.25, 67.5e3, 400.0, omega, 1.5, 0.3e-3)
    # independent: the lift along a fine grid from the ramp's end to the nose, its largest drop below a running maximum
    h = soft.lift(np.linspace(soft.start + soft.ramp_angle, 0.0, 20001))
    drop = np.max(np.maximum.accumulate(h) - h)
    assert drop > 1e-5 and soft.fall_before_nose() == pytest.approx(drop, rel=1e-3)
    assert failed(soft.checks())[0].quantity == "dynamic cam: fall of the lift before the nose"
    with pytest.raises(ValueError, match="would not rise above its ramp"):
        DynamicLaw(*args, 1.5e3, 0.25, 67.5e3, 400.0, omega, 1.5, 0.3e-3)


def test_dynamic_cam_gives_the_design_valve_motion():
    """Simulated one-mass elastic train, M y'' = c(k h - x0 - y) - (F0 + K y), integrated with scipy's LSODA from the
    valve's opening at the design speed: the valve follows the design polynomial (spec section 8)."""
    from scipy.integrate import solve_ivp

    law, omega = _dynamic()
    t0 = law.start + law.ramp_angle

    def rhs(t, s):
        theta = t0 + omega * t
        u = law.ratio * float(law.lift(np.array([theta]))[0]) - law.x0
        return [s[1], (law.c * (u - s[0]) - (law.F0 + law.K * s[0])) / law.m]

    t_end = 2 * law.main_half_angle / omega
    sol = solve_ivp(rhs, (0, t_end), [0.0, law.v_y * omega], method="LSODA", rtol=1e-11, atol=1e-13,
                    dense_output=True, max_step=t_end / 2000)
    t = np.linspace(0, t_end, 201)
    design = law.valve_motion(t0 + omega * t)[0]
    assert np.abs(sol.sol(t)[0] - design).max() < 1e-7  # 0.1 um on 8 mm
