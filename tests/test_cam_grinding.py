"""The grinding geometry (valvetrain.cam_grinding): the wheel-centre path, the master cam and the lift error of wheel
wear (issue 13, "Tests": the wheel-centre path of a circle-arc cam is a circle; zero wear gives zero lift error; the
first-order wear error agrees with re-enveloping for small wear; and the master reproduces the cam lift through the
master follower and the bar ratio)."""

import functools
from pathlib import Path

import numpy as np
import pytest

from valvetrain import cam_grinding as mf, geometry
from valvetrain.design import run
from valvetrain.followers import FLAT, RollerFollower
from valvetrain.specification import load_spec
from valvetrain.laws.convex import ThreeArcLaw

E, A, R_ROLLER = 4e-3, 20e-3, 10e-3
"""An eccentric disc cam: eccentricity, disc radius and the roller radius [m]; its heel radius is A - E."""
HEEL = A - E
TOL = 1e-6
"""Lift tolerance of the simulated grinder [m]: its master and its wheel positions are sampled (30001 and 4000
points), the error of a roller on a polygon."""
THETA = np.linspace(-np.pi, np.pi, 721)


def follower_of(name, radius):
    """The follower object of a test parameter."""
    return RollerFollower(radius) if name == "roller" else FLAT


def disc_flat(theta):
    """Lift of a flat follower on the disc (support function e cos theta + a minus the heel radius)."""
    theta = np.asarray(theta, dtype=float)
    return np.stack([E * (1.0 + np.cos(theta)), -E * np.sin(theta), -E * np.cos(theta)])


def disc_roller(theta, radius=A):
    """Lift of a central roller follower on a disc of ``radius``: g = e cos theta + sqrt(R^2 - e^2 sin^2 theta),
    R = disc + roller radius, from the heel pitch radius of the design disc."""
    theta = np.asarray(theta, dtype=float)
    big = radius + R_ROLLER
    s = np.sqrt(big**2 - E**2 * np.sin(theta) ** 2)
    q = 0.5 * E**2 * np.sin(2.0 * theta)
    ds = -q / s
    d2s = -E**2 * np.cos(2.0 * theta) / s - q**2 / s**3
    return np.stack([E * np.cos(theta) + s - (A + R_ROLLER - E), -E * np.sin(theta) + ds, -E * np.cos(theta) + d2s])


@pytest.mark.parametrize("follower, derivs", [("flat", disc_flat), ("roller", disc_roller)])
@pytest.mark.parametrize("wheel", [0.05, 0.3])
def test_the_wheel_centre_path_of_a_disc_cam_is_a_circle(follower, derivs, wheel):
    """The offset of a circle is a concentric circle: radius a + R_w about the disc centre, exactly."""
    c, length, psi = mf.wheel_centre_path(derivs, THETA, HEEL, wheel, follower_of(follower, R_ROLLER))
    assert np.hypot(c[0], c[1] - E) == pytest.approx(A + wheel, abs=1e-15)
    assert length == pytest.approx(np.hypot(*c), abs=0)
    # the flat-follower closed form of the method: L = sqrt((R0 + h + R_w)^2 + h'^2), psi = theta + atan(h'/(...))
    if follower == "flat":
        h, dh = derivs(THETA)[:2]
        assert length == pytest.approx(np.hypot(HEEL + h + wheel, dh), rel=1e-15)
        inside = np.abs(THETA) < 3.0
        assert psi[inside] == pytest.approx(THETA[inside] + np.arctan(dh / (HEEL + h + wheel))[inside], abs=1e-14)


