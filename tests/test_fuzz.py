"""Fuzzing the specification path (issue 9): a mutated specification, or one with a malformed lift table or
indicator diagram, either runs to finite, plausible results or is refused (SpecError, exit status 2) with one
message per problem that names its key; never a traceback, a numerical RuntimeWarning, a hang, NaN or inf in an
output, or a message without its key.

The cases come from the generator of tools/fuzz_specs.py (one copy of the mutations and of the checks), drawn by
hypothesis; the runs are derandomized and keep no example database, so CI sees the same cases every time.
``python tools/fuzz_specs.py`` runs many more cases and groups the failures: this file is the regression guard
(360 fixed cases; a fuzz campaign runs thousands), sized to the CI's time.
"""

import math

from hypothesis import given, settings, strategies as st
import pytest

from fuzz_contract import BASES, FUZZ, assert_contract, fuzz

FILE_CASES = [c for c in fuzz.file_cases(BASES)
              if not any(name in fuzz.SLOW_FILES for op in c["ops"] for name in op if isinstance(name, str))]


def _assert_contract(case):
    assert_contract(case, timeout=60.0)


@settings(FUZZ, max_examples=300)
@given(st.data())
def test_mutated_specification_runs_or_is_refused(data):
    _assert_contract(fuzz.draw_case(lambda seq: data.draw(st.sampled_from(seq)), BASES))


@settings(FUZZ, max_examples=60)
@given(st.sampled_from(FILE_CASES))
def test_malformed_file_runs_or_is_refused(case):
    _assert_contract(case)


def test_the_fuzzer_covers_the_commands_and_the_stage_sections():
    """Issue 21: the fuzzer's random cases run study, optimize (bounded: --maxiter 1), sweep and compare besides run,
    and mutate the keys of the [dynamics] and [hydraulic] sections or add them to a valve."""
    cases = fuzz.random_cases(200, "21", BASES)
    commands = {c["command"][0] for c in cases if c.get("command")}
    assert commands == set(fuzz.COMMANDS)
    assert all(c["command"][1:3] == ["--maxiter", "1"] for c in cases if c.get("command", [""])[0] == "optimize")
    ops = [op for c in cases for op in c["ops"]]
    assert any(op[0] == "stage" for op in ops)
    assert any(op[0] in ("scale", "set", "type", "delete") and len(op[1]) > 3 and op[1][2] in fuzz.STAGES
               for op in ops)


def test_a_command_case_is_classified_by_its_exit_status():
    """compare of the built-in example with itself runs (exit status 0, no NaN printed or written); a --grid of a
    key the file does not have is refused with exit status 2 and a message naming the key; an optimisation with no
    feasible point is that outcome (exit status 1 with the failing limits named)."""
    ok = fuzz.run_case({"base": "example", "ops": [], "command": ["compare", "<base>"]}, BASES, timeout=120.0)
    assert ok["outcome"] == "ok", ok
    refused = fuzz.run_case({"base": "example", "ops": [], "command": ["study", "--grid", "engine.nosuchkey_mm=1,2"]},
                            BASES, timeout=120.0)
    assert refused["outcome"] == "refused" and "engine.nosuchkey_mm" in " ".join(refused["detail"]), refused
    # no follower separation up to 3 x the rated speed is out of the built-in train's reach (it separates near the
    # rated speed): optimize exits 1 naming the limit, a result the fuzzer counted as a traceback
    infeasible = fuzz.run_case({"base": "example", "ops": [], "command": ["optimize", "--maxiter", "1", "--no-jump",
                                                                         "3"]}, BASES, timeout=120.0)
    assert infeasible["outcome"] == "infeasible" and "separation" in " ".join(infeasible["detail"]), infeasible


