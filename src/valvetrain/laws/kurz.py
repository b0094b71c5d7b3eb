"""Kurz shock-free cam (Valve-train practical works (n.d.), work 2).

Cosine ramp Phi0, half-sine positive acceleration Phi1, quarter-sine negative
acceleration Phi2 and a parabolic negative acceleration (quartic lift) Phi3 up to the
nose; symmetric closing flank.  The seven coefficients are the exact closed-form
solution of the continuity system (2.9)-(2.22).
"""

from dataclasses import asdict, dataclass

import numpy as np
from numba import njit

from ..checks import check
from ..errors import InputError
from ..locale import cited, note
from .base import RampedLaw, SymmetricLaw, mirror
from .ramps import make_ramp, ramp_at

RAMP_VELOCITY_RANGE_MM_PER_DEG = (0.008, 0.022)
"""Recommended tappet velocity at the end of the ramp [mm/deg cam] (Valve-train practical works (n.d.), eq. 2.1)."""

PHI2_TO_PHI3_RANGE = (0.10, 0.25)
"""Recommended Phi2/Phi3 (Valve-train practical works (n.d.), eq. 2.3)."""

NEGATIVE_TO_POSITIVE_RANGE = (1.5, 3.0)
"""Recommended (Phi2 + Phi3)/Phi1 (Valve-train practical works (n.d.), eq. 2.4)."""


@dataclass(frozen=True)
class KurzCoefficients:
    """Coefficients of the Kurz law in the length unit of its inputs (L).

    ``c11, c21`` [L/rad], ``c12, c22, c33`` [L], ``c32`` [L/rad^2], ``c31`` [L/rad^4];
    the auxiliaries ``k1`` [rad^2], ``k2`` [rad^2], ``k3`` [rad], ``K1`` [rad^2], ``K2`` [rad].
    """

    c11: float
    c12: float
    c21: float
    c22: float
    c31: float
    c32: float
    c33: float
    k1: float
    k2: float
    k3: float
    K1: float
    K2: float


def kurz_coefficients(lift, ramp_velocity, phi1, phi2, phi3, shape_factor=0.625) -> KurzCoefficients:
    """Closed-form coefficients of the Kurz cam.

    Parameters
    ----------
    lift : float
        Maximum tappet lift above the ramp, h_T max [L, any length unit].
    ramp_velocity : float
        Tappet velocity at the end of the ramp per camshaft radian, w' [L/rad].
    phi1, phi2, phi3 : float
        Lengths of the positive, first negative and second negative acceleration
        segments Phi1, Phi2, Phi3 [rad camshaft].
    shape_factor : float
        Z = j_T2K / j_T3K, the ratio of the negative accelerations at the Phi2/Phi3
        junction and at the nose (5/8 recommended).

    Returns
    -------
    KurzCoefficients

    Notes
    -----
    .. math::

        k_1 = 8Z(\\Phi_2/\\pi)^2,\\ k_2 = (5+Z)\\Phi_3^2/6,\\ k_3 = (4+2Z)\\Phi_3/3,\\
        K_1 = k_1+k_2+k_3\\Phi_2,\\ K_2 = k_3 + 4Z\\Phi_2/\\pi

        c_{11} = \\frac{K_1 w' + K_2 h}{2K_1 + K_2\\Phi_1},\\
        c_{12} = (c_{11}-w')\\Phi_1/\\pi,\\ c_{32} = -(2c_{11}-w')/K_2,

        c_{21} = -c_{32}k_3,\\ c_{22} = -c_{32}k_1,\\ c_{31} = c_{32}(Z-1)/(6\\Phi_3^2),\\
        c_{33} = -c_{32}k_2

    References
    ----------
    Valve-train practical works (n.d.), work 2, eqs. (2.23)-(2.34) (verified on the appendix example).

    Examples
    --------
    The appendix of Valve-train practical works (n.d.) (h = 6.25 mm, w' = 0.02 mm/deg, Phi = 27/6/38 deg):

    >>> c = kurz_coefficients(6.25, 0.02 * 180 / np.pi, *np.deg2rad([27, 6, 38]))
    >>> round(c.c11, 6), round(c.c32, 6), round(c.c33, 6)
    (5.040392, -7.182502, 2.96189)
    """
    Z = shape_factor
    k1 = 8.0 * Z * (phi2 / np.pi) ** 2
    k2 = (5.0 + Z) * phi3**2 / 6.0
    k3 = (4.0 + 2.0 * Z) * phi3 / 3.0
    K1 = k1 + k2 + k3 * phi2
    K2 = k3 + 4.0 * Z * phi2 / np.pi
    c11 = (K1 * ramp_velocity + K2 * lift) / (2.0 * K1 + K2 * phi1)
    c12 = (c11 - ramp_velocity) * phi1 / np.pi
    c32 = -(2.0 * c11 - ramp_velocity) / K2
    values = dict(c11=c11, c12=c12, c21=-c32 * k3, c22=-c32 * k1, c31=c32 * (Z - 1.0) / (6.0 * phi3**2), c32=c32,
                  c33=-c32 * k2, k1=k1, k2=k2, k3=k3, K1=K1, K2=K2)
    return KurzCoefficients(**{k: float(v) for k, v in values.items()})


