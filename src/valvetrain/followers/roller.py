"""The central translating roller follower: its centre runs on the pitch curve, the contour is the inner offset.

References
----------
Shang Hanji (1988), section 2.1, eqs. (2.7), (2.16) (corrections note 33); UkrSURT Proceedings (2019) (pressure
angle).
"""

from dataclasses import dataclass

import numpy as np

from .. import geometry, strength, tribology
from ..checks import Check, check
from ..numerics import extremum, invert_angle
from ..results import quantity
from ..units import DEG
from .base import Follower, register

PRESSURE_ANGLE_MAX = 30.0 * DEG
"""Largest recommended pressure angle of a roller follower [rad] (UkrSURT Proceedings (2019))."""


@dataclass(frozen=True)
class RollerContact:
    """How a roller follower meets the cam."""

    roller_radius: float = quantity("roller_radius_mm", "mm", "roller radius")
    max_pressure_angle: float = quantity("max_pressure_angle_deg", "deg", "largest pressure angle")
    min_concave_radius: float = quantity("min_concave_radius_mm", "mm",
                                         "concave radius closest to zero (null: no concave stretch)")


@register
@dataclass(frozen=True)
class RollerFollower(Follower):
    """A roller of radius ``radius`` [m] whose axis line passes through the cam centre (SI)."""

    radius: float
    name = "roller"
    rolling = True
    undercut_code = "profile.undercut_roller"
    undercut_source = "Shang Hanji (1988), eq. (2.7)"

    @classmethod
    def from_cam(cls, cam) -> "RollerFollower":
        """The roller of ``cam.roller_radius`` [m]."""
        return cls(cam.roller_radius)

    @classmethod
    def missing_key(cls, cam) -> str | None:
        """``roller_radius_mm`` when the cam section does not give it."""
        if cam.roller_radius_mm is None:
            return "roller_radius_mm is required when follower = \"roller\" (allowed [1, 200] mm)"
        return None

    def contour(self, theta, heel, h, dh) -> np.ndarray:
        """The pitch curve offset inwards by the roller radius (:func:`valvetrain.geometry.roller_follower_contour`)."""
        return geometry.roller_follower_contour(theta, heel, self.radius, h, dh)

    def curvature(self, heel, h, dh, d2h) -> float | np.ndarray:
        """rho = rho_pitch - R_r [m] (:func:`valvetrain.geometry.roller_follower_curvature`)."""
        return geometry.roller_follower_curvature(heel, self.radius, h, dh, d2h)

    def pitch_curve(self, theta, heel, h, dh, d2h) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, float]:
        """The roller centre's curve g u, g = R0 + R_r + h (depth -R_r): derivative h' u + g t, its radius, normal
        (g u - h' t) / sqrt(g^2 + h'^2)."""
        u, t = geometry.axes(theta)
        g = geometry.roller_pitch_radius(heel, self.radius, h)
        rho = geometry.roller_pitch_curvature(heel, self.radius, h, dh, d2h)
        return g * u, dh * u + g * t, rho, (g * u - dh * t) / np.hypot(g, dh), -self.radius

    def pressure_angle(self, heel, h, dh) -> float | np.ndarray:
        """tan beta = h' / g (:func:`valvetrain.geometry.roller_pressure_angle`)."""
        return geometry.roller_pressure_angle(heel, self.radius, h, dh)

    def profile_contact(self, law, heel, max_offset) -> RollerContact:
        """The profile stage's contact record of the lift law ``law`` on the heel circle ``heel`` [m]: the roller's
        radius, the largest pressure angle and the concave radius closest to zero (None: no concave stretch the
        roller follows), each refined between the law's breakpoints (``max_offset``, a flat face's, unused)."""
        bp = law.breakpoints
        beta_max = extremum(lambda t: np.abs(law.profile(t, heel, self)[2]), bp, "max")[1]
        # the concave radius closest to zero is the most negative curvature (the radius itself passes through
        # -inf at the inflections, where its minimum would be found)
        curvature = extremum(lambda t: 1.0 / law.curvature(t, heel, self), bp, "min")[1]
        concave = 1.0 / curvature if curvature < 0.0 else 0.0
        return RollerContact(self.radius, beta_max, concave if concave + self.radius < 0.0 else None)

    def limited_contact(self, contact) -> tuple[float, float | None]:
        """The contact record's largest pressure angle [rad] and concave radius closest to zero [m] (or None)."""
        return contact.max_pressure_angle, contact.min_concave_radius

    @classmethod
    def admits(cls, law) -> bool:
        """Every law, those drawn for a translating roller (:data:`~valvetrain.followers.base.ROLLER_LAWS`) too."""
        return True

    def profile_checks(self, contact) -> list[Check]:
        """The largest pressure angle of the contact record against :data:`PRESSURE_ANGLE_MAX`."""
        return [check("profile.pressure_angle.max", contact.max_pressure_angle, high=PRESSURE_ANGLE_MAX,
                      source="UkrSURT Proceedings (2019)", unit="deg")]

    def side_force(self, force, heel, h, dh) -> np.ndarray:
        """P_T tan(beta) [N] at the pressure angle beta (:func:`valvetrain.strength.roller_side_force`)."""
        return strength.roller_side_force(force, self.pressure_angle(heel, h, dh))

    def rolling_losses(self, u_follower, slip, resistance) -> tuple[np.ndarray, float, np.ndarray]:
        """The roller's surface lags the cam's by the share ``slip``; it rolls at that velocity with the rolling
        resistance coefficient ``resistance`` (:func:`valvetrain.tribology.friction_torque`)."""
        u_follower = (1.0 - slip) * u_follower
        return u_follower, resistance, u_follower

    def contact_offset(self, dh) -> np.ndarray:
        """Zero: the roller touches on its centre's normal, reported as no offset from the axis."""
        return np.zeros_like(np.asarray(dh, dtype=float))

    def convex_radius(self, rho) -> np.ndarray:
        """rho where the pitch curve is convex (rho + R_r > 0), +inf on a concave stretch (which the roller
        follows, not an undercut)."""
        rho = np.asarray(rho, dtype=float)
        return np.where(rho + self.radius > 0.0, rho, np.inf)

    def concave(self, rho) -> np.ndarray:
        """Where the pitch curve is concave, rho + R_r < 0."""
        return np.asarray(rho, dtype=float) + self.radius < 0.0

    def undercut(self, rho_min) -> bool:
        """0 < rho_pitch <= R_r at the smallest convex radius (:func:`valvetrain.geometry.undercut_roller`)."""
        return bool(geometry.undercut_roller(rho_min + self.radius, self.radius))

    def line_contact(self, rho) -> np.ndarray:
        """A convex profile, or a concave one wider than the roller (rho < -R_r)."""
        rho = np.asarray(rho, dtype=float)
        return (rho > 0.0) | (rho < -self.radius)

    def surface_velocities(self, omega, heel, h, dh, d2h, rho) -> tuple[np.ndarray, np.ndarray]:
        """The contact point's speed along the profile, both surfaces alike: pure rolling
        (:func:`valvetrain.tribology.roller_follower_velocities`)."""
        return tribology.roller_follower_velocities(omega, heel, self.radius, h, dh, rho)

    def lift_on_path(self, path, theta, base) -> np.ndarray:
        """The roller centre on the envelope's offset by R_r, at the point on the follower axis: |Q| - (base + R_r)."""
        def centre(t):
            e, n = path(t)
            return e + self.radius * n

        tau = invert_angle(lambda t: np.arctan2(*centre(t)), theta)
        return np.hypot(*centre(tau)) - (base + self.radius)

    def wear_error(self, offset, base, heel, h, dh) -> tuple[float | np.ndarray, float | np.ndarray]:
        """d sec(beta) - base and the phase shift d sin(beta) / g (the pitch curve offset by d)."""
        g = geometry.roller_pitch_radius(heel, self.radius, h)
        beta = self.pressure_angle(heel, h, dh)
        return offset / np.cos(beta) - base, offset * np.sin(beta) / g
