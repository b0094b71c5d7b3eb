"""Cam lift laws.  Every law is a :class:`~valvetrain.laws.base.LiftLaw`.

A law has analytic derivatives, its segment boundaries and its own checks; ramps and the clearance take-up are laws
too (:mod:`.ramps`, :mod:`.takeup`), a measured table is fitted (:mod:`.measured`, the fit chosen and why as codes).
:mod:`.records` holds what a law adds to the cam's results as frozen records (``LawRecord``: a Kurz cam's appendix
formulas and junction residuals, a power-polynomial synthesis's responses, a measured table's analysis), built by
the cam sections of the specification; :mod:`.errors` the reason code and the values in SI of inputs a law refuses,
its message built from them in one place (``LawError``).

A new law is its module here and its cam model in :mod:`valvetrain.specification.cams` (keys, ``problems``,
``build``, ``search_variables`` for the synthesis' defaults), decorated ``@register``; a key it needs is a README row
and a report name.
"""

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
