"""Piecewise power-polynomial acceleration cam of the UkrSURT Proceedings (2019) dynamic synthesis (reconstructed).

The article builds the tappet's acceleration analogue a = d2S/dphi2 over half the event from four
parts: the clearance take-up ramp a-b (length phi_0), positive accelerations b-e (phi_1), negative
accelerations e-h (phi_2) and half the top dwell h-i (a = 0).  Each part is a power polynomial, the
lift and velocity analogues are its closed-form integrals, and the coefficients follow from the
characteristic points.  **The article's formulas (1)-(12) and the patent they come from are not
available**; this module implements a documented reconstruction of them:

* ``"R2"`` (default): every sub-piece is a two-term power law with a flat extremum,
  b-d ``a = a_qd (m xi^n - n xi^m)/(m - n)``, d-e ``a = a_qd (q (1-eta)^p - p (1-eta)^q)/(q - p)``,
  e-g and g-h the same with ``a_g`` and the exponents r, s and t, u.  d lies at ``x_d phi_1`` and g at
  ``x_g phi_2``.  It gives the article's exponent ranges a physical meaning (n = 1-3: finite jerk
  after the ramp; p, r < 1: a steep zero crossing at e; t, u = 3-9: a smooth entry into the dwell).
* ``"R1"`` (for comparison, our own simpler reading): b-e and e-h are each a flat-topped bump of two
  pieces, ``a = a_qd (1 - (1 - xi)^chi)`` up to d and ``a = a_qd (1 - eta^chi)`` after it (likewise e-h
  with a_g), chi the sharpness of the bump; the higher chi, the more rectangular the acceleration.

In both, the ramp is ``a = A_0 + B_0 x + C_0 x^2`` (x = psi/phi_0) with a(b) = 0, v(b) = v_qb and
S(b) = S_b; the negative amplitude a_g makes v(h) = 0; phi_2 is solved in closed form so that the
dwell lift S_h equals the required lift (the lift gained over e-h is proportional to phi_2 at a
given shape).  The curve is C2 (lift, velocity and acceleration continuous); the jerk jumps at b
and is infinite at a junction where an exponent below 1 meets it (p and r of the article's ranges).
The ramp starts with the finite acceleration A_0 (three coefficients, three conditions).
"""

from functools import cached_property, lru_cache

import numpy as np

from ..checks import check
from ..errors import InputError
from ..locale import cited, note
from .base import SymmetricLaw, member_values
from .errors import LawError

ARTICLE_EXPONENTS = dict(n=1.0, m=4.0, p=0.5, q=4.5, r=0.3, s=2.5, t=4.0, u=7.0)
"""Exponents of the article's optimum.  n, m, p, q are printed (UkrSURT Proceedings (2019), 'n=1; m=4;
p=0,5; q=4,5'); r, s, t, u are printed garbled ('r=0,3; s=25; t=14; u=1') and are read here as
r = 0.3, s = 2.5, t = 4, u = 7: within the article's ranges (r = 0.1-0.5, s = 1-3, t = 3-7, u = 3-9), they
reproduce a dwell lift of 18.57 mm at the article's a_qd, phi_1 and phi_2 with x_d = 0.2, x_g = 0.8."""

ARTICLE_FULLNESS = dict(optimum=0.667, serial=0.602)
"""Fullness of the tappet lift over the valve-open part that the article reports for its optimum and for the
serial cam of the 26/27 diesel (UkrSURT Proceedings (2019)): the figures an optimum is compared with."""

EXPONENT_RANGES = dict(n=(1.0, 3.0), m=(3.0, 6.0), p=(0.3, 0.7), q=(4.0, 6.0), r=(0.1, 0.5), s=(1.0, 3.0),
                       t=(3.0, 7.0), u=(3.0, 9.0))
"""The exponent ranges the article recommends from its search studies (UkrSURT Proceedings (2019))."""

RECONSTRUCTIONS = ("R2", "R1")
"""The readings of the article's missing formulas: R2 two-term power laws with flat extrema, R1 one bump a segment."""


class _Piece:
    """A unit-amplitude acceleration shape f(xi) on [0, 1] with its closed-form integrals.

    ``F(xi) = int_0^xi f`` and ``G(xi) = int_0^xi F``; ``df`` is f'(xi).
    """

    def values(self, xi):
        """f, F, G, df at xi (arrays)."""
        raise NotImplementedError

    def totals(self):
        """F(1), G(1)."""
        return self._totals

    @cached_property
    def _totals(self):
        """F(1), G(1), evaluated once per piece (a law's construction asks for them up to three times)."""
        _, F, G, _ = self.values(np.array([1.0]))
        return float(F[0]), float(G[0])


