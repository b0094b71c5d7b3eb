"""Circular-arc cams: the three-arc convex cam for a flat follower and the tangent cam for a roller follower
(the construction of Kolchin and Demidov (1980); Valve-train dynamics article (n.d.) uses the three-arc cam).

The classical arc cams have no ramp: the lift starts on the base circle of radius r0.
"""

import numpy as np

from ..errors import InputError
from ..locale import cited, note
from .base import RampedLaw, SymmetricLaw
from .errors import LawError


def three_arc_geometry(base_radius, lift, half_angle, nose_radius) -> tuple[float, float, float]:
    """Flank radius r1, flank angle phi1 and nose angle phi2 of a three-arc convex cam.

    Parameters
    ----------
    base_radius, lift : float
        r0 and h_max [m].
    half_angle : float
        phi_p0, half the action angle [rad].
    nose_radius : float
        r2 [m].

    Notes
    -----
    .. math::

        a = r_0 + h - r_2,\\quad
        r_1 = \\frac{r_0^2 + a^2 - r_2^2 - 2r_0a\\cos\\varphi_{p0}}{2(r_0 - r_2 - a\\cos\\varphi_{p0})},\\quad
        \\sin\\varphi_1 = \\frac{a\\sin\\varphi_{p0}}{r_1 - r_2},\\quad \\varphi_2 = \\varphi_{p0} - \\varphi_1

    References
    ----------
    Kolchin and Demidov (1980) (the construction; the closed forms are derived in this package).

    Examples
    --------
    A worked example: r0 = 20, h = 8, phi_p0 = 60 deg, r2 = 5: r1 = 63.4286, phi1 = 19.9320 deg.

    >>> r1, f1, f2 = three_arc_geometry(20.0, 8.0, np.radians(60), 5.0)
    >>> round(r1, 4), round(float(np.degrees(f1)), 4), round(float(np.degrees(f2)), 4)
    (63.4286, 19.932, 40.068)
    """
    a = base_radius + lift - nose_radius
    den = base_radius - nose_radius - a * np.cos(half_angle)
    if not (0.0 < nose_radius < base_radius and den > 0.0):
        raise LawError("three_arc_nose", nose=nose_radius)
    r1 = (base_radius**2 + a**2 - nose_radius**2 - 2.0 * base_radius * a * np.cos(half_angle)) / (2.0 * den)
    s1 = a * np.sin(half_angle) / (r1 - nose_radius)
    if not (r1 > base_radius and 0.0 < s1 < 1.0):
        raise LawError("three_arc_junction")
    phi1 = float(np.arcsin(s1))
    return float(r1), phi1, float(half_angle - phi1)


def _solve_nose_radius(base_radius, lift, half_angle, target):
    """r2 such that ``target(r1, phi1) = 0``, bracketed over the admissible nose radii and solved with brentq."""
    from scipy.optimize import brentq

    grid = np.linspace(0.0, base_radius, 2001)[1:-1]
    vals = []
    for r2 in grid:
        try:
            vals.append(target(*three_arc_geometry(base_radius, lift, half_angle, r2)[:2]))
        except ValueError:
            vals.append(np.nan)
    vals = np.array(vals)
    ok = np.flatnonzero(np.isfinite(vals[:-1]) & np.isfinite(vals[1:]) & (np.sign(vals[:-1]) != np.sign(vals[1:])))
    if ok.size == 0:
        raise LawError("three_arc_no_nose")
    i = ok[0]
    return brentq(lambda r2: target(*three_arc_geometry(base_radius, lift, half_angle, r2)[:2]), grid[i], grid[i + 1],
                  xtol=1e-14)


class _ArcCam(RampedLaw, SymmetricLaw):
    """Common frame of the circular-arc cams: no ramp, a flank up to ``flank_end`` and a nose arc to phi_p0."""

    continuity = 1

    @property
    def main_half_angle(self):
        return self.phi_p0

    @property
    def half_angle(self):
        return self.phi_p0

    def _rise_segments(self):
        return [("flank", 0.0, self.flank_end), ("nose", self.flank_end, self.phi_p0)]


