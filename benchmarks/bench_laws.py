"""Benchmark: evaluating a lift law with its derivatives on 10^6 camshaft angles.

Run on demand: ``python benchmarks/bench_laws.py``.  Prints the best of several repeats
per law and the throughput; the baseline for comparison is a plain numpy evaluation of
one sine on the same array (the cheapest vectorised call a law could be).
"""

import time

import numpy as np

from valvetrain.laws import KurzLaw, PolydyneLaw

N = 1_000_000
REPEATS = 7


def best_time(fn):
    times = []
    for _ in range(REPEATS):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


def main():
    theta = np.linspace(-np.pi, np.pi, N)
    laws = {
        "kurz (seed 000 appendix)": KurzLaw(6.25e-3, 0.25e-3, 0.02e-3 * 180 / np.pi, *np.deg2rad([27, 6, 38])),
        "polydyne p=8": PolydyneLaw(6.25e-3, np.deg2rad(71.0), 8),
        "polydyne p=8 with ramp": PolydyneLaw(6.0e-3, np.deg2rad(71.0), 8, ramp_height=0.25e-3,
                                              ramp_velocity=0.02e-3 * 180 / np.pi),
    }
    base = best_time(lambda: np.sin(theta))
    print(f"baseline np.sin on {N:,} angles: {base * 1e3:.1f} ms")
    for name, law in laws.items():
        t = best_time(lambda: law.derivatives(theta))
        print(f"{name:28s} lift+3 derivatives: {t * 1e3:7.1f} ms  ({N / t / 1e6:5.1f} M angles/s, "
              f"{t / base:4.1f} x np.sin)")


if __name__ == "__main__":
    main()
