"""Error control of a sweep's headlines (valvetrain.dynamics.accuracy): the jump speed of a harmonic cam against its
closed form on light and stiff trains, and the jump speed, the bounce height and onset and the seating velocity of
an elastic train against a second integrator (scipy's DOP853 on the same equations, tests/reference_dynamics.py)."""

import numpy as np
import pytest

from valvetrain.dynamics.accuracy import BOUNCE_ACCURACY, JUMP_ACCURACY, ONSET_ACCURACY, SEATING_ACCURACY, refine
from valvetrain.dynamics.models import one_mass_train
from valvetrain.dynamics.sweep import sweep

from reference_dynamics import appendix_train, harmonic_cam, harmonic_jump_speed, reference_events

RPM = np.pi / 60
"""Camshaft rad/s per engine rpm of a four-stroke."""


@pytest.mark.parametrize("mass, rate, preload, stiffness, zeta, base_error", [
    (1.0, 5e3, 50.0, 1e8, 0.1, 2.5e-3), (1.0, 5e3, 50.0, 1e9, 0.1, 6e-3),
    (0.2, 50e3, 300.0, 1e8, 0.2, None), (0.2, 50e3, 300.0, 1e9, 0.2, 3e-3)])
def test_the_jump_speed_of_a_harmonic_cam_against_its_closed_form(mass, rate, preload, stiffness, zeta, base_error):
    """A harmonic cam with a base circle (L = 8 mm over 2 rad) on a light, soft train (1 kg, K = 5 N/mm, F0 = 50 N)
    and on a 0.2 kg train of K = 50 N/mm, F0 = 300 N, each with a drive of 1e8 and 1e9 N/m, swept at the default
    0.1 cam deg over 81 speeds 0.5 % apart.  Reference: the closed form of reference_dynamics.harmonic_jump_speed, the
    steady forced response of the linear oscillator the train is while the cam carries it (its free vibration has
    decayed to below 1e-6 at the nose, exp(-C phi / 2 M omega)).  The refined jump speed is within the 0.05 % of
    JUMP_ACCURACY (the issue asks 0.1 % at the defaults; found within 1e-6) and within its estimated error, which is
    within 0.05 %; the fixed step alone is 0.30 % and 0.73 % off on the light train and 0.36 % at 1e9 N/m on the
    other, growing with the stiffness (the stages of RK4 clip the contact force near zero)."""
    train = one_mass_train(mass, stiffness, rate, preload, damping_ratio=zeta)
    law = harmonic_cam(8e-3, 1.0)
    exact = harmonic_jump_speed(8e-3, 1.0, train)
    rigid = np.sqrt(2 * (preload + rate * 8e-3) / (mass * 8e-3 * np.pi**2))
    result = sweep(law, train, np.linspace(0.8, 1.2, 81) * rigid * 1.0013)
    refined = refine(law, train, result)
    jump, error = refined.headline["jump_speed"], refined.accuracy.jump_speed
    assert abs(jump / exact - 1) < JUMP_ACCURACY
    assert error < JUMP_ACCURACY * jump and abs(jump - exact) <= error
    assert refined.accuracy.jump_speed_grid <= refined.accuracy.jump_speed   # both parts, each finite
    if base_error is not None:
        assert abs(result.headline()["jump_speed"] / exact - 1) > base_error


@pytest.fixture(scope="module")
def appendix():
    """The appendix train of tests/reference_dynamics.py swept over engine speeds from 4000 to 8750 rpm about 40 rpm
    apart (the built-in example's spacing), refined with the rated speed 7000 rpm as its extra speed."""
    law, train = appendix_train()
    result = sweep(law, train, np.linspace(4000, 8750, 118) * RPM)
    rated = sweep(law, train, [7000 * RPM])
    return law, train, result, refine(law, train, result, seating_top=7000 * RPM, extra=rated)