class KurzLaw(RampedLaw, SymmetricLaw):
    """Kurz shock-free cam law.

    Parameters
    ----------
    lift : float
        Maximum tappet lift above the ramp h_T max [m].
    clearance : float
        Valve clearance at the cam h0 = ramp height [m], > 0.
    ramp_velocity : float
        Tappet velocity at the end of the ramp per camshaft radian w' [m/rad], > 0.
    phi1, phi2, phi3 : float
        Segment lengths Phi1, Phi2, Phi3 [rad camshaft]; their sum is phi_p0 (eq. 2.2).
    shape_factor : float
        Z (eq. 2.22), default 5/8.
    ramp_kind : str
        ``cosine`` (Valve-train practical works (n.d.), eq. 2.5; default), ``constant_velocity`` or ``constant_acceleration``:
        the coefficients depend only on the ramp's end velocity, and every ramp ends at zero
        acceleration, so the main lift joins any of them as in (2.13).
    ramp_fraction : float
        Acceleration share of a ``constant_acceleration`` ramp.

    Examples
    --------
    >>> law = KurzLaw(6.25e-3, 0.25e-3, 0.02e-3 * 180 / np.pi, *np.deg2rad([27, 6, 38]))
    >>> round(float(law.lift(0.0)) * 1e3, 6)  # nose: h_T max + h0 [mm]
    6.5
    """

    name = "kurz"
    source = cited(note("source.kurz", work="Valve-train practical works (n.d.), work 2"))

    def __init__(self, lift, clearance, ramp_velocity, phi1, phi2, phi3, shape_factor=0.625, ramp_kind="cosine",
                 ramp_fraction=0.5):
        if not (lift > 0 and clearance > 0 and ramp_velocity > 0 and phi1 > 0 and phi2 > 0 and phi3 > 0):
            raise InputError("Kurz law: lift, clearance, ramp velocity and Phi1..Phi3 must be positive")
        if not 0.0 < shape_factor < 1.0:
            raise InputError(f"Kurz law: shape factor Z = {shape_factor!r}: allowed 0 < Z < 1")
        self._lift = float(lift)
        self.clearance = float(clearance)
        self.ramp_velocity = float(ramp_velocity)
        self.phi1, self.phi2, self.phi3 = float(phi1), float(phi2), float(phi3)
        self.shape_factor = float(shape_factor)
        self.ramp = make_ramp(ramp_kind, self.clearance, self.ramp_velocity, ramp_fraction)
        self.phi0 = float(self.ramp.length)
        self.c = kurz_coefficients(self._lift, self.ramp_velocity, self.phi1, self.phi2, self.phi3, self.shape_factor)
        self._edges = np.cumsum([0.0, self.phi0, self.phi1, self.phi2, self.phi3])
        c = self.c
        self._kernel_arguments = (self.half_angle, self._edges, self.ramp.parameters,
                                  (self.clearance, c.c11, c.c12, c.c21, c.c22, c.c31, c.c32, c.c33, self.phi1,
                                   self.phi2, self.phi3))

    @property
    def main_half_angle(self) -> float:
        """phi_p0 = Phi1 + Phi2 + Phi3, from the end of the ramp to the nose [rad] (eq. 2.2)."""
        return self.phi1 + self.phi2 + self.phi3

    @property
    def half_angle(self) -> float:
        return float(self._edges[-1])

    def _rise_segments(self):
        e = self._edges
        return [("ramp", e[0], e[1]), ("Phi1", e[1], e[2]), ("Phi2", e[2], e[3]), ("Phi3", e[3], e[4])]

    def _mirrored(self, theta, out):
        _kurz_kernel(theta, out, *self._kernel_arguments)

    def coefficients(self) -> dict:
        """Coefficients and auxiliaries in the manual's units (mm, rad), keys as in Valve-train practical works (n.d.)."""
        return {k: v * 1e3 if k.startswith("c") else v for k, v in asdict(self.c).items()}

    def residuals(self) -> dict:
        """Residuals of the continuity system (2.10), (2.12), (2.14), (2.16), (2.18), (2.20), (2.22) [mm, rad].

        With the closed-form coefficients they vanish to round-off; the appendix of
        Valve-train practical works (n.d.) prints residuals up to 8.2e-5 because it rounded the coefficients (corrections note 11).
        """
        c = {k: v * 1e3 for k, v in asdict(self.c).items() if k.startswith("c")}
        f1, f2, f3, Z = self.phi1, self.phi2, self.phi3, self.shape_factor
        w, h = self.ramp_velocity * 1e3, self._lift * 1e3
        m = np.pi / (2.0 * f2)
        return {
            "2.10": c["c11"] * f1 + c["c21"] * f2 + c["c22"] + c["c33"] - h,
            "2.12": c["c31"] * f3**4 + c["c32"] * f3**2 + c["c33"],
            "2.14": c["c11"] - c["c12"] * np.pi / f1 - w,
            "2.16": c["c11"] + c["c12"] * np.pi / f1 - c["c21"] - c["c22"] * m,
            "2.18": c["c21"] + 4.0 * c["c31"] * f3**3 + 2.0 * c["c32"] * f3,
            "2.20": c["c22"] * m**2 + 12.0 * c["c31"] * f3**2 + 2.0 * c["c32"],
            "2.22": -c["c22"] * m**2 / (2.0 * c["c32"]) - Z,
        }

    def seed_formulas(self, base_radius, omega) -> dict:
        """The closed-form extremes of Valve-train practical works (n.d.) (2.35)-(2.39), follower side, SI.

        Parameters
        ----------
        base_radius : float
            Cam base-circle radius r0 [m].
        omega : float
            Camshaft speed [rad/s].

        Returns
        -------
        dict
            ``max_velocity`` (2.35) [m/s], ``max_acceleration`` (2.36) and
            ``min_acceleration`` (2.37) [m/s^2], ``rho_min`` (2.38) and ``rho_max`` (2.39)
            [m].  (2.39) is evaluated at Phi1/2, slightly below the true maximum (corrections note 16);
            the profile extremes are computed along the contour by
            :mod:`valvetrain.geometry`.
        """
        c, f1 = self.c, self.phi1
        return {
            "max_velocity": -omega * c.K2 * c.c32,
            "max_acceleration": omega**2 * c.c12 * (np.pi / f1) ** 2,
            "min_acceleration": 2.0 * omega**2 * c.c32,
            "rho_min": base_radius + self._lift + 2.0 * c.c32,
            "rho_max": base_radius + c.c11 * f1 / 2.0 + c.c12 * ((np.pi / f1) ** 2 - 1.0),
        }

    def checks(self) -> list:
        """Recommended ranges of (2.1), (2.3) and (2.4)."""
        return [
            check("ramp.end_velocity", self.ramp_velocity, *(w * 1e-3 / np.radians(1.0)
                                                             for w in RAMP_VELOCITY_RANGE_MM_PER_DEG),
                  source="Valve-train practical works (n.d.), work 2, eq. (2.1)", unit="mm/deg"),
            check("law.kurz.phi2_to_phi3", self.phi2 / self.phi3, *PHI2_TO_PHI3_RANGE, source="Valve-train practical works (n.d.), work 2, eq. (2.3)"),
            check("law.kurz.negative_to_positive", (self.phi2 + self.phi3) / self.phi1, *NEGATIVE_TO_POSITIVE_RANGE,
                  source="Valve-train practical works (n.d.), work 2, eq. (2.4)"),
        ]


