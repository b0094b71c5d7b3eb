"""The cam card: the figures cams are specified and compared by (events at checking heights, lobe centres, lobe
separation, lift at TDC, overlap and its area).

Crank angles are from the gas-exchange TDC (positive after it), camshaft angles from the cam nose, as everywhere in
valvetrain: a valve whose nose sits at crank angle ``nose`` has its lift at crank angle ``c`` at the camshaft angle
``(c - nose) / 2`` (a four-stroke's camshaft turns at half the crank speed).  SI: m, rad.

Notes
-----
The checking heights and the figures are the cam trade's conventions (cam makers' cards); no work of the
bibliography defines them, so they are stated here: 0.050 in of tappet lift above the heel circle, 1 mm of valve
lift, seat to seat (where the valve leaves and meets its seat); the lobe centre is the nose's crank angle; the lobe
separation the camshaft angle between the two lobes' centres; the overlap exhaust closing less intake opening
(negative: none).
"""

import numpy as np

TAPPET_CHECKING_HEIGHT = 0.050 * 25.4e-3
"""Tappet lift above the heel circle at which the American cam card gives its events and durations [m]."""

VALVE_CHECKING_HEIGHT = 1.0e-3
"""Valve lift at which the European cam card gives its events and durations [m]."""


def crank_events(cam_angles, nose) -> float | np.ndarray:
    """Crank angles [rad from the gas-exchange TDC] of camshaft angles [rad from the nose] of a lobe whose nose is
    at crank angle ``nose`` [rad]: ``nose + 2 theta``."""
    return nose + 2.0 * np.asarray(cam_angles, dtype=float)


def tappet_events(law, nose, height=TAPPET_CHECKING_HEIGHT) -> tuple[float, float]:
    """Opening and closing crank angles [rad] where the tappet lift passes ``height`` [m] above the heel circle
    (the law's lift, ramp included); ``(nan, nan)`` where it never reaches it."""
    return tuple(float(c) for c in crank_events(law.crossings(height), nose))


def valve_events(law, rocker_ratio, nose, height=VALVE_CHECKING_HEIGHT) -> tuple[float, float]:
    """Opening and closing crank angles [rad] where the valve lift i_k (h - h0) passes ``height`` [m], i.e. the
    tappet lift passes h0 + height / i_k; ``(nan, nan)`` where it never reaches it."""
    return tappet_events(law, nose, law.ramp_height + height / rocker_ratio)


def lift_at(law, rocker_ratio, nose, crank) -> np.ndarray:
    """Valve lift [m] at crank angles ``crank`` [rad from the gas-exchange TDC] (0 off the lobe)."""
    theta = (np.asarray(crank, dtype=float) - nose) / 2.0
    inside = (theta >= law.start) & (theta <= law.end)
    return np.where(inside, law.valve_lift(np.clip(theta, law.start, law.end), rocker_ratio), 0.0)


def lobe_separation(intake_nose, exhaust_nose) -> float:
    """Lobe separation angle [rad, camshaft]: the camshaft angle between the exhaust lobe's centre and the intake's,
    (nose_in - nose_ex) / 2 (crank angles halved).

    >>> round(float(np.degrees(lobe_separation(np.radians(108.0), np.radians(-112.0)))), 9)
    110.0
    """
    return (intake_nose - exhaust_nose) / 2.0


def overlap(intake_opens, exhaust_closes) -> float:
    """Overlap [crank rad]: exhaust closing less intake opening (negative where the intake opens after the exhaust
    closes: no overlap at that height)."""
    return exhaust_closes - intake_opens


def overlap_area(intake, exhaust, samples=2001) -> float:
    """The area under the lower of the two valve lifts over the overlap [m rad, crank]: the overlap's lift-angle
    area, trapezoidal on ``samples`` points.

    Parameters
    ----------
    intake, exhaust : (law, rocker_ratio, nose)
        Each valve's law, rocker ratio and nose crank angle [rad].

    Notes
    -----
    A = int from IO to EC of min(h_in(c), h_ex(c)) dc, with IO the intake's opening and EC the exhaust's closing
    (seat to seat); 0 without an overlap.
    """
    (law_in, ik_in, nose_in), (law_ex, ik_ex, nose_ex) = intake, exhaust
    opens = float(crank_events(law_in.valve_opens, nose_in))
    closes = float(crank_events(law_ex.valve_closes, nose_ex))
    if closes <= opens:
        return 0.0
    c = np.linspace(opens, closes, samples)
    low = np.minimum(lift_at(law_in, ik_in, nose_in, c), lift_at(law_ex, ik_ex, nose_ex, c))
    return float(np.sum((low[1:] + low[:-1]) * np.diff(c)) / 2.0)
