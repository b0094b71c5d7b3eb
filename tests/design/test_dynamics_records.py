"""The records of the dynamics stage (valvetrain.design.dynamics_records): the per-speed records made over the speeds
at once against each speed's own."""

from dataclasses import replace

import numpy as np
import pytest

from valvetrain.design import run
from valvetrain.design.dynamics_records import speed_record
from valvetrain.specification import parse_spec

from appendix import appendix_text


def with_dynamics(dynamics):
    """The built-in example with a [valves.intake.dynamics] section of the text ``dynamics``."""
    return parse_spec(appendix_text().replace("[valves.intake.parts]",
                                              f"[valves.intake.dynamics]\n{dynamics}\n[valves.intake.parts]"))


@pytest.mark.parametrize("dynamics", ["speeds = 12\nrevolutions = 2\nstep_cam_deg = 0.5\n",
                                      "model = \"multi\"\ncoils_per_spring = 4\nspeeds = 6\nrevolutions = 2\n"
                                      "step_cam_deg = 0.5\n"])
def test_the_per_speed_records_at_once_are_each_speeds_own(dynamics):
    """The stage's per-speed records, made over the speeds at once (speed_records, SweepResult.events), are those
    speed_record makes of each speed's own SpeedResult (SweepResult.speed): every field, one-mass and multi-mass (coil
    surge and clash margin), bit for bit (nan where a speed has no separation, no seating or no monitored clash); but
    the events of the speeds that decide the headlines, which are those of their refined step (the refinement's)."""
    d = run(with_dynamics(dynamics)).valves["intake"].dynamics
    r = d.records
    each = [speed_record(d.sweep.speed(i), s, e) for i, (s, e) in enumerate(zip(r.speed, r.epsilon, strict=True))]
    fine, events = d.refinement.halvings > 0, d.refinement.events
    assert fine.any() and not fine.all()
    each = [x if not f else replace(x, min_contact_force=events.min_contact_force[i],
                                    seating_velocity=events.seating_velocity[i], bounce=events.bounce_height[i],
                                    bounce_count=events.bounce_count[i], jump_intervals=(
                                        ((events.jump_from[i], events.jump_to[i]),) if events.jumped[i] else ()))
            for i, (x, f) in enumerate(zip(each, fine, strict=True))]
    for name in ("min_contact_force", "max_contact_force", "seating_velocity", "bounce", "bounce_count",
                 "max_lift_error", "revolutions"):
        np.testing.assert_array_equal(getattr(r, name), [getattr(x, name) for x in each], err_msg=name)
    np.testing.assert_array_equal(r.jump, [bool(x.jump_intervals) for x in each])
    np.testing.assert_array_equal(r.jump_from, [x.jump_intervals[0][0] if x.jump_intervals else np.nan for x in each])
    np.testing.assert_array_equal(r.jump_to, [x.jump_intervals[-1][1] if x.jump_intervals else np.nan for x in each])
    surge = [np.nan if x.max_surge is None else x.max_surge for x in each]
    np.testing.assert_array_equal(np.full(len(each), np.nan) if r.max_surge is None else r.max_surge, surge)
    np.testing.assert_array_equal(r.clash_margin, [np.nan if x.clash_margin is None else x.clash_margin for x in each])
