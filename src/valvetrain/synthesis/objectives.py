"""What a cam synthesis maximises (:data:`OBJECTIVES`): the fullness or the time-area of the valve's lift, or a
figure of the breathing averaged over its conditions and curve speeds (:class:`BreathingObjective`, the breathing
of a point's law with every other valve the start's); the fullness of the polydyne that the article compares a
power-polynomial optimum with."""

from dataclasses import dataclass, replace

from .. import flow
from ..breathing import BreathingError
from ..design import breathing_view
from ..design.breathing import breathe_conditions, breathing_conditions, breathing_engine, speed_mean
from ..errors import InputError
from ..laws import PolydyneLaw
from ..specification.si import si
from ..units import to_display


OBJECTIVES = {
    "fullness": ("fullness", "", "fullness of the valve lift diagram (Shang Hanji (1988), eq. 2.3)"),
    "time_area": ("time_area_open", "mm2 s", "time-area of the valve's whole opening"),
    "volumetric_efficiency": ("volumetric_efficiency", "", "volumetric efficiency, the mean over the breathing's "
                              "conditions and curve speeds"),
    "torque": ("torque", "N m", "indicated torque of the fired engine, the mean over the breathing's conditions and "
               "curve speeds"),
}
"""Objective name -> (field of the flow stage's result, or of the breathing's records for :data:`BREATHING`,
display unit, what it is)."""

BREATHING = ("volumetric_efficiency", "torque")
"""The objectives of the breathing (:mod:`valvetrain.design.breathing`): the mean of a figure of its converged cycles
over every condition and curve speed of ``[breathing]``, each weighing the same."""


def objective_value(results, valve, objective) -> float:
    """An objective of :data:`OBJECTIVES` as ``valvetrain run`` computes it (``results``, a
    :class:`~valvetrain.design.DesignResults`), for the valve named ``valve``."""
    if objective in BREATHING:
        return speed_mean(results.breathing.conditions + results.breathing.curve, OBJECTIVES[objective][0])
    return float(getattr(results.valves[valve].flow, OBJECTIVES[objective][0]))


@dataclass(frozen=True)
class BreathingObjective:
    """What a cam synthesis by the breathing holds fixed: the SI views of ``[breathing]`` (its files read), of
    ``[engine]`` and ``[crank]`` (or None), the starting design's valves and their SI views, and the conditions and
    curve speeds (:func:`~valvetrain.design.breathing.breathing_conditions`)."""

    view: object
    engine: object
    crank: object
    valves: dict
    views: dict
    conditions: tuple

    def value(self, name, figure, law, valve) -> float:
        """The mean of the breathing's ``figure`` over the conditions with the valve ``name`` lifted by ``law`` (its
        SI view ``valve``), every other valve the start's: the valve's design with that law and nose in its cam
        stage gives the breathing its lift (:attr:`~valvetrain.design.valve.ValveDesign.cycle_lift`), as ``run``
        does; 0 where the cycle leaves the physical range (:class:`~valvetrain.breathing.BreathingError`)."""
        start = self.valves[name]
        cam = replace(start.cam, law=law, nose=valve.cam.section.nose_crank(valve, law),
                      rocker_ratio=valve.rocker_ratio)
        engines = breathing_engine(self.view, self.engine, self.crank, {**self.valves, name: replace(start, cam=cam)},
                                   {**self.views, name: valve}, [c for part in self.conditions for c in part])[0]
        try:
            conditions, curve = breathe_conditions(engines, self.view, *self.conditions)
        except BreathingError:
            return 0.0
        return speed_mean(conditions + curve, figure)


def check_breathing_objective(spec, valve, objective) -> None:
    """Refuse an objective of :data:`BREATHING` that the specification cannot give for the valve named ``valve``.

    Raises
    ------
    ValueError
        No ``[breathing]`` section; ``torque`` of a motored breathing; the valve's side lifted by a measured
        ``lift_file`` (the cam would not move the breathing): the message names the key.
    """
    if spec.breathing is None:
        raise InputError(f"optimize: --objective {objective} needs a [breathing] section (its conditions or curve "
                         "give the speeds); allowed without it: fullness, time_area")
    if objective == "torque" and spec.breathing.mode != "fired":
        raise InputError(f"optimize: --objective torque needs breathing.mode = 'fired' (the file's is "
                         f"{spec.breathing.mode!r}: a motored engine gives no torque); allowed volumetric_efficiency")
    kind = spec.valves[valve].kind
    if getattr(spec.breathing, kind).lift_file is not None:
        raise InputError(f"optimize: --objective {objective}: breathing.{kind}.lift_file lifts the {kind} valves by a "
                         f"measured table, so valve {valve!r}'s cam does not move the breathing; allowed without "
                         "lift_file (the designed valves' lift)")


def breathing_objective(spec, results) -> BreathingObjective:
    """The :class:`BreathingObjective` of a specification and its starting design ``results``."""
    view = breathing_view(spec)
    views = {name: si(section, spec) for name, section in spec.valves.items()}
    crank = None if spec.crank is None else si(spec.crank, spec)
    return BreathingObjective(view, si(spec.engine), crank, dict(results.valves), views,
                              breathing_conditions(view))


def shown_objective(objective, value) -> float:
    """An objective's value (SI) in its display unit (:data:`OBJECTIVES`)."""
    return to_display(value, OBJECTIVES[objective][1])


def polydyne_fullness(law, exponents=(10, 18, 26, 34)) -> float:
    """Fullness of the polydyne (2, p, q, r, s) with the same lift, cosine ramp of the same height and end velocity
    and the same main angle as a power-polynomial ``law``, on the same definition (tappet lift over the valve-open
    part): the serial-type reference of the comparison.

    References
    ----------
    Valve-train practical works (n.d.), work 3 (the polydyne); UkrSURT Proceedings (2019) (the comparison).
    """
    poly = PolydyneLaw(law.lift_max, law.main_half_angle, *exponents, ramp_height=law.ramp_height,
                       ramp_velocity=law.v_qb)
    return flow.fullness(poly.lift, poly.valve_opens, poly.valve_closes, poly.lift_max + poly.ramp_height,
                         poly.breakpoints)
