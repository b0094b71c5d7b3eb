"""Variance-based (Sobol') sensitivity indices: Saltelli's sampling scheme of the unit hypercube and the first-order
and total indices of an output evaluated at its points, with their bootstrap confidence intervals, by SALib.

Pure functions over numpy arrays; SALib is imported where it is used (it imports pandas, about 2 s).

>>> u = saltelli_points(4, 2, seed=1)
>>> u.shape, bool(np.all((u >= 0.0) & (u < 1.0)))
((16, 2), True)
>>> y = 3.0 * u[:, 0]                       # the output does not depend on the second input
>>> s = sobol_indices(y, 2, seed=1)
>>> s["reason"], s["total"][1] == s["first"][1] == 0.0
(None, True)
"""

from typing import Any

import numpy as np

CONFIDENCE = 0.95
"""Level of the confidence intervals of the indices."""

RESAMPLES = 100
"""Bootstrap resamples of the confidence intervals (SALib's default)."""

MIN_BLOCKS = 2
"""Fewest complete blocks of Saltelli's scheme (base points) that give indices."""


def is_power_of_two(n) -> bool:
    """Whether ``n`` is 2, 4, 8, ... (the base counts of Saltelli's scheme that keep the Sobol' sequence balanced).

    >>> [n for n in range(1, 20) if is_power_of_two(n)]
    [2, 4, 8, 16]
    """
    return n >= 2 and n & (n - 1) == 0


def saltelli_size(n, dimensions) -> int:
    """The points of Saltelli's scheme of ``n`` base points in ``dimensions`` (first-order and total indices):
    ``n (dimensions + 2)``."""
    return n * (dimensions + 2)


def _problem(dimensions):
    return {"num_vars": dimensions, "names": [f"x{j}" for j in range(dimensions)], "bounds": [[0.0, 1.0]] * dimensions}


def saltelli_points(n, dimensions, seed) -> np.ndarray:
    """The points of the unit hypercube at which a model is evaluated for its first-order and total Sobol' indices,
    ``(n (dimensions + 2), dimensions)``, in blocks of ``dimensions + 2`` rows (A, A with column j from B for each j,
    B), the same for the same arguments.

    Parameters
    ----------
    n : int
        Base points, a power of two (:func:`is_power_of_two`).
    dimensions : int
        Inputs.
    seed : int
        Seed of the scrambling of the Sobol' sequence.

    Notes
    -----
    A and B are the two halves of the points of a scrambled Sobol' sequence in 2 x dimensions (scrambled by a linear matrix scramble and a digital shift,
    :class:`scipy.stats.qmc.Sobol`), as SALib's ``sample.sobol`` builds them.

    References
    ----------
    Saltelli (2002); Saltelli et al. (2010), section 2.
    """
    from SALib.sample import sobol

    return sobol.sample(_problem(dimensions), n, calc_second_order=False, seed=seed)


def constant(low, high) -> bool:
    """Whether values from ``low`` to ``high`` are one value to rounding (relative 1e-9, absolute 1e-9 about 0)."""
    return high - low <= 1e-9 * max(1.0, abs(low), abs(high))


def _no_indices(blocks, reason, dimensions) -> dict[str, Any]:
    return {"blocks": blocks, "reason": reason,
            **{name: [None] * dimensions for name in ("first", "first_95", "total", "total_95")}}


def sobol_indices(values, dimensions, seed) -> dict[str, Any]:
    """First-order and total Sobol' indices of an output at the points of :func:`saltelli_points`, with the
    half-widths of their 95 % bootstrap intervals.

    Parameters
    ----------
    values : array_like of float
        The output at each point, in the points' order; NaN where it has no value.
    dimensions : int
        Inputs.
    seed : int
        Seed of the bootstrap resamples.

    Returns
    -------
    dict
        ``blocks`` (the base points whose every evaluation has a value: the indices are of these, the others
        left out), ``reason`` (None, or why there are no indices: ``"constant"``, the output does not vary over
        those blocks' f(A) and f(B) to rounding (:func:`constant`), so there is no variance to share out; ``"too_few_samples"``, fewer than :data:`MIN_BLOCKS` blocks,
        or an index whose 95 % interval lies wholly outside [0, 1], where no index can be: too few blocks to resolve
        it), and per input (lists, None where there are no indices) ``first`` (S_i), ``first_95``, ``total`` (S_Ti),
        ``total_95`` (the half-widths of the intervals).  An estimate may fall a little outside [0, 1] (its
        sampling error, within its interval), as computed.

    Notes
    -----
    S_i = V[E(Y | X_i)] / V(Y), S_Ti = E[V(Y | X_~i)] / V(Y), estimated from the blocks f(A), f(A_B^(i)), f(B) by
    S_i = mean(f(B) (f(A_B^(i)) - f(A))) / V, S_Ti = mean((f(A) - f(A_B^(i)))^2) / (2 V) (Saltelli et al. (2010),
    table 2, estimators b and f), V the variance of f(A) and f(B); intervals from :data:`RESAMPLES` bootstrap
    resamples of the blocks, z_0.975 times their standard deviation (SALib's ``analyze.sobol``).

    References
    ----------
    Sobol' (2001); Saltelli et al. (2010).
    """
    y = np.asarray(values, dtype=float).reshape(-1, dimensions + 2)
    blocks = y[np.all(np.isfinite(y), axis=1)]
    ends = blocks[:, [0, -1]]   # f(A) and f(B), whose variance the indices share out
    reason = ("too_few_samples" if len(blocks) < MIN_BLOCKS else
              "constant" if constant(ends.min(), ends.max()) else None)
    if reason:
        return _no_indices(len(blocks), reason, dimensions)
    from SALib.analyze import sobol

    s = sobol.analyze(_problem(dimensions), blocks.ravel(), calc_second_order=False, num_resamples=RESAMPLES,
                      conf_level=CONFIDENCE, seed=np.random.default_rng(seed))
    if any(np.any((s[key] - s[f"{key}_conf"] > 1.0) | (s[key] + s[f"{key}_conf"] < 0.0)) for key in ("S1", "ST")):
        return _no_indices(len(blocks), "too_few_samples", dimensions)
    return {"blocks": len(blocks), "reason": None,
            **{name: [float(v) for v in s[key]]
               for name, key in (("first", "S1"), ("first_95", "S1_conf"), ("total", "ST"), ("total_95", "ST_conf"))}}
