"""The design specification: TOML file, pydantic models, validation messages.

Units are in the key names (``_mm``, ``_deg``, ``_rpm``); they are converted to SI in
:mod:`valvetrain.design`, never here.  Timing angles are crank degrees, cam segment
angles camshaft degrees.

Every problem in a file becomes one message naming the key, the value and what is
allowed; :func:`load_spec` raises :class:`SpecError` carrying them all.
"""

from importlib.resources import files
import math
from pathlib import Path
import re
import tomllib
from typing import Annotated, Literal, Optional, Union

from pydantic import AfterValidator, BaseModel, ConfigDict, Field, ValidationError, field_validator, model_validator

from .numerics import extremum
from .spring_materials import GRADES, grade
from .springs import feasible_mean_diameters
from .units import MM, cam_per_crank


class SpecError(Exception):
    """A specification that cannot be used; ``problems`` holds one message per problem."""

    def __init__(self, problems):
        self.problems = list(problems)
        super().__init__("\n".join(self.problems))


def _bounded(low, high, unit="", low_open=True, high_open=False):
    """A float constrained to a physical range, with a message that states the whole range."""
    lo_sym, hi_sym = ("(" if low_open else "["), (")" if high_open else "]")
    text = f"allowed {lo_sym}{low:g}, {high:g}{hi_sym}{' ' + unit if unit else ''}"

    def check(v):
        if not math.isfinite(v):
            raise ValueError(f"must be a finite number; {text}")
        below = v <= low if low_open else v < low
        above = v >= high if high_open else v > high
        if below or above:
            raise ValueError(text)
        return v

    return Annotated[float, AfterValidator(check)]


Length = lambda low, high, **kw: _bounded(low, high, "mm", **kw)  # noqa: E731


def _zero_or(low, high, unit="", zero="none"):
    """A float that is either 0 (meaning ``zero``) or within [low, high]: a tiny positive value is no quantity."""
    suffix = f" {unit}" if unit else ""

    def check(v):
        if not (v == 0.0 or low <= v <= high):
            raise ValueError(f"allowed 0 ({zero}) or [{low:g}, {high:g}]{suffix}")
        return v

    return Annotated[float, AfterValidator(check)]


def Pair(low, high, unit=""):  # noqa: N802 (a type factory, like Length)
    """Two bounded numbers, written as a TOML array ``[a, b]``."""
    return Annotated[tuple[_bounded(low, high, unit), _bounded(low, high, unit)], Field(strict=False)]


MAX_LIFT_TO_THROAT = 0.5
"""Largest valve lift / throat diameter accepted.  The curtain area pi d y equals the throat area at y = d/4
(seed 000, eq. 1.3 with the seat cone neglected), the recommended lift is 0.18-0.30 d (seed 000, work 2); a
lift of more than half the throat is no valve design."""

RAMP_VELOCITY = _bounded(0.001, 1.0, "mm/deg", low_open=False)
"""Tappet velocity at the end of a ramp; seed 000 work 2 recommends 0.008-0.022 mm/deg, and below 0.001 mm/deg
a ramp of the usual clearance would outlast the whole cam revolution."""

SEGMENT_ANGLE = _bounded(0.1, 180.0, "deg", low_open=False)
"""A segment of a lift law [cam deg]: below 0.1 deg the accelerations of any law leave every physical scale."""


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid", strict=True)


class Engine(_Model):
    """[engine]: the engine the valves belong to."""

    name: str = "engine"
    bore_mm: Length(5.0, 2000.0, low_open=False)
    stroke_mm: Length(5.0, 4000.0, low_open=False)
    rated_speed_rpm: _bounded(10.0, 30000.0, "rpm", low_open=False)
    cylinders: Annotated[int, Field(ge=1, le=64)]
    strokes: Literal[2, 4]
    type: Literal["si", "si_injected", "diesel"] = "si"
    chamber: Literal["side_valve", "overhead", "prechamber_diesel", "direct_injection_diesel", "wedge",
                     "hemispherical"] = "overhead"
    rod_length_mm: Optional[Length(5.0, 10000.0, low_open=False)] = None
    layout: Literal["inline", "v"] = "inline"
    bank_angle_deg: _bounded(1.0, 180.0, "deg", low_open=False) = 90.0
    firing_order: Optional[list[int]] = None
    crank_throws_deg: Optional[list[_bounded(-720.0, 720.0, "deg", low_open=False)]] = None
    banks: Optional[list[Literal[0, 1]]] = None
    firing_angles_deg: Optional[list[_bounded(0.0, 720.0, "deg", low_open=False, high_open=True)]] = None

    @model_validator(mode="after")
    def _engine_consistency(self):
        problems = []
        if self.rod_length_mm is not None and self.rod_length_mm <= self.stroke_mm / 2.0:
            problems.append(f"engine.rod_length_mm = {self.rod_length_mm:g} must exceed the crank radius "
                            f"stroke_mm/2 = {self.stroke_mm / 2.0:g} mm")
        n = self.cylinders
        if self.firing_order is not None and sorted(self.firing_order) != list(range(1, n + 1)):
            problems.append(f"engine.firing_order = {_shown(self.firing_order)}: must list each cylinder 1...{n} once")
        for key in ("crank_throws_deg", "banks", "firing_angles_deg"):
            value = getattr(self, key)
            if value is not None and len(value) != n:
                problems.append(f"engine.{key} has {len(value)} entries: one per cylinder ({n}) is needed")
        if self.firing_angles_deg is not None and len(self.firing_angles_deg) == n:
            cycle = 180.0 * self.strokes
            if self.firing_angles_deg[0] != 0.0 or not all(0.0 <= a < cycle for a in self.firing_angles_deg):
                problems.append(f"engine.firing_angles_deg = {self.firing_angles_deg}: cylinder 1 fires at 0 and "
                                f"every angle lies in [0, {cycle:g}) crank deg")
        if self.firing_angles_deg is not None and self.crank_throws_deg is not None:
            problems.append("engine: give firing_angles_deg or crank_throws_deg, not both")
        if problems:
            raise ValueError("; ".join(problems))
        return self


class _CamBase(_Model):
    base_radius_mm: Length(2.0, 500.0, low_open=False)
    follower: Literal["flat", "roller"] = "flat"
    roller_radius_mm: Optional[Length(1.0, 200.0, low_open=False)] = None

    @model_validator(mode="after")
    def _roller_needs_radius(self):
        if self.follower == "roller" and self.roller_radius_mm is None:
            raise ValueError("roller_radius_mm is required when follower = \"roller\" (allowed (0, 200] mm)")
        return self


