"""The records a law adds to the cam's results (laws/records.py): frozen, read by attribute, and projected to
results.json under the keys and units it always had (the keys of tests/data/outputs/seed000-appendix-kurz.json)."""

import dataclasses
import json
from pathlib import Path

import pytest

from valvetrain.laws.records import Duration, LawRecord, PowerPolynomialRecord, SeedFormulas
from valvetrain.results import record
from valvetrain.units import DEG, MM

STORED = Path(__file__).parents[1] / "data" / "outputs" / "seed000-appendix-kurz.json"


def test_a_kurz_record_has_the_keys_and_units_of_the_stored_results():
    """SI inside, mm outside: rho 11.885e-3 m is 11.885 mm; the part a law does not give is left out, not null."""
    formulas = SeedFormulas(3.2748, 3487.8, -1929.7, 11.885 * MM, 46.567 * MM)
    rec = record(LawRecord(seed_formulas=formulas, residuals={"2.10": 0.0}))
    assert rec == {"seed_formulas": {"max_velocity_m_s": 3.2748, "max_acceleration_m_s2": 3487.8,
                                     "min_acceleration_m_s2": -1929.7, "rho_min_mm": 11.885, "rho_max_mm": 46.567},
                   "residuals": {"2.10": 0.0}}
    stored = json.loads(STORED.read_text(encoding="utf-8"))["results.json"]["valves"]["intake"]["cam"]
    assert set(rec["seed_formulas"]) == set(stored["seed_formulas"])
    assert record(LawRecord()) == {}


def test_records_are_frozen():
    formulas = SeedFormulas(1.0, 2.0, -1.0, 0.01, 0.05)
    with pytest.raises(dataclasses.FrozenInstanceError):
        formulas.max_velocity = 2.0
    same = SeedFormulas(1.0, 2.0, -1.0, 0.01, 0.05)
    assert formulas == same and hash(formulas) == hash(same)


def test_angles_in_degrees_and_a_duration_never_reached_is_null():
    """A duration at a height the lobe never reaches stays in results.json as null (the key says the height was
    asked); angles kept in radians are shown in degrees: 60 deg dwell, 12.5 deg phi_2."""
    assert record(Duration(1.0 * MM, None)) == {"height_mm": 1.0, "duration_deg": None}
    assert record(Duration(0.1 * MM, 120.0 * DEG)) == {"height_mm": 0.1, "duration_deg": 120.0}
    rec = record(PowerPolynomialRecord(12.5 * DEG, 60.0 * DEG, 0.3 * MM, 0.4 * MM, 0.55))
    assert rec == {"phi2_deg": 12.5, "dwell_deg": 60.0, "S_e_mm": 0.3, "v_e_mm_per_rad": 0.4, "tappet_fullness": 0.55}
