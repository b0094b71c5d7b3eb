"""valvetrain: design calculation of internal-combustion-engine valve trains.

Three layers (see DESIGN.md in the project's shared folder):

* physics functions: :mod:`valvetrain.flow`, :mod:`valvetrain.geometry`,
  :mod:`valvetrain.laws`, :mod:`valvetrain.crank` (pure, vectorised, SI units);
* objects: the lift laws (:class:`~valvetrain.laws.KurzLaw`,
  :class:`~valvetrain.laws.PolydyneLaw`) and the sampled results;
* orchestration and edges: :mod:`valvetrain.specification` (validated TOML design
  specification), :func:`valvetrain.design.run`, :mod:`valvetrain.export`,
  :mod:`valvetrain.report`, :mod:`valvetrain.cli`.
"""

__version__ = "0.1.0"
