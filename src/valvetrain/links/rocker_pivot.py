"""The pivot ball of a stud-mounted rocker (a stamped rocker on a ball on its stud, instead of a shaft): the contact
stress of the ball in the rocker's spherical seat under the fulcrum load.

The rocker is a lever of the first kind: the pushrod's force P_T on one arm and the valve's P_T / i_k on the other,
both on the same side, are held by the fulcrum, R = P_T (1 + 1 / i_k) (the arms' forces taken parallel).  A convex
sphere in a concave seat carries sigma = 0.388 (R E^2 (1/r_1 - 1/r_2)^2)^(1/3), the source's formula and allowable for
its ball joints (the pushrod's ball in its socket), applied to the pivot ball.

References
----------
Valve-train practical works (n.d.), work 7, eqs. (7.11), (7.14) (a convex sphere in a concave socket, <= 2000 MPa).
"""

from .. import strength
from .base import Link, register


def fulcrum_load(cam_force, rocker_ratio) -> float:
    """The load on a rocker's fulcrum, R = P_T (1 + 1 / i_k) [N], from the cam force at the pushrod ``cam_force`` [N]
    and the rocker ratio i_k = l_v / l_t.

    Examples
    --------
    A 1000 N pushrod force on a rocker of ratio 1.6 (valve force 625 N):

    >>> fulcrum_load(1000.0, 1.6)
    1625.0
    """
    return cam_force * (1.0 + 1.0 / rocker_ratio)


@register
class RockerPivot(Link):
    """The pivot ball a stud-mounted rocker turns on; a rocker on a shaft has none (its keys not given: no check and
    no note)."""

    name = "rocker_pivot"
    part_keys = ("rocker_pivot_ball_radius_mm", "rocker_pivot_seat_radius_mm")

    def checks(self, loads) -> list:
        """The contact stress of the pivot ball (``rocker_pivot_ball_radius_mm``) in the rocker's seat
        (``rocker_pivot_seat_radius_mm``) under :func:`fulcrum_load` (:func:`valvetrain.strength.sphere_socket_verdict`),
        where the keys are given; a note names the other where only one is."""
        parts = loads.parts
        if parts.rocker_pivot_ball_radius is None and parts.rocker_pivot_seat_radius is None:
            return []
        if not loads.need(["rocker_pivot_ball_radius_mm", "rocker_pivot_seat_radius_mm"], "rocker_pivot_stress"):
            return []
        load = fulcrum_load(loads.cam_force, loads.rocker_ratio)
        return [strength.sphere_socket_verdict("rocker_pivot_stress", load, loads.modulus,
                                               parts.rocker_pivot_ball_radius, parts.rocker_pivot_seat_radius,
                                               loads.where)]
