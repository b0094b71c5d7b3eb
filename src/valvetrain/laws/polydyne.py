"""Polydyne and high-order polynomial cams (Valve-train practical works (n.d.), work 3; Shang Hanji (1988), section 2.6).

.. math:: h = h_{nose}\\,(1 + C_2x^2 + C_px^p + C_qx^q + C_rx^r + C_sx^s),\\quad x = \\theta/\\varphi_{p0}

with ``theta`` the camshaft angle from the nose.  Without a ramp (Valve-train practical works (n.d.)) the five
coefficients make h and its first four derivatives vanish at x = 1 (closed form
(3.4)-(3.8)).  With a ramp the same polynomial is joined to a cosine ramp: h = h0 and
dh/dtheta = ramp end velocity at x = 1, the second to fourth derivatives zero there (a
5x5 linear system, derived in this package).  The cosine ramp
ends at zero acceleration, so the joined law is C2; its jerk jumps at the junction.
"""

import functools

import mpmath
import numpy as np
from numba import njit

from ..checks import check
from ..errors import InputError
from ..locale import cited, note
from .base import RampedLaw, SymmetricLaw, mirror
from .ramps import make_ramp, ramp_at

JUNCTION_DIGITS = 50
"""Decimal digits of the arithmetic that solves :func:`polynomial_junction_coefficients` (the floats of its matrix
and right-hand side are exact in it; 50 digits leave the 16 of the result exact for a condition number up to 1e30)."""

EXPONENT_P_RANGE = (6, 16)
"""Recommended first exponent p: 6-10 for fast passenger-car engines, 12-16 for trucks (Valve-train practical works (n.d.), work 3)."""


def default_exponents(p) -> tuple[float, float, float, float]:
    """The progression of Valve-train practical works (n.d.), work 3: q = 2p - 2, r = 3p - 4, s = 4p - 6 (difference p - 2).

    >>> default_exponents(12)
    (12, 22, 32, 42)
    """
    return (p, 2 * p - 2, 3 * p - 4, 4 * p - 6)


def polydyne_coefficients(p, q, r, s) -> tuple[float, float, float, float, float]:
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
    Valve-train practical works (n.d.), work 3, eqs. (3.4)-(3.8).

    Examples
    --------
    p = 8 with the default progression:

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


def polynomial_junction_coefficients(exponents, nose_lift, end_lift, end_slope) -> np.ndarray:
    """Coefficients of h = nose_lift + sum a_k x^k meeting a ramp (or the base circle) at x = 1.

    Conditions: h(1) = ``end_lift``, dh/dx(1) = ``end_slope`` and the 2nd to (N-1)-th
    derivatives zero at x = 1, for N exponents.

    Parameters
    ----------
    exponents : sequence of float
        The N exponents (e.g. (2, p, q, r, s)).
    nose_lift : float
        h(0), lift at the nose [L].
    end_lift : float
        h(1) [L].
    end_slope : float
        dh/dx at x = 1 [L] (negative: the lift falls away from the nose).

    Returns
    -------
    ndarray
        a_k [L].

    Notes
    -----
    With five exponents and ``end_lift = end_slope = 0`` the solution is ``nose_lift``
    times the closed form of :func:`polydyne_coefficients` (derived in this package).

    The system (row j: the j-th falling factorials of the exponents) is solved in
    :data:`JUNCTION_DIGITS`-digit arithmetic (mpmath's LU solver) and rounded to the nearest
    floats: the matrix is ill-conditioned (1.3e6 for the exponents (2, 8, 14, 20, 26)), and
    LAPACK's solution in double precision differs in the 14th digit with the BLAS kernels of the
    processor, a difference the breathing cycle of a polydyne cam carries to the 5th digit of its
    results (examples/phaser.toml).  Rounded from the exact solution, the coefficients are the
    same on every machine.

    References
    ----------
    mpmath development team (2023) (its ``lu_solve``).
    """
    return np.array(_junction(tuple(float(k) for k in exponents), float(end_lift - nose_lift), float(end_slope)))


@functools.lru_cache(maxsize=256)
def _junction(exponents, drop, slope) -> tuple[float, ...]:
    """:func:`polynomial_junction_coefficients` of the exponents (a tuple), ``end_lift - nose_lift`` and
    ``end_slope``, kept for the next law of the same cam (a tolerance study's samples: about 0.8 ms a solve)."""
    k = np.asarray(exponents)
    matrix = [_falling(k, j).tolist() for j in range(k.size)]
    rhs = [0.0] * k.size
    rhs[0], rhs[1] = drop, slope
    with mpmath.workdps(JUNCTION_DIGITS):
        solution = mpmath.lu_solve(mpmath.matrix(matrix), mpmath.matrix(rhs))
    return tuple(float(a) for a in solution)


