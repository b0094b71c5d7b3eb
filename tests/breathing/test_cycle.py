"""The converged cycle (valvetrain.breathing.cycle): the energy balance of cylinder and runners closes to round-off,
the pumping loop of unrestricted valves is p_e - p_i (Heywood (1988), section 5.4, the ideal cycle's pumping work),
the runners' grid converges, a fired cycle delivers torque; events the cycle cannot hold are refused."""

import numpy as np
import pytest

from valvetrain.breathing import cycle as C

CYLINDER = C.Cylinder(0.086, 0.086, 0.145, 10.0)


def _flow(opens, closes, diameter=0.034, lift=0.009, cd=0.6):
    """A cosine lift from ``opens`` to ``closes`` [crank deg] through a curtain of C_D 0.6."""
    theta = np.radians(np.arange(0.0, 720.0, 0.25))
    rel = np.mod(np.degrees(theta) - opens, 720.0)
    span = (closes - opens) % 720.0
    h = np.where(rel < span, 0.5 * lift * (1.0 - np.cos(2.0 * np.pi * rel / span)), 0.0)
    area = cd * np.pi * diameter * h
    return C.ValveFlow(theta, area, area)


INTAKE, EXHAUST = _flow(-10.0, 230.0), _flow(490.0, 10.0)
RUNNERS = C.Runner(0.35, 0.036), C.Runner(0.3, 0.034)


def _condition(rpm, p_i=100e3, p_e=105e3):
    return C.Condition(rpm * np.pi / 30.0, C.Plenum(p_i, 300.0), C.Plenum(p_e), 400.0)


FIRING = C.Firing("isooctane", 1.0, np.radians(-20.0), np.radians(55.0))


@pytest.mark.parametrize("firing", [None, FIRING])
def test_energy_balance_closes(firing):
    """The last cycle's energy balance (cylinder and runners: plenums' flows, piston work, wall heat, heat release)
    closes to 1e-12 of the energy that crossed it; the cycles repeat within the tolerance."""
    result = C.breathe(C.Engine(CYLINDER, INTAKE, EXHAUST, *RUNNERS, firing=firing), _condition(3000))
    f = result.figures
    assert result.converged and f.cycle_change < C.TOLERANCE
    assert abs(f.energy_balance) < 1e-12
    assert f.imep == pytest.approx(f.imep_gross - f.pmep, rel=1e-12)


def test_unrestricted_pumping_loop():
    """Valves of 50 times the area, no runners, adiabatic, slow: the pumping mean effective pressure tends to
    p_e - p_i = 40 kPa of the ideal throttled cycle (within 1 %)."""
    wide = [C.ValveFlow(f.angle, 50 * f.forward, 50 * f.reverse) for f in (INTAKE, EXHAUST)]
    result = C.breathe(C.Engine(CYLINDER, *wide, heat_transfer=False), _condition(600, 60e3, 100e3))
    assert result.figures.pmep == pytest.approx(40e3, rel=0.01)


def test_runner_grid_converges():
    """Halving the cells four times moves the volumetric efficiency by under 0.2 % at 6000 rpm."""
    results = [C.breathe(C.Engine(CYLINDER, INTAKE, EXHAUST, C.Runner(0.35, 0.036, cell), C.Runner(0.3, 0.034, cell)),
                         _condition(6000)).figures.volumetric_efficiency for cell in (0.04, 0.0025)]
    assert results[0] == pytest.approx(results[1], rel=2e-3)


def test_fired_cycle():
    """Stoichiometric iso-octane at 3000 rpm: positive torque and power, the peak after the firing TDC, burned gas as
    residual (a few per cent), hot exhaust."""
    f = C.breathe(C.Engine(CYLINDER, INTAKE, EXHAUST, *RUNNERS, firing=FIRING), _condition(3000)).figures
    assert f.torque > 0 and f.power == pytest.approx(f.torque * 3000 * np.pi / 30)
    assert 360.0 < np.degrees(f.peak_pressure_angle) < 390.0
    assert 0.01 < f.residual_gas_fraction < 0.15
    assert 800.0 < f.exhaust_temperature < 1600.0


def test_events_the_cycle_cannot_hold():
    with pytest.raises(C.BreathingError, match="closed cycle must hold the firing TDC"):
        C.breathe(C.Engine(CYLINDER, _flow(300.0, 400.0), EXHAUST), _condition(2000))
    late = C.Firing("isooctane", 1.0, np.radians(60.0), np.radians(90.0))
    with pytest.raises(C.BreathingError, match="combustion from 420 to 510 crank deg"):
        C.breathe(C.Engine(CYLINDER, INTAKE, EXHAUST, firing=late), _condition(2000))


def test_a_valve_that_bounces_off_its_seat():
    """An intake valve that opens again after its closing (a bounce, 250-260 deg) closes the cycle at its last
    closing: the trapped mass is the cylinder's there.  The same bounce during combustion (370-380 deg) is refused
    for a fired cycle (both valves shut from the intake's closing to the exhaust's opening), motored it only flows."""
    bounce = _flow(250.0, 260.0, lift=20e-6)
    twice = C.ValveFlow(INTAKE.angle, INTAKE.forward + bounce.forward, INTAKE.reverse + bounce.reverse)
    r = C.breathe(C.Engine(CYLINDER, twice, EXHAUST), _condition(3000))
    closing = np.argmin(np.abs(np.degrees(r.columns.angle) - 260.0))
    assert r.figures.trapped_mass == pytest.approx(r.columns.mass[closing], rel=1e-9)
    late = _flow(370.0, 380.0, lift=20e-6)
    during = C.ValveFlow(INTAKE.angle, INTAKE.forward + late.forward, INTAKE.reverse + late.reverse)
    assert C.breathe(C.Engine(CYLINDER, during, EXHAUST), _condition(3000)).converged
    with pytest.raises(C.BreathingError, match="both valves shut between them"):
        C.breathe(C.Engine(CYLINDER, during, EXHAUST, firing=FIRING), _condition(3000))