class ThreeArcLaw(_ArcCam):
    """Three-arc convex cam (flank arc r1, nose arc r2) for a flat-faced follower.

    Parameters
    ----------
    base_radius : float
        r0 [m].
    lift : float
        h_max [m].
    half_angle : float
        phi_p0 [rad camshaft].
    nose_radius : float
        r2 [m]; use :meth:`from_flank_radius` or :meth:`from_flank_angle` to give r1 or phi1 instead.

    Notes
    -----
    Flank (0 <= phi <= phi1 from the start of lift): h = (r1 - r0)(1 - cos phi); nose
    (psi = phi_p0 - phi): h = a cos psi + r2 - r0.  The radius of curvature of the flat
    follower's cam is r1 on the flank and r2 on the nose (Shang Hanji (1988), eq. 2.6 reproduces both).
    The acceleration jumps at the start of lift and at the flank-nose junction.

    References
    ----------
    Kolchin and Demidov (1980); Valve-train dynamics article (n.d.) (three-arc profile).
    """

    name = "three_arc"
    source = cited(note("source.three_arc", works="Kolchin and Demidov (1980); Valve-train dynamics article (n.d.)"))

    def __init__(self, base_radius, lift, half_angle, nose_radius):
        self.r0, self._lift, self.phi_p0, self.r2 = map(float, (base_radius, lift, half_angle, nose_radius))
        self.r1, self.phi1, self.phi2 = three_arc_geometry(self.r0, self._lift, self.phi_p0, self.r2)
        self.a = self.r0 + self._lift - self.r2

    @classmethod
    def from_flank_radius(cls, base_radius, lift, half_angle, flank_radius) -> "ThreeArcLaw":
        r2 = _solve_nose_radius(base_radius, lift, half_angle, lambda r1, f1: r1 - flank_radius)
        return cls(base_radius, lift, half_angle, r2)

    @classmethod
    def from_flank_angle(cls, base_radius, lift, half_angle, flank_angle) -> "ThreeArcLaw":
        """The Valve-train dynamics article (n.d.) fixes the flank (positive-acceleration) angle phi1.

        >>> law = ThreeArcLaw.from_flank_angle(20.0, 8.0, np.radians(60), np.radians(25))
        >>> round(law.r2, 5), round(law.r1, 4)
        (2.02655, 55.2511)
        """
        r2 = _solve_nose_radius(base_radius, lift, half_angle, lambda r1, f1: f1 - flank_angle)
        return cls(base_radius, lift, half_angle, r2)

    @property
    def flank_end(self) -> float:
        """End of the flank arc, phi1 [rad]."""
        return self.phi1

    def _rise(self, phi):
        flank = phi <= self.phi1
        k = self.r1 - self.r0
        psi = self.phi_p0 - phi
        s, c = np.sin(phi), np.cos(phi)
        sp, cp = np.sin(psi), np.cos(psi)
        return np.where(flank, [k * (1 - c), k * s, k * c, -k * s],
                        [self.a * cp + self.r2 - self.r0, self.a * sp, -self.a * cp, -self.a * sp])

    def coefficients(self) -> dict:
        """Radii [mm] and angles [deg] of the construction."""
        return {"r0": self.r0 * 1e3, "r1": self.r1 * 1e3, "r2": self.r2 * 1e3, "a": self.a * 1e3,
                "phi1_deg": float(np.degrees(self.phi1)), "phi2_deg": float(np.degrees(self.phi2))}


