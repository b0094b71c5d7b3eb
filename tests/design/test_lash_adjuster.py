"""The lash adjuster stage of a design (valvetrain.design.lash_adjuster): the plunger's leak-down, pump-up and the
valve held off its seat over a revolution, by hand (the adjuster's physics and the stage in a design run:
tests/test_lash_adjuster.py)."""

import numpy as np
import pytest

from valvetrain.design.lash_adjuster import plunger_motion

UM = 1e-6


def test_plunger_motion_by_hand():
    """Extension z = 10, 9, 9.5, 12, 12, 11, 11.5 um at seven instants; the lift event covers instants 1-4, the valve
    off its seat at 1-4, the base circle at 0 and 6.  Steps -1, +0.5, +2.5, 0, -1, +0.5: the sink is 1 + 1 = 2 um; the
    gain while the valve is off its seat in the event (steps into instants 1-4) is 0.5 + 2.5 = 3 um (the last +0.5,
    a refill on the base circle, is not pump-up); the valve seats on the base circle: held open 0."""
    z = np.array([10.0, 9.0, 9.5, 12.0, 12.0, 11.0, 11.5]) * UM
    lift = np.array([0.0, 1e-3, 2e-3, 1e-3, 0.5e-3, 0.0, 0.0])
    event = np.array([0, 1, 1, 1, 1, 0, 0], dtype=bool)
    base = np.array([1, 0, 0, 0, 0, 0, 1], dtype=bool)
    leak, pump, held = plunger_motion(z, lift, event, base)
    assert (leak / UM, pump / UM, held) == pytest.approx((2.0, 3.0, 0.0), abs=1e-9)
    # the valve kept 2 um and 5 um off its seat on the base circle: held open by the smaller, 2 um
    lift[[0, 6]] = 2 * UM, 5 * UM
    assert plunger_motion(z, lift, event, base)[2] == pytest.approx(2 * UM, rel=1e-12)
    # a gain outside the event (the valve's bounce after its return) is refill, not pump-up
    assert plunger_motion(z, lift, np.zeros(7, dtype=bool), base)[1] == 0.0
