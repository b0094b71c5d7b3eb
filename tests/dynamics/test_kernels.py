"""The compiled integrator of the dynamics (valvetrain.dynamics.kernels): its RK4 against scipy's DOP853 on the same
equations, and the split of the speeds into blocks for the threads."""

from dataclasses import replace

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from valvetrain.dynamics.kernels import BLOCK_SPEEDS, blocks
from valvetrain.dynamics.sweep import simulate, sweep

from reference_dynamics import RPM, appendix_train, one_mass_rhs, reference_events, spec12


def test_fast_integrator_agrees_with_solve_ivp():
    """The compiled RK4 at 0.1 cam deg against scipy's DOP853 at rtol 1e-10 on the same equations (spec section
    12) over one revolution at the design speed: the valve lift agrees within 0.2 um."""
    law, train = spec12()
    omega = 3000 * RPM
    sol = solve_ivp(one_mass_rhs(law, train, omega), (0, 2 * np.pi / omega), [-train.preload / train.seat_stiffness, 0.0], method="DOP853",
                    rtol=1e-10, atol=1e-13, dense_output=True)
    r = simulate(law, train, omega, revolutions=1)
    reference = sol.sol((r.theta + np.pi) / omega)[0]
    assert reference.max() > 7e-3
    assert np.abs(r.lift - reference).max() < 2e-7


@pytest.mark.parametrize("rpm", [5554.0, 6525.0, 7820.0])
def test_a_bounce_off_the_seat_against_a_second_integrator(rpm):
    """The appendix train of tests/reference_dynamics.py at engine speeds where its valve bounces 1.6-2.5 um after
    the first seating: at the default 0.1 cam deg the bounce height is within 0.5 % of DOP853's (rtol 1e-10, its
    largest lift after the seating located by the event finder, reference_dynamics.reference_events).  The step the
    seat closes in is split at the closing and each part integrates its own law (the seat open, then closed): with
    the law of the state at each stage, a stage that found the seat closed in the first part (open in the second)
    applied (dropped) the seat's damping force at that stage alone, and the bounce read 11 %, 1.2 % and 1.4 % low."""
    law, train = appendix_train()
    reference = reference_events(law, train, rpm * np.pi / 60)["bounce_height"]
    assert 1.5e-6 < reference < 2.5e-6
    assert sweep(law, train, [rpm * np.pi / 60]).events.bounce_height[0] == pytest.approx(reference, rel=5e-3)


def test_blocks_of_equal_sub_steps_by_hand():
    """20 speeds of 3 sub-steps and 3 of 5, two threads: the group of 20 splits into min(20 // 8, 2) = 2 pieces of
    ceil(20 / 2) = 10 speeds, rounded up to 16 (a multiple of 8), so blocks of 16 and 4; the group of 3 is one block.
    Costs 16 x 3 = 48, 4 x 3 = 12 and 3 x 5 = 15 put the blocks in the order 0, 2, 1 (by hand from the rules of
    the docstring)."""
    n_sub = np.array([5, 3] * 3 + [3] * 17)
    order, start, seq = blocks(n_sub, workers=2)
    assert start.tolist() == [0, 16, 20, 23] and seq.tolist() == [0, 2, 1]
    assert sorted(order.tolist()) == list(range(23))                     # every speed once
    for j in range(3):
        assert np.unique(n_sub[order[start[j]:start[j + 1]]]).size == 1  # one sub-step count a block
    assert np.all(np.diff(order[:20]) > 0)                               # speeds keep their order in a group


def test_a_large_group_splits_into_blocks_of_at_most_block_speeds():
    """200 speeds of one sub-step count: ceil(200 / 64) = 4 pieces of 50, rounded up to 56: blocks of 56, 56, 56, 32."""
    assert BLOCK_SPEEDS == 64
    _, start, _ = blocks(np.full(200, 7), workers=2)
    assert np.diff(start).tolist() == [56, 56, 56, 32]



