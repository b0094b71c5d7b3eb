"""One evaluation of the cam synthesis (valvetrain.synthesis.problem): its fast margins and objective against the full
design's, a population at once against each point alone, a finger follower's margins against the direct geometric
construction."""

from pathlib import Path

import numpy as np
import pytest

from valvetrain.design import run
from valvetrain.specification.reading import load_spec
from valvetrain.specification.si import si
from valvetrain.synthesis.constraints import Limits, contact_stress_value, spring_reserve_value
from valvetrain.synthesis.optimize import design_limits
from valvetrain.synthesis.problem import Problem
from valvetrain.synthesis.variables import Variable, default_variables

from appendix import appendix_spec
from synthesis.test_constraints import hand_finger_stress

MM = 1e-3

EXAMPLES = Path(__file__).parents[2] / "examples"
UKRSURT = EXAMPLES / "ukrsurt2019-diesel.toml"


def test_fast_margins_agree_with_the_design():
    """The optimiser's margins on the law alone match the constraints of the full design (same spring)."""
    spec = load_spec(UKRSURT)
    design = run(spec).valves["intake"]
    problem = Problem(spec, design, default_variables(spec.valves["intake"], spec.engine),
                      Limits.article(min_spring_reserve=2.2, cam_width=40 * MM, top_speed=1.1))
    fullness, margins = problem.evaluate(problem.x0)
    assert fullness == pytest.approx(design.flow.fullness, rel=1e-12)
    named = dict(zip(problem.margin_names(), margins, strict=True))
    # the smallest convex radius and the Hertz stress refined around the grid's extremes against the profile stage's
    # and the constraint's Brent-refined extremes (a second refinement of the same contour)
    assert named["rho_min"] == pytest.approx((design.profile.rho_min - 2 * MM) / (2 * MM), abs=1e-6)
    assert named["contact stress"] == pytest.approx(1 - contact_stress_value(design, 40 * MM, top=1.1) / 1200e6,
                                                    abs=1e-6)
    # the design's own concave radius -102.43 mm and pressure angle 26.8165 deg (tests/laws/test_power_polynomial.py)
    assert named["concave radius"] == pytest.approx(1 - 170 / 102.43, abs=2e-3)
    assert named["pressure angle"] == pytest.approx((30 - 26.8165) / 30, abs=1e-4)
    # a_qd = 5 mm/rad2 over phi_1 = 3 deg never reaches the lift within the angle: no cam
    assert problem.evaluate([5.0, 3.0, 0.5, 0.5])[0] == 0.0


def test_the_objective_is_the_design_time_area():
    spec = appendix_spec()
    design = run(spec).valves["intake"]
    variables = default_variables(spec.valves["intake"], spec.engine)
    problem = Problem(spec, design, variables, design_limits(design)[0], objective="time_area")
    assert problem.evaluate(problem.x0)[0] == pytest.approx(design.flow.time_area_open, rel=1e-12)
    # phi3 is left to the remainder of the half angle when phi1 or phi2 move: 27 + 6 + 38 = 71 cam deg
    x = problem.x0.copy()
    x[0] = 30.0
    section = problem.point(x)
    assert "phi3_deg" not in section["cam"] and section["cam"]["phi1_deg"] == 30.0


def test_a_variable_must_be_a_numeric_key():
    spec = appendix_spec()
    design = run(spec).valves["intake"]
    with pytest.raises(ValueError, match="cam.follower is not a numeric key"):
        Problem(spec, design, [Variable("cam.follower", 0, 1)], design_limits(design)[0])


