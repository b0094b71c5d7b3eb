"""The lost-motion drive (valvetrain.hydraulic_actuation; Bernard et al. (2009), the MultiAir intake): the solenoid
valve that bypasses the pump chamber to the accumulator and the hydraulic brake, each against an independent
reference: the quasi-static compressible column of a solenoid that never opens, the oil circuit's volume balance and
the closed-form landing velocity of a valve falling against a quadratic brake."""

import math

import numpy as np
import pytest

from valvetrain.hydraulic_actuation import (Actuator, Brake, Fluid, HydraulicDrive, Pipe, Pump, Solenoid, Valve,
                                            orifice_flow, simulate)
from valvetrain.laws import KurzLaw

PISTON = math.pi * 0.014**2 / 4
"""Area of the assumed pump and brake pistons, 14 mm [m^2]."""

RELEASE = -0.3
"""Camshaft angle at which the solenoid opens in the early-closing cases [rad from the nose]."""


@pytest.fixture(scope="module")
def law():
    """A Kurz law of 9 mm lift as the pump piston's lift (any lift law will do)."""
    return KurzLaw(9e-3, 0.25e-3, 0.02e-3 * 180 / np.pi, *np.deg2rad([27.0, 6.0, 38.0]), 0.625)


def drive(solenoid=None, brake=None, leakage=0.0, fill=0.0, pressure=0.5e6):
    """An assumed MultiAir-sized drive: 14 mm pistons, 2 cm^3 chambers, a 30 mm passage of 12 mm, a 0.1 kg valve on a
    30 N/mm spring of 200 N preload; the accumulator and the rest at ``pressure`` (absolute)."""
    return HydraulicDrive(Fluid(bulk_modulus=1.5e9), Pipe(0.03, 0.012, friction_factor=0.03, reaches=2),
                          Pump(PISTON, 2e-6, leakage, pressure, fill), Actuator(PISTON, 2e-6, leakage),
                          Valve(0.1, 30e3, 200.0, 20.0), initial_pressure=pressure, back_pressure=0.1e6,
                          solenoid=solenoid, brake=brake)


def test_a_solenoid_never_open_lifts_the_rigid_cam_less_the_oil_compression(law):
    """Closed form (quasi-static, a slow cam): with the solenoid shut the whole revolution the oil is trapped, and the
    open valve holds its spring with p = p_back + (F_0 + k y) / A_a; the plunger's volume A_p h fills the valve's
    A_a y and the oil's compression C (p - p_0), C = (V_p + V_a) / K + A L / (rho a^2), so
    y = (A_p h - C (p_back - p_0) - C F_0 / A_a) / (A_a + C k / A_a), the rigid lift less the compression.  The
    shut solenoid and the brake (on a slow valve) change nothing: the same drive without them gives the same lift."""
    shut = drive(Solenoid(20e-6, 0.5e6), Brake(2.5e-3, 0.5e-6, 20e-6))
    omega = 2 * math.pi * 100 / 60
    r = simulate(law, shut, omega)
    c = (shut.pump.volume + shut.actuator.volume) / shut.fluid.bulk_modulus + shut.pipe.area * shut.pipe.length / (
        shut.fluid.density * shut.wave_speed**2)
    k, f0 = shut.valve.spring_rate, shut.valve.preload
    closed = (PISTON * r.plunger_lift - c * (shut.back_pressure - shut.initial_pressure) - c * f0 / PISTON) / (
        PISTON + c * k / PISTON)
    open_ = closed > 1e-6
    error = np.abs(r.valve_lift[open_] - closed[open_]).max()
    assert error < 0.01 * r.lift_loss             # 0.8 um: the compression, 86 um of the rigid 9.25 mm, to 1 %
    assert r.bypassed_volume[-1] == 0.0 and np.all(r.solenoid_share == 0.0)
    free = simulate(law, drive(), omega)
    assert np.abs(free.valve_lift - r.valve_lift).max() < 1e-3 * closed.max()


@pytest.mark.parametrize("reaches", [2, 4])
def test_the_oil_circuit_conserves_its_volume(law, reaches):
    """Mass conservation of the oil circuit (linear compressibility): at every step the plunger's displaced volume
    A_p h equals the oil stored by compression in the chambers and the passage, the valve's A_a y, the volume let out
    by the leaks and the fill valve and the volume the solenoid let out to the accumulator; the passage's storage is
    summed on its grid, so the balance closes to that grid's error (1.4e-4 of the displaced volume at 2 reaches,
    halved at 4).  The solenoid's volume is its orifice flow at the pump chamber's pressure, summed over the steps."""
    d = drive(Solenoid(20e-6, 0.5e6, opens=RELEASE, stroke_time=1e-3), Brake(2.5e-3, 0.5e-6, 20e-6), 1e-13, 1e-9)
    d = HydraulicDrive(d.fluid, Pipe(0.03, 0.012, friction_factor=0.03, reaches=reaches), d.pump, d.actuator, d.valve,
                       d.initial_pressure, d.back_pressure, d.solenoid, d.brake)
    r = simulate(law, d, 2 * math.pi * 750 / 60)
    K, p0 = d.fluid.bulk_modulus, d.initial_pressure
    displaced = PISTON * r.plunger_lift
    stored = (d.pump.volume / K * (r.pump_pressure - p0) + d.actuator.volume / K * (r.actuator_pressure - p0)
              + r.pipe_stored_volume + PISTON * r.valve_lift + r.leaked_volume + r.bypassed_volume)
    assert not r.cavitation.any()
    assert np.abs(displaced - stored).max() < (1.5e-4 if reaches == 2 else 0.8e-4) * displaced.max()
    flow = orifice_flow(d.solenoid.area * r.solenoid_share, r.pump_pressure - d.solenoid.accumulator_pressure,
                        d.fluid.density, d.solenoid.discharge_coefficient)
    assert r.bypassed_volume == pytest.approx(np.cumsum(np.concatenate([[0.0], flow[1:]])) * r.time_step,
                                              rel=1e-9, abs=1e-9 * r.bypassed_volume.max())
    assert r.bypassed_volume.max() > 0.5 * PISTON * (r.plunger_lift.max() - law.lift(np.array([RELEASE]))[0])


