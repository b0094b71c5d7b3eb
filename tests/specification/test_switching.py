"""[valves.NAME.switching] (valvetrain.specification.switching): bad input refused naming the key, its value and the
range."""

from pathlib import Path

import pytest

from valvetrain.specification import SpecError, example_spec, load_spec, spec_document, validate

EXAMPLE = Path(__file__).parents[2] / "examples" / "switching-finger.toml"


def _doc(**switching):
    doc = spec_document(load_spec(EXAMPLE))
    doc["valves"]["intake"]["switching"].update(switching)
    return doc


@pytest.mark.parametrize("keys, words", [
    ({"latch_seat_radius_mm": 1.5}, "latch_seat_radius_mm = 1.5: allowed above the pin's radius"),
    ({"spring_mean_diameter_mm": 4.0}, "spring_mean_diameter_mm = 4: allowed above twice spring_wire_diameter_mm"),
    ({"spring_material": "60S2A"}, "spring_material = '60S2A'"),
    ({"mode": "two_step"}, "mode"),
    ({"inner_arm_mm": 0.5}, "inner_arm_mm"),
    ({"speeds": 2}, "speeds = 2: allowed 4...200"),
    ({"wall_temperature_C": None}, "the deactivated cylinder's breathing needs wall_temperature_C too"),
    ({"oil_passage_diameter_mm": None}, "the latch's switching needs oil_passage_diameter_mm too"),
    ({"oil_pressure_MPa": 0.15}, "oil_pressure_MPa = 0.15: its force on the latch pin, 1.885 N, must exceed the "
                                 "return spring's at the stroke's end"),
])
def test_bad_switching_input_is_refused_naming_the_key(keys, words):
    with pytest.raises(SpecError, match="switching") as err:
        validate(_doc(**keys))
    assert words in str(err.value)


@pytest.mark.parametrize("value", [5e-324, 1e-300, 0.0099])
def test_a_latch_spring_preload_of_almost_nothing_is_refused(value):
    """Fuzz (fuzz11): latch_spring_preload_N, then (0, 1000] N, took the smallest subnormal 5e-324 N and ended in a
    traceback (a division by zero bounding the pin's return time); now at least 0.01 N, the weight of a gram
    (switching.py's docstring), and 0.01 itself is taken."""
    with pytest.raises(SpecError) as err:
        validate(_doc(latch_spring_preload_N=value))
    assert f"valves.intake.switching.latch_spring_preload_N = {value!r}: allowed [0.01, 1000] N" in str(err.value)
    assert validate(_doc(latch_spring_preload_N=0.01)).valves["intake"].switching.latch_spring_preload_N == 0.01


def test_switching_needs_a_finger():
    doc = spec_document(example_spec())
    doc["valves"]["intake"]["switching"] = spec_document(load_spec(EXAMPLE))["valves"]["intake"]["switching"]
    with pytest.raises(SpecError, match=r"valves\.intake\.switching.*cam\.follower = \"finger\"") as err:
        validate(doc)
    assert "not with cam.follower = 'flat'" in str(err.value)


def test_the_deactivated_cylinders_breathing_needs_the_rod():
    doc = _doc()
    doc["engine"]["rod_length_mm"] = None
    with pytest.raises(SpecError, match=r"valves\.intake\.switching\.compression_ratio.*engine\.rod_length_mm"):
        validate(doc)
