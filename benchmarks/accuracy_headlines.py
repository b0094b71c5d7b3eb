"""Accuracy of the dynamics headlines and of their estimated errors (issue 35, items 2 and 3).

Run on demand: ``python benchmarks/accuracy_headlines.py [SPEC ...]`` (default: the built-in example and
examples/pushrod-dynamics.toml).  Two parts:

1. Closed form: the jump speed of a harmonic cam (L = 8 mm over 2 rad, a base circle) on one-mass trains of
   1 kg (K = 5 N/mm, F0 = 50 N: a light, soft train) and 0.2 kg (K = 50 N/mm, F0 = 300 N) with drives of 1e8 and
   1e9 N/m, 200 speeds 0.8-1.2 x the rigid jump speed at 0.1 cam deg: the fixed step's error, the refined value's
   and its estimated error against tests/reference_dynamics.harmonic_jump_speed.
2. A second integrator: for each one-mass valve of each specification, the stage's jump speed, bounce onset, largest
   seating velocity and the rated speed's seating velocity and bounce against scipy's DOP853 on the same equations
   (tests/reference_dynamics.reference_events): the jump speed as the zero of its smallest contact force without the
   clamp at zero and the onset as the bounce height's crossing of 1 um, both by brentq; beside each the sweep's own
   value at the base step (SweepResult.headline, before the refinement) and the estimated error.

Slow: a minute or more per valve (each reference speed 1-3 s).
"""

from pathlib import Path
import sys
import time

import numpy as np
from scipy.optimize import brentq

sys.path.insert(0, str(Path(__file__).parents[1] / "tests"))
from reference_dynamics import harmonic_cam, harmonic_jump_speed, reference_events  # noqa: E402  the tests' reference

from valvetrain.design import sweep_designs
from valvetrain.dynamics.accuracy import refine
from valvetrain.dynamics.models import one_mass_train
from valvetrain.dynamics.sweep import sweep
from valvetrain.specification.reading import example_spec, load_spec

ROOT = Path(__file__).parents[1]
RPM = np.pi / 30
"""Engine rad/s per engine rpm."""


def closed_form():
    """Part 1: the harmonic cam's jump speed against its closed form."""
    law = harmonic_cam(8e-3, 1.0)
    for mass, rate, preload, zeta in ((1.0, 5e3, 50.0, 0.1), (0.2, 50e3, 300.0, 0.2)):
        for stiffness in (1e8, 1e9):
            train = one_mass_train(mass, stiffness, rate, preload, damping_ratio=zeta)
            exact = harmonic_jump_speed(8e-3, 1.0, train)
            rigid = np.sqrt(2 * (preload + rate * 8e-3) / (mass * 8e-3 * np.pi**2))
            t0 = time.perf_counter()
            result = sweep(law, train, np.linspace(0.8, 1.2, 200) * rigid * 1.0013)
            t1 = time.perf_counter()
            refined = refine(law, train, result)
            t2 = time.perf_counter()
            base, jump = result.headline()["jump_speed"], refined.headline["jump_speed"]
            a = refined.accuracy
            print(f"  M {mass:g} kg, K {rate / 1e3:g} N/mm, F0 {preload:g} N, c {stiffness:.0e} N/m: closed form "
                  f"{exact:.5f} rad/s; fixed step {100 * (base / exact - 1):+.4f} %; refined {100 * (jump / exact - 1):+.6f} "
                  f"% (estimated {100 * a.jump_speed / jump:.5f} %: step {100 * a.jump_speed_step / jump:.5f}, grid "
                  f"{100 * a.jump_speed_grid / jump:.6f}; finest {np.degrees(a.step):g} cam deg); sweep {t1 - t0:.2f} s, "
                  f"refinement {t2 - t1:.2f} s", flush=True)


def revolutions(result, speed):
    """The revolutions the sweep's speed nearest ``speed`` took to repeat."""
    return int(result.revolutions[np.argmin(np.abs(result.cam_speeds - speed))])


