"""The report's one rule for printing numbers (issue 24): significant figures, noise about a zero, powers of ten,
the decimal comma of Russian, margins in per cent."""

import numpy as np

ZERO_BELOW = 1e-6
"""Numbers of the report smaller than this in their unit print as 0: the noise of a computation about a zero (a cam
angle of 3.2e-7 deg, a residual of 1e-15)."""

SUPERSCRIPTS = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def number(x, lang="en") -> str:
    """A number in the report's one rule: 4 significant figures; an integer and a number of 10,000 or more in whole
    units; a number below :data:`ZERO_BELOW` as 0; below 0.0001 with a power of ten; a decimal comma in Russian.

    >>> [number(x) for x in (1.30337, 3.19142e-07, 57834.0, 0.000322464, 6.79592e-05, -0.0, 250)]
    ['1.303', '0', '57834', '0.0003225', '6.796·10⁻⁵', '0', '250']
    >>> number(1.30337, "ru")
    '1,303'
    """
    if isinstance(x, (int, np.integer)):
        return str(int(x))
    x = float(x)
    if x != x or abs(x) == float("inf"):
        return str(x)
    if abs(x) < ZERO_BELOW:
        return "0"
    if abs(x) >= 1e4:
        text = f"{x:.0f}"
    elif abs(x) < 1e-4:
        mantissa, exponent = f"{x:.3e}".split("e")
        text = f"{mantissa.rstrip('0').rstrip('.')}·10{str(int(exponent)).translate(SUPERSCRIPTS)}"
    else:
        text = f"{x:.4g}"
    return text.replace(".", ",") if lang == "ru" else text


def percent(x, lang="en") -> str:
    """A relative margin in per cent by :func:`number`'s rule, signed: ``0.0004`` -> ``"+0.04 %"`` (not "+0%").

    >>> percent(0.0004), percent(-0.26), percent(0.0026, "ru")
    ('+0.04 %', '-26 %', '+0,26 %')
    """
    text = number(100.0 * x, lang)
    return f"{'' if text.startswith('-') or text == '0' else '+'}{text} %"
