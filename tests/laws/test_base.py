"""The law base (laws/base.py).  Steps of the acceleration (issue 20, item 3): laws whose acceleration jumps at a
segment boundary report each step (angle, size) from the one-sided limits of their segments; the jerk is an impulse
there, and the comparison and the results say so instead of a finite, flat jerk.  The extremes of a law with such a
step.  Several laws sampled as one batch (batch_derivatives) equal each law sampled on its own, and each member keeps
its own closed-form values."""

import json
from pathlib import Path

import numpy as np
import pytest

from valvetrain.compare import comparison
from valvetrain.design import run
from valvetrain.export import results_json
from valvetrain.laws.constant_acceleration import ConstantAccelerationLaw
from valvetrain.laws.convex import TangentLaw, ThreeArcLaw
from valvetrain.laws.base import batch_derivatives
from valvetrain.laws.kurz import KurzLaw
from valvetrain.laws.polydyne import PolydyneLaw
from valvetrain.laws.power_polynomial import PowerPolynomialLaw
from valvetrain.specification import load_spec

from laws.test_power_polynomial import LAWS, MM, article

THREE_ARC = Path(__file__).parents[2] / "examples" / "dynamics-comparison" / "three-arc.toml"


def steps_mm(law):
    """(angle [deg], step of d2h/dtheta2 [mm/rad^2]) of each step."""
    return [(np.degrees(s.angle), s.size * 1e3) for s in law.acceleration_steps()]


def test_three_arc_steps_are_the_jumps_of_the_radius():
    """Hand derivation for the three-arc cam r0 = 20 mm, h = 8 mm, phi_p0 = 60 deg, nose radius r2 = 5 mm.

    A flat follower touches the cam where its radius of curvature is rho = r0 + h + h'' (Shang Hanji (1988),
    eq. 2.6): rho = r0 on the base circle (h = h'' = 0), r1 on the flank arc, r2 on the nose arc.  The lift and its
    slope are continuous (the arcs are tangent), so h'' jumps by the jump of rho: r1 - r0 where the lift starts,
    r2 - r1 at the flank-nose junction.

    r1 from the triangle of the cam centre O, the flank centre C1 and the nose centre C2: |OC1| = r1 - r0 (C1 lies
    beyond O from the point where the flank leaves the base circle, 60 deg before the nose, so the angle C1 O C2 is
    180 - 60 = 120 deg), |OC2| = a = r0 + h - r2 = 23 mm, |C1C2| = r1 - r2 (tangent arcs).  Law of cosines:
    (r1 - 5)^2 = (r1 - 20)^2 + 23^2 + 23 (r1 - 20)  ->  -10 r1 + 25 = -17 r1 + 469  ->  r1 = 444/7 = 63.4286 mm.
    Law of sines for the angle at C1, the flank's angle phi1 from the start of lift:
    sin phi1 = 23 sin 120 deg / (444/7 - 5) = 0.340916 -> phi1 = 19.932 deg; the junction lies 60 - 19.932 =
    40.068 deg before the nose.

    Steps of h'': +304/7 = +43.4286 mm/rad^2 at -60 deg, 5 - 444/7 = -58.4286 at -40.068 deg, and the mirror
    images on the closing flank.
    """
    law = ThreeArcLaw(20e-3, 8e-3, np.radians(60.0), 5e-3)
    r1 = 444.0 / 7.0
    junction = 60.0 - np.degrees(np.arcsin(23.0 * np.sin(np.radians(120.0)) / (r1 - 5.0)))
    expected = [(-60.0, r1 - 20.0), (-junction, 5.0 - r1), (junction, r1 - 5.0), (60.0, 20.0 - r1)]
    found = steps_mm(law)
    assert [a for a, _ in found] == pytest.approx([a for a, _ in expected], abs=1e-9)
    assert [s for _, s in found] == pytest.approx([s for _, s in expected], rel=1e-9)
    # the one-sided limits themselves: zero on the base circle, (r1 - r0) cos(phi1) at the end of the flank
    first, second = law.acceleration_steps()[:2]
    assert first.before == 0.0
    assert second.before * 1e3 == pytest.approx((r1 - 20.0) * np.cos(np.radians(60.0 - junction)), rel=1e-9)


def test_tangent_cam_starts_with_a_step_of_r0_plus_rr():
    """A tangent cam's roller centre runs on a straight line along the flank, whose radius of curvature is
    infinite; for a roller through the cam centre the pitch radius at the start of lift (h = h' = 0, pitch radius
    R = r0 + rr) is R^2 / (R - h''), infinite only for h'' = R: the step from the base circle is r0 + rr =
    20 + 10 = 30 mm/rad^2."""
    law = TangentLaw(20e-3, 8e-3, np.radians(60.0), 10e-3)
    found = steps_mm(law)
    assert found[0] == pytest.approx((-60.0, 30.0), rel=1e-9)
    assert found[-1] == pytest.approx((60.0, -30.0), rel=1e-9)
    assert len(found) == 4       # and at the flank-nose junctions