class PolynomialLaw(RampedLaw, SymmetricLaw):
    """High-order polynomial cam with any exponent set, optionally joined to ramps.

    .. math:: h = h_{nose} + \\sum_k a_k x^k,\\quad x = \\theta/\\varphi_{p0}

    Parameters
    ----------
    lift : float
        Tappet lift above the ramp, h_T max [m].
    main_half_angle : float
        phi_p0, from the end of the ramp (or the start of lift) to the nose [rad camshaft].
    exponents : sequence of float
        Increasing exponents, each 2 or >= 3 (below 3, other than 2, the jerk is infinite at the nose).
    ramp_height, ramp_velocity : float
        Ramp height h0 [m] and end velocity [m/rad]; 0 for no ramp.
    ramp_kind : str
        ``cosine``, ``constant_velocity`` or ``constant_acceleration`` (see :mod:`.ramps`).
    ramp_fraction : float
        Acceleration share f of a ``constant_acceleration`` ramp.

    Notes
    -----
    The coefficients solve :func:`polynomial_junction_coefficients`: lift and slope of the
    ramp's end, higher derivatives zero, so the law is C2 with every ramp kind (they all
    end at zero acceleration).

    References
    ----------
    Valve-train practical works (n.d.), work 3; Shang Hanji (1988), section 2.6 (高次方凸轮); the junction
    with a ramp is derived in this package.
    """

    name = "polynomial"
    source = cited(note("source.polynomial", work="Shang Hanji (1988), section 2.6"))

    def __init__(self, lift, main_half_angle, exponents, ramp_height=0.0, ramp_velocity=0.0, ramp_kind="cosine",
                 ramp_fraction=0.5):
        k = tuple(float(e) for e in exponents)
        if len(k) < 2 or any(b <= a for a, b in zip(k, k[1:], strict=False)) or any(e < 3 and e != 2 for e in k):
            raise InputError(f"polynomial exponents {k}: allowed an increasing set of at least two, each 2 or >= 3 "
                             "(below 3 the jerk is infinite at the nose)")
        if not (lift > 0 and main_half_angle > 0):
            raise InputError("polynomial law: lift and main half angle must be positive")
        self._lift = float(lift)
        self.phi_p0 = float(main_half_angle)
        self.ramp = make_ramp(ramp_kind, ramp_height, ramp_velocity, ramp_fraction) if ramp_height > 0 else None
        self._k = np.array(k)
        self._a = self._solve()

    def _solve(self):
        nose = self._lift + self.ramp_height
        if self.ramp is None:
            return polynomial_junction_coefficients(self._k, nose, 0.0, 0.0)
        return polynomial_junction_coefficients(self._k, nose, self.ramp_height, -self.ramp.end_velocity * self.phi_p0)

    @property
    def exponents(self) -> tuple[float, ...]:
        return tuple(float(e) for e in self._k)

    @property
    def main_half_angle(self) -> float:
        """phi_p0 [rad camshaft]."""
        return self.phi_p0

    @property
    def half_angle(self) -> float:
        return self.ramp_angle + self.phi_p0

    def _rise_segments(self):
        ramp = [("ramp", 0.0, self.ramp_angle)] if self.ramp is not None else []
        return ramp + [(self.name, self.ramp_angle, self.half_angle)]

    def _mirrored(self, theta, out):
        quad = self._k == 2.0
        a, k = self._a[~quad], self._k[~quad]
        # x^(k_n - 3) as a running product of x^(k_n - k_(n-1)), one power per distinct step (two for a progression)
        powers, step = np.unique(np.diff(k, prepend=3.0), return_inverse=True)
        ramp = self.ramp.parameters if self.ramp is not None else (0, 0.0, 0.0, 0.0, 0.0)
        _polynomial_kernel(theta, out, self.half_angle, self.ramp_angle, self.phi_p0, self._lift + self.ramp_height,
                           float(self._a[quad].sum()), np.stack([a, a * k, a * _falling(k, 2), a * _falling(k, 3)]),
                           powers, np.where(powers == np.round(powers), powers, -1).astype(np.int64), step, ramp)

    def coefficients(self) -> dict:
        """a_k / h_nose (dimensionless, h = h_nose (1 + sum C_k x^k)) keyed ``C<k>``, and the exponents."""
        c = self._a / (self._lift + self.ramp_height)
        out = {f"C{e:g}": float(v) for e, v in zip(self._k, c, strict=True)}
        out["exponents"] = list(self.exponents)
        return out


