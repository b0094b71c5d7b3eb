"""Issue 23, item 3: one unit table (valvetrain.units.UNITS) from which the SI view of a specification, the display
units of the records and the report's unit symbols derive."""

import dataclasses
import math

import numpy as np
import pytest

from valvetrain import design
from valvetrain.design import run
from valvetrain.locale import LANGS
from valvetrain.report.names import label
from valvetrain.specification import example_spec
from valvetrain.specification.si import si
from valvetrain.units import SUFFIXES, UNITS, si_name, symbol, to_display


@pytest.mark.parametrize("key, expected", [
    ("throat_diameter_mm", ("throat_diameter", 1e-3)),                 # 1 mm = 1e-3 m
    ("rated_speed_rpm", ("rated_speed", 2.0 * math.pi / 60.0)),        # 1 rev/min = 2 pi rad / 60 s
    ("ramp_velocity_mm_per_deg", ("ramp_velocity", 1e-3 * 180.0 / math.pi)),   # 1 mm/deg = 1e-3 m / (pi/180 rad)
    ("stiffness_N_per_mm", ("stiffness", 1e3)),                       # 1 N/mm = 1000 N/m
    ("leakage_cm3_per_s_MPa", ("leakage", 1e-6 / 1e6)),               # 1 cm3/(s MPa) = 1e-6 m3 / (s 1e6 Pa)
    ("step_cam_deg", ("step", math.pi / 180.0)),
    ("valve_kg", ("valve_kg", 1.0)),                                  # SI: the key keeps its name
    ("density_kg_m3", ("density_kg_m3", 1.0)),
    ("count", ("count", 1.0)),
])
def test_the_si_name_of_a_key_comes_from_the_unit_table(key, expected):
    name, factor = si_name(key)
    assert name == expected[0] and factor == pytest.approx(expected[1], rel=1e-15)


def test_display_values_by_hand():
    assert to_display(2.0 * math.pi * 7000.0 / 60.0, "rpm") == pytest.approx(7000.0, rel=1e-15)
    assert to_display(0.0118, "mm") == pytest.approx(11.8, rel=1e-15)
    assert to_display(math.pi, "crank deg") == pytest.approx(180.0, rel=1e-15)
    assert to_display(2.5e-5, "us") == pytest.approx(25.0, rel=1e-15)
    with pytest.raises(ValueError, match="unit 'furlong'"):
        to_display(1.0, "furlong")


def test_every_unit_has_a_symbol_in_every_language_and_suffixes_are_unique():
    for unit, (factor, suffixes, *symbols) in UNITS.items():
        assert factor > 0.0 and len(symbols) == len(LANGS) and all(isinstance(s, str) for s in symbols), unit
    lengths = [len(s) for s, _ in SUFFIXES]
    assert len({s for s, _ in SUFFIXES}) == len(SUFFIXES) and lengths == sorted(lengths, reverse=True)
    assert symbol("m/s2", "ru") == "м/с²" and symbol("N/mm", "en") == "N/mm"


def test_the_report_labels_take_their_unit_from_the_table():
    assert label("lift.tappet_acceleration_m_s2", "ru") == "ускорение толкателя a_T, " + symbol("m/s2", "ru")
    assert label("spring.rate_N_per_mm", "en").endswith(", " + symbol("N/mm", "en"))


def test_every_display_unit_of_the_records_is_in_the_table():
    """The records name the unit each field is shown in (``quantity(key, unit, ...)``): every one is in the table,
    and the key's own suffix, where it has one, names the same unit."""
    types = [t for t in vars(design).values() if dataclasses.is_dataclass(t)]
    units = set()
    for t in types:
        for f in dataclasses.fields(t):
            unit = f.metadata.get("unit")
            if unit is not None:
                units.add(unit)
                assert unit in UNITS, (t.__name__, f.name, unit)
    assert {"mm", "m/s2", "rpm", "crank deg"} <= units


def test_the_si_view_of_a_specification_uses_the_table():
    engine = si(example_spec().engine)
    assert engine.rated_speed == pytest.approx(example_spec().engine.rated_speed_rpm * 2.0 * np.pi / 60.0, rel=1e-15)
    assert run(example_spec()).to_dict()["engine"]["mean_piston_speed_m_s"] == pytest.approx(
        example_spec().engine.stroke_mm * 1e-3 * example_spec().engine.rated_speed_rpm / 30.0, rel=1e-14)
