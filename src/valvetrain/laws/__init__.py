"""Cam lift laws.  Every law is a :class:`~valvetrain.laws.base.LiftLaw`."""

from .asymmetric import AsymmetricLaw
from .base import Extremes, LiftLaw, Segment, SymmetricLaw
from .combined import CombinedLaw
from .constant_acceleration import ConstantAccelerationLaw
from .convex import TangentLaw, ThreeArcLaw
from .dynamic import DynamicLaw
from .harmonic import HarmonicLaw, harmonic_limit
from .kurz import KurzLaw, kurz_coefficients
from .polydyne import PolydyneLaw, PolynomialLaw, default_exponents, polydyne_coefficients
from .power_polynomial import PowerPolynomialLaw
from .ramps import make_ramp

__all__ = [
    "AsymmetricLaw", "CombinedLaw", "ConstantAccelerationLaw", "DynamicLaw", "HarmonicLaw", "harmonic_limit", "TangentLaw", "ThreeArcLaw", "Extremes", "LiftLaw", "Segment", "SymmetricLaw", "KurzLaw", "kurz_coefficients", "PolydyneLaw",
    "PolynomialLaw", "PowerPolynomialLaw", "default_exponents", "make_ramp", "polydyne_coefficients",
]
