"""The sections of a specification: engine, valves (drive, springs, parts and the valve's stages), output, the
specification itself; the engine's further stages (camshaft, gas, crank, two-stroke ports, breathing) in
:mod:`.engine_sections`.

Units are in the key names; :mod:`.si` converts them.  Timing angles are crank degrees, cam segment angles
camshaft degrees.  A model checks its own keys and the keys that must agree within it; the checks across
sections are in :mod:`.validate`.
"""

import math
import re
from typing import Annotated, Literal, Optional, Union

from pydantic import Field, ValidationError, field_validator, model_validator

from ..errors import InputError
from ..layouts import LAYOUTS, layout
from ..locale import NoteText, note
from ..spring_materials import GRADES, grade
from .cams import LAWS, Cam
from .engine_sections import Breathing, Camshaft, CrankSpec, Gas, TwoStroke, resolve_path
from .fields import Length, Pair, _bounded, _Model, Whole, _zero_or
from .messages import SpecError, message, shown
from .switching import Switching
from .validate import problems, set_keys, spec_document


class Engine(_Model):
    """[engine]: the engine the valves belong to."""

    name: str = "engine"
    bore_mm: Length(5.0, 2000.0, low_open=False)
    stroke_mm: Length(5.0, 4000.0, low_open=False)
    rated_speed_rpm: _bounded(10.0, 30000.0, "rpm", low_open=False)
    cylinders: Whole(1, 64)
    strokes: Literal[2, 4]
    type: Literal["si", "si_injected", "diesel"] = "si"
    engine_class: Optional[Literal["automotive_petrol", "automotive_diesel", "heavy_duty"]] = None
    chamber: Literal["side_valve", "overhead", "prechamber_diesel", "direct_injection_diesel", "wedge",
                     "hemispherical"] = "overhead"
    rod_length_mm: Optional[Length(5.0, 10000.0, low_open=False)] = None
    over_speed_ratio: _bounded(1.0, 2.0, low_open=False) = 1.1
    idle_speed_rpm: Optional[_bounded(10.0, 30000.0, "rpm", low_open=False)] = None
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
            problems.append(note("spec.rod_exceeds", rod=self.rod_length_mm, radius=self.stroke_mm / 2.0))
        if self.idle_speed_rpm is not None and self.idle_speed_rpm >= self.rated_speed_rpm:
            problems.append(note("spec.idle", idle=self.idle_speed_rpm, rated=self.rated_speed_rpm))
        n = self.cylinders
        if self.firing_order is not None and sorted(self.firing_order) != list(range(1, n + 1)):
            problems.append(note("spec.firing_order", order=shown(self.firing_order), count=n))
        for key in ("crank_throws_deg", "banks", "firing_angles_deg"):
            value = getattr(self, key)
            if value is not None and len(value) != n:
                problems.append(note("spec.per_cylinder", key=key, entries=len(value), count=n))
        if self.firing_angles_deg is not None and len(self.firing_angles_deg) == n:
            cycle = 180.0 * self.strokes
            if self.firing_angles_deg[0] != 0.0 or not all(0.0 <= a < cycle for a in self.firing_angles_deg):
                problems.append(note("spec.firing_angles", angles=f"{self.firing_angles_deg}", cycle=cycle))
        if self.firing_angles_deg is not None and self.crank_throws_deg is not None:
            problems.append(note("spec.angles_or_throws"))
        if problems:
            raise InputError(NoteText(sum(problems, ())))
        return self


LEAST_PART_MASS_KG = 1e-4
"""Least mass of a part of the train that has one [kg], a tenth of a gram: below the lightest part of a valve train
(a pair of cotters, 2 g in the examples).  A part's mass is 0 (no such part) or at least this, a spring's coil mass
at least this: a node of the multi-mass train of 5e-324 kg overflowed its natural frequency (a traceback), one of
0 kg divided by zero."""


class Masses(_Model):
    """[valves.NAME.drive.masses]: part masses for the reduced mass (Valve-train practical works (n.d.), eq. 5.2);
    a part the layout has not is 0, a part it has at least :data:`LEAST_PART_MASS_KG` (a rocker's inertia at least
    0.01 kg mm2, that mass 10 mm from its pivot)."""

    valve_kg: _bounded(0.001, 50.0, "kg", low_open=False)
    retainer_kg: _zero_or(LEAST_PART_MASS_KG, 20.0, "kg") = 0.0
    cotters_kg: _zero_or(LEAST_PART_MASS_KG, 5.0, "kg") = 0.0
    spring_kg: Optional[_bounded(0.001, 20.0, "kg", low_open=False)] = None
    pushrod_kg: _zero_or(LEAST_PART_MASS_KG, 20.0, "kg") = 0.0
    tappet_kg: _zero_or(LEAST_PART_MASS_KG, 20.0, "kg") = 0.0
    rocker_inertia_kg_mm2: _zero_or(LEAST_PART_MASS_KG * 100.0, 1e7, "kg mm2") = 0.0
    bridge_kg: Optional[_bounded(LEAST_PART_MASS_KG, 20.0, "kg", low_open=False)] = None


class Drive(_Model):
    """[valves.NAME.drive]: drive layout, masses and spring reserve (Valve-train practical works (n.d.), works 5 and 7)."""

    layout: Optional[Literal[tuple(LAYOUTS)]] = None
    spring_reserve: _bounded(1.0, 5.0) = 1.8
    stiffness_N_per_mm: Optional[_bounded(10.0, 1e7, "N/mm", low_open=False)] = None
    specific_mass_kg_m2: Optional[_bounded(10.0, 5000.0, "kg/m2", low_open=False)] = None
    valve_arm_mm: Optional[Length(1.0, 1000.0, low_open=False)] = None
    masses: Optional[Masses] = None

    @model_validator(mode="after")
    def _one_mass_model(self):
        if self.masses is not None and self.specific_mass_kg_m2 is not None:
            raise InputError(NoteText(note("spec.mass_or_masses")))
        return self


