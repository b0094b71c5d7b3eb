"""The pivoted (finger) follower (valvetrain.followers.finger): its linkage against a closed form, the forward problem
against a loop closure solved by scipy's brentq in the test, the pressure angle against the contact normal of that
construction, and the cam synthesised for a valve law giving that law back through the forward problem."""

from dataclasses import replace

import numpy as np
import pytest
from scipy.optimize import brentq

from valvetrain.followers.finger import PivotedFollower

HEEL, ROLLER = 0.017, 0.00875
"""Cam heel radius and roller radius [m] (a DOHC finger's, the shipped modern example's)."""

FINGER = PivotedFollower(radius=ROLLER, pivot_x=-0.022, pivot_y=0.027, roller_arm=0.0225, pad_arm=0.036,
                         pad_drop=-0.010, pad_radius=0.012, valve_angle=np.radians(4.0), tip_offset=0.0005)
"""An end-pivot roller finger: pivot 22 mm aside and 1.25 mm above the roller centre's heel circle."""

LIFT, HALF = 0.009, 1.1
"""The valve law of the round trip: 9 mm over +-1.1 rad of camshaft, h = H cos^4(pi theta / (2 HALF)) (continuous
acceleration at its ends)."""


def valve_law(theta):
    """h, h', h'' of the test's valve law [m, m/rad, m/rad^2]; zero outside +-HALF."""
    k = np.pi / (2.0 * HALF)
    on = np.abs(theta) < HALF
    c, s = np.cos(k * theta), np.sin(k * theta)
    h = np.where(on, LIFT * c ** 4, 0.0)
    dh = np.where(on, -4.0 * LIFT * k * c ** 3 * s, 0.0)
    d2h = np.where(on, LIFT * k ** 2 * (12.0 * c ** 2 * s ** 2 - 4.0 * c ** 4), 0.0)
    return h, dh, d2h


def turn(w, angle):
    """w turned counter-clockwise by ``angle``, written out as a matrix product."""
    return np.array([[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]]) @ w


def hand_valve_lift(f, psi, psi0):
    """The valve tip's position from the pad's centre B = P + R(psi) (L_p, d_p): the highest point of the pad's circle
    along the valve axis a, B . a + rho_p, less its value at psi0 (a hand-built linkage)."""
    a = np.array([np.sin(f.valve_angle), np.cos(f.valve_angle)])
    pivot = np.array([f.pivot_x, f.pivot_y])

    def tip(p):
        return (pivot + turn(np.array([f.pad_arm, f.pad_drop]), p)) @ a + f.pad_radius
    return tip(psi) - tip(psi0)


def test_closed_form_with_the_roller_on_the_line_from_pivot_to_pad():
    """Pivot at (-L_r, R0 + R_r): the roller centre on the heel circle straight above the cam (psi0 = 0); pad centre on
    the same line (d_p = 0), valve square to it.  Then v = L_p sin psi, i = L_p cos psi / L_r: at the shut valve the
    ratio is the arm ratio L_p / L_r = 36 / 22.5 = 1.6; at psi = 0.2 rad v = 36 sin 0.2 = 7.152 mm,
    i = 1.6 cos 0.2 = 1.5681 (hand calculation); the pad's contact slides L_p (cos psi - 1) = -0.7167 mm."""
    f = PivotedFollower(radius=ROLLER, pivot_x=-0.0225, pivot_y=HEEL + ROLLER, roller_arm=0.0225, pad_arm=0.036)
    assert f.base_angle(HEEL) == pytest.approx(0.0, abs=1e-12)
    assert f.lever_ratio(np.array(0.0)) == pytest.approx(1.6, rel=1e-12)
    assert f.valve_lift_of(np.array(0.2), HEEL) == pytest.approx(0.036 * np.sin(0.2), rel=1e-12)
    assert f.lever_ratio(np.array(0.2)) == pytest.approx(1.6 * np.cos(0.2), rel=1e-12)
    assert f.tip_contact(np.array(0.2), HEEL) == pytest.approx(0.036 * (np.cos(0.2) - 1.0), rel=1e-12)
    assert f.angle_of(f.valve_lift_of(np.array(0.2), HEEL), HEEL) == pytest.approx(0.2, rel=1e-12)


