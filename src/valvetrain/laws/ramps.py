"""Ramps (clearance take-up segments) of lift laws.

A ramp lifts the follower through the valve clearance h0 at a small, controlled
velocity so that the valve opens and seats softly.  On a valve with a hydraulic lash adjuster
(no clearance) the same ramp, of the small height ``[lash_adjuster] ramp_height_mm``, is a
quieting ramp: it lifts the valve itself at that velocity
(:func:`valvetrain.specification.cam_base.ramp_height`).
"""

import numpy as np
from numba import njit

from ..errors import InputError


def cosine_ramp_length(height, end_velocity) -> float:
    """Length of a cosine ramp, Phi_0 = pi h0 / (2 w') [rad].

    Parameters
    ----------
    height : float
        Ramp height (the clearance h0) [m].
    end_velocity : float
        Follower velocity at the end of the ramp per camshaft radian, w' = dh/dphi [m/rad].

    Notes
    -----
    .. math:: \\Phi_0 = \\frac{\\pi h_0}{2\\,\\omega'_{T0K}}

    The manual's form with w' in mm/deg has pi^2 / (2 * 180) in front.

    References
    ----------
    Valve-train practical works (n.d.), work 2, eq. (2.1).

    Examples
    --------
    the appendix of Valve-train practical works (n.d.): h0 = 0.25 mm, w' = 0.02 mm/deg gives 19.635 deg.

    >>> round(float(np.rad2deg(cosine_ramp_length(0.25e-3, 0.02e-3 * 180 / np.pi))), 3)
    19.635
    """
    return np.pi * height / (2.0 * end_velocity)


@njit(cache=True)
def cosine_ramp_at(phi, height, length) -> tuple[float, float, float, float]:
    """Cosine ramp at one angle: lift and its first three derivatives with respect to camshaft angle.

    Parameters
    ----------
    phi : float
        Camshaft angle from the start of the ramp, 0 <= phi <= length [rad].
    height : float
        Ramp height h0 [m].
    length : float
        Ramp length Phi_0 [rad].

    Returns
    -------
    tuple of float
        h [m], dh/dphi [m/rad], d2h/dphi2 [m/rad^2], d3h/dphi3 [m/rad^3].

    Notes
    -----
    .. math:: h = h_0\\left(1-\\cos\\frac{\\pi\\varphi}{2\\Phi_0}\\right)

    The end acceleration is zero and the end velocity is pi h0 / (2 Phi0).

    References
    ----------
    Valve-train practical works (n.d.), work 2, eq. (2.5).
    """
    k = np.pi / (2.0 * length)
    s, c = np.sin(k * phi), np.cos(k * phi)
    return height * (1.0 - c), height * k * s, height * k**2 * c, -height * k**3 * s


@njit(cache=True)
def constant_velocity_ramp_at(phi, end_velocity) -> tuple[float, float, float, float]:
    """Constant-velocity ramp h = w' phi at one angle: h [m] and its three derivatives (see
    :class:`ConstantVelocityRamp`)."""
    return end_velocity * phi, end_velocity, 0.0, 0.0


@njit(cache=True)
def constant_acceleration_ramp_at(phi, end_velocity, accelerating) -> tuple[float, float, float, float]:
    """Constant-acceleration ramp at one angle: h [m] and its three derivatives (see
    :class:`ConstantAccelerationRamp`; ``accelerating`` = f alpha_r [rad], the accelerating stretch)."""
    if phi < accelerating:
        acc = end_velocity / accelerating
        return 0.5 * acc * phi**2, acc * phi, acc, 0.0
    return end_velocity * phi - end_velocity * accelerating / 2.0, end_velocity, 0.0, 0.0


COSINE, CONSTANT_VELOCITY, CONSTANT_ACCELERATION = 0, 1, 2
"""Codes of the ramp kinds in the compiled kernels (:attr:`Ramp.code`)."""


@njit(cache=True)
def ramp_at(code, phi, height, end_velocity, length, fraction) -> tuple[float, float, float, float]:
    """A ramp of kind ``code`` at one angle phi [rad from its start]: h and its three derivatives (the
    compiled laws' ramp; the arguments are :attr:`Ramp.parameters`)."""
    if code == COSINE:
        return cosine_ramp_at(phi, height, length)
    if code == CONSTANT_VELOCITY:
        return constant_velocity_ramp_at(phi, end_velocity)
    return constant_acceleration_ramp_at(phi, end_velocity, fraction * length)


@njit(cache=True)
def _ramp_values(phi, code, height, end_velocity, length, fraction):
    out = np.empty((4, phi.size))
    for i in range(phi.size):
        out[0, i], out[1, i], out[2, i], out[3, i] = ramp_at(code, phi[i], height, end_velocity, length, fraction)
    return out


