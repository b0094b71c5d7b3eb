"""Accuracy of the sweep's seating velocity at the default 0.1 cam deg step (issue 20, item 1).

Run on demand: ``python benchmarks/accuracy_dynamics.py [rpm ...]`` (engine rpm; default ten speeds 2000-8750)
with ``SPEC=file.toml`` to choose the specification (default examples/pushrod-dynamics.toml).  For each speed it
prints the seating velocity of the sweep beside scipy's DOP853 (rtol 1e-10, largest step 0.01 cam deg, the y = 0
crossing located by its event finder) on the same one-mass train, run for as many revolutions as the sweep took, and
the largest relative error.  Slow: a minute or more per speed.
"""

import os
from pathlib import Path
import sys

import numpy as np

sys.path.insert(0, str(Path(__file__).parents[1] / "tests"))
from reference_dynamics import seat_crossings  # noqa: E402  the tests' independent reference

from valvetrain.design import sweep_designs
from valvetrain.dynamics.models import one_mass_train
from valvetrain.dynamics.sweep import sweep
from valvetrain.specification.reading import load_spec


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
        revolutions = int(res.revolutions[i])
        times, states = seat_crossings(design.law, train, cam[i], revolutions, 36000)   # 0.01 cam deg largest step
        last = times >= (revolutions - 1) * 2 * np.pi / cam[i]
        times, states = times[last], states[last]
        angles = (times * cam[i]) % (2 * np.pi) - np.pi
        exact = states[np.argmin(np.abs(angles - r.seating_angle)), 1]
        err = 100 * (r.seating_velocity / exact - 1)
        worst = max(worst, abs(err))
        print(f"{rpm[i]:7.0f} rpm  revolutions {res.revolutions[i]}  sweep {r.seating_velocity:.5f} m/s  reference "
              f"{exact:.5f} m/s  error {err:+.3f} %", flush=True)
    print(f"largest |error| {worst:.3f} %")


if __name__ == "__main__":
    main()
