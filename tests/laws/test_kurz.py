"""Kurz cam against the appendix of Valve-train practical works (n.d.) (coefficients, Table P1, extremes)."""

import numpy as np
import pytest

from valvetrain.laws.kurz import KurzLaw, kurz_coefficients

from conftest import SEED000_OMEGA_EXACT, SEED000_OMEGA_TABLE

DEG = np.pi / 180

# Printed coefficients of the appendix of Valve-train practical works (n.d.), truncated (not rounded) to the printed
# digits (spec/valvetrain-works-1-8.md, 4.1 and Valve-train practical works (n.d.), corrections note 10).
PRINTED = {"k1": 0.0055, "k2": 0.412, "k3": 1.160, "K1": 0.539, "K2": 1.243, "c11": 5.040, "c12": 0.584,
           "c32": -7.182, "c21": 8.336, "c22": 0.039, "c31": 1.020, "c33": 2.961}

# The exact closed-form values, from the independent reconstruction in
# spec/valvetrain-works-1-8.md, section 4.1 ("computed" column).
RECONSTRUCTED = {"k1": 0.0055556, "k2": 0.412376, "k3": 1.160644, "K1": 0.539474, "K2": 1.243977,
                 "c11": 5.040392, "c12": 0.584172, "c32": -7.182502, "c21": 8.336327, "c22": 0.039903,
                 "c31": 1.020549, "c33": 2.961890}


def _decimals(x):
    return len(repr(x).split(".")[1])


@pytest.mark.parametrize("key", PRINTED)
def test_coefficients_match_printed_digits(kurz_appendix, key):
    value = kurz_appendix.coefficients()[key]
    d = _decimals(PRINTED[key])
    # appendix of Valve-train practical works (n.d.): coefficients printed truncated to d decimals (corrections note 10)
    assert np.trunc(value * 10**d) / 10**d == pytest.approx(PRINTED[key], abs=1e-12)


@pytest.mark.parametrize("key", RECONSTRUCTED)
def test_coefficients_match_reconstruction(kurz_appendix, key):
    # spec/valvetrain-works-1-8.md, 4.1, computed column (6-7 significant digits)
    assert kurz_appendix.coefficients()[key] == pytest.approx(RECONSTRUCTED[key], abs=1e-6)


def test_continuity_residuals_vanish(kurz_appendix):
    # (2.10)-(2.22) with the exact coefficients: residuals <= 2e-15 (spec 4.1; the printed
    # 8.19e-5 comes from rounded coefficients, Valve-train practical works (n.d.), corrections note 11)
    for key, r in kurz_appendix.residuals().items():
        assert abs(r) < 1e-12, key


def test_ramp_length(kurz_appendix):
    # appendix of Valve-train practical works (n.d.): Phi0 = 19.63 deg (19 deg 38 min in Table P1), eq. (2.1) with exact pi
    assert np.rad2deg(kurz_appendix.phi0) == pytest.approx(19.63495, abs=1e-5)
    assert round(np.rad2deg(kurz_appendix.phi0) * 60) == 19 * 60 + 38


def test_extremes_against_appendix(kurz_appendix):
    e = kurz_appendix.extremes(SEED000_OMEGA_EXACT)
    # appendix of Valve-train practical works (n.d.): j_max printed 3487 (truncated; exact 3487.80, spec 4.1)
    assert np.trunc(e.max_acceleration) == 3487
    assert e.max_acceleration == pytest.approx(3487.80, abs=0.01)
    # j_min printed -1930 (spec 4.1: -1929.74 with the exact omega)
    assert round(e.min_acceleration) == -1930
    assert e.min_acceleration == pytest.approx(-1929.74, abs=0.01)
    # max velocity: Table P1 end of Phi1, 3.2746 m/s with omega = 366.5 (spec 4.1: 3.27480 exact omega)
    assert e.max_velocity == pytest.approx(3.27480, abs=1e-5)
    assert kurz_appendix.extremes(SEED000_OMEGA_TABLE).max_velocity == pytest.approx(3.2746, abs=1e-4)


def test_seed_formulas_equal_profile_extremes(kurz_appendix):
    """(2.35)-(2.37) are the exact extremes; found independently on the sampled analytic law."""
    f = kurz_appendix.seed_formulas(20e-3, SEED000_OMEGA_EXACT)
    e = kurz_appendix.extremes(SEED000_OMEGA_EXACT)
    assert e.max_velocity == pytest.approx(f["max_velocity"], rel=1e-9)
    assert e.max_acceleration == pytest.approx(f["max_acceleration"], rel=1e-9)
    assert e.min_acceleration == pytest.approx(f["min_acceleration"], rel=1e-9)


