"""The rocker (valvetrain.links.rocker): its pad's contact stress on the valve tip against a hand calculation of
Valve-train practical works (n.d.), eq. (7.13), under the valve force, and the notes of its shaft's keys not given."""

import math
from types import SimpleNamespace

import pytest

from valvetrain.links import Rocker

from link_loads import loads


def test_the_pad_stress_is_that_of_the_valve_force_by_hand():
    """sigma = 0.418 sqrt(P E / (b r)) = 0.418 sqrt(600 N x 2.1e5 MPa / (10 mm x 20 mm)) = 331.8 MPa (hand
    calculation), under the force at the valve, not the cam's."""
    parts = SimpleNamespace(rocker_pad_width=0.010, rocker_pad_radius=0.020, rocker_shaft_span=None,
                            rocker_shaft_diameter=None, rocker_width=None)
    made, notes = loads(parts, cam_force=1000.0, valve_force=600.0)
    (pad,) = Rocker().checks(made)
    assert pad.value == pytest.approx(0.418 * math.sqrt(600.0 * 2.1e11 / (0.010 * 0.020)), rel=1e-12)
    assert pad.value == pytest.approx(331.8e6, rel=1e-3)
    assert notes == ["rocker_shaft: not checked"]


def test_its_node_is_its_inertia_on_the_valve_arm():
    """J / l_v^2 = 40 kg mm^2 / (40 mm)^2 = 25 g whatever the ratio (Valve-train practical works (n.d.), eq. 5.2; hand
    calculation); it needs its inertia and the valve arm, and is the last link's joint to the valve."""
    masses = SimpleNamespace(rocker_inertia=40e-6)
    assert Rocker().node(masses, 1.6, 0.040) == ("rocker", pytest.approx(0.025))
    assert Rocker().missing(masses, 0.040) == [] and Rocker().joint == "rocker and valve joint"
    assert Rocker().missing(SimpleNamespace(rocker_inertia=0.0), None) == ["rocker_inertia_kg_mm2",
                                                                          "valve_arm_mm (in [drive])"]
