"""valvetrain: design calculation of internal-combustion-engine valve trains.

Three layers:

* physics functions: :mod:`valvetrain.flow`, :mod:`valvetrain.geometry`, :mod:`valvetrain.springs`,
  :mod:`valvetrain.strength`, :mod:`valvetrain.crank`, :mod:`valvetrain.dynamics` (pure, vectorised, SI units);
* objects: the lift laws of :mod:`valvetrain.laws` (:class:`KurzLaw`, :class:`PolydyneLaw`, ...);
* orchestration and edges: :mod:`valvetrain.specification` (the validated TOML specification and its SI
  view), :mod:`valvetrain.design` (the stages and :func:`run`), :mod:`valvetrain.export`,
  :mod:`valvetrain.report`, :mod:`valvetrain.cli`.

In a notebook::

    import valvetrain as vt
    spec = vt.load_spec("my-engine.toml")      # or vt.example_spec()
    results = vt.run(spec)                     # a DesignResults: results.valves["intake"].flow.time_area, ...
    results                                    # a summary table
"""

__version__ = "0.1.0"

from .checks import Check  # noqa: E402
from .design import (DesignResults, ValveDesign, clearance_stage, design_valve, flow_stage, law_stage,  # noqa: E402
                     profile_stage, run, valve_checks)
from .laws import (AsymmetricLaw, CombinedLaw, ConstantAccelerationLaw, DynamicLaw, HarmonicLaw, KurzLaw,  # noqa: E402
                   LiftLaw, PolydyneLaw, PolynomialLaw, TangentLaw, ThreeArcLaw)
from .specification import SpecError, example_spec, load_spec, parse_spec, si  # noqa: E402

__all__ = [
    "AsymmetricLaw", "Check", "CombinedLaw", "ConstantAccelerationLaw", "DesignResults", "DynamicLaw", "HarmonicLaw",
    "KurzLaw", "LiftLaw", "PolydyneLaw", "PolynomialLaw", "SpecError", "TangentLaw", "ThreeArcLaw", "ValveDesign",
    "clearance_stage", "design_valve", "example_spec", "flow_stage", "law_stage", "load_spec", "parse_spec",
    "profile_stage", "run", "si", "valve_checks",
]