def test_the_wheel_centre_path_of_a_three_arc_cam_is_made_of_circle_arcs():
    """On the nose arc (radius r2 about (0, a)) and the opening flank arc (radius r1 about -(r1 - r0) u(-phi_p0)) the
    wheel centre keeps the arc's radius plus the wheel's from the arc's centre."""
    law = ThreeArcLaw(20e-3, 8e-3, np.radians(60.0), 5e-3)
    wheel = 0.25
    nose = np.linspace(-law.phi2, law.phi2, 101)
    c = mf.wheel_centre_path(law.derivatives, nose, law.r0, wheel)[0]
    assert np.hypot(c[0], c[1] - law.a) == pytest.approx(law.r2 + wheel, abs=1e-14)
    flank = np.linspace(-law.phi_p0, -law.phi_p0 + law.phi1, 101)
    centre = -(law.r1 - law.r0) * np.array([np.sin(-law.phi_p0), np.cos(-law.phi_p0)])
    c = mf.wheel_centre_path(law.derivatives, flank, law.r0, wheel)[0]
    assert np.hypot(c[0] - centre[0], c[1] - centre[1]) == pytest.approx(law.r1 + wheel, abs=1e-14)


@pytest.mark.parametrize("follower, derivs", [("flat", disc_flat), ("roller", disc_roller)])
def test_zero_wear_gives_zero_lift_error(follower, derivs):
    worn = mf.worn_wheel_lift(derivs, THETA, HEEL, 0.3, 0.0, follower_of(follower, R_ROLLER))
    assert worn - derivs(THETA)[0] == pytest.approx(0.0, abs=1e-15)
    first, phase = mf.wear_error_first_order(derivs, THETA, HEEL, 0.0, follower_of(follower, R_ROLLER))
    assert not first.any() and not phase.any()


def test_a_worn_wheel_on_a_flat_follower_cam_gives_no_lift_error():
    """The worn wheel grinds the cam offset by the wear: a flat follower's lift from its own base circle is the same."""
    law = ThreeArcLaw(20e-3, 8e-3, np.radians(60.0), 5e-3)
    worn = mf.worn_wheel_lift(law.derivatives, THETA, law.r0, 0.3, 2e-3)
    assert worn == pytest.approx(law.lift(THETA), abs=1e-15)


@pytest.mark.parametrize("wear", [1e-5, 1e-3, 5e-3])
def test_re_enveloping_is_exact_on_a_disc_cam_with_a_roller(wear):
    """A worn wheel on the design path grinds a disc larger by the wear; the roller's lift on it is known in closed
    form, and the re-enveloped lift equals it to round-off at any wear."""
    worn = mf.worn_wheel_lift(disc_roller, THETA, HEEL, 0.3, wear, RollerFollower(R_ROLLER))
    exact = disc_roller(THETA, A + wear)[0] - wear
    assert worn == pytest.approx(exact, abs=1e-15)


def test_the_first_order_wear_error_agrees_with_re_enveloping_for_small_wear():
    """w (sec beta - 1) with the phase shift w sin(beta) / g: the first-order error differs from the exact one by
    O(w^2), so the difference falls a hundredfold when the wear falls tenfold."""
    misses = []
    for wear in (1e-4, 1e-5):
        roller = RollerFollower(R_ROLLER)
        exact = mf.worn_wheel_lift(disc_roller, THETA, HEEL, 0.3, wear, roller) - disc_roller(THETA)[0]
        first, phase = mf.wear_error_first_order(disc_roller, THETA, HEEL, wear, roller)
        assert np.max(np.abs(first)) > 0.005 * wear   # a real error: the pressure angle reaches 7.7 deg
        misses.append(np.max(np.abs(exact - first)))
        assert misses[-1] < 0.01 * np.max(np.abs(first))
        # the lift is the design lift at theta + delta, plus w cos(beta) - w, to second order
        h, dh = disc_roller(THETA)[:2]
        beta = geometry.roller_pressure_angle(HEEL, R_ROLLER, h, dh)
        shifted = disc_roller(THETA + phase)[0] + wear * (np.cos(beta) - 1.0) - h
        assert np.max(np.abs(shifted - exact)) < 0.01 * np.max(np.abs(first))
    assert misses[1] < misses[0] / 50.0


def test_a_master_of_bar_ratio_one_and_a_roller_as_large_as_the_wheel_is_the_cam():
    law = ThreeArcLaw(20e-3, 8e-3, np.radians(60.0), 5e-3)
    wheel = 0.2
    base = mf.default_master_base_radius(law.r0, wheel, 1.0, wheel)
    assert base == pytest.approx(law.r0)
    master = mf.master_contour(law.derivatives, THETA, law.r0, wheel, 1.0, base, wheel)
    cam = law.profile(THETA, law.r0)[0]
    assert master == pytest.approx(cam, abs=1e-15)


