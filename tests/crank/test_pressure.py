"""Indicator diagrams: p-phi and p-V files, line-numbered errors, the Wiebe model."""

import re

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from valvetrain.crank import kinematics, pressure
from valvetrain.files import read_indicator

GEOM = dict(bore=0.080, radius=0.0385, lam=0.285)


def _wiebe(phi):
    return pressure.wiebe_pressure(phi, pressure.WiebeCycle(10.0, 950.0), GEOM["bore"], GEOM["radius"], GEOM["lam"], 4)


def test_p_phi_file_round_trip(tmp_path):
    phi = np.radians(np.arange(0.0, 720.0, 0.5))
    p = _wiebe(phi)
    f = tmp_path / "ind.csv"
    f.write_text("# a comment\ncrank_deg,pressure_MPa\n" + "".join(f"{np.degrees(a):.6f},{b / 1e6:.9f}\n"
                                                                 for a, b in zip(phi, p)))
    t = read_indicator(f, 4)
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
        read_indicator(f, 4)


def test_p_v_needs_one_branch_per_stroke():
    v = np.array([1.0, 2.0, 3.0, 2.0, 1.0]) * 1e-4
    with pytest.raises(pressure.PressureFileError, match="4 monotone branches"):
        pressure.pv_to_angle(v, np.ones(5) * 1e5, GEOM["bore"], GEOM["radius"], GEOM["lam"], 10.0, 4)


def test_wiebe_model_closed_cycle():
    """Without heat release the closed cycle is isentropic: p V^gamma = p0 V0^gamma from BDC to BDC (analytic
    identity, to round-off), for both cycles and an offset mechanism."""
    cyc = pressure.WiebeCycle(10.0, 0.0)
    for strokes, k in ((4, 0.0), (2, 0.15)):
        phi = np.radians(np.arange(180.0, 540.0, 1.0)) - np.pi * (4 - strokes)
        p = pressure.wiebe_pressure(phi, cyc, GEOM["bore"], GEOM["radius"], GEOM["lam"], strokes, k)
        v = pressure.cylinder_volume(phi, GEOM["bore"], GEOM["radius"], GEOM["lam"], 10.0, k)
        assert np.abs(p * v**cyc.gamma / (cyc.intake_pressure * v[0] ** cyc.gamma) - 1.0).max() < 1e-13


@pytest.mark.parametrize("strokes,k", [(4, 0.0), (2, 0.1)])
def test_wiebe_pressure_against_the_energy_equation(strokes, k):
    """Independent computation: the energy equation dp/dphi = (gamma - 1)/V Q dx/dphi - gamma p/V dV/dphi
    integrated step by step (solve_ivp, DOP853, rtol 1e-12, restarted at the start of combustion, where the
    burn rate is not smooth), dV/dphi = F_p v/omega from the kinematics; the closed form agrees to 1e-9 (the LSODA
    integration it replaces, rtol 1e-9 across the start of combustion, to 2e-7)."""
    cyc = pressure.WiebeCycle(10.0, 950.0)
    bore, radius, lam = GEOM["bore"], GEOM["radius"], GEOM["lam"]
    firing = np.pi * (strokes - 2)

    def rhs(t, p):
        v = pressure.cylinder_volume(t, bore, radius, lam, cyc.compression_ratio, k)
        dv = np.pi * bore**2 / 4.0 * kinematics.velocity(t, radius, lam, 1.0, k)
        z = (t - firing - cyc.start) / cyc.duration
        rate = cyc.a * (cyc.m + 1) / cyc.duration * z**cyc.m * np.exp(-cyc.a * z ** (cyc.m + 1)) if z > 0 else 0.0
        return (cyc.gamma - 1.0) / v * cyc.heat_input * rate - cyc.gamma * p / v * dv

    phi = firing + np.radians(np.arange(-180.0, 180.0, 0.5))
    start = firing + cyc.start
    legs = [solve_ivp(rhs, (phi[0], start), [cyc.intake_pressure], method="DOP853", dense_output=True, rtol=1e-12,
                      atol=1e-6)]
    legs.append(solve_ivp(rhs, (start, phi[-1]), legs[0].y[:, -1], method="DOP853", dense_output=True, rtol=1e-12,
                          atol=1e-6))
    ref = np.where(phi <= start, legs[0].sol(phi)[0], legs[1].sol(phi)[0])
    p = pressure.wiebe_pressure(phi, cyc, bore, radius, lam, strokes, k)
    assert np.abs(p / ref - 1.0).max() < 1e-9