def test_rho_formulas(kurz_appendix):
    f = kurz_appendix.seed_formulas(20e-3, SEED000_OMEGA_EXACT)
    # (2.38): 20 + 6.25 - 14.365 = 11.885 mm; the printed 19.75 is the heel radius (Valve-train practical works (n.d.), corrections note 2)
    assert f["rho_min"] * 1e3 == pytest.approx(11.885, abs=5e-4)
    # (2.39): printed 46.566 mm (spec 4.1: 46.56662)
    assert np.trunc(f["rho_max"] * 1e6) / 1e3 == pytest.approx(46.566, abs=1e-9)


def test_phase_angles_are_the_corrected_formula(kurz_appendix):
    # phi_p0 = (26 + 180 + 78)/4 = 71 deg = Phi1 + Phi2 + Phi3 (Valve-train practical works (n.d.), corrections note 1, eq. 2.2)
    assert np.rad2deg(kurz_appendix.main_half_angle) == pytest.approx(71.0, abs=1e-12)


def test_coefficients_scale_with_length_unit():
    """The coefficients are linear in the lengths: mm in gives mm out (identity of (2.28)-(2.34))."""
    a = kurz_coefficients(6.25, 1.1459, 0.47, 0.10, 0.66)
    b = kurz_coefficients(6.25e-3, 1.1459e-3, 0.47, 0.10, 0.66)
    assert b.c31 * 1e3 == pytest.approx(a.c31, rel=1e-12)
    assert b.K2 == pytest.approx(a.K2, rel=1e-12)


# Table P1 of Valve-train practical works (n.d.) (46 rows): (crank angle printed [deg, min], segment, phi_k [deg, min], direction,
# h = h_T + h0 printed [mm], omega_T printed [m/s], j_T printed [m/s2]).  Transcribed from
# spec/valvetrain-works-1-8.md, section 4.3.
TABLE_P1 = [
    ((654, 44), 0, (0, 0), +1, 0.000, 0.0000, 706), ((664, 44), 0, (5, 0), +1, 0.020, 0.1635, 650),
    ((674, 44), 0, (10, 0), +1, 0.076, 0.3013, 492), ((684, 44), 0, (15, 0), +1, 0.159, 0.3914, 256),
    ((694, 0), 0, (19, 38), +1, 0.250, 0.4200, 0), ((694, 0), 1, (0, 0), +1, 0.250, 0.4200, 0),
    ((700, 0), 1, (3, 0), +1, 0.314, 0.5061, 1193), ((708, 0), 1, (7, 0), +1, 0.441, 0.8678, 2537),
    ((714, 0), 1, (10, 0), +1, 0.593, 1.2820, 3202), ((0, 0), 1, (13, 0), +1, 0.810, 1.7643, 3482),
    ((10, 0), 1, (18, 0), +1, 1.327, 2.5610, 3020), ((20, 0), 1, (23, 0), +1, 1.990, 3.1228, 1595),
    ((28, 0), 1, (27, 0), +1, 2.625, 3.2746, 0), ((28, 0), 2, (0, 0), +1, 2.625, 3.2746, 0),
    ((30, 0), 2, (1, 0), +1, 2.781, 3.2672, -312), ((38, 0), 2, (5, 0), +1, 3.391, 3.1120, -1165),
    ((40, 0), 2, (6, 0), +1, 3.538, 3.0553, -1206), ((40, 0), 3, (0, 0), +1, 3.538, 3.0553, -1206),
    ((50, 0), 3, (5, 0), +1, 4.230, 2.7464, -1384), ((70, 0), 3, (15, 0), +1, 5.369, 2.0166, -1664),
    ((90, 0), 3, (25, 0), +1, 6.133, 1.1777, -1849), ((110, 0), 3, (35, 0), +1, 6.498, 0.2754, -1925),
    ((116, 0), 3, (38, 0), +1, 6.500, 0.0000, -1930), ((116, 0), 3, (38, 0), -1, 6.500, 0.0000, -1930),
    ((122, 0), 3, (35, 0), -1, 6.498, -0.2754, -1925), ((142, 0), 3, (25, 0), -1, 6.133, -1.1777, -1849),
    ((162, 0), 3, (15, 0), -1, 5.369, -2.0166, -1664),
    ((180, 0), 3, (5, 0), -1, 4.230, -2.7464, -1384), ((192, 0), 3, (0, 0), -1, 3.538, -3.0553, -1206),
    ((192, 0), 2, (6, 0), -1, 3.538, -3.0553, -1206), ((194, 0), 2, (5, 0), -1, 3.391, -3.1120, -1165),
    ((202, 0), 2, (1, 0), -1, 2.781, -3.2672, -312), ((204, 0), 2, (0, 0), -1, 2.625, -3.2746, 0),
    ((204, 0), 1, (27, 0), -1, 2.625, -3.2746, 0), ((212, 0), 1, (23, 0), -1, 1.990, -3.1228, 1595),
    ((222, 0), 1, (18, 0), -1, 1.327, -2.5610, 3020), ((232, 0), 1, (13, 0), -1, 0.810, -1.7643, 3482),
    ((238, 0), 1, (10, 0), -1, 0.593, -1.2820, 3202), ((244, 0), 1, (7, 0), -1, 0.441, -0.8678, 2537),
    ((252, 0), 1, (3, 0), -1, 0.314, -0.5061, 1193), ((258, 0), 1, (0, 0), -1, 0.250, -0.4200, 0),
    ((258, 0), 0, (19, 38), -1, 0.250, -0.4200, 0), ((267, 16), 0, (15, 0), -1, 0.159, -0.3914, 256),
    ((277, 16), 0, (10, 0), -1, 0.076, -0.3013, 492), ((287, 16), 0, (5, 0), -1, 0.020, -0.1635, 650),
    ((297, 16), 0, (0, 0), -1, 0.000, 0.0000, 706),
]

