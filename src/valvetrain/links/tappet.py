"""The tappet: a follower's body sliding in its guide under the cam (a bucket or mushroom tappet, the lower end of a
pushrod train).

References
----------
Valve-train practical works (n.d.), work 7, eqs. (7.6)-(7.7).
"""

from .. import strength
from ..locale import note
from ..units import to_display
from .base import Link, register


@register
class Tappet(Link):
    """A tappet in its guide: its side pressure where a flat face slides on the cam, its face for the edge loading."""

    name = "tappet"
    mass_key = mass_attr = "tappet_kg"
    carrier = "strength.carried_by_guide"
    joint = "valve stem and tappet"
    part_keys = ("tappet_diameter_mm", "tappet_guide_length_mm")

    def checks(self, loads) -> list:
        """The side pressure on the guide, q = 6 P_T b / (d l^2) (:func:`valvetrain.strength.tappet_side_pressure`),
        with the contact's offset b where a flat face slides on the cam (a roller's side load is its own record)."""
        if loads.guide_offset is None or not loads.need(["tappet_diameter_mm", "tappet_guide_length_mm"],
                                                        "tappet_side_pressure"):
            return []
        parts, b = loads.parts, loads.guide_offset
        q = strength.tappet_side_pressure(loads.cam_force, b, parts.tappet_diameter, parts.tappet_guide_length)
        return [strength.verdict("tappet_side_pressure", q, loads.where + note(
            "strength.tappet_offset", offset_mm=to_display(b, "mm")))]

    def face_diameter(self, parts) -> float | None:
        """The tappet's diameter: a bucket tappet's face is its diameter (``tappet_diameter_mm``)."""
        return parts.tappet_diameter
