"""The flat-faced translating follower (a bucket tappet, a mushroom tappet): the cam's support function is its lift.

References
----------
Shang Hanji (1988), section 2.1, eqs. (2.6), (2.12), (2.15); Valve-train practical works (n.d.), eq. (2.38).
"""

from dataclasses import dataclass

import numpy as np

from .. import geometry, tribology
from ..numerics import invert_angle
from ..results import quantity
from .base import Follower, register


@dataclass(frozen=True)
class FlatContact:
    """Where a flat follower touches the cam."""

    max_contact_offset: float = quantity("max_contact_offset_mm", "mm", "largest contact offset from the axis, h'")


@register
class FlatFollower(Follower):
    """A flat face square to its line of action, touching the cam h' off the axis (SI)."""

    name = "flat"
    part_keys = ("tappet_face_diameter_mm",)
    undercut_code = "profile.undercut_flat"
    undercut_source = "Shang Hanji (1988), eq. (2.6); Valve-train practical works (n.d.), corrections note 26"

    def contour(self, theta, heel, h, dh) -> np.ndarray:
        """p = (R0 + h) u + h' t [m] (:func:`valvetrain.geometry.flat_follower_contour`)."""
        return geometry.flat_follower_contour(theta, heel, h, dh)

    def curvature(self, heel, h, dh, d2h) -> float | np.ndarray:
        """rho = R0 + h + h'' [m] (:func:`valvetrain.geometry.flat_follower_curvature`)."""
        return geometry.flat_follower_curvature(heel, h, d2h)

    def pitch_curve(self, theta, heel, h, dh, d2h) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, float]:
        """The contour itself (depth 0): its derivative rho t, radius rho and normal u."""
        u, t = geometry.axes(theta)
        rho = self.curvature(heel, h, dh, d2h)
        return self.contour(theta, heel, h, dh), rho * t, rho, u, 0.0

    def pressure_angle(self, heel, h, dh) -> np.ndarray:
        """Zero: the contact normal is the face's normal, the line of action."""
        return np.zeros_like(np.asarray(h, dtype=float))

    def profile_contact(self, law, heel, max_offset) -> FlatContact:
        """The profile stage's contact record: the largest contact offset ``max_offset`` [m] (the law's largest h'
        per radian, Shang Hanji (1988), eq. 2.15)."""
        return FlatContact(max_offset)

    def face_offset(self, dh) -> np.ndarray:
        """|h'| [m]: the contact point's distance from the face's axis (Shang Hanji (1988), eq. 2.15)."""
        return np.abs(dh)

    def contact_offset(self, dh) -> float | np.ndarray:
        """h' [m]: the contact point's distance from the axis (Shang Hanji (1988), eq. 2.15)."""
        return dh

    def convex_radius(self, rho) -> np.ndarray:
        """rho as it is: a flat face touches only convex stretches, rho <= 0 is its undercut."""
        return np.asarray(rho, dtype=float)

    def concave(self, rho) -> np.ndarray:
        """None: a flat face cannot follow a concave stretch (rho <= 0 is its undercut)."""
        return np.zeros(np.shape(rho), dtype=bool)

    def undercut(self, rho_min) -> bool:
        """rho_min <= 0 (:func:`valvetrain.geometry.undercut_flat`)."""
        return bool(geometry.undercut_flat(rho_min))

    def line_contact(self, rho) -> np.ndarray:
        """Convex stretches, rho > 0."""
        return np.asarray(rho, dtype=float) > 0.0

    def lift_on_path(self, path, theta, base) -> np.ndarray:
        """The support function of the envelope in the direction u(theta) less ``base``: the envelope point whose
        normal points along u."""
        tau = invert_angle(lambda t: np.arctan2(*path(t)[1]), theta)
        e, _ = path(tau)
        return np.sum(e * geometry.axes(theta)[0], axis=0) - base

    def wear_error(self, offset, base, heel, h, dh) -> tuple[float | np.ndarray, float | np.ndarray]:
        """The support function grows by the offset: error offset - base, no phase shift."""
        return offset - base, np.zeros_like(np.asarray(h, dtype=float))

    def surface_velocities(self, omega, heel, h, dh, d2h, rho) -> tuple[np.ndarray, np.ndarray]:
        """omega rho and omega h'' (:func:`valvetrain.tribology.flat_follower_velocities`)."""
        return tribology.flat_follower_velocities(omega, heel, h, d2h)

    def lubrication(self, heel, h, rho) -> float | np.ndarray:
        """gamma = rho / (R0 + h) (Shang Hanji (1988), eq. 2.12; corrections note 34)."""
        return rho / (heel + h)