def second_integrator(path):
    """Part 2: the one-mass valves of the specification ``path`` (None: the built-in example) against DOP853."""
    for name, design in sweep_designs(example_spec() if path is None else load_spec(path)).items():
        d = design.dynamics
        if d is None or d.model != "1dof":
            continue
        p = d.parameters
        train = one_mass_train(p.mass, p.drive_stiffness, p.spring_rate, p.preload, p.rocker_ratio, p.lash,
                               damping_ratio=p.damping_ratio, seat_stiffness=p.seat_stiffness,
                               seat_damping_ratio=p.seat_damping_ratio)
        to_cam = d.sweep.cam_speeds[0] / d.per_speed.speed[0]
        base, a = d.sweep.headline(), d.accuracy
        print(f"  {'built-in example' if path is None else Path(path).name}, {name}:", flush=True)
        if np.isfinite(d.jump_speed):
            cam = d.jump_speed * to_cam
            revs = revolutions(d.sweep, cam)
            exact = brentq(lambda w: reference_events(design.law, train, w, revs)["min_force"], 0.995 * cam,  # noqa: B023
                           1.005 * cam, xtol=1e-6 * cam) / to_cam
            print(f"    jump speed {d.jump_speed / RPM:.2f} rpm, DOP853 {exact / RPM:.2f} rpm: refined "
                  f"{(d.jump_speed - exact) / RPM:+.3f} rpm ({100 * (d.jump_speed / exact - 1):+.4f} %), estimated "
                  f"{a.jump_speed / RPM:.3f} rpm; base step {(base['jump_speed'] / to_cam - exact) / RPM:+.3f} rpm",
                  flush=True)
        if np.isfinite(d.bounce_speed):
            cam = d.bounce_speed * to_cam
            revs = revolutions(d.sweep, cam)
            exact = brentq(lambda w: reference_events(design.law, train, w, revs)["bounce_height"]  # noqa: B023
                           - d.sweep.bounce_tolerance, cam - 40 * RPM * to_cam, cam + 40 * RPM * to_cam,
                           xtol=0.01 * RPM * to_cam) / to_cam
            print(f"    bounce onset {d.bounce_speed / RPM:.2f} rpm, DOP853 {exact / RPM:.2f} rpm: refined "
                  f"{(d.bounce_speed - exact) / RPM:+.2f} rpm, estimated {a.bounce_speed / RPM:.2f} rpm; base step "
                  f"{(base['bounce_onset_speed'] / to_cam - exact) / RPM:+.2f} rpm", flush=True)
        top = d.max_seating_velocity_speed * to_cam
        ref = reference_events(design.law, train, top, revolutions(d.sweep, top))
        print(f"    largest seating velocity {d.max_seating_velocity:.5f} m/s at {d.max_seating_velocity_speed / RPM:.0f} "
              f"rpm, DOP853 {abs(ref['seating_velocity']):.5f}: {100 * (d.max_seating_velocity / abs(ref['seating_velocity']) - 1):+.4f} "
              f"%, estimated {a.max_seating_velocity:.2e} m/s", flush=True)
        rated = d.at_rated_speed
        ref = reference_events(design.law, train, rated.speed * to_cam, max(rated.revolutions, 1))
        print(f"    rated speed: seating velocity {rated.seating_velocity:.5f} m/s, DOP853 {ref['seating_velocity']:.5f} "
              f"(estimated error {a.rated_seating_velocity:.2e}); bounce {rated.bounce * 1e6:.4f} um, DOP853 "
              f"{ref['bounce_height'] * 1e6:.4f} um (estimated error {a.rated_bounce * 1e6:.4f} um)", flush=True)


def main():
    print("1. The jump speed of a harmonic cam against its closed form, 0.1 cam deg, 200 speeds:")
    closed_form()
    print("2. The headlines of the stage against DOP853:")
    for path in sys.argv[1:] or (None, ROOT / "examples" / "pushrod-dynamics.toml"):
        second_integrator(path)


if __name__ == "__main__":
    main()