def test_valve_lift_and_base_angle_against_a_hand_built_linkage():
    """The finger angle on the heel circle puts the roller centre at R0 + R_r from the cam centre; the valve lift at a
    few finger angles is the hand-built linkage's (B . a + rho_p)."""
    psi0 = FINGER.base_angle(HEEL)
    centre = np.array([FINGER.pivot_x, FINGER.pivot_y]) + turn(np.array([FINGER.roller_arm, 0.0]), psi0)
    assert np.hypot(*centre) == pytest.approx(HEEL + ROLLER, rel=1e-13)
    for dpsi in (0.05, 0.1, 0.2):
        assert FINGER.valve_lift_of(np.array(psi0 + dpsi), HEEL) == pytest.approx(
            hand_valve_lift(FINGER, psi0 + dpsi, psi0), rel=1e-12)


def radial_cam_path(lift, half):
    """A cam of a central translating roller follower (the same roller), h = lift cos^2(pi phi / (2 half)): its
    contour point E and outward normal n at the polar angle phi (the pitch curve g u, g = R0 + R_r + h, offset
    inwards by R_r along its normal (g u - h' t) / sqrt(g^2 + h'^2)), written out here."""
    k = np.pi / (2.0 * half)

    def h(phi):
        on = np.abs(phi) < half
        return (np.where(on, lift * np.cos(k * phi) ** 2, 0.0),
                np.where(on, -lift * k * np.sin(2.0 * k * phi), 0.0))

    def path(phi):
        hh, dh = h(phi)
        g = HEEL + ROLLER + hh
        u, t = np.stack([np.sin(phi), np.cos(phi)]), np.stack([np.cos(phi), -np.sin(phi)])
        n = (g * u - dh * t) / np.hypot(g, dh)
        return g * u - ROLLER * n, n
    return h, path


def loop_closure(f, h, theta):
    """The finger angle at camshaft angle theta by brentq (xtol 1e-15): the roller centre C(psi) = P + L_r e(psi),
    seen in the cam frame R(-theta) C, lies on the pitch curve, |q| = R0 + R_r + h(polar angle of q)."""
    pivot = np.array([f.pivot_x, f.pivot_y])

    def miss(psi):
        q = turn(pivot + f.roller_arm * np.array([np.cos(psi), np.sin(psi)]), -theta)
        return np.hypot(*q) - (HEEL + ROLLER + h(np.arctan2(q[0], q[1]))[0])
    psi0 = FINGER.base_angle(HEEL)
    return brentq(miss, psi0 - 1e-3, psi0 + 0.6, xtol=1e-15, rtol=4 * np.finfo(float).eps)


def test_forward_problem_against_a_loop_closure_solved_by_brentq():
    """The valve lift of a given cam (a translating roller's harmonic cam, 6 mm over +-1 rad) at a few camshaft
    angles: lift_on_path (pitch curve bracketed and refined) against brentq on the loop closure and the hand-built
    valve side, to 1e-10 m."""
    h, path = radial_cam_path(0.006, 1.0)
    theta = np.array([-0.9, -0.5, -0.2, 0.0, 0.3, 0.7, 1.5])
    got = FINGER.lift_on_path(path, theta, HEEL)
    psi0 = FINGER.base_angle(HEEL)
    want = [hand_valve_lift(FINGER, loop_closure(FINGER, h, t), psi0) for t in theta]
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-10)
    assert got[-1] == pytest.approx(0.0, abs=1e-12) and got[3] > 0.008


