"""The train models (valvetrain.dynamics.models): multi-mass (4 + N1 + N2) trains reduced to one mass, spring surge,
coil clash, layouts and the parts' stiffness estimates (spec section 12)."""

from dataclasses import replace

import numpy as np
import pytest

from valvetrain.dynamics.coils import CoilSpring, coil_spring_from_geometry
from valvetrain.dynamics.models import OneMassTrain, direct_train, natural_frequencies, pushrod_train, rocker_train
from valvetrain.dynamics.sweep import simulate, sweep
from valvetrain.masses import reduced_mass_at_valve
from valvetrain.springs import natural_frequency

from reference_dynamics import RPM, spec12

PARTS = dict(tappet_mass=0.06, pushrod_mass=0.09, rocker_inertia=6e-5, valve_mass=0.12, valve_arm=0.045,
             rocker_ratio=1.5)


def test_pushrod_masses_are_seed000_reduced_mass():
    """With massless-coil springs (N = 0, m_s/3 on the valve) the node masses of the pushrod train add up to
    Valve-train practical works (n.d.), eq. (5.2), valvetrain.masses.reduced_mass_at_valve."""
    spring = CoilSpring(67.5e3, 400.0, 0.05, coils=0)
    train = pushrod_train(**PARTS, cam_stiffness=5e7, pushrod_stiffness=4e7, rocker_stiffness=3e7,
                          valve_stiffness=2e8, springs=[spring])
    expected = reduced_mass_at_valve(0.12, 0.0, 0.0, 0.05, 0.09, 0.06, 6e-5, 0.045, 1.5)
    assert train.network().mass.sum() == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("rpm", [2000, 3000])
def test_rigid_links_reduce_to_one_mass(rpm):
    """Drive links 10^4 times stiffer than the cam link make the four drive masses move as one: with the clearance
    of the worked example (0.3 mm, taken up at the cam in both trains) the valve lift, the cam force and the seating
    velocity equal those of the one-mass train with M = their sum, c = the links in series, C = the cam link's and the
    same seat (spec section 12), over the whole revolution: the drive parts are held, so they stay on the valve when
    it seats (with joints that parted they flew off the stopped valve).  The multi-mass train's seating velocity is
    within 0.2 % of the one-mass train's (1.3 % with links 10^3 times stiffer: the difference falls with the links'
    compliance); below (2000 rpm) and at the design speed of the cam."""
    law, _ = spec12()
    spring = CoilSpring(67.5e3, 400.0, 0.05, coils=0)
    k2 = PARTS["rocker_ratio"] ** 2
    c = 15e6
    rigid = 1e4 * c
    multi = pushrod_train(**PARTS, cam_stiffness=c * k2, pushrod_stiffness=rigid * k2 / 2, rocker_stiffness=2 * rigid,
                          valve_stiffness=2 * rigid, springs=[spring], lash=0.3e-3)
    net = multi.network()
    one = OneMassTrain(net.mass.sum(), 1.0 / sum(1.0 / x for x in multi.links), net.damping[net.cam_element], 67.5e3,
                       400.0, 1.5, 0.3e-3, net.stiffness[net.seat_element], net.damping[net.seat_element])
    omega = rpm * RPM
    a, b = simulate(law, multi, omega), simulate(law, one, omega)
    assert a.lift.max() > 7e-3
    assert np.abs(a.lift - b.lift).max() < 1e-6
    assert np.abs(a.contact_force - b.contact_force).max() < 0.005 * b.contact_force.max()
    assert a.seating_velocity == pytest.approx(b.seating_velocity, rel=2e-3)


