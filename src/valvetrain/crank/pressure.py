"""Cylinder pressure over the cycle: indicator-diagram files (p-phi or p-V), a Wiebe cycle model,
interpolation onto the calculation grid and the indicated work.

Cycle angle convention (Power units manual (n.d.)): a four-stroke cycle runs 0...720 deg crank with
phi = 0 the TDC that starts the intake stroke and the firing TDC at 360 deg; a two-stroke
cycle runs 0...360 deg with the firing TDC at 0 (= 360).  Pressures are absolute [Pa].
"""

from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from ..locale import NoteText
from ..numerics import cumulative_integral
from .kinematics import brix_crank_angle, crank_angle_at, displacement, piston_stroke

MIN_PRESSURE_MPA = 0.001
"""Least absolute pressure of an indicator diagram [MPa] (1 kPa, far below any cylinder's)."""


class PressureFileError(InputError):
    """An indicator-diagram file that cannot be used; the message names the file and the line."""


def cycle_length(strokes) -> float:
    """Length of the cycle in crank angle [rad]: 4 pi for a four-stroke, 2 pi for a two-stroke (C = 180 tau)."""
    return np.pi * strokes


def cylinder_volume(phi, bore, radius, lam, compression_ratio, k=0.0, exact=True) -> float | np.ndarray:
    """Cylinder volume V = V_c + F_p s(phi) with V_c = V_h / (epsilon - 1) [m^3]."""
    area = np.pi * bore**2 / 4.0
    clearance = area * 2.0 * radius / (compression_ratio - 1.0)
    return clearance + area * displacement(phi, radius, lam, k, exact)


MAX_GAP_DEG = 60.0
"""Longest stretch of the cycle [crank deg] an indicator diagram may leave without a point: linear
interpolation across a longer gap (a file of only the closed cycle, or of 0...360 deg of a four-stroke)
would invent the pressure of whole strokes."""

MIN_PEAK_RATIO = 2.0
"""Least ratio of the peak to the lowest pressure of an indicator diagram: compression alone raises the
pressure of any engine more than this (p_c / p_a = epsilon^n, about 15 at epsilon = 7, n = 1.35)."""

FIRING_WINDOW_DEG = 90.0
"""The peak pressure of a fired cycle lies within this many crank degrees of the firing TDC."""


def check_cycle(angle, pressure, strokes, source="indicator diagram") -> None:
    """Refuse a p(phi) diagram that does not describe one whole fired cycle in the cycle-angle convention.

    Parameters
    ----------
    angle : ndarray
        Increasing cycle angles [rad], 0 = the TDC that starts the intake stroke (four-stroke).
    pressure : ndarray
        Absolute pressures [Pa].
    strokes : {2, 4}
    source : str
        Name of the diagram in the messages.

    Raises
    ------
    PressureFileError
        When a gap between points (periodically, across the end of the cycle) exceeds
        :data:`MAX_GAP_DEG`, or the peak pressure lies more than :data:`FIRING_WINDOW_DEG` from
        the firing TDC (360 deg of a four-stroke, 0 = 360 deg of a two-stroke): a file counted
        from the firing TDC gives a negative indicated work.
    """
    if pressure.max() < MIN_PEAK_RATIO * pressure.min():
        raise PressureFileError(NoteText.of("pressure.flat", where=source, low=pressure.min() / 1e6,
                                            high=pressure.max() / 1e6, ratio=MIN_PEAK_RATIO))
    length = cycle_length(strokes)
    ends = np.concatenate([angle, [angle[0] + length]])
    gaps = np.diff(ends)
    k = int(np.argmax(gaps))
    if gaps[k] > np.radians(MAX_GAP_DEG):
        raise PressureFileError(NoteText.of(
            "pressure.gap", where=source, start=np.degrees(ends[k]), end=np.degrees(ends[k + 1]) % (180 * strokes),
            gap=np.degrees(gaps[k]), most=MAX_GAP_DEG, cycle=180 * strokes))
    firing = np.pi * (strokes - 2)
    peak = float(angle[int(np.argmax(pressure))])
    off = abs((peak - firing + length / 2.0) % length - length / 2.0)
    if off > np.radians(FIRING_WINDOW_DEG):
        raise PressureFileError(NoteText.of(
            "pressure.peak", where=source, peak=np.degrees(peak),
            firing=np.degrees(firing) % 360 if strokes == 2 else 360, window=FIRING_WINDOW_DEG))


def on_grid(angle, pressure, grid, strokes) -> float | np.ndarray:
    """Periodic linear interpolation of p(phi) onto the calculation grid [Pa]."""
    return np.interp(np.asarray(grid), angle, pressure, period=cycle_length(strokes))