def test_constant_acceleration_steps_are_its_levels():
    """Constant-acceleration cam of the worked example (h_max 8 mm at the nose, cosine ramp h0 = 0.35 mm with end
    velocity v0 = 1.3369 mm/rad, 18/20/12 deg, kappa 0.6; A1 = 54.142, A2 = 38.646 mm/rad^2 from the closure,
    Shang Hanji (1988), section 2.4).  The cosine ramp h0 (1 - cos(pi phi / 2L)) with v0 = h0 pi / 2L starts with
    h'' = h0 (pi / 2L)^2 = v0^2 / h0 = 1.3369^2 / 0.35 = 5.1066 mm/rad^2 and ends with h'' = 0; then the levels
    +A1, -A2, -0.6 A2 follow each other: steps +A1, -(A1 + A2) = -92.788, +0.4 A2 = +15.458, none at the nose."""
    law = ConstantAccelerationLaw(7.65e-3, 0.35e-3, 1.3369e-3, *np.radians([18.0, 20.0, 12.0]), kappa=0.6)
    a1, a2 = 54.142, 38.646
    found = steps_mm(law)
    ramp = np.degrees(np.pi * 0.35 / (2.0 * 1.3369))       # the cosine ramp's length L = pi h0 / (2 v0)
    opening = [(-(50.0 + ramp), 1.3369**2 / 0.35), (-50.0, a1), (-32.0, -(a1 + a2)), (-12.0, 0.4 * a2)]
    expected = opening + [(-a, -s) for a, s in reversed(opening)]
    assert [a for a, _ in found] == pytest.approx([a for a, _ in expected], abs=1e-9)
    assert [s for _, s in found] == pytest.approx([s for _, s in expected], rel=1e-4)


def test_a_smooth_law_has_no_step():
    """A polydyne cam (continuous acceleration by construction, from its ramp to the nose) reports none."""
    assert PolydyneLaw(6e-3, 1.0, 10).acceleration_steps() == ()


def test_three_arc_design_reports_its_steps_and_compare_an_infinite_jerk():
    """The three-arc cam of the dynamics comparison: each step in results.json at the rated camshaft speed
    (omega^2 times the step of h''), and `compare` gives its jerk as infinite with the largest step instead of the
    2e5 m/s^3 of the sampled curve, which made the roughest cam of the three look the smoothest."""
    res = run(load_spec(THREE_ARC))
    v = res.valves["intake"]
    law, omega = v.law, v.omega_cam
    rec = json.loads(results_json(res))["valves"]["intake"]["cam"]["acceleration_steps"]
    assert len(rec) == 4
    start = rec[0]
    assert start["cam_deg"] == pytest.approx(np.degrees(law.start))
    assert start["before_m_s2"] == 0.0
    # on the flank arc h'' = (r1 - r0) cos(phi): at its start r1 - r0 (the jump of the radius of curvature)
    assert start["step_m_s2"] == pytest.approx(omega**2 * (law.r1 - law.r0), rel=1e-9)
    assert rec[1]["step_m_s2"] == pytest.approx(omega**2 * (law.r2 - law.r1), rel=1e-9)
    assert not any(s["on_ramp"] for s in rec)
    row = comparison({"three-arc": v})[0]["three-arc"]
    assert row["max_jerk_m_s3"].startswith("∞ (step of ")
    assert f"{omega**2 * (law.r2 - law.r1):+.4g} m/s2" in row["max_jerk_m_s3"]
    assert row["acceleration_steps"].count("m/s2 at") == 4


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


def members(n=24, seed=3):
    """n power-polynomial cams of the 26/27 diesel with a_qd, phi_1, x_d, x_g drawn in the optimiser's box (the
    parameters that admit no cam skipped): one batch key, pieces of different lengths and amplitudes."""
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < n:
        try:
            out.append(article(rng.uniform(60.0, 400.0), rng.uniform(8.0, 45.0), rng.uniform(0.02, 0.98),
                               rng.uniform(0.02, 0.98)))
        except ValueError:
            continue
    return out


def sampled_both_ways(laws, seed=4):
    """(batch, one by one) of the laws each at its own angles: a random count of random angles over and beyond the
    event, the junctions and the nose among them."""
    rng = np.random.default_rng(seed)
    thetas = [np.concatenate([np.sort(rng.uniform(law.start - 0.1, law.end + 0.1, rng.integers(50, 900))),
                              law.breakpoints, [0.0]]) for law in laws]
    member = np.repeat(np.arange(len(laws)), [t.size for t in thetas])
    return (batch_derivatives(laws, np.concatenate(thetas), member),
            np.concatenate([law.derivatives(t) for law, t in zip(laws, thetas, strict=True)], axis=1))


def test_a_batch_of_power_polynomial_cams_equals_each_cam():
    laws = members()
    assert len({law.batch_key() for law in laws}) == 1
    batch, single = sampled_both_ways(laws)
    np.testing.assert_allclose(batch, single, rtol=1e-12, atol=0.0)
    # each member's own closed-form values: the nose lift S_max = lift + S_b with zero velocity, the ramp's end at
    # S_b with the velocity analogue v_qb on the opening flank (the law's parameters, not its pieces)
    d = batch_derivatives(laws, np.array([t for law in laws for t in (0.0, law.valve_opens)]),
                          np.repeat(np.arange(len(laws)), 2))
    np.testing.assert_allclose(d[0, ::2], 21.1 * MM, rtol=1e-12)
    np.testing.assert_allclose(d[1, ::2], 0.0, atol=0.0)
    np.testing.assert_allclose(d[0, 1::2], 0.8 * MM, rtol=1e-12)
    np.testing.assert_allclose(d[1, 1::2], 6.0 * MM, rtol=1e-12)


def test_a_batch_of_mixed_laws_samples_each_group_together():
    """The R2 and R1 readings, other exponents and a Kurz cam (no batch of its own) in one batch."""
    kurz = KurzLaw(6.25e-3, 0.25e-3, 0.02e-3 * 180 / np.pi, *np.deg2rad([27.0, 6.0, 38.0]), 0.625)
    laws = [*LAWS, kurz, *members(4), LAWS[3]]
    assert len({(type(law), law.batch_key()) for law in laws}) == 5
    batch, single = sampled_both_ways(laws)
    np.testing.assert_allclose(batch, single, rtol=1e-12, atol=0.0)
    assert isinstance(laws[0], PowerPolynomialLaw)
