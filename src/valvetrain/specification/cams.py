"""The cam section of a valve, ``[valves.NAME.cam]``: one model per lift law, the registry of the laws.

Each model is the single place where its law meets the specification: its keys (pydantic
fields, with the allowed ranges), the cross-checks of its angles against the valve's timing
(:meth:`problems`), the law it builds in SI (:meth:`build`, the law's constructor holding the
parameter rules), and what it adds to the results (:meth:`records`, :meth:`nose_crank`,
:meth:`timing`).  Adding a law means adding its module under :mod:`valvetrain.laws` and its
model here, decorated with :func:`.cam_base.register`.

``build`` receives the valve's SI view (:func:`valvetrain.specification.si.si`), whose ``cam`` is the
cam's own SI view, and the engine's.  Tappet-side lifts: the valve lift divided by the rocker
ratio.  Timing angles are crank angles, segment angles camshaft angles.
"""

from typing import Annotated, ClassVar, Literal, Optional, Union

import numpy as np
from pydantic import Field, model_validator

from ..checks import check
from ..errors import InputError
from ..files import LIFT_TABLE_RANGES, read_lift_table, shown_path
from ..followers import REGISTRY as FOLLOWERS
from ..laws import (CombinedLaw, ConstantAccelerationLaw, DynamicLaw, HarmonicLaw, KurzLaw, LiftLaw,
                    PolydyneLaw, PolynomialLaw, PowerPolynomialLaw, TangentLaw, ThreeArcLaw)
from ..laws.power_polynomial import ARTICLE_EXPONENTS
from ..laws.measured import CHECKING_HEIGHTS_MM, MIN_VALVE_LIFT_MM, TableLaw, lobe_table, table_accuracy
from ..laws.records import Duration, FitQuality, LawRecord, MeasuredRecord, PowerPolynomialRecord, SeedFormulas
from ..laws.takeup import ClearanceTakeUp
from ..locale import NoteText, cited, note, note_of
from ..layouts import train_mass
from ..locale.wording import fit_reason
from ..units import DEG, MM, rad_to_deg
from .fields import RAMP_VELOCITY, SEGMENT_ANGLE, Length, _bounded, Whole, _Model
from .messages import Problem, said, shown

from .cam_base import (REGISTRY, register, main_half_angle, main_half_angle_deg, _finite, _CamBase, _tappet_lift, _ramp, ramp_height, _clearance_problem, _RampKeys, _ClosingSide, _with_cam, _SegmentAngles)


@register
class KurzCam(_SegmentAngles, _CamBase, _RampKeys):
    """[valves.NAME.cam] with law = "kurz" (Valve-train practical works (n.d.), work 2)."""

    law: Literal["kurz"]
    ramp_end_velocity_mm_per_deg: RAMP_VELOCITY
    phi1_deg: SEGMENT_ANGLE
    phi2_deg: SEGMENT_ANGLE
    phi3_deg: Optional[SEGMENT_ANGLE] = None
    shape_factor: _bounded(0.05, 1.0, low_open=False, high_open=True) = 0.625

    def search_variables(self, valve, engine) -> list[tuple[str, float, float]]:
        """phi1, phi2 and the shape factor Z."""
        return self.segment_variables(valve, engine) + [("cam.shape_factor", 0.05, 0.99)]

    def build_flank(self, valve, engine) -> KurzLaw:
        c = valve.cam
        return KurzLaw(_tappet_lift(valve), ramp_height(valve), c.ramp_end_velocity, c.phi1, c.phi2,
                       self._phi3(valve, engine), c.shape_factor, **_ramp(c))

    def asymmetric_problems(self, at, closing) -> list[Problem]:
        if self.phi3_deg is None or closing.phi3_deg is None:
            return [Problem(f"{at}.cam", NoteText(note("spec.asymmetric_phi3")))]
        return []

    def records(self, law, valve, engine, nose) -> tuple[LawRecord, list]:
        """The appendix formulas of Valve-train practical works (n.d.) (2.35)-(2.39) beside the exact extremes, and the residuals of the
        junction conditions (2.10)-(2.20), for a symmetric cam."""
        if self.closing is not None:
            return LawRecord(), []
        sf = law.seed_formulas(valve.cam.base_radius, engine.rated_speed / 2.0)
        return LawRecord(seed_formulas=SeedFormulas(**sf), residuals=law.residuals()), []