class Spring(_Model):
    """[valves.NAME.spring]: spring count, material, search ranges and design limits (Valve-train practical works (n.d.), works 5-6).

    ``material`` names a wire grade of :data:`valvetrain.spring_materials.GRADES` (or a list of
    them, all searched); the property keys left out come from the grade, a key given replaces
    the grade's value for every wire.  ``min_frequency_difference`` (a nested pair's) is 0 (the check switched off)
    or at least 0.01: a smaller requirement is finer than a wound spring's frequency is known (its rate and mass
    vary by per cents), and one near zero overflowed the check's margin."""

    count: Literal[1, 2] = 1
    inner_share: _bounded(0.05, 0.95, low_open=False) = 0.4
    material: Union[str, list[str]] = "60S2A"
    shear_modulus_MPa: Optional[_bounded(1e3, 3e5, "MPa")] = None
    density_kg_m3: Optional[_bounded(100.0, 20000.0, "kg/m3")] = None
    allowable_stress_MPa: Optional[_bounded(50.0, 3000.0, "MPa", low_open=False)] = None
    endurance_limit_MPa: Optional[_bounded(50.0, 3000.0, "MPa", low_open=False)] = None
    mean_stress_factor: Optional[_bounded(0.0, 1.0, low_open=False)] = None
    min_safety_factor: _bounded(0.1, 10.0, low_open=False) = 1.3
    min_resonance_ratio: _zero_or(1.0, 100.0, zero="field.zero_off") = 10.0
    min_margin_percent: _bounded(0.0, 50.0, "%", low_open=False) = 5.0
    coil_gap_factor: _bounded(0.01, 1.0, low_open=False) = 0.12
    mean_diameter_ratio: Pair(0.0, 5.0) = (0.7, 0.9)
    wire_diameter_range_mm: Pair(0.1, 30.0, "mm") = (2.0, 7.0)
    wire_step_mm: _bounded(0.01, 1.0, "mm", low_open=False) = 0.1
    deflection_ratio_range: Pair(1.0, 20.0) = (1.6, 3.2)
    min_frequency_difference: _zero_or(0.01, 1.0, zero="field.zero_off") = 0.1
    radial_gap_mm: Length(0.0, 20.0, low_open=False) = 1.0
    min_preload_N: Optional[_bounded(0.0, 1e6, "N", low_open=False)] = None
    installed_length_mm: Optional[Pair(1.0, 5000.0, "mm")] = None
    max_free_length_mm: Optional[Length(1.0, 5000.0, low_open=False)] = None

    @property
    def materials(self) -> list[str]:
        """The grade names searched, canonical spelling."""
        names = [self.material] if isinstance(self.material, str) else self.material
        return [grade(n).name for n in names]

    @model_validator(mode="after")
    def _ordered_range(self):
        for key, default in (("mean_diameter_ratio", "[0.7, 0.9]"), ("deflection_ratio_range", "[1.6, 3.2]"),
                             ("wire_diameter_range_mm", "[2.0, 7.0]")):
            low, high = getattr(self, key)
            if low >= high:
                raise InputError(NoteText(note("spec.ordered_default", key=key, pair=f"{[low, high]}",
                                               default=default)))
        if self.installed_length_mm is not None and self.installed_length_mm[0] > self.installed_length_mm[1]:
            raise InputError(NoteText(note("spec.installed_order", pair=f"{list(self.installed_length_mm)}")))
        names = [self.material] if isinstance(self.material, str) else self.material
        if not names:
            raise InputError(NoteText(note("spec.no_material", names=", ".join(repr(n) for n in GRADES))))
        for name in names:
            try:
                grade(name)
            except InputError:
                raise InputError(NoteText(note("spec.material", name=shown(name),
                                               names=", ".join(repr(n) for n in GRADES)))) from None
        return self


class Parts(_Model):
    """[valves.NAME.parts]: dimensions of the loaded parts (Valve-train practical works (n.d.), work 7); a check runs when its keys are given."""

    contact_modulus_MPa: _bounded(1e3, 1e6, "MPa") = 2.1e5
    head_diameter_mm: Optional[Length(2.0, 1000.0, low_open=False)] = None
    stem_diameter_mm: Optional[Length(1.0, 100.0, low_open=False)] = None
    cam_width_mm: Optional[Length(1.0, 200.0, low_open=False)] = None
    camshaft_diameter_mm: Optional[Length(2.0, 500.0, low_open=False)] = None
    camshaft_bore_mm: Length(0.0, 500.0, low_open=False) = 0.0
    camshaft_span_mm: Optional[Length(5.0, 2000.0, low_open=False)] = None
    cam_to_bearing_mm: Optional[Length(0.5, 2000.0, low_open=False)] = None
    camshaft_modulus_MPa: _bounded(1e3, 1e6, "MPa") = 2.1e5
    camshaft_deflection_coefficient: _bounded(0.01, 100.0, low_open=False) = 64.0 / (3.0 * math.pi)
    tappet_diameter_mm: Optional[Length(2.0, 500.0, low_open=False)] = None
    tappet_face_diameter_mm: Optional[Length(2.0, 500.0, low_open=False)] = None
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
    rocker_pivot_ball_radius_mm: Optional[Length(0.5, 100.0, low_open=False)] = None
    rocker_pivot_seat_radius_mm: Optional[Length(0.5, 100.0, low_open=False)] = None
    finger_section_width_mm: Optional[Length(0.5, 100.0, low_open=False)] = None
    finger_section_height_mm: Optional[Length(0.5, 100.0, low_open=False)] = None
    bridge_span_mm: Optional[Length(5.0, 500.0, low_open=False)] = None
    bridge_width_mm: Optional[Length(1.0, 200.0, low_open=False)] = None
    bridge_height_mm: Optional[Length(1.0, 200.0, low_open=False)] = None

    @model_validator(mode="after")
    def _consistent(self):
        problems = []
        if self.camshaft_span_mm is not None and self.cam_to_bearing_mm is not None \
                and self.cam_to_bearing_mm >= self.camshaft_span_mm:
            problems.append(note("spec.must_be_smaller", key="cam_to_bearing_mm", value=self.cam_to_bearing_mm,
                                                         other="camshaft_span_mm", limit=self.camshaft_span_mm))
        for outer, inner in (("camshaft_diameter_mm", "camshaft_bore_mm"), ("pushrod_diameter_mm", "pushrod_bore_mm"),
                             ("rocker_shaft_diameter_mm", "rocker_shaft_bore_mm")):
            o, i = getattr(self, outer), getattr(self, inner)
            if o is not None and i >= o:
                problems.append(note("spec.must_be_smaller", key=inner, value=i, other=outer, limit=o))
        for ball, socket in (("ball_radius_mm", "socket_radius_mm"),
                             ("rocker_pivot_ball_radius_mm", "rocker_pivot_seat_radius_mm")):
            b, s = getattr(self, ball), getattr(self, socket)
            if b is not None and s is not None and s <= b:
                problems.append(note("spec.must_exceed", key=socket, value=s, other=ball, limit=b))
        if problems:
            raise InputError(NoteText(sum(problems, ())))
        return self


