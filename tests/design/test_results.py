"""The results are frozen and typed: no stage result can be changed after :func:`valvetrain.run`, results.json's
dictionary is made once, every field has a precise type, and the public functions and the stages say what they
return."""

import dataclasses
import importlib
import inspect
import pkgutil
import typing

import numpy as np
import pytest

from conftest import plain
import valvetrain
from valvetrain import results as machinery
from valvetrain.design import results as declared, run
from valvetrain.design.camcard import CamCardValve

from appendix import appendix_spec

DESIGN_MODULES = ["valvetrain.design", "valvetrain.design.valve", "valvetrain.design.valve_checks",
                  "valvetrain.design.drive", "valvetrain.design.drive_strength", "valvetrain.design.crank",
                  "valvetrain.design.twostroke", "valvetrain.design.dynamics", "valvetrain.design.dynamics_records",
                  "valvetrain.design.dynamics_checks", "valvetrain.design.grinding",
                  "valvetrain.design.hydraulic_actuation", "valvetrain.design.results",
                  "valvetrain.design.lubrication", "valvetrain.design.lash_adjuster",
                  "valvetrain.design.camcard", "valvetrain.results", "valvetrain.laws.records"]


def _defined(kind, modules=DESIGN_MODULES):
    for name in modules:
        module = importlib.import_module(name)
        for attr, obj in vars(module).items():
            if kind(obj) and obj.__module__ == name and not attr.startswith("_"):
                yield f"{name}.{attr}", obj


def _every_module():
    """Every module of the package (the physics, the laws, the report, the command line ...), but ``__main__``."""
    found = pkgutil.walk_packages(valvetrain.__path__, "valvetrain.")
    return ["valvetrain"] + sorted(m.name for m in found if not m.name.endswith("__main__"))


def _public_functions():
    public = {f"valvetrain.{n}": getattr(valvetrain, n) for n in valvetrain.__all__}
    return {**{k: f for k, f in public.items() if inspect.isfunction(f)},
            **dict(_defined(inspect.isfunction, _every_module()))}


@pytest.fixture(scope="module")
def results():
    return run(appendix_spec())


def test_the_public_functions_and_the_stages_say_what_they_return():
    """Every public function of every module (no leading underscore, defined in that module): about 400 of the
    physics modules had none."""
    functions = _public_functions()
    assert {"valvetrain.flow.fullness", "valvetrain.springs.formulas.wahl_factor", "valvetrain.crank.torque.is_even",
            "valvetrain.report.html.render_report", "valvetrain.specification.fields.Length"} <= set(functions)
    missing = [name for name, f in functions.items()
               if inspect.signature(f).return_annotation is inspect.Signature.empty]
    assert not missing, missing
    for f in _public_functions().values():
        typing.get_type_hints(f)            # every annotation names a type that exists


def _loose(t):
    """A type that says nothing of what it holds: object, or a bare dict, list or tuple (also inside Optional)."""
    return t in (object, dict, list, tuple) or any(_loose(a) for a in typing.get_args(t))


def test_every_result_is_frozen_and_precisely_typed():
    for name, cls in _defined(lambda o: inspect.isclass(o) and dataclasses.is_dataclass(o)):
        assert cls.__dataclass_params__.frozen, name
        loose = {f: t for f, t in typing.get_type_hints(cls).items() if _loose(t)}
        assert not loose, (name, loose)


def test_results_cannot_be_changed(results):
    """run() used to assign each valve's checks after the acceptances (ValveDesign was mutable)."""
    v = results.valves["intake"]
    with pytest.raises(dataclasses.FrozenInstanceError):
        v.checks = ()
    with pytest.raises(dataclasses.FrozenInstanceError):
        results.checks = ()
    assert isinstance(results.checks, tuple) and isinstance(v.checks, tuple)


def test_the_json_projection_is_made_once(results):
    assert results.to_dict() is results.to_dict()
    v = results.valves["intake"]
    assert v.summary is v.summary
    assert results.to_dict()["valves"]["intake"] is v.summary


def test_figure_data_are_plain_series(results):
    """The data of each separated figure are numbers and arrays, and its drawing takes them alone."""
    from matplotlib.figure import Figure

    from valvetrain.report import engine_plots, plots
    from valvetrain.report.i18n import TEXT

    v = results.valves["intake"]
    made = [(plots.kinematics_data(v), plots.draw_kinematics), (plots.time_area_data(v), plots.draw_time_area),
            (plots.spring_data(v), plots.draw_spring), (plots.strength_speed_data(v), plots.draw_strength_speed),
            (plots.timing_data(results.valves), plots.draw_timing), (plots.contour_data(v), plots.draw_contour),
            (plots.curvature_data(v), plots.draw_curvature),
            (engine_plots.crank_forces_data(results.crank), engine_plots.draw_crank_forces),
            (engine_plots.crank_torque_data(results.crank), engine_plots.draw_crank_torque),
            (engine_plots.crank_pin_data(results.crank), engine_plots.draw_crank_pin)]
    for data, draw in made:
        assert plain(data), draw.__name__
        assert isinstance(draw(data, TEXT["en"]), Figure)
    # the series are those of the results: the time-area plot's stroke is results.json's
    assert plots.time_area_data(v)["stroke_crank_deg"] == results.to_dict()["valves"]["intake"]["flow"]["stroke_crank_deg"]


def test_the_stages_declare_their_results_with_the_package_s_machinery():
    """valvetrain.design.results is valvetrain.results for the stages: the same objects, and a stage's record comes
    out in its display units (a cam card line: -pi/18 rad is -10 crank deg, 0.170371e-3 m is 0.170371 mm)."""
    assert all(getattr(declared, name) is getattr(machinery, name) for name in declared.__all__)
    line = declared.record(CamCardValve(*[-np.pi / 18] * 10, 0.170371e-3))
    assert line["seat_opens_crank_deg"] == pytest.approx(-10.0) and line["lift_at_tdc_mm"] == pytest.approx(0.170371)

