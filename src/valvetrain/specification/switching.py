"""[valves.NAME.switching]: the valve's finger is a switching roller finger follower (its inner arm, lost-motion
spring and latch); the physics is :mod:`valvetrain.switching`, the stage :mod:`valvetrain.design.switching`."""

import math
from typing import Literal, Optional

from pydantic import model_validator

from ..errors import InputError
from ..locale import NoteText, note
from ..spring_materials import GRADES
from .fields import Length, _bounded, _Model


class LowLobe(_Model):
    """[valves.NAME.switching.low_lobe]: the second, low-lift lobe of a two-step switching finger, a lift law like the
    valve's own: the cam section's law and coefficients with its own largest valve lift ``max_lift_mm`` and events
    ``opens_deg`` and ``closes_deg`` (crank deg, counted as the valve's own ``opens_deg`` and ``closes_deg``: before the
    dead centre where the stroke starts, after the one where it ends; negative: after it, before it), on the same
    base circle and seen through the same finger; the finger's body follows it unlatched."""

    max_lift_mm: Length(0.3, 500.0, low_open=False)
    opens_deg: _bounded(-180.0, 180.0, "deg")
    closes_deg: _bounded(-180.0, 180.0, "deg")

    @model_validator(mode="after")
    def _an_event(self):
        if self.opens_deg + self.closes_deg + 180.0 <= 0.0:
            raise InputError(NoteText(note("spec.lobe_event", opens=self.opens_deg, closes=self.closes_deg)))
        return self