def test_the_fuzzer_reaches_the_finger_the_adjuster_the_camshaft_the_tolerances_and_the_designer():
    """Issue 36: the random cases put the finger follower on valves (its variants, measured tables among the bases)
    and mutate its keys, add a lash adjuster and a [camshaft] and mutate their keys, run `valvetrain tolerance` with
    drawn [[tolerances]] and damaged records, and run the designer's session and `valvetrain serve`."""
    cases = fuzz.random_cases(400, "36", BASES)
    ops = [op for c in cases for op in c["ops"]]
    kinds = {op[0] for op in ops}
    assert {"finger", "tolerances", "stage", "section"} <= kinds
    assert {op[2] for op in ops if op[0] == "finger"} == set(fuzz.FINGER_VARIANTS)
    assert any(op[0] == "stage" and op[2] == "lash_adjuster" for op in ops)
    assert ["section", "add_camshaft"] in ops
    mutated = [op[1] for op in ops if op[0] in ("scale", "set", "type", "delete")]
    assert any(p[0] == "camshaft" for p in mutated)
    assert any(len(p) == 4 and p[2] == "cam" and str(p[3]).startswith("finger_") for p in mutated)
    assert any(len(p) > 3 and p[2] == "lash_adjuster" for p in mutated)
    commands = [c["command"] for c in cases if c.get("command")]
    assert any(c[0] == "tolerance" and any(a.startswith("<damage:") for a in c) for c in commands)
    assert any(c.get("session") for c in cases) and any(c.get("serve") for c in cases)


@pytest.mark.parametrize("case", [
    # the findings of the campaign of issue 36, each a traceback before
    {"base": "law:table", "ops": [["finger", "intake", "pivot_out_of_reach"]]},
    {"base": "example", "ops": [["stage", "intake", "lash_adjuster"],
                                ["set", ["valves", "intake", "lash_adjuster", "supply_pressure_MPa"], 0.0],
                                ["set", ["valves", "intake", "lash_adjuster", "plunger_spring_N"], 0.0]]},
    {"base": "examples/modern-dohc-roller-finger.toml", "ops": [["finger", "intake", "tip_off_axis"]]},
    {"base": "example", "ops": [["section", "add_camshaft"],
                                ["set", ["camshaft", "section_bores_mm"], [24.999, 31.999]]]},
    {"base": "examples/measured-lobe.toml", "ops": [], "session": [["drag", "intake", 0, 10.0, 5.0], ["toml"]]},
    # the fuzzer's session dragged a handle by its Handle, not its name: a three-arc cam's nose fell through to the
    # keys of a cam of segment angles (KeyError 'phi1_deg')
    {"base": "law:three_arc+roller", "ops": [["stage", "intake", "hydraulic"]],
     "session": [["drag", "intake", 2, -10.0, -0.5], ["edit", "valves.intake.dynamics.damping_ratio", 0.5]]},
    # nan_output before: a lash adjuster on a valve without [dynamics] has no simulated plunger motion, its per-speed
    # pumped_up_um, revolutions and settled null as their labels say
    {"base": "examples/measured-lobe.toml", "ops": [["stage", "intake", "lash_adjuster"]]},
    # bad_message before: a lift table with a row off the spline fit was refused in more than 300 characters
    {"base": "law:table", "ops": [["lift_file", "intake", "short_event_10_deg", "valve", "spline"]]},
    # nan_output before (the campaign on the merged main): a valve of 1 mm lift never reaches the cam card's checking
    # heights, 1 mm and 0.050 in; its events there are null as their labels say
    {"base": "examples/seed000-polydyne.toml", "ops": [["scale", ["valves", "intake", "max_lift_mm"], 0.1]]},
], ids=["finger on a table, out of reach", "adjuster without refill", "finger pad off the tip", "camshaft wall 0.5 um",
        "designer on a measured table", "designer drags a three-arc nose", "adjuster without dynamics",
        "a row off the fit", "a lift below the cam card's heights"])
def test_the_findings_of_issue_36_run_or_are_refused(case):
    rec = fuzz.run_case(case, BASES, timeout=120.0)
    assert rec["outcome"] in ("ok", "refused"), rec


def test_serve_refuses_a_file_that_is_not_toml_as_run_does(tmp_path):
    """Issue 36 (fuzz): `valvetrain serve` on a file with a duplicate key prints what `valvetrain run` prints, the file
    and the line ("<file>: not valid TOML: Cannot overwrite a value (at line 4, column 15)"); the fuzzer compared
    the message, its temporary folder written <tmp>, with the file's real path and counted it a bad message."""
    from click.testing import CliRunner
    from valvetrain.cli import main

    case = {"base": "examples/measured-lobe.toml", "ops": [["text", "duplicate_key"]],
            "serve": {"mode": "ok", "requests": []}}
    rec = fuzz.run_case(case, BASES, timeout=120.0)
    assert rec["outcome"] == "refused", rec
    text, _, _ = fuzz.materialize(case, BASES)
    (tmp_path / "spec.toml").write_bytes(text)
    ran = CliRunner().invoke(main, ["run", str(tmp_path / "spec.toml"), "--out", str(tmp_path / "out")])
    assert ran.exit_code == 2
    assert rec["detail"] == [m.replace(str(tmp_path), "<tmp>") for m in fuzz._command_messages(ran.output)]
    assert rec["detail"][0].startswith("<tmp>/spec.toml: not valid TOML: Cannot overwrite a value (at line ")


