"""Cam lift laws.  Every law is a :class:`~valvetrain.laws.base.LiftLaw`."""

from .base import Extremes, LiftLaw, Segment, SymmetricLaw
from .kurz import KurzLaw, kurz_coefficients
from .polydyne import PolydyneLaw, default_exponents, polydyne_coefficients

__all__ = [
    "Extremes", "LiftLaw", "Segment", "SymmetricLaw", "KurzLaw", "kurz_coefficients", "PolydyneLaw",
    "default_exponents", "polydyne_coefficients",
]
