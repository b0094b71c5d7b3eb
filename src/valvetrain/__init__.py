"""valvetrain: design calculation of internal-combustion-engine valve trains.

Three layers:

* physics functions: :mod:`valvetrain.flow`, :mod:`valvetrain.geometry`, :mod:`valvetrain.springs`,
  :mod:`valvetrain.strength`, :mod:`valvetrain.crank`, :mod:`valvetrain.dynamics`,
  :mod:`valvetrain.cam_grinding`, :mod:`valvetrain.hydraulic_actuation`, :mod:`valvetrain.layouts` (pure,
  vectorised, SI units);
* objects: the lift laws of :mod:`valvetrain.laws` (:class:`KurzLaw`, :class:`PolydyneLaw`, ...) and the followers
  of :mod:`valvetrain.followers` (flat, roller);
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

_PUBLIC = {
    "Check": "checks",
    **dict.fromkeys(["DesignResults", "ValveDesign", "clearance_stage", "design_valve", "flow_stage", "law_stage",
                     "profile_stage", "run", "valve_checks"], "design"),
    "grinding_stage": "design.grinding",
    "hydraulic_stage": "design.hydraulic_actuation",
    **dict.fromkeys(["AsymmetricLaw", "CombinedLaw", "ConstantAccelerationLaw", "DynamicLaw", "HarmonicLaw", "KurzLaw",
                     "LiftLaw", "PolydyneLaw", "PolynomialLaw", "TangentLaw", "ThreeArcLaw"], "laws"),
    **dict.fromkeys(["SpecError", "example_spec", "load_spec", "parse_spec", "si"], "specification"),
}
"""The public names and the module each comes from: imported when first used (PEP 562), so that ``import
valvetrain`` and the command line start without loading the whole package."""

__all__ = sorted(_PUBLIC)


def __getattr__(name):
    if name not in _PUBLIC:
        raise AttributeError(f"module 'valvetrain' has no attribute {name!r}")
    from importlib import import_module

    return getattr(import_module(f".{_PUBLIC[name]}", __name__), name)


def __dir__():
    return sorted(set(globals()) | set(_PUBLIC))
