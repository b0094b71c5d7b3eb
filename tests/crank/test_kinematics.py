"""Crank mechanism kinematics (Power units manual (n.d.)): the displacement factor tables, the kinematic identities,
the extremes, the offset mechanism, Brix's construction and the crank angle at a piston travel."""

import numpy as np
import pytest

from valvetrain import twostroke
from valvetrain.crank import kinematics

from factor_tables import table as _table

SERIES = {  # tables 1.1-1.3 of the Power units manual (n.d.) tabulate the 2-term series (spec section 6)
    "1.1": lambda p, lam: (1 - np.cos(p)) + lam / 4 * (1 - np.cos(2 * p)),
    "1.2": lambda p, lam: np.sin(p) + lam / 2 * np.sin(2 * p),
    "1.3": lambda p, lam: np.cos(p) + lam * np.cos(2 * p),
}


@pytest.mark.parametrize("name", sorted(SERIES))
def test_tables_1_1_to_1_3(name):
    """Tables 1.1-1.3 against (1.2), (1.5), (1.8): within one unit of the 4th decimal plus rounding
    (spec section 6), except the typo of Table 1.1 at 90 deg, lambda = 0.27: 1.1355 for 1.1350 (section 8)."""
    phi, lam, val, signed = _table(name)
    formula = SERIES[name](phi, lam)
    printed = signed if name == "1.3" else val
    typo = (name == "1.1") & np.isclose(np.degrees(phi), 90) & np.isclose(lam, 0.27)
    assert np.abs(printed - formula)[~typo].max() <= 1.5e-4
    if typo.any():
        assert formula[typo][0] == pytest.approx(1.1350, abs=1e-12)
        assert abs(printed[typo][0] - formula[typo][0]) > 4e-4
    # and the exact kinematics are NOT what the tables hold: Table 1.1 differs by up to 0.0039 (section 6)
    if name == "1.1":
        exact = kinematics.displacement(phi, 1.0, lam)
        assert 0.003 < np.abs(exact - formula).max() < 0.004


@pytest.mark.parametrize("exact", [True, False])
@pytest.mark.parametrize("k", [0.0, 0.1])
def test_velocity_and_acceleration_are_derivatives(exact, k):
    """v = ds/dt and j = dv/dt (central differences), for both forms and both mechanisms."""
    phi = np.linspace(0.05, 2 * np.pi - 0.05, 97)
    h, R, lam, w = 1e-6, 0.04, 0.285, 300.0
    s = lambda p: kinematics.displacement(p, R, lam, k, exact)  # noqa: E731
    v = lambda p: kinematics.velocity(p, R, lam, w, k, exact)  # noqa: E731
    assert np.allclose((s(phi + h) - s(phi - h)) / (2 * h) * w, v(phi), rtol=1e-7, atol=1e-7)
    a = kinematics.acceleration(phi, R, lam, w, k, exact)
    assert np.allclose((v(phi + h) - v(phi - h)) / (2 * h) * w, a, rtol=1e-6, atol=1e-4)


def test_series_against_exact_lambda_0_285():
    """Spec section 7 (lambda = 0.285): max errors of the series 0.00302 R (s), 0.00394 omega R (v), 0.01233 omega^2 R (j)."""
    phi = np.radians(np.arange(0, 360, 0.01))
    lam = 0.285
    ds = np.abs(kinematics.displacement(phi, 1, lam) - kinematics.displacement(phi, 1, lam, exact=False)).max()
    dv = np.abs(kinematics.velocity(phi, 1, lam, 1) - kinematics.velocity(phi, 1, lam, 1, exact=False)).max()
    dj = np.abs(kinematics.acceleration(phi, 1, lam, 1) - kinematics.acceleration(phi, 1, lam, 1, exact=False)).max()
    assert (ds, dv, dj) == pytest.approx((0.00302, 0.00394, 0.01233), abs=1e-5)
    assert ds < lam**2 / 4 * 1.0  # O(lambda^2)


def test_extremes_lambda_0_285():
    """Spec section 7: exact v_max 1.04004 at 75.17 deg, j_min -0.71830 at 155.23 deg; (1.7) 1.03982,
    (1.11) -0.72360 at 151.31 deg; j_max = 1 + lambda."""
    e = kinematics.extremes(1.0, 0.285, 1.0)
    assert e["v_max"] == pytest.approx(1.04004, abs=1e-5)
    assert np.degrees(e["v_max_angle"]) == pytest.approx(75.17, abs=0.01)
    assert e["j_min"] == pytest.approx(-0.71830, abs=1e-5)
    assert np.degrees(e["j_min_angle"]) in (pytest.approx(155.23, abs=0.01), pytest.approx(204.77, abs=0.01))
    assert e["j_max"] == pytest.approx(1.285, abs=1e-12)
    book = kinematics.textbook_extremes(1.0, 0.285, 1.0)
    assert book["v_max"] == pytest.approx(1.03982, abs=1e-5)
    assert book["j_min"] == pytest.approx(-0.72360, abs=1e-5)
    assert np.degrees(book["j_min_angle"]) == pytest.approx(151.31, abs=0.01)
    assert kinematics.textbook_extremes(1.0, 0.24, 1.0)["j_min"] == pytest.approx(-0.76)  # lambda <= 1/4: 1 - lambda