class Dynamics(_Model):
    """[valves.NAME.dynamics]: the elastic valve train over a speed range (Shang Hanji 1988, ch. 3).

    A key left out is estimated from what the specification has (the reduced mass, the designed
    spring, the part geometry of [parts]); results.json states each estimate.  ``spring_rate_N_per_mm``
    and ``spring_preload_N`` replace the designed spring in the dynamics alone, in either model (a train
    given as a whole, e.g. a published worked example); a preload given without a rate sizes the rate as
    Valve-train dynamics article (n.d.), step 4a: (K_3 M |j_min| - P_0) / h_max with K_3 =
    drive.spring_reserve at the rated speed.  ``mass_kg`` replaces the one-mass train's reduced mass; the
    multi-mass train takes its drive masses from [drive.masses] and, with ``spring_mass_kg``, a given
    mass of the active coils.  ``revolutions`` is the most camshaft revolutions a speed runs: it stops
    once its motion repeats (default 3; 20 with a ``[lash_adjuster]``,
    whose plunger settles over several revolutions: :data:`valvetrain.design.dynamics.REVOLUTIONS`).  A sweep estimated above the limits of work or memory is refused unless
    ``allow_large_sweep = true``."""

    model: Literal["1dof", "multi"] = "1dof"
    drive_stiffness_N_per_mm: Optional[_bounded(100.0, 1e6, "N/mm", low_open=False)] = None
    damping_ratio: _bounded(0.0, 0.5, low_open=False) = 0.05
    seat_stiffness_N_per_mm: _bounded(1e3, 1e7, "N/mm", low_open=False) = 2e5
    seat_damping_ratio: _bounded(0.0, 1.0, low_open=False, high_open=True) = 0.4
    speed_range_rpm: Optional[Pair(10.0, 30000.0, "rpm")] = None
    speeds: Whole(2, 2000) = 200
    revolutions: Optional[Whole(1, 20)] = None
    coils_per_spring: Whole(0, 64) = 8
    step_cam_deg: _bounded(0.01, 2.0, "deg", low_open=False) = 0.1
    mass_kg: Optional[_bounded(0.001, 50.0, "kg", low_open=False)] = None
    spring_rate_N_per_mm: Optional[_bounded(0.0, 1e6, "N/mm", low_open=False)] = None
    spring_preload_N: Optional[_bounded(0.0, 1e6, "N", low_open=False)] = None
    spring_mass_kg: Optional[_bounded(LEAST_PART_MASS_KG, 5.0, "kg", low_open=False)] = None
    allow_large_sweep: bool = False

    @model_validator(mode="after")
    def _range_and_step(self):
        problems = []
        if self.speed_range_rpm is not None and self.speed_range_rpm[0] >= self.speed_range_rpm[1]:
            problems.append(note("spec.speed_range", pair=f"{list(self.speed_range_rpm)}"))
        n = 360.0 / self.step_cam_deg
        if abs(n - round(n)) > 1e-6:
            problems.append(note("spec.step_cam", step=self.step_cam_deg))
        if self.mass_kg is not None and self.model == "multi":
            problems.append(note("spec.one_mass_only"))
        if self.spring_mass_kg is not None and self.model == "1dof":
            problems.append(note("spec.multi_mass_only"))
        if self.spring_rate_N_per_mm == 0.0 and self.spring_preload_N == 0.0:
            problems.append(note("spec.no_spring"))
        if problems:
            raise InputError(NoteText(sum(problems, ())))
        return self


class Grinding(_Model):
    """[valves.NAME.grinding]: the cam's copy grinder, its master cam and the effect of wheel wear (Shang Hanji (1988),
    ch. 6).

    The master turns with the cam; its follower (a roller) moves ``bar_ratio`` times as far as the wheel centre.
    ``master_base_radius_mm`` left out makes the master's pitch curve the wheel-centre path scaled by the bar ratio
    (with bar ratio 1 and a master roller as large as the wheel the master is the cam itself).
    ``wear_compensation``: ``"none"``, the worn wheel runs on the design centre path (the base circle grows by the
    wear); ``"infeed"``, the head is fed in by the wear to restore the base circle."""

    wheel_radius_mm: Length(5.0, 1000.0, low_open=False)
    master_follower_radius_mm: Length(1.0, 1000.0, low_open=False)
    bar_ratio: _bounded(0.1, 10.0, low_open=False) = 1.0
    master_base_radius_mm: Optional[Length(5.0, 5000.0, low_open=False)] = None
    wheel_wear_mm: _bounded(0.0, 50.0, "mm", low_open=False) = 0.5
    wear_compensation: Literal["none", "infeed"] = "none"

    @model_validator(mode="after")
    def _wear_below_radius(self):
        if self.wheel_wear_mm >= self.wheel_radius_mm:
            raise InputError(NoteText(note("spec.wheel_wear", wear=self.wheel_wear_mm, radius=self.wheel_radius_mm)))
        return self


