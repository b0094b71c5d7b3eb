"""The runners' finite-volume scheme (valvetrain.breathing.runners): Sod's shock tube against the exact Riemann
solution (Toro (2009), chapter 4, solved here independently), the quarter-wave frequency of a pipe closed at one end
(Kinsler et al. (2000), section 10.2), conservation with closed ends, and the ends' matching conditions."""

import numpy as np
import pytest
from scipy.optimize import brentq

from valvetrain.breathing import runners
from valvetrain.breathing.orifice import mass_flux

GAS = np.array([1.4, 287.0, 0.0, 1.8e-5])


def _pipe(n, state):
    q = np.empty((n, 4))
    for i in range(n):
        runners.conserved(*state(i), GAS, q[i])
    return q


def _exact_riemann(left, right, gamma, xi):
    """Density of the exact solution of the Riemann problem at x/t = xi (Toro (2009), sections 4.2-4.5)."""
    (rl, ul, pl), (rr, ur, pr) = left, right
    cl, cr = np.sqrt(gamma * pl / rl), np.sqrt(gamma * pr / rr)

    def f(p, r, pk, c):
        if p > pk:
            a, b = 2.0 / ((gamma + 1.0) * r), (gamma - 1.0) / (gamma + 1.0) * pk
            return (p - pk) * np.sqrt(a / (p + b))
        return 2.0 * c / (gamma - 1.0) * ((p / pk) ** ((gamma - 1.0) / (2.0 * gamma)) - 1.0)

    ps = brentq(lambda p: f(p, rl, pl, cl) + f(p, rr, pr, cr) + ur - ul, 1e-6, 10 * max(pl, pr), xtol=1e-12)
    us = 0.5 * (ul + ur) + 0.5 * (f(ps, rr, pr, cr) - f(ps, rl, pl, cl))
    g = (gamma - 1.0) / (gamma + 1.0)
    out = np.empty_like(xi)
    for i, s in enumerate(xi):
        if s <= us:     # left of the contact: a rarefaction (Sod)
            rs = rl * (ps / pl) ** (1.0 / gamma)
            head, tail = ul - cl, us - cl * (ps / pl) ** ((gamma - 1.0) / (2.0 * gamma))
            out[i] = rl if s < head else rs if s > tail else rl * (2.0 / (gamma + 1.0) + g / cl * (ul - s)) ** (
                2.0 / (gamma - 1.0))
        else:           # right of the contact: a shock
            rs = rr * (ps / pr + g) / (g * ps / pr + 1.0)
            speed = ur + cr * np.sqrt((gamma + 1.0) / (2.0 * gamma) * ps / pr + (gamma - 1.0) / (2.0 * gamma))
            out[i] = rs if s < speed else rr
    return out


def test_sod_shock_tube():
    """Sod's problem (1 kg/m3, 1 bar | 0.125 kg/m3, 0.1 bar) on 400 cells: the density's mean error under 0.5 % of the
    jump, the plateaus within 0.2 %."""
    n, length = 400, 1.0
    dx = length / n
    q = _pipe(n, lambda i: (1.0, 0.0, 1e5, 0.0) if (i + 0.5) * dx < 0.5 else (0.125, 0.0, 1e4, 1.0))
    c = np.sqrt(1.4e5)
    dt = 0.4 * dx / c
    steps = int(round(0.25 * length / c / dt))
    runners.simulate_pipe(q, GAS, dx, 0.05, False, dt, steps, runners.WALL, np.zeros(3), runners.WALL, np.zeros(3), 0)
    x = (np.arange(n) + 0.5) * dx - 0.5
    exact = _exact_riemann((1.0, 0.0, 1e5), (0.125, 0.0, 1e4), 1.4, x / (steps * dt))
    assert np.mean(np.abs(q[:, 0] - exact)) < 0.005 * 0.875
    assert q[int(0.72 * n), 0] == pytest.approx(exact[int(0.72 * n)], rel=2e-3)     # between contact and shock
    assert q[int(0.6 * n), 0] == pytest.approx(exact[int(0.6 * n)], rel=2e-3)       # between fan and contact


