"""Issue 24: the cam card against a hand calculation on two cosine lobes.

Each lobe lifts h(theta) = H/2 (1 + cos(pi theta / Phi)) for |theta| <= Phi (camshaft angle from the nose), H = 10 mm,
Phi = 60 cam deg, no ramp, rocker ratio 1; the intake nose at +110 crank deg, the exhaust nose at -110 crank deg
from the gas-exchange TDC.  By hand:

- seat to seat: intake -10...230, exhaust -230...10 crank deg; overlap 20 crank deg; lobe separation
  (110 + 110) / 2 = 110 cam deg;
- at 1 mm: cos(pi theta/Phi) = 2 x 1/10 - 1 = -0.8, theta = (60/180) arccos(-0.8) = 47.7101 cam deg, duration
  4 theta = 190.840 crank deg; at 0.050 in = 1.27 mm: cos = -0.746, theta = 46.0817, duration 184.327 crank deg;
- lift at TDC: theta = -55 cam deg, h = 5 (1 + cos 165 deg) = 0.170371 mm;
- overlap area: by symmetry about TDC twice the area under the intake's lift from -10 to 0 crank deg, where
  h = 5 (1 + cos(pi u / 120)) mm with u = c - 110 crank deg from -120 to -110:
  2 x 5 [10 + (120/pi)(sin(-165 deg) - sin(-180 deg))] = 1.13841 mm crank deg.
"""

import math

import pytest

from valvetrain import camcard

from cosine_lobe import NOSE_EX, NOSE_IN, CosineLobe


def test_events_and_durations_by_hand():
    lobe = CosineLobe()
    o, c = camcard.valve_events(lobe, 1.0, NOSE_IN)
    assert math.degrees(c - o) == pytest.approx(4 * 60 / 180 * math.degrees(math.acos(-0.8)), rel=1e-12)
    assert math.degrees(c - o) == pytest.approx(190.840, abs=1e-3)
    o, c = camcard.tappet_events(lobe, NOSE_IN)
    assert math.degrees(c - o) == pytest.approx(184.327, abs=1e-3)
    assert math.degrees(o) == pytest.approx(110.0 - 184.327 / 2, abs=1e-3)


def test_a_rocker_and_a_ramp_move_the_valve_checking_height_onto_the_tappet():
    """With i_k = 2 and a 0.3 mm ramp, 1 mm at the valve is 0.3 + 0.5 = 0.8 mm at the tappet: cos = 0.16 - 1."""
    lobe = CosineLobe()
    lobe.ramp_height = 0.3e-3
    o, c = camcard.valve_events(lobe, 2.0, NOSE_IN)
    assert math.degrees(c - o) == pytest.approx(4 * 60 / 180 * math.degrees(math.acos(-0.84)), rel=1e-12)


def test_separation_overlap_lift_at_tdc_and_overlap_area_by_hand():
    lobe = CosineLobe()
    assert math.degrees(camcard.lobe_separation(NOSE_IN, NOSE_EX)) == pytest.approx(110.0)
    opens = camcard.crank_events(lobe.valve_opens, NOSE_IN)
    closes = camcard.crank_events(lobe.valve_closes, NOSE_EX)
    assert math.degrees(camcard.overlap(opens, closes)) == pytest.approx(20.0)
    assert float(camcard.lift_at(lobe, 1.0, NOSE_IN, 0.0)) * 1e3 == pytest.approx(0.170371, abs=1e-6)
    area = camcard.overlap_area((lobe, 1.0, NOSE_IN), (lobe, 1.0, NOSE_EX)) / 1e-3 / math.radians(1.0)
    by_hand = 2 * 5 * (10 + 120 / math.pi * (math.sin(math.radians(-165.0)) - math.sin(math.radians(-180.0))))
    assert by_hand == pytest.approx(1.13841, abs=1e-5)
    assert area == pytest.approx(by_hand, rel=1e-4)       # trapezoids on 2001 points: 5e-7 relative here


def test_no_overlap_gives_a_negative_overlap_and_no_area():
    lobe = CosineLobe()
    late = math.radians(140.0)                          # intake opens at +20, after the exhaust closes at +10
    assert math.degrees(camcard.overlap(camcard.crank_events(lobe.valve_opens, late),
                                        camcard.crank_events(lobe.valve_closes, NOSE_EX))) == pytest.approx(-10.0)
    assert camcard.overlap_area((lobe, 1.0, late), (lobe, 1.0, NOSE_EX)) == 0.0
