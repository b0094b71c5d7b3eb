"""Indicator diagrams: p-phi and p-V files, line-numbered errors, the Wiebe model."""

import numpy as np
import pytest

from valvetrain.crank import pressure

GEOM = dict(bore=0.080, radius=0.0385, lam=0.285)


def _wiebe(phi):
    return pressure.wiebe_pressure(phi, pressure.WiebeCycle(10.0, 950.0), GEOM["bore"], GEOM["radius"], GEOM["lam"], 4)


def test_p_phi_file_round_trip(tmp_path):
    phi = np.radians(np.arange(0.0, 720.0, 0.5))
    p = _wiebe(phi)
    f = tmp_path / "ind.csv"
    f.write_text("# a comment\ncrank_deg,pressure_MPa\n" + "".join(f"{np.degrees(a):.6f},{b / 1e6:.9f}\n"
                                                                 for a, b in zip(phi, p)))
    t = pressure.read_indicator(f, 4)
    assert t.kind == "angle"
    assert np.allclose(pressure.on_grid(t.x, t.pressure, phi, 4), p, rtol=1e-8)


def test_p_v_file_to_angle(tmp_path):
    """A p-V diagram written from the exact kinematics maps back onto its crank angles (exact method, closed form,
    to round-off), while Brix's construction shifts it (by up to 0.0056 R in the piston position, spec section 4)."""
    phi = np.radians(np.arange(0.0, 720.0, 0.5))
    p = _wiebe(phi)
    v = pressure.cylinder_volume(phi, GEOM["bore"], GEOM["radius"], GEOM["lam"], 10.0)
    ang, pp = pressure.pv_to_angle(v, p, GEOM["bore"], GEOM["radius"], GEOM["lam"], 10.0, 4)
    assert np.abs(ang - phi).max() < 1e-12 and np.array_equal(pp, p)
    work_pv = np.sum(0.5 * (pp[1:] + pp[:-1]) * np.diff(pressure.cylinder_volume(ang, GEOM["bore"], GEOM["radius"],
                                                                                      GEOM["lam"], 10.0)))
    assert work_pv == pytest.approx(pressure.indicated_work(phi, p, v), rel=2e-3)
    ang_b, _ = pressure.pv_to_angle(v, p, GEOM["bore"], GEOM["radius"], GEOM["lam"], 10.0, 4, method="brix")
    assert 0.1 < np.degrees(np.abs(ang_b - ang).max()) < 3.0


BAD = [
    ("crank_deg;pressure_MPa\n0;0.1\n", "ind.csv:1: header"),
    ("crank_deg,pressure_MPa\n0,0.1\n10,abc\n", "ind.csv:3: '10,abc' is not two numbers"),
    ("crank_deg,pressure_MPa\n0,0.1\n10,0.2\n5,0.3\n20,0.1\n", "ind.csv:4: crank_deg = 5 must be larger"),
    ("crank_deg,pressure_MPa\n0,0.1\n800,0.2\n", "ind.csv:3: crank_deg = 800: allowed [0, 720]"),
    ("crank_deg,pressure_MPa\n0,0.1\n10,-0.2\n", "ind.csv:3: pressure_MPa = -0.2"),
    ("crank_deg,pressure_MPa\n0,0.1\n10,0.2,3\n", "ind.csv:3: expected 2 values"),
    ("crank_deg,pressure_MPa\n0,0.1\n", "at least 4 data rows"),
]


@pytest.mark.parametrize("text,message", BAD)
def test_bad_files_name_the_line(tmp_path, text, message):
    f = tmp_path / "ind.csv"
    f.write_text(text)
    with pytest.raises(pressure.PressureFileError, match=message.replace("[", r"\[").replace("]", r"\]")):
        pressure.read_indicator(f, 4)


def test_p_v_needs_one_branch_per_stroke():
    v = np.array([1.0, 2.0, 3.0, 2.0, 1.0]) * 1e-4
    with pytest.raises(pressure.PressureFileError, match="4 monotone branches"):
        pressure.pv_to_angle(v, np.ones(5) * 1e5, GEOM["bore"], GEOM["radius"], GEOM["lam"], 10.0, 4)


def test_wiebe_model_closed_cycle():
    """Without heat release the closed cycle is isentropic: p V^gamma is constant from BDC to BDC."""
    cyc = pressure.WiebeCycle(10.0, 0.0)
    phi = np.radians(np.arange(180.0, 540.0, 1.0))
    p = pressure.wiebe_pressure(phi, cyc, GEOM["bore"], GEOM["radius"], GEOM["lam"], 4)
    v = pressure.cylinder_volume(phi, GEOM["bore"], GEOM["radius"], GEOM["lam"], 10.0)
    pv = p * v**cyc.gamma
    assert np.ptp(pv) / pv.mean() < 1e-6
