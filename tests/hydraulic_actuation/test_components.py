"""The components of hydraulic valve actuation (valvetrain.hydraulic_actuation.components): the wave speed of the
oil in a rigid and in an elastic pipe against its closed forms."""

import math

import pytest

from valvetrain.hydraulic_actuation import wave_speed


def test_wave_speed_korteweg():
    """Analytic identities: a rigid pipe carries sound at sqrt(K / rho); the Korteweg formula for the wall."""
    assert wave_speed(1.5e9, 870.0) == pytest.approx(math.sqrt(1.5e9 / 870.0), rel=1e-15)
    K, rho, d, e, E = 1.5e9, 870.0, 0.02, 0.003, 210e9
    assert wave_speed(K, rho, d, e, E) == pytest.approx(math.sqrt(K / rho / (1 + K * d / (E * e))), rel=1e-15)
    assert wave_speed(K, rho, d, e, E) < wave_speed(K, rho)