class _RampKeys(_Model):
    ramp_type: Literal["cosine", "constant_velocity", "constant_acceleration"] = "cosine"
    ramp_acceleration_fraction: _bounded(0.01, 1.0, low_open=False) = 0.5


class _ClosingSide(_Model):
    closing: Optional[dict] = None
    """[valves.NAME.cam.closing]: the closing flank's own keys (same law; angles and ramp may differ)."""

    def closing_cam(self):
        """The closing flank as a cam of the same law (the keys not given are the opening flank's)."""
        if self.closing is None:
            return None
        data = {**self.model_dump(exclude={"closing"}), **self.closing, "law": self.law}
        return type(self).model_validate(data)


class KurzCam(_CamBase, _RampKeys, _ClosingSide):
    """[valves.NAME.cam] with law = "kurz" (seed 000, work 2)."""

    law: Literal["kurz"]
    ramp_end_velocity_mm_per_deg: RAMP_VELOCITY
    phi1_deg: SEGMENT_ANGLE
    phi2_deg: SEGMENT_ANGLE
    phi3_deg: Optional[SEGMENT_ANGLE] = None
    shape_factor: _bounded(0.05, 1.0, low_open=False, high_open=True) = 0.625


class PolydyneCam(_CamBase, _RampKeys):
    """[valves.NAME.cam] with law = "polydyne" (seed 000, work 3)."""

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
            raise ValueError(f"exponents p, q, r, s = {p:g}, {q:g}, {r:g}, {s:g} must increase strictly "
                             "(3 <= p < q < r < s)")
        if self.ramp and self.ramp_end_velocity_mm_per_deg is None:
            raise ValueError("ramp = true needs ramp_end_velocity_mm_per_deg (allowed (0, 1] mm/deg)")
        return self


class PolynomialCam(_CamBase, _RampKeys):
    """[valves.NAME.cam] with law = "polynomial": any exponent set (seed 002 section 2.6; spec section 7)."""

    law: Literal["polynomial"]
    exponents: Annotated[list[_bounded(2.0, 1000.0, low_open=False)], Field(min_length=2, max_length=20)]
    ramp: bool = False
    ramp_end_velocity_mm_per_deg: Optional[RAMP_VELOCITY] = None

    @model_validator(mode="after")
    def _exponents_and_ramp(self):
        k = self.exponents
        if any(b <= a for a, b in zip(k, k[1:], strict=False)) or any(e < 3 and e != 2 for e in k):
            raise ValueError(f"exponents = {k}: allowed an increasing list, each 2 or >= 3 (below 3 the jerk is "
                             "infinite at the nose)")
        if self.ramp and self.ramp_end_velocity_mm_per_deg is None:
            raise ValueError("ramp = true needs ramp_end_velocity_mm_per_deg (allowed (0, 1] mm/deg)")
        return self


class ConstantAccelerationCam(_CamBase, _RampKeys, _ClosingSide):
    """[valves.NAME.cam] with law = "constant_acceleration" (seed 002 section 2.4; spec section 5)."""

    law: Literal["constant_acceleration"]
    ramp_end_velocity_mm_per_deg: RAMP_VELOCITY
    phi1_deg: SEGMENT_ANGLE
    phi2_deg: SEGMENT_ANGLE
    phi3_deg: Optional[_bounded(0.0, 180.0, "deg", low_open=False)] = None
    kappa: _bounded(0.01, 10.0, low_open=False) = 0.6


class Segment(_Model):
    """One acceleration segment of a combined-function cam."""

    shape: Literal["half_sine", "quarter_sine", "quarter_cosine", "constant", "linear", "parabola_to_nose"]
    length_deg: SEGMENT_ANGLE


class Ratio(_Model):
    """a(end of segment) = value x a(nose), e.g. Kurz's Z."""

    segment: Annotated[int, Field(ge=1, le=50)]
    value: _bounded(-100.0, 100.0)


class CombinedCam(_CamBase, _RampKeys, _ClosingSide):
    """[valves.NAME.cam] with law = "combined": acceleration segments with continuous acceleration (spec section 6)."""

    law: Literal["combined"]
    ramp_end_velocity_mm_per_deg: RAMP_VELOCITY
    segments: Annotated[list[Segment], Field(min_length=1, max_length=50)]
    ratios: list[Ratio] = []

    @model_validator(mode="after")
    def _ratio_segments_exist(self):
        bad = [r.segment for r in self.ratios if r.segment > len(self.segments)]
        if bad:
            raise ValueError(f"ratios name segments {bad}; allowed 1...{len(self.segments)}")
        return self


class DynamicCam(_CamBase, _RampKeys):
    """[valves.NAME.cam] with law = "dynamic": the multi-term dynamic (Dudley-Stoddart polydyne) cam (spec section 8)."""

    law: Literal["dynamic"]
    exponents: Annotated[list[_bounded(2.0, 1000.0, low_open=False)], Field(min_length=5, max_length=5)] = \
        [2.0, 10.0, 18.0, 26.0, 34.0]
    valve_opening_velocity_m_s: _bounded(0.01, 10.0, "m/s", low_open=False)
    drive_stiffness_N_per_mm: _bounded(10.0, 1e7, "N/mm", low_open=False)
    spring_rate_N_per_mm: _bounded(0.0, 1e6, "N/mm", low_open=False)
    spring_preload_N: _bounded(0.0, 1e6, "N", low_open=False)
    design_speed_rpm: Optional[_bounded(10.0, 30000.0, "rpm", low_open=False)] = None


class HarmonicCam(_CamBase):
    """[valves.NAME.cam] with law = "harmonic": an N-harmonic cosine series fitted to the law of
    [valves.NAME.cam.target] (spec section 9); the target inherits base_radius_mm, follower and roller_radius_mm."""

    law: Literal["harmonic"]
    harmonics: Annotated[int, Field(ge=2, le=400)]
    junction_order: Annotated[int, Field(ge=0, le=10)] = 1
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
            raise ValueError("target.law = \"harmonic\": the target must be another law")
        if self.harmonics < self.junction_order + 2:
            raise ValueError(f"harmonics = {self.harmonics} cannot meet junction_order + 2 = {self.junction_order + 2} "
                             "conditions")
        return self


