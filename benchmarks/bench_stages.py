"""Benchmark: recomputing one valve after a parameter change (law + flow + profile + checks, no files).

Run on demand: ``python benchmarks/bench_stages.py``.  The law of the built-in example's intake valve is rebuilt
with a changed shape factor each repeat (so no stage result can be reused), then the flow, profile and check stages
run on it; the whole valve with its drive (springs, strength) is timed beside it, and ``design_valve`` as the
design runs it (all stages, the law's records, the checks).  Best of the repeats.
"""

import time

from valvetrain.design.drive import drive_stage, strength_stage
from valvetrain.design.valve import design_valve, flow_stage, law_stage, profile_stage, valve_checks
from valvetrain.specification import example_spec, si

REPEATS = 30


def main():
    spec = example_spec()
    engine, output, gas = si(spec.engine), si(spec.output), si(spec.gas)
    base = spec.valves["intake"]
    variants = [si(base.model_copy(update={"cam": base.cam.model_copy(update={"shape_factor": 0.6 + 0.001 * i})}),
                   spec) for i in range(REPEATS)]
    stages, whole, designs = [], [], []
    for valve in variants:
        t0 = time.perf_counter()
        cam = law_stage(valve, engine)
        flow = flow_stage(cam, valve, engine)
        profile = profile_stage(cam, valve, output)
        valve_checks(cam, flow, profile, valve, engine, (valve.opens, valve.closes))
        t1 = time.perf_counter()
        drive = drive_stage(valve, gas, cam)
        strength_stage(valve, gas, engine, cam, drive)
        t2 = time.perf_counter()
        design_valve("intake", valve, engine, gas, output)
        t3 = time.perf_counter()
        stages.append(t1 - t0)
        whole.append(t2 - t0)
        designs.append(t3 - t2)
    print(f"law + flow + profile + checks of one valve: best {min(stages) * 1e3:6.2f} ms, "
          f"median {sorted(stages)[len(stages) // 2] * 1e3:6.2f} ms")
    print(f"the same with the drive (masses, springs, strength over the speed range): best {min(whole) * 1e3:6.2f} ms")
    print(f"design_valve (all stages, records and checks): best {min(designs) * 1e3:6.2f} ms, "
          f"median {sorted(designs)[len(designs) // 2] * 1e3:6.2f} ms")


if __name__ == "__main__":
    main()