def test_pressure_angle_against_the_contact_normal_of_the_loop_closure():
    """The angle between the cam's contact normal (the radial cam's pitch-curve normal at the brentq solution, turned
    into the fixed frame) and the roller centre's velocity e_perp(psi), against pressure_angle of the valve law read
    off the same construction (v by brentq, v' by a central difference of step 1e-5 rad)."""
    h, path = radial_cam_path(0.006, 1.0)
    psi0 = FINGER.base_angle(HEEL)
    pivot = np.array([FINGER.pivot_x, FINGER.pivot_y])
    for theta in (-0.6, -0.2, 0.25, 0.55):
        psi = loop_closure(FINGER, h, theta)
        q = turn(pivot + FINGER.roller_arm * np.array([np.cos(psi), np.sin(psi)]), -theta)
        _, n = path(np.array([np.arctan2(q[0], q[1])]))
        normal = turn(n[:, 0], theta)
        velocity = np.array([-np.sin(psi), np.cos(psi)])
        want = np.arcsin(velocity[0] * normal[1] - velocity[1] * normal[0])
        step = 1e-5
        v = [hand_valve_lift(FINGER, loop_closure(FINGER, h, theta + d), psi0) for d in (-step, 0.0, step)]
        got = FINGER.pressure_angle(HEEL, np.array([v[1]]), np.array([(v[2] - v[0]) / (2 * step)]))
        assert got[0] == pytest.approx(want, abs=1e-7)


def synthesised_path(f, step=1e-6):
    """The synthesised cam as a path for the forward problem: its contour points at the design cam angle tau and the
    contour's own outward normals, from its tangent by a central difference of the points (step ``step`` rad), not
    the synthesis' normal: the roller circles must touch the envelope the contour really is."""
    def contour(tau):
        h, dh, _ = valve_law(tau)
        return f.contour(tau, HEEL, h, dh)

    def path(tau):
        tangent = (contour(tau + step) - contour(tau - step)) / (2 * step)
        n = np.stack([-tangent[1], tangent[0]]) / np.hypot(*tangent)   # clockwise contour: J t points outward
        return contour(tau), n
    return path


@pytest.mark.parametrize("f", [FINGER, PivotedFollower(
    radius=0.012, pivot_x=0.003, pivot_y=0.036, roller_arm=0.030, pad_arm=-0.040, pad_drop=0.002, pad_radius=0.010,
    valve_angle=np.pi)], ids=["end-pivot finger", "centre-pivot rocker"])
def test_synthesised_cam_gives_the_valve_law_back(f):
    """Inverse then forward: the cam enveloping the roller circles of the valve law, read by the forward problem,
    gives the valve law back to 1e-9 m over the turn (an end-pivot finger; a centre-pivot rocker with its valve end
    moving the other way, alpha = 180 deg)."""
    theta = np.linspace(-np.pi, np.pi, 721)
    got = f.lift_on_path(synthesised_path(f), theta, HEEL)   # the contour's normal by differences: ~1e-12 m
    np.testing.assert_allclose(got, valve_law(theta)[0], rtol=0, atol=1e-9)


def test_curvature_of_the_synthesised_cam():
    """On the heel circle the profile's radius is R0 (closed form); over the lift the pitch curve's radius against
    the circle through three of its points 1e-4 rad apart (finite differences, independent of the formula of W')."""
    h0 = np.zeros(1)
    assert FINGER.curvature(HEEL, h0, h0, h0)[0] == pytest.approx(HEEL, rel=1e-12)
    for t in (-0.8, -0.3, 0.0, 0.4):
        tau = t + np.array([-1e-4, 0.0, 1e-4])
        h, dh, d2h = valve_law(tau)
        a, b, c = FINGER.pitch_points(tau, HEEL, h, dh)[0].T
        circum = np.linalg.norm(a - b) * np.linalg.norm(b - c) * np.linalg.norm(c - a) / (
            2.0 * abs((b - a)[0] * (c - a)[1] - (b - a)[1] * (c - a)[0]))
        got = FINGER.pitch_radius(HEEL, h[1:2], dh[1:2], d2h[1:2])[0]
        assert got == pytest.approx(circum, rel=1e-5)


def test_the_contact_force_from_the_virtual_work():
    """N L_r cos(beta) dpsi = F dv: at the shut valve of the closed-form finger (beta from the pivot's offset only)
    N = F x 1.6 / cos(beta)."""
    f = PivotedFollower(radius=ROLLER, pivot_x=-0.0225, pivot_y=HEEL + ROLLER, roller_arm=0.0225, pad_arm=0.036)
    zero = np.zeros(1)
    assert f.pressure_angle(HEEL, zero, zero)[0] == pytest.approx(0.0, abs=1e-15)
    assert f.contact_force(1000.0, HEEL, zero, zero)[0] == pytest.approx(1600.0, rel=1e-12)