class LostMotion(_Model):
    """[valves.NAME.hydraulic.lost_motion]: a lost-motion drive (the MultiAir/UniAir intake, Bernard et al. (2009)): a
    solenoid valve from the pump chamber to an accumulator and a hydraulic brake on the actuator piston.

    ``solenoid_opens_crank_deg``: the timings to simulate, each where the solenoid valve opens and lets the pump's oil
    out to the accumulator, a cycle crank angle from the gas-exchange TDC (0...720) within the cam's lift: the valve
    then closes on its spring, before the cam does (an early closing); 1 to 12 timings.  ``solenoid_closes_crank_deg``:
    where the solenoid valve shuts (left out: before the cam lifts, the valve opens with the cam; later: the valve
    opens late).  ``solenoid_area_mm2``: the open valve's flow area, ``solenoid_stroke_us`` the time it takes to open
    or shut, ``discharge_coefficient`` that of its orifice and of the brake's.  ``accumulator_pressure_MPa``: the
    accumulator's absolute pressure (left out: the drive's ``initial_pressure_MPa``); at most the pressure that lifts
    the valve at rest.  ``brake_travel_mm``: the valve's last travel before its seat over which the brake's orifice
    closes down from ``brake_open_area_mm2`` to ``brake_end_area_mm2`` at the seat (0: no brake).  ``sweep``: each
    timing also at every speed of the [hydraulic] chapter's sweep (its landing velocity and closing against the
    speed).  The [hydraulic] chapter is the drive with the solenoid valve shut (the valve follows the whole cam) and
    the brake."""

    solenoid_opens_crank_deg: Annotated[list[_bounded(0.0, 720.0, "crank deg", low_open=False, high_open=True)],
                                        Field(min_length=1, max_length=12)]
    solenoid_closes_crank_deg: Optional[_bounded(0.0, 720.0, "crank deg", low_open=False, high_open=True)] = None
    solenoid_area_mm2: _bounded(0.01, 1000.0, "mm2", low_open=False)
    solenoid_stroke_us: _bounded(0.0, 10000.0, "us", low_open=False) = 500.0
    discharge_coefficient: _bounded(0.1, 1.0, low_open=False) = 0.7
    accumulator_pressure_MPa: Optional[_bounded(0.0, 100.0, "MPa")] = None
    brake_travel_mm: _zero_or(0.01, 50.0, "mm", zero="field.zero_no_brake") = 0.0
    brake_end_area_mm2: _bounded(0.001, 1000.0, "mm2", low_open=False) = 1.0
    brake_open_area_mm2: _bounded(0.001, 1000.0, "mm2", low_open=False) = 20.0
    sweep: bool = False

    @model_validator(mode="after")
    def _brake_closes_down(self):
        if self.brake_travel_mm > 0.0 and self.brake_end_area_mm2 > self.brake_open_area_mm2:
            raise InputError(NoteText(note("spec.brake_area", end=self.brake_end_area_mm2, most=self.brake_open_area_mm2)))
        return self