@pytest.mark.parametrize("cells", [10, 40])
def test_quarter_wave_frequency(cells):
    """A 0.5 m pipe closed at one end and open to a plenum at the other rings at c / (4 L) = 173.6 Hz (within 0.5 %
    on 10 cells)."""
    length = 0.5
    dx = length / cells
    q = _pipe(cells, lambda i: (1.01e5 / (287.0 * 300.0), 0.0, 1.01e5, 0.0))
    c = np.sqrt(1.4 * 287.0 * 300.0)
    dt = 0.7 * dx / c
    steps = int(0.06 / dt)
    p = runners.simulate_pipe(q, GAS, dx, 0.04, False, dt, steps, runners.PLENUM, np.array([1e5, 300.0, 0.0]),
                              runners.WALL, np.zeros(3), cells - 1) - 1e5
    t = np.arange(1, steps + 1) * dt
    up = np.flatnonzero((p[:-1] < 0) & (p[1:] >= 0))
    crossings = t[up] - p[up] * dt / (p[up + 1] - p[up])
    frequency = 1.0 / np.mean(np.diff(crossings))
    assert frequency == pytest.approx(runners.quarter_wave_frequency(length, c), rel=5e-3)


def test_closed_pipe_conserves():
    """Between walls, with friction, mass, energy and tracer stay constant to round-off (conservative fluxes; friction
    moves momentum only)."""
    q = _pipe(30, lambda i: (1.2 + 0.1 * np.sin(i), 20.0 * np.cos(i), 1e5 + 3e3 * np.sin(2 * i), i / 30))
    before = q.sum(axis=0)
    runners.simulate_pipe(q, GAS, 0.01, 0.03, True, 1e-5, 500, runners.WALL, np.zeros(3), runners.WALL, np.zeros(3), 0)
    after = q.sum(axis=0)
    assert np.allclose(after[[0, 2, 3]], before[[0, 2, 3]], rtol=1e-13)


def test_plenum_inflow_is_isentropic():
    """Inflow from a plenum: the face's total enthalpy and entropy are the plenum's (isentropic acceleration)."""
    flux = np.zeros(4)
    runners.plenum_face(1.1, 30.0, 0.97e5, 0.0, GAS, 1e5, 300.0, 0.0, flux, np.zeros(runners.SCRATCH))
    mass = flux[0]
    assert mass > 0
    h0 = flux[2] / mass
    assert h0 == pytest.approx(1.4 / 0.4 * 287.0 * 300.0, rel=1e-12)


def test_valve_face_passes_the_orifice_flow():
    """Out of the pipe: the face's mass flow equals the valve's quasi-steady flow from the face's stagnation state;
    a shut valve is a wall."""
    flux = np.zeros(4)
    scratch = np.zeros(runners.SCRATCH)
    rho, u, p = 1.1, 15.0, 1e5
    runners.valve_face(rho, u, p, 0.0, GAS, 5e-4, 1e-4, 1e-4, 0.8e5, 330.0, 0.0, 1.4, 287.0, 0.0, flux, scratch)
    z = scratch[1]
    t_c = p / (rho * 287.0)
    ub = u - np.sqrt(1.4 * p / rho) * (z - 1.0) / 0.2
    t0 = t_c * z * z + ub * ub / (2 * 1004.5)
    p0 = p * (t0 / t_c) ** 3.5
    assert flux[0] == pytest.approx(1e-4 * mass_flux(p0, t0, 0.8e5, 1.4, 287.0), rel=1e-8)
    runners.valve_face(rho, 0.0, p, 0.0, GAS, 5e-4, 0.0, 0.0, 0.8e5, 330.0, 0.0, 1.4, 287.0, 0.0, flux, scratch)
    assert flux[0] == 0.0 and flux[1] == pytest.approx(p * 5e-4)
