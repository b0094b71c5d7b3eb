"""A finger follower in the design chain (follower = "finger"): the valve law through the linkage, the cam's normal
force by the power balance, the lash adjuster's motion ratio from the geometry, and the refusals that name the key."""

from pathlib import Path

import numpy as np
import pytest

from valvetrain.design import run
from valvetrain.design.drive_strength import LoadMap, contact_loads
from valvetrain.design.dynamics import FINGER_MASS_BELOW, adjuster_ratio, finger_mass
from valvetrain.followers import PivotedFollower
from valvetrain.specification import SpecError, parse_spec, si

EXAMPLE = Path(__file__).parents[2] / "examples" / "modern-dohc-roller-finger.toml"


def example_text(drop_dynamics=True):
    """The shipped modern example, without its dynamics sweeps (the stages under test do not need them)."""
    text = EXAMPLE.read_text(encoding="utf-8")
    return text.replace("[valves.intake.dynamics]\nspeeds = 40\n", "").replace(
        "[valves.exhaust.dynamics]\nspeeds = 40\n", "") if drop_dynamics else text


@pytest.fixture(scope="module")
def design():
    return run(parse_spec(example_text()))


def test_the_valve_lift_is_the_law_and_the_cam_is_the_finger_s(design):
    """The law is the valve's (rocker ratio 1): the valve lift is the law's lift; the follower is the finger of the
    example's keys."""
    v = design.valves["intake"]
    theta = np.linspace(-1.0, 1.0, 9)
    np.testing.assert_array_equal(v.cam.valve_lift(theta), v.law.lift(theta))
    f = v.cam.follower_model
    assert isinstance(f, PivotedFollower) and f.roller_arm == pytest.approx(0.0225) and f.pad_arm == pytest.approx(0.036)
    assert v.profile.finger is not None and v.profile.finger.min_ratio <= v.profile.finger.rest_ratio


def test_contact_force_by_the_power_balance(design):
    """The cam's normal force N of a valve force F by the power balance N (dC/dtheta . n) = F dv/dtheta, with the
    roller centre's velocity dC/dtheta by central differences (step 1e-6 rad) of its position in the fixed frame and n
    the contact normal (the pitch curve's outward normal turned back into the fixed frame): contact_loads against it
    to 1e-6 relative."""
    v = design.valves["intake"]
    cam, f, heel = v.cam, v.cam.follower_model, v.cam.heel_radius
    theta = np.array([-0.6, -0.4, -0.15, 0.1, 0.3, 0.55])   # open, off the nose (dv/dtheta != 0)
    force = np.full((1, theta.size), 1000.0)
    got = contact_loads(cam, [LoadMap("quasi-static", np.array([1.0]), theta, force)])[0].force[0]
    step = 1e-6

    def centre(t):
        return f.centre(f.angle_of(cam.law.lift(t), heel))
    velocity = (centre(theta + step) - centre(theta - step)) / (2 * step)
    h, dh, d2h = cam.law.derivatives(theta)[:3]
    n = f.pitch_curve(theta, heel, h, dh, d2h)[3]
    c, s = np.cos(theta), np.sin(theta)
    normal = np.stack([c * n[0] - s * n[1], s * n[0] + c * n[1]])
    assert np.all(np.abs(dh) > 1e-4)
    want = 1000.0 * dh / np.sum(velocity * normal, axis=0)
    np.testing.assert_allclose(got, want, rtol=1e-6)