def test_the_master_pitch_curvature_is_the_scaled_wheel_path_curvature():
    """With the default master base the pitch curve is i times the wheel path, whose radius is rho + R_w (the
    master's curvature is differentiated numerically: to 1e-4)."""
    law = ThreeArcLaw(20e-3, 8e-3, np.radians(60.0), 5e-3)
    wheel, i, r_m = 0.3, 2.0, 0.02
    theta = np.linspace(-law.phi2 * 0.9, law.phi2 * 0.9, 201)   # on the nose arc
    base = mf.default_master_base_radius(law.r0, wheel, i, r_m)
    rho = mf.master_pitch_curvature(law.derivatives, theta, law.r0, wheel, i, base, r_m)
    assert rho[1:-1] == pytest.approx(i * (law.r2 + wheel), rel=1e-4)


@functools.cache
def exhaust():
    """The roller exhaust valve of the polydyne example (concave flanks of 72 mm)."""
    return run(load_spec(Path(__file__).parents[1] / "examples" / "seed000-polydyne.toml")).valves["exhaust"]


def cam_for(follower, flat_wheel):
    """A cam, its heel radius, a wheel that grinds it and the roller radius: a three-arc cam (flat follower) with
    ``flat_wheel``, or the polydyne with ramps and concave flanks of the example (roller) with a 50 mm wheel."""
    if follower == "flat":
        law = ThreeArcLaw(20e-3, 8e-3, np.radians(60.0), 5e-3)
        return law, law.r0, flat_wheel, 0.0
    v = exhaust()
    return v.law, v.heel_radius, 0.05, v.roller_radius


@pytest.mark.parametrize("follower", ["flat", "roller"])
def test_the_master_reproduces_the_cam_lift_through_its_follower_and_the_bar_ratio(follower):
    """Grind on a simulated copy grinder: a roller r_m on the sampled master contour gives the head's travel; divided
    by the bar ratio it places the wheel centre; the wheel's envelope is the ground cam, and the cam's follower lift
    on it (its support function for a flat follower, the roller centre for a roller) is the design lift.  The flat
    follower's cam is a three-arc cam, the roller's the polydyne with ramps and concave flanks of the example."""
    law, heel, wheel, roller = cam_for(follower, 0.15)
    i, r_m = 2.5, 0.03
    base = 0.4   # not the default: the master's own heel circle
    dense = np.linspace(-np.pi, np.pi, 30001)
    master = mf.master_contour(law.derivatives, dense, heel, wheel, i, base, r_m, follower_of(follower, roller))
    assert np.min(np.hypot(*master)) == pytest.approx(base, abs=1e-12)
    # the master follower on the sampled contour, at every spindle angle psi
    psi = np.linspace(-np.pi, np.pi, 4000, endpoint=False)
    s = np.empty_like(psi)
    for k, p in enumerate(psi):
        along = master[0] * np.sin(p) + master[1] * np.cos(p)
        across = master[0] * np.cos(p) - master[1] * np.sin(p)
        near = np.abs(across) < r_m
        s[k] = np.max(along[near] + np.sqrt(r_m**2 - across[near] ** 2))
    assert np.min(s) == pytest.approx(base + r_m, abs=1e-7)   # a roller on a polygon of the master
    lift = mf.master_follower_lift(law.derivatives, psi, heel, wheel, i, follower_of(follower, roller))
    assert s - (base + r_m) == pytest.approx(lift, abs=1e-7)
    # the wheel centre from the head's travel, its envelope, and the follower on the ground cam
    length = heel + wheel + (s - (base + r_m)) / i
    centre = length * np.stack([np.sin(psi), np.cos(psi)])
    tangent = np.roll(centre, -1, axis=1) - np.roll(centre, 1, axis=1)
    normal = np.stack([-tangent[1], tangent[0]]) / np.hypot(*tangent)
    ground = centre - wheel * normal
    theta = np.linspace(-np.pi, np.pi, 181)
    u = np.stack([np.sin(theta), np.cos(theta)])
    if follower == "flat":
        got = np.max(ground.T @ u, axis=0) - heel
    else:
        t = np.stack([np.cos(theta), -np.sin(theta)])
        along, across = ground.T @ u, ground.T @ t
        got = np.max(np.where(np.abs(across) < roller, along + np.sqrt(np.clip(roller**2 - across**2, 0, None)),
                              -np.inf), axis=0) - heel - roller
    assert got == pytest.approx(law.lift(theta), abs=TOL)