def test_a_population_evaluated_at_once_equals_each_point_on_its_own():
    """Problem.evaluate_many of a population (points with and without a cam, one twice) gives each point's objective
    and margins as evaluating it on its own, to 1e-12, and records the same history in the same order."""
    spec = load_spec(UKRSURT)
    design = run(spec).valves["intake"]
    variables = default_variables(spec.valves["intake"], spec.engine)

    def problem():
        return Problem(spec, design, variables, design_limits(design, 170 * MM, ramp_varied=False)[0])

    rng = np.random.default_rng(5)
    low, high = np.array([(v.low, v.high) for v in variables]).T
    together, alone = problem(), problem()
    near = together.x0 * (0.8 + 0.4 * rng.random((20, len(variables))))
    xs = [*(low + (high - low) * rng.random((20, len(variables)))), *near, np.array([5.0, 3.0, 0.5, 0.5])]
    xs.insert(7, xs[3])
    batch = together.evaluate_many(xs, dynamics=False)
    one_by_one = [alone.evaluate(x, dynamics=False) for x in xs]
    assert sum(objective > 0 for objective, _ in batch) >= 10  # cams among them
    for (o1, m1), (o2, m2) in zip(batch, one_by_one, strict=True):
        assert o1 == pytest.approx(o2, rel=1e-12)
        np.testing.assert_allclose(m1, m2, rtol=1e-12, atol=1e-15)
    assert together.evaluations == alone.evaluations == len(xs) - 1
    assert together.law_samples == alone.law_samples
    np.testing.assert_array_equal(np.array(together.points), np.array(alone.points))
    # the batch's refined extremes are the contour's: the concave radius margin against the law's own curvature
    # (LiftLaw.curvature) on a grid 256 times finer than the search's, its junctions among them
    at = together.names.index("concave radius")
    for x, (objective, margins) in [(x, r) for x, r in zip(xs, batch, strict=True) if r[0] > 0][-5:]:
        law = together.law(x)[0]
        theta = np.union1d(np.linspace(law.start, 0.0, 1200 * 256 + 1), law.breakpoints[law.breakpoints < 0.0])
        rho = law.curvature(theta, together.heel, together.follower)
        assert margins[at] == pytest.approx(1.0 - 170 * MM / -rho[rho < 0.0].max(), rel=2e-6)


def test_fast_acceleration_margins_of_a_finger_are_the_roller_s():
    """The optimiser's fast margins of the tappet acceleration band on a finger follower use the roller centre's
    acceleration along its arc, as the design's checks: on the shipped finger (intake) 4899.75 and -2196.90 m/s2 at
    the rated speed, from psi(theta) of the linkage differentiated twice numerically (np.gradient, 200001 angles;
    tests/synthesis/test_constraints.py), so against a band of -3000...6000 m/s2 the margins are
    (6000 - 4899.75)/6000 = 0.18337 and (3000 - 2196.90)/3000 = 0.26770.  Before the fix they were the valve law's
    (8107 m/s2: margin -0.351), and the search judged every finger cam 1.65 x too hard."""
    spec = load_spec(EXAMPLES / "modern-dohc-roller-finger.toml")
    design = run(spec).valves["intake"]
    problem = Problem(spec, design, default_variables(spec.valves["intake"], spec.engine),
                      Limits(max_acceleration=6000.0, min_acceleration=-3000.0))
    named = dict(zip(problem.margin_names(), problem.evaluate(problem.x0)[1], strict=True))
    assert named["max acceleration"] == pytest.approx((6000 - 4899.75) / 6000, abs=2e-4)
    assert named["min acceleration"] == pytest.approx((3000 - 2196.90) / 3000, abs=2e-4)


def test_fast_margins_of_a_finger_take_its_variable_ratio():
    """The optimiser's fast margins on the shipped finger (intake): the contact stress under the cam's force, the
    force at the valve carried through the linkage, against the direct geometric construction of
    synthesis/test_constraints.py (hand_finger_stress, its largest on 201 angles refined on 201, 688.140 MPa), to
    1e-4; and the spring reserve with the finger's inertia force by its variable ratio, against the drive stage's
    (spring_reserve_value: the chosen spring over m_v |j_v| with j_v of Lagrange's equation of the linkage,
    tests/followers/test_finger.py), to 1e-3 (the search's grid of the event against the drive stage's 2001 angles).
    Found: 0.311872 against 0.311860, 0.2010056 against 0.2010057.  Before the fix the margins took the valve's force
    for the cam's (margin 0.4679: 532.1 MPa) and the finger's inertia at its ratio on the heel circle (margin
    0.1985)."""
    spec = load_spec(EXAMPLES / "modern-dohc-roller-finger.toml")
    design = run(spec).valves["intake"]
    valve = si(spec.valves["intake"], spec)
    limit, width, modulus = 1e9, 0.014, 2.1e11
    problem = Problem(spec, design, default_variables(spec.valves["intake"], spec.engine),
                      Limits(cam_width=width, max_contact_stress=limit, contact_modulus=modulus))
    named = dict(zip(problem.margin_names(), problem.evaluate(problem.x0)[1], strict=True))
    law = design.law
    coarse = np.linspace(law.valve_opens, law.valve_closes, 201)
    at = coarse[int(np.argmax(hand_finger_stress(design, valve, coarse, width, modulus)))]
    step = coarse[1] - coarse[0]
    fine = np.linspace(max(at - step, law.valve_opens), min(at + step, law.valve_closes), 201)
    hand = hand_finger_stress(design, valve, fine, width, modulus).max()
    assert named["contact stress"] == pytest.approx((limit - hand) / limit, rel=1e-4)
    reserve, target = spring_reserve_value(design), problem.limits.min_spring_reserve
    assert named["spring reserve"] == pytest.approx((reserve - target) / target, rel=1e-3)
