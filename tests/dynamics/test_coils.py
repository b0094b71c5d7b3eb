"""The coil-mass spring (dynamics/coils.py): its surge frequencies against an eigen-solution of the assembled chain and
against the wave equation of the coil."""

import numpy as np
import pytest

from valvetrain.dynamics.coils import CoilSpring


def test_surge_frequencies_are_the_assembled_chains_eigenvalues():
    """N masses m_s / (N + 1) on N + 1 segments of (N + 1) K between fixed ends: the eigenvalues of the chain's stiffness and mass matrices, assembled
    here (numpy's symmetric eigen-solver, independent of the closed form the class uses)."""
    spring = CoilSpring(rate=38e3, preload=300.0, mass=0.045, coils=8)
    n = spring.coils
    k, m = (n + 1) * spring.rate, spring.mass / (n + 1)
    stiffness = k * (2.0 * np.eye(n) - np.eye(n, k=1) - np.eye(n, k=-1))
    omega = np.sqrt(np.linalg.eigvalsh(stiffness / m))
    assert [spring.surge_frequency(j) for j in range(1, n + 1)] == pytest.approx(omega, rel=1e-12)


def test_many_coil_masses_tend_to_the_wave_equations_surge():
    """omega_c1 = pi sqrt(K / m_s), the first surge mode of a spring fixed at both ends (Valve-train practical works
    (n.d.), eq. 6.13); the chain of N masses is short of it by about pi^2 / (24 (N + 1)^2)."""
    rate, mass = 38e3, 0.045
    exact = np.pi * np.sqrt(rate / mass)
    for n, error in ((8, 1e-2), (400, 1e-5)):
        assert CoilSpring(rate, 300.0, mass, coils=n).surge_frequency() == pytest.approx(exact, rel=error)
    assert CoilSpring(rate, 300.0, mass, coils=400).surge_frequency() < exact
