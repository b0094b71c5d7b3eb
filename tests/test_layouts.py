"""Drive layouts (layouts.py): the layout a valve's keys name or imply, its chain of parts, the valve arm, and the
train's mass reduced to the valve (Valve-train practical works (n.d.), work 5, eq. (5.2))."""

import math

import numpy as np
import pytest

from valvetrain import layouts
from valvetrain.laws.kurz import KurzLaw
from valvetrain.specification import example_spec, si


def _intake(**drive):
    """The built-in example's intake valve (SI view) with its [drive] keys replaced."""
    valve = example_spec().valves["intake"]
    valve = valve.model_copy(update={"drive": valve.drive.model_copy(update=drive)})
    return si(valve)


def test_a_layout_not_given_follows_the_rocker_ratio():
    """As given; else direct for a rocker ratio of 1 (the tappet on the valve) and pushrod otherwise."""
    assert layouts.layout(_intake()) == "pushrod"                      # given in the example
    assert layouts.layout(_intake(layout=None)) == "pushrod"           # rocker_ratio 1.6
    valve = example_spec().valves["intake"]
    drive = valve.drive.model_copy(update={"layout": None})
    direct = si(valve.model_copy(update={"rocker_ratio": 1.0, "drive": drive}))
    assert layouts.layout(direct) == "direct"


def test_each_layout_s_chain_of_parts_from_the_cam():
    assert layouts.LAYOUTS["direct"].parts == ("tappet",)
    assert layouts.LAYOUTS["rocker"].parts == ("rocker",)
    pushrod = layouts.chain(_intake())
    assert pushrod.parts == ("tappet", "pushrod", "rocker", "rocker_pivot")
    assert pushrod.valve_joint == "rocker and valve joint"
    # the pivot ball of a stud rocker does not move: no mass of its own in the train
    assert pushrod.train_masses == ("tappet_kg", "pushrod_kg", "rocker_inertia_kg_mm2")
    rocker = layouts.LAYOUTS["rocker"]
    assert rocker.train_masses == ("rocker_inertia_kg_mm2",)
    assert layouts.LAYOUTS["direct"].valve_joint == "valve stem and tappet"
    # the rocker is the one lever: the layouts with it set a rocker ratio, the direct drive has i_k = 1
    assert [name for name, chain in layouts.LAYOUTS.items() if any(link.lever for link in chain.links)] == [
        "rocker", "pushrod"]


def test_the_example_s_train_mass_by_hand():
    """The built-in example's intake (pushrod drive, i_k = 1.6, valve arm 40 mm) with a 60 g spring, eq. (5.2) by
    hand: m_v = 55 + 15 + 4 + 60/3 + 25 kg mm^2 / (40 mm)^2 + (35 + 30) / 1.6^2
    = 94 + 15.625 + 25.390625 = 135.015625 g."""
    valve = _intake()
    assert layouts.valve_arm(valve) == pytest.approx(0.040)
    mass, how = layouts.train_mass(valve, 0.060)
    assert mass == pytest.approx(0.135015625, rel=1e-12)
    assert how.startswith("part masses") and "spring mass of the design" in how


def test_without_part_masses_the_specific_mass_of_the_layout():
    """No [drive.masses]: m_v = m' f_g with the layout's default m' (135 kg/m^2 for a pushrod drive) or the one given;
    throat 38 mm: f_g = pi 0.038^2 / 4 = 1.1341e-3 m^2, so 0.15311 kg and, with 450 kg/m^2, 0.51035 kg."""
    area = math.pi * 0.038**2 / 4
    mass, how = layouts.train_mass(_intake(masses=None), 0.060)
    assert mass == pytest.approx(135.0 * area, rel=1e-12) and mass == pytest.approx(0.15311, abs=5e-6)
    assert "default for a pushrod drive" in how
    given, how = layouts.train_mass(_intake(masses=None, specific_mass_kg_m2=450.0), 0.060)
    assert given == pytest.approx(0.51035, abs=5e-6) and "(given)" in how


def test_no_finger_no_inertia_of_a_variable_ratio():
    """finger_inertia is zero for a follower whose ratio does not vary with the lift (the example's flat tappet),
    whatever the law: the Kurz cam of the appendix of Valve-train practical works (n.d.)."""
    law = KurzLaw(6.25e-3, 0.25e-3, 0.02e-3 / math.radians(1.0), *np.radians([27.0, 6.0, 38.0]))
    theta = np.linspace(law.start, law.end, 41)
    assert np.any(law.derivatives(theta)[2] != 0.0)
    assert np.all(layouts.finger_inertia(_intake(), law, theta) == 0.0)