def test_the_one_node_kernel_gives_the_general_kernels_records(monkeypatch):
    """A one-mass train runs on its own kernel (kernels.integrate_node, sweep.one_node): the appendix train at a slow
    speed that takes sub-steps, two speeds whose valve bounces after seating (its seat closings split,
    kernels._split_step) and one whose follower jumps, each until it repeats and each for two revolutions (the state
    carried from one to the next), recorded as the general kernel (kernels.integrate_block) records them: equal to the
    bit, every record and the revolutions too, with only an exact rest held (REST_AMPLITUDE 0: a state an RK4 step
    leaves as it is; the DOP853 tests above check the integration itself)."""
    import valvetrain.dynamics.sweep as module

    monkeypatch.setattr(module, "REST_AMPLITUDE", 0.0)
    law, train = appendix_train()
    speeds = np.array([700.0, 5554.0, 6200.0, 9500.0]) * np.pi / 60
    fields = ("lift", "velocity", "acceleration", "contact_force", "seat_force", "spring_force", "clash_margin",
              "revolutions", "converged", "substeps")
    net = train.network()
    assert module.one_node(net)
    # an element of another kind (the spring made unilateral) is left to the general kernel, which has every kind
    assert not module.one_node(replace(net, unilateral=np.ones_like(net.unilateral)))
    own = module.one_node
    for tolerance in (module.STATE_TOLERANCE, -1.0):
        one = sweep(law, train, speeds, revolutions=2, tolerance=tolerance)
        monkeypatch.setattr(module, "one_node", lambda net: False)
        general = sweep(law, train, speeds, revolutions=2, tolerance=tolerance)
        monkeypatch.setattr(module, "one_node", own)
        assert one.substeps.max() > 1 and one.events.bounce_height[1] > 1e-6
        assert one.events.jumped[-1] and not one.events.jumped[0]
        for name in fields:
            assert np.array_equal(getattr(one, name), getattr(general, name)), (tolerance, name)


def test_a_speed_held_at_rest_keeps_the_integrations_records(monkeypatch):
    """The one-node kernel holds a valve at rest on its seat while the base circle passes (kernels.integrate_node,
    sweep.REST_AMPLITUDE): the appendix train's speeds of the test above, two revolutions each, against the same
    kernel with only an exact rest held (REST_AMPLITUDE 0, the general kernel's records to the bit, test above).
    While held the valve's motion about its rest position is at most REST_AMPLITUDE (kernels._at_rest: the energy
    of the seated oscillator), so the lift differs by at most twice that over the first revolution (the held state
    and the integrated one each within it of the rest position), and the events carried by the second revolution
    (seating velocity, bounce, smallest contact force) by what a 2 pm start moves them; the revolutions are the same.
    And a speed's records do not depend on the speeds it runs with (held by its own state alone): swept alone, each
    speed's records are those of the sweep of four, to the bit."""
    import valvetrain.dynamics.sweep as module

    law, train = appendix_train()
    speeds = np.array([700.0, 5554.0, 6200.0, 9500.0]) * np.pi / 60
    held = sweep(law, train, speeds, revolutions=2, tolerance=-1.0)
    monkeypatch.setattr(module, "REST_AMPLITUDE", 0.0)
    integrated = sweep(law, train, speeds, revolutions=2, tolerance=-1.0)
    monkeypatch.undo()
    assert module.REST_AMPLITUDE == 1e-12
    assert np.abs(held.lift - integrated.lift).max() <= 2 * module.REST_AMPLITUDE
    assert not np.array_equal(held.lift, integrated.lift)     # held somewhere: the records are not the integration's
    assert np.array_equal(held.revolutions, integrated.revolutions)
    a, b = held.events, integrated.events
    assert np.array_equal(a.jumped, b.jumped)
    assert np.allclose(a.seating_velocity, b.seating_velocity, rtol=1e-6)
    assert np.allclose(a.bounce_height, b.bounce_height, rtol=1e-6, atol=1e-12)
    assert np.allclose(a.min_contact_force, b.min_contact_force, rtol=1e-6, atol=1e-6)
    for i, w in enumerate(speeds):
        alone = sweep(law, train, [w], revolutions=2, tolerance=-1.0)
        for name in ("lift", "velocity", "acceleration", "contact_force", "seat_force", "spring_force"):
            assert np.array_equal(getattr(alone, name)[0], getattr(held, name)[i]), (w, name)