@register
class PolydyneCam(_CamBase, _RampKeys):
    """[valves.NAME.cam] with law = "polydyne" (Valve-train practical works (n.d.), work 3)."""

    law: Literal["polydyne"]
    p: _bounded(3.0, 200.0, low_open=False)
    q: Optional[_bounded(3.0, 400.0)] = None
    r: Optional[_bounded(3.0, 600.0)] = None
    s: Optional[_bounded(3.0, 800.0)] = None
    ramp: bool = False
    ramp_end_velocity_mm_per_deg: Optional[RAMP_VELOCITY] = None

    @model_validator(mode="after")
    def _exponents_and_ramp(self):
        p = self.p
        q = self.q if self.q is not None else 2 * p - 2
        r = self.r if self.r is not None else 3 * p - 4
        s = self.s if self.s is not None else 4 * p - 6
        if not p < q < r < s:
            raise InputError(NoteText(note("spec.exponents_increase", p=p, q=q, r=r, s=s)))
        if self.ramp and self.ramp_end_velocity_mm_per_deg is None:
            raise InputError(NoteText(note("spec.ramp_velocity")))
        return self

    def search_variables(self, valve, engine) -> list[tuple[str, float, float]]:
        """The exponents the cam gives, each from 3 to four times its value."""
        return [(f"cam.{k}", 3.0, 4.0 * getattr(self, k)) for k in ("p", "q", "r", "s") if getattr(self, k) is not None]

    def law_of(self, cam, lift, half, r0, **ramp) -> PolydyneLaw:
        return PolydyneLaw(lift, half, cam.p, cam.q, cam.r, cam.s, **ramp)

    def build(self, valve, engine) -> LiftLaw:
        return _rampless_or_ramped(self, valve, engine, self.ramp)

    def problems(self, at, valve, engine) -> list[Problem]:
        return _clearance_problem(at, valve, "spec.ramp_needs_clearance", "ramp") if self.ramp else []


def _rampless_or_ramped(model, valve, engine, ramped=False):
    """Polydyne, polynomial and arc cams: joined to ramps that take up the clearance, or without a ramp lifting
    the valve lift plus the clearance from a heel circle r0 - h0 and taking the clearance up on the flanks
    (:class:`~valvetrain.laws.takeup.ClearanceTakeUp`), so that with any law the valve reaches ``max_lift_mm`` and
    starts to move at radius r0."""
    cam, lift, h0 = valve.cam, _tappet_lift(valve), valve.clearance
    half, r0 = main_half_angle(valve, engine.strokes), cam.base_radius
    if ramped:
        return model.law_of(cam, lift, half, r0, ramp_height=ramp_height(valve), ramp_velocity=cam.ramp_end_velocity,
                            **_ramp(cam))
    if h0 == 0.0:
        return model.law_of(cam, lift, half, r0)
    return ClearanceTakeUp(model.law_of(cam, lift + h0, half, r0 - h0), h0)


