"""Unit conversions at the edges of the package.

Everything inside the package is SI: m, s, rad, N, Pa.  Engineers write millimetres,
degrees, rpm and MPa; the spec reader, the tables and the report convert here and
nowhere else.

Angles: a *camshaft* angle and a *crank* angle are different quantities.  For a
four-stroke engine crank angle = 2 x camshaft angle (Valve-train practical works (n.d.), section 0); the
conversions take the number of strokes so that a two-stroke is handled too.
"""

from functools import cache
import math

import numpy as np

from .errors import InputError
from .languages import LANGS

MM = 1e-3
"""metres per millimetre"""

MPA = 1e6
"""pascals per megapascal"""


DEG = np.pi / 180.0
"""radians per degree"""


def rad_to_deg(x) -> float | np.ndarray:
    """Radians to degrees (any angle, crank or camshaft: the kind is kept)."""
    return x / DEG


def rpm_to_rad_s(n) -> float | np.ndarray:
    """Rotational speed in min^-1 to angular velocity in rad/s, omega = pi n / 30."""
    return np.pi * n / 30.0


def cam_per_crank(strokes) -> float:
    """Camshaft revolutions per crank revolution: 1/2 for a four-stroke, 1 for a two-stroke."""
    if strokes not in (2, 4):
        raise InputError(f"strokes = {strokes!r}: allowed values are 2 and 4")
    return 2.0 / strokes


UNITS = {
    # unit: SI value of one unit, the key suffixes that name it, its symbol in English and in Russian
    "": (1.0, (), "", ""),
    "mm": (MM, ("_mm",), "mm", "мм"),
    "mm2": (MM**2, ("_mm2",), "mm²", "мм²"),
    "mm2 s": (MM**2, ("_mm2_s",), "mm²·s", "мм²·с"),
    "mm4": (MM**4, (), "mm⁴", "мм⁴"),
    "m": (1.0, (), "m", "м"),
    "m/s": (1.0, ("_m_s",), "m/s", "м/с"),
    "m/s2": (1.0, ("_m_s2",), "m/s²", "м/с²"),
    "m/s3": (1.0, ("_m_s3",), "m/s³", "м/с³"),
    "N": (1.0, ("_N",), "N", "Н"),
    "kN": (1e3, ("_kN",), "kN", "кН"),
    "N/mm": (1.0 / MM, ("_N_per_mm",), "N/mm", "Н/мм"),
    "N m": (1.0, ("_Nm",), "N·m", "Н·м"),
    "N m/rad": (1.0, ("_Nm_per_rad",), "N·m/rad", "Н·м/рад"),
    "N s/m": (1.0, ("_N_s_per_m",), "N·s/m", "Н·с/м"),
    "cm3": (1e-6, ("_cm3",), "cm³", "см³"),
    "cm3/(s MPa)": (1e-6 / MPA, ("_cm3_per_s_MPa",), "cm³/(s·MPa)", "см³/(с·МПа)"),
    "kg": (1.0, ("_kg",), "kg", "кг"),
    "mg": (1e-6, ("_mg",), "mg", "мг"),
    "g/s": (1e-3, ("_g_s",), "g/s", "г/с"),
    "kg mm2": (MM**2, ("_kg_mm2",), "kg·mm²", "кг·мм²"),
    "kg/m2": (1.0, ("_kg_m2",), "kg/m²", "кг/м²"),
    "kg/m3": (1.0, ("_kg_m3",), "kg/m³", "кг/м³"),
    "Pa": (1.0, (), "Pa", "Па"),
    "kPa": (1e3, ("_kPa",), "kPa", "кПа"),
    "MPa": (MPA, ("_MPa",), "MPa", "МПа"),
    "GPa": (1e3 * MPA, ("_GPa",), "GPa", "ГПа"),
    "J": (1.0, ("_J",), "J", "Дж"),
    "deg": (DEG, ("_deg",), "deg", "град"),
    "crank deg": (DEG, ("_crank_deg",), "crank deg", "град ПКВ"),
    "cam deg": (DEG, ("_cam_deg",), "cam deg", "град ПРВ"),
    "rad": (1.0, (), "rad", "рад"),
    "rad2": (1.0, (), "rad²", "рад²"),
    "rad/s": (1.0, ("_rad_s",), "rad/s", "рад/с"),
    "rpm": (np.pi / 30.0, ("_rpm",), "rpm", "мин⁻¹"),
    "Hz": (1.0, ("_Hz",), "Hz", "Гц"),
    "us": (1e-6, ("_us",), "µs", "мкс"),
    "ms": (1e-3, ("_ms",), "ms", "мс"),
    "mm/rad2": (MM, ("_mm_per_rad2", "_mm_rad2"), "mm/rad²", "мм/рад²"),
    "mm/rad": (MM, ("_mm_per_rad", "_mm_rad"), "mm/rad", "мм/рад"),
    "mm/deg": (MM / DEG, ("_mm_per_deg",), "mm/deg", "мм/град"),
    "mm crank deg": (MM * DEG, ("_mm_crank_deg",), "mm·crank deg", "мм·град ПКВ"),
    "mm cam deg": (MM * DEG, (), "mm·cam deg", "мм·град ПРВ"),
    "%": (0.01, ("_percent",), "%", "%"),
    "um": (1e-6, ("_um",), "µm", "мкм"),
    "mPa s": (1e-3, ("_mPa_s",), "mPa·s", "мПа·с"),
    "1/GPa": (1e-9, ("_per_GPa",), "1/GPa", "1/ГПа"),
    "W": (1.0, (), "W", "Вт"),
    "kW": (1e3, ("_kW",), "kW", "кВт"),
    "K": (1.0, ("_K",), "K", "К"),
    "degC": (1.0, ("_C",), "°C", "°C"),
}
"""The one unit table: every unit a key, a table, a record or the report shows, the SI value of one unit (a quantity
of ``x`` SI is shown as ``x / value``; ``rpm`` is shown from rad/s), the key suffixes that name it (``_N_per_mm``)
and its symbol in each language of the report (:data:`valvetrain.languages.LANGS`).  The SI view of a
specification (:func:`si_name`), the display of the records (:func:`to_display`) and the report's units
(:func:`symbol`, :data:`SUFFIXES`) derive from it."""

