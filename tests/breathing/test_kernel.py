"""The compiled cycle (valvetrain.breathing.kernel) against closed forms: a vessel emptying and filling through a
choked orifice (adiabatic, perfect gas: Heywood (1988), Appendix C with the energy balance of a fixed volume), an
isentropic compression with the valves shut (p V^gamma; and Cantera's isentropic state of the same real gas)."""

import cantera as ct
import numpy as np
import pytest

from valvetrain.breathing import gas, kernel as kn
from valvetrain.breathing.cycle import Cylinder

R, GAMMA = 287.0, 1.4
PERFECT = gas.Gas.perfect(R, GAMMA)


def _run(volume, rate, dt, intake=0.0, exhaust=0.0, plenums=((1e5, 300.0), (1e5, 300.0)), g=PERFECT, state=None):
    """Integrate the kernel over the given schedule of volume, adiabatic, no runners, a perfect gas by default."""
    steps = volume.size - 1
    sched = np.zeros((kn.SCHEDULE_ROWS, steps + 1))
    sched[kn.VOLUME], sched[kn.VOLUME_RATE] = volume, rate
    sched[kn.INTAKE_IN], sched[kn.EXHAUST_OUT] = intake, exhaust
    par = np.zeros(kn.PARAMETERS)
    par[kn.DT], par[kn.BORE], par[kn.SWEPT], par[kn.IVC], par[kn.T_MID] = dt, 0.1, 1e-3, steps, g.t_mid
    par[kn.GROSS_TO] = steps
    coef = np.stack([g.coefficients, g.coefficients])
    rgas = np.array([g.gas_constant, g.gas_constant])
    rows = [[p, t, y, float(gas.enthalpy(g, t)), float(gas.ratio_of_specific_heats(g, t)), g.gas_constant]
            for (p, t), y in zip(plenums, (0.0, 1.0), strict=True)]
    p0, t0 = state
    m = p0 * volume[0] / (g.gas_constant * t0)
    cyl = np.zeros(kn.CYLINDER_STATE)
    cyl[kn.M], cyl[kn.U], cyl[kn.TG] = m, m * float(gas.internal_energy(g, t0)), t0
    cyl[kn.P_REF], cyl[kn.V_REF], cyl[kn.T_REF], cyl[kn.G_REF] = p0, volume[0], t0, GAMMA
    records = np.zeros((kn.RECORDS, steps + 1))
    tallies = np.zeros(kn.TALLIES)
    kn.run_cycle(cyl, np.zeros((0, 4)), np.zeros((0, 4)), sched, par, coef, rgas, np.array(rows), np.zeros((2, 5)),
                 np.ones((2, 4)), tallies, records)
    return records, tallies, cyl


def test_emptying_through_a_choked_orifice():
    """A 1 L vessel at 5 bar, 300 K empties through 20 mm^2 into 0.5 bar: while choked, adiabatic,
    p / p0 = (1 + (gamma-1)/(2 gamma) K t)^(-2 gamma/(gamma-1)), K = gamma A C* c0 / V (to 1e-6)."""
    volume, area, p0, t0 = 1e-3, 20e-6, 5e5, 300.0
    dt, steps = 2e-6, 10000
    v = np.full(steps + 1, volume)
    records, _, _ = _run(v, np.zeros(steps + 1), dt, exhaust=area, plenums=((1e5, 300.0), (0.5e5, 300.0)),
                         state=(p0, t0))
    t = np.arange(steps + 1) * dt
    c_star = (2.0 / (GAMMA + 1.0)) ** ((GAMMA + 1.0) / (2.0 * (GAMMA - 1.0)))
    k = GAMMA * area * c_star * np.sqrt(GAMMA * R * t0) / volume
    exact = p0 * (1.0 + (GAMMA - 1.0) / (2.0 * GAMMA) * k * t) ** (-2.0 * GAMMA / (GAMMA - 1.0))
    choked = exact > 0.5e5 / 0.5283
    assert choked.sum() > steps // 2
    assert np.max(np.abs(records[kn.REC_P][choked] / exact[choked] - 1.0)) < 1e-6


def test_filling_through_a_choked_orifice():
    """A 1 L vessel at 0.2 bar fills from a 1 bar, 300 K plenum through 10 mm^2: while choked the flow is constant and
    dp/dt = gamma R T_0 m_dot / V (adiabatic), the pressure a straight line (to 1e-9)."""
    volume, area = 1e-3, 10e-6
    dt, steps = 2e-6, 20000
    records, tallies, _ = _run(np.full(steps + 1, volume), np.zeros(steps + 1), dt, intake=area,
                               plenums=((1e5, 300.0), (1e5, 300.0)), state=(0.2e5, 300.0))
    t = np.arange(steps + 1) * dt
    flow = area * 1e5 * np.sqrt(GAMMA / (R * 300.0)) * (2.0 / (GAMMA + 1.0)) ** 3.0
    exact = 0.2e5 + GAMMA * R * 300.0 * flow * t / volume
    choked = exact < 0.5283e5 * 0.999
    assert choked.sum() > steps // 3
    assert np.max(np.abs(records[kn.REC_P][choked] / exact[choked] - 1.0)) < 1e-9


def _compression(g, steps=3600):
    cyl = Cylinder(0.092, 0.086, 0.231, 10.0)
    omega = 2000.0 * np.pi / 30.0
    theta = np.linspace(np.pi, 2.0 * np.pi, steps + 1)
    records, tallies, state = _run(cyl.volume(theta), cyl.volume_rate(theta, omega), np.pi / (steps * omega), g=g,
                                   state=(1e5, 330.0))
    return cyl, records, tallies


def test_isentropic_compression_of_a_perfect_gas():
    """Valves shut, adiabatic, BDC to TDC: p V^gamma constant (to 1e-6 at half a degree a step... 1/20 deg here) and
    the work equals the change of internal energy (to round-off)."""
    cyl, records, tallies = _compression(PERFECT)
    v = cyl.volume(np.linspace(np.pi, 2.0 * np.pi, records.shape[1]))
    invariant = records[kn.REC_P] * v**GAMMA
    assert np.max(np.abs(invariant / invariant[0] - 1.0)) < 1e-6
    m = records[kn.REC_M, 0]
    cv = R / (GAMMA - 1.0)
    assert -tallies[kn.WORK] == pytest.approx(m * cv * (records[kn.REC_T, -1] - records[kn.REC_T, 0]), rel=1e-12)


def test_isentropic_compression_of_air_against_cantera():
    """Real air from BDC (1 bar, 330 K) to TDC: the pressure and temperature of Cantera's state of the same entropy at
    the TDC's specific volume (the same NASA polynomials, evaluated by Cantera), to 1e-6."""
    air = gas.air()
    cyl, records, _ = _compression(air)
    species = [s for s in ct.Species.list_from_file(gas.SPECIES_FILE) if s.name in gas.AIR]
    solution = ct.Solution(thermo="ideal-gas", species=species)
    solution.TPX = 330.0, 1e5, gas.AIR
    m = records[kn.REC_M, 0]
    solution.SV = solution.s, float(cyl.volume(2.0 * np.pi)) / m
    assert records[kn.REC_P, -1] == pytest.approx(solution.P, rel=1e-6)
    assert records[kn.REC_T, -1] == pytest.approx(solution.T, rel=1e-6)