@pytest.mark.parametrize("coils", [4, 8, 16, 32])
def test_first_surge_frequency_tends_to_the_spring_formula(coils):
    """Coil-mass model with the valve held: its first mode is that of a uniform fixed-fixed chain,
    2 (N + 1) sqrt(K/m_s) sin(pi / (2 (N + 1))), below Valve-train practical works (n.d.), eq. (6.13),
    omega_c1 = d / (D^2 i_p) sqrt(G / (2 rho)) = pi sqrt(K / m_s) of the continuous spring, by exactly the ratio
    (2 (N + 1) / pi) sin(pi / (2 (N + 1))) (0.99493 at N = 8; its series 1 - pi^2 / (24 (N + 1)^2)).  The coil masses are
    the active coils' alone (6 of 8 coils): with the two end coils as coil mass the mode was sqrt(6/8) lower."""
    d, big_d, i_p = 4e-3, 30e-3, 6.0
    spring = coil_spring_from_geometry(d, big_d, i_p, 300.0, installed_length=40e-3, coils=coils)
    train = direct_train(0.05, 0.1, 5e7, 2e8, [spring])
    modes = natural_frequencies(train.network(), held=("valve", "tappet"))
    analytic = natural_frequency(d, big_d, i_p, 8.0e10, 7850.0)
    ratio = 2 * (coils + 1) / np.pi * np.sin(np.pi / (2 * (coils + 1)))
    assert modes[0] == pytest.approx(ratio * analytic, rel=1e-12)
    assert 1 - ratio == pytest.approx(np.pi**2 / (24 * (coils + 1) ** 2), rel=0.02)


def test_coil_clash_margin():
    """Slow cam: the coils share the valve lift evenly, so the closing margin of each segment is
    (closing gap - valve lift) / (N + 1); a gap below the lift makes the coils clash."""
    law, _ = spec12()
    springs = [CoilSpring(45e3, 250.0, 0.04, closing_gap=gap, coils=8) for gap in (10e-3, 6e-3)]
    trains = [pushrod_train(**PARTS, cam_stiffness=4e7, pushrod_stiffness=3e7, rocker_stiffness=3e7,
                            valve_stiffness=2e8, springs=[s, CoilSpring(22.5e3, 150.0, 0.02, coils=4)], lash=0.3e-3)
              for s in springs]
    results = [sweep(law, t, [300 * RPM], revolutions=1) for t in trains]
    lift = results[0].lift[0].max()
    assert results[0].clash_margin[0] == pytest.approx((10e-3 - lift) / 9, abs=5e-6)
    assert results[1].clash_margin[0] == pytest.approx((6e-3 - lift) / 9, abs=5e-6) and results[1].clash_margin[0] < 0
    assert results[1].headline()["coil_clash_speed"] == 300 * RPM
    assert results[0].surge_amplitude.shape == (1, 12)


def test_surge_grows_at_resonance():
    """A cam harmonic on the first surge frequency (omega_c1 = 13 omega_cam, Valve-train practical works (n.d.), eq. 6.14's ratio below
    its limit of 10 is the resonant case) makes the coils swing more than off resonance (omega_c1 = 13.5)."""
    law, _ = spec12()
    spring = CoilSpring(45e3, 400.0, 0.05, coils=8, damping_ratio=0.01)
    train = rocker_train(3e-5, 0.12, 0.04, 1.5, 1e8, 3e7, 2e8, [spring], lash=0.3e-3)
    omega_c1 = natural_frequencies(train.network(), held=("valve", "rocker"))[0]
    r = sweep(law, train, [omega_c1 / 13, omega_c1 / 13.5])
    amp = r.surge_amplitude.max(axis=1)
    assert amp[0] > 1.5 * amp[1]


def test_layouts_lash_and_held_joints():
    """Every layout takes up its clearance at the cam contact, the only contact of the drive; its joints are held
    (bilateral): the cam contact and the seat are the network's only compression-only elements."""
    spring = CoilSpring(45e3, 250.0, 0.04, coils=2)
    p = pushrod_train(**PARTS, cam_stiffness=4e7, pushrod_stiffness=3e7, rocker_stiffness=3e7, valve_stiffness=2e8,
                      springs=[spring], lash=0.3e-3).network()
    r = rocker_train(3e-5, 0.12, 0.04, 1.5, 1e8, 3e7, 2e8, [spring], lash=0.2e-3).network()
    d = direct_train(0.05, 0.1, 5e7, 2e8, [spring], lash=0.25e-3).network()
    for net, lash in ((p, 0.3e-3), (r, 0.2e-3), (d, 0.25e-3)):
        assert net.elements[int(np.argmax(net.gap))] == "cam contact" and net.lash == lash
        assert [net.elements[i] for i in np.flatnonzero(net.unilateral)] == ["cam contact", "seat"]
    assert p.names[:4] == ("tappet", "pushrod", "rocker", "valve") and len(p.names) == 6
    assert replace(p).valve == 3