@pytest.mark.parametrize("m", [-0.9, -0.5, 0.0])
def test_wiebe_pressure_with_a_burn_rate_singular_at_the_start(m):
    """For -1 < m < 0 the burn rate z^m is unbounded at the start of combustion.  Independent computation: in the
    variable u = z^(m+1) the heat-release integral is int V(phi(u))^(gamma - 1) a e^(-a u) du with
    phi(u) = phi_s + Delta phi u^(1/(m+1)), smooth for m <= 0 (400-point Gauss-Legendre rule); agreement to 1e-11."""
    cyc = pressure.WiebeCycle(18.0, 1500.0, m=m)
    bore, radius, lam = GEOM["bore"], GEOM["radius"], GEOM["lam"]

    def volume(t):
        return pressure.cylinder_volume(t, bore, radius, lam, cyc.compression_ratio)

    start = 2 * np.pi + cyc.start
    phi = np.linspace(start + 0.01, 3 * np.pi, 20)
    x, w = np.polynomial.legendre.leggauss(400)
    top = ((phi - start) / cyc.duration) ** (m + 1)
    u = 0.5 * top[:, None] * (x + 1)
    released = 0.5 * top * ((volume(start + cyc.duration * u ** (1 / (m + 1))) ** (cyc.gamma - 1)
                             * cyc.a * np.exp(-cyc.a * u)) @ w)
    ref = (cyc.intake_pressure * volume(np.pi) ** cyc.gamma
           + (cyc.gamma - 1) * cyc.heat_input * released) / volume(phi) ** cyc.gamma
    p = pressure.wiebe_pressure(phi, cyc, bore, radius, lam, 4)
    assert np.abs(p / ref - 1.0).max() < 1e-11


def _scaled_rows(header, rows, factor, at):
    """A file of ``rows`` with row ``at`` (0-based) multiplied by ``factor``."""
    return header + "\n" + "".join(f"{x:g},{y * factor if i == at else y:g}\n" for i, (x, y) in enumerate(rows))


INDICATOR_ROWS = [(0, 0.1), (180, 0.1), (360, 6.0), (540, 0.3), (700, 0.11)]


@pytest.mark.parametrize("header,at,factor,message", [
    # issue 21 nonsense 6: a pressure file scaled by 1e300 (p_max 6e300 MPa) was accepted
    ("crank_deg,pressure_MPa", 2, 1e300, "ind.csv:4: pressure_MPa = 6e+300: allowed [0.001, 100] (an absolute cylinder "
                                         "pressure)"),
    ("crank_deg,pressure_MPa", 2, 1e3, "ind.csv:4: pressure_MPa = 6000: allowed [0.001, 100]"),   # kPa read as MPa
    ("volume_cm3,pressure_MPa", 0, 1e300, "ind.csv:2: pressure_MPa = 1e+299: allowed [0.001, 100]"),
])
def test_pressure_values_outside_any_cylinder_are_refused(tmp_path, header, at, factor, message):
    f = tmp_path / "ind.csv"
    rows = INDICATOR_ROWS if header.startswith("crank") else [(50 + 10 * i, p) for i, (_, p) in enumerate(INDICATOR_ROWS)]
    f.write_text(_scaled_rows(header, rows, factor, at))
    with pytest.raises(pressure.PressureFileError, match=re.escape(message)):
        read_indicator(f, 4)


def test_a_volume_outside_any_cylinder_is_refused(tmp_path):
    f = tmp_path / "ind.csv"
    f.write_text("volume_cm3,pressure_MPa\n50,0.1\n500,0.2\n5e9,0.3\n60,4\n")
    with pytest.raises(pressure.PressureFileError, match=re.escape("ind.csv:4: volume_cm3 = 5e+09: allowed [0, 1e+08]")):
        read_indicator(f, 4)


@pytest.mark.parametrize("column,factor,message", [
    ("lift", 1e300, "lift.csv:{line}: lift_mm = 1e+301: allowed [-500, 500]"),
    ("lift", 1e3, "lift.csv:{line}: lift_mm = 10000: allowed [-500, 500]"),     # metres read as millimetres
    ("angle", 1e300, "lift.csv:{line}: angle_deg = 4e+302: allowed [-3600, 3600]"),
])
@pytest.mark.parametrize("comment", ["", "# a comment line keeps the file off numpy's fast path\n"])
def test_lift_table_values_outside_any_valve_are_refused(tmp_path, column, factor, message, comment):
    """Both readers of a lift table (numpy's for a plain file, the line-by-line one) name the same line."""
    from valvetrain.files import TableFileError, read_lift_table

    rows = [(-60.0 + 10.0 * i, 10.0 * np.sin(np.pi * i / 12) ** 2) for i in range(13)]
    rows[-1] = (400.0 if column == "angle" else rows[-1][0], rows[-1][1])
    text = "".join(f"{a * (factor if column == 'angle' and i == 12 else 1):g},"
                   f"{y * (factor if column == 'lift' and i == 6 else 1):g}\n" for i, (a, y) in enumerate(rows))
    f = tmp_path / "lift.csv"
    f.write_text(comment + "angle_deg,lift_mm\n" + text)
    line = (14 if column == "angle" else 8) + (1 if comment else 0)
    with pytest.raises(TableFileError, match=re.escape(message.format(line=line))):
        read_lift_table(f)
