"""N-harmonic cam: a finite cosine series over the working angle with junction conditions
(Shang Hanji (1988), section 4.2; reconstructed in this package).

.. math:: h(\\theta) = \\sum_{k=0}^{N} a_k\\cos\\frac{k\\pi\\theta}{\\alpha_W},\\quad |\\theta| \\le \\alpha_W

Odd derivatives vanish at +-alpha_W by construction; the even ones up to 2m are made zero
there (a C^(2m+1) junction with the base circle), h(0) is the nose lift, and the remaining
freedom is fitted to a target law by equality-constrained least squares.  Shang's exact
rules for N and the end conditions are not available to this package.
"""

import numpy as np

from ..checks import check
from ..errors import InputError
from ..locale import cited, note
from ..numerics import level_span
from .base import LiftLaw, Segment
from .errors import LawError


def harmonic_limit(half_angle, natural_frequency, cam_speed) -> float:
    """Largest harmonic order whose frequency stays below the natural frequency, N < alpha_W omega_n / (pi omega).

    Parameters
    ----------
    half_angle : float
        alpha_W, half the working angle [rad camshaft].
    natural_frequency : float
        omega_n of the valve train [rad/s].
    cam_speed : float
        omega [rad/s].

    Notes
    -----
    The outer solution of the 1-DOF train converges for a trigonometric polynomial when
    epsilon (N pi / alpha_W)^2 < 1 with epsilon = (omega / omega_n)^2.

    References
    ----------
    Shang Hanji (1988), sections 4.2 and 3.3 (the N-harmonic cam and the perturbation method; reconstructed).

    Examples
    --------
    >>> round(harmonic_limit(np.radians(70), 2000.0, 300.0), 3)
    2.593
    """
    return float(half_angle * natural_frequency / (np.pi * cam_speed))


MAX_DEVIATION = 0.05
"""Largest deviation of the series from its target, as a share of the target's lift, accepted as a fit."""


def _junction_conditions(w, order, nose_lift):
    """Equality constraints C a = d of the series: even derivatives 0, 2, ..., 2m zero at theta = alpha_W and
    h(0) = the nose lift.  Row j is scaled by (w_N)^(2j) so that every row has entries of order one."""
    k = np.arange(w.size)
    scale = w / w[-1]
    c = np.array([(-1.0) ** k * scale ** (2 * j) for j in range(order + 1)] + [np.ones(w.size)])
    d = np.zeros(order + 2)
    d[-1] = nose_lift
    return c, d


def constrained_least_squares(a, b, c, d) -> np.ndarray:
    """Minimise ||a x - b|| subject to c x = d, by the null-space method.

    ``x = x_p + Z y`` with ``x_p`` the minimum-norm solution of ``c x = d`` and ``Z`` an orthonormal
    basis of the null space of ``c`` (both from the SVD, :func:`scipy.linalg.null_space`), then ``y``
    by least squares.  Unlike the KKT system this stays solvable when the constraints are badly
    scaled or nearly dependent (high harmonic and junction orders).

    Examples
    --------
    The point of the line x0 + x1 = 2 closest to (0, 0):

    >>> [round(float(v), 12) for v in constrained_least_squares(np.eye(2), np.zeros(2), np.ones((1, 2)), [2.0])]
    [1.0, 1.0]
    """
    from scipy.linalg import lstsq, null_space

    x_p = lstsq(c, d)[0]
    z = null_space(c)
    if z.shape[1] == 0:
        return x_p
    y = lstsq(a @ z, b - a @ x_p)[0]
    return x_p + z @ y


class HarmonicLaw(LiftLaw):
    """N-harmonic cam fitted to a target law.

    Parameters
    ----------
    target : LiftLaw
        The law whose lift the series approximates; its whole event (ramps included) is the
        working angle, and its ramp height is the clearance the valve opens after.
    harmonics : int
        N, the highest harmonic.
    junction_order : int
        m: the even derivatives 0, 2, ..., 2m vanish at the ends.
    samples : int
        Fitting points over half the working angle.
    """

    name = "harmonic"
    source = cited("Shang Hanji (1988), section 4.2", note("source.harmonic"))

    def __init__(self, target, harmonics, junction_order=1, samples=2001):
        n, m = int(harmonics), int(junction_order)
        if n < m + 2:
            raise InputError(f"harmonic law: N = {n} harmonics cannot meet {m + 2} conditions; allowed N >= {m + 2}")
        self.target = target
        self.alpha = float(target.end)
        self.harmonics, self.junction_order = n, m
        k = np.arange(n + 1)
        self.w = k * np.pi / self.alpha
        theta = np.linspace(0.0, self.alpha, samples)
        a = np.cos(np.outer(theta, self.w))
        b = target.lift(theta)
        self.a = constrained_least_squares(a, b, *_junction_conditions(self.w, m, float(target.lift(0.0))))
        self.deviation = float(np.abs(a @ self.a - b).max())
        if not self.deviation <= MAX_DEVIATION * float(target.lift(0.0)):
            raise LawError("harmonics_deviate", harmonics=n, junction_order=m, deviation=self.deviation,
                           lift=float(target.lift(0.0)), most=MAX_DEVIATION)
        self._ramp_height = float(target.ramp_height)
        self._opening = self._valve_opening()

    def _valve_opening(self):
        """Angle from the start of the event where the lift reaches the target's ramp height [rad]."""
        if self._ramp_height <= 0.0:
            return 0.0
        return level_span(self.lift, -self.alpha, self.alpha, self._ramp_height)[0] + self.alpha

    @property
    def segments(self) -> list[Segment]:
        return [Segment("harmonic opening", -self.alpha, 0.0), Segment("harmonic closing", 0.0, self.alpha)]

    @property
    def lift_max(self) -> float:
        return float(self.lift(0.0)) - self._ramp_height

    @property
    def ramp_height(self) -> float:
        return self._ramp_height

    @property
    def ramp_angle(self) -> float:
        return self._opening

    @property
    def main_half_angle(self) -> float:
        return self.alpha - self._opening

    @property
    def breakpoints(self) -> np.ndarray:
        o = self._opening
        return np.unique(np.array([-self.alpha, -self.alpha + o, 0.0, self.alpha - o, self.alpha]))

    def derivatives(self, theta) -> np.ndarray:
        theta = np.asarray(theta, dtype=float)
        flat = theta.ravel()
        out = np.zeros((4, flat.size))
        inside = np.abs(flat) <= self.alpha
        arg = np.outer(flat[inside], self.w)
        c, s = np.cos(arg), np.sin(arg)
        out[:, inside] = [c @ self.a, -s @ (self.a * self.w), -c @ (self.a * self.w**2), s @ (self.a * self.w**3)]
        return out.reshape((4,) + theta.shape)

    def train_checks(self, natural_frequency, cam_speed) -> list:
        """The harmonic order against the train: N < alpha_W omega_n / (pi omega) (:func:`harmonic_limit`)."""
        return [check("law.harmonic.order", self.harmonics,
                      high=harmonic_limit(self.alpha, natural_frequency, cam_speed),
                      source=cited(note("source.harmonic_order", work="Shang Hanji (1988), section 4.2")))]

    def coefficients(self) -> dict:
        """a_0 ... a_N [mm], N, m and the largest deviation from the target [mm]."""
        return {"a": [float(x) * 1e3 for x in self.a], "harmonics": self.harmonics,
                "junction_order": self.junction_order, "max_deviation_mm": self.deviation * 1e3,
                "target": self.target.name}