def test_extremes_kept_for_equal_arguments_are_a_callers_own():
    """The extremes found once for a set of arguments (a tolerance study's samples): a caller changing its dict
    changes no later answer, and numpy scalars find the same values as floats.  Spec section 7's exact j_max of
    lambda = 0.285 is 1 + lambda."""
    first = kinematics.extremes(1.0, 0.285, 1.0)
    first["j_max"] = 0.0
    again = kinematics.extremes(np.float64(1.0), np.float64(0.285), np.float64(1.0))
    assert again["j_max"] == pytest.approx(1.285, abs=1e-12)
    assert again is not first


def test_offset_mechanism():
    """Spec section 7, k = 0.1, lambda = 0.285: stroke 2R x 1.00044, TDC at 1.27 deg, BDC at 182.28 deg,
    s(phi = 0) from true TDC 0.00032 R."""
    lam, k = 0.285, 0.1
    tdc, bdc = kinematics.dead_centres(lam, k)
    assert np.degrees(tdc) == pytest.approx(1.27, abs=0.005)
    assert np.degrees(bdc) == pytest.approx(182.28, abs=0.005)
    stroke = kinematics.displacement(bdc, 1.0, lam, k) - kinematics.displacement(tdc, 1.0, lam, k)
    assert stroke / 2 == pytest.approx(1.00044, abs=1e-5)
    assert kinematics.displacement(0.0, 1.0, lam, k) == pytest.approx(0.00032, abs=1e-5)
    assert kinematics.displacement(tdc, 1.0, lam, k) == pytest.approx(0.0, abs=1e-12)


def test_brix_construction():
    """Spec section 4: Brix differs from (1.2) by up to 0.0039 R and from the exact law by up to 0.0056 R at 0.285."""
    phi = np.radians(np.arange(0, 360, 0.05))
    b = kinematics.brix_displacement(phi, 1.0, 0.285)
    assert np.abs(b - kinematics.displacement(phi, 1.0, 0.285, exact=False)).max() == pytest.approx(0.0039, abs=1e-4)
    assert np.abs(b - kinematics.displacement(phi, 1.0, 0.285)).max() == pytest.approx(0.0056, abs=1e-4)


@pytest.mark.parametrize("k", [0.0, 0.1, -0.2])
@pytest.mark.parametrize("lam", [0.24, 0.31])
def test_crank_angle_at_inverts_displacement(lam, k):
    """Round trip s(phi(s)) = s to 1e-12 of the stroke over the whole stroke, on the way down (from TDC to BDC,
    spec section 3) and back; and phi(s(phi)) = phi away from the dead centres, where ds/dphi vanishes."""
    R = 0.04
    tdc, bdc = kinematics.dead_centres(lam, k)
    full = kinematics.piston_stroke(R, lam, k)
    assert full == pytest.approx(kinematics.displacement(bdc, R, lam, k), rel=1e-14)
    s = np.linspace(0.0, full, 2001)
    down, up = (kinematics.crank_angle_at(s, R, lam, k, upstroke=b) for b in (False, True))
    for phi in (down, up):
        assert np.abs(kinematics.displacement(phi, R, lam, k) - s).max() < 1e-12 * full
    assert (down[0], down[-1], up[0], up[-1]) == pytest.approx((tdc, bdc, 2 * np.pi + tdc, bdc), abs=1e-7)
    assert np.all(np.diff(down) > 0) and np.all(np.diff(up) < 0)
    phi = np.linspace(tdc, 2 * np.pi + tdc, 721)[1:-1]
    phi = phi[np.abs(phi - bdc) > 0.01]
    back = kinematics.crank_angle_at(kinematics.displacement(phi, R, lam, k), R, lam, k, upstroke=False)
    back[phi > bdc] = kinematics.crank_angle_at(kinematics.displacement(phi[phi > bdc], R, lam, k), R, lam, k,
                                                upstroke=True)
    assert np.abs(back - phi).max() < 1e-9


@pytest.mark.parametrize("lam", [0.24, 0.31])
def test_crank_angle_at_series_and_brix(lam):
    """The series (1.2) and Brix's construction (2.1) invert in closed form too: round trip to 1e-12 of the stroke
    on both halves of the revolution; the series inverse is (8.1) of Valve-train practical works (n.d.), work 8 (phi from BDC,
    s = S (1 - sigma))."""
    R = 0.04
    s = np.linspace(0.0, 2 * R, 2001)
    for up in (False, True):
        series = kinematics.crank_angle_at(s, R, lam, exact=False, upstroke=up)
        brix = kinematics.brix_crank_angle(s, R, lam, up)
        assert np.abs(kinematics.displacement(series, R, lam, exact=False) - s).max() < 1e-12 * 2 * R
        assert np.abs(kinematics.brix_displacement(brix, R, lam) - s).max() < 1e-12 * 2 * R
        lo, hi = (np.pi, 2 * np.pi) if up else (0.0, np.pi)
        assert np.all((series >= lo) & (series <= hi)) and np.all((brix >= lo) & (brix <= hi))
    sigma = np.array([0.18, 0.27, 0.32])
    assert np.allclose(np.pi - kinematics.crank_angle_at(2 * R * (1 - sigma), R, lam, exact=False),
                       twostroke.port_angle_series(sigma, lam), rtol=0, atol=1e-13)


def test_crank_angle_at_refuses_travel_outside_the_stroke():
    with pytest.raises(ValueError, match="allowed 0 ... 0.08"):
        kinematics.crank_angle_at([0.0, 0.0800001], 0.04, 0.25)
    with pytest.raises(ValueError, match="use the exact kinematics"):
        kinematics.crank_angle_at(0.01, 0.04, 0.25, 0.1, exact=False)
    with pytest.raises(ValueError, match="allowed 0 ... 0.08"):
        kinematics.brix_crank_angle(-1e-9, 0.04, 0.25)