def test_the_lash_adjuster_at_the_pivot_moves_the_valve_by_the_finger_s_linkage(design):
    """The valve's motion per pivot motion along the adjuster's axis (by default the valve's, -a: the plunger extends
    towards the cam's side), by a central difference (step 1e-7 m) of the hand-built linkage: the pivot moved by s u,
    the finger's angle psi where the roller centre P + L_r e(psi) lies on the heel circle R_0 + R_r (Newton's
    iteration), the pad centre B = P + R(psi) (L_p, d_p) along a.  Near the straight lever's i_0 - 1 (i_0 = dv/d(L_r
    psi) on the heel circle), not equal to it: the valve and the roller's normal are not parallel."""
    spec = parse_spec(example_text())
    valve = si(spec).valves["intake"]
    f = design.valves["intake"].cam.follower_model
    a = np.array([np.sin(f.valve_angle), np.cos(f.valve_angle)])
    heel = valve.cam.base_radius + f.radius

    def tip(s):
        pivot = np.array([f.pivot_x, f.pivot_y]) - s * a
        p = f.base_angle(valve.cam.base_radius)
        for _ in range(50):
            centre = pivot + f.roller_arm * np.array([np.cos(p), np.sin(p)])
            slope = 2.0 * f.roller_arm * (centre @ np.array([-np.sin(p), np.cos(p)]))
            p -= (centre @ centre - heel**2) / slope
        turn = np.array([[np.cos(p), -np.sin(p)], [np.sin(p), np.cos(p)]])
        return (pivot + turn @ np.array([f.pad_arm, f.pad_drop])) @ a

    def pad(p):
        turn = np.array([[np.cos(p), -np.sin(p)], [np.sin(p), np.cos(p)]])
        return (np.array([f.pivot_x, f.pivot_y]) + turn @ np.array([f.pad_arm, f.pad_drop])) @ a

    psi0 = f.base_angle(valve.cam.base_radius)
    i0 = (pad(psi0 + 1e-7) - pad(psi0 - 1e-7)) / (2e-7 * f.roller_arm)
    ratio = adjuster_ratio(valve, design.valves["intake"].law)
    assert ratio == pytest.approx((tip(1e-7) - tip(-1e-7)) / 2e-7, rel=1e-6)
    assert f.rest_ratio(valve.cam.base_radius) == pytest.approx(i0, rel=1e-7) and i0 == pytest.approx(1.6492, abs=1e-4)
    assert ratio == pytest.approx(i0 - 1.0, rel=0.06)


@pytest.mark.parametrize("old, new, words", [
    ("opens_deg = 8.0\n", "opens_deg = 8.0\nrocker_ratio = 1.6\n", "rocker_ratio = 1.6: allowed 1 with cam.follower"),
    ('layout = "rocker"              #', 'layout = "direct"              #',
     "drive.layout = 'direct': allowed \"rocker\""),
    ('layout = "rocker"              #', 'layout = "rocker"\nvalve_arm_mm = 37.1 #',
     "drive.valve_arm_mm = 37.1: not allowed with cam.follower"),
    ("finger_roller_arm_mm = 22.5    # pivot to roller centre\n", "", "finger_roller_arm_mm is required"),
    ("finger_roller_arm_mm = 22.5", "finger_roller_arm_mm = 2.5", "cam.finger_roller_arm_mm = 2.5 from the pivot"),
    ("finger_valve_angle_deg = 12.0", "finger_valve_angle_deg = 80.0", "cam.finger_valve_angle_deg = 80: the valve pad"),
])
def test_refusals_name_the_key(old, new, words):
    text = example_text()
    assert old in text
    with pytest.raises(SpecError, match=words.replace("(", r"\(")):
        run(parse_spec(text.replace(old, new, 1)))


MEASURED = Path(__file__).parents[2] / "examples" / "measured-lobe.toml"

FINGER_KEYS = """follower = "finger"
roller_radius_mm = 8.75
finger_pivot_x_mm = -22.0
finger_pivot_y_mm = {pivot_y}
finger_roller_arm_mm = 22.5
finger_pad_arm_mm = 36.0
finger_pad_drop_mm = -10.0
finger_pad_radius_mm = 12.0
finger_valve_angle_deg = 12.0
"""


def test_a_finger_on_a_measured_table_is_refused_where_its_pivot_cannot_reach_the_cam():
    """A measured table gives the lift only once it is read, after the specification's checks: a finger whose roller
    arm (22.5 mm) cannot reach the heel circle from its pivot (83 mm from the cam centre) is refused by the design
    naming the key, as the specification's checks refuse it on a law of given lift (a ValueError of the finger's
    linkage stopped the design before: fuzz campaign of issue 36)."""
    text = MEASURED.read_text(encoding="utf-8").replace("rocker_ratio = 1.6\n", "")
    text = text.replace('base_radius_mm = 20.0\n', 'base_radius_mm = 20.0\n' + FINGER_KEYS.format(pivot_y=80.0))
    text += '\n[valves.intake.drive]\nlayout = "rocker"\n'
    with pytest.raises(SpecError, match=r"valves\.intake\.cam\.finger_roller_arm_mm = 22\.5 from the pivot .* "
                       r"cannot reach the roller centre's heel circle"):
        run(parse_spec(text, source_dir=MEASURED.parent))
    reach = run(parse_spec(text.replace("finger_pivot_y_mm = 80.0", "finger_pivot_y_mm = 27.0"),
                           source_dir=MEASURED.parent))
    assert reach.valves["intake"].profile.finger is not None


