"""Asymmetric cams: the opening flank of one law joined at the nose to the closing flank of another.

Both flanks must reach the same nose lift above the same ramp height; velocity is zero
at the nose on both sides, so lift and velocity are continuous there.  The acceleration is
continuous only when both flanks end with the same nose acceleration; otherwise it jumps
at the nose, which :attr:`AsymmetricLaw.nose_acceleration_jump` reports.
"""

import numpy as np

from ..checks import check
from ..errors import InputError
from ..locale import cited, note
from .base import LiftLaw
from .errors import LawError


class AsymmetricLaw(LiftLaw):
    """Opening flank of ``opening`` (theta < 0) and closing flank of ``closing`` (theta >= 0).

    Parameters
    ----------
    opening, closing : LiftLaw
        Symmetric laws with equal ``lift_max`` and ``ramp_height``.
    """

    def __init__(self, opening, closing):
        if not np.isclose(opening.lift_max, closing.lift_max, rtol=1e-9, atol=0.0):
            raise LawError("flanks_lift_differ", opening=opening.lift_max, closing=closing.lift_max)
        if not np.isclose(opening.ramp_height, closing.ramp_height, rtol=1e-9, atol=1e-15):
            raise InputError("asymmetric cam: the flanks have different ramp heights")
        self.opening, self.closing = opening, closing
        self.name = opening.name if opening.name == closing.name else f"{opening.name}/{closing.name}"
        flanks = (opening.source if opening.source == closing.source
                  else note("source.flanks", opening=cited(opening.source).parts, closing=cited(closing.source).parts))
        self.source = cited(flanks, note("source.asymmetric"))
        self.nose_acceleration_jump = float(closing.derivatives(np.zeros(1))[2, 0]
                                            - opening.derivatives(np.zeros(1))[2, 0])
        self.continuity = min(opening.continuity, closing.continuity)
        if abs(self.nose_acceleration_jump) > 1e-9 * abs(float(opening.derivatives(np.zeros(1))[2, 0])):
            self.continuity = min(self.continuity, 1)

    @property
    def segments(self) -> list:
        return ([s for s in self.opening.segments if s.end <= 0.0]
                + [s for s in self.closing.segments if s.start >= 0.0])

    @property
    def lift_max(self) -> float:
        return self.opening.lift_max

    @property
    def ramp_height(self) -> float:
        return self.opening.ramp_height

    @property
    def ramp_angle(self) -> float:
        """Ramp length of the opening flank [rad]."""
        return self.opening.ramp_angle

    @property
    def valve_closes(self) -> float:
        return self.end - self.closing.ramp_angle

    @property
    def main_half_angle(self) -> float:
        """Opening flank's angle from the end of its ramp to the nose [rad]."""
        return self.opening.main_half_angle

    def derivatives(self, theta) -> np.ndarray:
        theta = np.asarray(theta, dtype=float)
        return np.where(theta < 0.0, self.opening.derivatives(theta), self.closing.derivatives(theta))

    def coefficients(self) -> dict:
        """Both flanks' coefficients and the acceleration jump at the nose [mm/rad^2]."""
        return {"opening": self.opening.coefficients(), "closing": self.closing.coefficients(),
                "nose_acceleration_jump": self.nose_acceleration_jump * 1e3}

    def checks(self) -> list:
        """Both flanks' checks, and the acceleration jump at the nose (a jerk impulse on the train)."""
        jump = [check("law.asymmetric.nose_jump", self.nose_acceleration_jump, 0.0, 0.0,
                      source=cited(note("source.shock_free", work="Valve-train practical works (n.d.), work 2")),
                      unit="mm/rad2")] if self.continuity < 2 else []
        return self.opening.checks() + self.closing.checks() + jump
