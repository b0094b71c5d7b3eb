"""A finger follower's inertia by its variable ratio in the dynamics (valvetrain.dynamics.models.VariableMass, the
kernels' node of variable mass and valvetrain.design.dynamics.finger_mass), each against an independent reference:
the reduced mass of a finger whose linkage has a closed form, the one-mass train with that mass integrated by scipy
solve_ivp (DOP853, rtol 1e-10) from Lagrange's equation written out here, and the work-energy balance of an undamped
node under a constant force."""

from dataclasses import replace
from types import SimpleNamespace

import numpy as np
import pytest

from reference_dynamics import RPM, one_mass_rhs, spec12
from valvetrain.design.dynamics import finger_mass
from valvetrain.dynamics.models import one_mass_train
from valvetrain.dynamics.sweep import simulate, sweep
from valvetrain.followers.finger import PivotedFollower
from valvetrain.laws import KurzLaw

HEEL, ROLLER, ROLLER_ARM, PAD_ARM = 0.017, 0.00875, 0.0225, 0.018
"""A finger whose roller sits straight above the cam on the heel circle with its pad on the line from the pivot and
the valve square to it: the pivot at (-L_r, R0 + R_r), so psi_0 = 0 and v = L_p sin psi, G = dv/dpsi = L_p cos psi
= sqrt(L_p^2 - v^2) (tests/followers/test_finger.py, the closed form).  A short pad arm, 18 mm, so that the ratio
changes much over a lift of 8 mm."""

FINGER = PivotedFollower(radius=ROLLER, pivot_x=-ROLLER_ARM, pivot_y=HEEL + ROLLER, roller_arm=ROLLER_ARM,
                         pad_arm=PAD_ARM)
INERTIA, REST = 1.5e-5, 0.1
"""J about the pivot [kg m^2] (J / L_p^2 = 46.3 g on the heel circle, 58.8 g at 8.3 mm) and the valve's own mass
[kg]."""


def hand_mass(v):
    """m(v) = m_0 + J / (L_p^2 - v^2) and dm/dv = 2 J v / (L_p^2 - v^2)^2 of the closed-form finger, by hand."""
    g2 = PAD_ARM**2 - v**2
    return REST + INERTIA / g2, 2.0 * INERTIA * v / g2**2


def finger_train():
    """spec12's law (k = 1.5, lash 0.3 mm: the cam moves the valve side 8.32 mm, the valve lifts 8.02 mm) on a
    one-mass train whose valve carries the finger: m(y) = hand_mass(y + lash), the reference mass its value at the
    largest lift; and the largest cam displacement at the valve [m]."""
    law, _ = spec12()
    lash, top = 0.3e-3, 1.5 * (law.lift_max + law.ramp_height)
    variable = finger_mass(FINGER, INERTIA, HEEL, top, "valve", REST, lash)
    train = one_mass_train(hand_mass(top)[0], 15e6, 67.5e3, 400.0, 1.5, lash, damping_ratio=0.05)
    return law, replace(train, variable_mass=variable), top


def test_the_finger_s_mass_table_against_the_closed_form():
    """The table of the finger's node (:func:`finger_mass`) at every position: m = m_0 + J / (L_p^2 - v^2) and
    m' = 2 J v / (L_p^2 - v^2)^2 with v = x + lash (closed form by hand), to 1e-12; it spans 1 mm below the shut
    valve to 1.5 x the law's top, 12.5 mm here (under half-way from the top to the pad's reach, L_p = 18 mm)."""
    _, train, top = finger_train()
    table = train.variable_mass
    mass, slope = hand_mass(table.position + train.lash)
    np.testing.assert_allclose(table.mass, mass, rtol=1e-12)
    np.testing.assert_allclose(table.slope, slope, rtol=1e-12, atol=1e-15)
    assert table.position[0] == pytest.approx(-1e-3 - train.lash, rel=1e-12)
    assert table.position[-1] + train.lash == pytest.approx(1.5 * top, rel=1e-12)
    assert np.ptp(np.diff(table.position)) < 1e-15


def lagrange_reference(law, train, omega, velocity_term=True):
    """The valve lift of the one-mass train with the finger's mass by scipy's DOP853 at rtol 1e-10 over one revolution
    from rest: Lagrange's equation of T = m(y) y_dot^2 / 2, m(y) y_ddot + (1/2) m'(y) y_dot^2 = F_c - F_0 - K y + F_s
    (tests/reference_dynamics.py, the one-mass train's contact and seat laws) with m(y) = :func:`hand_mass` (y +
    lash); without the velocity term, m(y) y_ddot = F."""
    from scipy.integrate import solve_ivp

    def mass(y):
        m, dm = hand_mass(y + train.lash)
        return m, dm if velocity_term else 0.0

    return solve_ivp(one_mass_rhs(law, train, omega, mass), (0, 2 * np.pi / omega),
                     [-train.preload / train.seat_stiffness, 0.0], method="DOP853", rtol=1e-10, atol=1e-13,
                     dense_output=True)


