"""The tappet (valvetrain.links.tappet): its guide's side pressure against a hand calculation of Valve-train practical
works (n.d.), eq. (7.6), only under a sliding face, and the face it offers a flat follower."""

from types import SimpleNamespace

import pytest

from valvetrain.links import Tappet

from link_loads import loads


def parts(**kw):
    return SimpleNamespace(**{"tappet_diameter": 0.030, "tappet_guide_length": 0.040, **kw})


def test_the_side_pressure_of_a_flat_face_by_hand():
    """q = 6 P b / (d l^2) = 6 x 1000 N x 5 mm / (30 mm x (40 mm)^2) = 0.625 MPa (hand calculation)."""
    made, notes = loads(parts(), guide_offset=0.005)
    (c,) = Tappet().checks(made)
    assert c.code == "strength.tappet_side_pressure" and c.value == pytest.approx(0.625e6, rel=1e-12)
    assert c.passed and notes == []


def test_no_side_pressure_under_a_roller_and_a_note_without_the_keys():
    """A roller (no sliding face: guide offset None) loads no guide by its offset; without the guide's length the check
    is named as not checked."""
    assert Tappet().checks(loads(parts(), guide_offset=None)[0]) == []
    made, notes = loads(parts(tappet_guide_length=None), guide_offset=0.005)
    assert Tappet().checks(made) == [] and notes == ["tappet_side_pressure: not checked"]


def test_the_face_of_a_bucket_tappet_is_its_diameter():
    assert Tappet().face_diameter(parts()) == 0.030