def test_an_arm_that_cannot_reach_the_heel_circle_is_refused():
    with pytest.raises(ValueError, match="cannot reach"):
        PivotedFollower(radius=ROLLER, pivot_x=-0.1, pivot_y=0.1, roller_arm=0.02, pad_arm=0.036).base_angle(HEEL)


def cross(u, w):
    """The z component of u x w, written out."""
    return u[0] * w[1] - u[1] * w[0]


def test_loads_hold_the_finger_in_equilibrium():
    """Under F = 1000 N at the valve: the moments about the pivot of the cam's force N n at the roller centre and the
    valve tip's -F a at the pad's contact cancel (the hand-built linkage: B = P + R(psi) (L_p, d_p), X = B + rho_p a,
    n the pitch curve's normal turned into the fixed frame); the pivot's load is |F a - N n|, and the moment of the
    pivot's reaction about the roller centre is the bending moment there."""
    theta = np.array([-0.8, -0.4, 0.0, 0.35, 0.7])
    h, dh, d2h = valve_law(theta)
    n_cam = FINGER.pitch_curve(theta, HEEL, h, dh, d2h)[3]
    normal, pivot, moment = FINGER.loads(1000.0, HEEL, h, dh)
    a = np.array([np.sin(FINGER.valve_angle), np.cos(FINGER.valve_angle)])
    p = np.array([FINGER.pivot_x, FINGER.pivot_y])
    for k, t in enumerate(theta):
        psi = FINGER.angle_of(h[k], HEEL)
        c = p + turn(np.array([FINGER.roller_arm, 0.0]), psi)
        x = p + turn(np.array([FINGER.pad_arm, FINGER.pad_drop]), psi) + FINGER.pad_radius * a
        n = turn(n_cam[:, k], t)
        cam_force, tip_force = normal[k] * n, -1000.0 * a
        torque = cross(c - p, cam_force) + cross(x - p, tip_force)
        assert abs(torque) < 1e-9 * 1000.0 * FINGER.pad_arm
        reaction = -(cam_force + tip_force)
        assert pivot[k] == pytest.approx(np.hypot(*reaction), rel=1e-12)
        assert moment[k] == pytest.approx(abs(cross(p - c, reaction)), rel=1e-9)


ROCKER = PivotedFollower(radius=0.012, pivot_x=0.003, pivot_y=0.036, roller_arm=0.030, pad_arm=-0.040, pad_drop=0.002,
                         pad_radius=0.010, valve_angle=np.pi)
"""A centre-pivot rocker whose valve end moves the other way (alpha = 180 deg)."""

INNER = PivotedFollower(radius=ROLLER, pivot_x=-0.022, pivot_y=0.027, roller_arm=0.0225, pad_arm=0.012, pad_drop=-0.004,
                        pad_radius=0.012, valve_angle=np.radians(4.0))
"""A finger whose valve pad lies between its pivot and its roller (L_p = 12 mm < L_r = 22.5 mm)."""


