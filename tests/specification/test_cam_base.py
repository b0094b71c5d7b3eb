"""The parts every cam section shares (specification/cam_base.py): the main event's half angle and the nose's crank
angle from the valve's timing."""

import math
from types import SimpleNamespace

import pytest

from valvetrain.specification.cam_base import main_half_angle, main_half_angle_deg, symmetric_nose


def test_the_half_angle_and_the_nose_by_hand():
    """phi_p0 = (opens + 180 + closes) / 2 crank deg, on the camshaft half that for a four-stroke (work 2, corrected
    formula, corrections note 1): (26 + 180 + 78) / 2 / 2 = 71 cam deg; a two-stroke's camshaft turns with the crank:
    142 deg.  The intake nose lies midway between opening (-26) and closing (180 + 78): 116 crank deg after TDC; an
    exhaust opening 40 deg before BDC and closing 10 deg after TDC: midway between -220 and 10, -105 deg."""
    valve = SimpleNamespace(opens_deg=26.0, closes_deg=78.0, opens=math.radians(26.0), closes=math.radians(78.0),
                            kind="intake")
    assert main_half_angle_deg(valve, 4) == pytest.approx(71.0)
    assert main_half_angle_deg(valve, 2) == pytest.approx(142.0)
    assert math.degrees(main_half_angle(valve, 4)) == pytest.approx(71.0, rel=1e-12)
    assert math.degrees(symmetric_nose(valve)) == pytest.approx(116.0, rel=1e-12)
    exhaust = SimpleNamespace(opens=math.radians(40.0), closes=math.radians(10.0), kind="exhaust")
    assert math.degrees(symmetric_nose(exhaust)) == pytest.approx(-105.0, rel=1e-12)
