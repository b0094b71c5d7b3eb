"""The checks and notes of the dynamics stage (valvetrain.design.dynamics_checks): the note on a speed whose motion
does not repeat (the seating velocity and jump checks are tested through the design, tests/design/test_dynamics.py)."""

import numpy as np

from valvetrain.design.dynamics_checks import unsettled_note
from valvetrain.units import MM


def test_a_speed_that_does_not_repeat_over_an_undamped_seat_says_so():
    """Issue 36 (fuzz: the dynamic law with seat_damping_ratio = 0): one mass with its clearance open between the lifts
    rests on an undamped seat, sqrt((c_s + K) / M) / 2 pi = 5987 Hz for the fuzz case's M = 0.1414 kg, K = 72.4 kN/m,
    c_s = 200 kN/mm (closed form), no damper acting on it; the note says it does not decay (a RuntimeWarning of a
    division by a decay of zero before), in English and in Russian."""
    from types import SimpleNamespace

    from valvetrain.dynamics.models import one_mass_train
    from valvetrain.report.names import translate

    mass, spring, seat = 0.14138065, 7.23848447e4, 2e8
    net = one_mass_train(mass, 1.29315348e7, spring, 400.0, lash=0.4 * MM, damping_ratio=0.05, seat_stiffness=seat,
                         seat_damping_ratio=0.0).network()
    events = SimpleNamespace(jumped=np.array([False, False]), bounce_count=np.array([0, 0]))
    result = SimpleNamespace(converged=np.array([True, False]), events=events, cam_speeds=np.array([100.0, 400.0]))
    speeds = 2.0 * result.cam_speeds
    note = unsettled_note(result, speeds, net, 3, adjuster=False)
    hz = np.sqrt((seat + spring) / mass) / (2 * np.pi)
    assert round(hz) == 5987
    assert note == (f"1 of 2 speeds, {speeds[1] * 30 / np.pi:.0f} rpm, did not repeat within 3 revolutions; at 1 the "
                    "slowest vibration of the train, 5987 Hz, is undamped between the lifts (no damping acts on it "
                    "with the valve on its seat): it does not decay")
    assert "не затухает" in translate(note, "ru")