class _Quadratic(_Piece):
    """f = A + B xi + C xi^2 (the ramp)."""

    def __init__(self, A, B, C):
        self.c = (A, B, C)

    def values(self, xi):
        A, B, C = self.c
        return (A + B * xi + C * xi**2, A * xi + B * xi**2 / 2 + C * xi**3 / 3,
                A * xi**2 / 2 + B * xi**3 / 6 + C * xi**4 / 12, B + 2 * C * xi)


class _PowerRise(_Piece):
    """f = sum c_k xi^e_k, the terms ``((c, e), ...)`` (e >= 0)."""

    def __init__(self, terms):
        self.terms = tuple((float(c), float(e)) for c, e in terms)

    def values(self, xi):
        tiny = np.maximum(xi, 1e-12)
        f = F = G = df = 0.0
        for c, e in self.terms:
            f = f + c * xi**e
            F = F + c * xi ** (e + 1) / (e + 1)
            G = G + c * xi ** (e + 2) / ((e + 1) * (e + 2))
            df = df + (c * e * tiny ** (e - 1) if e else 0.0)
        return f, F, G, df

    def area(self):
        """int_0^1 G, the third integral over the piece."""
        return sum(c / ((e + 1) * (e + 2) * (e + 3)) for c, e in self.terms)


class _PowerFall(_PowerRise):
    """f = g(1 - xi), g the sum of the terms as in :class:`_PowerRise`."""

    def values(self, xi):
        u = 1.0 - xi
        tiny = np.maximum(u, 1e-12)
        f = F = G = df = 0.0
        for c, e in self.terms:
            f = f + c * u**e
            F = F + c * (1.0 - u ** (e + 1)) / (e + 1)
            G = G + c * (xi - (1.0 - u ** (e + 2)) / (e + 2)) / (e + 1)
            df = df - (c * e * tiny ** (e - 1) if e else 0.0)
        return f, F, G, df

    def area(self):
        return sum(c * (0.5 - (1.0 - 1.0 / (e + 3)) / (e + 2)) / (e + 1) for c, e in self.terms)


def flat_extremum(e1, e2) -> tuple[tuple[float, float], tuple[float, float]]:
    """Terms of (e2 x^e1 - e1 x^e2)/(e2 - e1): 0 at x = 0, 1 with zero slope at x = 1 (R2)."""
    return ((e2 / (e2 - e1), e1), (-e1 / (e2 - e1), e2))


def plateau(chi) -> tuple[tuple[float, float], tuple[float, float]]:
    """Terms of 1 - x^chi: 1 with zero slope at x = 0, 0 at x = 1 (R1)."""
    return ((1.0, 0.0), (-1.0, chi))


@lru_cache(maxsize=64)
def _shape(kind, terms):
    """The piece ``kind(terms)`` (:class:`_PowerRise` or :class:`_PowerFall`), made once for each set of terms: the
    laws of a search share their pieces' shapes, and with them the totals F(1), G(1)."""
    return kind(terms)


@lru_cache(maxsize=64)
def _ramp(height, angle, velocity):
    """The ramp piece of :func:`ramp_coefficients`, solved once for each ramp (the laws of a search share it)."""
    return _Quadratic(*ramp_coefficients(height, angle, velocity))


def ramp_coefficients(height, angle, velocity) -> tuple[float, float, float]:
    """A_0, B_0, C_0 of the ramp a = A_0 + B_0 x + C_0 x^2, x = psi/phi_0 [length/rad^2].

    Parameters
    ----------
    height : float
        S_b, the lift at the end of the ramp [length].
    angle : float
        phi_0, the ramp length [rad].
    velocity : float
        v_qb, the velocity analogue at the end of the ramp [length/rad].

    Notes
    -----
    From a(b) = 0, v(b) = v_qb and S(b) = S_b with S(a) = v(a) = 0:

    .. math:: A+B+C=0,\\quad \\varphi_0(A+B/2+C/3)=v_{qb},\\quad \\varphi_0^2(A/2+B/6+C/12)=S_b

    References
    ----------
    UkrSURT Proceedings (2019), the a-b part; the polynomial form is reconstructed.

    Examples
    --------
    The article's ramp (S_b = 0.8 mm, phi_0 = 12 deg, v_qb = 6 mm/rad), in mm/rad^2:

    >>> [round(c, 3) for c in ramp_coefficients(0.8, np.radians(12.0), 6.0)]
    [46.966, -15.978, -30.988]
    """
    matrix = np.array([[1.0, 1.0, 1.0], [1.0, 0.5, 1.0 / 3.0], [0.5, 1.0 / 6.0, 1.0 / 12.0]])
    return tuple(float(c) for c in np.linalg.solve(matrix, [0.0, velocity / angle, height / angle**2]))


