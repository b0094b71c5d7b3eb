"""Total torque of a multi-cylinder engine for any layout and firing order (Power units manual (n.d.), section 2.5;
generalised here to any layout and firing order).

Angles in rad.  ``firing[c]`` is the shaft angle at which cylinder c fires, measured
after cylinder 1; the cycle angle of cylinder c at engine angle psi (the cycle angle of
cylinder 1) is (psi - firing[c]) mod C.
"""

import numpy as np


def firing_interval(strokes, cylinders) -> float:
    """Even firing interval theta = 180 tau / i [rad] (Power units manual (n.d.), eq. 2.22).

    >>> round(float(np.degrees(firing_interval(4, 4))), 9)
    180.0
    """
    return np.pi * strokes / cylinders


def even_firing(order, strokes) -> np.ndarray:
    """Firing angles of an even-firing engine: the m-th cylinder of ``order`` fires (m - 1) theta after the first.

    Parameters
    ----------
    order : sequence of int
        Firing order, cylinder numbers from 1 (e.g. ``[1, 3, 4, 2]``).
    strokes : {2, 4}

    Returns
    -------
    ndarray
        ``firing[c - 1]`` for cylinders 1...i [rad].
    """
    n = len(order)
    theta = firing_interval(strokes, n)
    out = np.empty(n)
    for m, c in enumerate(order):
        out[c - 1] = m * theta
    return out - out[order[0] - 1]


def layout_firing(order, throws, banks, strokes) -> np.ndarray:
    """Firing angles from the crank-throw and cylinder-axis angles of any layout (inline, V, W, boxer).

    Parameters
    ----------
    order : sequence of int
        Firing order (cylinder numbers from 1).
    throws : sequence of float
        Crank-throw angle gamma_c of each cylinder relative to throw 1, in the direction of rotation [rad].
    banks : sequence of float
        Cylinder-axis angle alpha_c of each cylinder relative to cylinder 1 [rad].
    strokes : {2, 4}

    Notes
    -----
    Cylinder c is at TDC when the shaft angle is alpha_c - gamma_c (mod 2 pi).  For a
    four-stroke the firing TDC is that angle or that angle + 2 pi, chosen so that the
    cylinders fire in the given order with increasing angle within the cycle.

    References
    ----------
    Power units manual (n.d.), section 2.5, generalised to any layout.

    Examples
    --------
    A 90 deg V-twin on one crank pin fires at 0 and 90 deg (intervals 90/630 deg):

    >>> [round(float(np.degrees(a)), 6) for a in layout_firing([1, 2], [0, 0], [0, np.pi / 2], 4)]
    [0.0, 90.0]
    """
    throws, banks = np.asarray(throws, dtype=float), np.asarray(banks, dtype=float)
    tdc = np.mod(banks - throws, 2 * np.pi)
    cycle = np.pi * strokes
    out = np.empty(len(order))
    prev = None
    for c in order:
        candidates = np.mod(tdc[c - 1] - tdc[order[0] - 1] + 2 * np.pi * np.arange(strokes // 2), cycle)
        if prev is None:
            angle = 0.0
        else:
            ahead = np.mod(candidates - prev, cycle)
            ahead[ahead == 0] = cycle
            angle = candidates[int(np.argmin(ahead))]
        out[c - 1] = angle
        prev = angle
    return out


def engine_torque(psi, cylinder_torque, firing, strokes) -> tuple[np.ndarray, np.ndarray]:
    """Torque of every cylinder and their sum at engine angles psi.

    Parameters
    ----------
    psi : ndarray
        Engine angle = cycle angle of cylinder 1 [rad].
    cylinder_torque : callable or (ndarray, ndarray)
        ``M(phi)`` of one cylinder over its cycle, or a table ``(phi, M)`` interpolated
        periodically (linear).
    firing : ndarray
        Firing angles after cylinder 1 [rad].
    strokes : {2, 4}

    Returns
    -------
    (ndarray, ndarray)
        Per-cylinder torques, shape (i, n), and the total, shape (n,) [N m].

    Notes
    -----
    :math:`M(\\psi) = \\sum_c M_{cyl}((\\psi - f_c) \\bmod C)`.

    References
    ----------
    Power units manual (n.d.), section 2 (Table 2.8).
    """
    cycle = np.pi * strokes
    psi = np.asarray(psi, dtype=float)
    angles = np.mod(psi[None, :] - np.asarray(firing)[:, None], cycle)
    if callable(cylinder_torque):
        each = cylinder_torque(angles)
    else:
        phi, m = cylinder_torque
        each = np.interp(angles, phi, m, period=cycle)
    return each, each.sum(axis=0)


def torque_statistics(total) -> dict[str, float | None]:
    """Mean, max, min, the mean's share of the largest |torque| M_mean / max(|M_max|, |M_min|) (0 for a torque that
    is 0 throughout) and the non-uniformity mu = (M_max - M_min) / M_mean of samples over one period.

    The samples must cover exactly one period, uniformly, without a duplicated end point.  The
    non-uniformity is defined for an engine that delivers torque: it is None where the mean torque is
    not positive (a motored cycle) or vanishes against the largest torque (a share up to 1e-9).

    References
    ----------
    Kolchin and Demidov (1980) (coefficient of torque non-uniformity).
    """
    mean = float(np.mean(total))
    mx, mn = float(np.max(total)), float(np.min(total))
    peak = max(abs(mx), abs(mn))
    share = mean / peak if peak > 0.0 else 0.0
    return {"mean": mean, "max": mx, "min": mn, "mean_share": share,
            "nonuniformity": (mx - mn) / mean if share > 1e-9 else None}


def is_even(firing, strokes, tol=1e-9) -> bool:
    """True when the firing angles are equally spaced over the cycle."""
    f = np.sort(np.mod(firing, np.pi * strokes))
    gaps = np.diff(np.append(f, f[0] + np.pi * strokes))
    return bool(np.allclose(gaps, gaps[0], atol=tol))