@pytest.mark.parametrize("f, where", [(FINGER, "roller"), (ROCKER, "pivot"), (INNER, "pad")])
def test_the_bending_moment_at_the_middle_of_the_three_forces(f, where):
    """Under F = 1000 N at the valve the finger is a beam under three forces (the hand-built linkage of
    :func:`test_loads_hold_the_finger_in_equilibrium`: cam's N n at C, valve's -F a at X, pivot's R at P); it bends
    most at the middle one, the moment there being that of the forces on one side: the valve's about C (end-pivot
    finger), the valve's about P (centre-pivot rocker: F x the arm G = dv/dpsi, a central difference of the tip),
    the cam's about X (the valve between pivot and roller)."""
    theta = np.array([-0.6, -0.2, 0.0, 0.4])
    h, dh, d2h = valve_law(theta)
    n_cam = f.pitch_curve(theta, HEEL, h, dh, d2h)[3]
    moment = f.loads(1000.0, HEEL, h, dh)[2]
    a = np.array([np.sin(f.valve_angle), np.cos(f.valve_angle)])
    p = np.array([f.pivot_x, f.pivot_y])
    psi0 = f.base_angle(HEEL)
    for k, t in enumerate(theta):
        psi = f.angle_of(h[k], HEEL)
        c = p + turn(np.array([f.roller_arm, 0.0]), psi)
        x = p + turn(np.array([f.pad_arm, f.pad_drop]), psi) + f.pad_radius * a
        cam_force = f.contact_force(1000.0, HEEL, h[k:k + 1], dh[k:k + 1])[0] * turn(n_cam[:, k], t)
        about = {"roller": abs(cross(x - c, -1000.0 * a)), "pivot": abs(cross(x - p, -1000.0 * a)),
                 "pad": abs(cross(c - x, cam_force))}
        assert moment[k] == pytest.approx(about[where], rel=1e-9)
        if where == "pivot":
            arm = (hand_valve_lift(f, psi + 1e-7, psi0) - hand_valve_lift(f, psi - 1e-7, psi0)) / 2e-7
            assert moment[k] == pytest.approx(1000.0 * abs(arm), rel=1e-6)


def test_the_mid_lift_rule_brings_the_contact_back():
    """The practice of rocker geometry (the arm square to the valve stem at mid-lift, Miller's mid-lift rule) in closed
    form: with the pad centre's line square to the valve axis at half the lift V, sin chi_0 = -V / (2 L_b) and
    sin chi_full = +V / (2 L_b), so cos chi_full = cos chi_0 and the contact at full lift is where it was with the valve
    shut; in between it runs out to L_b (1 - cos chi_0) = 36 (1 - sqrt(1 - (4.5/36)^2)) = 0.2823 mm (hand calculation)
    at mid-lift.  The pad on the finger's line (d_p = 0), valve angle chosen so that chi = 0 at v = 4.5 mm."""
    f0 = PivotedFollower(radius=ROLLER, pivot_x=-0.0225, pivot_y=HEEL + ROLLER, roller_arm=0.0225, pad_arm=0.036)
    f = PivotedFollower(radius=ROLLER, pivot_x=-0.0225, pivot_y=HEEL + ROLLER, roller_arm=0.0225, pad_arm=0.036,
                        valve_angle=np.arcsin(-0.0045 / 0.036) - f0.base_angle(HEEL))
    psi = f.angle_of(np.array([0.0, 0.0045, 0.009]), HEEL)
    tip = f.tip_contact(psi, HEEL)
    assert tip[2] == pytest.approx(tip[0], abs=1e-15)
    assert abs(tip[1] - tip[0]) == pytest.approx(0.036 * (1.0 - np.sqrt(1.0 - (4.5 / 36.0) ** 2)), rel=1e-12)


def lagrangian_force(f, inertia, h, dh, d2h, step=2e-6):
    """The force at the valve per camshaft speed squared that turns the finger, from Lagrange's equation of its
    kinetic energy written out with the hand-built linkage: psi(v) by brentq on :func:`hand_valve_lift`, the reduced
    mass m(v) = J / (dv/dpsi)^2 with dv/dpsi a central difference, F / omega^2 = m(v) v'' + (1/2) dm/dv v'^2 with dm/dv
    a central difference of m over the valve lift (step ``step`` [m])."""
    psi0 = f.base_angle(HEEL)

    def mass(v):
        psi = brentq(lambda p: hand_valve_lift(f, p, psi0) - v, psi0 - 0.6, psi0 + 0.6, xtol=1e-15, rtol=1e-15)
        g = (hand_valve_lift(f, psi + 1e-6, psi0) - hand_valve_lift(f, psi - 1e-6, psi0)) / 2e-6
        return inertia / g**2

    return np.array([mass(v) * a + 0.5 * (mass(v + step) - mass(v - step)) / (2.0 * step) * w**2
                     for v, w, a in zip(h, dh, d2h, strict=True)])


