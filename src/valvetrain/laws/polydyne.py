"""Polydyne (high-order polynomial) cam (seed 000, work 3; seed 002, section 2.6).

.. math:: h = h_{nose}\\,(1 + C_2x^2 + C_px^p + C_qx^q + C_rx^r + C_sx^s),\\quad x = \\theta/\\varphi_{p0}

with ``theta`` the camshaft angle from the nose.  Without a ramp (seed 000) the five
coefficients make h and its first four derivatives vanish at x = 1 (closed form
(3.4)-(3.8)).  With a ramp the same polynomial is joined to a cosine ramp: h = h0 and
dh/dtheta = ramp end velocity at x = 1, the second to fourth derivatives zero there (a
5x5 linear system; spec/methods-seeds-002-004.md, section 7, [D]).  The cosine ramp
ends at zero acceleration, so the joined law is C2; its jerk jumps at the junction.
"""

import numpy as np

from ..checks import check_range
from .base import SymmetricLaw
from .ramps import cosine_ramp, cosine_ramp_length

EXPONENT_P_RANGE = (6, 16)
"""Recommended first exponent p: 6-10 for fast passenger-car engines, 12-16 for trucks (seed 000, work 3)."""


def default_exponents(p):
    """The progression of seed 000 work 3: q = 2p - 2, r = 3p - 4, s = 4p - 6 (difference p - 2).

    >>> default_exponents(12)
    (12, 22, 32, 42)
    """
    return (p, 2 * p - 2, 3 * p - 4, 4 * p - 6)


def polydyne_coefficients(p, q, r, s):
    """Closed-form polydyne coefficients C2, Cp, Cq, Cr, Cs (dimensionless).

    Parameters
    ----------
    p, q, r, s : float
        Exponents, 2 < p < q < r < s.

    Returns
    -------
    tuple of float
        (C2, Cp, Cq, Cr, Cs); their sum is -1.

    Notes
    -----
    .. math::

        C_2 = -\\frac{pqrs}{(p-2)(q-2)(r-2)(s-2)},\\
        C_p = \\frac{2qrs}{(p-2)(q-p)(r-p)(s-p)},\\
        C_q = -\\frac{2prs}{(q-2)(q-p)(r-q)(s-q)},

        C_r = \\frac{2pqs}{(r-2)(r-p)(r-q)(s-r)},\\
        C_s = -\\frac{2pqr}{(s-2)(s-p)(s-q)(s-r)}

    References
    ----------
    seed 000, work 3, eqs. (3.4)-(3.8).

    Examples
    --------
    p = 8 with the default progression (spec/valvetrain-works-1-8.md, 4.5):

    >>> [round(c, 5) for c in polydyne_coefficients(8, 14, 20, 26)]
    [-1.87243, 1.87243, -1.60494, 0.74897, -0.14403]
    """
    return (
        -p * q * r * s / ((p - 2) * (q - 2) * (r - 2) * (s - 2)),
        2 * q * r * s / ((p - 2) * (q - p) * (r - p) * (s - p)),
        -2 * p * r * s / ((q - 2) * (q - p) * (r - q) * (s - q)),
        2 * p * q * s / ((r - 2) * (r - p) * (r - q) * (s - r)),
        -2 * p * q * r / ((s - 2) * (s - p) * (s - q) * (s - r)),
    )


def _falling(k, j):
    """k (k-1) ... (k-j+1), the j-th derivative factor of x^k."""
    out = np.ones_like(np.asarray(k, dtype=float))
    for i in range(j):
        out = out * (k - i)
    return out


def polydyne_junction_coefficients(exponents, nose_lift, end_lift, end_slope):
    """Polynomial coefficients that meet a ramp: h(1), dh/dx(1) given, h'', h''', h'''' = 0 at x = 1.

    Parameters
    ----------
    exponents : sequence of 5 floats
        (2, p, q, r, s).
    nose_lift : float
        h(0), lift at the nose [L].
    end_lift : float
        h(1), lift where the polynomial meets the ramp [L].
    end_slope : float
        dh/dx at x = 1 [L] (negative: the lift falls away from the nose).

    Returns
    -------
    ndarray
        Coefficients a_k [L] of h = nose_lift + sum a_k x^k.

    Notes
    -----
    With ``end_lift = end_slope = 0`` the solution is ``nose_lift`` times the closed form
    of :func:`polydyne_coefficients` (spec/methods-seeds-002-004.md, section 7, [D]).
    """
    k = np.asarray(exponents, dtype=float)
    matrix = np.array([_falling(k, j) for j in range(5)])
    rhs = np.array([end_lift - nose_lift, end_slope, 0.0, 0.0, 0.0])
    return np.linalg.solve(matrix, rhs)


