"""Cylinder pressure (valvetrain.crank.pressure): a p-V diagram mapped onto crank angles, the Wiebe model against the
energy equation (the reading of the files: tests/test_files.py)."""

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from valvetrain.crank import kinematics, pressure

GEOM = dict(bore=0.080, radius=0.0385, lam=0.285)


def _wiebe(phi):
    return pressure.wiebe_pressure(phi, pressure.WiebeCycle(10.0, 950.0), GEOM["bore"], GEOM["radius"], GEOM["lam"], 4)


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