def contact_force(law, train, omega, t, state):
    """The cam contact force at the cam [N] of the reference's state (y, y_dot) at the times ``t``: k max(0, c delta
    + C delta_dot) where delta = k h - x_0 - y > 0 (the one-mass train's contact law)."""
    d = law.derivatives(-np.pi + omega * t)[:2] * train.rocker_ratio
    y, v = state
    gap = d[0] - train.lash - y
    force = np.maximum(train.stiffness * gap + train.damping * (omega * d[1] - v), 0.0)
    return train.rocker_ratio * np.where(gap > 0.0, force, 0.0)


@pytest.mark.parametrize("rpm", [1500, 2500, 3000])
def test_the_kernel_s_variable_mass_agrees_with_lagrange_s_equation_by_solve_ivp(rpm):
    """The compiled RK4 at 0.1 cam deg with the finger's node of variable mass against :func:`lagrange_reference` at
    three camshaft speeds: the valve lift agrees within 5 nm up to the first seating (found 1.4-1.6 nm) and within
    1 um over the revolution (the bounces after it: found 0.19-0.59 um; the same train with a constant mass of 0.15
    kg, 0.30-0.35 um there, a fixed step against a stiff seat); the cam contact force within 0.1 N up to the first
    seating (found 0.034-0.038 N).  The velocity-squared force is what the cam feels: the same reference without it
    has a contact force 6.2, 20.5 and 30.8 N away from the kernel's before the seating."""
    law, train, _ = finger_train()
    omega = rpm * RPM
    r = simulate(law, train, omega, revolutions=1)
    t = (r.theta + np.pi) / omega
    reference = lagrange_reference(law, train, omega).sol(t)
    before = r.theta < r.seating_angle
    assert reference[0].max() > 0.0079 and np.degrees(r.seating_angle) > 50.0
    assert np.abs(r.lift - reference[0])[before].max() < 5e-9
    assert np.abs(r.lift - reference[0]).max() < 1e-6
    assert np.abs(r.contact_force - contact_force(law, train, omega, t, reference))[before].max() < 0.1
    without = lagrange_reference(law, train, omega, velocity_term=False).sol(t)
    assert np.abs(r.contact_force - contact_force(law, train, omega, t, without))[before].max() > 5.0


def test_an_undamped_node_of_variable_mass_keeps_its_energy():
    """The finger's node alone under a constant force F and nothing else (no spring force, the cam and the seat
    apart): its kinetic energy is the work of F, m(y) y_dot^2 / 2 = F (y - y_0) (the work-energy theorem of
    Lagrange's equation with a configuration-dependent mass; sign: the velocity-squared force slows a node whose mass
    grows as it moves).  The kernel keeps it within 1e-6 of F (y - y_0) from 1 mm of travel on (found 1.2e-10); the
    mass grows by 24 % over the 11 mm travelled: a node without the velocity term (m(y) y_ddot = F) would gain the
    work of (1/2) m' y_dot^2 besides, 15 % of F (y - y_0) here (the trapezoid rule on the recorded path; asserted
    above 5 %), and one whose term had the wrong sign twice that."""
    _, train, _ = finger_train()
    net = train.network()
    force, y0 = 0.0085, 0.5e-3
    gap = net.gap.copy()
    gap[net.cam_element] = 1.0                               # the cam never reaches the valve
    spring = net.elements.index("spring at valve")
    free = replace(net, stiffness=np.where(np.arange(3) == spring, 0.0, net.stiffness), damping=np.zeros(3),
                   gap=gap, preload=np.where(np.arange(3) == spring, -force, 0.0), x_init=np.array([y0]))
    omega = 10.0                                             # one revolution: 0.63 s
    r = sweep(KurzLaw(6.25e-3, 0.25e-3, 1.146e-3, *np.radians([27.0, 6.0, 38.0])),
              SimpleNamespace(network=lambda: free), [omega], revolutions=1, tolerance=-1.0)
    y, v = r.lift[0], r.velocity[0]
    work = force * (y - y0)
    mass = hand_mass(y + train.lash)[0]
    moved = y - y0 > 1e-3
    assert 0.011 < y.max() < train.variable_mass.position[-1] and mass.max() / mass.min() > 1.2
    np.testing.assert_allclose(0.5 * mass[moved] * v[moved] ** 2, work[moved], rtol=1e-6)
    slope = hand_mass(y + train.lash)[1]                     # the work a node without the velocity term gains
    term = np.concatenate([[0.0], np.cumsum(0.5 * np.diff(y) * 0.5 * (slope[1:] * v[1:]**2 + slope[:-1] * v[:-1]**2))])
    assert np.max(term[moved] / work[moved]) > 0.05