def test_the_reduced_mass_table_of_a_finger_pressed_near_its_dead_point_stays_within_the_pad_s_reach():
    """The example's finger with its pad arm at 0 (the pad 10 mm beside the pivot, the shut valve 0.3 mm above the
    pad's lowest reach): the table of J / G^2 reaches halfway to that reach below the shut valve, not the fixed 1 mm
    (where no finger angle gives the valve's position: a ValueError of the linkage stopped the design of such a
    finger without a lash adjuster, fuzz campaign of issue 36).  The reach below, L_b (1 + sin chi_0), against the
    lowest valve lift over a whole turn of the finger, sampled (an independent evaluation)."""
    f = PivotedFollower(radius=0.00875, pivot_x=-0.022, pivot_y=0.027, roller_arm=0.0225, pad_arm=0.0,
                        pad_drop=-0.010, pad_radius=0.012, valve_angle=np.radians(12.0))
    heel = 0.017
    table = finger_mass(f, 12e-9, heel, 0.009, "valve")
    psi = np.linspace(-np.pi, np.pi, 2_000_001)
    assert f.reach_below(heel) == pytest.approx(-f.valve_lift_of(psi, heel).min(), rel=1e-9)
    assert f.reach_below(heel) < FINGER_MASS_BELOW
    assert table.position[0] == pytest.approx(-0.5 * f.reach_below(heel), rel=1e-12)
    assert np.all(np.isfinite(table.mass)) and np.all(table.mass > 0.0)


def test_the_pad_s_contact_stays_on_the_valve_tip():
    """Issue 36: a finger whose pad meets the valve 50 mm off its axis was accepted with no check.  The largest
    distance of the contact point from the valve axis over the lift against the hand-built linkage (finger_linkage:
    the contact X = B + rho_p a, its offset (X - X_0) . a_perp + x_0 at 201 valve lifts, psi by brentq), graded
    against the tip's radius less 0.5 mm: the example's fingers pass (0.26 mm against 6 mm stems by default, 0.2 x
    the throat); a 5.5 mm stem with the contact 2.5 mm off the axis fails (2.76 > 2.25 mm); 50 mm off fails."""
    from finger_linkage import hand_finger

    text = example_text().replace("[valves.intake.parts]\n", "[valves.intake.parts]\nstem_diameter_mm = 5.5\n", 1)
    for offset, passes in ((0.0, True), (2.5, False), (50.0, False)):
        spec = parse_spec(text.replace("finger_valve_angle_deg = 12.0  #", f"finger_tip_offset_mm = {offset}\n"
                                       "finger_valve_angle_deg = 12.0  #", 1))
        v = run(spec).valves["intake"]
        hand = hand_finger(v.cam)
        across = np.array([hand.a[1], -hand.a[0]])
        lifts = np.linspace(0.0, v.law.lift_max + v.law.ramp_height, 201)
        reach = max(abs((hand.pad(hand.angle(y)) - hand.pad(hand.psi0)) @ across + offset * 1e-3) for y in lifts)
        (c,) = [c for c in v.checks if c.code == "finger.tip_contact"]
        assert c.value == pytest.approx(reach, rel=1e-5, abs=1e-9)
        assert c.high == pytest.approx(5.5e-3 / 2 - 0.5e-3) and c.severity == "failure" and c.passed == passes
    assert all(c.passed for c in run(parse_spec(example_text())).checks if c.code == "finger.tip_contact")