class TableCam(_CamBase):
    """[valves.NAME.cam] with law = "table": a measured lift table (seed 002 sections 5.1-5.3; spec sections 9-11)."""

    law: Literal["table"]
    table_file: str
    table_angle: Literal["crank", "cam"]
    table_lift_at: Literal["valve", "tappet"]
    table_zero: Literal["gas_exchange_tdc", "firing_tdc"] = "gas_exchange_tdc"
    fit: Literal["auto", "spline", "harmonic"] = "auto"
    accuracy_mm: _bounded(1e-4, 0.1, "mm", low_open=False) = 0.005
    max_harmonics: Annotated[int, Field(ge=4, le=400)] = 60


class ThreeArcCam(_CamBase):
    """[valves.NAME.cam] with law = "three_arc": convex cam of two arcs (spec section 3); no ramp."""

    law: Literal["three_arc"]
    nose_radius_mm: Optional[Length(0.5, 500.0, low_open=False)] = None
    flank_radius_mm: Optional[Length(1.0, 10000.0, low_open=False)] = None
    flank_angle_deg: Optional[_bounded(0.1, 90.0, "deg", low_open=False, high_open=True)] = None

    @model_validator(mode="after")
    def _one_parameter(self):
        given = [k for k in ("nose_radius_mm", "flank_radius_mm", "flank_angle_deg") if getattr(self, k) is not None]
        if len(given) != 1:
            raise ValueError(f"give exactly one of nose_radius_mm, flank_radius_mm, flank_angle_deg (got {given or 'none'})")
        return self


class TangentCam(_CamBase):
    """[valves.NAME.cam] with law = "tangent": straight flanks and a nose arc for a roller follower (spec section 4)."""

    law: Literal["tangent"]

    @model_validator(mode="after")
    def _roller(self):
        if self.follower != "roller":
            raise ValueError("law = \"tangent\" needs follower = \"roller\" (a flat follower on straight flanks is "
                             "degenerate) and roller_radius_mm")
        return self


Cam = Annotated[Union[KurzCam, PolydyneCam, PolynomialCam, ConstantAccelerationCam, CombinedCam, DynamicCam,
                      HarmonicCam, ThreeArcCam, TangentCam, TableCam], Field(discriminator="law")]
LAWS = ("kurz", "polydyne", "polynomial", "constant_acceleration", "combined", "dynamic", "harmonic", "three_arc",
        "tangent", "table")
HarmonicCam.model_rebuild()


class Masses(_Model):
    """[valves.NAME.drive.masses]: part masses for the reduced mass (seed 000, eq. 5.2)."""

    valve_kg: _bounded(0.001, 50.0, "kg", low_open=False)
    retainer_kg: _bounded(0.0, 20.0, low_open=False) = 0.0
    cotters_kg: _bounded(0.0, 5.0, low_open=False) = 0.0
    spring_kg: Optional[_bounded(0.001, 20.0, "kg", low_open=False)] = None
    pushrod_kg: _bounded(0.0, 20.0, low_open=False) = 0.0
    tappet_kg: _bounded(0.0, 20.0, low_open=False) = 0.0
    rocker_inertia_kg_mm2: _bounded(0.0, 1e7, "kg mm2", low_open=False) = 0.0


class Drive(_Model):
    """[valves.NAME.drive]: drive layout, masses and spring reserve (seed 000, works 5 and 7)."""

    layout: Optional[Literal["direct", "rocker", "pushrod"]] = None
    spring_reserve: _bounded(1.0, 5.0) = 1.8
    stiffness_N_per_mm: Optional[_bounded(10.0, 1e7, "N/mm", low_open=False)] = None
    specific_mass_kg_m2: Optional[_bounded(10.0, 5000.0, "kg/m2", low_open=False)] = None
    valve_arm_mm: Optional[Length(1.0, 1000.0, low_open=False)] = None
    masses: Optional[Masses] = None

    @model_validator(mode="after")
    def _one_mass_model(self):
        if self.masses is not None and self.specific_mass_kg_m2 is not None:
            raise ValueError("give either specific_mass_kg_m2 or a [masses] table, not both")
        if self.masses is not None and self.masses.rocker_inertia_kg_mm2 > 0 and self.valve_arm_mm is None:
            raise ValueError("masses.rocker_inertia_kg_mm2 needs valve_arm_mm (the valve-side rocker arm)")
        return self


class Spring(_Model):
    """[valves.NAME.spring]: spring count, material, search ranges and design limits (seed 000, works 5-6).

    ``material`` names a wire grade of :data:`valvetrain.spring_materials.GRADES` (or a list of
    them, all searched); the property keys left out come from the grade, a key given replaces
    the grade's value for every wire."""

    count: Literal[1, 2] = 1
    inner_share: _bounded(0.05, 0.95, low_open=False) = 0.4
    material: Union[str, list[str]] = "60S2A"
    shear_modulus_MPa: Optional[_bounded(1e3, 3e5, "MPa")] = None
    density_kg_m3: Optional[_bounded(100.0, 20000.0, "kg/m3")] = None
    allowable_stress_MPa: Optional[_bounded(50.0, 3000.0, "MPa", low_open=False)] = None
    endurance_limit_MPa: Optional[_bounded(50.0, 3000.0, "MPa", low_open=False)] = None
    mean_stress_factor: Optional[_bounded(0.0, 1.0, low_open=False)] = None
    min_safety_factor: _bounded(0.1, 10.0, low_open=False) = 1.3
    min_resonance_ratio: _zero_or(1.0, 100.0, zero="the check switched off") = 10.0
    coil_gap_factor: _bounded(0.01, 1.0, low_open=False) = 0.12
    mean_diameter_ratio: Pair(0.0, 5.0) = (0.7, 0.9)
    wire_diameter_range_mm: Pair(0.1, 30.0, "mm") = (2.0, 7.0)
    wire_step_mm: _bounded(0.01, 1.0, "mm", low_open=False) = 0.1
    deflection_ratio_range: Pair(1.0, 20.0) = (1.6, 3.2)
    min_frequency_difference: _bounded(0.0, 1.0, low_open=False) = 0.1
    radial_gap_mm: Length(0.0, 20.0, low_open=False) = 1.0
    min_preload_N: Optional[_bounded(0.0, 1e6, "N", low_open=False)] = None
    installed_length_mm: Optional[Pair(1.0, 5000.0, "mm")] = None
    max_free_length_mm: Optional[Length(1.0, 5000.0, low_open=False)] = None

    @property
    def materials(self):
        """The grade names searched, canonical spelling."""
        names = [self.material] if isinstance(self.material, str) else self.material
        return [grade(n).name for n in names]

    @model_validator(mode="after")
    def _ordered_range(self):
        for key, default in (("mean_diameter_ratio", "[0.7, 0.9]"), ("deflection_ratio_range", "[1.6, 3.2]"),
                             ("wire_diameter_range_mm", "[2.0, 7.0]")):
            low, high = getattr(self, key)
            if low >= high:
                raise ValueError(f"{key} = {[low, high]} must be [low, high] with low < high (default: {default})")
        if self.installed_length_mm is not None and self.installed_length_mm[0] > self.installed_length_mm[1]:
            raise ValueError(f"installed_length_mm = {list(self.installed_length_mm)} must be [low, high] with "
                             "low <= high")
        names = [self.material] if isinstance(self.material, str) else self.material
        if not names:
            raise ValueError(f"material = []: name at least one of {', '.join(repr(n) for n in GRADES)}")
        for name in names:
            try:
                grade(name)
            except KeyError as exc:
                raise ValueError(exc.args[0]) from None
        return self


