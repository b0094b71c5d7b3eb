"""A tolerance sample's design (:func:`valvetrain.tolerance.evaluate_sample`: the headline sweep, issue 38) against
the full design of the same sample (:func:`valvetrain.design.run`, every speed of the sweep), on random samples of
the built-in example: the answers a study gives must not depend on the shortcut."""

import tomllib

import numpy as np
import pytest

from valvetrain.design import run
from valvetrain.specification import example_text, validate
from valvetrain.study import with_values
from valvetrain.tolerance import check_id, draw, evaluate_sample, nominal
from valvetrain.units import rpm_to_rad_s

TOLERANCES = """
[[tolerances]]
key = "valves.intake.clearance_mm"
distribution = "uniform"
half_range = 0.05

[[tolerances]]
key = "valves.exhaust.clearance_mm"
distribution = "uniform"
half_range = 0.05

[[tolerances]]
key = "valves.intake.drive.masses.valve_kg"
distribution = "normal"
sigma = 0.005

[[tolerances]]
key = "valves.exhaust.drive.masses.valve_kg"
distribution = "normal"
sigma = 0.005
"""
"""The benchmark's tolerances (benchmarks/bench_tolerance.py) widened: +-0.05 mm on the clearances, 5 g on the valve
masses (a tenth of the example's): the three samples of seed 38 move the nominal jump speed (8092 and 8195 rpm) by
-1.4 to +2.7 % and the exhaust's largest seating velocity by up to -17 %."""

MARGIN_RTOL = 1e-3
"""A sample's margins against the full design's: the strength checks read the cam force at the speeds the headline
sweep simulates, the speeds around the full sweep's largest (:func:`valvetrain.dynamics.sweep.headline_sweep`); the
largest force between them moves by less than 0.1 % (test_tolerance.py, test_samples_have_the_full_designs_checks,
the nominal example)."""


def samples(count, seed):
    """``count`` random samples of the example with :data:`TOLERANCES`: the TOML documents, as a study designs
    them."""
    document = tomllib.loads(example_text() + TOLERANCES)
    spec = validate(document)
    keys = [t.key for t in spec.tolerances]
    centres = [nominal(spec, k) for k in keys]
    values = draw(spec, centres, count, "mc", seed)
    return [with_values(document, dict(zip(keys, row, strict=True))) for row in values]


@pytest.mark.parametrize("index", [0, 2])
def test_a_sample_gives_the_full_designs_answers(index):
    """Two of three random samples (seed 38; the second, close to the first, left out for the time of the full
    designs): the jump speed and the largest seating velocity of each valve are the full
    sweep's (the headline sweep simulates the speeds that decide them, so the same interpolation through the same
    speeds: equal to the bit), every check has the full design's verdict and its margin within
    :data:`MARGIN_RTOL`."""
    document = samples(3, 38)[index]
    record = evaluate_sample(document)
    full = run(validate(document))
    assert record["status"] == "ok"
    for name, v in full.valves.items():
        head = record["headlines"][name]
        jump = v.dynamics.jump_speed / rpm_to_rad_s(1.0)
        assert head["jump_speed_rpm"] == (jump if np.isfinite(jump) else None), name
        assert head["max_seating_velocity_m_s"] == v.dynamics.max_seating_velocity, name
    checks = {check_id(c): c for c in full.checks}
    assert set(record["checks"]) == set(checks)
    for cid, (margin, passed, *_) in record["checks"].items():
        c = checks[cid]
        assert passed == c.passed, cid
        if margin is None:
            assert not np.isfinite(c.margin), cid
        else:
            assert margin == pytest.approx(c.margin, rel=MARGIN_RTOL, abs=1e-12), cid


def test_a_valve_a_sample_leaves_as_it_was_is_not_designed_again(monkeypatch):
    """Two samples that differ in the intake's clearance alone, designed in turn in one process: the second designs
    its intake only, its exhaust is the first's design (tolerance.DESIGNS), and its record is the one a process that
    has designed nothing gives (the valves without their [dynamics], for the test's time)."""
    import valvetrain.design as design
    import valvetrain.tolerance as tolerance

    first = samples(1, 38)[0]
    for valve in first["valves"].values():
        del valve["dynamics"]
    second = with_values(first, {"valves.intake.clearance_mm": first["valves"]["intake"]["clearance_mm"] + 0.01})
    monkeypatch.setattr(tolerance, "DESIGNS", {})
    evaluate_sample(first)
    designed, real = [], design.design_valve
    monkeypatch.setattr(design, "design_valve", lambda name, *args, **kw: designed.append(name) or real(name, *args,
                                                                                                          **kw))
    record = evaluate_sample(second)
    assert designed == ["intake"]
    monkeypatch.setattr(tolerance, "DESIGNS", {})
    assert evaluate_sample(second) == record
    assert designed == ["intake", "intake", "exhaust"]


def test_a_sample_whose_spring_fails_has_the_full_designs_checks():
    """A sample whose intake spring fails (the manual's 60S2A wire: no spring of it reaches the resonance ratio 10 at
    7000 rpm, the built-in example's comment) is designed without the diagnosis of the failure (evaluate_sample:
    words the record does not keep, a search per remedy); its checks are the full design's, which diagnoses it:
    the same verdicts and margins within :data:`MARGIN_RTOL`, the spring's checks failing."""
    document = samples(1, 38)[0]
    document["valves"]["intake"]["spring"]["material"] = "60S2A"
    record = evaluate_sample(document)
    full = run(validate(document))
    failing = [c for c in full.checks if not c.passed and c.code.startswith("spring.")]
    assert failing and any(c.note for c in failing)    # the full design says why
    checks = {check_id(c): c for c in full.checks}
    assert record["status"] == "ok" and set(record["checks"]) == set(checks)
    for cid, (margin, passed, *_) in record["checks"].items():
        assert passed == checks[cid].passed, cid
        if margin is None:
            assert not np.isfinite(checks[cid].margin), cid
        else:
            assert margin == pytest.approx(checks[cid].margin, rel=MARGIN_RTOL, abs=1e-12), cid
