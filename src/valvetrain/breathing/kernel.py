"""Compiled integration of one engine cycle: the cylinder, its valves, runners and plenums, step by step.

The cylinder is one zone (Heywood (1988), chapter 14): its mass m, sensible internal energy U and the mass m_b of
burned or residual gas change as

.. math:: \\dot m = \\sum_v \\dot m_v + \\dot m_f,\\quad
          \\dot U = \\sum_v \\dot H_v - p\\dot V - \\dot Q_w + \\dot Q_c,\\quad
          \\dot m_b = \\sum_v \\dot m_v Y_v + \\dot m_{conv},

the gas ideal with the polynomials of :mod:`.gas`, mixed by the burned fraction x = m_b / m; its temperature from
U / m, its pressure p = m R T / V.  The valves' flows are the end faces of the runners (:mod:`.runners`), or, without
a runner, orifices to the plenum; the wall heat is Woschni's (:mod:`.heat_transfer`); the heat release and the
fuel's mass follow the burned fraction's schedule.  The fresh charge is traced: the gas that was in the cylinder at
the firing TDC, and the gas of the exhaust plenum, count as old (Y = 1).

The runners' cells and the cylinder advance together with Heun's two-stage scheme (the strong stability preserving
Runge-Kutta method of second order, Gottlieb and Shu (1998)) on a fixed step; every flow into or out of a part is
counted with the weights of that scheme, so the energy that crosses a face leaves one part and enters the other
exactly and the cycle's balances close to round-off.
"""

import numpy as np
from numba import njit

from .gas import cp_at, enthalpy_at, temperature_at
from .heat_transfer import woschni_coefficient, woschni_velocity
from .orifice import mass_flux
from .runners import SCRATCH, pipe_rates, plenum_face, primitive, valve_face

# rows of the schedule (per step node)
VOLUME, VOLUME_RATE, WALL_AREA, INTAKE_IN, INTAKE_OUT, EXHAUST_OUT, EXHAUST_IN, C1, C2, BURN = range(10)
"""Rows of the cycle's schedule: volume [m^3], dV/dt [m^3/s], wall area [m^2], effective areas [m^2] of the intake
valve into and out of the cylinder and of the exhaust valve out of and into it, Woschni's C1 and C2 and the burned
fraction's schedule (0 to 1)."""
SCHEDULE_ROWS = 10

# scalar parameters
DT, BORE, PISTON_SPEED, SWEPT, WALL_T, HEAT, FUEL_AIR, HEAT_PER_FUEL, IVC, GROSS_FROM, GROSS_TO, T_MID = range(12)
"""Indices of the kernel's parameters: the step [s], bore [m], mean piston speed [m/s], swept volume [m^3], wall
temperature [K], 1 with Woschni's heat transfer (0 adiabatic), the fuel-air ratio, the heat released per kg of fuel
[J/kg], the step of the intake valve's closing, the steps where the gross work's span starts and ends, and the
temperature where the gas polynomials change range [K]."""
PARAMETERS = 12

# plenum rows: [p0, T0, Y0, h0 (the cylinder's sensible enthalpy of the plenum gas), gamma0, R0]
PLENUM_P, PLENUM_T, PLENUM_Y, PLENUM_H, PLENUM_GAMMA, PLENUM_R = range(6)

# pipe rows: [dx, diameter, area, friction, present]
PIPE_DX, PIPE_D, PIPE_AREA, PIPE_FRICTION, PIPE_PRESENT = range(5)

# tallies of a cycle
(DELIVERED, TO_EXHAUST, INTAKE_FORWARD, INTAKE_BACK, EXHAUST_FORWARD, EXHAUST_BACK, WORK, GROSS_WORK, WALL_HEAT,
 COMBUSTION_HEAT, ENERGY_IN, ENERGY_OUT, VALVE_ENERGY, EXHAUST_TEMPERATURE, FUEL) = range(15)
"""Tallies of one cycle: net mass from the intake plenum and into the exhaust plenum [kg]; mass into the cylinder
through the intake valve and back out, out through the exhaust valve and back in [kg]; piston work and its gross
part [J]; heat to the walls and released by combustion [J]; energy from the intake plenum and into the exhaust plenum
[J]; net energy into the cylinder through its valves [J]; the exhaust valve's outflow weighted by the cylinder
temperature [kg K]; fuel burned [kg]."""
TALLIES = 15