class Hydraulic(_Model):
    """[valves.NAME.hydraulic]: hydraulic valve actuation (Shang Hanji (1988), ch. 7): the valve's cam drives a
    plunger that feeds a pipe to an actuator piston on the valve (one mass on a spring and a seat).

    The section belongs to a valve, not to the engine, because each valve's own cam drives its plunger.
    Pressures are absolute.  ``speed_rpm`` is the engine speed of the simulation (the rated speed if left out);
    ``speed_range_rpm`` the engine speeds of the sweep, ``speeds`` of them (50 % to 110 % of the rated speed if
    left out).  ``pipe_wall_mm``
    left out makes the pipe rigid.  ``fill_pressure_MPa`` gives the pump chamber a fill (check) valve from a supply
    at that pressure, ``relief_pressure_MPa`` a relief valve opening at it.  The valve's mass, spring and damping are
    the ones of the hydraulic drive and stand apart from the mechanical spring design.  The valve's travel ends at
    a stop ``stop_margin_mm`` above the rigid drive's largest lift (10 % of that lift if left out), of rate
    ``stop_stiffness_N_per_mm``.  A ``lost_motion`` section makes it a lost-motion drive (:class:`LostMotion`).
    ``vapour_pressure_MPa`` is 0 (cavitation at absolute zero) or at least 1e-6 MPa, 1 Pa: the cavitation check's
    margin is the smallest pressure's distance from it relative to it, which a smaller vapour pressure puts beyond
    1e5 and one near zero overflowed."""

    speed_rpm: Optional[_bounded(1.0, 30000.0, "rpm", low_open=False)] = None
    speed_range_rpm: Optional[Pair(1.0, 30000.0, "rpm")] = None
    speeds: Whole(2, 200) = 12
    plunger_diameter_mm: Length(1.0, 1000.0, low_open=False)
    pump_volume_cm3: _bounded(0.001, 1e6, "cm3", low_open=False)
    pipe_length_mm: Length(1.0, 100000.0, low_open=False)
    pipe_diameter_mm: Length(0.5, 500.0, low_open=False)
    pipe_wall_mm: Optional[Length(0.1, 200.0, low_open=False)] = None
    pipe_wall_modulus_GPa: _bounded(1.0, 1000.0, "GPa", low_open=False) = 210.0
    friction_factor: _bounded(0.0, 1.0, low_open=False) = 0.03
    reaches: Whole(1, 400) = 20
    actuator_diameter_mm: Length(1.0, 1000.0, low_open=False)
    actuator_volume_cm3: _bounded(0.001, 1e6, "cm3", low_open=False)
    valve_mass_kg: _bounded(0.001, 1000.0, "kg", low_open=False)
    spring_rate_N_per_mm: _bounded(0.0, 1e6, "N/mm", low_open=False)
    spring_preload_N: _bounded(0.0, 1e7, "N", low_open=False)
    damping_N_s_per_m: _bounded(0.0, 1e7, "N s/m", low_open=False) = 0.0
    density_kg_m3: _bounded(100.0, 20000.0, "kg/m3", low_open=False) = 870.0
    bulk_modulus_GPa: _bounded(0.01, 100.0, "GPa", low_open=False) = 1.5
    vapour_pressure_MPa: _zero_or(1e-6, 1.0, "MPa", zero="field.zero_cavitation") = 0.002
    initial_pressure_MPa: _bounded(0.0, 100.0, "MPa", low_open=False) = 0.3
    back_pressure_MPa: _bounded(0.0, 100.0, "MPa", low_open=False) = 0.1
    leakage_cm3_per_s_MPa: _bounded(0.0, 1e6, "cm3/(s MPa)", low_open=False) = 0.0
    fill_pressure_MPa: Optional[_bounded(0.0, 100.0, "MPa", low_open=False)] = None
    fill_conductance_cm3_per_s_MPa: _bounded(0.0, 1e9, "cm3/(s MPa)") = 1000.0
    relief_pressure_MPa: Optional[_bounded(0.0, 1000.0, "MPa")] = None
    relief_conductance_cm3_per_s_MPa: _bounded(0.0, 1e9, "cm3/(s MPa)") = 1000.0
    stop_margin_mm: Optional[Length(0.0, 500.0, low_open=False)] = None
    stop_stiffness_N_per_mm: _bounded(1.0, 1e8, "N/mm", low_open=False) = 1e5
    lost_motion: Optional[LostMotion] = None

    @model_validator(mode="after")
    def _pressures_in_order(self):
        problems = []
        held = self.spring_preload_N / (math.pi * (self.actuator_diameter_mm * 1e-3) ** 2 / 4.0) / 1e6
        if self.initial_pressure_MPa > self.back_pressure_MPa + held:
            problems.append(note("spec.initial_lifts", initial=self.initial_pressure_MPa, preload=self.spring_preload_N,
                                                       held=self.back_pressure_MPa + held))
        if self.speed_range_rpm is not None and self.speed_range_rpm[0] >= self.speed_range_rpm[1]:
            problems.append(note("spec.speed_range", pair=f"{list(self.speed_range_rpm)}"))
        if self.vapour_pressure_MPa >= self.initial_pressure_MPa:
            problems.append(note("spec.must_be_below", key="vapour_pressure_MPa", value=self.vapour_pressure_MPa,
                                                       other="initial_pressure_MPa", limit=self.initial_pressure_MPa))
        if self.relief_pressure_MPa is not None and self.relief_pressure_MPa <= self.initial_pressure_MPa:
            problems.append(note("spec.must_be_above", key="relief_pressure_MPa", value=self.relief_pressure_MPa,
                                                       other="initial_pressure_MPa", limit=self.initial_pressure_MPa))
        accumulator = None if self.lost_motion is None else self.lost_motion.accumulator_pressure_MPa
        if accumulator is not None and not self.vapour_pressure_MPa < accumulator <= self.back_pressure_MPa + held:
            problems.append(note("spec.accumulator", accumulator=accumulator, vapour=self.vapour_pressure_MPa,
                                                     held=self.back_pressure_MPa + held))
        if (self.relief_pressure_MPa is not None and self.fill_pressure_MPa is not None
                and self.relief_pressure_MPa <= self.fill_pressure_MPa):
            problems.append(note("spec.must_be_above", key="relief_pressure_MPa", value=self.relief_pressure_MPa,
                                                       other="fill_pressure_MPa", limit=self.fill_pressure_MPa))
        if problems:
            raise InputError(NoteText(sum(problems, ())))
        return self