def test_the_jump_speed_of_an_elastic_train_against_a_second_integrator(appendix):
    """Reference: the smallest contact force while the cam lifts, by DOP853 (rtol 1e-10), without the contact law's
    clamp at zero (reference_dynamics.reference_events: negative once the follower has left the cam), whose zero is
    the jump speed: positive 0.05 % below the refined jump speed (7953 rpm) and negative 0.05 % above it."""
    law, train, _, refined = appendix
    jump = refined.headline["jump_speed"]
    assert 7900 * RPM < jump < 8000 * RPM and refined.accuracy.jump_speed < JUMP_ACCURACY * jump
    below, above = (reference_events(law, train, jump * f)["min_force"] for f in (1 - JUMP_ACCURACY, 1 + JUMP_ACCURACY))
    assert below > 0.0 > above


def test_the_bounce_onset_against_a_second_integrator(appendix):
    """The bounce onset (5331 rpm) is where the bounce height of DOP853 (its peaks located by the event finder,
    reference_dynamics.reference_events) crosses 1 um: below it 10 engine rpm lower, above it 10 rpm higher (the
    issue's bound); its estimated error is within ONSET_ACCURACY.  The former kernel, which did not split the step of
    the seat's closing consistently, put the onset at 5397 rpm, 65 rpm above."""
    law, train, result, refined = appendix
    onset = refined.headline["bounce_onset_speed"]
    assert 5300 * RPM < onset < 5360 * RPM and refined.accuracy.bounce_onset < ONSET_ACCURACY * onset
    below, above = (reference_events(law, train, onset + d * RPM)["bounce_height"] for d in (-10, 10))
    assert below < result.bounce_tolerance < above


@pytest.mark.parametrize("rpm", [5554.0, 6525.0, 7820.0])
def test_the_refined_bounce_height_against_a_second_integrator(appendix, rpm):
    """Refined as the rated speed is (an extra speed), the bounce height (1.6-2.5 um) is within BOUNCE_ACCURACY of
    DOP853's (its largest lift after the first seating, located by the event finder) and so is its estimated error,
    and the seating velocity within SEATING_ACCURACY."""
    law, train, _, _ = appendix
    ref = reference_events(law, train, rpm * RPM)
    result = sweep(law, train, [rpm * RPM])
    refined = refine(law, train, result, extra=result)
    height, error = refined.extra.bounce_height[0], refined.extra_bounce_error[0]
    assert abs(height - ref["bounce_height"]) < BOUNCE_ACCURACY * height and error < BOUNCE_ACCURACY * height
    seat, seat_error = refined.extra.seating_velocity[0], refined.extra_seating_error[0]
    assert abs(seat - ref["seating_velocity"]) < SEATING_ACCURACY * abs(seat) and seat_error < SEATING_ACCURACY * abs(seat)


def test_the_largest_seating_velocity_against_a_second_integrator(appendix):
    """The largest |seating velocity| of the sweep (at 8548 rpm, the valve floating) refined, and the rated speed's:
    within SEATING_ACCURACY of DOP853's seating (the y = 0 crossing after the largest lift, located by the event
    finder) and of their estimated errors."""
    law, train, result, refined = appendix
    head = refined.headline
    ref = reference_events(law, train, head["max_seating_velocity_speed"],
                           int(result.revolutions[np.argmin(np.abs(result.cam_speeds - head["max_seating_velocity_speed"]))]))
    assert head["max_seating_velocity"] == pytest.approx(abs(ref["seating_velocity"]), rel=SEATING_ACCURACY)
    assert refined.accuracy.max_seating_velocity < SEATING_ACCURACY * head["max_seating_velocity"]
    rated = reference_events(law, train, 7000 * RPM)["seating_velocity"]
    assert refined.extra.seating_velocity[0] == pytest.approx(rated, rel=SEATING_ACCURACY)
    assert refined.extra_seating_error[0] < SEATING_ACCURACY * abs(rated)