@njit(cache=True)
def _kurz_kernel(theta, out, half, edges, ramp, coefficients):
    """Kurz law at the angles ``theta`` into ``out`` (zeros, shape (4, n)), one pass (see :class:`KurzLaw`).

    Notes
    -----
    With x the angle from the start of each segment: the ramp (:func:`~.ramps.ramp_at`); Phi1
    :math:`h = h_0 + c_{11}x - c_{12}\\sin(\\pi x/\\Phi_1)`; Phi2
    :math:`h = h_{1K} + c_{21}x + c_{22}\\sin(\\pi x/(2\\Phi_2))`; Phi3, with y = Phi3 - x the angle to
    the nose, :math:`h = h_{2K} + c_{31}y^4 + c_{32}y^2 + c_{33}`; :math:`h_{1K} = h_0 + c_{11}\\Phi_1`,
    :math:`h_{2K} = h_{1K} + c_{21}\\Phi_2 + c_{22}`, and their derivatives.

    References
    ----------
    Valve-train practical works (n.d.), work 2, eqs. (2.5)-(2.8).
    """
    h0, c11, c12, c21, c22, c31, c32, c33, phi1, phi2, phi3 = coefficients
    k1, k2 = np.pi / phi1, np.pi / (2.0 * phi2)
    h1k = h0 + c11 * phi1
    h2k = h1k + c21 * phi2 + c22
    for i in range(theta.size):
        phi, flip = mirror(theta[i], half)
        if phi < 0.0:
            continue
        if phi < edges[1]:
            h, v, a, j = ramp_at(ramp[0], phi, ramp[1], ramp[2], ramp[3], ramp[4])
        elif phi < edges[2]:
            x = phi - edges[1]
            s, co = np.sin(k1 * x), np.cos(k1 * x)
            h, v, a, j = h0 + c11 * x - c12 * s, c11 - c12 * k1 * co, c12 * k1**2 * s, c12 * k1**3 * co
        elif phi < edges[3]:
            x = phi - edges[2]
            s, co = np.sin(k2 * x), np.cos(k2 * x)
            h, v, a, j = h1k + c21 * x + c22 * s, c21 + c22 * k2 * co, -c22 * k2**2 * s, -c22 * k2**3 * co
        else:
            y = phi3 - (phi - edges[3])
            h = h2k + c31 * y**4 + c32 * y**2 + c33
            v, a, j = -(4.0 * c31 * y**3 + 2.0 * c32 * y), 12.0 * c31 * y**2 + 2.0 * c32, -24.0 * c31 * y
        out[0, i], out[1, i], out[2, i], out[3, i] = h, flip * v, a, flip * j