@pytest.mark.parametrize("brake, tolerance", [(5.6, 4e-3), (800.0, 1e-4)])
def test_the_brake_lands_the_valve_at_the_hand_calculated_velocity(law, brake, tolerance):
    """Hand calculation: released at rest from the lift y_0 near the nose, a valve of mass M under the constant net
    force F = F_0 - (p_acc - p_back) A_a (no spring rate, no damping; the accumulator's pressure under its piston
    through a wide solenoid) against a brake of constant B (its orifice the same at every lift) obeys
    M v dv/dy = F - B v^2, so it lands at v = sqrt(F / B) sqrt(1 - exp(-2 B y_0 / M)): 4.41 m/s of a 4.73 m/s
    terminal velocity with B = 5.6 N s^2/m^2, the terminal 0.46 m/s with B = 800."""
    rho, cd, mass, preload = 870.0, 0.7, 0.1, 200.0
    area = math.sqrt(rho * PISTON**3 / (2 * cd**2 * brake))           # B = rho A_a^3 / (2 C_d^2 A^2)
    d = HydraulicDrive(Fluid(density=rho, bulk_modulus=1.5e9), Pipe(0.01, 0.03, reaches=1), Pump(PISTON, 2e-6),
                       Actuator(PISTON, 2e-6), Valve(mass, 0.0, preload), initial_pressure=0.3e6, back_pressure=0.1e6,
                       solenoid=Solenoid(5e-4, 0.3e6, opens=0.0), brake=Brake(1.0, area, area, cd))
    r = simulate(law, d, 2 * math.pi * 1500 / 60)
    i = np.searchsorted(r.angle, 0.0)
    y0, force = r.valve_lift[i], preload - (0.3e6 - 0.1e6) * PISTON
    assert abs(r.valve_velocity[i]) < 0.02                   # the nose: the valve is nearly at rest
    landing = -math.sqrt(force / brake) * math.sqrt(1.0 - math.exp(-2.0 * brake * y0 / mass))
    assert r.seating()[1] == pytest.approx(landing, rel=tolerance)


def test_the_brake_and_the_early_release_close_the_valve_early_and_softly(law):
    """The lost-motion drive's purpose: a solenoid opened before the nose closes the valve earlier than the cam and
    with less lift the earlier it opens, and the brake lands it at a fraction of the unbraked velocity."""
    omega = 2 * math.pi * 1500 / 60
    shut = simulate(law, drive(Solenoid(20e-6, 0.5e6)), omega)
    closings, lifts = [], []
    for release in (0.2, -0.2, -0.4):
        r = simulate(law, drive(Solenoid(20e-6, 0.5e6, opens=release, stroke_time=1e-3), Brake(2.5e-3, 0.5e-6,
                                                                                               20e-6)), omega)
        closings.append(r.seating()[0])
        lifts.append(r.valve_lift.max())
    assert shut.seating()[0] > closings[0] > closings[1] > closings[2]
    assert lifts[0] == pytest.approx(shut.valve_lift.max(), rel=1e-6) and lifts[0] > lifts[1] > lifts[2]
    free = simulate(law, drive(Solenoid(20e-6, 0.5e6, opens=-0.2, stroke_time=1e-3)), omega)
    braked = simulate(law, drive(Solenoid(20e-6, 0.5e6, opens=-0.2, stroke_time=1e-3), Brake(2.5e-3, 0.5e-6, 20e-6)),
                      omega)
    assert abs(braked.seating()[1]) < 0.2 * abs(free.seating()[1])
    assert braked.brake_pressure.max() > braked.actuator_pressure.max()


def test_a_solenoid_shut_late_opens_the_valve_late_and_lower(law):
    """Late opening: the solenoid valve open while the cam starts its lift lets the pump's oil out, so the valve stays
    on its seat; shut later, it lifts later and less, the lift lost the plunger's travel before the shutting (at the
    slow cam, quasi-statically: the valve's largest lift is the full lift less A_p / A_a times the plunger's lift where
    the solenoid valve has shut, to 2 % of that loss)."""
    omega = 2 * math.pi * 100 / 60
    full = simulate(law, drive(Solenoid(20e-6, 0.5e6)), omega)
    shut = -0.5
    late = simulate(law, drive(Solenoid(20e-6, 0.5e6, closes=shut)), omega)
    assert late.lift_off() > full.lift_off() and late.angle[late.lift_off()] > shut
    lost = law.lift(np.array([shut]))[0]                               # A_p / A_a = 1
    assert full.valve_lift.max() - late.valve_lift.max() == pytest.approx(lost, rel=0.02)
