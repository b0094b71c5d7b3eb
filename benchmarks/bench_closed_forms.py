"""Benchmark: closed forms against the loops they replaced (issue 14, item 7).

Run on demand: ``python benchmarks/bench_closed_forms.py``.  Prints the best of several
repeats of each old and new implementation, their ratio and how far their results differ:

* the Wiebe cycle pressure: the integrating factor V^gamma and one vectorised quadrature
  (``crank.pressure.wiebe_pressure``) against LSODA with a scalar right-hand side;
* the inverse slider-crank: the closed form (``crank.kinematics.crank_angle_at``) against a
  ``brentq`` per port height, and ``crank.pressure.pv_to_angle`` against interpolation on a
  fine grid of every branch;
* ``LiftLaw.extremes``: the roots of the next derivative refined all at once against three
  calls of ``numerics.extremum`` (grid and bounded Brent per call), both on the same (compiled)
  law evaluation, so the ratio is the search's alone.

The old implementations live only here, as the baselines, copied from the commit before
each change.
"""

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from valvetrain import twostroke
from valvetrain.crank import kinematics, pressure
from valvetrain.laws import KurzLaw, PolydyneLaw, TangentLaw
from valvetrain.laws.base import Extremes
from valvetrain.numerics import extremum

from timing import best_time

GEOM = dict(bore=0.080, radius=0.0385, lam=0.285)


def old_wiebe_pressure(phi, cycle, bore, radius, lam, strokes, k=0.0):
    """The Wiebe cycle by LSODA with a scalar right-hand side (before the closed form)."""
    phi = np.asarray(phi, dtype=float)
    firing = np.pi * (strokes - 2)
    area = np.pi * bore**2 / 4.0

    def volume(t):
        return pressure.cylinder_volume(t, bore, radius, lam, cycle.compression_ratio, k)

    def dvolume(t):
        return area * kinematics.velocity(t, radius, lam, 1.0, k)

    def burn_rate(t):
        z = (t - firing - cycle.start) / cycle.duration
        if z <= 0.0:
            return 0.0
        return cycle.a * (cycle.m + 1) / cycle.duration * z**cycle.m * np.exp(-cycle.a * z ** (cycle.m + 1))

    def rhs(t, p):
        v = volume(t)
        return [(cycle.gamma - 1.0) / v * cycle.heat_input * burn_rate(t) - cycle.gamma * p[0] / v * dvolume(t)]

    t0, t1 = firing - np.pi, firing + np.pi
    sol = solve_ivp(rhs, (t0, t1), [cycle.intake_pressure], method="LSODA", dense_output=True, rtol=1e-9, atol=1.0,
                    max_step=np.radians(0.5))
    length = pressure.cycle_length(strokes)
    rel = np.mod(phi - t0, length)
    p = np.where(rel <= 2 * np.pi, sol.sol(t0 + np.clip(rel, 0.0, 2 * np.pi))[0], cycle.intake_pressure)
    if strokes == 4:
        cyc = np.mod(phi, length)
        p = np.where((cyc > 3 * np.pi) & (cyc < 4 * np.pi), cycle.exhaust_pressure, p)
        p = np.where(cyc < np.pi, cycle.intake_pressure, p)
    return p


def old_port_angle(sigma, lam):
    """Exact port opening angle from BDC by brentq (before crank_angle_at)."""
    return np.pi - brentq(lambda a: kinematics.displacement(a, 0.5, lam) - (1.0 - sigma), 0.0, np.pi, xtol=1e-14)


def old_pv_angles(volume, bore, radius, lam, compression_ratio, strokes, k=0.0):
    """The crank angles of a p-V diagram by interpolation on 4001 angles per branch (before the closed form)."""
    dv = np.sign(np.diff(volume))
    dv[dv == 0] = 1.0
    branches = np.split(np.arange(volume.size), np.flatnonzero(dv[1:] != dv[:-1]) + 1)
    phi_fine = np.linspace(0.0, np.pi, 4001)
    area = np.pi * bore**2 / 4.0
    clearance = area * 2.0 * radius / (compression_ratio - 1.0)
    out = []
    for n, rows in enumerate(branches):
        ph = n * np.pi + phi_fine
        v = clearance + area * kinematics.displacement(ph, radius, lam, k)
        order = np.argsort(v)
        out.append(np.interp(volume[rows], v[order], ph[order]))
    return np.concatenate(out)


