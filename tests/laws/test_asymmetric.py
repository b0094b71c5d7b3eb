"""Asymmetric cams: opening and closing flanks of their own (issue 5)."""

import numpy as np
import pytest

from valvetrain.design import run
from valvetrain.checks import failed
from valvetrain.laws import AsymmetricLaw, KurzLaw
from valvetrain.specification import parse_spec

from appendix import appendix_text

W = 0.02e-3 * 180 / np.pi


def test_equal_flanks_are_the_symmetric_law():
    k = KurzLaw(6.25e-3, 0.25e-3, W, *np.radians([27, 6, 38]))
    a = AsymmetricLaw(k, k)
    theta = np.linspace(-1.7, 1.7, 1001)
    assert np.array_equal(a.derivatives(theta), k.derivatives(theta))
    assert a.continuity == 2 and a.nose_acceleration_jump == 0.0


def test_different_flanks():
    """Lift and velocity continuous at the nose; the acceleration jumps by 2 (c32_closing - c32_opening) (eq. 2.37)."""
    o = KurzLaw(6.25e-3, 0.25e-3, W, *np.radians([21, 5, 30]))
    c = KurzLaw(6.25e-3, 0.25e-3, 0.75 * W, *np.radians([30, 7, 49]))
    a = AsymmetricLaw(o, c)
    d = a.derivatives(np.array([-1e-12, 1e-12]))
    assert d[0, 0] == pytest.approx(d[0, 1], abs=1e-15) and abs(d[1]).max() < 1e-12
    jump = 2 * (c.coefficients()["c32"] - o.coefficients()["c32"]) * 1e-3
    assert a.nose_acceleration_jump == pytest.approx(jump, rel=1e-9)
    assert a.start == pytest.approx(o.start) and a.end == pytest.approx(c.end)
    assert a.valve_closes == pytest.approx(c.end - c.ramp_angle)
    assert a.continuity == 1
    assert any(f.quantity == "acceleration jump at the nose" for f in failed(a.checks()))
    with pytest.raises(ValueError, match="different lifts"):
        AsymmetricLaw(o, KurzLaw(6.0e-3, 0.25e-3, W, *np.radians([30, 7, 49])))


def _spec(closing, phis=("21.0", "5.0", "30.0")):
    t = appendix_text().replace('follower = "flat"            # "flat" or "roller" (then roller_radius_mm)',
                               f'follower = "flat"\nclosing = {closing}')
    for key, new in zip(("phi1_deg = 27.0", "phi2_deg = 6.0", "phi3_deg = 38.0"), phis, strict=True):
        t = t.replace(key, key.split("=")[0] + "= " + new)
    return t


def test_asymmetric_kurz_in_the_design():
    res = run(parse_spec(_spec("{phi1_deg = 30.0, phi2_deg = 7.0, phi3_deg = 49.0, "
                               "ramp_end_velocity_mm_per_deg = 0.015}")))
    cam = res.to_dict()["valves"]["intake"]["cam"]
    # the main lift starts 26 deg before TDC; the opening flank is 56 cam deg = 112 crank deg long
    assert cam["nose_crank_deg"] == pytest.approx(-26.0 + 112.0)
    assert set(cam["coefficients"]) == {"opening", "closing", "nose_acceleration_jump"}
    assert res.valves["intake"].table.valve_lift.max() * 1e3 == pytest.approx(10.0, abs=1e-6)


def test_asymmetric_angles_must_add_up(refused):
    assert "flanks add up to 133 cam deg" in refused(_spec("{phi1_deg = 30.0, phi2_deg = 7.0, phi3_deg = 40.0}"))
    assert "valves.intake.cam.closing:" in refused(_spec("{phi1_deg = -3.0, phi2_deg = 7.0, phi3_deg = 40.0}"))
