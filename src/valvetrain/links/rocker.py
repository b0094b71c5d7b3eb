"""The rocker on its shaft (or a finger's lever, whose pad presses the valve): the contact stress of its pad on the
valve tip and the bending, shear and bearing of its shaft.

References
----------
Valve-train practical works (n.d.), work 7, eqs. (7.13), (7.15)-(7.18) (corrections notes 25, 48).
"""

from .. import strength
from ..locale import note
from ..units import to_display
from .base import Link, register


@register
class Rocker(Link):
    """A rocker on its shaft, its valve arm at the valve."""

    name = "rocker"
    mass_key = "rocker_inertia_kg_mm2"
    mass_attr = "rocker_inertia"
    carrier = "strength.carried_by_rocker"
    joint = "rocker and valve joint"
    lever = True
    part_keys = ("rocker_pad_width_mm", "rocker_pad_radius_mm", "rocker_shaft_span_mm", "rocker_shaft_diameter_mm",
                 "rocker_shaft_bore_mm", "rocker_width_mm")

    def node(self, masses, ratio, arm) -> tuple[str, float]:
        """The rocker's inertia about its shaft on the valve arm, J / l_v^2 [kg] (Valve-train practical works (n.d.),
        eq. 5.2)."""
        return self.name, masses.rocker_inertia / arm**2

    def missing(self, masses, arm) -> list[str]:
        """Its inertia where not positive, and the valve arm where not known."""
        return super().missing(masses, arm) + ([] if arm is not None else ["valve_arm_mm (in [drive])"])

    def checks(self, loads) -> list:
        """The pad's contact stress on the valve tip under the valve force, and the shaft's bending (a built-in
        beam), shear and bearing pressure under the cam force, each where its keys are given."""
        parts, p_max, out = loads.parts, loads.cam_force, []
        if loads.need(["rocker_pad_width_mm", "rocker_pad_radius_mm"], "rocker_pad_stress"):
            out.append(strength.verdict("rocker_pad_stress", strength.rocker_pad_stress(
                loads.valve_force, loads.modulus, parts.rocker_pad_width, parts.rocker_pad_radius), loads.where))
        if loads.need(["rocker_shaft_span_mm", "rocker_shaft_diameter_mm", "rocker_width_mm"], "rocker_shaft"):
            st = strength.rocker_shaft_stresses(p_max, parts.rocker_shaft_span, parts.rocker_width,
                                                parts.rocker_shaft_diameter, parts.rocker_shaft_bore)
            out.append(strength.verdict("rocker_shaft_bending", st["bending"], loads.where + note(
                "strength.rocker_shaft_beam", simply_supported_MPa=to_display(st["bending_simply_supported"], "MPa"))))
            out.append(strength.verdict("rocker_shaft_shear", st["shear"], loads.where))
            out.append(strength.verdict("rocker_shaft_bearing", st["bearing"], loads.where))
        return out
