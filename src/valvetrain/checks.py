"""Design checks as data.

Every computed design is compared with the recommended ranges of the sources.  A value
outside its range is not an exception: it becomes a :class:`Finding`, a record of the
quantity, its value, the allowed range and the source of the range.  The report lists
the findings and ``results.json`` carries them under ``warnings``.
"""

from dataclasses import asdict, dataclass
import math


@dataclass(frozen=True)
class Finding:
    """One value outside its recommended range.

    Attributes
    ----------
    quantity : str
        What was checked, with the part it belongs to (e.g. ``"intake: V' (throat)"``).
    value : float
        The computed value, in ``unit``.
    range : str
        The allowed or recommended range, as text with its unit (e.g. ``"50...80 m/s"``).
    source : str
        Where the range comes from (seed and equation or section).
    unit : str
        Unit of ``value``.
    """

    quantity: str
    value: float
    range: str
    source: str
    unit: str = ""

    def as_dict(self):
        return asdict(self)


_TOL = 1e-9
"""Relative tolerance at a bound, so that a value printed as the bound (0.46 = 36.8/80) is inside."""


def _fmt(x):
    return f"{x:g}"


def describe_range(low=None, high=None, unit=""):
    """Text of a range ``low...high`` (either side may be open) with its unit."""
    suffix = f" {unit}" if unit else ""
    if low is not None and low == high:
        return f"{_fmt(low)}{suffix}"
    if low is not None and high is not None:
        return f"{_fmt(low)}...{_fmt(high)}{suffix}"
    if low is not None:
        return f">= {_fmt(low)}{suffix}"
    if high is not None:
        return f"<= {_fmt(high)}{suffix}"
    raise ValueError("a range needs at least one bound")


def check_range(quantity, value, low=None, high=None, *, source, unit="", strict_low=False):
    """Compare a value with a recommended range.

    Parameters
    ----------
    quantity : str
        Name of the checked quantity.
    value : float
        Value in ``unit``.
    low, high : float or None
        Bounds of the recommended range (inclusive); ``None`` leaves that side open.
    source : str
        Source of the range.
    unit : str
        Unit of value and bounds.
    strict_low : bool
        If true the lower bound itself is outside the range (``value > low`` required).

    Returns
    -------
    list of Finding
        Empty when the value is inside the range, otherwise one finding.

    Examples
    --------
    >>> check_range("V'", 85.07, 50, 80, source="seed 000, work 1", unit="m/s")[0].range
    '50...80 m/s'
    >>> check_range("V'", 70.0, 50, 80, source="seed 000, work 1", unit="m/s")
    []
    """
    value = float(value)
    bad = not math.isfinite(value)
    if low is not None:
        bad |= value <= low if strict_low else value < low - _TOL * max(1.0, abs(low))
    if high is not None:
        bad |= value > high + _TOL * max(1.0, abs(high))
    if not bad:
        return []
    text = describe_range(low, high, unit)
    if strict_low and high is None:
        text = f"> {_fmt(low)}{' ' + unit if unit else ''}"
    return [Finding(quantity, value, text, source, unit)]
