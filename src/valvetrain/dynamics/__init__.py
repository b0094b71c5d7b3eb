"""Elastic valve-train dynamics: one-mass and multi-mass models, speed sweeps, Valve-train dynamics article (n.d.) resonance,
the perturbation parameter and the outer solution (Shang Hanji (1988), chapter 3)."""
