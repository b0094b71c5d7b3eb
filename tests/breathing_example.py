"""The built-in example with a [breathing] section through its designed valves: the designer's breathing panel."""

import tomllib

import tomli_w

from valvetrain.specification import example_text


def breathing_text(curve_points=3) -> str:
    """The built-in example with [breathing] (motored, a curve of ``curve_points`` speeds over 2000-6000 rpm at
    100 kPa, 25 degC in the intake plenum, 102 kPa in the exhaust's, walls at 90 degC: chosen figures of a
    naturally aspirated engine) through its designed valves; the intake's phi3 left out (the remainder of its
    half-angle), so that its closing can be edited."""
    document = tomllib.loads(example_text())
    del document["valves"]["intake"]["cam"]["phi3_deg"]
    document["breathing"] = {"mode": "motored", "compression_ratio": 10.0, "curve": {
        "speed_range_rpm": [2000.0, 6000.0], "points": curve_points, "intake_pressure_kPa": 100.0,
        "intake_temperature_C": 25.0, "exhaust_pressure_kPa": 102.0, "wall_temperature_C": 90.0}}
    return tomli_w.dumps(document)
