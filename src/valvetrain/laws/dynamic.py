"""Multi-term dynamic cam (Shang Hanji (1988), section 4.1 多项动力凸轮) = the Dudley-Stoddart polydyne:
the cam is shaped so that the valve of a one-mass elastic train follows a chosen polynomial
motion at the design speed (Dudley (1948); Stoddart (1953); Rothbart (2004), section 13.7; the
formulas of the multi-term cam are derived in this package).
"""

import numpy as np

from ..checks import check
from ..errors import InputError
from ..locale import cited, note

from .base import RampedLaw, SymmetricLaw
from .errors import LawError
from .polydyne import _falling, polynomial_junction_coefficients
from .ramps import make_ramp


class DynamicLaw(RampedLaw, SymmetricLaw):
    """Cam lift that makes the valve follow a polynomial motion at the design speed.

    Parameters
    ----------
    valve_lift : float
        Design valve lift y_max [m].
    main_half_angle : float
        From the valve's opening to the nose [rad camshaft].
    exponents : sequence of float
        Exponents of the valve motion y = y_max + sum C_k x^k (e.g. 2, 10, 18, 26, 34).
    opening_velocity : float
        Valve velocity per camshaft radian at opening, v_y [m/rad].
    stiffness : float
        Drive stiffness reduced to the valve c [N/m].
    mass : float
        Mass reduced to the valve M [kg].
    spring_rate, preload : float
        Valve spring rate K [N/m] and preload F0 [N].
    cam_speed : float
        Design camshaft speed omega [rad/s].
    rocker_ratio : float
        k = valve arm / tappet arm.
    lash : float
        Valve lash at the valve x0 [m].
    ramp_kind, ramp_fraction
        The ramp before the valve opens (see :mod:`.ramps`).

    Notes
    -----
    With the valve open, a one-mass train satisfies :math:`M\\ddot y = c(kh - x_0 - y) - (F_0 + Ky)`;
    with :math:`\\ddot y = \\omega^2 y''` the cam lift is

    .. math:: k\\,h(\\alpha) = x_0 + y + \\frac{M\\omega^2y'' + Ky + F_0}{c}.

    The valve motion meets the ramp with y = 0, y' = -v_y and y'' = y''' = y'''' = 0, so the
    cam lift is C2 there; the ramp ends at (x0 + F0/c)/k with slope (1 + K/c) v_y / k.

    References
    ----------
    Shang Hanji (1988), section 4.1 (multi-term dynamic cam); Dudley (1948); Stoddart (1953);
    Rothbart (2004), section 13.7.
    """

    name = "dynamic"
    source = cited("Shang Hanji (1988), section 4.1",
                   note("source.dynamic", works="Dudley (1948); Stoddart (1953); Rothbart (2004), section 13.7"))

    def __init__(self, valve_lift, main_half_angle, exponents, opening_velocity, stiffness, mass, spring_rate,
                 preload, cam_speed, rocker_ratio=1.0, lash=0.0, ramp_kind="cosine", ramp_fraction=0.5):
        self.y_max, self.phi_p0 = float(valve_lift), float(main_half_angle)
        self.k = np.array([float(e) for e in exponents])
        self.v_y, self.c, self.m = float(opening_velocity), float(stiffness), float(mass)
        self.K, self.F0, self.omega = float(spring_rate), float(preload), float(cam_speed)
        self.ratio, self.x0 = float(rocker_ratio), float(lash)
        if not (self.y_max > 0 and self.phi_p0 > 0 and self.v_y > 0 and self.c > 0 and self.m > 0):
            raise InputError("dynamic law: lift, angle, opening velocity, stiffness and mass must be positive")
        if len(self.k) != 5:
            raise InputError("dynamic law: five exponents are needed (y, y', y'', y''', y'''' fixed at the junction)")
        self.coef = polynomial_junction_coefficients(self.k, self.y_max, 0.0, -self.v_y * self.phi_p0)
        self.ramp = make_ramp(ramp_kind, (self.x0 + self.F0 / self.c) / self.ratio,
                              (1.0 + self.K / self.c) * self.v_y / self.ratio, ramp_fraction)
        self._nose = float(self._cam(np.zeros(1))[0, 0])
        if self.lift_max <= 0.0:
            raise LawError("nose_below_ramp", nose=self.lift_max, inertia_rate=self.m * self.omega**2, stiffness=self.c)

    def valve_motion(self, u) -> np.ndarray:
        """Design valve motion y and its first five derivatives with respect to the cam angle from the nose u [rad]."""
        x = np.abs(np.asarray(u, dtype=float)) / self.phi_p0
        sign = np.sign(u)
        out = []
        for j in range(6):
            term = (self.coef[:, None] * _falling(self.k[:, None], j) * x[None, :] ** np.maximum(self.k[:, None] - j, 0)
                    ).sum(0) / self.phi_p0**j
            out.append(term * (sign**j if j % 2 else 1.0) + (self.y_max if j == 0 else 0.0))
        return np.array(out)

    def _cam(self, u):
        """Cam lift from the nose and its derivatives in u (distance from the nose), shape (4, n)."""
        y = self.valve_motion(u)
        w2 = self.m * self.omega**2
        h = [(self.x0 + y[0] + (w2 * y[2] + self.K * y[0] + self.F0) / self.c) / self.ratio]
        for j in range(1, 4):
            h.append((y[j] + (w2 * y[j + 2] + self.K * y[j]) / self.c) / self.ratio)
        return np.array(h)

    @property
    def lift_max(self) -> float:
        return self._nose - self.ramp.height

    @property
    def main_half_angle(self) -> float:
        return self.phi_p0

    @property
    def half_angle(self) -> float:
        return self.ramp.length + self.phi_p0

    def _rise_segments(self):
        return [("ramp", 0.0, self.ramp.length), ("dynamic", self.ramp.length, self.half_angle)]

    def _rise(self, phi):
        out = np.empty((4, phi.size))
        ramp = phi < self.ramp.length
        out[:, ramp] = self.ramp.evaluate(phi[ramp])
        u = self.half_angle - phi[~ramp]                      # distance from the nose (positive)
        d = self._cam(u)
        out[:, ~ramp] = [d[0], -d[1], d[2], -d[3]]            # d/dphi = -d/du
        return out

    def fall_before_nose(self, samples=2001) -> float:
        """Largest drop of the cam lift on its way to the nose [m] (0 for a cam that rises monotonically).

        The correction (M omega^2 y'' + K y)/c lowers the lift near the nose, where y'' < 0; a compliant
        drive or a heavy train makes the cam dip there, a shape no follower can use."""
        h = self._cam(np.linspace(self.phi_p0, 0.0, samples))[0]        # from the ramp's end to the nose
        return float(np.max(np.maximum.accumulate(h) - h))

    def checks(self) -> list:
        """The cam lift must rise monotonically to the nose (a dip means the drive is too compliant)."""
        return [check("law.dynamic.fall_before_nose", self.fall_before_nose(), high=0.0,
                      source=cited(note("source.rises_to_nose", work="Rothbart (2004), section 13.7")), unit="mm")]

    def coefficients(self) -> dict:
        """Valve-motion coefficients C_k = a_k / y_max, exponents, and the drive data used."""
        out = {f"C{e:g}": float(a / self.y_max) for e, a in zip(self.k, self.coef, strict=True)}
        out.update(exponents=[float(e) for e in self.k], stiffness_N_per_mm=self.c * 1e-3, mass_kg=self.m,
                   spring_rate_N_per_mm=self.K * 1e-3, preload_N=self.F0,
                   design_speed_rpm=self.omega * 60.0 / np.pi)
        return out