def test_the_finger_s_inertia_force_against_lagrange_s_equation_by_finite_differences():
    """J psi'' / G at five angles of the valve law against Lagrange's equation of the finger's kinetic energy, built by
    finite differences of the hand-built linkage (:func:`lagrangian_force`), to 1e-6 (found 2.2e-7); the
    velocity-squared term is 0.27-5.5 % of the force here, so a constant-ratio J / G^2 v'' would fail (it is checked
    to)."""
    inertia = 12e-6
    theta = np.array([-0.8, -0.45, -0.2, 0.3, 0.7])
    h, dh, d2h = valve_law(theta)
    hand = lagrangian_force(FINGER, inertia, h, dh, d2h)
    np.testing.assert_allclose(FINGER.inertia_force(inertia, HEEL, h, dh, d2h), hand, rtol=1e-6)
    frozen = FINGER.reduced_inertia(inertia, HEEL, h) * d2h
    assert np.min(np.abs(frozen - hand) / np.abs(hand)) > 1e-3


def test_the_pad_s_reach_is_refused_as_a_geometry_problem_not_a_traceback():
    """Fuzz case (valve axis at 120 deg): the valve pad cannot give the lift.  Before the fix the reach of a pad whose
    valve arm is negative on the heel circle was taken as L_b (1 + sin chi_0), the check passed, and the design
    stopped on a ValueError.  Reference: the largest lift of the hand-built linkage over a full turn of the finger."""
    f = replace(FINGER, valve_angle=np.radians(120.0))
    psi0 = f.base_angle(HEEL)
    reach = max(hand_valve_lift(f, p, psi0) for p in np.linspace(psi0 - np.pi, psi0 + np.pi, 20001))
    key, value, message, _ = f.geometry_problem(HEEL, 0.0085)
    assert (key, value) == ("finger_valve_angle_deg", "120")
    assert f"reaches a valve lift of {reach * 1e3:.4g} mm at most" in message
    below = f.geometry_problem(HEEL, 0.98 * reach)
    assert below is None or "reaches" not in below[2]


def test_the_geometry_refusals_fit_the_fuzzer_s_message_length():
    """Issue 36's fuzzer: the refusal of a finger the cam cannot push open named every key of its geometry and came
    to 304 characters on a valve (over the fuzzer's 300).  Each refusal's line, under a valve's key, stays within 300
    (a valve named "intake"; the longest key)."""
    for change in ({"valve_angle": np.pi}, {"pivot_x": 0.0}, {"pivot_y": 0.1}, {"valve_angle": np.radians(120.0)}):
        f = replace(FINGER, **change)
        key, value, message, joiner = f.geometry_problem(HEEL, 0.0085)
        assert len(f"valves.intake.cam.{key} = {value}{joiner}{message}") <= 300, change


@pytest.mark.parametrize("change, words", [
    ({"valve_angle": np.pi}, "not steadily outwards"),   # the roller falls 25.75 -> 20.15 mm as the valve opens
    ({"pivot_x": 0.0}, "turns clockwise"),               # lever ratio -1.51: the loads came out negative
])
def test_a_finger_the_cam_cannot_open_is_refused(change, words):
    """Fuzz cases that ran with negative loads and a ratio changing sign, graded only a warning.  Reference: the
    roller centre's distance from the cam centre, |P + L_r e(psi)|, over the finger angles that give the lift on
    the hand-built linkage must grow (the cam pushes the roller out), and the finger of the example passes."""
    f = replace(FINGER, **change)
    psi0 = f.base_angle(HEEL)
    psi = np.linspace(psi0, float(f.angle_of(0.008, HEEL)), 101)
    pivot = np.array([f.pivot_x, f.pivot_y])
    radius = np.hypot(*(pivot[:, None] + f.roller_arm * np.array([np.cos(psi), np.sin(psi)])))
    lift = np.array([hand_valve_lift(f, p, psi0) for p in psi])
    outwards_and_opening = np.all(np.diff(radius) > 0) and np.all(np.diff(lift) * np.diff(psi) > 0)
    assert not outwards_and_opening
    assert words in f.geometry_problem(HEEL, 0.008)[2]
    assert FINGER.geometry_problem(HEEL, 0.008) is None
