"""The pushrod between the tappet and the rocker of an overhead-valve train: its buckling, its ball end in the rocker's
socket and the pressure on its head.

References
----------
Valve-train practical works (n.d.), work 7, eqs. (7.8)-(7.12), (7.14) (corrections note 21).
"""

from .. import strength
from ..dynamics.models import pushrod_stiffness
from ..locale import note
from ..units import to_display
from .base import Link, register


@register
class Pushrod(Link):
    """A pushrod, a slender column under the cam force."""

    name = "pushrod"
    mass_key = mass_attr = "pushrod_kg"
    elastic = True
    part_keys = ("pushrod_length_mm", "pushrod_diameter_mm", "pushrod_bore_mm", "pushrod_modulus_MPa", "ball_radius_mm",
                 "socket_radius_mm", "pushrod_head_area_mm2")

    def stiffness(self, parts) -> float | None:
        """Its axial stiffness E A / L (:func:`valvetrain.dynamics.models.pushrod_stiffness`) where its length and
        diameter are given."""
        if None in (parts.pushrod_length, parts.pushrod_diameter):
            return None
        return pushrod_stiffness(parts.pushrod_length, parts.pushrod_diameter, parts.pushrod_bore,
                                 parts.pushrod_modulus)

    def checks(self, loads) -> list:
        """The buckling margin P_cr / P_T (Euler's load of a tube pinned at both ends), the contact stress of its
        ball in the socket and the pressure on its head, each where its keys are given."""
        parts, p_max, out = loads.parts, loads.cam_force, []
        if loads.need(["pushrod_length_mm", "pushrod_diameter_mm"], "pushrod_buckling_margin"):
            inertia = strength.second_moment(parts.pushrod_diameter, parts.pushrod_bore)
            p_cr = strength.euler_load(parts.pushrod_modulus, inertia, parts.pushrod_length)
            out.append(strength.verdict("pushrod_buckling_margin", p_cr / p_max, loads.where + note(
                "strength.euler_load", load_N=p_cr, modulus_MPa=to_display(parts.pushrod_modulus, "MPa"))))
        if loads.need(["ball_radius_mm", "socket_radius_mm"], "ball_socket_stress"):
            out.append(strength.sphere_socket_verdict("ball_socket_stress", p_max, loads.modulus, parts.ball_radius,
                                                      parts.socket_radius, loads.where))
        if loads.need(["pushrod_head_area_mm2"], "pushrod_head_pressure"):
            out.append(strength.verdict("pushrod_head_pressure", p_max / parts.pushrod_head_area, loads.where))
        return out