@register
class PolynomialCam(_CamBase, _RampKeys):
    """[valves.NAME.cam] with law = "polynomial": any exponent set (Shang Hanji (1988), section 2.6; the junction with a ramp derived in this package)."""

    law: Literal["polynomial"]
    exponents: Annotated[list[_bounded(2.0, 1000.0, low_open=False)], Field(min_length=2, max_length=20)]
    ramp: bool = False
    ramp_end_velocity_mm_per_deg: Optional[RAMP_VELOCITY] = None

    @model_validator(mode="after")
    def _exponents_and_ramp(self):
        k = self.exponents
        if any(b <= a for a, b in zip(k, k[1:], strict=False)) or any(e < 3 and e != 2 for e in k):
            raise InputError(NoteText(note("spec.exponent_list", exponents=f"{k}")))
        if self.ramp and self.ramp_end_velocity_mm_per_deg is None:
            raise InputError(NoteText(note("spec.ramp_velocity")))
        return self

    def law_of(self, cam, lift, half, r0, **ramp) -> PolynomialLaw:
        return PolynomialLaw(lift, half, cam.exponents, **ramp)

    def build(self, valve, engine) -> LiftLaw:
        return _rampless_or_ramped(self, valve, engine, self.ramp)

    def problems(self, at, valve, engine) -> list[Problem]:
        return _clearance_problem(at, valve, "spec.ramp_needs_clearance", "ramp") if self.ramp else []


@register
class ConstantAccelerationCam(_SegmentAngles, _CamBase, _RampKeys):
    """[valves.NAME.cam] with law = "constant_acceleration" (Shang Hanji (1988), section 2.4; reconstructed)."""

    law: Literal["constant_acceleration"]
    ramp_end_velocity_mm_per_deg: RAMP_VELOCITY
    phi1_deg: SEGMENT_ANGLE
    phi2_deg: SEGMENT_ANGLE
    phi3_deg: Optional[_bounded(0.0, 180.0, "deg", low_open=False)] = None
    kappa: _bounded(0.01, 10.0, low_open=False) = 0.6

    def search_variables(self, valve, engine) -> list[tuple[str, float, float]]:
        """phi1, phi2 and kappa."""
        return self.segment_variables(valve, engine) + [("cam.kappa", 0.1, 5.0)]

    def build_flank(self, valve, engine) -> ConstantAccelerationLaw:
        c = valve.cam
        return ConstantAccelerationLaw(_tappet_lift(valve), ramp_height(valve), c.ramp_end_velocity, c.phi1, c.phi2,
                                       self._phi3(valve, engine), c.kappa, **_ramp(c))


class Segment(_Model):
    """One acceleration segment of a combined-function cam."""

    shape: Literal["half_sine", "quarter_sine", "quarter_cosine", "constant", "linear", "parabola_to_nose"]
    length_deg: SEGMENT_ANGLE


class Ratio(_Model):
    """a(end of segment) = value x a(nose), e.g. Kurz's Z."""

    segment: Whole(1, 50)
    value: _bounded(-100.0, 100.0)


@register
class CombinedCam(_ClosingSide, _CamBase, _RampKeys):
    """[valves.NAME.cam] with law = "combined": acceleration segments with continuous acceleration (Shang Hanji (1988), section 2.5: the general mechanism)."""

    law: Literal["combined"]
    ramp_end_velocity_mm_per_deg: RAMP_VELOCITY
    segments: Annotated[list[Segment], Field(min_length=1, max_length=50)]
    ratios: Annotated[list[Ratio], Field(max_length=50)] = []

    @model_validator(mode="after")
    def _ratio_segments_exist(self):
        bad = sorted({r.segment for r in self.ratios if r.segment > len(self.segments)})
        if bad:
            raise InputError(NoteText(note("spec.ratio_segments", segments=shown(bad), count=len(self.segments))))
        return self

    def flank_angle_deg(self) -> float:
        return sum(seg.length_deg for seg in self.segments)

    def search_variables(self, valve, engine) -> list[tuple[str, float, float]]:
        """The ratios' values, each within five times its size plus one either side."""
        if not self.ratios:
            raise InputError(NoteText(note("spec.no_ratios")))
        return [(f"cam.ratios.{i}.value", -5.0 * abs(r.value) - 1.0, 5.0 * abs(r.value) + 1.0)
                for i, r in enumerate(self.ratios, 1)]

    def build_flank(self, valve, engine) -> CombinedLaw:
        c = valve.cam
        return CombinedLaw(_tappet_lift(valve), ramp_height(valve), c.ramp_end_velocity,
                           [(seg.shape, seg.length) for seg in c.segments], [(r.segment - 1, r.value) for r in c.ratios],
                           **_ramp(c))

    def flank_problems(self, at, valve, engine) -> list[Problem]:
        out = []
        total, half = self.flank_angle_deg(), main_half_angle_deg(valve, engine.strokes)
        if abs(total - half) > 1e-6:
            out.append(Problem(f"{at}.cam.segments", NoteText(note("spec.segments_sum", total=total, half=half))))
        return out + _clearance_problem(at, valve)