def pv_to_angle(volume, pressure, bore, radius, lam, compression_ratio, strokes, k=0.0, method="exact",
                source="p-V table") -> tuple[np.ndarray, np.ndarray]:
    """Convert a p-V diagram to p(phi) through the piston kinematics.

    The rows follow the cycle from its first TDC; the volume rises and falls once per
    stroke, so the table splits into ``strokes`` monotone branches, the n-th belonging to
    the crank angles from one dead centre to the next (about [n pi, (n + 1) pi]).  Each volume
    is mapped to the crank angle of its branch where the cylinder has that volume, in closed
    form: exactly (``method="exact"``, :func:`~.kinematics.crank_angle_at`), which replaces
    Brix's graphical construction, or with Brix's construction itself (``method="brix"``,
    Power units manual (n.d.), eq. 2.1, :func:`~.kinematics.brix_crank_angle`).

    Returns
    -------
    (ndarray, ndarray)
        Crank angles [rad] (increasing) and pressures [Pa].

    Raises
    ------
    PressureFileError
        When the volumes do not form one monotone branch per stroke, or leave the range of
        the cylinder volume.
    """
    volume = np.asarray(volume, dtype=float)
    dv = np.sign(np.diff(volume))
    dv[dv == 0] = 1.0
    turns = np.flatnonzero(dv[1:] != dv[:-1]) + 1
    branches = np.split(np.arange(volume.size), turns)
    if len(branches) != strokes:
        raise PressureFileError(NoteText.of("pressure.branches", where=source, turns=len(turns), strokes=strokes))
    area = np.pi * bore**2 / 4.0
    clearance = area * 2.0 * radius / (compression_ratio - 1.0)
    full = 2.0 * radius if method == "brix" else piston_stroke(radius, lam, k)
    lo, hi = clearance, clearance + area * full
    out_phi, out_p = [], []
    for n, rows in enumerate(branches):
        bad = (volume[rows] < lo * (1 - 1e-3)) | (volume[rows] > hi * (1 + 1e-3))
        if bad.any():
            i = rows[np.flatnonzero(bad)[0]]
            raise PressureFileError(NoteText.of("pressure.volume", where=source, row=i + 1, volume=volume[i] * 1e6,
                                                low=lo * 1e6, high=hi * 1e6, stroke=n + 1))
        travel = np.clip((volume[rows] - clearance) / area, 0.0, full)
        upstroke = n % 2 == 1
        angle = (brix_crank_angle(travel, radius, lam, upstroke) if method == "brix"
                 else crank_angle_at(travel, radius, lam, k, upstroke=upstroke))
        out_phi.append(2.0 * np.pi * (n // 2) + angle)
        out_p.append(pressure[rows])
    phi, p = np.concatenate(out_phi), np.concatenate(out_p)
    keep = np.concatenate([[True], np.diff(phi) > 0])
    return phi[keep], p[keep]


BLOWDOWN_DEG = 60.0
"""Crank angle over which the cylinder pressure falls from its value at the exhaust opening to the exhaust
pressure [deg]: the blowdown runs from the exhaust opening to somewhat past BDC (Heywood (1988), section 6.5); the
model's figure, about twice the exhaust lead of a four-stroke."""

OVERLAP_DEG = 20.0
"""Crank angle over which the pressure changes from the exhaust to the intake pressure about the gas-exchange TDC
when the valves' timing is not known [deg]."""


def blend(phi, start, length) -> np.ndarray:
    """Weight rising smoothly from 0 at ``start`` to 1 at ``start + length`` (half a cosine wave; 0 before, 1
    after), continuous with its first derivative; a step where ``length`` is 0."""
    if length <= 0.0:
        return np.where(np.asarray(phi) >= start, 1.0, 0.0)
    z = np.clip((np.asarray(phi, dtype=float) - start) / length, 0.0, 1.0)
    return 0.5 - 0.5 * np.cos(np.pi * z)


@dataclass(frozen=True)
class WiebeCycle:
    """Parameters of the single-zone Wiebe cycle model (SI; angles relative to the firing TDC, rad).

    The built-in example's indicator diagram: gas exchange at constant pressures (intake
    at ``intake_pressure``, exhaust at ``exhaust_pressure``), a closed cycle from the intake
    valve's closing to the exhaust valve's opening with a constant ratio of specific heats, no
    wall heat loss and a Wiebe heat release
    :math:`x = 1 - \\exp(-a\\,((\\varphi-\\varphi_s)/\\Delta\\varphi)^{m+1})`, a blowdown from the
    exhaust opening to the exhaust pressure over ``blowdown`` and, for a four-stroke, the change from
    the exhaust to the intake pressure over the valve overlap (:func:`wiebe_pressure`).  The valve
    angles default to the dead centres.
    (Wiebe (1970); Heywood (1988), sections 9.2 (Wiebe function) and 6.5
    (exhaust blowdown); the standard single-zone model, not in the design sources of this package.)
    """

    compression_ratio: float
    heat_input: float            # Q per cycle [J]
    intake_pressure: float = 0.09e6
    exhaust_pressure: float = 0.11e6
    start: float = np.radians(-15.0)
    duration: float = np.radians(60.0)
    a: float = 6.908
    m: float = 2.0
    gamma: float = 1.33
    intake_closes: float = -np.pi            # start of compression, from the firing TDC [rad]
    exhaust_opens: float = np.pi             # start of the blowdown, from the firing TDC [rad]
    blowdown: float = np.radians(BLOWDOWN_DEG)
    intake_opens: float = np.radians(-OVERLAP_DEG / 2.0)   # from the gas-exchange TDC [rad] (four-stroke)
    exhaust_closes: float = np.radians(OVERLAP_DEG / 2.0)  # from the gas-exchange TDC [rad] (four-stroke)


def wiebe_fraction(phi, cycle, firing) -> float | np.ndarray:
    """Wiebe mass fraction burnt x at cycle angles ``phi`` for the firing TDC at ``firing`` [rad].

    Notes
    -----
    .. math:: x = 1 - e^{-a z^{m+1}},\\quad z = \\frac{\\varphi - \\varphi_s}{\\Delta\\varphi} > 0,

    zero before the start of combustion :math:`\\varphi_s` (``firing + cycle.start``).

    References
    ----------
    Wiebe (1970) (see :class:`WiebeCycle`).
    """
    z = np.maximum((np.asarray(phi, dtype=float) - firing - cycle.start) / cycle.duration, 0.0)
    return -np.expm1(-cycle.a * z ** (cycle.m + 1.0))


def wiebe_rate(phi, cycle, firing) -> np.ndarray:
    """Wiebe burn rate dx/dphi [1/rad] at cycle angles ``phi`` for the firing TDC at ``firing`` [rad].

    Notes
    -----
    .. math:: \\frac{dx}{d\\varphi} = \\frac{a(m+1)}{\\Delta\\varphi}\\,z^m e^{-a z^{m+1}}

    for z > 0 (see :func:`wiebe_fraction`), zero before the start of combustion; integrable but
    unbounded at the start for -1 < m < 0.

    References
    ----------
    Wiebe (1970) (see :class:`WiebeCycle`).
    """
    z = (np.asarray(phi, dtype=float) - firing - cycle.start) / cycle.duration
    burning = z > 0.0
    zb = np.where(burning, z, 1.0)
    rate = cycle.a * (cycle.m + 1.0) / cycle.duration * zb**cycle.m * np.exp(-cycle.a * zb ** (cycle.m + 1.0))
    return np.where(burning, rate, 0.0)


WIEBE_PIECE = np.radians(5.0)
"""Longest piece of the closed cycle [rad] in the quadrature of the heat-release integral: a 16-point
Gauss-Legendre rule is exact to round-off on it whatever grid the pressure is asked on."""

WIEBE_GRADING = 50
"""Pieces of the quadrature graded towards the start of combustion, at Delta phi / 2^j, j < 50: the
integrand behaves like z^(m+1) there, smooth only for an integer m."""


def wiebe_pressure(phi, cycle, bore, radius, lam, strokes, k=0.0) -> np.ndarray:
    """Cylinder pressure of the Wiebe cycle model at cycle angles ``phi`` [Pa].

    Notes
    -----
    Over the closed cycle (from BDC before the firing TDC to BDC after it for a two-stroke; for a
    four-stroke from the intake valve's closing to the end of the blowdown)

    .. math:: \\frac{dp}{d\\varphi} = \\frac{\\gamma - 1}{V}\\,Q\\frac{dx}{d\\varphi}
              - \\gamma\\frac{p}{V}\\frac{dV}{d\\varphi},

    which the integrating factor :math:`V^\\gamma` makes exact,
    :math:`d(pV^\\gamma)/d\\varphi = (\\gamma - 1)\\,Q\\,V^{\\gamma-1}\\,dx/d\\varphi`; from the intake
    pressure p_0 at BDC (angle :math:`\\varphi_0`, volume V_0), with :math:`V_s = V(\\varphi_s)` at the
    start of combustion taken out of the integral in closed form,

    .. math:: p\\,V^\\gamma = p_0V_0^\\gamma + (\\gamma - 1)\\,Q\\left[V_s^{\\gamma-1}\\big(x(\\varphi) -
              x(\\varphi_0)\\big) + \\int_{\\varphi_0}^{\\varphi}\\big(V^{\\gamma-1} - V_s^{\\gamma-1}\\big)
              \\frac{dx}{d\\varphi'}\\,d\\varphi'\\right].

    The remaining integrand is bounded (it vanishes like :math:`z^{m+1}` at the start) and is
    integrated by :func:`~valvetrain.numerics.cumulative_integral` in pieces of at most
    :data:`WIEBE_PIECE`, cut at the start and the nominal end of combustion and graded towards the
    start (:data:`WIEBE_GRADING`); V is the exact cylinder volume (:func:`cylinder_volume`).

    A four-stroke's blowdown blends this pressure into the exhaust pressure from the exhaust opening
    over ``cycle.blowdown`` (:func:`blend`, half a cosine wave); the exhaust pressure holds to the valve
    overlap, across which it blends into the intake pressure, which holds to the intake valve's closing:
    the pressure is continuous over the whole cycle, with a continuous slope at the ends of the blends.

    References
    ----------
    Wiebe's heat release, see :class:`WiebeCycle`; the single-zone energy equation with a
    constant ratio of specific heats and no wall heat loss, integrated in closed form here.
    """
    phi = np.asarray(phi, dtype=float)
    firing = np.pi * (strokes - 2)          # 2 pi for a four-stroke, 0 (= 2 pi) for a two-stroke
    exponent = cycle.gamma - 1.0
    four = strokes == 4

    def volume(t):
        return cylinder_volume(t, bore, radius, lam, cycle.compression_ratio, k)

    if four:
        t0, opens = firing + cycle.intake_closes, firing + cycle.exhaust_opens
        t1 = opens + cycle.blowdown
    else:
        t0, t1 = firing - np.pi, firing + np.pi
    burn = firing + cycle.start
    at_start = volume(burn) ** exponent

    def excess(t):
        return (volume(t) ** exponent - at_start) * wiebe_rate(t, cycle, firing)

    length = cycle_length(strokes)
    rel = np.mod(phi - t0, length)                  # angle since the start of the closed cycle
    closed = rel <= t1 - t0
    t = t0 + rel[closed]
    grid = np.unique(np.concatenate([[t0, t1], t]))
    pieces = np.linspace(t0, t1, int(np.ceil((t1 - t0) / WIEBE_PIECE)) + 1)
    graded = burn + cycle.duration * 2.0 ** -np.arange(WIEBE_GRADING)
    cuts = np.concatenate([pieces, [burn], graded])
    released = (at_start * (wiebe_fraction(grid, cycle, firing) - wiebe_fraction(t0, cycle, firing))
                + cumulative_integral(excess, grid, cuts[(cuts >= t0) & (cuts <= t1)]))
    pv = cycle.intake_pressure * volume(t0) ** cycle.gamma + exponent * cycle.heat_input * released
    p = np.full(phi.shape, cycle.intake_pressure)
    p[closed] = pv[np.searchsorted(grid, t)] / volume(t) ** cycle.gamma
    if four:
        # blowdown: from the closed cycle's pressure at the exhaust opening to the exhaust pressure
        w = blend(t, opens, cycle.blowdown)
        p[closed] = (1.0 - w) * p[closed] + w * cycle.exhaust_pressure
        # exhaust stroke, then the change to the intake pressure over the overlap about the gas-exchange TDC
        cyc = np.mod(phi - t1, length) + t1          # cycle angle from the end of the blowdown on
        change = cycle.exhaust_closes - cycle.intake_opens
        w = blend(cyc, length + cycle.intake_opens, change)
        exchange = ~closed
        p[exchange] = ((1.0 - w) * cycle.exhaust_pressure + w * cycle.intake_pressure)[exchange]
    return p


def check_timing(cycle) -> None:
    """Refuse valve angles the four-stroke model cannot place: the closed cycle must start before the firing TDC
    and the blowdown end before the intake valve opens, the overlap after it.

    Raises
    ------
    ValueError
        Naming the crank angles (from the gas-exchange TDC) and what is allowed.
    """
    ivc, evo = np.degrees(cycle.intake_closes) + 360.0, np.degrees(cycle.exhaust_opens) + 360.0
    end = evo + np.degrees(cycle.blowdown)
    ivo, evc = np.degrees(cycle.intake_opens) + 720.0, np.degrees(cycle.exhaust_closes) + 720.0
    if not 0.0 < ivc < 360.0 + np.degrees(cycle.start):
        raise InputError(NoteText.of("pressure.wiebe_ivc", closes=ivc, most=360.0 + np.degrees(cycle.start)))
    if not (360.0 < evo and end <= ivo and evc - 720.0 < ivc and evc >= ivo):
        raise InputError(NoteText.of("pressure.wiebe_evo", opens=evo, end=end, start=ivo - 720.0, closes=evc - 720.0))


def indicated_work(phi, pressure, volume) -> float:
    """Indicated work of one cycle, W_i = closed integral of p dV [J] (trapezoidal rule over the closed cycle)."""
    v = np.append(volume, volume[0])
    p = np.append(pressure, pressure[0])
    return float(np.sum(0.5 * (p[1:] + p[:-1]) * np.diff(v)))
