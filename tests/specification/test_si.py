"""The SI view of a specification (specification/si.py): each key without its unit suffix and in SI by the unit's
definition (1 mm = 1e-3 m, 1 deg = pi/180 rad, 1 rpm = 2 pi/60 rad/s, 1 MPa = 1e6 Pa, 1 % = 0.01), frozen, comparing
and hashing by value."""

import dataclasses
import math

import pytest

from valvetrain.specification import example_spec, si


def test_every_unit_of_the_example_becomes_si_by_its_definition():
    spec = example_spec()
    engine, valve = si(spec.engine), si(spec.valves["intake"])
    section = spec.valves["intake"]
    assert engine.bore == pytest.approx(spec.engine.bore_mm / 1000.0, rel=1e-15)
    assert engine.rated_speed == pytest.approx(spec.engine.rated_speed_rpm * 2.0 * math.pi / 60.0, rel=1e-15)
    assert valve.throat_diameter == pytest.approx(section.throat_diameter_mm / 1000.0, rel=1e-15)
    assert valve.opens == pytest.approx(math.radians(section.opens_deg), rel=1e-15)
    assert valve.cam.phi1 == pytest.approx(math.radians(section.cam.phi1_deg), rel=1e-15)
    # mm per camshaft degree to m per radian: x 1e-3 / (pi / 180)
    assert valve.cam.ramp_end_velocity == pytest.approx(
        section.cam.ramp_end_velocity_mm_per_deg * 1e-3 * 180.0 / math.pi, rel=1e-15)
    # kg mm^2 to kg m^2: 25 kg mm^2 = 25e-6 kg m^2; percent to a fraction: 5 % = 0.05
    assert valve.drive.masses.rocker_inertia == pytest.approx(section.drive.masses.rocker_inertia_kg_mm2 * 1e-6,
                                                              rel=1e-15)
    assert valve.spring.min_margin == pytest.approx(section.spring.min_margin_percent / 100.0, rel=1e-15)
    # a pair of lengths stays a pair, in metres
    low, high = section.spring.wire_diameter_range_mm
    assert valve.spring.wire_diameter_range == pytest.approx((low / 1000.0, high / 1000.0), rel=1e-15)


def test_keys_already_in_si_keep_their_name_and_value():
    spec = example_spec()
    section, valve = spec.valves["intake"], si(spec.valves["intake"])
    assert valve.drive.masses.valve_kg == section.drive.masses.valve_kg
    assert valve.spring.min_preload_N == section.spring.min_preload_N
    assert si(spec.engine).cylinders == spec.engine.cylinders and si(spec.engine).strokes == spec.engine.strokes


def test_a_view_is_frozen_and_compares_and_hashes_by_value():
    spec = example_spec()
    a, b = si(spec.engine), si(example_spec().engine)
    assert a == b and hash(a) == hash(b) and a is not b
    assert a.section is spec.engine
    assert isinstance(a.firing_order, tuple) and list(a.firing_order) == spec.engine.firing_order
    with pytest.raises(dataclasses.FrozenInstanceError):
        a.bore = 0.1
    other = si(spec.engine.model_copy(update={"bore_mm": spec.engine.bore_mm + 1.0}))
    assert other != a