# state of the cylinder: [m, U, m_b, T guess, fresh mass at IVC, p_ref, V_ref, T_ref, gamma_ref]
M, U, MB, TG, FRESH_IVC, P_REF, V_REF, T_REF, G_REF = range(9)
CYLINDER_STATE = 9

# records per step node
REC_P, REC_T, REC_M, REC_INTAKE, REC_EXHAUST, REC_MB, REC_INTAKE_PORT, REC_EXHAUST_PORT = range(8)
"""Rows of the per-step records: pressure [Pa], temperature [K], mass [kg], mass flows into the cylinder through the
intake valve and out through the exhaust valve [kg/s], burned mass [kg], pressures at the intake and exhaust valves'
ports [Pa]."""
RECORDS = 8

COURANT_EVERY = 4
"""Steps between two measurements of the runners' Courant number (the largest |u| + c of their cells)."""


@njit(cache=True, nogil=True)
def _gas_state(m, energy, mb, coef, rgas, t_mid, guess, volume, mixed):
    """The cylinder's temperature, pressure, sensible enthalpy, gamma and gas constant; ``mixed`` (2, 6) receives the
    mixture's coefficients."""
    x = mb / m
    for j in range(2):
        for k in range(6):
            mixed[j, k] = coef[0, j, k] + x * (coef[1, j, k] - coef[0, j, k])
    r = rgas[0] + x * (rgas[1] - rgas[0])
    t = temperature_at(energy / m, mixed, t_mid, r, guess)
    cp = cp_at(t, mixed, t_mid)
    return t, m * r * t / volume, enthalpy_at(t, mixed, t_mid), cp / (cp - r), r


@njit(cache=True, nogil=True)
def _direct(area_in, area_out, plenum, p, t, h, gamma, r, x, flux):
    """Flow between a plenum and the cylinder through a valve without a runner, into ``flux`` (mass, -, energy,
    tracer; positive into the cylinder)."""
    m_in = area_in * mass_flux(plenum[PLENUM_P], plenum[PLENUM_T], p, plenum[PLENUM_GAMMA], plenum[PLENUM_R])
    m_out = area_out * mass_flux(p, t, plenum[PLENUM_P], gamma, r)
    flux[0] = m_in - m_out
    flux[1] = 0.0
    flux[2] = m_in * plenum[PLENUM_H] - m_out * h
    flux[3] = m_in * plenum[PLENUM_Y] - m_out * x


@njit(cache=True, nogil=True)
def _port(q, gas, pipe, plenum, area_to_cylinder, area_from_cylinder, p, t, h, gamma, r, x, left, right, flux,
          roots):
    """A runner's end faces: ``left`` (per unit area, from its plenum) and ``right`` (per unit area, at its valve), and
    the valve's flow into the cylinder ``flux`` (mass, momentum, energy, tracer); ``roots`` (2,
    :data:`~.runners.SCRATCH`) the ends' scratch (their roots of the previous step)."""
    rho, u, pc, y = primitive(q[0], gas)
    plenum_face(rho, u, pc, y, gas, plenum[PLENUM_P], plenum[PLENUM_T], plenum[PLENUM_Y], left, roots[0])
    n = q.shape[0]
    rho, u, pc, y = primitive(q[n - 1], gas)
    valve_face(rho, u, pc, y, gas, pipe[PIPE_AREA], area_to_cylinder, area_from_cylinder, p, t, h, gamma, r, x, flux,
               roots[1])
    for k in range(4):
        right[k] = flux[k] / pipe[PIPE_AREA]


@njit(cache=True, nogil=True)
def _wave_speed(q, gas):
    """Largest |u| + c of a runner's cells [m/s]; inf where a cell's density or pressure is not positive (or not a
    number): the gas has left the physical range."""
    out = 0.0
    for i in range(q.shape[0]):
        rho, u, p, y = primitive(q[i], gas)
        if not (rho > 0.0 and p > 0.0):
            return np.inf
        out = max(out, abs(u) + np.sqrt(gas[0] * p / rho))
    return out


