"""The [valves.NAME.hydraulic] section: specification, the hydraulic stage, results.json and the table."""

import csv
import json

import jsonschema
import numpy as np
import pytest

from valvetrain.design import results_schema, run
from valvetrain.export import results_json, write_outputs
from valvetrain.specification import SpecError, example_text, parse_spec

SECTION = """speed_rpm = 1500.0
plunger_diameter_mm = 20.0
pump_volume_cm3 = 5.0
pipe_length_mm = 500.0
pipe_diameter_mm = 6.0
pipe_wall_mm = 1.5
actuator_diameter_mm = 25.0
actuator_volume_cm3 = 5.0
valve_mass_kg = 0.2
spring_rate_N_per_mm = 40.0
spring_preload_N = 250.0
damping_N_s_per_m = 50.0
leakage_cm3_per_s_MPa = 0.1
fill_pressure_MPa = 0.3
"""
"""An assumed small drive on the built-in example's intake cam (every value stated here)."""


def with_section(hydraulic):
    """The built-in example's text with a [valves.intake.hydraulic] section."""
    return example_text().replace("[valves.intake.parts]",
                                  f"[valves.intake.hydraulic]\n{hydraulic}\n[valves.intake.parts]")


def test_no_section_no_hydraulic(tmp_path):
    results = run(parse_spec(example_text()))
    assert all("hydraulic" not in v for v in json.loads(results_json(results))["valves"].values())
    write_outputs(results, tmp_path / "out")
    assert not list((tmp_path / "out").rglob("*hydraulic*"))


def test_the_section_runs_to_results_and_a_table(tmp_path):
    results = run(parse_spec(with_section(SECTION)))
    data = json.loads(results_json(results))
    jsonschema.validate(data, results_schema())
    h = data["valves"]["intake"]["hydraulic"]
    law = results.valves["intake"].cam.law
    assert h["area_ratio"] == pytest.approx(0.64)
    assert h["rigid_lift_mm"] == pytest.approx(0.64 * law.lift(np.array([0.0]))[0] * 1e3, rel=1e-6)
    assert 0 < h["lift_loss_mm"] < 0.2 * h["rigid_lift_mm"]
    assert h["opening_delay_cam_deg"] > 0 and h["closing_delay_cam_deg"] < 0
    assert not h["cavitation"] and h["min_pressure_MPa"] > 0.002
    assert h["speed_rpm"] == pytest.approx(1500.0) and h["max_pressure_MPa"] > 0.3
    assert not [w for w in data["warnings"] if "hydraulic" in w["quantity"]]
    out = write_outputs(results, tmp_path / "out")
    with open(out / h["table"], newline="") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    assert rows[0] == ["cam_deg", "plunger_lift_mm", "pump_pressure_MPa", "actuator_pressure_MPa", "valve_lift_mm",
                       "rigid_lift_mm", "cavitation"]
    table = np.array(rows[1:], dtype=float)
    assert np.ptp(table[:, 0]) > 359.0 and np.allclose(np.diff(table[:, 0]), np.diff(table[:, 0])[0])
    assert table[:, 4].max() == pytest.approx(h["valve_lift_mm"], rel=1e-2)


def test_cavitation_is_a_warning():
    """At the rated 7000 rpm the assumed spring cannot hold the valve to the liquid: the column separates."""
    results = run(parse_spec(with_section(SECTION.replace("speed_rpm = 1500.0\n", ""))))
    data = json.loads(results_json(results))
    h = data["valves"]["intake"]["hydraulic"]
    assert h["speed_rpm"] == pytest.approx(7000.0) and h["cavitation"] and h["min_pressure_MPa"] == pytest.approx(0.002)
    (w,) = [w for w in data["warnings"] if "hydraulic" in w["quantity"]]
    assert w["severity"] == "warning" and "Shang Hanji (1988), ch. 7" in w["source"]


@pytest.mark.parametrize("text, words", [
    (SECTION.replace("plunger_diameter_mm = 20.0", "plunger_diameter_mm = 0.0"),
     ["plunger_diameter_mm", "allowed [1, 1000] mm"]),
    (SECTION + "relief_pressure_MPa = 0.2\n", ["relief_pressure_MPa = 0.2", "initial_pressure_MPa = 0.3"]),
    (SECTION + "vapour_pressure_MPa = 0.5\n", ["vapour_pressure_MPa = 0.5", "below initial_pressure_MPa"]),
    (SECTION.replace("pipe_length_mm = 500.0\n", ""), ["pipe_length_mm"]),
    (SECTION + "pipe_colour = 1.0\n", ["pipe_colour"]),
])
def test_bad_values_are_refused_with_the_key_and_the_range(text, words):
    with pytest.raises(SpecError) as err:
        parse_spec(with_section(text))
    found = "; ".join(err.value.problems)
    assert "hydraulic" in found
    for w in words:
        assert w in found, found


def test_a_grid_too_fine_for_one_revolution_is_refused():
    text = with_section(SECTION.replace("pipe_length_mm = 500.0", "pipe_length_mm = 1.0") + "reaches = 400\n")
    with pytest.raises(SpecError) as err:
        run(parse_spec(text))
    (problem,) = err.value.problems
    assert problem.startswith("valves.intake.hydraulic.reaches = 400: one revolution") and "allowed <=" in problem


@pytest.mark.parametrize("lang, heading", [("en", "9. Hydraulic valve actuation"),
                                           ("ru", "9. Гидравлический привод клапана")])
def test_the_report_has_the_hydraulic_chapter(tmp_path, lang, heading):
    results = run(parse_spec(with_section(SECTION)))
    out = write_outputs(results, tmp_path / "out", lang=lang)
    html = (out / "report.html").read_text(encoding="utf-8")
    assert heading in html and "Shang Hanji (1988), ch. 7" in html and "Wylie and Streeter (1978)" in html
    assert (out / "plots" / "intake_hydraulic.png").is_file() and "tables/intake_hydraulic.csv" in html