class Parts(_Model):
    """[valves.NAME.parts]: dimensions of the loaded parts (seed 000, work 7); a check runs when its keys are given."""

    contact_modulus_MPa: _bounded(1e3, 1e6, "MPa") = 2.1e5
    head_diameter_mm: Optional[Length(2.0, 1000.0, low_open=False)] = None
    cam_width_mm: Optional[Length(1.0, 200.0, low_open=False)] = None
    camshaft_diameter_mm: Optional[Length(2.0, 500.0, low_open=False)] = None
    camshaft_bore_mm: Length(0.0, 500.0, low_open=False) = 0.0
    camshaft_span_mm: Optional[Length(5.0, 2000.0, low_open=False)] = None
    cam_to_bearing_mm: Optional[Length(0.5, 2000.0, low_open=False)] = None
    camshaft_modulus_MPa: _bounded(1e3, 1e6, "MPa") = 2.1e5
    camshaft_deflection_coefficient: _bounded(0.01, 100.0, low_open=False) = 64.0 / (3.0 * math.pi)
    tappet_diameter_mm: Optional[Length(2.0, 500.0, low_open=False)] = None
    tappet_guide_length_mm: Optional[Length(1.0, 500.0, low_open=False)] = None
    pushrod_length_mm: Optional[Length(5.0, 2000.0, low_open=False)] = None
    pushrod_diameter_mm: Optional[Length(1.0, 100.0, low_open=False)] = None
    pushrod_bore_mm: Length(0.0, 100.0, low_open=False) = 0.0
    pushrod_modulus_MPa: _bounded(1e3, 1e6, "MPa") = 2.1e5
    ball_radius_mm: Optional[Length(0.5, 100.0, low_open=False)] = None
    socket_radius_mm: Optional[Length(0.5, 100.0, low_open=False)] = None
    pushrod_head_area_mm2: Optional[_bounded(0.1, 1e5, "mm2", low_open=False)] = None
    rocker_pad_width_mm: Optional[Length(0.5, 100.0, low_open=False)] = None
    rocker_pad_radius_mm: Optional[Length(0.5, 1000.0, low_open=False)] = None
    rocker_shaft_span_mm: Optional[Length(1.0, 1000.0, low_open=False)] = None
    rocker_shaft_diameter_mm: Optional[Length(1.0, 200.0, low_open=False)] = None
    rocker_shaft_bore_mm: Length(0.0, 200.0, low_open=False) = 0.0
    rocker_width_mm: Optional[Length(0.5, 200.0, low_open=False)] = None

    @model_validator(mode="after")
    def _consistent(self):
        problems = []
        if self.camshaft_span_mm is not None and self.cam_to_bearing_mm is not None \
                and self.cam_to_bearing_mm >= self.camshaft_span_mm:
            problems.append(f"cam_to_bearing_mm = {self.cam_to_bearing_mm:g} must be smaller than camshaft_span_mm = "
                            f"{self.camshaft_span_mm:g}")
        for outer, inner in (("camshaft_diameter_mm", "camshaft_bore_mm"), ("pushrod_diameter_mm", "pushrod_bore_mm"),
                             ("rocker_shaft_diameter_mm", "rocker_shaft_bore_mm")):
            o, i = getattr(self, outer), getattr(self, inner)
            if o is not None and i >= o:
                problems.append(f"{inner} = {i:g} must be smaller than {outer} = {o:g}")
        if self.ball_radius_mm is not None and self.socket_radius_mm is not None \
                and self.socket_radius_mm <= self.ball_radius_mm:
            problems.append(f"socket_radius_mm = {self.socket_radius_mm:g} must exceed ball_radius_mm = "
                            f"{self.ball_radius_mm:g}")
        if problems:
            raise ValueError("; ".join(problems))
        return self


class Valve(_Model):
    """[valves.NAME]: one valve (or a set of same-name valves) of a cylinder."""

    kind: Literal["intake", "exhaust"]
    count: Annotated[int, Field(ge=1, le=8)] = 1
    throat_diameter_mm: Length(2.0, 1000.0, low_open=False)
    seat_angle_deg: _bounded(0.0, 75.0, "deg", low_open=False)
    max_lift_mm: Optional[Length(0.3, 500.0, low_open=False)] = None
    clearance_mm: _zero_or(0.01, 5.0, "mm", zero="no clearance: a hydraulic lash adjuster")
    opens_deg: Optional[_bounded(-180.0, 180.0, "deg")] = None
    closes_deg: Optional[_bounded(-180.0, 180.0, "deg")] = None
    rocker_ratio: _bounded(0.2, 5.0, low_open=False) = 1.0
    piston_gap_tdc_mm: Optional[Length(-100.0, 500.0)] = None
    cam: Cam
    drive: Drive = Drive()
    spring: Spring = Spring()
    parts: Parts = Parts()

    @property
    def layout(self):
        """Drive layout: as given, else direct for rocker ratio 1 and pushrod otherwise."""
        if self.drive.layout is not None:
            return self.drive.layout
        return "direct" if self.rocker_ratio == 1.0 else "pushrod"