class Lubrication(_Model):
    """[valves.NAME.lubrication]: the oil film and the friction of the cam contact over the speed range (Dowson and
    Higginson (1977); Hamrock, Schmid and Jacobson (2004); Blok (1937)).

    The oil is taken at the inlet of the contact at ``oil_temperature_C``; roughnesses are RMS (R_q).  The friction
    coefficient falls linearly in the film parameter from ``boundary_friction`` (lambda <= 1) to
    ``full_film_friction`` (lambda >= 3); a roller adds ``roller_rolling_friction`` x load on its rolling velocity
    and slides with ``roller_slip`` of the cam's surface velocity.

    Defaults: ``oil_viscosity_mPa_s`` = 10 at ``oil_temperature_C`` = 100 is an SAE 30 (or xW-30) oil of SAE J300
    (2015), whose kinematic viscosity at 100 degC is 9.3 to below 12.5 mm^2/s: 10 mPa s is inside that range for an
    oil density of 0.80 to 1.07 g/cm^3 (an engine oil's density near 100 degC, about 0.8 to 0.85 g/cm^3, is a typical
    value, not from J300).  The other defaults are typical values chosen without a cited source:
    ``pressure_viscosity_per_GPa`` = 20 (a mineral oil), the roughnesses of a ground cam (0.2 um) and a polished
    follower (0.1 um), ``boundary_friction`` = 0.12, ``full_film_friction`` = 0.04, ``roller_rolling_friction`` =
    0.005 and the limits ``min_film_parameter`` = 1 (where Hamrock, Schmid and Jacobson (2004) put the start of
    boundary lubrication; at least 1e-4: a ten-thousandth of the roughness, 0.02 nm for the default finishes, a
    tenth of an atom, asks for no film, and a value near zero overflows the check's margin) and ``max_contact_temperature_C`` = 150 (the critical temperature of Blok (1937) is a property
    of each oil; 150 is a typical value)."""

    oil_viscosity_mPa_s: _bounded(0.1, 2000.0, "mPa s") = 10.0
    pressure_viscosity_per_GPa: _bounded(1.0, 60.0, "1/GPa") = 20.0
    oil_temperature_C: _bounded(-40.0, 250.0, "degC", low_open=False) = 100.0
    cam_roughness_um: _bounded(0.005, 10.0, "um") = 0.2
    follower_roughness_um: _bounded(0.005, 10.0, "um") = 0.1
    boundary_friction: _bounded(0.01, 0.5) = 0.12
    full_film_friction: _bounded(0.001, 0.3) = 0.04
    roller_rolling_friction: _bounded(0.0, 0.1, low_open=False) = 0.005
    roller_slip: _bounded(0.0, 1.0, low_open=False) = 0.0
    min_film_parameter: _bounded(1e-4, 10.0, low_open=False) = 1.0
    max_contact_temperature_C: _bounded(0.0, 1000.0, "degC") = 150.0

    @model_validator(mode="after")
    def _consistent(self):
        problems = []
        if self.full_film_friction > self.boundary_friction:
            problems.append(note("spec.must_not_exceed", key="full_film_friction", value=self.full_film_friction,
                                                         other="boundary_friction", limit=self.boundary_friction))
        if self.max_contact_temperature_C <= self.oil_temperature_C:
            problems.append(note("spec.must_exceed", key="max_contact_temperature_C",
                                                     value=self.max_contact_temperature_C, other="oil_temperature_C",
                                                     limit=self.oil_temperature_C))
        if problems:
            raise InputError(NoteText(sum(problems, ())))
        return self


AXIS_ANGLE = _bounded(-180.0, 180.0, "deg", low_open=False)
"""The bounds of ``[lash_adjuster] axis_angle_deg``: a direction from the follower's (+y) clockwise."""


class LashAdjuster(_Model):
    """[valves.NAME.lash_adjuster]: a hydraulic lash adjuster (zero lash on the base circle): its oil column's
    compliance joins the drive stiffness of the dynamics, its leak-down and refill are followed per camshaft
    revolution, and a float of the follower pumps it up (Merritt (1967)).

    ``location``: ``"pivot"`` (the pivot of an end-pivot finger follower: it moves the valve by (i - 1) times its own
    motion and carries (i - 1) times the valve force) or ``"tappet"`` (in the tappet or bucket: i times its motion,
    the cam force).  ``axis_angle_deg``: at the pivot of a finger given by its geometry (``follower = "finger"``), the
    adjuster's axis from +y clockwise (default: the valve's, ``finger_valve_angle_deg``, the bore parallel to the valve
    stem); its motion ratio is then the finger's linkage on the heel circle
    (:func:`valvetrain.lash_adjuster.pivot_motion_ratio`), not the straight lever's i - 1.  A tappet's adjuster moves
    along the tappet, a rocker's of a given ``rocker_ratio`` along the straight lever's normal: no axis to give.

    ``ramp_height_mm``: the height of the cam's quieting ramps at the cam (as ``clearance_mm``), allowed with a ramped
    law (its ramp keys as for a mechanical train); absent, a ramp is refused.  A hydraulic train has no clearance for a
    ramp to take up: the ramp lifts the valve at its small end velocity, so that it leaves and meets its seat slowly
    (the dynamics simulate no lash; flow and timing count the valve's lift from the ramp's end, the ramp's lift
    being at most 0.05 mm).  The band (0, 0.05] mm is an engineering assumption: no published band of the quieting
    ramps of hydraulic cams was found; a mechanical clearance is 0.25-0.35 mm (Valve-train practical works (n.d.),
    work 2), so a ramp of at most a fifth of the smallest of it is "small".

    ``plunger_eccentricity``: e / c, the offset of the plunger's axis in its bore over the radial clearance, 0
    (concentric) to 1 (touching the bore on one side); the clearance leaks 1 + 1.5 (e / c)^2 times the concentric
    leakage (Merritt (1967); White (2006)), 2.5 times fully eccentric.  Default 0, the concentric plunger: the least
    leak-down, the safe side of the pump-up (a leakier plunger sinks back faster); the leak-down and the lash it
    leaves at the valve grow with it.

    ``plunger_travel_mm``: the plunger's travel from its working position (the valve seated, no lash, on the base
    circle) out to its stop (the retaining ring), at the adjuster: pump-up extends it no further, and the valve it then
    holds off its seat settles there.  Default 1.0 mm, the middle of the 0.5-1.5 mm (0.020-0.060 in) a hydraulic
    lifter's plunger is set below its retaining lock in most applications (Engine Builder (2011)).

    Defaults: ``oil_viscosity_mPa_s`` = 10 is an SAE 30 (or xW-30) oil near 100 degC (SAE J300 (2015), as in
    ``[lubrication]``).  The other defaults are typical values of a passenger-car adjuster chosen without a cited
    source (its dimensions, the supply pressure, the plunger spring, the oil's bulk modulus of 1.5 GPa and its 2 %
    free air); Merritt (1967) gives the formulas they enter, not these values."""

    location: Literal["pivot", "tappet"] = "pivot"
    axis_angle_deg: Optional[AXIS_ANGLE] = None
    ramp_height_mm: Optional[Length(0.0, 0.05)] = None
    plunger_diameter_mm: Length(2.0, 50.0, low_open=False) = 9.0
    radial_clearance_um: _bounded(0.5, 50.0, "um", low_open=False) = 4.0
    leak_length_mm: Length(0.5, 100.0, low_open=False) = 8.0
    chamber_volume_cm3: _bounded(0.001, 50.0, "cm3", low_open=False) = 0.15
    oil_viscosity_mPa_s: _bounded(0.1, 2000.0, "mPa s") = 10.0
    bulk_modulus_GPa: _bounded(0.1, 5.0, "GPa") = 1.5
    air_content: _bounded(0.0, 0.5, low_open=False) = 0.02
    supply_pressure_MPa: _bounded(0.0, 2.0, "MPa", low_open=False) = 0.3
    plunger_spring_N: _bounded(0.0, 500.0, "N", low_open=False) = 15.0
    check_valve_diameter_mm: Length(0.2, 20.0, low_open=False) = 2.0
    plunger_eccentricity: _bounded(0.0, 1.0, low_open=False, high_open=False) = 0.0
    plunger_travel_mm: Length(0.01, 20.0, low_open=False) = 1.0

    @model_validator(mode="after")
    def _refills(self):
        if self.supply_pressure_MPa == 0.0 and self.plunger_spring_N == 0.0:
            raise InputError(NoteText(note("spec.nothing_refills")))
        return self