class PolydyneLaw(PolynomialLaw):
    """Polydyne cam of Valve-train practical works (n.d.), work 3: exponents 2, p, q, r, s (default progression), optionally joined to ramps.

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
    ramp_height, ramp_velocity, ramp_kind, ramp_fraction
        As for :class:`PolynomialLaw`; no ramp by default, as in Valve-train practical works (n.d.).

    Notes
    -----
    Without a ramp the coefficients are the closed form (3.4)-(3.8) times h_T max.

    Examples
    --------
    >>> law = PolydyneLaw(6.25e-3, np.deg2rad(71.0), 8)
    >>> bool(np.abs(law.derivatives(np.array([law.start]))).max() < 1e-12)  # lift and 3 derivatives vanish
    True
    """

    name = "polydyne"
    source = cited(note("source.polydyne", work="Valve-train practical works (n.d.), work 3"))

    def __init__(self, lift, main_half_angle, p, q=None, r=None, s=None, ramp_height=0.0, ramp_velocity=0.0,
                 ramp_kind="cosine", ramp_fraction=0.5):
        dp, dq, dr, ds = default_exponents(p)
        exps = (float(p), float(dq if q is None else q), float(dr if r is None else r), float(ds if s is None else s))
        if not 3 <= exps[0] < exps[1] < exps[2] < exps[3]:
            raise InputError(f"polydyne exponents {exps}: allowed 3 <= p < q < r < s "
                             "(p < 3 makes the jerk infinite at the nose)")
        super().__init__(lift, main_half_angle, (2.0,) + exps, ramp_height, ramp_velocity, ramp_kind, ramp_fraction)

    def _solve(self):
        if self.ramp is None:
            return self._lift * np.array(polydyne_coefficients(*self._k[1:]))
        return super()._solve()

    def coefficients(self) -> dict:
        """C2, Cp, Cq, Cr, Cs of h = h_nose (1 + sum C x^k) (dimensionless) and the exponents p, q, r, s."""
        c = self._a / (self._lift + self.ramp_height)
        out = dict(zip(("C2", "Cp", "Cq", "Cr", "Cs"), map(float, c), strict=True))
        out.update(zip(("p", "q", "r", "s"), map(float, self._k[1:]), strict=True))
        return out

    def checks(self) -> list:
        """The recommended range of p (Valve-train practical works (n.d.), work 3)."""
        return [check("law.polydyne.exponent_p", self._k[1], *EXPONENT_P_RANGE, source="Valve-train practical works (n.d.), work 3")]


@njit(cache=True)
def _polynomial_kernel(theta, out, half, ramp_angle, phi_p0, nose, c2, weights, powers, whole, step, ramp):
    """Polynomial law at the angles ``theta`` into ``out`` (zeros, shape (4, n)), one pass (see :class:`PolynomialLaw`).

    Notes
    -----
    On the ramp :func:`~.ramps.ramp_at`; after it, with :math:`x = \\theta/\\varphi_{p0}` from the nose,
    :math:`h = h_{nose} + c_2x^2 + \\sum_n a_n x^{k_n}` and :math:`d^jh/d\\theta^j = \\varphi_{p0}^{-j}\\,d^jh/dx^j`
    (``weights`` holds :math:`a_n`, :math:`a_nk_n`, :math:`a_nk_n(k_n-1)`, :math:`a_nk_n(k_n-1)(k_n-2)`);
    :math:`x^{k_n-3}` is the product of ``powers[step[m]]`` = :math:`x^{k_m - k_{m-1}}` over m <= n
    (:math:`k_0 - 3` first).  The angle phi from the start of the event runs the other way, so
    the odd derivatives change sign.

    References
    ----------
    Valve-train practical works (n.d.), work 3, eq. (3.1).
    """
    pw = np.empty(powers.size)
    for i in range(theta.size):
        phi, flip = mirror(theta[i], half)
        if phi < 0.0:
            continue
        if phi < ramp_angle:
            h, v, a, j = ramp_at(ramp[0], phi, ramp[1], ramp[2], ramp[3], ramp[4])
        else:
            x = (half - phi) / phi_p0
            for m in range(powers.size):
                pw[m] = x ** whole[m] if whole[m] >= 0 else x ** powers[m]
            base, s0, s1, s2, s3 = 1.0, 0.0, 0.0, 0.0, 0.0
            for n in range(step.size):
                base *= pw[step[n]]
                s0 += weights[0, n] * base * x**3
                s1 += weights[1, n] * base * x**2
                s2 += weights[2, n] * base * x
                s3 += weights[3, n] * base
            h = nose + (s0 + c2 * x * x)
            v, a, j = -(s1 + 2.0 * c2 * x) / phi_p0, (s2 + 2.0 * c2) / phi_p0**2, -s3 / phi_p0**3
        out[0, i], out[1, i], out[2, i], out[3, i] = h, flip * v, a, flip * j
