"""Benchmark: evaluating a lift law with its derivatives on 10^6 camshaft angles.

Run on demand: ``python benchmarks/bench_laws.py``.  Prints the best of several repeats
per law and the throughput of the compiled kernels (``SymmetricLaw._mirrored`` of the Kurz
and polynomial laws) against the numpy evaluation they replaced (kept here only, as the
baseline: masks per segment, the rise scattered into the result), the largest difference
between the two relative to each row's largest value, and a plain numpy evaluation of one
sine on the same array (the cheapest vectorised call a law could be).  The first call of
each kernel, which compiles it or loads it from numba's cache, is not timed.  The polynomial
laws differ by up to some 1e-14 of a row's scale: the round-off of their alternating sums
(both implementations are that far from an 80-bit evaluation), not a change of formula.
"""


import numpy as np

from valvetrain.laws import KurzLaw, PolydyneLaw
from valvetrain.laws.base import segment_index
from valvetrain.laws.polydyne import _falling

from timing import best_time

N = 1_000_000


def old_ramp(ramp, phi):
    """The numpy ramps (before the compiled ramp_at)."""
    if ramp.kind == "cosine":
        k = np.pi / (2.0 * ramp.length)
        s, c = np.sin(k * phi), np.cos(k * phi)
        return np.stack([ramp.height * (1.0 - c), ramp.height * k * s, ramp.height * k**2 * c,
                         -ramp.height * k**3 * s])
    if ramp.kind == "constant_velocity":
        z = np.zeros_like(phi)
        return np.stack([ramp.end_velocity * phi, z + ramp.end_velocity, z, z])
    ta = ramp.fraction * ramp.length
    acc = ramp.end_velocity / ta
    first = phi < ta
    h = np.where(first, 0.5 * acc * phi**2, ramp.end_velocity * phi - ramp.end_velocity * ta / 2.0)
    return np.stack([h, np.where(first, acc * phi, ramp.end_velocity), np.where(first, acc, 0.0), np.zeros_like(phi)])


def old_kurz_rise(law, phi):
    c, h0 = law.c, law.clearance
    out = np.empty((4, phi.size))
    seg = segment_index(phi, law._edges)
    x = phi - law._edges[seg]
    m = seg == 0
    out[:, m] = old_ramp(law.ramp, x[m])
    m = seg == 1
    k = np.pi / law.phi1
    s, co = np.sin(k * x[m]), np.cos(k * x[m])
    out[:, m] = [h0 + c.c11 * x[m] - c.c12 * s, c.c11 - c.c12 * k * co, c.c12 * k**2 * s, c.c12 * k**3 * co]
    m = seg == 2
    k = np.pi / (2.0 * law.phi2)
    s, co = np.sin(k * x[m]), np.cos(k * x[m])
    h1k = h0 + c.c11 * law.phi1
    out[:, m] = [h1k + c.c21 * x[m] + c.c22 * s, c.c21 + c.c22 * k * co, -c.c22 * k**2 * s, -c.c22 * k**3 * co]
    m = seg == 3
    y = law.phi3 - x[m]
    h2k = h1k + c.c21 * law.phi2 + c.c22
    out[:, m] = [h2k + c.c31 * y**4 + c.c32 * y**2 + c.c33, -(4.0 * c.c31 * y**3 + 2.0 * c.c32 * y),
                 12.0 * c.c31 * y**2 + 2.0 * c.c32, -24.0 * c.c31 * y]
    return out


def old_polynomial_rise(law, phi):
    out = np.empty((4, phi.size))
    ramp = phi < law.ramp_angle
    if law.ramp is not None:
        out[:, ramp] = old_ramp(law.ramp, phi[ramp])
    x = (law.half_angle - phi[~ramp]) / law.phi_p0
    quad = law._k == 2.0
    c2 = float(law._a[quad].sum())
    a, k = law._a[~quad, None], law._k[~quad, None]
    base = x[None, :] ** (k - 3.0)
    x1 = x[None, :]
    series = [(a * base * x1**3).sum(0) + c2 * x * x, (a * k * base * x1**2).sum(0) + 2.0 * c2 * x,
              (a * _falling(k, 2) * base * x1).sum(0) + 2.0 * c2, (a * _falling(k, 3) * base).sum(0)]
    nose = law._lift + law.ramp_height
    out[:, ~ramp] = [nose + series[0], -series[1] / law.phi_p0, series[2] / law.phi_p0**2,
                     -series[3] / law.phi_p0**3]
    return out


def old_derivatives(law, rise, theta):
    """SymmetricLaw.derivatives before the kernels: the rise on the angles inside the event, mirrored."""
    flat = theta.ravel()
    out = np.zeros((4, flat.size))
    inside = np.abs(flat) <= law.half_angle
    t = flat[inside]
    r = rise(law, law.half_angle - np.abs(t))
    r[1::2] *= -np.sign(t)
    out[:, inside] = r
    return out.reshape((4,) + theta.shape)


def main():
    theta = np.linspace(-np.pi, np.pi, N)
    laws = {
        "kurz (seed 000 appendix)": (KurzLaw(6.25e-3, 0.25e-3, 0.02e-3 * 180 / np.pi, *np.deg2rad([27, 6, 38])),
                                     old_kurz_rise),
        "polydyne p=8": (PolydyneLaw(6.25e-3, np.deg2rad(71.0), 8), old_polynomial_rise),
        "polydyne p=8 with ramp": (PolydyneLaw(6.0e-3, np.deg2rad(71.0), 8, ramp_height=0.25e-3,
                                               ramp_velocity=0.02e-3 * 180 / np.pi), old_polynomial_rise),
    }
    base = best_time(lambda: np.sin(theta))
    print(f"baseline np.sin on {N:,} angles: {base * 1e3:.1f} ms")
    for name, (law, rise) in laws.items():
        new = law.derivatives(theta)
        old = old_derivatives(law, rise, theta)
        difference = (np.abs(new - old).max(axis=1) / np.abs(old).max(axis=1)).max()
        t_old = best_time(lambda law=law, rise=rise: old_derivatives(law, rise, theta))
        t_new = best_time(lambda law=law: law.derivatives(theta))
        print(f"{name:24s} lift+3 derivatives: old {t_old * 1e3:6.1f} ms ({N / t_old / 1e6:5.1f} M angles/s)  "
              f"new {t_new * 1e3:6.1f} ms ({N / t_new / 1e6:5.1f} M angles/s, {t_new / base:4.1f} x np.sin)  "
              f"old/new {t_old / t_new:4.1f} x  max difference {difference:.1e} of the row's scale, "
              f"{np.mean(new == old):.0%} bitwise")


if __name__ == "__main__":
    main()