class Gas(_Model):
    """[gas]: absolute pressures for the closed-valve spring check and the cam load (seed 000, works 5, 7)."""

    exhaust_back_pressure_MPa: _bounded(0.001, 10.0, "MPa", low_open=False) = 0.106
    cylinder_intake_pressure_MPa: _bounded(0.001, 10.0, "MPa", low_open=False) = 0.085
    intake_port_pressure_MPa: _bounded(0.001, 10.0, "MPa", low_open=False) = 0.1
    cylinder_exhaust_pressure_MPa: _bounded(0.001, 10.0, "MPa", low_open=False) = 0.115
    exhaust_opening_pressure_MPa: _bounded(0.001, 50.0, "MPa", low_open=False) = 0.5


class Cycle(_Model):
    """[crank.cycle]: the Wiebe cycle model used when no pressure_file is given."""

    heat_input_J: _bounded(0.01, 1e8, "J", low_open=False)
    intake_pressure_MPa: _bounded(0.001, 10.0, "MPa", low_open=False) = 0.09
    exhaust_pressure_MPa: _bounded(0.001, 10.0, "MPa", low_open=False) = 0.11
    combustion_start_deg: _bounded(-90.0, 90.0, "deg") = -15.0
    combustion_duration_deg: _bounded(1.0, 180.0, "deg", low_open=False) = 60.0
    wiebe_a: _bounded(0.01, 50.0, low_open=False) = 6.908
    wiebe_m: _bounded(-1.0, 10.0) = 2.0
    gamma: _bounded(1.0, 2.0) = 1.33


class CrankSpec(_Model):
    """[crank]: the crank mechanism (seed 001).  bore, stroke, rod length and speed default to [engine]."""

    bore_mm: Optional[Length(5.0, 2000.0, low_open=False)] = None
    stroke_mm: Optional[Length(5.0, 4000.0, low_open=False)] = None
    rod_length_mm: Optional[Length(5.0, 10000.0, low_open=False)] = None
    offset_mm: _bounded(-1000.0, 1000.0, "mm", low_open=False) = 0.0
    speed_rpm: Optional[_bounded(10.0, 30000.0, "rpm", low_open=False)] = None
    kinematics: Literal["exact", "approximate"] = "exact"
    pressure_file: Optional[str] = None
    pv_method: Literal["exact", "brix"] = "exact"
    compression_ratio: Optional[_bounded(1.0, 60.0)] = None
    ambient_pressure_MPa: _bounded(0.001, 10.0, "MPa", low_open=False) = 0.1
    step_deg: _bounded(0.1, 10.0, "deg", low_open=False) = 1.0
    piston_kg: Optional[_bounded(0.001, 1e4, "kg", low_open=False)] = None
    rod_kg: Optional[_bounded(0.001, 1e4, "kg", low_open=False)] = None
    crank_kg: Optional[_bounded(0.0, 1e4, "kg", low_open=False)] = None
    specific_piston_kg_m2: Optional[_bounded(1.0, 1e4, "kg/m2", low_open=False)] = None
    specific_rod_kg_m2: Optional[_bounded(1.0, 1e4, "kg/m2", low_open=False)] = None
    specific_crank_kg_m2: Optional[_bounded(0.0, 1e4, "kg/m2", low_open=False)] = None
    rod_pin_fraction: _bounded(0.01, 0.99, low_open=False) = 0.275
    cycle: Optional[Cycle] = None

    @model_validator(mode="after")
    def _masses_and_pressure(self):
        problems = []
        for part in ("piston", "rod", "crank"):
            given = getattr(self, f"{part}_kg") is not None, getattr(self, f"specific_{part}_kg_m2") is not None
            if all(given):
                problems.append(f"give {part}_kg or specific_{part}_kg_m2, not both")
            elif not any(given):
                problems.append(f"{part}_kg or specific_{part}_kg_m2 is required (seed 001, eq. 2.6 and Table 2.1)")
        if self.pressure_file is None and self.cycle is None:
            problems.append("the cylinder pressure is needed: give pressure_file (crank_deg,pressure_MPa or "
                            "volume_cm3,pressure_MPa) or a [crank.cycle] table with heat_input_J")
        if self.cycle is not None and self.compression_ratio is None:
            problems.append("[crank.cycle] needs compression_ratio")
        if problems:
            raise ValueError("; ".join(problems))
        return self


class Port(_Model):
    """[two_stroke.ports.NAME]: one piston-controlled port (or a group of equal ports: width is their sum)."""

    kind: Literal["exhaust", "transfer", "inlet"]
    width_mm: Length(0.5, 10000.0, low_open=False)
    height_mm: Optional[Length(0.1, 3000.0, low_open=False)] = None
    opens_before_bdc_deg: Optional[_bounded(0.1, 180.0, "deg", low_open=False, high_open=True)] = None
    lower_edge_mm: Optional[Length(0.0, 5000.0, low_open=False)] = None

    @model_validator(mode="after")
    def _geometry(self):
        if self.kind == "inlet":
            if self.lower_edge_mm is None or self.height_mm is None:
                raise ValueError("an inlet port needs lower_edge_mm (below the crown at TDC) and height_mm "
                                 "(seed 000, eq. 8.4)")
        elif (self.height_mm is None) == (self.opens_before_bdc_deg is None):
            raise ValueError("give height_mm or opens_before_bdc_deg (one of them) for an exhaust or transfer port")
        return self


class TwoStroke(_Model):
    """[two_stroke]: port timing of a piston-ported two-stroke (seed 000, work 8)."""

    speed_rpm: Optional[_bounded(10.0, 30000.0, "rpm", low_open=False)] = None
    speed_range_rpm: Optional[Pair(10.0, 30000.0, "rpm")] = None
    kinematics: Literal["exact", "approximate"] = "exact"
    piston_height_mm: Optional[Length(1.0, 3000.0, low_open=False)] = None
    step_deg: _bounded(0.05, 10.0, "deg", low_open=False) = 0.5
    ports: dict[str, Port]


class Output(_Model):
    """[output]: tables and exports."""

    table_step_cam_deg: _bounded(0.05, 10.0, "deg", low_open=False) = 0.5
    contour_points: Annotated[int, Field(ge=36, le=100000)] = 721
    export_step_deg: _bounded(0.1, 10.0, "deg", low_open=False) = 1.0