class TangentLaw(_ArcCam):
    """Tangent cam (straight flanks, nose arc) for a translating roller follower through the cam centre.

    Parameters
    ----------
    base_radius, lift : float
        r0, h_max [m].
    half_angle : float
        phi_p0 [rad camshaft].
    roller_radius : float
        r_r [m]; the lift law of a tangent cam depends on it.

    Notes
    -----
    :math:`r_2 = r_0 - h\\cos\\varphi_{p0}/(1 - \\cos\\varphi_{p0})`, :math:`a = r_0 + h - r_2`.
    Flank: :math:`h = (r_0 + r_r)(\\sec\\varphi - 1)`.  Nose (psi from the nose):
    :math:`h = a\\cos\\psi + \\sqrt{(r_2 + r_r)^2 - a^2\\sin^2\\psi} - (r_0 + r_r)`, for
    :math:`|\\psi| \\le \\theta_t = \\operatorname{atan2}(C_x, C_y)`, C the roller centre at the junction.

    References
    ----------
    Kolchin and Demidov (1980) (the tangent cam; the closed forms are derived in this package).

    Examples
    --------
    r0 = 20, h = 8, phi_p0 = 60 deg, r_r = 10: r2 = 12, junction at 24.7913 deg, lift there 3.04542.

    >>> law = TangentLaw(20.0, 8.0, np.radians(60), 10.0)
    >>> round(law.r2, 6), round(float(np.degrees(law.junction)), 4), round(float(law.lift(-law.half_angle + law.junction)), 5)
    (12.0, 24.7913, 3.04542)
    """

    name = "tangent"
    source = cited(note("source.tangent", works="Kolchin and Demidov (1980)"))

    def __init__(self, base_radius, lift, half_angle, roller_radius):
        self.r0, self._lift, self.phi_p0, self.rr = map(float, (base_radius, lift, half_angle, roller_radius))
        c = np.cos(self.phi_p0)
        if not (0.0 < self.phi_p0 < np.pi / 2):
            raise InputError("tangent cam: the half action angle must lie in (0, 90) deg")
        self.r2 = float(self.r0 - self._lift * c / (1.0 - c))
        if not 0.0 < self.r2 < self.r0:
            raise LawError("tangent_nose", nose=self.r2)
        self.a = self.r0 + self._lift - self.r2
        centre = np.array([0.0, self.a]) + (self.r2 + self.rr) * np.array([np.sin(self.phi_p0), c])
        self.theta_t = float(np.arctan2(centre[0], centre[1]))
        self.junction = self.phi_p0 - self.theta_t

    @property
    def flank_end(self) -> float:
        """End of the straight flank [rad]."""
        return self.junction

    def _rise(self, phi):
        out = np.empty((4, phi.size))
        k = self.r0 + self.rr
        flank = phi <= self.junction
        s, c = np.sin(phi[flank]), np.cos(phi[flank])
        out[:, flank] = [k * (1.0 / c - 1.0), k * s / c**2, k * (1.0 + s * s) / c**3, k * s * (5.0 + s * s) / c**4]
        a, big = self.a, self.r2 + self.rr
        u = self.phi_p0 - phi[~flank]
        su, cu = np.sin(u), np.cos(u)
        q = np.sqrt(big**2 - (a * su) ** 2)
        # g(u) = a cos u + q and its derivatives with respect to u, the angle from the nose
        g1 = -a * su - a**2 * su * cu / q
        g2 = -a * cu - a**2 * (cu**2 - su**2) / q - a**4 * su**2 * cu**2 / q**3
        g3 = (a * su + 4.0 * a**2 * su * cu / q - 3.0 * a**4 * su * cu * (cu**2 - su**2) / q**3
              - 3.0 * a**6 * su**3 * cu**3 / q**5)
        out[:, ~flank] = [a * cu + q - k, -g1, g2, -g3]
        return out

    def coefficients(self) -> dict:
        """Radii [mm] and the junction angle [deg]."""
        return {"r0": self.r0 * 1e3, "r2": self.r2 * 1e3, "a": self.a * 1e3, "roller_radius": self.rr * 1e3,
                "junction_deg": float(np.degrees(self.junction))}
