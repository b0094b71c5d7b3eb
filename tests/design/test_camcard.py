"""The cam card stage of a design (valvetrain.design.camcard): its lines and the pair's figures for the two cosine
lobes of tests/cosine_lobe.py against the hand calculation of tests/test_camcard.py, and the card of a shipped
example in results.json."""

import math
from pathlib import Path
from types import SimpleNamespace

import pytest

from valvetrain.design import run
from valvetrain.design.camcard import cam_card_stage
from valvetrain.specification import load_spec

from cosine_lobe import NOSE_EX, NOSE_IN, CosineLobe


def test_the_card_of_two_cosine_lobes_by_hand():
    """Seat to seat: intake -10...230, exhaust -230...10 crank deg (nose +-2 x 60); at 1 mm a duration of
    4 (60/180) arccos(-0.8) = 190.840 crank deg; lift at TDC 5 (1 + cos 165 deg) = 0.170371 mm; lobe separation
    (110 + 110) / 2 = 110 cam deg, overlap 20 crank deg, overlap area 1.13841 mm crank deg (tests/test_camcard.py)."""
    valves = {name: SimpleNamespace(kind=kind, cam=SimpleNamespace(law=CosineLobe(), rocker_ratio=1.0, nose=nose))
              for name, kind, nose in (("in", "intake", NOSE_IN), ("ex", "exhaust", NOSE_EX))}
    card = cam_card_stage(valves)
    deg = math.degrees
    assert (deg(card.valves["in"].opens), deg(card.valves["in"].closes)) == pytest.approx((-10.0, 230.0))
    assert (deg(card.valves["ex"].opens), deg(card.valves["ex"].closes)) == pytest.approx((-230.0, 10.0))
    assert deg(card.valves["in"].duration_1mm) == pytest.approx(190.840, abs=1e-3)
    assert card.valves["in"].lift_at_tdc == pytest.approx(0.170371e-3, abs=1e-9)
    assert deg(card.separation) == pytest.approx(110.0) and deg(card.overlap) == pytest.approx(20.0)
    assert card.overlap_area / 1e-3 / math.radians(1.0) == pytest.approx(1.13841, rel=1e-4)


def test_a_card_without_an_exhaust_valve_has_no_pair_figures():
    valves = {"in": SimpleNamespace(kind="intake", cam=SimpleNamespace(law=CosineLobe(), rocker_ratio=1.0,
                                                                       nose=NOSE_IN))}
    card = cam_card_stage(valves)
    assert list(card.valves) == ["in"] and card.separation is None and card.overlap is None


def test_the_card_of_a_design_is_in_results_json():
    """seed000-polydyne.toml (intake 26 before TDC to 78 after BDC, exhaust 50 before BDC to 20 after TDC: the
    file's own timing): seat-to-seat events as given, overlap 26 + 20 = 46 crank deg."""
    card = run(load_spec(Path(__file__).parents[2] / "examples" / "seed000-polydyne.toml")).to_dict()["cam_card"]
    assert card["valves"]["intake"]["seat_opens_crank_deg"] == pytest.approx(-26.0)
    assert card["valves"]["intake"]["seat_closes_crank_deg"] == pytest.approx(180.0 + 78.0)
    assert card["valves"]["exhaust"]["seat_opens_crank_deg"] == pytest.approx(-180.0 - 50.0)
    assert card["overlap_crank_deg"] == pytest.approx(46.0)
    assert card["overlap_area_mm_crank_deg"] > 0.0
