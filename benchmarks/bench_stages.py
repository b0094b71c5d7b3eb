"""Benchmark: recomputing one valve after a parameter change (law + flow + profile + checks, no files), its spring
search and the whole ``design_valve``.

Run on demand: ``python benchmarks/bench_stages.py``.  The case is the valve the goals of issue 22 were set on, the
textbook appendix's (examples/seed000-appendix-kurz.toml, the built-in example until 7cf5134: one valve, no dynamics,
no design margin of the spring; the built-in example now sweeps its dynamics in ``design_valve``).  Its law is rebuilt
with a changed shape factor each repeat (so no stage result can be reused), then the flow, profile and check stages
run on it; the drive (masses, the spring search) and the strength over the speed range are timed beside them, and
``design_valve`` as the design runs it (all stages, the law's records, the checks).  The spring search of the example's requirement is timed beside its baseline in the same run: the
exhaustive search (every candidate of the grid designed, :func:`valvetrain.springs.evaluate_springs`, as the search
did before its screen), which must choose the same spring.  Best and median of the repeats; the goals of issue 22.

Last, the dynamics stage's per-speed records of the built-in example's intake valve (a sweep of 200 speeds): its
events and records over the speeds at once (:attr:`~valvetrain.dynamics.sweep.SweepResult.events`,
:func:`~valvetrain.design.dynamics_records.speed_records`, the headline) against the baseline of a
:class:`~valvetrain.dynamics.sweep.SpeedResult` and a :class:`~valvetrain.design.dynamics_records.SpeedRecord` made speed by
speed, as the stage did before; both must give the same minimum contact forces, seating velocities and bounces.
"""

from dataclasses import replace
from pathlib import Path
import time

import numpy as np

from valvetrain import springs
from valvetrain.design import run
from valvetrain.design.dynamics_records import speed_record, speed_records
from valvetrain.dynamics.perturbation import perturbation_parameter
from valvetrain.design.drive import drive_stage, spring_options
from valvetrain.design.drive_strength import strength_stage
from valvetrain.design.valve import design_valve, flow_stage, law_stage, profile_stage
from valvetrain.design.valve_checks import valve_checks
from valvetrain.layouts import train_mass
from valvetrain.specification import example_spec, load_spec, si

from timing import best_time

REPEATS = 30
APPENDIX = Path(__file__).resolve().parents[1] / "examples" / "seed000-appendix-kurz.toml"


def _figure(label, times, goal_ms):
    """Print best and median of (wall, processor) times [s]: on a machine that others use, a run of some
    milliseconds is often preempted, and its processor time is the figure that does not depend on their load."""
    wall, cpu = (sorted(x) for x in zip(*times, strict=True))
    middle = len(wall) // 2
    print(f"{label}: best {wall[0] * 1e3:6.2f} ms, median {wall[middle] * 1e3:6.2f} ms wall; best "
          f"{cpu[0] * 1e3:6.2f} ms, median {cpu[middle] * 1e3:6.2f} ms processor (goal <= {goal_ms:g} ms)")


def _clock():
    return time.perf_counter(), time.process_time()


def _since(start):
    now = _clock()
    return now[0] - start[0], now[1] - start[1]


def _requirement(valve, engine):
    """The spring requirement of the valve (a spring mass of zero: the drive stage's first search)."""
    cam = law_stage(valve, engine)
    law = cam.law
    theta = np.linspace(law.valve_opens, law.valve_closes, 2001)
    accel = cam.rocker_ratio * cam.cam_speed**2 * law.derivatives(theta)[2]
    mass = train_mass(valve, 0.0)[0]
    return (springs.Requirement(cam.valve_lift(theta), springs.required_spring_force(mass, accel,
                                                                                      valve.drive.spring_reserve),
                                springs.seat_load(mass)), cam.cam_speed)


def _exhaustive(requirement, throat, speed, options):
    """The lightest passing spring of every candidate designed (no screen): (D, d, coils, passing, tried)."""
    preloads, rates = requirement.lines(options.ratio_range)
    big_d, d = springs.search._grid(throat, options.diameter_range, options.diameter_step,
                                    springs.wire_series(options.wire_range_mm, options.wire_step_mm))
    lift = requirement.max_lift
    found = springs.evaluate_springs(preloads[:, None], rates[:, None], lift, big_d[None, :], d[None, :],
                                     options.materials[0], speed, ratio_range=options.ratio_range,
                                     min_installed_length=options.installed_limits(lift)[0],
                                     max_installed_length=options.installed_limits(lift)[1],
                                     max_free_length=options.max_free_length)
    i = int(np.argmin(np.where(found.passed, found.mass, np.inf)))
    return found.mean_diameter[i], found.wire_diameter[i], found.coils[i], int(found.passed.sum()), len(found)


