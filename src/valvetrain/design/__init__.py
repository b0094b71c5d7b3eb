"""Orchestration: ``run(spec) -> DesignResults``, the chain of stages of a design.

This package is the one place where the specification's engineering units (mm, deg,
rpm) are converted to SI for the physics functions.  Stages:

* per valve (:mod:`.valve`, :mod:`.drive`): flow sections and conditional velocities
  (seed 000 work 1), the lift law (works 2-3), time-area and fullness (work 4, seed 002),
  the cam contour (seed 002 section 2.1), masses and springs (works 5-6), strength (work 7);
* the crank mechanism (:mod:`.crank`): kinematics, forces and torque, multi-cylinder torque (seed 001);
* two-stroke ports (:mod:`.twostroke`): timing, areas, time-area (seed 000 work 8);
* recommended-range checks of every stage (warnings, never exceptions).
"""

from dataclasses import dataclass

from .. import flow
from ..checks import check, failed
from ..crank.pressure import PressureFileError
from ..files import TableFileError
from ..specification import SpecError, si
from ..units import MM
from .crank import CrankResults, crank_stage
from .twostroke import TwoStrokeResults, two_stroke_stage
from .valve import (THROAT_AREA_SHARE_RANGE, ValveDesign, clearance_stage, design_valve, flow_stage, law_stage,
                    profile_stage, valve_checks)

__all__ = ["DesignResults", "ValveDesign", "clearance_stage", "design_valve", "flow_stage", "law_stage", "profile_stage", "run",
           "valve_checks"]


@dataclass(repr=False)
class DesignResults:
    """Result of :func:`run`: the engine's derived figures, each valve's design, all warnings."""

    spec: object
    engine: dict
    valves: dict
    checks: list                  # every valvetrain.checks.Check of the design, passed or not
    crank: CrankResults = None
    two_stroke: TwoStrokeResults = None

    @property
    def warnings(self):
        """The checks that fail, in the order of the chapters."""
        return failed(self.checks)

    def _rows(self):
        """One line of figures per valve: name, law, valve lift, time-area, fullness, spring, failed checks."""
        for name, v in self.valves.items():
            spring = v.drive.spring
            yield (name, v.law.name, f"{v.flow.valve_lift / MM:.4g}", f"{v.flow.time_area / MM**2:.4g}",
                   f"{v.flow.fullness:.4g}", f"{spring['wire_mm']:g} x {spring['mean_diameter_mm']:g}",
                   f"{len(v.warnings)} of {len(v.checks)}")

    _HEADS = ("valve", "law", "lift, mm", "time-area, mm2 s", "fullness", "spring wire x D, mm", "checks failed")

    def __repr__(self):
        e = self.engine
        lines = [f"DesignResults: {e['name']} ({e['cylinders']} cyl., {e['bore_mm']:g} x {e['stroke_mm']:g} mm, "
                 f"{e['rated_speed_rpm']:g} rpm), {len(self.warnings)} of {len(self.checks)} checks fail"]
        lines += ["  " + ", ".join(f"{h} {c}" for h, c in zip(self._HEADS, row, strict=True)) for row in self._rows()]
        if self.crank is not None:
            lines.append(f"  crank: mean torque {self.crank.figures.mean_torque:.4g} N m")
        return "\n".join(lines)

    def _repr_html_(self):
        """A summary table for notebooks: the valves' figures and the checks that fail."""
        from html import escape

        def table(heads, rows):
            head = "".join(f"<th>{escape(h)}</th>" for h in heads)
            body = "".join("<tr>" + "".join(f"<td>{escape(str(c))}</td>" for c in r) + "</tr>" for r in rows)
            return f"<table><tr>{head}</tr>{body}</table>"

        warnings = [(w.quantity, f"{w.shown_value:.6g} {w.unit}", w.range, w.source) for w in self.warnings]
        return (f"<p><b>{escape(self.engine['name'])}</b></p>" + table(self._HEADS, self._rows())
                + "<p>Checks that fail</p>" + table(("quantity", "value", "allowed", "source"), warnings))

    def to_dict(self):
        """JSON-ready dictionary (engineering units, named in the keys)."""
        from .. import __version__

        out = {
            "valvetrain_version": __version__,
            "engine": self.engine,
            "valves": {name: v.summary for name, v in self.valves.items()},
        }
        if self.crank is not None:
            out["crank"] = self.crank.summary
        if self.two_stroke is not None:
            out["two_stroke"] = self.two_stroke.summary
        out["warnings"] = [w.warning() for w in self.warnings]
        out["checks"] = [c.as_dict() for c in self.checks]
        return out


def run(spec, laws=None):
    """Run the whole design of a validated specification.

    Parameters
    ----------
    spec : valvetrain.specification.Spec
    laws : dict, optional
        ``valve name -> LiftLaw``: enter those valves' designs with a law of the caller's own.

    Returns
    -------
    DesignResults

    Raises
    ------
    SpecError
        Inputs that admit no design (a cam the law cannot make, a file that cannot be read, no spring that
        fits), one message per problem of every valve.
    """
    engine, gas, output = si(spec.engine), si(spec.gas), si(spec.output)
    valves, problems = {}, []
    for name, v in spec.valves.items():
        try:
            valve = si(v, spec)
        except (TableFileError, PressureFileError) as exc:
            problems.append(f"valves.{name}.cam.table_file: {exc}")
            continue
        try:
            valves[name] = design_valve(name, valve, engine, gas, output, (laws or {}).get(name))
        except SpecError as err:
            problems += err.problems
    if problems:
        raise SpecError(problems)
    found = [c for v in valves.values() for c in v.checks]
    if {v.kind for v in valves.values()} == {"intake", "exhaust"}:
        share = sum(v.count * v.flow.throat_area for v in valves.values())
        found.append(check("sum of throat areas / piston area", share / float(flow.circle_area(engine.bore)),
                           *THROAT_AREA_SHARE_RANGE, source="seed 000, work 1"))
    crank_view = None
    if spec.crank is not None:
        try:
            crank_view = si(spec.crank, spec)
        except PressureFileError as exc:
            raise SpecError([f"crank.pressure_file: {exc}"]) from None
    crank = crank_stage(crank_view, engine) if crank_view is not None else None
    ports = two_stroke_stage(si(spec.two_stroke), crank_view, engine) if spec.two_stroke is not None else None
    for stage, tag in ((crank, "crank"), (ports, "two-stroke")):
        if stage is not None:
            found += [c.named(tag) for c in stage.checks]
    return DesignResults(spec, engine_record(spec.engine), valves, found, crank, ports)


def engine_record(eng):
    """The engine's figures in results.json: its data and the mean piston speed, swept volume and piston area."""
    bore, stroke = eng.bore_mm * MM, eng.stroke_mm * MM
    return {
        "name": eng.name,
        "bore_mm": eng.bore_mm,
        "stroke_mm": eng.stroke_mm,
        "rated_speed_rpm": eng.rated_speed_rpm,
        "cylinders": eng.cylinders,
        "strokes": eng.strokes,
        "mean_piston_speed_m_s": flow.mean_piston_speed(stroke, eng.rated_speed_rpm),
        "swept_volume_cm3": float(flow.swept_volume(bore, stroke)) * 1e6,
        "displacement_cm3": float(flow.swept_volume(bore, stroke)) * 1e6 * eng.cylinders,
        "piston_area_mm2": float(flow.circle_area(bore)) / MM**2,
    }