def test_a_multi_mass_train_starts_in_static_equilibrium():
    """The pushrod train at rest on the base circle, by hand: the clearance open at the cam, the valve on its seat
    under the preloads of both springs and their rates in parallel with the seat, y = -(F0_1 + F0_2) / (c_s + K_1 +
    K_2), the held drive parts with it and each spring's coils at their share (N + 1 - i) / (N + 1) of it; every
    node's force balances (the accelerations of the first step are zero)."""
    outer, inner = CoilSpring(45e3, 250.0, 0.04, coils=4), CoilSpring(20e3, 120.0, 0.02, coils=2)
    train = pushrod_train(**PARTS, cam_stiffness=4e7, pushrod_stiffness=3e7, rocker_stiffness=3e7,
                          valve_stiffness=2e8, springs=[outer, inner], lash=0.3e-3, seat_stiffness=2e8)
    net = train.network()
    y = -(250.0 + 120.0) / (2e8 + 45e3 + 20e3)
    coils = [y * (5 - i) / 5 for i in range(1, 5)] + [y * (3 - i) / 3 for i in range(1, 3)]
    np.testing.assert_allclose(net.x_init, [y] * 4 + coils, rtol=1e-12, atol=0)
    law, _ = spec12()
    r = simulate(law, train, 300 * RPM, revolutions=1)
    assert np.abs(r.lift[:100] - y).max() < 1e-15          # at rest on the base circle until the ramp


def test_geometry_estimates():
    """Stiffness and inertia estimates from part geometry against hand formulas: a steel tube E pi (D^2 - d^2)/4/L;
    a rectangular cantilever 3 E b h^3 / (12 l^3); the camshaft between bearings 3 E I l / (l1^2 l2^2) (simply
    supported beam, the force over the deflection of Valve-train practical works (n.d.), eq. 7.3); a rocker of two equal slender arms
    m l^2 / 3."""
    from valvetrain.dynamics.models import camshaft_stiffness, pushrod_stiffness, rocker_arm_inertia, rocker_stiffness

    e = 2.1e11
    assert pushrod_stiffness(0.25, 8e-3, 5e-3) == pytest.approx(e * np.pi * (8e-3**2 - 5e-3**2) / 4 / 0.25)
    assert rocker_stiffness(0.04, 12e-3, 10e-3) == pytest.approx(3 * e * 12e-3 * (10e-3) ** 3 / 12 / 0.04**3)
    inertia = np.pi * 0.025**4 / 64
    assert camshaft_stiffness(0.03, 0.05, 0.025) == pytest.approx(3 * e * inertia * 0.08 / (0.03**2 * 0.05**2))
    assert rocker_arm_inertia(0.09, 0.04, 0.04) == pytest.approx(0.09 * 0.04**2 / 3)


def test_a_trains_network_is_built_once():
    """A train keeps its network and the network its highest frequency (models._kept: every sweep of a design asks
    for them); a train replaced (dataclasses.replace) builds its own: the lash changed is the cam contact's gap."""
    from valvetrain.dynamics.models import one_mass_train

    train = one_mass_train(0.25, 15e6, 67.5e3, 400.0, lash=3e-4)
    net = train.network()
    assert train.network() is net and net.highest_frequency() == net.highest_frequency()
    other = replace(train, lash=2e-4).network()
    assert other.gap[net.cam_element] == 2e-4 and net.gap[net.cam_element] == 3e-4
    assert other.highest_frequency() == pytest.approx(net.highest_frequency(), rel=1e-12)