@register
class DynamicCam(_CamBase, _RampKeys):
    """[valves.NAME.cam] with law = "dynamic": the multi-term dynamic (Dudley-Stoddart polydyne) cam (Shang Hanji (1988), section 4.1; Dudley (1948); Stoddart (1953)).

    Its ramp ends where the drive force reaches the preload; its design speed defaults to the rated speed and its
    mass is the reduced mass at the valve without the spring (unless the masses give ``spring_kg``)."""

    law: Literal["dynamic"]
    exponents: Annotated[list[_bounded(2.0, 1000.0, low_open=False)], Field(min_length=5, max_length=5)] = \
        [2.0, 10.0, 18.0, 26.0, 34.0]
    valve_opening_velocity_m_s: _bounded(0.01, 10.0, "m/s", low_open=False)
    drive_stiffness_N_per_mm: _bounded(10.0, 1e7, "N/mm", low_open=False)
    spring_rate_N_per_mm: _bounded(0.0, 1e6, "N/mm", low_open=False)
    spring_preload_N: _bounded(0.0, 1e6, "N", low_open=False)
    design_speed_rpm: Optional[_bounded(10.0, 30000.0, "rpm", low_open=False)] = None

    def build(self, valve, engine) -> DynamicLaw:
        c = valve.cam
        omega = (c.design_speed if c.design_speed is not None else engine.rated_speed) / 2.0
        mass = train_mass(valve, 0.0)[0]
        return DynamicLaw(valve.max_lift, main_half_angle(valve, engine.strokes), c.exponents,
                          c.valve_opening_velocity_m_s / omega, c.drive_stiffness, mass, c.spring_rate,
                          c.spring_preload_N, omega, valve.rocker_ratio, valve.clearance * valve.rocker_ratio,
                          c.ramp_type, c.ramp_acceleration_fraction)


_EXPONENT = _bounded(0.05, 50.0)
"""A power of the power-polynomial law: below 0.05 a piece is a step, above 50 a spike."""


