"""Compressible flow through a restriction (valvetrain.breathing.orifice) against the isentropic nozzle written with
the Mach number (an independent form of the same physics, Anderson, Modern Compressible Flow, eqs. 3.28-3.31)."""

import numpy as np
import pytest

from valvetrain.breathing import orifice

R, GAMMA = 287.0, 1.4


def _by_mach(p0, t0, p, gamma=GAMMA, r=R):
    """Mass flux of the isentropic nozzle at the throat pressure max(p, p*), through the Mach number."""
    ratio = max(p / p0, (2.0 / (gamma + 1.0)) ** (gamma / (gamma - 1.0)))
    mach = np.sqrt(2.0 / (gamma - 1.0) * (ratio ** (-(gamma - 1.0) / gamma) - 1.0))
    t = t0 / (1.0 + 0.5 * (gamma - 1.0) * mach**2)
    return p0 * ratio / (r * t) * mach * np.sqrt(gamma * r * t)


@pytest.mark.parametrize("ratio", [0.99, 0.9, 0.7, 0.6, 0.5283, 0.4, 0.1])
def test_flux_against_the_mach_number_form(ratio):
    """Choked and unchoked: the orifice's flux equals the nozzle's through the Mach number (to 1e-12)."""
    assert orifice.mass_flux(2e5, 350.0, 2e5 * ratio, GAMMA, R) == pytest.approx(_by_mach(2e5, 350.0, 2e5 * ratio),
                                                                                  rel=1e-12)


def test_choked_closed_form():
    """Below the critical ratio 0.5283 (gamma 1.4) the flux is the choked closed form, whatever the back pressure."""
    assert orifice.critical_pressure_ratio(1.4) == pytest.approx(0.528281788, rel=1e-9)
    choked = orifice.choked_mass_flux(5e5, 900.0, 1.33, 290.0)
    for back in (1e5, 2e5, 2.6e5):
        assert orifice.mass_flux(5e5, 900.0, back, 1.33, 290.0) == pytest.approx(choked, rel=1e-12)


def test_no_flow_against_the_pressure_and_reverse_flow():
    """No flow from the lower to the higher pressure; the signed flow reverses with the pressures, through the reverse
    area."""
    assert orifice.mass_flux(1e5, 300.0, 1.2e5, GAMMA, R) == 0.0
    forward = orifice.mass_flow(1e-4, 2e-4, 1.5e5, 300.0, 1e5, 300.0, GAMMA, GAMMA, R, R)
    backward = orifice.mass_flow(1e-4, 2e-4, 1e5, 300.0, 1.5e5, 300.0, GAMMA, GAMMA, R, R)
    assert forward > 0 and backward == pytest.approx(-2.0 * forward, rel=1e-12)