# Misprinted cells (spec/valvetrain-works-1-8.md, section 5) and their corrected values
# (section 4.3, "calc" columns with omega = 366.5 for omega_T and j_T).
MISPRINTS = {
    11: {"h": 2.0112, "j": 1565.2}, 34: {"h": 2.0112, "j": 1565.2},       # Valve-train practical works (n.d.), corrections note 3
    20: {"v": 1.17706, "j": -1844.9}, 25: {"v": -1.17706, "j": -1844.9},  # Valve-train practical works (n.d.), corrections note 5
    21: {"h": 6.4803}, 24: {"h": 6.4803},                                 # Valve-train practical works (n.d.), corrections note 4
    27: {"crank": (182, 0)},                                              # Valve-train practical works (n.d.), corrections note 6
}


def _theta(law, segment, phi_k_deg, direction):
    """Camshaft angle from the nose of a Table P1 row (phi_k counted from the start of the segment on the
    opening flank, back from its end on the closing flank: Valve-train practical works (n.d.), corrections note 14)."""
    starts = np.cumsum([0.0, law.phi0, law.phi1, law.phi2])
    theta = -law.half_angle + starts[segment] + np.deg2rad(phi_k_deg)
    return theta if direction > 0 else -theta


@pytest.mark.parametrize("row", range(len(TABLE_P1)))
def test_table_p1_row(kurz_appendix, row):
    crank, seg, (deg, minute), direction, h_printed, v_printed, j_printed = TABLE_P1[row]
    law = kurz_appendix
    theta = _theta(law, seg, deg + minute / 60.0, direction)
    fix = MISPRINTS.get(row, {})
    h = float(law.lift(theta)) * 1e3
    v = float(law.velocity(theta, SEED000_OMEGA_TABLE))
    j = float(law.acceleration(theta, SEED000_OMEGA_TABLE))
    # lift: printed truncated to 3 decimals (spec 4.2: max error 0.00058 mm); corrected cells to 1e-4
    if "h" in fix:
        assert abs(h - h_printed) > 0.01  # the printed cell is wrong (spec section 5)
        assert h == pytest.approx(fix["h"], abs=1e-4)
    else:
        assert h == pytest.approx(h_printed, abs=6e-4)
    # velocity: omega = 366.5 reproduces the printed 4 decimals (spec 4.2: max error 4.8e-5 m/s)
    assert v == pytest.approx(fix.get("v", v_printed), abs=1e-4)
    # acceleration: printed to whole m/s2 (spec 4.2: max error 0.47 m/s2)
    if "j" in fix:
        assert abs(j - j_printed) > 4.0
        assert j == pytest.approx(fix["j"], abs=0.1)
    else:
        assert j == pytest.approx(j_printed, abs=0.5)
    # crank angle: nose at 116 deg after TDC (crank = 2 x cam), 0...720 deg as printed
    crank_calc = (116.0 + 2.0 * np.rad2deg(theta)) % 720.0
    cdeg, cmin = fix.get("crank", crank)
    assert round(crank_calc * 60) % (720 * 60) == (cdeg * 60 + cmin) % (720 * 60)


def test_table_p1_has_every_row():
    # spec/valvetrain-works-1-8.md, 4.3: 46 rows, 0-22 opening flank, 23-45 closing flank
    assert len(TABLE_P1) == 46
    assert [r[3] for r in TABLE_P1].count(+1) == 23


def test_kurz_with_another_ramp_keeps_its_coefficients():
    """(2.28)-(2.34) depend on the ramp's end velocity only (Valve-train practical works (n.d.)): a constant-velocity ramp changes Phi0 only."""
    args = (6.25e-3, 0.25e-3, 0.02e-3 / DEG, *np.radians([27, 6, 38]))
    a, b = KurzLaw(*args), KurzLaw(*args, ramp_kind="constant_velocity")
    assert a.coefficients() == b.coefficients()
    assert b.ramp_angle == pytest.approx(0.25e-3 / (0.02e-3 / DEG))
    j = b.start + b.ramp_angle
    d = b.derivatives(np.array([j - 1e-12, j + 1e-12]))
    assert np.allclose(d[:3, 0], d[:3, 1], atol=1e-9)