def test_the_surface_grinder_lift_of_a_master_is_its_support_function():
    """A master of bar ratio 1 and a roller as large as the wheel is the cam, whose flat-follower lift is the law and
    whose polar radius is the cam's."""
    law = ThreeArcLaw(20e-3, 8e-3, np.radians(60.0), 5e-3)
    args = (law.r0, 0.2, 1.0, law.r0, 0.2)
    assert mf.master_flat_lift(law.derivatives, THETA, *args) == pytest.approx(law.lift(THETA), abs=1e-15)
    assert mf.master_polar_radius(law.derivatives, THETA, *args) == pytest.approx(
        law.polar_radius(THETA, law.r0), abs=1e-15)


def test_the_surface_grinder_lift_of_a_scaled_master_against_a_sampled_support_function():
    """The flat-follower lift of a master (bar ratio 2.5, its own heel circle) equals the largest projection of its
    densely sampled contour on each direction (a lower bound, short by the sagitta of the samples' chords)."""
    law = ThreeArcLaw(20e-3, 8e-3, np.radians(60.0), 5e-3)
    args = (law.r0, 0.15, 2.5, 0.4, 0.03)
    dense = np.linspace(-np.pi, np.pi, 40001)
    points = mf.master_contour(law.derivatives, dense, *args)
    u = np.stack([np.sin(THETA), np.cos(THETA)])
    sampled = np.max(points.T @ u, axis=0) - 0.4
    miss = mf.master_flat_lift(law.derivatives, THETA, *args) - sampled
    assert np.all(miss > -1e-15) and np.all(miss < 5e-9)


def test_a_concave_stretch_smaller_than_the_wheel_cannot_be_ground():
    """A roller cam with concave flanks: the wheel grinds it only while its radius is below the concave radius."""
    v = exhaust()
    theta = np.linspace(-np.pi, np.pi, 8001)
    concave = -v.grinding.concave_radius
    assert 0.05 < concave < 0.1
    for wheel, ok in ((0.9 * concave, True), (1.1 * concave, False)):
        assert mf.grindable(v.law.derivatives, theta, v.heel_radius, wheel, v.follower_model)[0] is ok


@pytest.mark.parametrize("follower", ["flat", "roller"])
def test_infeed_keeps_the_base_circle_and_its_first_order_error_agrees_with_re_enveloping(follower):
    """The head fed in by the wear: zero wear, zero error; the base circle is the design's; the first-order error
    w (1 - cos gamma) (times sec beta for a roller) differs from the re-enveloped one by O(w^2)."""
    law, heel, wheel, roller = cam_for(follower, 0.3)
    theta = np.linspace(-np.pi, np.pi, 721)
    kind = follower_of(follower, roller)
    zero = mf.worn_wheel_lift(law.derivatives, theta, heel, wheel, 0.0, kind, infeed=True)
    assert zero == pytest.approx(law.lift(theta), abs=1e-15)
    misses = []
    for wear in (1e-3, 1e-4):
        exact = mf.worn_wheel_lift(law.derivatives, theta, heel, wheel, wear, kind, infeed=True)
        error = exact - law.lift(theta)
        assert error[0] == pytest.approx(0.0, abs=1e-15)           # on the base circle: restored
        first = mf.wear_error_first_order(law.derivatives, theta, heel, wear, kind, wheel, True)[0]
        assert np.max(np.abs(error)) > 1e-3 * wear                 # a flat follower sees an error too
        misses.append(np.max(np.abs(error - first)))
        assert misses[-1] < 0.05 * np.max(np.abs(error))
    assert misses[1] < misses[0] / 50.0