_NAME = re.compile(r"^[A-Za-z][A-Za-z0-9_-]{0,31}$")


class Spec(_Model):
    """A whole design specification."""

    engine: Engine
    valves: dict[str, Valve] = {}
    gas: Gas = Gas()
    crank: Optional[CrankSpec] = None
    two_stroke: Optional[TwoStroke] = None
    output: Output = Output()
    source_dir: Optional[str] = Field(default=None, exclude=True)
    """Folder of the specification file: relative file names (pressure_file) are read from there."""

    @field_validator("valves")
    @classmethod
    def _valve_names(cls, valves):
        bad = [_shown(n, 40) for n in valves if not _NAME.match(n) or n in ("crank", "two_stroke")]
        if bad:
            raise ValueError(f"valve names {', '.join(bad)}: allowed a letter, then up to 31 letters, digits, '_' and "
                             "'-' (and not 'crank' or 'two_stroke', the names of the engine's chapters)")
        return valves

    @model_validator(mode="after")
    def _something_to_design(self):
        if not self.valves and self.crank is None and self.two_stroke is None:
            raise ValueError("nothing to design: give at least one [valves.NAME], [crank] or [two_stroke] section")
        return self


def main_half_angle_deg(valve, strokes):
    """phi_p0 in camshaft degrees: half the main event (ramps excluded), (opens + 180 + closes)/2 crank deg
    converted to the camshaft (seed 000, work 2, corrected phi_p0 formula, E1)."""
    return (valve.opens_deg + 180.0 + valve.closes_deg) / 2.0 * cam_per_crank(strokes)


def kurz_phi3_deg(cam, valve, strokes):
    """Phi3 in camshaft degrees: given, or the remainder phi_p0 - Phi1 - Phi2 (eq. 2.2; also the
    constant-acceleration cam's third segment)."""
    if cam.phi3_deg is not None:
        return cam.phi3_deg
    return main_half_angle_deg(valve, strokes) - cam.phi1_deg - cam.phi2_deg


def _valve_problems(name, v, engine):
    at = f"valves.{name}"
    missing = [k for k in ("max_lift_mm", "opens_deg", "closes_deg") if getattr(v, k) is None]
    if missing and v.cam.law != "table":
        return [f"{at}.{k}: required key is missing (only a measured table, law = \"table\", sets its own lift "
                "and timing)" for k in missing]
    out = []
    if len({"opens_deg", "closes_deg"} & set(missing)) == 1:
        given, other = ("opens_deg", "closes_deg") if v.closes_deg is None else ("closes_deg", "opens_deg")
        return [f"{at}.{given} = {getattr(v, given):g} needs {other} too: the timing is given by both or, for a "
                "measured table, by neither"]
    if v.throat_diameter_mm >= engine.bore_mm:
        out.append(f"{at}.throat_diameter_mm = {v.throat_diameter_mm:g} must be smaller than engine.bore_mm = "
                   f"{engine.bore_mm:g}")
    if v.cam.base_radius_mm <= v.clearance_mm:
        out.append(f"{at}.cam.base_radius_mm = {v.cam.base_radius_mm:g} must exceed clearance_mm = {v.clearance_mm:g}")
    ratio = v.spring.mean_diameter_ratio
    wires = v.spring.wire_diameter_range_mm
    low, high = (x / MM for x in feasible_mean_diameters(wires))
    if ratio[1] * v.throat_diameter_mm < low or ratio[0] * v.throat_diameter_mm > high:
        out.append(f"{at}.spring.mean_diameter_ratio = {list(ratio)} with throat_diameter_mm = "
                   f"{v.throat_diameter_mm:g} gives spring mean diameters {ratio[0] * v.throat_diameter_mm:g}..."
                   f"{ratio[1] * v.throat_diameter_mm:g} mm; wire of {wires[0]:g}...{wires[1]:g} mm makes "
                   f"{low:g}...{high:g} mm (index D/d = 3...12, seed 000, work 6)")
    installed = v.spring.installed_length_mm
    if installed is not None and v.max_lift_mm is not None and installed[1] <= v.max_lift_mm:
        out.append(f"{at}.spring.installed_length_mm = {list(installed)}: the spring must be longer than the valve "
                   f"lift max_lift_mm = {v.max_lift_mm:g} (it is compressed by it, seed 000, eq. 6.5)")
    if v.drive.layout == "direct" and v.rocker_ratio != 1.0:
        out.append(f"{at}.drive.layout = \"direct\" needs rocker_ratio = 1 (got {v.rocker_ratio:g})")
    if v.piston_gap_tdc_mm is not None and engine.rod_length_mm is None:
        out.append(f"{at}.piston_gap_tdc_mm needs engine.rod_length_mm for the piston kinematics")
    if not {"opens_deg", "closes_deg"} & set(missing):
        out += _cam_angle_problems(at, v, engine)
    return out


def _cam_angle_problems(at, v, engine):
    """The cam's angles against the valve event given by opens_deg/closes_deg, and the ramps' clearance."""
    out = []
    half = main_half_angle_deg(v, engine.strokes)
    if not 0.0 < half < 180.0:
        out.append(f"{at}.opens_deg + closes_deg = {v.opens_deg + v.closes_deg:g}: the valve event "
                   f"opens_deg + 180 + closes_deg must lie in (0, 360) crank deg")
    cam = v.cam.target if isinstance(v.cam, HarmonicCam) else v.cam
    if getattr(cam, "closing", None) is not None:
        return out + _asymmetric_problems(at, cam, half, v)
    if isinstance(cam, (KurzCam, ConstantAccelerationCam)):
        if v.clearance_mm <= 0.0:
            out.append(f"{at}.clearance_mm = {v.clearance_mm:g}: the cam's ramp takes up the clearance, "
                       "allowed (0, 5] mm")
        phi3 = kurz_phi3_deg(cam, v, engine.strokes)
        total = cam.phi1_deg + cam.phi2_deg + phi3
        if cam.phi3_deg is None and phi3 < 0.0 or (isinstance(cam, KurzCam) and cam.phi3_deg is None and phi3 == 0.0):
            out.append(f"{at}.cam: phi1_deg + phi2_deg = {cam.phi1_deg + cam.phi2_deg:g} leaves no room for phi3 "
                       f"in the half-angle phi_p0 = {half:g} cam deg; allowed phi1_deg + phi2_deg < {half:g}")
        elif abs(total - half) > 1e-6:
            out.append(f"{at}.cam: phi1_deg + phi2_deg + phi3_deg = {total:g} cam deg must equal the half-angle "
                       f"phi_p0 = (opens_deg + 180 + closes_deg)/2 crank deg = {half:g} cam deg (seed 000, eq. 2.2)")
    elif isinstance(cam, CombinedCam):
        total = sum(seg.length_deg for seg in cam.segments)
        if abs(total - half) > 1e-6:
            out.append(f"{at}.cam.segments: the lengths add up to {total:g} cam deg; they must equal the half-angle "
                       f"phi_p0 = {half:g} cam deg")
        if v.clearance_mm <= 0.0:
            out.append(f"{at}.clearance_mm = {v.clearance_mm:g}: the cam's ramp takes up the clearance, allowed (0, 5] mm")
    elif getattr(cam, "ramp", False) and v.clearance_mm <= 0.0:
        out.append(f"{at}.clearance_mm = {v.clearance_mm:g}: a ramp needs a clearance to take up, "
                   "allowed (0, 5] mm")
    return out