class PolydyneLaw(SymmetricLaw):
    """Polydyne cam law, optionally joined to cosine ramps.

    Parameters
    ----------
    lift : float
        Tappet lift above the ramp, h_T max [m].
    main_half_angle : float
        phi_p0, from the end of the ramp (or the start of lift) to the nose [rad camshaft].
    p : float
        First exponent, >= 3 (below 3 the jerk is infinite at the nose).
    q, r, s : float, optional
        Further exponents; default the progression of :func:`default_exponents`.
    ramp_height : float
        Cosine-ramp height h0 [m]; 0 (default) for no ramp, as in seed 000.
    ramp_velocity : float
        Ramp end velocity per camshaft radian [m/rad]; required with a ramp.

    Examples
    --------
    >>> law = PolydyneLaw(6.25e-3, np.deg2rad(71.0), 8)
    >>> bool(np.abs(law.derivatives(np.array([law.start]))).max() < 1e-12)  # lift and 3 derivatives vanish
    True
    """

    name = "polydyne"

    def __init__(self, lift, main_half_angle, p, q=None, r=None, s=None, ramp_height=0.0, ramp_velocity=0.0):
        dp, dq, dr, ds = default_exponents(p)
        self.exponents = (float(p), float(dq if q is None else q), float(dr if r is None else r),
                          float(ds if s is None else s))
        if not 3 <= self.exponents[0] < self.exponents[1] < self.exponents[2] < self.exponents[3]:
            raise ValueError(f"polydyne exponents {self.exponents}: allowed 3 <= p < q < r < s "
                             "(p < 3 makes the jerk infinite at the nose)")
        if not (lift > 0 and main_half_angle > 0):
            raise ValueError("polydyne law: lift and main half angle must be positive")
        if ramp_height < 0 or (ramp_height > 0 and not ramp_velocity > 0):
            raise ValueError("polydyne law: a ramp needs a positive height and end velocity")
        self._lift = float(lift)
        self.phi_p0 = float(main_half_angle)
        self._ramp_height = float(ramp_height)
        self.ramp_velocity = float(ramp_velocity) if ramp_height > 0 else 0.0
        self.phi0 = float(cosine_ramp_length(ramp_height, ramp_velocity)) if ramp_height > 0 else 0.0
        nose = self._lift + self._ramp_height
        if self._ramp_height > 0:
            self._a = polydyne_junction_coefficients((2.0,) + self.exponents, nose, self._ramp_height,
                                                     -self.ramp_velocity * self.phi_p0)
        else:
            self._a = nose * np.array(polydyne_coefficients(*self.exponents))
        self._k = np.array((2.0,) + self.exponents)

    @property
    def lift_max(self):
        return self._lift

    @property
    def ramp_height(self):
        return self._ramp_height

    @property
    def ramp_angle(self):
        return self.phi0

    @property
    def main_half_angle(self):
        """phi_p0 [rad camshaft]."""
        return self.phi_p0

    @property
    def half_angle(self):
        return self.phi0 + self.phi_p0

    def _rise_segments(self):
        ramp = [("ramp", 0.0, self.phi0)] if self.phi0 > 0 else []
        return ramp + [("polydyne", self.phi0, self.half_angle)]

    def _rise(self, phi):
        out = np.empty((4, phi.size))
        ramp = phi < self.phi0
        if self.phi0 > 0:
            out[:, ramp] = cosine_ramp(phi[ramp], self._ramp_height, self.phi0)
        x = (self.half_angle - phi[~ramp]) / self.phi_p0
        # d^j/dx^j of sum a_k x^k: the x^2 term directly, the others from one power x^(k-3) per exponent
        c2, a = self._a[0], self._a[1:, None]
        k = self._k[1:, None]
        base = x[None, :] ** (k - 3.0)
        x1 = x[None, :]
        series = [(a * base * x1**3).sum(0) + c2 * x * x, (a * k * base * x1**2).sum(0) + 2.0 * c2 * x,
                  (a * _falling(k, 2) * base * x1).sum(0) + 2.0 * c2, (a * _falling(k, 3) * base).sum(0)]
        nose = self._lift + self._ramp_height
        # d/dphi = -d/dtheta_from_nose = -(1/phi_p0) d/dx
        out[:, ~ramp] = [nose + series[0], -series[1] / self.phi_p0, series[2] / self.phi_p0**2,
                         -series[3] / self.phi_p0**3]
        return out

    def coefficients(self):
        """C2, Cp, Cq, Cr, Cs of h = h_nose (1 + sum C x^k) (dimensionless) and the exponents p, q, r, s."""
        c = self._a / (self._lift + self._ramp_height)
        out = dict(zip(("C2", "Cp", "Cq", "Cr", "Cs"), map(float, c), strict=True))
        out.update(zip(("p", "q", "r", "s"), self.exponents, strict=True))
        return out

    def checks(self):
        """The recommended range of p (seed 000, work 3)."""
        return check_range("polydyne exponent p", self.exponents[0], *EXPONENT_P_RANGE,
                           source="seed 000, work 3")