class PowerPolynomialLaw(SymmetricLaw):
    """The piecewise power-polynomial acceleration cam (ramp, positive, negative, half dwell), symmetric.

    Parameters
    ----------
    lift : float
        Tappet lift above the ramp, S_max - S_b [m].
    main_half_angle : float
        phi_1 + phi_2 + phi_dwell/2, half the event without the ramps [rad camshaft].
    ramp_height : float
        S_b, the clearance taken up by the ramp [m] (> 0).
    ramp_angle : float
        phi_0, the ramp length [rad camshaft].
    ramp_velocity : float
        v_qb, the velocity analogue at the end of the ramp [m/rad] (the seating velocity analogue).
    peak_acceleration : float
        a_qd, the largest acceleration analogue [m/rad^2].
    phi1 : float
        The positive-acceleration part b-e [rad camshaft].
    peak_position, trough_position : float
        x_d and x_g, where the extremum of the positive (negative) part lies, a fraction of its length.
    exponents : dict
        n, m, p, q, r, s, t, u of the R2 power laws (defaults :data:`ARTICLE_EXPONENTS`).
    reconstruction : {"R2", "R1"}
        Which reading of the missing formulas (see the module docstring).
    sharpness : float
        chi of the R1 bumps (> 1).

    Raises
    ------
    ValueError
        Parameters that admit no cam: the lift is reached before the ramp's end or never (phi_2 < 0),
        or phi_1 + phi_2 exceeds the main half angle (no room for the dwell).

    Notes
    -----
    On a piece of length L starting with velocity v_0 and lift S_0, with the acceleration a = A f(xi):

    .. math:: v = v_0 + A L F(\\xi),\\quad S = S_0 + v_0 L \\xi + A L^2 G(\\xi),\\quad F=\\int_0^\\xi f,\\ G=\\int_0^\\xi F

    For R2, :math:`\\int_0^1 (e_2\\xi^{e_1}-e_1\\xi^{e_2})/(e_2-e_1)\\,d\\xi = I(e_1,e_2)
    =\\frac{e_2/(e_1+1)-e_1/(e_2+1)}{e_2-e_1}`, and v(h) = 0 gives
    :math:`a_g=-v_e/(\\varphi_2[x_gI(r,s)+(1-x_g)I(t,u)])`.  With a_g ~ 1/phi_2 the lift gained over e-h
    is :math:`v_e\\varphi_2\\kappa`, kappa a number of the shape, so phi_2 = (S_max - S_e)/(v_e kappa).

    References
    ----------
    UkrSURT Proceedings (2019): the four parts, the characteristic points, the exponent ranges and
    the example of the 26/27 diesel.  The article's formulas are not available; the pieces are
    reconstructed in this package.
    """

    name = "power_polynomial"
    source = cited(note("source.power_polynomial", work="UkrSURT Proceedings (2019)"))

    def __init__(self, lift, main_half_angle, ramp_height, ramp_angle, ramp_velocity, peak_acceleration, phi1,
                 peak_position=0.2, trough_position=0.8, exponents=None, reconstruction="R2", sharpness=10.0):
        if reconstruction not in RECONSTRUCTIONS:
            raise InputError(f"power_polynomial reconstruction {reconstruction!r}: allowed {RECONSTRUCTIONS}")
        if not (lift > 0 and main_half_angle > 0 and ramp_height > 0 and ramp_angle > 0 and ramp_velocity > 0
                and peak_acceleration > 0 and phi1 > 0):
            raise InputError("power_polynomial law: lift, angles, ramp height and velocity and the peak acceleration "
                             "must be positive")
        if not (0.0 < peak_position < 1.0 and 0.0 < trough_position < 1.0):
            raise InputError("power_polynomial law: peak_position and trough_position must lie in (0, 1)")
        e = {**ARTICLE_EXPONENTS, **(exponents or {})}
        for a, b in (("n", "m"), ("p", "q"), ("r", "s"), ("t", "u")):
            if not (e[a] > 0 and e[b] > 0 and e[a] != e[b]):
                raise InputError(f"power_polynomial exponents {a} = {e[a]:g}, {b} = {e[b]:g}: both positive and "
                                 "different")
        self._lift, self.phi_p0 = float(lift), float(main_half_angle)
        self._h0, self._phi0, self.v_qb = float(ramp_height), float(ramp_angle), float(ramp_velocity)
        self.a_qd, self.phi1 = float(peak_acceleration), float(phi1)
        self.x_d, self.x_g, self.exponents, self.reconstruction = float(peak_position), float(trough_position), e, \
            reconstruction
        self.sharpness = float(sharpness)
        self._build()

    def _shapes(self):
        e = self.exponents
        if self.reconstruction == "R2":
            pos = [(self.x_d, _shape(_PowerRise, flat_extremum(e["n"], e["m"]))),
                   (1.0 - self.x_d, _shape(_PowerFall, flat_extremum(e["p"], e["q"])))]
            neg = [(self.x_g, _shape(_PowerRise, flat_extremum(e["r"], e["s"]))),
                   (1.0 - self.x_g, _shape(_PowerFall, flat_extremum(e["t"], e["u"])))]
        else:
            chi = self.sharpness
            pos = [(self.x_d, _shape(_PowerFall, plateau(chi))), (1.0 - self.x_d, _shape(_PowerRise, plateau(chi)))]
            neg = [(self.x_g, _shape(_PowerFall, plateau(chi))), (1.0 - self.x_g, _shape(_PowerRise, plateau(chi)))]
        return pos, neg

    def _build(self):
        ramp = _ramp(self._h0, self._phi0, self.v_qb)
        pos, neg = self._shapes()
        pieces = [("ramp", self._phi0, 1.0, ramp)]
        pieces += [(name, frac * self.phi1, self.a_qd, shape) for name, (frac, shape) in zip(("b-d", "d-e"), pos)]
        S, v = 0.0, 0.0
        for _, L, A, shape in pieces:
            F, G = shape.totals()
            S, v = S + v * L + A * L**2 * G, v + A * L * F
        self.S_e, self.v_e = S, v
        # over e-h with a_g = -v_e/(phi2 sum frac F): lift gained = v_e phi2 kappa
        sumF = sum(frac * shape.totals()[0] for frac, shape in neg)
        gain, vrel = 0.0, 1.0
        for frac, shape in neg:
            F, G = shape.totals()
            gain += vrel * frac - frac**2 * G / sumF
            vrel -= frac * F / sumF
        need = self.nose_lift - self.S_e
        if need <= 0.0 or gain <= 0.0:
            raise LawError("lift_within_positive_part", lift=self.nose_lift, positive_lift=self.S_e)
        self.phi2 = need / (self.v_e * gain)
        self.dwell = 2.0 * (self.phi_p0 - self.phi1 - self.phi2)
        if self.dwell < -1e-12:
            raise LawError("phases_exceed_half", phases=self.phi1 + self.phi2, half=self.phi_p0)
        self.dwell = max(self.dwell, 0.0)
        self.a_g = -self.v_e / (self.phi2 * sumF)
        pieces += [(name, frac * self.phi2, self.a_g, shape) for name, (frac, shape) in zip(("e-g", "g-h"), neg)]
        self._pieces, start, S, v = [], 0.0, 0.0, 0.0
        for name, L, A, shape in pieces:
            self._pieces.append((name, start, L, A, shape, S, v))
            F, G = shape.totals()
            S, v, start = S + v * L + A * L**2 * G, v + A * L * F, start + L
        self.S_h, self.v_h = S, v
        self._table = np.array([(start, L, A, S0, v0) for _, start, L, A, _, S0, v0 in self._pieces])

    @property
    def nose_lift(self) -> float:
        """S_max = S_b + lift, the tappet lift over the dwell [m]."""
        return self._lift + self._h0

    @property
    def lift_max(self) -> float:
        return self._lift

    @property
    def ramp_height(self) -> float:
        return self._h0

    @property
    def ramp_angle(self) -> float:
        return self._phi0

    @property
    def main_half_angle(self) -> float:
        """phi_1 + phi_2 + phi_dwell/2 [rad camshaft]."""
        return self.phi_p0

    @property
    def half_angle(self) -> float:
        return self._phi0 + self.phi_p0

    def _rise_segments(self):
        out = [(name, start, start + L) for name, start, L, *_ in self._pieces]
        if self.dwell > 0.0:
            out.append(("dwell", out[-1][2], self.half_angle))
        else:
            out[-1] = (out[-1][0], out[-1][1], self.half_angle)
        return out

    def batch_key(self) -> tuple:
        """The shapes of the pieces: laws with the same reconstruction, exponents and sharpness are sampled together
        (their pieces differ in length, amplitude and start values only)."""
        return self.reconstruction, tuple(self.exponents.values()), self.sharpness

    def _rise(self, phi):
        return self._batch_rise([self], phi, None)

    @classmethod
    def _batch_rise(cls, laws, phi, member):
        """The rise of ``laws[member[k]]`` at ``phi[k]`` (``member`` None: the one law), shape (4, n): on each piece
        S = S_0 + v_0 L xi + A L^2 G(xi), v = v_0 + A L F(xi), a = A f(xi), a' = A f'(xi) / L, the lift S_h over
        the dwell."""
        table = None if member is None else np.array([law._table for law in laws]).transpose(1, 2, 0)
        out = np.zeros((4, phi.size))
        out[0] = member_values([law.S_h for law in laws], member)
        for k, piece in enumerate(laws[0]._pieces):
            if member is None:
                _, start, L, A, _, S0, v0 = piece
                m = (phi >= start) & (phi <= start + L)
            else:
                start, L = table[k, 0][member], table[k, 1][member]
                m = (phi >= start) & (phi <= start + L)
                start, L, A, S0, v0 = table[k][:, member[m]]
            xi = np.clip((phi[m] - start) / L, 0.0, 1.0)
            f, F, G, df = piece[4].values(xi)
            out[:, m] = (S0 + v0 * L * xi + A * L**2 * G, v0 + A * L * F, A * f, A * df / L)
        return out

    def coefficients(self) -> dict:
        mm = 1e3
        A0, B0, C0 = (c * mm for c in ramp_coefficients(self._h0, self._phi0, self.v_qb))
        out = {"reconstruction": self.reconstruction, "A0_mm_rad2": A0, "B0_mm_rad2": B0, "C0_mm_rad2": C0,
               "a_qd_mm_rad2": self.a_qd * mm, "a_g_mm_rad2": self.a_g * mm, "phi0_deg": np.degrees(self._phi0),
               "phi1_deg": np.degrees(self.phi1), "phi2_deg": np.degrees(self.phi2),
               "dwell_deg": np.degrees(self.dwell), "x_d": self.x_d, "x_g": self.x_g,
               "S_e_mm": self.S_e * mm, "v_e_mm_rad": self.v_e * mm, "S_h_mm": self.S_h * mm}
        if self.reconstruction == "R2":
            out.update({k: float(v) for k, v in self.exponents.items()})
        else:
            out["chi"] = self.sharpness
        return out

    def fullness(self) -> float:
        """eta_П = int_b^b' S dphi / (S_max (phi_D - 2 phi_0)): tappet lift over the valve-open part.

        Notes
        -----
        The article's definition is not available; this reading reproduces its fullness best
        (UkrSURT Proceedings (2019); reconstructed).  The integral is closed-form: on a piece of length L,
        int S = L (S_0 + v_0 L/2 + A L^2 int_0^1 G).
        """
        # int_0^L S = L (S_0 + v_0 L/2 + A L^2 int_0^1 G), in closed form on every piece after the ramp
        total = sum(L * (S0 + v0 * L / 2 + A * L**2 * shape.area()) for _, _, L, A, shape, S0, v0 in self._pieces[1:])
        total += 0.5 * self.dwell * self.S_h
        return total / (self.S_h * self.phi_p0)

    def checks(self) -> list:
        if self.reconstruction != "R2":
            return []
        src = cited(note("source.exponent_ranges", work="UkrSURT Proceedings (2019)"))
        return [check("law.power_polynomial.exponent", self.exponents[k], lo, hi, source=src, severity="info",
                      params={"exponent": k})
                for k, (lo, hi) in EXPONENT_RANGES.items()]

