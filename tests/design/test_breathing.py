"""The breathing stage (valvetrain.design.breathing) on the shipped TCC-III example and on the built-in example's
designed valves: the records results.json promises, the valves' effective areas from the measured lift and C_D table
(by hand), the bad inputs refused naming their keys."""

from pathlib import Path
import shutil

import numpy as np
import pytest

from valvetrain.design import run
from valvetrain.specification import SpecError, example_spec, load_spec, spec_document, validate
from valvetrain.tables import breathing_columns

EXAMPLE = Path(__file__).parents[2] / "examples" / "tcc3-motored.toml"
KEYS = ("speed_rpm", "intake_pressure_kPa", "air_mass_flow_g_s", "volumetric_efficiency", "peak_pressure_kPa",
        "peak_pressure_crank_deg", "imep_kPa", "imep_gross_kPa", "residual_gas_fraction")
"""The keys of a condition's record the issue asks for (issue 37)."""


@pytest.fixture(scope="module")
def tcc3():
    return run(load_spec(EXAMPLE))


def test_tcc3_records(tcc3):
    """Every condition's record has the keys; the air flow is the volumetric efficiency times the plenum's density,
    the swept volume and the cycles per second (the definition, by hand); a motored engine's pressure peaks just
    before the firing TDC (heat lost to the walls); the energy balance closes."""
    records = tcc3.to_dict()["breathing"]["conditions"]
    assert [r["speed_rpm"] for r in records] == [800.0, 1300.0, 1300.0]
    for r in records:
        assert set(KEYS) <= set(r)
        rho = r["intake_pressure_kPa"] * 1e3 / (287.0575 * r["intake_temperature_K"])
        swept = np.pi * 0.092**2 / 4 * 0.086
        assert r["air_mass_flow_g_s"] == pytest.approx(
            r["volumetric_efficiency"] * rho * swept * r["speed_rpm"] / 120.0 * 1e3, rel=1e-4)
        assert 355.0 < r["peak_pressure_crank_deg"] < 360.0
        assert abs(r["energy_balance"]) < 1e-12 and r["imep_kPa"] < 0.0
    assert records[2]["pmep_kPa"] > 50.0 > records[1]["pmep_kPa"]      # throttled to 40 kPa: the pumping loop grows


def test_measured_lift_and_cd_make_the_effective_area(tcc3):
    """At the intake's peak lift 8.89 mm (L/D = 0.35, 114.8 crank deg of the lift file) the area is C_D(0.35)
    pi 25.4^2 / 4 with C_D interpolated in the table: 0.8029 + (0.35 - 0.315) / 0.0393 (0.8212 - 0.8029)."""
    flow = tcc3.breathing.engine.intake
    cd = 0.8029 + (8.89 / 25.4 - 0.315) / (0.3543 - 0.315) * (0.8212 - 0.8029)
    peak = float(np.max(flow.forward))
    assert peak == pytest.approx(cd * np.pi * 0.0254**2 / 4, rel=2e-3)
    assert np.degrees(flow.angle[np.argmax(flow.forward)]) == pytest.approx(114.8, abs=1.5)


def test_table_of_a_condition(tcc3):
    """tables/breathing_condition_N.csv: every crank degree, its pressure peak the record's (within the degree)."""
    columns = breathing_columns(tcc3.breathing.conditions[0])
    assert columns["crank_deg"].size == 721
    record = tcc3.breathing.conditions[0].figures
    assert np.max(columns["pressure_kPa"]) == pytest.approx(record.peak_pressure / 1e3, rel=2e-3)


def test_designed_valves_fired():
    """The built-in example's designed valves (default C_D on the flow section), fired on [crank.cycle]'s Wiebe
    schedule with iso-octane: torque and power at each speed of the curve, the lift from the designed laws."""
    doc = spec_document(example_spec())
    doc["breathing"] = {"mode": "fired", "wall_temperature_C": 150.0,
                        "intake": {"runner_length_mm": 350.0, "runner_diameter_mm": 38.0},
                        "curve": {"speed_range_rpm": [2000.0, 6000.0], "points": 2, "intake_pressure_kPa": 100.0,
                                  "intake_temperature_C": 25.0, "exhaust_pressure_kPa": 105.0}}
    b = run(validate(doc)).breathing
    assert b.figures.intake_lift.startswith("designed: intake (kurz")
    assert "C_D = 0.7" in b.figures.intake_discharge
    for r in b.curve:
        assert r.figures.torque > 0 and r.figures.power == pytest.approx(r.figures.torque * r.figures.speed)
        assert 0.5 < r.figures.volumetric_efficiency < 1.2


def _tcc3_document(**change):
    doc = spec_document(load_spec(EXAMPLE))
    for path, value in change.items():
        *head, key = path.split("__")
        table = doc
        for part in head:
            table = table[int(part)] if part.isdigit() else table[part]
        table[key] = value
    return doc