def old_extremes(law, omega):
    """LiftLaw.extremes by three calls of numerics.extremum (before the vectorised root search)."""
    edges = law.breakpoints
    opening = edges[edges <= 0.0]
    xv, v = extremum(lambda t: law.derivatives(t)[1], opening, "max")
    xa, amax = extremum(lambda t: law.derivatives(t)[2], edges, "max")
    xn, amin = extremum(lambda t: law.derivatives(t)[2], edges, "min")
    return Extremes(omega * v, omega**2 * amax, omega**2 * amin, xv, xa, xn)


def report(name, old, new, difference, unit):
    print(f"{name:44s} old {old * 1e3:9.3f} ms  new {new * 1e3:8.3f} ms  old/new {old / new:7.1f}  "
          f"max difference {difference:.1e} {unit}")


def bench_wiebe():
    cycle = pressure.WiebeCycle(10.0, 950.0)
    for step in (1.0, 0.25):
        phi = np.radians(np.arange(0.0, 720.0, step))
        args = (phi, cycle, GEOM["bore"], GEOM["radius"], GEOM["lam"], 4)
        old, new = old_wiebe_pressure(*args), pressure.wiebe_pressure(*args)
        report(f"Wiebe cycle, {phi.size} angles", best_time(lambda a=args: old_wiebe_pressure(*a)),
               best_time(lambda a=args: pressure.wiebe_pressure(*a)), np.abs(new / old - 1).max(), "relative")


def bench_inverse_slider_crank():
    sigma = np.linspace(0.05, 0.95, 1000)
    lam = GEOM["lam"]
    old = np.array([old_port_angle(s, lam) for s in sigma])
    new = np.pi - kinematics.crank_angle_at(1.0 - sigma, 0.5, lam)
    report("exact port angle, 1000 heights (vectorised)", best_time(lambda: [old_port_angle(s, lam) for s in sigma]),
           best_time(lambda: np.pi - kinematics.crank_angle_at(1.0 - sigma, 0.5, lam)), np.abs(new - old).max(), "rad")
    report("exact port angle, one height (port_angle)", best_time(lambda: old_port_angle(0.27, lam), 50),
           best_time(lambda: twostroke.port_angle(0.27, lam), 50),
           abs(old_port_angle(0.27, lam) - twostroke.port_angle(0.27, lam)), "rad")
    phi = np.radians(np.arange(0.0, 720.0, 0.5))
    args = (GEOM["bore"], GEOM["radius"], lam, 10.0, 4)
    volume = pressure.cylinder_volume(phi, GEOM["bore"], GEOM["radius"], lam, 10.0)
    p = np.ones_like(phi)
    old, new = old_pv_angles(volume, *args), pressure.pv_to_angle(volume, p, *args)[0]
    report(f"p-V diagram to crank angle, {phi.size} rows", best_time(lambda: old_pv_angles(volume, *args)),
           best_time(lambda: pressure.pv_to_angle(volume, p, *args)), np.abs(new - old).max(), "rad")
    print(f"{'':44s} error against the angles written: old {np.abs(old - phi).max():.1e} rad, "
          f"new {np.abs(new - phi).max():.1e} rad")


def bench_extremes():
    omega = np.pi * 7000 / 60
    laws = {
        "kurz (seed 000 appendix)": KurzLaw(6.25e-3, 0.25e-3, 0.02e-3 * 180 / np.pi, *np.deg2rad([27, 6, 38])),
        "polydyne p=8": PolydyneLaw(6.25e-3, np.deg2rad(71.0), 8),
        "polydyne p=8 with ramp": PolydyneLaw(6.0e-3, np.deg2rad(71.0), 8, ramp_height=0.25e-3,
                                              ramp_velocity=0.02e-3 * 180 / np.pi),
        "tangent (acceleration jump)": TangentLaw(20e-3, 10e-3, np.radians(50), 10e-3),
    }
    keys = ("max_velocity", "max_acceleration", "min_acceleration")
    for name, law in laws.items():
        old, new = old_extremes(law, omega), law.extremes(omega)
        difference = max(abs(getattr(new, k) / getattr(old, k) - 1) for k in keys)
        report(f"extremes, {name}", best_time(lambda law=law: old_extremes(law, omega)),
               best_time(lambda law=law: law.extremes(omega)), difference, "relative")


def main():
    bench_wiebe()
    bench_inverse_slider_crank()
    bench_extremes()


if __name__ == "__main__":
    main()