@register
class PowerPolynomialCam(_CamBase):
    """[valves.NAME.cam] with law = "power_polynomial": the piecewise power-polynomial acceleration cam of the
    UkrSURT Proceedings (2019) dynamic synthesis (reconstructed; the article's formulas are not available).

    The ramp takes up ``clearance_mm`` (S_b) over ``ramp_angle_deg`` (phi_0) and ends at
    ``ramp_end_velocity_mm_per_rad`` (v_qb); the positive part lasts ``phi1_deg`` with the peak
    ``peak_acceleration_mm_per_rad2`` (a_qd) at ``peak_position``; the negative part's length phi_2 follows
    from ``max_lift_mm``, and the rest of the main half angle is the top dwell."""

    law: Literal["power_polynomial"]
    reconstruction: Literal["R2", "R1"] = "R2"
    ramp_angle_deg: SEGMENT_ANGLE
    ramp_end_velocity_mm_per_rad: _bounded(0.05, 60.0, "mm/rad", low_open=False)
    peak_acceleration_mm_per_rad2: _bounded(1.0, 10000.0, "mm/rad2", low_open=False)
    phi1_deg: SEGMENT_ANGLE
    peak_position: _bounded(0.0, 1.0, high_open=True) = 0.2
    trough_position: _bounded(0.0, 1.0, high_open=True) = 0.8
    n: _EXPONENT = ARTICLE_EXPONENTS["n"]
    m: _EXPONENT = ARTICLE_EXPONENTS["m"]
    p: _EXPONENT = ARTICLE_EXPONENTS["p"]
    q: _EXPONENT = ARTICLE_EXPONENTS["q"]
    r: _EXPONENT = ARTICLE_EXPONENTS["r"]
    s: _EXPONENT = ARTICLE_EXPONENTS["s"]
    t: _EXPONENT = ARTICLE_EXPONENTS["t"]
    u: _EXPONENT = ARTICLE_EXPONENTS["u"]
    sharpness: _bounded(1.0, 50.0, low_open=False) = 10.0

    varies_ramp_and_spring: ClassVar[bool] = False   # its article holds the spring and the ramp

    def search_variables(self, valve, engine) -> list[tuple[str, float, float]]:
        """a_qd, phi_1, x_d, x_g (UkrSURT Proceedings (2019))."""
        half = main_half_angle_deg(valve, engine.strokes)
        return [("cam.peak_acceleration_mm_per_rad2", 10.0, 600.0),
                ("cam.phi1_deg", 2.0, 0.9 * (half - self.ramp_angle_deg)),
                ("cam.peak_position", 0.02, 0.98), ("cam.trough_position", 0.02, 0.98)]

    @model_validator(mode="after")
    def _distinct_pairs(self):
        for a, b in (("n", "m"), ("p", "q"), ("r", "s"), ("t", "u")):
            if getattr(self, a) == getattr(self, b):
                raise InputError(NoteText(note("spec.distinct_powers", a=a, b=b, value=getattr(self, a))))
        return self

    def build(self, valve, engine) -> PowerPolynomialLaw:
        c = valve.cam
        exponents = {k: getattr(c, k) for k in ARTICLE_EXPONENTS}
        try:
            return PowerPolynomialLaw(_tappet_lift(valve), main_half_angle(valve, engine.strokes),
                                      ramp_height(valve), c.ramp_angle, c.ramp_end_velocity, c.peak_acceleration,
                                      c.phi1, c.peak_position, c.trough_position, exponents, c.reconstruction,
                                      c.sharpness)
        except ValueError as exc:
            raise InputError(NoteText(note("spec.power_keys", error=note_of(said(exc))))) from None

    def problems(self, at, valve, engine) -> list[Problem]:
        out = _clearance_problem(at, valve)
        half = main_half_angle_deg(valve, engine.strokes)
        if self.phi1_deg >= half:
            out.append(Problem(f"{at}.cam.phi1_deg", NoteText(note("spec.no_negative_part", half=half)),
                               f"{self.phi1_deg:g}", " "))
        return out

    def records(self, law, valve, engine, nose) -> tuple[LawRecord, list]:
        """The responses of the synthesis: phi_2, the dwell, S_e, v_e and the fullness of the tappet lift."""
        return LawRecord(power_polynomial=PowerPolynomialRecord(float(law.phi2), float(law.dwell), law.S_e, law.v_e,
                                                                float(law.fullness()))), []


