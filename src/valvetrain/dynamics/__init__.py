"""Elastic valve-train dynamics: one-mass and multi-mass models, speed sweeps, seed 003 resonance,
the perturbation parameter and the outer solution (seed 002, chapter 3; spec/methods-seeds-002-004.md,
sections 2, 12 and 16)."""
