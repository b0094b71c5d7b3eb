"""Constant-acceleration cam with ramps (Shang Hanji (1988), section 2.4 等加速凸轮; reconstructed).

After the ramp (height h0, end velocity v0, zero end acceleration): +A1 over Phi1, -A2
over Phi2 and optionally -kappa A2 over Phi3 up to the nose.  A1 and A2 follow from the
closure conditions, a 2 x 2 linear system.  The acceleration is piecewise constant (soft
impacts where it jumps); the lift is C1.  Shang's exact segmentation and parameter rules
are not available to this package: this is the general classical form.
"""

import numpy as np

from ..errors import InputError
from ..locale import cited, note
from .base import RampedLaw, SymmetricLaw, segment_index
from .ramps import make_ramp


def constant_acceleration_levels(nose_lift, ramp_height, ramp_velocity, phi1, phi2, phi3=0.0, kappa=1.0) -> tuple[float, float]:
    """A1 and A2 [L/rad^2] of the constant-acceleration cam.

    Notes
    -----
    .. math::

        v_0 + A_1\\Phi_1 - A_2(\\Phi_2 + \\kappa\\Phi_3) = 0

        h_0 + v_0T + A_1\\Phi_1\\left(\\tfrac{\\Phi_1}{2} + \\Phi_2 + \\Phi_3\\right)
        - A_2\\left(\\tfrac{\\Phi_2^2}{2} + \\Phi_2\\Phi_3 + \\tfrac{\\kappa\\Phi_3^2}{2}\\right) = h_{max}

    with :math:`T = \\Phi_1 + \\Phi_2 + \\Phi_3`.

    References
    ----------
    Shang Hanji (1988), section 2.4 (the method; the formulas are reconstructed in this package).

    Examples
    --------
    A worked example: h_max 8, h0 0.35, v0 1.33690 mm/rad, 18/20/12 deg, kappa 0.6:

    >>> a1, a2 = constant_acceleration_levels(8.0, 0.35, 1.33690, *np.radians([18, 20, 12]), kappa=0.6)
    >>> round(a1, 3), round(a2, 3)
    (54.142, 38.646)
    """
    total = phi1 + phi2 + phi3
    matrix = np.array([[phi1, -(phi2 + kappa * phi3)],
                       [phi1 * (phi1 / 2.0 + phi2 + phi3), -(phi2**2 / 2.0 + phi2 * phi3 + kappa * phi3**2 / 2.0)]])
    rhs = np.array([-ramp_velocity, nose_lift - ramp_height - ramp_velocity * total])
    a1, a2 = np.linalg.solve(matrix, rhs)
    return float(a1), float(a2)


class ConstantAccelerationLaw(RampedLaw, SymmetricLaw):
    """Constant-acceleration cam with ramps on both sides.

    Parameters
    ----------
    lift : float
        Tappet lift above the ramp h_T max [m].
    ramp_height, ramp_velocity : float
        Ramp height h0 [m] and end velocity v0 [m/rad].
    phi1, phi2, phi3 : float
        Segment lengths [rad camshaft]; phi3 may be 0.
    kappa : float
        Ratio of the third segment's deceleration to A2.
    ramp_kind, ramp_fraction
        The ramp (see :mod:`.ramps`).
    """

    name = "constant_acceleration"
    source = cited("Shang Hanji (1988), section 2.4", note("source.constant_acceleration"))
    continuity = 1

    def __init__(self, lift, ramp_height, ramp_velocity, phi1, phi2, phi3=0.0, kappa=1.0, ramp_kind="cosine",
                 ramp_fraction=0.5):
        if not (lift > 0 and phi1 > 0 and phi2 > 0 and phi3 >= 0 and kappa > 0):
            raise InputError("constant-acceleration law: lift, Phi1, Phi2 and kappa must be positive, Phi3 >= 0")
        self._lift = float(lift)
        self.ramp = make_ramp(ramp_kind, ramp_height, ramp_velocity, ramp_fraction)
        self.phi = (float(phi1), float(phi2), float(phi3))
        self.kappa = float(kappa)
        h0, v0 = self.ramp.height, self.ramp.end_velocity
        self.a1, self.a2 = constant_acceleration_levels(self._lift + h0, h0, v0, *self.phi, kappa=self.kappa)
        if not (self.a1 > 0 and self.a2 > 0):
            raise InputError(f"constant-acceleration law: the angles give A1 = {self.a1:.4g}, A2 = {self.a2:.4g} "
                             "mm/rad^2; both must be positive (lengthen the event or lower the lift)")
        self._edges = np.cumsum([0.0, self.ramp.length, *self.phi])
        acc = [self.a1, -self.a2, -self.kappa * self.a2]
        h, v = [h0], [v0]
        for a, L in zip(acc, self.phi, strict=True):
            h.append(h[-1] + v[-1] * L + a * L * L / 2.0)
            v.append(v[-1] + a * L)
        self._start = (np.array(h[:3]), np.array(v[:3]), np.array(acc))

    @property
    def main_half_angle(self) -> float:
        return float(sum(self.phi))

    @property
    def half_angle(self) -> float:
        return float(self._edges[-1])

    def _rise_segments(self):
        e = self._edges
        out = [("ramp", e[0], e[1]), ("A1", e[1], e[2]), ("A2", e[2], e[3])]
        return out + ([("A3", e[3], e[4])] if self.phi[2] > 0 else [])

    def _rise(self, phi):
        out = np.empty((4, phi.size))
        edges = self._edges if self.phi[2] > 0 else self._edges[:-1]
        seg = segment_index(phi, edges)
        ramp = seg == 0
        out[:, ramp] = self.ramp.evaluate(phi[ramp])
        h0, v0, acc = self._start
        i = seg[~ramp] - 1
        x = phi[~ramp] - edges[seg[~ramp]]
        out[:, ~ramp] = [h0[i] + v0[i] * x + acc[i] * x * x / 2.0, v0[i] + acc[i] * x, acc[i], np.zeros_like(x)]
        return out

    def coefficients(self) -> dict:
        """A1, A2 and the third level [mm/rad^2], the ramp velocity [mm/rad] and kappa."""
        return {"A1": self.a1 * 1e3, "A2": self.a2 * 1e3, "A3": self.kappa * self.a2 * 1e3,
                "ramp_velocity": self.ramp.end_velocity * 1e3, "kappa": self.kappa}