def _same(spec, key_crank, key_engine):
    """A [crank] value that defaults to [engine]'s; a problem message when both are given and differ."""
    a, b = getattr(spec.crank, key_crank) if spec.crank else None, getattr(spec.engine, key_engine)
    if a is not None and b is not None and abs(a - b) > 1e-9 * max(abs(a), abs(b)):
        return a, [f"crank.{key_crank} = {a:g} differs from engine.{key_engine} = {b:g}; give it in one place"]
    return (a if a is not None else b), []


def crank_geometry(spec):
    """Effective bore, stroke, rod length [mm] and speed [rpm] of the crank mechanism."""
    return tuple(_same(spec, kc, ke)[0] for kc, ke in (("bore_mm", "bore_mm"), ("stroke_mm", "stroke_mm"),
                                                      ("rod_length_mm", "rod_length_mm"),
                                                      ("speed_rpm", "rated_speed_rpm")))


def _crank_problems(spec):
    if spec.crank is None and spec.two_stroke is None:
        return []
    out = []
    for kc, ke in (("bore_mm", "bore_mm"), ("stroke_mm", "stroke_mm"), ("rod_length_mm", "rod_length_mm"),
                   ("speed_rpm", "rated_speed_rpm")):
        out += _same(spec, kc, ke)[1]
    bore, stroke, rod, _ = crank_geometry(spec)
    if rod is None:
        out.append("crank.rod_length_mm (or engine.rod_length_mm) is required for the crank mechanism and the "
                   "two-stroke ports")
    elif rod <= stroke / 2.0:
        out.append(f"crank.rod_length_mm = {rod:g} must exceed the crank radius {stroke / 2.0:g} mm")
    c = spec.crank
    if c is None:
        return out
    if rod is not None and rod > stroke / 2.0 and abs(c.offset_mm) >= rod - stroke / 2.0:
        out.append(f"crank.offset_mm = {c.offset_mm:g}: allowed |offset| < rod length - crank radius = "
                   f"{rod - stroke / 2.0:g} mm")
    cycle = 180.0 * spec.engine.strokes
    n = cycle / c.step_deg
    if abs(n - round(n)) > 1e-9:
        out.append(f"crank.step_deg = {c.step_deg:g} must divide the {cycle:g} deg cycle into whole steps")
    return out


def resolve_path(spec, name):
    """A file named in the specification, relative to the specification file's folder."""
    path = Path(name)
    return path if path.is_absolute() or spec.source_dir is None else Path(spec.source_dir) / path


def input_files(spec):
    """Every file the specification names (each ``..._file`` key: lift tables, indicator diagrams), resolved."""
    def named(node):
        if isinstance(node, dict):
            for key, value in node.items():
                if key.endswith("_file") and isinstance(value, str):
                    yield resolve_path(spec, value)
                else:
                    yield from named(value)
        elif isinstance(node, list):
            for value in node:
                yield from named(value)

    return sorted(set(named(spec.model_dump())))


def _two_stroke_problems(spec):
    ts = spec.two_stroke
    if ts is None:
        return []
    out = []
    if spec.engine.strokes != 2:
        out.append(f"[two_stroke] needs engine.strokes = 2 (got {spec.engine.strokes})")
    if not ts.ports:
        out.append("[two_stroke] needs at least one [two_stroke.ports.NAME]")
    stroke = crank_geometry(spec)[1]
    for name, port in ts.ports.items():
        if port.height_mm is not None and port.kind != "inlet" and port.height_mm >= stroke:
            out.append(f"two_stroke.ports.{name}.height_mm = {port.height_mm:g} must be smaller than the stroke "
                       f"{stroke:g} mm")
        if port.kind == "inlet" and ts.piston_height_mm is None:
            out.append(f"two_stroke.ports.{name}: an inlet port needs two_stroke.piston_height_mm")
    if ts.speed_range_rpm is not None and ts.speed_range_rpm[0] >= ts.speed_range_rpm[1]:
        out.append(f"two_stroke.speed_range_rpm = {list(ts.speed_range_rpm)} must be [low, high] with low < high")
    return out


def side_half_angle_deg(cam):
    """Main angle of one flank [cam deg]: the sum of its segment angles (phi3 must be given on an asymmetric cam)."""
    if isinstance(cam, CombinedCam):
        return sum(seg.length_deg for seg in cam.segments)
    return cam.phi1_deg + cam.phi2_deg + (cam.phi3_deg or 0.0)


def _asymmetric_problems(at, cam, half, v):
    out = []
    if v.clearance_mm <= 0.0:
        out.append(f"{at}.clearance_mm = {v.clearance_mm:g}: the cam's ramp takes up the clearance, allowed (0, 5] mm")
    try:
        closing = cam.closing_cam()
    except ValidationError as exc:
        return out + [f"{at}.cam.closing: {_message(err)}" for err in exc.errors()]
    if isinstance(cam, KurzCam) and (cam.phi3_deg is None or closing.phi3_deg is None):
        out.append(f"{at}.cam: an asymmetric Kurz cam needs phi3_deg on both flanks")
    total = side_half_angle_deg(cam) + side_half_angle_deg(closing)
    if abs(total - 2.0 * half) > 1e-6:
        out.append(f"{at}.cam: the opening and closing flanks add up to {total:g} cam deg; they must equal the main "
                   f"event (opens_deg + 180 + closes_deg)/2 = {2.0 * half:g} cam deg")
    return out


