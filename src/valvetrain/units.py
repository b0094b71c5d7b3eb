"""Unit conversions at the edges of the package.

Everything inside the package is SI: m, s, rad, N, Pa.  Engineers write millimetres,
degrees, rpm and MPa; the spec reader, the tables and the report convert here and
nowhere else.

Angles: a *camshaft* angle and a *crank* angle are different quantities.  For a
four-stroke engine crank angle = 2 x camshaft angle (seed 000, section 0); the
conversions take the number of strokes so that a two-stroke is handled too.
"""

import numpy as np

MM = 1e-3
"""metres per millimetre"""

MPA = 1e6
"""pascals per megapascal"""


DEG = np.pi / 180.0
"""radians per degree"""


def mm_to_m(x):
    """Millimetres to metres."""
    return x * MM


def m_to_mm(x):
    """Metres to millimetres."""
    return x / MM


def deg_to_rad(x):
    """Degrees to radians (any angle, crank or camshaft: the kind is kept)."""
    return x * DEG


def rad_to_deg(x):
    """Radians to degrees (any angle, crank or camshaft: the kind is kept)."""
    return x / DEG


def rpm_to_rad_s(n):
    """Rotational speed in min^-1 to angular velocity in rad/s, omega = pi n / 30."""
    return np.pi * n / 30.0


def cam_per_crank(strokes):
    """Camshaft revolutions per crank revolution: 1/2 for a four-stroke, 1 for a two-stroke."""
    if strokes not in (2, 4):
        raise ValueError(f"strokes = {strokes!r}: allowed values are 2 and 4")
    return 2.0 / strokes


def crank_to_cam(angle, strokes=4):
    """Crank angle to camshaft angle (same unit in and out)."""
    return angle * cam_per_crank(strokes)


def cam_to_crank(angle, strokes=4):
    """Camshaft angle to crank angle (same unit in and out)."""
    return angle / cam_per_crank(strokes)