def _records_at_once(sweep, speeds, epsilon):
    """The per-speed records as the dynamics stage makes them now (a fresh result: its events are found anew)."""
    fresh = replace(sweep)
    fresh.headline()
    return speed_records(fresh, speeds, epsilon)


def _records_speed_by_speed(sweep, speeds, epsilon):
    """The baseline: a SpeedResult and a SpeedRecord made for each speed."""
    return [speed_record(r, s, e) for r, s, e in zip(sweep.per_speed(), speeds, epsilon, strict=True)]


def dynamics_records():
    """Print the per-speed records' figure of the built-in example's intake valve beside its baseline."""
    design = run(example_spec()).valves["intake"]
    d, sweep = design.dynamics, design.dynamics.sweep
    speeds = np.asarray(d.per_speed.speed)
    p = d.parameters
    epsilon = perturbation_parameter(p.mass, p.drive_stiffness, p.spring_rate, sweep.cam_speeds)
    now, before = _records_at_once(sweep, speeds, epsilon), _records_speed_by_speed(sweep, speeds, epsilon)
    same = all(np.array_equal(getattr(now, name), [getattr(r, name) for r in before], equal_nan=True)
               for name in ("min_contact_force", "seating_velocity", "bounce", "bounce_count", "max_lift_error"))
    t_now = best_time(lambda: _records_at_once(sweep, speeds, epsilon), repeats=REPEATS)
    t_before = best_time(lambda: _records_speed_by_speed(sweep, speeds, epsilon), repeats=REPEATS)
    print(f"per-speed records of the built-in example's intake sweep ({speeds.size} speeds): over the speeds at once "
          f"{t_now * 1e3:6.2f} ms, baseline (speed by speed) {t_before * 1e3:6.2f} ms; the same records: "
          f"{'yes' if same else 'NO'}")


def main():
    spec = load_spec(APPENDIX)
    engine, output, gas = si(spec.engine), si(spec.output), si(spec.gas)
    base = spec.valves["intake"]
    variants = [si(base.model_copy(update={"cam": base.cam.model_copy(update={"shape_factor": 0.6 + 0.001 * i})}),
                   spec) for i in range(REPEATS)]
    stages, drives, strengths, designs = [], [], [], []
    for valve in variants:
        start = _clock()
        cam = law_stage(valve, engine)
        flow = flow_stage(cam, valve, engine)
        profile = profile_stage(cam, valve, output)
        valve_checks(cam, flow, profile, valve, engine, (valve.opens, valve.closes))
        stages.append(_since(start))
        start = _clock()
        drive = drive_stage(valve, gas, cam)
        drives.append(_since(start))
        start = _clock()
        strength_stage(valve, gas, engine, cam, drive)
        strengths.append(_since(start))
        start = _clock()
        design_valve("intake", valve, engine, gas, output)
        designs.append(_since(start))
    _figure("law + flow + profile + checks of one valve", stages, 3)
    print(f"the drive (masses, the spring search): best {min(w for w, _ in drives) * 1e3:6.2f} ms; the strength over "
          f"the speed range: best {min(w for w, _ in strengths) * 1e3:6.2f} ms (wall)")
    _figure("design_valve (all stages, the spring search, the strength, records and checks)", designs, 10)

    valve = si(base, spec)
    requirement, speed = _requirement(valve, engine)
    options = spring_options(valve.spring)
    throat = valve.throat_diameter
    screened = springs.design_springs(requirement, throat, speed, options)
    chosen = screened.designs["spring"]
    exhaustive = _exhaustive(requirement, throat, speed, options)
    same = exhaustive == (chosen.mean_diameter, chosen.wire_diameter, chosen.coils, screened.passing, screened.tried)
    t_screened = best_time(lambda: springs.design_springs(requirement, throat, speed, options), repeats=REPEATS)
    t_exhaustive = best_time(lambda: _exhaustive(requirement, throat, speed, options), repeats=REPEATS)
    print(f"one spring search of the example ({screened.tried} candidates, {screened.passing} passing): "
          f"screened {t_screened * 1e3:6.2f} ms, baseline (every candidate designed) {t_exhaustive * 1e3:6.2f} ms; "
          f"the same spring: {'yes' if same else 'NO'}")
    dynamics_records()


if __name__ == "__main__":
    main()