def test_the_camshaft_link_is_reduced_to_the_valve_by_the_finger_s_ratio(design):
    """The camshaft's stiffness under the cam, k_cam = 1 / (its deflection under 1 N, eq. 7.3 of Valve-train practical
    works (n.d.)), reaches the valve divided by i_0^2, i_0 = 1.6492 the finger's ratio on the heel circle (central
    difference of the hand-built linkage as above), not by rocker_ratio^2 = 1; in series with the lash adjuster's
    oil column (its own stage's stiffness at the valve)."""
    from valvetrain.design.dynamics import adjuster_link, build_train, lever_ratio
    from valvetrain.strength import camshaft_deflection

    spec = parse_spec(example_text(drop_dynamics=False))
    valve = si(spec).valves["intake"]
    v = design.valves["intake"]
    params = build_train(valve.dynamics, valve, v.law, v.drive, "valves.intake", v.cam.cam_speed)[1]
    p = valve.parts
    k_cam = 1.0 / camshaft_deflection(1.0, p.cam_to_bearing, p.camshaft_span - p.cam_to_bearing, p.camshaft_diameter,
                                      p.camshaft_bore, p.camshaft_modulus)
    i0 = lever_ratio(valve, v.law)
    assert i0 == pytest.approx(1.6492, abs=1e-4)
    oil = adjuster_link(valve, v.law, v.drive, v.cam.cam_speed, "valves.intake")[0]
    assert params.links[0] == pytest.approx(1.0 / (i0**2 / k_cam + 1.0 / oil), rel=1e-12)


def test_the_camshaft_drive_torque_is_the_valve_force_s_power(design):
    """Without friction the camshaft's torque is the power at the valve over its speed, T = F dv/dtheta (virtual
    work): the lubrication stage's drive torque less its friction torque, under the cam's normal force of F = 1000 N at
    the valve (contact_loads), against 1000 N x dv/dtheta."""
    from valvetrain.design.lubrication import contact_map

    valve = si(parse_spec(example_text())).valves["intake"]
    v = design.valves["intake"]
    theta = np.array([-0.6, -0.3, 0.0, 0.2, 0.5])
    normal = contact_loads(v.cam, [LoadMap("quasi-static", np.array([1.0]), theta, np.full((1, 5), 1000.0))])[0]
    c = contact_map(valve.lubrication, v.cam, valve.parts.cam_width, valve.parts.contact_modulus, theta,
                    normal.force, np.array([[300.0]]))
    dv = v.law.derivatives(theta)[1]
    np.testing.assert_allclose(c["drive_torque"][0] - c["friction_torque"][0], 1000.0 * dv, rtol=1e-12, atol=1e-12)


def hand_arm_and_force(f, heel, inertia, h, dh, d2h, step=2e-6):
    """The finger's effective valve arm G = dv/dpsi and its inertia force at the valve per camshaft speed squared
    (Lagrange's equation, F / omega^2 = m(v) v'' + (1/2) dm/dv v'^2 with m = J / G^2) by finite differences of the
    hand-built linkage: the tip B(psi) . a from P + R(psi) (L_p, d_p), psi(v) by brentq."""
    from scipy.optimize import brentq

    a = np.array([np.sin(f.valve_angle), np.cos(f.valve_angle)])

    def tip(p):
        turn = np.array([[np.cos(p), -np.sin(p)], [np.sin(p), np.cos(p)]])
        return (np.array([f.pivot_x, f.pivot_y]) + turn @ np.array([f.pad_arm, f.pad_drop])) @ a

    psi0 = f.base_angle(heel)

    def arm(v):
        psi = brentq(lambda p: tip(p) - tip(psi0) - v, psi0 - 0.6, psi0 + 0.6, xtol=1e-15, rtol=1e-15)
        return (tip(psi + 1e-6) - tip(psi - 1e-6)) / 2e-6

    def mass(v):
        return inertia / arm(v) ** 2

    force = [mass(v) * acc + 0.5 * (mass(v + step) - mass(v - step)) / (2.0 * step) * w**2
             for v, w, acc in zip(h, dh, d2h, strict=True)]
    return np.array([arm(v) for v in h]), np.array(force)


