"""Timing shared by the benchmarks: the best of several runs of a call (``timeit.repeat``, one call per run)."""

import timeit


def best_time(fn, repeats=7):
    """The shortest wall time [s] of ``repeats`` calls of ``fn()``."""
    return min(timeit.repeat(fn, number=1, repeat=repeats))
