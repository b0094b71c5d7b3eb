"""Unit conversions at the edges of the package.

Everything inside the package is SI: m, s, rad, N, Pa.  Engineers write millimetres,
degrees, rpm and MPa; the spec reader, the tables and the report convert here and
nowhere else.

Angles: a *camshaft* angle and a *crank* angle are different quantities.  For a
four-stroke engine crank angle = 2 x camshaft angle (Valve-train practical works (n.d.), section 0); the
conversions take the number of strokes so that a two-stroke is handled too.
"""

from functools import cache

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


DISPLAY_UNITS = {
    "": 1.0, "mm": MM, "mm2": MM**2, "mm2 s": MM**2, "m": 1.0, "m/s": 1.0, "m/s2": 1.0, "m/s3": 1.0, "N": 1.0,
    "kN": 1e3, "cm3": 1e-6, "N/mm": 1.0 / MM, "N m": 1.0, "kg": 1.0, "kg/m2": 1.0, "kg mm2": MM**2, "MPa": MPA, "Pa": 1.0, "J": 1.0,
    "deg": DEG, "crank deg": DEG, "cam deg": DEG, "rad/s": 1.0, "Hz": 1.0, "rpm": np.pi / 30.0,
    "mm/rad2": MM, "mm/rad": MM, "mm/deg": MM / DEG, "mm crank deg": MM * DEG, "GPa": 1e3 * MPA, "us": 1e-6,
}
"""SI value of one display unit: a quantity of ``x`` SI is shown as ``x / DISPLAY_UNITS[unit]`` (tables,
reports, check records); ``rpm`` is shown from rad/s."""


def to_display(value, unit):
    """An SI value (or array) in the display ``unit`` of :data:`DISPLAY_UNITS`.

    >>> round(to_display(0.0118, "mm"), 9), round(to_display(np.pi, "crank deg"), 9)
    (11.8, 180.0)
    """
    try:
        return value / DISPLAY_UNITS[unit]
    except KeyError:
        raise ValueError(f"unit {unit!r}: allowed {sorted(DISPLAY_UNITS)}") from None


UNIT_SUFFIXES = (
    ("_cm3_per_s_MPa", 1e-6 / MPA), ("_cm3", 1e-6), ("_GPa", 1e3 * MPA),
    ("_mm_per_rad2", MM), ("_mm_per_rad", MM), ("_mm_per_deg", MM / DEG), ("_N_per_mm", 1.0 / MM), ("_kg_mm2", MM**2), ("_mm2", MM**2), ("_mm", MM),
    ("_cam_deg", DEG), ("_deg", DEG), ("_rpm", rpm_to_rad_s(1.0)), ("_MPa", MPA),
)
"""Key suffixes of non-SI units and the SI value of one unit; the first suffix that ends a key applies."""


@cache
def si_name(key):
    """The SI field of a key and the factor to SI: ``("throat_diameter", 1e-3)`` for ``throat_diameter_mm``.

    >>> si_name("rated_speed_rpm")[0], si_name("valve_kg")
    ('rated_speed', ('valve_kg', 1.0))
    """
    for suffix, factor in UNIT_SUFFIXES:
        if key.endswith(suffix):
            return key[: -len(suffix)], factor
    return key, 1.0