def test_the_spring_requirement_and_the_dynamics_take_the_finger_s_inertia_by_its_variable_ratio():
    """The intake of the example: the reduced mass m_v = valve + retainer + cotters + spring / 3 + J / G_0^2 (eq. 5.2 of
    Valve-train practical works (n.d.), G_0 the hand-built linkage's arm on the heel circle); the required spring
    force at seven angles of the event K_z |P_j|, P_j = omega^2 ((m_v - J / G_0^2) h'' + F_J) with F_J from Lagrange's
    equation by finite differences (:func:`hand_arm_and_force`), to 1e-6; the dynamics' mass M = m_v - J / G_0^2 +
    J / G^2 at the lift of the largest required force."""
    from valvetrain.design.dynamics import build_train

    spec = parse_spec(example_text(drop_dynamics=False))
    valve = si(spec).valves["intake"]
    design = run(parse_spec(example_text()))
    v = design.valves["intake"]
    law, f, parts = v.law, v.cam.follower_model, valve.drive.masses
    inertia, omega = parts.rocker_inertia, v.cam.cam_speed
    assert inertia == pytest.approx(12e-6)
    g0 = hand_arm_and_force(f, v.cam.heel_radius, inertia, np.zeros(1), np.zeros(1), np.zeros(1))[0][0]
    spring = v.drive.spring.design.mass
    rest = parts.valve_kg + parts.retainer_kg + parts.cotters_kg + spring / 3.0
    assert v.drive.masses.at_valve == pytest.approx(rest + inertia / g0**2, rel=1e-9)
    theta = np.unique(np.concatenate([np.linspace(law.valve_opens, law.valve_closes, 2001), law.breakpoints]))
    theta = theta[(theta >= law.valve_opens) & (theta <= law.valve_closes)]
    pick = np.linspace(0, theta.size - 1, 7).astype(int)
    h, dh, d2h = law.derivatives(theta[pick])[:3]
    force = omega**2 * (rest * d2h + hand_arm_and_force(f, v.cam.heel_radius, inertia, h, dh, d2h)[1])
    expected = valve.drive.spring_reserve * np.clip(-force, 0.0, None)
    assert np.count_nonzero(expected) >= 3
    np.testing.assert_allclose(v.drive.required_force[pick], expected, rtol=1e-6, atol=1e-9)
    at = int(np.argmax(v.drive.required_force))
    arm = hand_arm_and_force(f, v.cam.heel_radius, inertia, v.drive.lift[at:at + 1], np.zeros(1), np.zeros(1))[0][0]
    params = build_train(valve.dynamics, valve, law, v.drive, "valves.intake", omega)[1]
    assert params.mass == pytest.approx(rest + inertia / arm**2, rel=1e-9)


def test_the_finger_s_bending_stress_by_hand(design):
    """The example's finger: b x h = 5 x 12 mm (two cheeks of 2.5 mm beside the roller), W = b h^2 / 6 = 5 x 144 / 6
    = 120 mm^3; sigma = M / W with M the largest bending moment at the roller's section (the middle of its three
    forces, tested in tests/followers/test_finger.py), against 150 MPa; without the section keys the check is not run
    and a note names them."""
    st = design.valves["intake"].drive.strength
    moment = st.finger.bending_moment_max
    assert 10.0 < moment < 20.0
    check = next(c for c in st.checks if c.code == "strength.finger_bending")
    assert check.value == pytest.approx(moment / 120e-9, rel=1e-12)
    assert st.finger.bending_stress_max == check.value and check.high == 150e6 and check.passed
    text = example_text().replace("finger_section_height_mm = 12.0", "", 1)
    bare = run(parse_spec(text)).valves["intake"].drive.strength
    assert bare.finger.bending_stress_max is None
    assert "finger_bending: not checked, parts.finger_section_height_mm not given" in bare.not_checked


def test_a_finger_has_no_flat_face_to_edge_load(design):
    """A finger touches the cam with its roller: no note asks for a flat follower's face diameter (before, the
    strength stage sent every follower but a tappet's roller to the flat face's edge loading, and the finger's
    record said flat_follower_edge_loading was not checked for want of parts.tappet_face_diameter_mm)."""
    notes = design.to_dict()["valves"]["intake"]["strength"]["not_checked"]
    assert notes and not any(n.startswith("flat_follower_edge_loading") for n in notes)