class Switching(_Model):
    """[valves.NAME.switching]: a switching roller finger follower on a valve whose cam has ``follower = "finger"``:
    the finger's body rests on the pivot (lash adjuster) and the valve, and an inner arm carrying the roller is
    pivoted in it, held on the cam by a lost-motion spring (a helical torsion spring about the arm's pivot); a latch
    pin locks the arm to the body.

    ``mode``: ``"deactivation"``, the unlatched valve stays shut (cylinder deactivation) and the arm follows its cam
    against the lost-motion spring; ``"two_step"``, the unlatched body follows a second, low-lift lobe
    (``[valves.NAME.switching.low_lobe]``, :class:`LowLobe`) and lifts the valve by it while the arm follows the main
    lobe against the lost-motion spring (two-step lift).  ``inner_arm_mm``: the arm's pivot to its roller centre, L_i;
    ``inner_arm_inertia_kg_mm2``: its moment of inertia about that pivot, the roller's included, J_i;
    ``contact_stiffness_N_per_mm``: the arm's stiffness at the roller, cam contact and the arm's bending in series
    (the unlatched arm's dynamics).  ``reserve``: the lost-motion spring's margin over the arm's inertia torque at
    the over-speed (as the valve spring's ``drive.spring_reserve``; default: that key's value).
    ``spring_wire_diameter_mm``, ``spring_mean_diameter_mm``, ``spring_material``: the torsion spring, its active
    coils found from the rate it needs.  ``latch_arm_mm``: the arm's pivot to the latch's contact, L_l;
    ``latch_pin_diameter_mm``, ``latch_width_mm``: the pin and the length of its line contact on its seat;
    ``latch_seat_radius_mm``: the seat's concave radius (larger than the pin's), absent: a flat seat.
    ``speeds``: the speeds of the unlatched arm's dynamic sweep, up to twice the over-speed.

    The breathing of the deactivated cylinder (its valves shut all cycle), with ``compression_ratio``: its trapped
    charge at ``trapped_pressure_kPa`` and ``trapped_temperature_C`` at the bottom dead centre (what the deactivation
    traps: fresh charge or exhaust, as the engine's strategy makes it), the walls at ``wall_temperature_C``; needs
    ``engine.rod_length_mm``; a deactivation's only.

    The latch's switching (all six or none): the pin of ``latch_pin_diameter_mm`` and ``latch_pin_mass_kg`` moves
    over ``latch_stroke_mm`` under the oil's ``oil_pressure_MPa`` (gauge, at the passage) against its return spring
    (``latch_spring_preload_N`` at home, at least 0.01 N, the weight of a gram: a spring that holds less holds no
    pin, and a preload near zero overflowed the return's time bound; ``latch_spring_rate_N_per_mm``), its oil through a passage of
    ``oil_passage_diameter_mm`` (``passage_discharge_coefficient``, ``oil_density_kg_m3``), and back on the spring;
    it may move only while both arms rest on their base circles, the switching window."""

    mode: Literal["deactivation", "two_step"] = "deactivation"
    inner_arm_mm: Length(2.0, 200.0, low_open=False)
    inner_arm_inertia_kg_mm2: _bounded(0.01, 1e5, "kg mm2", low_open=False)
    contact_stiffness_N_per_mm: _bounded(100.0, 1e7, "N/mm", low_open=False)
    reserve: Optional[_bounded(1.0, 5.0, low_open=False)] = None
    spring_wire_diameter_mm: Length(0.2, 10.0, low_open=False)
    spring_mean_diameter_mm: Length(1.0, 60.0, low_open=False)
    spring_material: str = "VDSiCr"
    latch_arm_mm: Length(1.0, 200.0, low_open=False)
    latch_pin_diameter_mm: Length(0.5, 30.0, low_open=False)
    latch_width_mm: Length(0.2, 50.0, low_open=False)
    latch_seat_radius_mm: Optional[Length(0.25, 1000.0, low_open=False)] = None
    speeds: int = 16
    compression_ratio: Optional[_bounded(1.5, 60.0)] = None
    trapped_pressure_kPa: Optional[_bounded(1.0, 10000.0, "kPa")] = None
    trapped_temperature_C: Optional[_bounded(-50.0, 1500.0, "degC")] = None
    wall_temperature_C: Optional[_bounded(-50.0, 1500.0, "degC")] = None
    low_lobe: Optional[LowLobe] = None
    latch_stroke_mm: Optional[Length(0.05, 20.0, low_open=False)] = None
    latch_pin_mass_kg: Optional[_bounded(1e-5, 0.5, "kg", low_open=False)] = None
    latch_spring_preload_N: Optional[_bounded(0.01, 1000.0, "N", low_open=False)] = None
    latch_spring_rate_N_per_mm: Optional[_bounded(0.0, 1000.0, "N/mm", low_open=False)] = None
    oil_pressure_MPa: Optional[_bounded(0.0, 20.0, "MPa")] = None
    oil_passage_diameter_mm: Optional[Length(0.05, 20.0, low_open=False)] = None
    oil_density_kg_m3: _bounded(600.0, 1200.0, "kg/m3", low_open=False) = 870.0
    passage_discharge_coefficient: _bounded(0.1, 1.0) = 0.7

    @model_validator(mode="after")
    def _consistent(self):
        problems = []
        if self.spring_mean_diameter_mm <= 2.0 * self.spring_wire_diameter_mm:
            problems.append(note("spec.spring_index", diameter=self.spring_mean_diameter_mm,
                                 least=2.0 * self.spring_wire_diameter_mm))
        if self.latch_seat_radius_mm is not None and self.latch_seat_radius_mm <= self.latch_pin_diameter_mm / 2.0:
            problems.append(note("spec.latch_seat", radius=self.latch_seat_radius_mm,
                                 pin=self.latch_pin_diameter_mm / 2.0))
        strong = [name for name, g in GRADES.items() if g.tensile is not None]
        if self.spring_material not in strong:
            problems.append(note("spec.torsion_material", material=repr(self.spring_material),
                                 allowed=", ".join(strong)))
        if not 4 <= self.speeds <= 200:
            problems.append(note("spec.switching_speeds", speeds=self.speeds))
        trapped = ("compression_ratio", "trapped_pressure_kPa", "trapped_temperature_C", "wall_temperature_C")
        given = [k for k in trapped if getattr(self, k) is not None]
        if given and len(given) < len(trapped):
            problems.append(note("spec.trapped_keys", given=", ".join(given),
                                 missing=", ".join(k for k in trapped if k not in given)))
        latch = ("latch_stroke_mm", "latch_pin_mass_kg", "latch_spring_preload_N", "latch_spring_rate_N_per_mm",
                 "oil_pressure_MPa", "oil_passage_diameter_mm")
        moving = [k for k in latch if getattr(self, k) is not None]
        if moving and len(moving) < len(latch):
            problems.append(note("spec.latch_keys", given=", ".join(moving),
                                 missing=", ".join(k for k in latch if k not in moving)))
        if len(moving) == len(latch):
            push = self.oil_pressure_MPa * math.pi * self.latch_pin_diameter_mm ** 2 / 4.0
            hold = self.latch_spring_preload_N + self.latch_spring_rate_N_per_mm * self.latch_stroke_mm
            if push <= hold:
                problems.append(note("spec.latch_push", pressure=self.oil_pressure_MPa, push=push, hold=hold))
        if (self.mode == "two_step") != (self.low_lobe is not None):
            problems.append(note("spec.needs_low_lobe" if self.low_lobe is None else "spec.low_lobe_two_step",
                                 mode=repr(self.mode)))
        if self.mode == "two_step" and given:
            problems.append(note("spec.trapped_two_step", given=", ".join(given)))
        if problems:
            raise InputError(NoteText(sum(problems, ())))
        return self
