"""The multi-mass train (valvetrain.dynamics.models.MultiMassTrain) against independent references: scipy's DOP853 on
its equations written out in tests/reference_multi.py, and the closed forms of the spring's surge."""

import numpy as np
import pytest

from valvetrain.dynamics.coils import coil_spring
from valvetrain.dynamics.models import natural_modes, pushrod_train
from valvetrain.dynamics.events import runs
from valvetrain.dynamics.sweep import sweep

from conftest import seed000_law
from reference_dynamics import RPM
from reference_multi import PushrodParts, PushrodReference

EXAMPLE = PushrodParts(tappet_mass=0.030, pushrod_mass=0.035, rocker_inertia=25e-6, valve_mass=0.074, valve_arm=0.040,
                       rocker_ratio=1.6, cam_stiffness=360302978.25 * 1.6**2, pushrod_stiffness=19108519.77 * 1.6**2,
                       rocker_stiffness=45e6, rate=66501.13, preload=311.4477, spring_mass=0.0813621, active_coils=3.0,
                       end_coils=2.0, coils=8, lash=0.4e-3)
"""The train of examples/pushrod-dynamics.toml with model = "multi" (its results.json parameters): the part masses of
[drive.masses], the camshaft's 360303 N/mm and the pushrod's 19109 N/mm at the valve estimated from [parts], 45000 N/mm
for the rocker, the designed spring (5.1 mm wire, 3 active coils of 5, 43.66 mm installed), the clearance 0.25 mm at
the cam, 0.4 mm at the valve; on the Kurz cam of the appendix (conftest.seed000_law, the example's intake)."""


def example_train(parts):
    spring = coil_spring(parts.rate, parts.preload, parts.spring_mass, parts.active_coils, 5.1e-3, 43.66e-3,
                         parts.coils, parts.end_coils)
    return pushrod_train(parts.tappet_mass, parts.pushrod_mass, parts.rocker_inertia, parts.valve_mass, parts.valve_arm,
                         parts.rocker_ratio, parts.cam_stiffness, parts.pushrod_stiffness, parts.rocker_stiffness,
                         np.inf, [spring], parts.lash)


def test_the_multi_mass_sweep_agrees_with_dop853():
    """The example's multi-mass train swept by the package's kernel (RK4 at 0.1 cam deg) and integrated by scipy's
    DOP853 at rtol 1e-10 from the same rest, each contact state a smooth segment ended by its events
    (tests/reference_multi.py: the equations written out from the model's definition, not from the network), two
    camshaft revolutions, the second compared: at 4500 rpm (the cam carries the valve) and at the rated 7000 rpm (the
    follower leaves the cam at the start of the deceleration, -38.8 cam deg).  The valve lift agrees within 0.5 um,
    the largest lift within 1e-6, the seating velocity within 1e-4 (found 1e-5), the smallest cam force while the
    cam lifts within 1 N, and the separations (no force, the tappet at or above the cam's rigid lift, the valve more
    than 1 um off its seat) start at the same recorded samples.  (The cam force at the lash take-up differs by up to
    200 N for a sample or two: the kernel's fixed step does not locate the contact's closing.)"""
    law, train = seed000_law(), example_train(EXAMPLE)
    reference = PushrodReference(law, EXAMPLE)
    speeds = np.array([4500.0, 7000.0]) / 2 * RPM
    result = sweep(law, train, speeds, revolutions=2, tolerance=-1.0)
    for i, omega in enumerate(speeds):
        s = result.speed(i)
        lift, tappet, force, seatings = reference.run(omega, 2, s.theta)
        lifting = (s.kinematic_lift > 0) & (lift > 0)
        assert np.abs(lift - s.lift).max() < 5e-7
        assert s.lift.max() == pytest.approx(lift.max(), rel=1e-6)
        assert s.seating_velocity == pytest.approx(seatings[0][1], rel=1e-4)
        assert s.min_contact_force == pytest.approx(force[lifting].min(), abs=1.0)
        separated = (force <= 0) & (s.kinematic_lift > 0) & (tappet >= s.kinematic_lift) & (lift > 1e-6)
        np.testing.assert_array_equal(s.theta[runs(separated)[:, 0]], s.jump_intervals[:, 0])
    assert result.speed(0).jump_intervals.size == 0 and result.speed(1).jump_intervals[0, 0] == pytest.approx(
        np.radians(-38.8))


def test_the_example_s_surge_modes_are_the_spring_s():
    """The example's train: its coil masses are the 3 active coils' of the spring's 5 (the end coil at the retainer on
    the valve), so with the valve held its first mode is the spring chapter's surge frequency, pi sqrt(K / m_s) =
    583.58 Hz (Valve-train practical works (n.d.), eq. 6.13, d / (D^2 i_p) sqrt(G / (2 rho))), times the exact ratio of
    a chain of 8 coil masses, (18 / pi) sin(pi / 18) = 0.99493 (580.62 Hz; 447 Hz before, with the inactive coils as
    coil mass: sqrt(3/5) lower); on its drive with the seat open the valve moves a little and the lowest mode of the
    train lies 0.6 % below it (577.4 Hz).  The coil masses m_s / 9 each, the valve's node the valve with the retainer
    and cotters, one end coil (a fifth of the spring) and half a coil mass."""
    net = example_train(EXAMPLE).network()
    m_s = EXAMPLE.spring_mass * 3 / 5
    continuous = np.pi * np.sqrt(EXAMPLE.rate / m_s) / (2 * np.pi)
    held = natural_modes(net, held=("valve",))[0][0] / (2 * np.pi)
    assert held == pytest.approx(18 / np.pi * np.sin(np.pi / 18) * continuous, rel=1e-12)
    assert continuous == pytest.approx(583.58, abs=0.01)
    lowest = natural_modes(net, opened=("seat",))[0][0] / (2 * np.pi)
    assert 0.99 * held < lowest < held
    coils = [m for name, m in zip(net.names, net.mass, strict=True) if "coil" in name]
    assert coils == pytest.approx([m_s / 9] * 8, rel=1e-12)          # half a coil mass on the head
    assert net.mass[net.valve] == pytest.approx(EXAMPLE.valve_mass + EXAMPLE.spring_mass / 5 + m_s / 18, rel=1e-12)