@pytest.mark.parametrize("change, message", [
    ({"breathing__conditions__0__intake_pressure_kPa": 0.0},
     r"breathing.conditions.0.intake_pressure_kPa = 0.0: allowed \[1, 10000\] kPa"),
    ({"breathing__intake__runner_length_mm": 0.0}, r"breathing.intake.runner_length_mm = 0.0: allowed \(0, 20000\] mm"),
    ({"breathing__exhaust__cd_diameter_mm": None}, r"breathing.exhaust: cd_file needs cd_diameter_mm"),
    ({"breathing__mode": "fired"}, r"breathing.mode = 'fired': 'fired' burns on the Wiebe schedule of \[crank.cycle\]"),
])
def test_bad_input_is_refused_naming_the_key(change, message):
    with pytest.raises(SpecError, match=message):
        validate(_tcc3_document(**change))


def test_a_cd_table_that_is_not_a_function_of_l_over_d(tmp_path):
    """A C_D table with two rows at one L/D is refused, naming the key and the file's row."""
    shutil.copytree(EXAMPLE.parent / "data", tmp_path / "data")
    table = tmp_path / "data" / "tcc3-valve-cd.csv"
    table.write_text(table.read_text(encoding="utf-8").replace("0.1575,", "0.1181,"), encoding="utf-8")
    (tmp_path / EXAMPLE.name).write_text(EXAMPLE.read_text(encoding="utf-8"), encoding="utf-8")
    with pytest.raises(SpecError, match=r"breathing.intake.cd_file: .*row 5: L/D = 0.1181 after 0.1181: C_D must be "
                                        r"a function of L/D"):
        run(load_spec(tmp_path / EXAMPLE.name))


def test_the_crank_reads_the_breathing_pressure():
    """With [breathing] the crank chapter's cylinder pressure is the breathing's converged cycle at the speed nearest
    the crank's (the rated 7000 rpm: the curve's last point), on the crank's grid: the same peak within the grid's
    step, the Wiebe model of [crank.cycle] only the heat release's schedule."""
    doc = spec_document(example_spec())
    doc["breathing"] = {"mode": "fired", "wall_temperature_C": 150.0,
                        "curve": {"speed_range_rpm": [5000.0, 7000.0], "points": 2, "intake_pressure_kPa": 100.0,
                                  "intake_temperature_C": 25.0, "exhaust_pressure_kPa": 105.0}}
    results = run(validate(doc))
    crank, last = results.crank, results.breathing.curve[-1]
    assert crank.pressure_source.startswith("the breathing's converged fired cycle at 7000 rpm")
    assert crank.figures.max_gas_pressure == pytest.approx(last.figures.peak_pressure, rel=5e-3)
    assert crank.figures.work.imep == pytest.approx(last.figures.imep, rel=1e-2)


def test_a_breathing_that_would_run_for_minutes_is_refused():
    """1200 conditions of the TCC-III example ask for about 3e9 cell-steps: refused before they run, naming what to
    change (the fuzzer's long list of conditions ran for minutes)."""
    doc = spec_document(load_spec(EXAMPLE))
    doc["breathing"]["conditions"] = doc["breathing"]["conditions"] * 400
    with pytest.raises(SpecError, match=r"breathing: 1200 conditions and 0 curve speeds .* allowed at most 1e\+08"):
        run(validate(doc))


def test_what_the_boundary_fuzzer_found():
    """tools/fuzz_bounds.py on the TCC-III example: cycles that do not repeat within max_cycles are a warning check
    naming the speed (it raised a NameError); an exhaust plenum at 10 MPa, which blows the gas back through the intake
    runner until its cells lose their pressure, is refused (it wrote NaN); a compression ratio of 1.001, whose cylinder
    never pushes gas out, has no exhaust temperature (it was NaN)."""
    doc = spec_document(load_spec(EXAMPLE))
    doc["breathing"]["max_cycles"] = 2
    doc["breathing"]["cycle_tolerance"] = 1e-6
    checks = [c for c in run(validate(doc)).checks if c.code == "breathing.cycle_change"]
    assert len(checks) == 3 and not any(c.passed for c in checks)
    assert checks[0].quantity == "breathing: relative change of the last cycle at 800 rpm"
    doc = _tcc3_document(breathing__conditions__2__exhaust_pressure_kPa=10000.0)
    with pytest.raises(SpecError, match=r"breathing: the cycle left the physical range at 1300 rpm"):
        run(validate(doc))
    records = run(validate(_tcc3_document(breathing__compression_ratio=1.001))).to_dict()["breathing"]["conditions"]
    assert all("exhaust_temperature_K" not in r and np.isfinite(r["air_mass_flow_g_s"]) for r in records)