class Ramp:
    """A ramp (clearance take-up segment): height h0 [m], end velocity w' [m/rad], zero end acceleration.

    ``evaluate(phi)`` gives lift and three derivatives, shape (4, n), for 0 <= phi <= length
    (camshaft angle from the start of the ramp).  Every ramp ends with zero acceleration,
    so a main segment starting with zero acceleration joins it with continuous
    acceleration.
    """

    kind = ""

    #: whether the ramp starts with zero velocity (a constant-velocity ramp starts with a velocity step)
    starts_at_rest = True

    #: kind code of the compiled kernels (:data:`COSINE`, ...)
    code = COSINE

    #: acceleration share of the ramp's length (a constant-acceleration ramp's only)
    fraction = 0.0

    def __init__(self, height, end_velocity):
        if not (height > 0 and end_velocity > 0):
            raise InputError(f"{self.kind} ramp: height and end velocity must be positive")
        self.height = float(height)
        self.end_velocity = float(end_velocity)

    @property
    def length(self) -> float:
        """Ramp length [rad camshaft]."""
        raise NotImplementedError

    @property
    def parameters(self) -> tuple:
        """``(code, height, end_velocity, length, fraction)``, the arguments of :func:`ramp_at`."""
        return self.code, self.height, self.end_velocity, self.length, self.fraction

    def evaluate(self, phi) -> np.ndarray:
        """Lift and three derivatives at the angles ``phi`` from the start of the ramp, shape (4, n)."""
        return _ramp_values(np.ascontiguousarray(phi, dtype=float).ravel(), *self.parameters)


class CosineRamp(Ramp):
    """Cosine ramp of Valve-train practical works (n.d.), eqs. (2.1) and (2.5); the acceleration jumps at its start (train unloaded)."""

    kind = "cosine"

    @property
    def length(self) -> float:
        return float(cosine_ramp_length(self.height, self.end_velocity))


class ConstantVelocityRamp(Ramp):
    """Constant-velocity ramp h = w' phi, length h0 / w' (Shang Hanji (1988), section 2.2, as a ramp family).

    The velocity steps from 0 to w' at the start of the ramp, while the clearance is still open.
    """

    kind = "constant_velocity"
    code = CONSTANT_VELOCITY
    starts_at_rest = False

    @property
    def length(self) -> float:
        return self.height / self.end_velocity


class ConstantAccelerationRamp(Ramp):
    """Constant acceleration over a fraction f of the ramp, then constant velocity (等加速-等速).

    Notes
    -----
    On :math:`[0, f\\alpha_r]`: :math:`h = \\frac{v_0}{2f\\alpha_r}t^2`; after it :math:`h = v_0 t - v_0 f\\alpha_r/2`;
    the height is :math:`h_0 = v_0\\alpha_r(1 - f/2)`, hence :math:`\\alpha_r = h_0 / (v_0 (1 - f/2))`.

    References
    ----------
    A constant-acceleration and constant-velocity ramp as used in the Chinese patent CN 103422923 B
    (abstract); the formulas are derived in this package.

    Examples
    --------
    h0 = 0.35 mm, alpha_r = 20 deg, f = 0.5 give v0 = 1.3369 mm/rad and a ramp
    acceleration of 7.66 mm/rad^2.

    >>> r = ConstantAccelerationRamp(0.35, 1.33690, 0.5)
    >>> round(float(np.degrees(r.length)), 3), round(float(r.evaluate(np.array([0.01]))[2, 0]), 2)
    (20.0, 7.66)
    """

    kind = "constant_acceleration"
    code = CONSTANT_ACCELERATION

    def __init__(self, height, end_velocity, fraction=0.5):
        super().__init__(height, end_velocity)
        if not 0.0 < fraction <= 1.0:
            raise InputError(f"constant-acceleration ramp: fraction f = {fraction!r}: allowed (0, 1]")
        self.fraction = float(fraction)

    @property
    def length(self) -> float:
        return self.height / (self.end_velocity * (1.0 - self.fraction / 2.0))


RAMPS = {"cosine": CosineRamp, "constant_velocity": ConstantVelocityRamp,
         "constant_acceleration": ConstantAccelerationRamp}


def make_ramp(kind, height, end_velocity, fraction=0.5) -> Ramp:
    """A ramp of the named kind (``cosine``, ``constant_velocity``, ``constant_acceleration``)."""
    if kind == "constant_acceleration":
        return ConstantAccelerationRamp(height, end_velocity, fraction)
    return RAMPS[kind](height, end_velocity)