class Phaser(_Model):
    """[valves.NAME.phaser]: a cam phaser on the camshaft that drives the valve: it turns the camshaft against its
    drive, so every event of the valve moves by the same crank angle.

    ``advance_range_crank_deg``: the phaser's range ``[low, high]`` in crank degrees, an advance positive (the events
    earlier: the valve opens and closes ``advance`` crank degrees sooner), a retard negative; 0 is the designed timing
    (``opens_deg``, ``closes_deg``, or the measured table's), which the range must hold (a phaser's locked home
    position is usually one end of it).  Each allowed [-90, 90] crank deg (45 camshaft degrees of a four-stroke:
    an engineering bound of this package, no published one).  ``step_crank_deg``:
    the map's step, the phases from ``low`` to ``high`` at most this far apart (0 among them).
    ``tolerance_crank_deg``: how closely the best phase at each speed is found (a bounded one-dimensional search
    between the map's neighbours of its best point)."""

    advance_range_crank_deg: Pair(-90.0, 90.0, "crank deg")
    step_crank_deg: _bounded(0.5, 180.0, "crank deg", low_open=False) = 10.0
    tolerance_crank_deg: _bounded(0.01, 5.0, "crank deg", low_open=False) = 0.5

    @model_validator(mode="after")
    def _holds_the_designed_timing(self):
        low, high = self.advance_range_crank_deg
        if not low <= 0.0 <= high or low == high:
            raise InputError(NoteText(note("spec.advance_range", low=low, high=high)))
        return self


class Valve(_Model):
    """[valves.NAME]: one valve (or a set of same-name valves) of a cylinder."""

    kind: Literal["intake", "exhaust"]
    count: Whole(1, 8) = 1
    throat_diameter_mm: Length(2.0, 1000.0, low_open=False)
    seat_angle_deg: _bounded(0.0, 75.0, "deg", low_open=False)
    max_lift_mm: Optional[Length(0.3, 500.0, low_open=False)] = None
    clearance_mm: _zero_or(0.01, 5.0, "mm", zero="field.zero_no_clearance")
    opens_deg: Optional[_bounded(-180.0, 180.0, "deg")] = None
    closes_deg: Optional[_bounded(-180.0, 180.0, "deg")] = None
    rocker_ratio: _bounded(0.2, 5.0, low_open=False) = 1.0
    piston_gap_tdc_mm: Optional[Length(-100.0, 500.0)] = None
    cam: Cam
    drive: Drive = Drive()
    spring: Spring = Spring()
    parts: Parts = Parts()
    dynamics: Optional[Dynamics] = None
    grinding: Optional[Grinding] = None
    hydraulic: Optional[Hydraulic] = None
    lubrication: Optional[Lubrication] = None
    lash_adjuster: Optional[LashAdjuster] = None
    phaser: Optional[Phaser] = None
    switching: Optional[Switching] = None

    @property
    def layout(self) -> str:
        """Drive layout: as given, else direct for rocker ratio 1 and pushrod otherwise."""
        return layout(self)


class Output(_Model):
    """[output]: tables and exports."""

    table_step_cam_deg: _bounded(0.05, 10.0, "deg", low_open=False) = 0.5
    contour_points: Whole(36, 100000) = 721
    export_step_deg: _bounded(0.1, 10.0, "deg", low_open=False) = 0.25


_TEXT = Annotated[str, Field(max_length=200)]


class Document(_Model):
    """[document]: the title page of the calculation note (report.html, GOST 7.32 / 2.105); every key optional,
    printed as given, a key left out a blank line to fill in by hand: the organisation and its department, the course
    (discipline) the note is written for, the document's title and number, who performed it (``author``, with the
    student's ``group``), who supervised and who checked it, the city and year (and a date)."""

    number: Optional[_TEXT] = None
    title: Optional[_TEXT] = None
    organisation: Optional[_TEXT] = None
    department: Optional[_TEXT] = None
    discipline: Optional[_TEXT] = None
    author: Optional[_TEXT] = None
    group: Optional[_TEXT] = None
    supervisor: Optional[_TEXT] = None
    checker: Optional[_TEXT] = None
    city: Optional[_TEXT] = None
    year: Optional[Whole(1900, 2100)] = None
    date: Optional[_TEXT] = None


_NAME = re.compile(r"^[A-Za-z][A-Za-z0-9_-]{0,31}$")