def _resolve_tables(spec):
    """Make every valve's table_file absolute (relative to the specification file's folder)."""
    valves = {}
    for name, v in spec.valves.items():
        if v.cam.law == "table":
            cam = v.cam.model_copy(update={"table_file": str(resolve_path(spec, v.cam.table_file))})
            v = v.model_copy(update={"cam": cam})
        valves[name] = v
    return spec.model_copy(update={"valves": valves})


def _location(err):
    """The key path of a pydantic error without the law tags pydantic inserts after a cam (``cam.kurz.phi1_deg``)."""
    loc = err["loc"]
    parts = [str(p) if len(str(p)) <= 40 else f"{str(p)[:35]}..." for i, p in enumerate(loc)
             if not (p in LAWS and i > 0 and loc[i - 1] in ("cam", "target"))]
    return ".".join(parts) if parts else "(file)"


def _shown(value, limit=60):
    """A value as echoed in a message: its repr, cut to ``limit`` characters."""
    text = repr(value)
    return text if len(text) <= limit else f"{text[:limit - 5]}...{text[-2:]}"


def _message(err):
    loc = _location(err)
    kind = err["type"]
    if kind == "missing":
        return f"{loc}: required key is missing"
    if kind == "extra_forbidden":
        return f"{loc}: unknown key (value {_shown(err['input'])}); check the spelling against `valvetrain example`"
    if kind == "union_tag_invalid":
        return f"{loc}.law = {_shown(err['ctx']['tag'])}: allowed {err['ctx']['expected_tags']}"
    if kind == "union_tag_not_found":
        return f"{loc}.law: required key is missing; allowed {', '.join(repr(law) for law in LAWS)}"
    msg = err["msg"].removeprefix("Value error, ")
    if isinstance(err["input"], dict):
        return f"{loc}: {msg}"
    return f"{loc} = {_shown(err['input'])}: {msg}"


def validate(data):
    """Validate a parsed TOML document; return a :class:`Spec` or raise :class:`SpecError`.

    Field problems (missing keys, wrong types, values outside physical bounds) are
    reported first; the cross-checks between keys (angles that must add up, a throat
    smaller than the bore, ...) run once every field is valid.
    """
    try:
        spec = Spec.model_validate(data)
    except ValidationError as exc:
        raise SpecError([_message(err) for err in exc.errors()]) from None
    spec = _resolve_tables(spec)
    problems = [p for name, v in spec.valves.items() for p in _valve_problems(name, v, spec.engine)]
    problems += _crank_problems(spec) + _two_stroke_problems(spec)
    if spec.engine.strokes != 4 and spec.valves:
        problems.insert(0, f"engine.strokes = {spec.engine.strokes}: the valve timing (opens_deg/closes_deg before and "
                           "after TDC/BDC of the gas-exchange strokes) is defined for four-stroke engines; allowed 4 "
                           "with [valves.NAME] sections")
    if not problems:
        problems += _law_problems(spec)
    if problems:
        raise SpecError(problems)
    return spec


def _law_problems(spec):
    """Build every valve's law once: inputs that pass the field checks can still admit no cam (a nose radius
    that does not fit, a negative acceleration level); each becomes a message naming the cam."""
    from .design import build_law

    out = []
    for name, v in spec.valves.items():
        try:
            law = build_law(v, spec.engine.strokes, spec.engine.rated_speed_rpm)
        except ValueError as exc:
            out.append(f"valves.{name}.cam: {exc}")
            continue
        nose = law.lift_max + law.ramp_height
        low, high = (extremum(law.lift, law.breakpoints, kind)[1] for kind in ("min", "max"))
        if high > nose * (1.0 + 1e-6) or low < -1e-6 * nose:
            out.append(f"valves.{name}.cam: the lift runs from {low / MM:.4g} to {high / MM:.4g} mm; allowed 0 to the "
                       f"nose lift {nose / MM:.4g} mm (the law's angles and ramp velocity do not fit together)")
            continue
        event = math.degrees(law.end - law.start)
        if not event < 360.0:
            ramp = math.degrees(law.ramp_angle)
            out.append(f"valves.{name}.cam: the cam event lasts {event:.4g} cam deg; allowed < 360" + (
                f" (a ramp of {ramp:.4g} cam deg on each flank: raise ramp_end_velocity_mm_per_deg or lower "
                "clearance_mm)" if ramp > 0.0 else ""))
        lift = law.lift_max * v.rocker_ratio / MM
        if lift > MAX_LIFT_TO_THROAT * v.throat_diameter_mm:
            what = "cam.table_file: the measured valve lift" if v.cam.law == "table" else "max_lift_mm"
            out.append(f"valves.{name}.{what} = {lift:.4g} mm: allowed at most {MAX_LIFT_TO_THROAT:g} x "
                       f"throat_diameter_mm = {MAX_LIFT_TO_THROAT * v.throat_diameter_mm:.4g} mm (the curtain area "
                       "already equals the throat area at a quarter of the diameter)")
    return out


def parse_spec(text, source="<string>", source_dir=None):
    """Parse and validate TOML text; relative file names in it are read from ``source_dir``."""
    try:
        data = tomllib.loads(text.removeprefix("\ufeff"))
    except tomllib.TOMLDecodeError as exc:
        raise SpecError([f"{source}: not valid TOML: {exc}"]) from None
    except RecursionError:
        raise SpecError([f"{source}: arrays or tables nested too deeply to be a specification"]) from None
    if source_dir is not None and isinstance(data, dict):
        data["source_dir"] = str(source_dir)
    return validate(data)


def load_spec(path):
    """Read and validate a specification file."""
    try:
        text = Path(path).read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise SpecError([f"{path}: cannot read the file: {exc}"]) from None
    return parse_spec(text, str(path), Path(path).resolve().parent)


def example_text():
    """The built-in example specification (the engine of seed 000's appendix), as TOML text."""
    return files("valvetrain").joinpath("data/example.toml").read_text(encoding="utf-8")


def example_spec():
    """The built-in example, validated."""
    return parse_spec(example_text(), "built-in example")
