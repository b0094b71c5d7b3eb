"""What the cam synthesis maximises (valvetrain.synthesis.objectives): the objective as ``run`` computes it, in its
display unit, and the breathing objectives refused where the specification cannot give them."""

import pytest

from valvetrain.design import run
from valvetrain.errors import InputError
from valvetrain.specification import example_spec
from valvetrain.synthesis.objectives import check_breathing_objective, objective_value, shown_objective


def test_the_flow_objectives_are_the_flow_stages_figures():
    """The fullness and the time-area are the flow stage's (results.json's ``fullness``, ``time_area_open``); the
    time-area is shown in mm2 s: 1e-6 m2 s is 1 mm2 s."""
    results = run(example_spec())
    flow = results.valves["intake"].flow
    assert objective_value(results, "intake", "fullness") == flow.fullness
    assert objective_value(results, "intake", "time_area") == flow.time_area_open
    assert shown_objective("time_area", 1e-6) == pytest.approx(1.0, rel=1e-15)
    assert shown_objective("fullness", 0.55) == 0.55


def test_a_breathing_objective_needs_the_breathing():
    spec = example_spec()
    assert spec.breathing is None
    with pytest.raises(InputError, match=r"needs a \[breathing\] section"):
        check_breathing_objective(spec, "intake", "volumetric_efficiency")