@njit(cache=True, nogil=True)
def _rates(k, burn, cyl, qi, qe, sched, par, coef, rgas, plenums, pipes, gases, dcyl, rate_i, rate_e, work_i, work_e,
           mixed, faces, roots, out):
    """Time derivatives of the cylinder ``dcyl`` (m, U, m_b) and of the runners' cells at step node ``k``, and the
    flows through the faces ``out``: intake valve, exhaust valve, intake plenum, exhaust plenum (mass and energy
    each), wall heat, combustion heat, fuel (rates); ``burn`` is the step's rate of the burned fraction's schedule
    [1/s], the same at both stages.  Returns the cylinder's pressure and temperature."""
    volume = sched[VOLUME, k]
    m, energy, mb = cyl[M], cyl[U], cyl[MB]
    t, p, h, gamma, r = _gas_state(m, energy, mb, coef, rgas, par[T_MID], cyl[TG], volume, mixed)
    x = mb / m
    left, right, fi, fe = faces[0], faces[1], faces[2], faces[3]
    # intake valve, positive into the cylinder
    if pipes[0, PIPE_PRESENT] > 0.0:
        _port(qi, gases[0], pipes[0], plenums[0], sched[INTAKE_IN, k], sched[INTAKE_OUT, k], p, t, h, gamma, r, x,
              left, right, fi, roots[0])
        pipe_rates(qi, gases[0], pipes[0, PIPE_DX], pipes[0, PIPE_D], pipes[0, PIPE_FRICTION] > 0.0, left, right,
                   rate_i, work_i)
        out[4] = left[0] * pipes[0, PIPE_AREA]
        out[5] = left[2] * pipes[0, PIPE_AREA]
    else:
        _direct(sched[INTAKE_IN, k], sched[INTAKE_OUT, k], plenums[0], p, t, h, gamma, r, x, fi)
        out[4] = fi[0]
        out[5] = fi[2]
    # exhaust valve: the runner's plenum end is at x = 0, its valve end (into the cylinder) at x = L
    if pipes[1, PIPE_PRESENT] > 0.0:
        _port(qe, gases[1], pipes[1], plenums[1], sched[EXHAUST_IN, k], sched[EXHAUST_OUT, k], p, t, h, gamma, r, x,
              left, right, fe, roots[1])
        pipe_rates(qe, gases[1], pipes[1, PIPE_DX], pipes[1, PIPE_D], pipes[1, PIPE_FRICTION] > 0.0, left, right,
                   rate_e, work_e)
        out[6] = -left[0] * pipes[1, PIPE_AREA]
        out[7] = -left[2] * pipes[1, PIPE_AREA]
    else:
        _direct(sched[EXHAUST_IN, k], sched[EXHAUST_OUT, k], plenums[1], p, t, h, gamma, r, x, fe)
        out[6] = -fe[0]
        out[7] = -fe[2]
    out[0], out[1], out[2], out[3] = fi[0], fi[2], fe[0], fe[2]
    # wall heat (Woschni), positive from the gas to the walls
    heat = 0.0
    if par[HEAT] > 0.0:
        motored = cyl[P_REF] * (cyl[V_REF] / volume) ** cyl[G_REF]
        w = woschni_velocity(sched[C1, k], sched[C2, k], par[PISTON_SPEED], par[SWEPT], cyl[T_REF], cyl[P_REF],
                             cyl[V_REF], p, motored)
        heat = woschni_coefficient(par[BORE], p, t, max(w, 0.0)) * sched[WALL_AREA, k] * (t - par[WALL_T])
    # the burned fraction's step: fuel, heat and the conversion of fresh gas to burned
    fuel = cyl[FRESH_IVC] * par[FUEL_AIR] * burn
    combustion = fuel * par[HEAT_PER_FUEL]
    out[8], out[9], out[10] = heat, combustion, fuel
    dcyl[0] = fi[0] + fe[0] + fuel
    dcyl[1] = fi[2] + fe[2] - p * sched[VOLUME_RATE, k] - heat + combustion
    dcyl[2] = fi[3] + fe[3] + cyl[FRESH_IVC] * burn + fuel
    return p, t