@register
class HarmonicCam(_CamBase):
    """[valves.NAME.cam] with law = "harmonic": an N-harmonic cosine series fitted to the law of
    [valves.NAME.cam.target] (Shang Hanji (1988), section 4.2, reconstructed); the target inherits base_radius_mm, follower and roller_radius_mm."""

    law: Literal["harmonic"]
    harmonics: Whole(2, 400)
    junction_order: Whole(0, 10) = 1
    target: "Cam"

    @model_validator(mode="before")
    @classmethod
    def _inherit(cls, data):
        if isinstance(data, dict) and isinstance(data.get("target"), dict):
            target = dict(data["target"])
            for key in ("base_radius_mm", "follower", "roller_radius_mm"):
                if key in data and key not in target:
                    target[key] = data[key]
            data = {**data, "target": target}
        return data

    @model_validator(mode="after")
    def _target_law(self):
        if self.target.law == "harmonic":
            raise InputError(NoteText(note("spec.harmonic_target")))
        if self.harmonics < self.junction_order + 2:
            raise InputError(NoteText(note("spec.harmonic_conditions", harmonics=self.harmonics,
                                           conditions=self.junction_order + 2)))
        return self

    def build(self, valve, engine) -> HarmonicLaw:
        target = self.target.build(_with_cam(valve, valve.cam.target), engine)
        return HarmonicLaw(target, self.harmonics, self.junction_order)

    def problems(self, at, valve, engine) -> list[Problem]:
        return self.target.problems(at, valve, engine)

    def nose_crank(self, valve, law) -> float:
        return self.target.nose_crank(valve, law)


@register
class ThreeArcCam(_CamBase):
    """[valves.NAME.cam] with law = "three_arc": convex cam of two arcs (Kolchin and Demidov (1980)); no ramp."""

    law: Literal["three_arc"]
    nose_radius_mm: Optional[Length(0.5, 500.0, low_open=False)] = None
    flank_radius_mm: Optional[Length(1.0, 10000.0, low_open=False)] = None
    flank_angle_deg: Optional[_bounded(0.1, 90.0, "deg", low_open=False, high_open=True)] = None

    @model_validator(mode="after")
    def _one_parameter(self):
        given = [k for k in ("nose_radius_mm", "flank_radius_mm", "flank_angle_deg") if getattr(self, k) is not None]
        if len(given) != 1:
            raise InputError(NoteText(note("spec.one_arc_parameter", given=f"{given or 'none'}")))
        return self

    def law_of(self, cam, lift, half, r0) -> ThreeArcLaw:
        if cam.nose_radius is not None:
            return ThreeArcLaw(r0, lift, half, cam.nose_radius)
        if cam.flank_radius is not None:
            return ThreeArcLaw.from_flank_radius(r0, lift, half, cam.flank_radius)
        return ThreeArcLaw.from_flank_angle(r0, lift, half, cam.flank_angle)

    def build(self, valve, engine) -> LiftLaw:
        return _rampless_or_ramped(self, valve, engine)


@register
class TangentCam(_CamBase):
    """[valves.NAME.cam] with law = "tangent": straight flanks and a nose arc for a roller follower (Kolchin and Demidov (1980))."""

    law: Literal["tangent"]

    @model_validator(mode="after")
    def _roller(self):
        if not FOLLOWERS[self.follower].admits(self.law):
            raise InputError(NoteText(note("spec.tangent_roller")))
        return self

    def law_of(self, cam, lift, half, r0) -> TangentLaw:
        return TangentLaw(r0, lift, half, cam.roller_radius)

    def build(self, valve, engine) -> LiftLaw:
        return _rampless_or_ramped(self, valve, engine)


MIN_TABLE_POINTS = 10
"""Fewest points of an inline lift table, as of a table file (:func:`valvetrain.files.read_lift_table`)."""

MAX_INLINE_POINTS = 10_000
"""Most points of an inline lift table (a longer table goes in a file)."""

TABLE_ANGLE = _bounded(*LIFT_TABLE_RANGES["angle_deg"][:2], "deg", low_open=False)
"""An angle of an inline lift table, bounded as in a table file [crank or cam deg, as ``table_angle`` says]."""

TABLE_LIFT = Length(*LIFT_TABLE_RANGES["lift_mm"][:2], low_open=False)
"""A lift of an inline lift table, bounded as in a table file [mm]."""