class Acceptance(_Model):
    """[[accepted]]: a check the user accepts outside its range, with the reason (see :mod:`valvetrain.checks`).

    ``quantity`` is the check's code (``"law.kurz.phi2_to_phi3"``, docs/checks.md) or its quantity as printed
    (``"intake: Phi2/Phi3"``) or, for a valve's check, without the valve (``"Phi2/Phi3"``: every valve, or the one
    ``valve`` names); :func:`valvetrain.checks.resolve` maps a text to its code.  A failure (a strength or spring limit) can be
    accepted like a warning; it stays marked as a failure."""

    quantity: Annotated[str, Field(min_length=1, max_length=200)]
    reason: Annotated[str, Field(max_length=2000)]
    valve: Optional[str] = None

    @field_validator("quantity", "reason")
    @classmethod
    def _not_blank(cls, text):
        if not text.strip():
            raise InputError(NoteText(note("spec.blank_reason")))
        return text


class Tolerance(_Model):
    """[[tolerances]]: the distribution of one key of the file for ``valvetrain tolerance`` (a Monte Carlo or Latin
    hypercube study over the tolerances; ``valvetrain run`` ignores them).

    ``key`` is a dotted key of the file as ``valvetrain study --grid`` names it (``valves.intake.clearance_mm``), in
    the key's unit; the file's value of the key is the nominal.  ``uniform``: nominal +- ``half_range``, or
    [``low``, ``high``]; ``normal``: mean the nominal, standard deviation ``sigma``, truncated to [``low``,
    ``high``] where they are given (else at +-6 sigma).  Every value of the range must be a value the key
    allows (checked before any sample is drawn)."""

    key: Annotated[str, Field(min_length=3, max_length=200)]
    distribution: Literal["uniform", "normal"]
    half_range: Optional[_bounded(0.0, 1e6)] = None
    sigma: Optional[_bounded(0.0, 1e6)] = None
    low: Optional[float] = None
    high: Optional[float] = None

    @model_validator(mode="after")
    def _parameters(self):
        bounds = self.low is not None, self.high is not None
        if self.distribution == "uniform":
            if self.sigma is not None:
                raise InputError(NoteText(note("spec.sigma_uniform", key=self.key)))
            if not ((self.half_range is None and all(bounds)) or (self.half_range is not None and not any(bounds))):
                raise InputError(NoteText(note("spec.uniform_bounds", key=self.key)))
        else:
            if self.sigma is None or self.half_range is not None:
                raise InputError(NoteText(note("spec.normal_sigma", key=self.key)))
        if all(bounds) and self.low >= self.high:
            raise InputError(NoteText(note("spec.low_below_high", key=self.key, low=self.low, high=self.high)))
        return self


class Spec(_Model):
    """A whole design specification."""

    engine: Engine
    valves: dict[str, Valve] = {}
    gas: Gas = Gas()
    crank: Optional[CrankSpec] = None
    camshaft: Optional[Camshaft] = None
    two_stroke: Optional[TwoStroke] = None
    breathing: Optional[Breathing] = None
    output: Output = Output()
    document: Document = Document()
    accepted: list[Acceptance] = []
    tolerances: list[Tolerance] = []
    source_dir: Optional[str] = Field(default=None, exclude=True)
    """Folder of the specification file: relative file names (pressure_file) are read from there."""

    @field_validator("valves")
    @classmethod
    def _valve_names(cls, valves):
        bad = [shown(n, 40) for n in valves if not _NAME.match(n) or n in ("crank", "two_stroke", "breathing")]
        if bad:
            raise InputError(NoteText(note("spec.valve_names", names=", ".join(bad))))
        return valves

    def replace(self, values) -> "Spec":
        """A copy with the dotted keys of ``values`` changed, validated like a specification file.

        The keys are those of ``valvetrain study --grid``: the path of TOML tables, then the key, in the file's units
        (``{"engine.bore_mm": 85.0, "valves.intake.cam.shape_factor": 0.6}``).  This is the one way to change a
        validated specification (``model_copy(update=...)`` validates nothing; :func:`valvetrain.design.run` refuses
        what it makes if that is not valid).

        Parameters
        ----------
        values : dict
            Dotted key -> value.

        Returns
        -------
        Spec

        Raises
        ------
        valvetrain.specification.SpecError
            One message per problem, naming the key, the value and what is allowed.
        """
        try:
            document = set_keys(spec_document(self), values)
        except ValueError as exc:
            raise SpecError([exc.args[0]]) from None
        return validate(document)

    @model_validator(mode="after")
    def _something_to_design(self):
        if not self.valves and self.crank is None and self.two_stroke is None and self.breathing is None:
            raise InputError(NoteText(note("spec.nothing_to_design")))
        return self


def _resolve_tables(spec):
    """Make every valve's table_file absolute (relative to the specification file's folder)."""
    valves = {}
    for name, v in spec.valves.items():
        if v.cam.law == "table" and v.cam.table_file is not None:
            cam = v.cam.model_copy(update={"table_file": str(resolve_path(spec, v.cam.table_file))})
            v = v.model_copy(update={"cam": cam})
        valves[name] = v
    return spec.model_copy(update={"valves": valves})


def validate(data) -> Spec:
    """Validate a parsed TOML document; return a :class:`Spec` or raise :class:`SpecError`.

    Field problems (missing keys, wrong types, values outside physical bounds) are
    reported first; the cross-checks between keys (angles that must add up, a throat
    smaller than the bore, ...) run once every field is valid.
    """
    try:
        spec = Spec.model_validate(data)
    except ValidationError as exc:
        raise SpecError([message(err, LAWS) for err in exc.errors()]) from None
    spec = _resolve_tables(spec)
    found = problems(spec)
    if found:
        raise SpecError(found)
    return spec