def test_a_check_without_bounds_has_no_margin_and_one_with_a_bound_has_one():
    """A check without bounds (range 'any') has no margin: +inf in memory, null in results.json, as the schema says;
    a null or infinite margin of a check with a bound stays a finding.  The fuzzer flagged every null margin of a
    written results.json before (the gas force at the exhaust's opening of every example with an exhaust valve)."""
    boundless = {"code": "gas_force.exhaust_opening", "value": 423.6, "low": None, "high": None}
    bounded = {"code": "flow.throat_velocity", "value": 85.0, "low": 50.0, "high": 80.0}
    for margin in (None, math.inf):
        data = {"checks": [{**boundless, "margin": margin}, {**bounded, "margin": margin}]}
        assert fuzz.null_problems(data, []) == [("checks[].margin", f"checks[1].margin = {margin!r}")]


def test_a_null_documented_by_its_path_is_not_excused_elsewhere():
    """The lash adjuster's per-speed revolutions and settled are null at a speed without a simulated motion (their
    labels); a null of a key of the same name in another section (the dynamics' revolutions) stays a finding."""
    data = {"valves": {"intake": {"lash_adjuster": {"per_speed": {"revolutions": [None, 3], "settled": [None, True],
                                                                  "pumped_up_um": [None, 1.5]}},
                                  "dynamics": {"revolutions": None}}}}
    assert fuzz.null_problems(data, ["intake"]) == [("valves.NAME.dynamics.revolutions",
                                                     "valves.intake.dynamics.revolutions = None")]


def test_a_tolerance_case_with_damaged_records_designs_them_again():
    """A tolerance case whose records.jsonl is damaged (a passing check made an unevaluated failure) after its first
    run: the run again designs that sample again and gives the first run's results (else: nonsense)."""
    case = {"base": "example", "ops": [["tolerances", [{"key": "valves.intake.throat_diameter_mm",
                                                         "distribution": "normal", "sigma": 0.01, "low": 37.2,
                                                         "high": 37.21}]]],
            "command": ["tolerance", "--samples", "3", "<damage:passed_flipped>"]}
    rec = fuzz.run_case(case, BASES, timeout=120.0)
    assert rec["outcome"] == "ok", rec


def test_the_hard_deadline_of_a_case_is_the_time_its_own_rules_allow():
    """A case's worker ends at the case's own allowance + 30 s: 41 valve sections (copy_many) may take 41/8 x the
    timeout, an optimisation 4 x (COMMAND_TIMEOUT).  fuzz7's campaign (seed fuzz7a) counted three copy_many cases as
    hangs in C code: the worker was ended at timeout + 30 s, before run_case's own 41/8 x timeout had passed."""
    many = {"base": "example", "ops": [["valve", "intake", "copy_many", "x"]]}
    assert fuzz.allowed_seconds(many, BASES, 60.0) == 60.0 * 42 / fuzz.VALVES_PER_TIMEOUT
    assert fuzz.allowed_seconds({"base": "example", "ops": []}, BASES, 60.0) == 60.0
    optimize = {"base": "example", "ops": [], "command": ["optimize", "--maxiter", "1"]}
    assert fuzz.allowed_seconds(optimize, BASES, 60.0) == 240.0


def test_toml_nested_deeper_than_the_parser_goes_is_refused_or_taken_as_text():
    """A fuzz run (fuzz9): the designer's session on a specification with an array nested 2000 deep raised
    RecursionError out of tomllib (the command line's parse_spec refused it already). The session, the overlaid file
    and the specification's text refuse it as too deeply nested; a grid value and a panel input so nested are their
    text (refused then as a value of the wrong type)."""
    pytest.importorskip("bokeh")
    from valvetrain.specification import SpecError, toml_tables
    from valvetrain.study import parse_value as grid_value
    from valvetrain.web.form import Field, parse_value as panel_value
    from valvetrain.web.session import Session

    deep = "[" * 2000 + "]" * 2000
    for read in (toml_tables, Session.start):
        with pytest.raises(SpecError, match="nested too deeply"):
            read(f"x = {deep}\n")
    assert grid_value(deep) == deep
    assert panel_value(Field("engine.cylinder_offsets_mm", "list", None), deep) == deep
