"""Accuracy of the sweep's seating velocity at the default 0.1 cam deg step (issue 20, item 1).

Run on demand: ``python benchmarks/accuracy_dynamics.py [rpm ...]`` (engine rpm; default ten speeds 2000-8750)
with ``SPEC=file.toml`` to choose the specification (default examples/pushrod-dynamics.toml).  For each speed it
prints the seating velocity of the sweep beside scipy's DOP853 (rtol 1e-10, largest step 0.01 cam deg, the y = 0
crossing located by its event finder) on the same one-mass train, run for as many revolutions as the sweep took, and
the largest relative error.  Slow: a minute or more per speed.
"""

import os
import sys

import numpy as np
from scipy.integrate import solve_ivp

from valvetrain.design import sweep_designs
from valvetrain.dynamics.models import one_mass_train
from valvetrain.dynamics.sweep import sweep
from valvetrain.specification.validate import load_spec


def reference(law, train, omega, revolutions):
    """Downward y = 0 crossings of the last revolution: (times [s], states)."""
    k = train.rocker_ratio

    def rhs(t, s):
        d = law.derivatives(np.array([(omega * t) % (2 * np.pi) - np.pi]))[:2, 0] * k
        y, v = s
        gap = d[0] - train.lash - y
        fc = max(0.0, train.stiffness * gap + train.damping * (omega * d[1] - v)) if gap > 0 else 0.0
        fs = max(0.0, -train.seat_stiffness * y - train.seat_damping * v) if y < 0 else 0.0
        return [v, (fc - train.preload - train.spring_rate * y + fs) / train.mass]

    def seat(t, s):
        return s[0]

    seat.direction = -1
    period = 2 * np.pi / omega
    sol = solve_ivp(rhs, (0, revolutions * period), [-train.preload / train.seat_stiffness, 0.0], method="DOP853",
                    rtol=1e-10, atol=1e-14, max_step=period / 36000, events=seat)
    last = sol.t_events[0] >= (revolutions - 1) * period
    return sol.t_events[0][last], sol.y_events[0][last]


def main():
    d = sweep_designs(load_spec(os.environ.get("SPEC", "examples/pushrod-dynamics.toml")))
    design = next(v for v in d.values() if v.dynamics is not None)
    p = design.dynamics.parameters
    train = one_mass_train(p.mass, p.drive_stiffness, p.spring_rate, p.preload, p.rocker_ratio, p.lash,
                           damping_ratio=p.damping_ratio, seat_stiffness=p.seat_stiffness,
                           seat_damping_ratio=p.seat_damping_ratio)
    rpm = np.array([float(a) for a in sys.argv[1:]]) if len(sys.argv) > 1 else np.linspace(2000, 8750, 10)
    cam = rpm * np.pi / 60
    res = sweep(design.law, train, cam, p.revolutions, 0.1)
    worst = 0.0
    for i in range(cam.size):
        r = res.speed(i)
        times, states = reference(design.law, train, cam[i], int(res.revolutions[i]))
        angles = (times * cam[i]) % (2 * np.pi) - np.pi
        exact = states[np.argmin(np.abs(angles - r.seating_angle)), 1]
        err = 100 * (r.seating_velocity / exact - 1)
        worst = max(worst, abs(err))
        print(f"{rpm[i]:7.0f} rpm  revolutions {res.revolutions[i]}  sweep {r.seating_velocity:.5f} m/s  reference "
              f"{exact:.5f} m/s  error {err:+.3f} %", flush=True)
    print(f"largest |error| {worst:.3f} %")


if __name__ == "__main__":
    main()