@register
class TableCam(_CamBase):
    """[valves.NAME.cam] with law = "table": a measured lift table (Shang Hanji (1988), sections 5.1-5.3, reconstructed).

    A table of valve lift is divided by the rocker ratio; a table of tappet lift is the cam's lift with its ramps,
    and the valve moves once the clearance is taken up.  The table sets the lift and the timing: a ``max_lift_mm``
    given beside it must agree with it to 1 %, ``opens_deg``/``closes_deg`` are checked against it.  The lobe must
    open the valve during the valve's own stroke.  The table is a file (``table_file``) or its points inline
    (``table_angles_deg``, ``table_lifts_mm``: the designer's control points)."""

    law: Literal["table"]
    table_file: Optional[str] = None
    table_angles_deg: Optional[Annotated[list[TABLE_ANGLE], Field(min_length=MIN_TABLE_POINTS,
                                                                  max_length=MAX_INLINE_POINTS)]] = None
    table_lifts_mm: Optional[Annotated[list[TABLE_LIFT], Field(min_length=MIN_TABLE_POINTS,
                                                               max_length=MAX_INLINE_POINTS)]] = None
    table_angle: Literal["crank", "cam"]
    table_lift_at: Literal["valve", "tappet"]
    table_zero: Literal["gas_exchange_tdc", "firing_tdc"] = "gas_exchange_tdc"
    fit: Literal["auto", "spline", "harmonic"] = "auto"
    accuracy_mm: Optional[_bounded(1e-4, 0.1, "mm", low_open=False)] = None
    max_harmonics: Whole(4, 400) = 60

    needs_timing: ClassVar[bool] = False
    si_extras: ClassVar[tuple] = ("table",)

    @model_validator(mode="after")
    def _one_table(self):
        inline = (self.table_angles_deg, self.table_lifts_mm)
        if (self.table_file is None) == all(v is None for v in inline):
            raise InputError(NoteText(note("spec.one_table")))
        if self.table_file is None:
            if None in inline or len(inline[0]) != len(inline[1]):
                sizes = [None if v is None else len(v) for v in inline]
                raise InputError(NoteText(note("spec.table_sizes", angles=sizes[0], lifts=sizes[1])))
            back = np.flatnonzero(np.diff(inline[0]) <= 0.0)
            if back.size:
                i = int(back[0]) + 1
                raise InputError(NoteText(note("spec.table_order", i=i, angle=inline[0][i], previous=inline[0][i - 1])))
        return self

    def read_extras(self, root) -> dict:
        """The table, ``(angle_deg, lift_mm)`` arrays: as read from ``table_file``
        (:func:`valvetrain.files.read_lift_table`) or the inline points."""
        if self.table_file is None:
            return {"table": (np.asarray(self.table_angles_deg, dtype=float),
                              np.asarray(self.table_lifts_mm, dtype=float))}
        return {"table": read_lift_table(self.table_file)}

    def build(self, valve, engine) -> LiftLaw:
        try:
            return self._checked_law(valve, engine)
        except ValueError as exc:
            where = "table_angles_deg, table_lifts_mm" if self.table_file is None else shown_path(self.table_file)
            raise InputError(NoteText(note("spec.in_table", where=where, error=note_of(said(exc))))) from None

    def _checked_law(self, valve, engine):
        cam, i_k = valve.cam, valve.rocker_ratio
        angle_deg, lift_mm = cam.table
        at_valve = cam.table_lift_at == "valve"
        clearance = 0.0 if at_valve else valve.clearance
        least = MIN_VALVE_LIFT_MM / (1.0 if at_valve else i_k) + clearance / MM
        accuracy_mm = table_accuracy(lift_mm) if cam.accuracy is None else cam.accuracy / MM
        theta, lift, per_point = lobe_table(angle_deg, lift_mm, cam.table_angle, cam.table_zero, accuracy_mm, least)
        to_tappet = MM / (i_k if at_valve else 1.0)
        law = TableLaw(theta, lift * to_tappet, cam.fit, accuracy_mm * to_tappet, cam.max_harmonics, clearance,
                       per_point, accuracy_stated=cam.accuracy is not None)
        table_lift = law.lift_max * i_k
        if valve.max_lift is not None and abs(valve.max_lift - table_lift) > 0.01 * table_lift:
            raise InputError(NoteText(note("spec.table_lift", lift=valve.max_lift / MM, table=table_lift / MM,
                                           low=0.99 * table_lift / MM, high=1.01 * table_lift / MM)))
        nose = 2.0 * law.centre
        lo, hi = (0.0, 180.0) if valve.kind == "intake" else (-180.0, 0.0)
        opens, closes = (rad_to_deg(nose + 2.0 * t) for t in (law.valve_opens, law.valve_closes))
        if closes <= lo or opens >= hi:
            raise InputError(NoteText(note("spec.lobe_misses", opens=opens, closes=closes, kind=valve.kind, lo=lo,
                                           hi=hi)))
        return law

    def nose_crank(self, valve, law) -> float:
        return 2.0 * law.centre

    def records(self, law, valve, engine, nose) -> tuple[LawRecord, list]:
        """The measured-table record of results.json and its timing checks (Shang Hanji (1988), sections 5.1-5.3)."""
        to_table = 2.0 if self.table_angle == "crank" else 1.0        # table angle units per cam angle
        at_valve = valve.rocker_ratio if self.table_lift_at == "valve" else 1.0
        durations = tuple(Duration(h * MM, _finite(law.duration(h * MM / at_valve) * to_table))
                          for h in CHECKING_HEIGHTS_MM)
        quality = {kind: FitQuality(q.rms_residual * at_valve, q.max_residual * at_valve, q.jerk_sign_changes)
                   for kind in ("spline", "harmonic") for q in [law.quality(kind)]}
        # the timing the table implies, where the valve lift crosses the first checking height (0.1 mm)
        rise, fall = law.crossings(law.ramp_height + CHECKING_HEIGHTS_MM[0] * MM / valve.rocker_ratio)
        opens = -(nose + 2.0 * rise) if valve.kind == "intake" else -np.pi - (nose + 2.0 * rise)
        closes = (nose + 2.0 * fall) - (np.pi if valve.kind == "intake" else 0.0)
        rec = MeasuredRecord(
            max_lift=(law.lift_max + law.ramp_height) * at_valve, lobe_centre=law.centre * to_table,
            durations=durations, fit=law.fit, fit_reason=fit_reason(law.fit, law.harmonics, *law.choice, law.smoothing),
            fit_reason_code=law.choice[0], spline_smoothing=law.smoothing,
            gcv_ratio=_finite(law.gcv["harmonic"] / law.gcv["spline"]), harmonics=law.harmonics,
            asymmetry_rms=law.asymmetry_rms * at_valve, accuracy=law.accuracy * at_valve,
            accuracy_from="stated" if law.accuracy_stated else "table", fit_quality=quality,
            table_angle=self.table_angle, table_lift_at=self.table_lift_at, table_zero=self.table_zero,
            opens=_finite(opens), closes=_finite(closes))
        found = []
        for code, given, derived in (("law.measured.opens", valve.opens, opens),
                                     ("law.measured.closes", valve.closes, closes)):
            if given is not None and np.isfinite(derived):
                found.append(check(code, given, derived - 2.0 * DEG,
                                   derived + 2.0 * DEG, unit="crank deg",
                                   source=cited(note("source.table_timing"))))
        return LawRecord(measured=rec), found

    def timing(self, valve, record) -> tuple[Optional[float], Optional[float]]:
        return record.measured.opens, record.measured.closes


Cam = Annotated[Union[tuple(REGISTRY.values())], Field(discriminator="law")]
"""The cam section: one of the registered models, chosen by its ``law``."""

LAWS = tuple(REGISTRY)
"""The ``law`` names of the registry."""

HarmonicCam.model_rebuild()
