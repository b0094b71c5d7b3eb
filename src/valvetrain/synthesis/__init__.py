"""Cam synthesis: design constraints as functions of a computed design (:mod:`.constraints`) and the optimiser
(:mod:`.optimize`): its variables (:mod:`.variables`), objectives (:mod:`.objectives`) and one evaluation of a point
or a population (:mod:`.problem`).

The optimiser takes its design variables as specification keys and evaluates a point fast: it samples the law on a
grid and around its extremes (the objective by the flow module's quadrature, the margins on the refined contour, the
spring's required force in closed form, the one-mass dynamics only where it can change the best point).
Differential evolution runs over the whole population as one batch (the laws of a population sampled together by
``laws.base.batch_derivatives``), then a polish, then the full designs of the best points until one meets every
limit.  It sits on :mod:`valvetrain.design`, the specification and the physics; the report's
:mod:`valvetrain.report.optimization` and the command line import it.
"""