@njit(cache=True, nogil=True)
def run_cycle(cyl, qi, qe, sched, par, coef, rgas, plenums, pipes, gases, tallies, records) -> float:
    """Integrate one cycle of ``sched.shape[1] - 1`` steps from the state ``cyl``, ``qi``, ``qe`` (changed in place).

    Parameters
    ----------
    cyl : ndarray
        (9,) the cylinder's mass [kg], sensible internal energy [J], burned mass [kg], last temperature [K], and what
        the cycle keeps at the intake valve's closing (fresh mass [kg], p [Pa], V [m^3], T [K], gamma for Woschni's
        motored pressure).
    qi, qe : ndarray
        (n, 4) conserved states of the intake and exhaust runners' cells (unused where ``pipes`` has none).
    sched : ndarray
        (10, steps + 1) the schedule at the step nodes (:data:`VOLUME` ... :data:`BURN`).
    par : ndarray
        (12,) the parameters (:data:`DT` ...).
    coef : ndarray
        (2, 2, 6) polynomials of the fresh and the burned gas (:mod:`.gas`).
    rgas : ndarray
        (2,) their gas constants [J/(kg K)].
    plenums : ndarray
        (2, 6) intake and exhaust plenums: p0 [Pa], T0 [K], tracer, the cylinder's enthalpy of their gas [J/kg], gamma,
        R [J/(kg K)].
    pipes : ndarray
        (2, 5) the runners: cell length [m], diameter [m], area [m^2], friction (1/0), present (1/0).
    gases : ndarray
        (2, 4) the runners' ``[gamma, R, e_0, mu]`` (:func:`~.runners.frozen_gas`).
    tallies : ndarray
        (15,) the cycle's tallies (:data:`DELIVERED` ...), set here.
    records : ndarray
        (8, steps + 1) per-step records (:data:`REC_P` ...), set here.

    Returns
    -------
    float
        The largest Courant number (|u| + c) dt / dx met in the runners (0 without runners); the caller repeats a
        cycle whose number exceeded 1 with a shorter step.  A non-finite state, a cell of no positive density or
        pressure (checked where the Courant number is) returns inf.
    """
    steps = sched.shape[1] - 1
    dt = par[DT]
    ivc = int(par[IVC])
    g0, g1 = int(par[GROSS_FROM]), int(par[GROSS_TO])
    ni, ne = qi.shape[0], qe.shape[0]
    rate_i, rate_e = np.zeros((ni, 4)), np.zeros((ne, 4))
    rate_i2, rate_e2 = np.zeros((ni, 4)), np.zeros((ne, 4))
    work_i, work_e = np.empty((3, ni + 1, 4)), np.empty((3, ne + 1, 4))
    si, se = qi.copy(), qe.copy()
    mixed = np.empty((2, 6))
    faces = np.empty((4, 4))
    out1, out2 = np.zeros(11), np.zeros(11)
    roots = np.zeros((2, 2, SCRATCH))
    d1, d2 = np.zeros(3), np.zeros(3)
    stage = cyl.copy()
    for j in range(TALLIES):
        tallies[j] = 0.0
    courant = 0.0
    for k in range(steps):
        if k == ivc:
            t, p, h, gamma, r = _gas_state(cyl[M], cyl[U], cyl[MB], coef, rgas, par[T_MID], cyl[TG], sched[VOLUME, k],
                                           mixed)
            cyl[FRESH_IVC] = cyl[M] - cyl[MB]
            cyl[P_REF], cyl[V_REF], cyl[T_REF], cyl[G_REF] = p, sched[VOLUME, k], t, gamma
        burn = (sched[BURN, k + 1] - sched[BURN, k]) / dt
        p, t = _rates(k, burn, cyl, qi, qe, sched, par, coef, rgas, plenums, pipes, gases, d1, rate_i, rate_e, work_i,
                      work_e, mixed, faces, roots, out1)
        cyl[TG] = t
        records[REC_P, k], records[REC_T, k], records[REC_M, k], records[REC_MB, k] = p, t, cyl[M], cyl[MB]
        records[REC_INTAKE, k], records[REC_EXHAUST, k] = out1[0], -out1[2]
        records[REC_INTAKE_PORT, k] = primitive(qi[ni - 1], gases[0])[2] if ni > 0 else plenums[0, PLENUM_P]
        records[REC_EXHAUST_PORT, k] = primitive(qe[ne - 1], gases[1])[2] if ne > 0 else plenums[1, PLENUM_P]
        if ni > 0 and k % COURANT_EVERY == 0:
            courant = max(courant, _wave_speed(qi, gases[0]) * dt / pipes[0, PIPE_DX])
        if ne > 0 and k % COURANT_EVERY == 0:
            courant = max(courant, _wave_speed(qe, gases[1]) * dt / pipes[1, PIPE_DX])
        # predictor
        stage[M] = cyl[M] + dt * d1[0]
        stage[U] = cyl[U] + dt * d1[1]
        stage[MB] = cyl[MB] + dt * d1[2]
        stage[TG] = t
        for j in range(FRESH_IVC, CYLINDER_STATE):
            stage[j] = cyl[j]
        for i in range(ni):
            for c in range(4):
                si[i, c] = qi[i, c] + dt * rate_i[i, c]
        for i in range(ne):
            for c in range(4):
                se[i, c] = qe[i, c] + dt * rate_e[i, c]
        if not (stage[M] > 0.0 and np.isfinite(stage[U])):
            return np.inf
        p2, t2 = _rates(k + 1, burn, stage, si, se, sched, par, coef, rgas, plenums, pipes, gases, d2, rate_i2, rate_e2,
                        work_i, work_e, mixed, faces, roots, out2)
        # corrector
        cyl[M] += 0.5 * dt * (d1[0] + d2[0])
        cyl[U] += 0.5 * dt * (d1[1] + d2[1])
        cyl[MB] += 0.5 * dt * (d1[2] + d2[2])
        cyl[TG] = t2
        for i in range(ni):
            for c in range(4):
                qi[i, c] += 0.5 * dt * (rate_i[i, c] + rate_i2[i, c])
        for i in range(ne):
            for c in range(4):
                qe[i, c] += 0.5 * dt * (rate_e[i, c] + rate_e2[i, c])
        if not (cyl[M] > 0.0 and np.isfinite(cyl[U])):
            return np.inf
        half = 0.5 * dt
        work = half * (p * sched[VOLUME_RATE, k] + p2 * sched[VOLUME_RATE, k + 1])
        tallies[WORK] += work
        if g0 <= k < g1:
            tallies[GROSS_WORK] += work
        tallies[DELIVERED] += half * (out1[4] + out2[4])
        tallies[ENERGY_IN] += half * (out1[5] + out2[5])
        tallies[TO_EXHAUST] += half * (out1[6] + out2[6])
        tallies[ENERGY_OUT] += half * (out1[7] + out2[7])
        tallies[INTAKE_FORWARD] += half * (max(out1[0], 0.0) + max(out2[0], 0.0))
        tallies[INTAKE_BACK] += half * (max(-out1[0], 0.0) + max(-out2[0], 0.0))
        tallies[EXHAUST_FORWARD] += half * (max(-out1[2], 0.0) + max(-out2[2], 0.0))
        tallies[EXHAUST_BACK] += half * (max(out1[2], 0.0) + max(out2[2], 0.0))
        tallies[EXHAUST_TEMPERATURE] += half * (max(-out1[2], 0.0) * t + max(-out2[2], 0.0) * t2)
        tallies[VALVE_ENERGY] += half * (out1[1] + out1[3] + out2[1] + out2[3])
        tallies[WALL_HEAT] += half * (out1[8] + out2[8])
        tallies[COMBUSTION_HEAT] += half * (out1[9] + out2[9])
        tallies[FUEL] += half * (out1[10] + out2[10])
    t, p, h, gamma, r = _gas_state(cyl[M], cyl[U], cyl[MB], coef, rgas, par[T_MID], cyl[TG], sched[VOLUME, steps],
                                   mixed)
    cyl[TG] = t
    records[REC_P, steps], records[REC_T, steps], records[REC_M, steps], records[REC_MB, steps] = p, t, cyl[M], cyl[MB]
    records[REC_INTAKE, steps], records[REC_EXHAUST, steps] = records[REC_INTAKE, 0], records[REC_EXHAUST, 0]
    records[REC_INTAKE_PORT, steps] = records[REC_INTAKE_PORT, 0]
    records[REC_EXHAUST_PORT, steps] = records[REC_EXHAUST_PORT, 0]
    return courant