SUFFIXES = tuple(sorted(((suffix, unit) for unit, (_, suffixes, *_) in UNITS.items() for suffix in suffixes),
                        key=lambda pair: -len(pair[0])))
"""``(key suffix, unit)`` of every suffix of :data:`UNITS`, the longest first."""


def to_display(value, unit) -> float | np.ndarray:
    """An SI value (or array) in the display ``unit`` of :data:`UNITS`.

    >>> round(to_display(0.0118, "mm"), 9), round(to_display(np.pi, "crank deg"), 9)
    (11.8, 180.0)
    """
    try:
        return value / UNITS[unit][0]
    except KeyError:
        raise InputError(f"unit {unit!r}: allowed {sorted(UNITS)}") from None


def per_cam_degree(value, order, omega) -> float | np.ndarray:
    """A derivative of a lift at the camshaft speed ``omega`` [rad/s] (m/s, m/s2, m/s3 for ``order`` 1, 2, 3) as
    the speed-independent derivative in mm per camshaft degree to the ``order``.

    Notes
    -----
    d^n h / d phi^n = (d^n h / d t^n) / omega^n, as d phi = omega d t; then m -> mm and rad -> deg.

    >>> round(per_cam_degree(1.0, 1, 180.0), 12)      # 1 m/s at 180 rad/s: 1/180 m/rad = 1000/180 x pi/180 mm/deg
    0.096962736222
    """
    return value * (DEG / omega) ** order / MM


TURNS = {"deg": 360.0, "cam deg": 360.0, "crank deg": 720.0}
"""A full turn (a cycle) of each angle unit of :data:`UNITS`: an angle computed in radians on a revolution or a cycle
carries the round-off of the turn (a few units in the last place of 2 pi, 4 pi), not of its own size."""


def without_noise(value, digits=12, scale=0.0) -> float:
    """A value shown in a display unit without the float noise of its conversion: rounded to ``digits`` significant
    digits where that moves it by four units in the last place at most (:func:`math.ulp`), kept otherwise.  A value
    smaller than ``scale`` (the magnitude its computation passed through: a turn for an angle) is rounded to the
    ``digits`` of the scale, and may move by four units in the last place of the scale.

    A bound written as 60 deg in its source and kept in radians is shown as 60 again, not 59.99999999999999; a value
    of more digits (8/3) is kept as it is; the grid angle -0.1 deg of a revolution from -180 deg is shown as -0.1
    with the scale 360 deg, not -0.10000000000001923, while a twist of 0.11399658396381009 deg keeps its digits.

    >>> without_noise(to_display(60.0 * DEG, "deg")), without_noise(8.0 / 3.0)
    (60.0, 2.6666666666666665)
    >>> without_noise(-0.10000000000001923), without_noise(-0.10000000000001923, scale=360.0)
    (-0.10000000000001923, -0.1)
    >>> without_noise(0.11399658396381009, scale=360.0)
    0.11399658396381009
    """
    if abs(value) < scale:
        rounded = round(value, digits - 1 - math.floor(math.log10(scale)))
    else:
        rounded = float(f"{value:.{digits}g}")
    return rounded if abs(rounded - value) <= 4.0 * math.ulp(max(abs(value), scale)) else value


def displayed(value, unit) -> float:
    """An SI number as the results show it in the display ``unit`` of :data:`UNITS`: :func:`to_display` without the
    noise of the conversion (:func:`without_noise`), and for an angle without the noise of its computation on the
    turn (:data:`TURNS`).

    >>> float(to_display(np.radians(250.0) - np.radians(276.0), "crank deg"))   # an event: 250 - 2 x 138
    -25.99999999999996
    >>> displayed(np.radians(250.0) - np.radians(276.0), "crank deg"), displayed(0.0118, "mm")
    (-26.0, 11.8)
    """
    return without_noise(float(to_display(float(value), unit)), scale=TURNS.get(unit, 0.0))


@cache
def si_name(key) -> tuple[str, float]:
    """The SI field of a key and the factor to SI: ``("throat_diameter", 1e-3)`` for ``throat_diameter_mm``.

    The longest suffix of :data:`SUFFIXES` that ends the key names its unit; a key in a unit other than SI loses the
    suffix, a key in SI (``valve_kg``, ``min_preload_N``) keeps its name.

    >>> si_name("rated_speed_rpm")[0], si_name("valve_kg")
    ('rated_speed', ('valve_kg', 1.0))
    """
    for suffix, unit in SUFFIXES:
        if key.endswith(suffix):
            factor = UNITS[unit][0]
            return (key, 1.0) if factor == 1.0 else (key[: -len(suffix)], factor)
    return key, 1.0


def symbol(unit, lang) -> str:
    """A unit as the report in ``lang`` prints it (``"m/s2"`` -> ``"m/s²"``, ``"м/с²"``); a unit not in
    :data:`UNITS` as it is."""
    row = UNITS.get(unit)
    return unit if row is None else row[2 + LANGS.index(lang)]
