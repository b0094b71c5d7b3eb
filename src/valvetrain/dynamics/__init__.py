"""Elastic valve-train dynamics: one-mass and multi-mass models, speed sweeps, Valve-train dynamics article (n.d.) resonance,
the perturbation parameter and the outer solution (Shang Hanji (1988), chapter 3).

* :mod:`.coils`: a valve spring as a chain of coil masses (the multi-mass trains');
* :mod:`.models`: the trains (one-mass; multi-mass with coil masses; ``VariableMass``, a node whose mass changes
  with its lift, a finger's J / G^2 with the velocity-squared force of Lagrange's equation; ``Adjuster``, a hydraulic
  lash adjuster's plunger carried from revolution to revolution) and ``build_train``;
* :mod:`.kernels`: the compiled (numba) integration of a revolution;
* :mod:`.sweep`: speed sweeps (the full grid, or ``headline_sweep``: the speeds that decide the jump speed, the
  largest seating velocity and the largest cam force, for the samples of a tolerance study);
* :mod:`.events`: the events of a recorded revolution (seating, separation, bounce; every speed's at once as numpy
  arrays, ``SweepResult.events``) and the speeds where a sweep's events start;
* :mod:`.accuracy`: error control: the speeds that decide the jump speed, the bounce onset and the seating velocity
  simulated again at halved steps until each settles, with the estimated error of each;
* :mod:`.perturbation`, :mod:`.resonance`, :mod:`.contact`.
"""
