"""A cam without a ramp used with a valve clearance: the flanks take up the clearance.

The follower rises from the base circle with the law's lift ``h``; the valve stays on its
seat until ``h`` reaches the clearance ``h0`` and then moves with ``i_k (h - h0)``.  With a
ramp (Kurz, constant acceleration, combined, ramped polydyne) the clearance is taken up at
the ramp's small constant velocity; without one it is taken up on the flank, and the valve
leaves and meets its seat at the flank's velocity there (Valve-train practical works (n.d.), work 2: the ramp exists
to limit exactly that velocity; the working
guidance for the seating velocity is about 0.3-0.5 m/s at rated speed).
"""

import numpy as np

from ..errors import InputError
from ..locale import cited, note
from ..numerics import level_span
from .base import LiftLaw, Segment
from .errors import LawError


class ClearanceTakeUp(LiftLaw):
    """A law without a ramp whose lift includes the clearance, taken up on its flanks.

    Parameters
    ----------
    law : LiftLaw
        A law without a ramp (``ramp_height == 0``); its lift above the base circle
        includes the clearance, ``law.lift_max = valve lift / i_k + h0``.
    clearance : float
        h0, the valve clearance at the cam [m], ``0 < h0 < law.lift_max``.

    Notes
    -----
    The valve opens and seats where ``h(theta) = h0`` (the first upward and last downward
    crossing, solved on the analytic law); :attr:`ramp_height` is ``h0`` and
    :attr:`ramp_angle` the opening flank's take-up angle, so the valve lift
    ``i_k max(h - h0, 0)`` and the valve-open interval of :class:`LiftLaw` hold unchanged.
    The segments of ``law`` are split at the take-up points.

    Examples
    --------
    A three-arc cam lifting 6.5 mm with a 0.25 mm clearance: the valve lift above it is 6.25 mm.

    >>> from valvetrain.laws import ThreeArcLaw
    >>> law = ClearanceTakeUp(ThreeArcLaw(0.01975, 0.0065, np.radians(71), 0.004), 0.00025)
    >>> round(law.lift_max * 1e3, 9), law.segments[0].name
    (6.25, 'clearance take-up opening')
    """

    clearance_on_flank = True

    def __init__(self, law, clearance):
        if law.ramp_height > 0.0:
            raise InputError(f"{law.name} law: it has a ramp, which takes up the clearance itself")
        if not 0.0 < clearance < law.lift_max:
            raise LawError("clearance_exceeds_lift", law=law.name, clearance=clearance, lift=law.lift_max)
        self.law, self.clearance = law, float(clearance)
        self._opens, self._closes = level_span(law.lift, law.start, law.end, self.clearance)
        self.name, self.continuity = law.name, law.continuity
        self.source = cited(law.source, note("source.takeup"))

    @property
    def segments(self) -> list[Segment]:
        out = []
        for s in self.law.segments:
            cuts = [a for a in (self._opens, self._closes) if s.start < a < s.end]
            edges = [s.start, *cuts, s.end]
            for a, b in zip(edges[:-1], edges[1:]):
                if b <= self._opens:
                    out.append(Segment("clearance take-up opening", a, b))
                elif a >= self._closes:
                    out.append(Segment("clearance take-up closing", a, b))
                else:
                    out.append(Segment(s.name, a, b))
        return out

    @property
    def lift_max(self) -> float:
        return self.law.lift_max - self.clearance

    @property
    def ramp_height(self) -> float:
        return self.clearance

    @property
    def ramp_angle(self) -> float:
        return self._opens - self.law.start

    @property
    def valve_closes(self) -> float:
        return self._closes

    @property
    def main_half_angle(self) -> float:
        return self.law.main_half_angle

    def derivatives(self, theta) -> np.ndarray:
        return self.law.derivatives(theta)

    def coefficients(self) -> dict:
        """The law's coefficients and the take-up angles of the clearance [cam deg]."""
        return {**self.law.coefficients(), "clearance_mm": self.clearance * 1e3,
                "take_up_opening_cam_deg": float(np.degrees(self.ramp_angle)),
                "take_up_closing_cam_deg": float(np.degrees(self.law.end - self._closes))}

    def checks(self) -> list:
        return self.law.checks()
