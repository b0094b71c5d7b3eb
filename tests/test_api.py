"""The JSON-in/JSON-out entry point valvetrain.api, against the batch program's files and closed forms."""

import json
from pathlib import Path
import subprocess
import sys
import tomllib

import numpy as np
import pytest

from valvetrain import api
from valvetrain.specification import SpecError, parse_spec

from appendix import appendix_text

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def _document(path):
    document = tomllib.loads(path.read_text(encoding="utf-8"))
    document["source_dir"] = str(path.parent)
    return document


def _close(a, b, path=""):
    """Nested data equal, numbers to 1e-12 relative."""
    if isinstance(a, dict):
        assert set(a) == set(b), path
        for k in a:
            _close(a[k], b[k], f"{path}.{k}")
    elif isinstance(a, list):
        assert len(a) == len(b), path
        for i, (x, y) in enumerate(zip(a, b, strict=True)):
            _close(x, y, f"{path}[{i}]")
    elif isinstance(a, float) and isinstance(b, (int, float)):
        assert a == pytest.approx(b, rel=1e-12, abs=1e-300), path
    else:
        assert a == b, path


def test_dict_route_gives_the_numbers_of_valvetrain_run(tmp_path):
    # the independent route: the command line writes results.json from the file; the dict route reads nothing
    path = EXAMPLES / "seed000-appendix-kurz.toml"
    done = subprocess.run([sys.executable, "-m", "valvetrain", "run", str(path), "--out", str(tmp_path / "out"),
                           "--figures", "none"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    batch = json.loads((tmp_path / "out" / "results.json").read_text(encoding="utf-8"))
    out = api.design(_document(path))
    assert out["ok"] and out["errors"] == []
    _close(out["results"], batch)
    json.dumps(out, allow_nan=False)          # plain, strict JSON


def test_series_against_finite_differences_and_the_inputs():
    document = tomllib.loads(appendix_text())
    out = api.design(document)
    s = out["series"]["intake"]
    # the nose lifts the valve by max_lift_mm of the specification (10 mm)
    assert max(s["valve_lift_mm"]) == pytest.approx(10.0, rel=1e-9)
    # valve lift = rocker ratio (1.6) x the tappet lift above the ramp, whose height is the clearance (0.25 mm)
    valve = 1.6 * np.maximum(np.array(s["tappet_lift_mm"]) - 0.25, 0.0)
    assert np.allclose(np.array(s["valve_lift_mm"]), valve, rtol=1e-9, atol=1e-9)
    # velocity at the valve side = i omega_cam dh_T/dphi, omega_cam = pi n / 60 at 7000 rpm; central differences of
    # the sampled tappet lift (0.5 cam deg) agree to 1 % of the peak velocity
    omega = np.pi * 7000.0 / 60.0
    v = 1.6 * np.gradient(np.array(s["tappet_lift_mm"]) * 1e-3, np.radians(s["cam_deg"])) * omega
    assert np.max(np.abs(v - np.array(s["valve_velocity_m_s"]))) < 0.01 * np.max(np.abs(v))
    # the crank angle is the nose's plus twice the cam angle (four-stroke)
    nose = out["results"]["valves"]["intake"]["cam"]["nose_crank_deg"]
    assert np.allclose(np.array(s["crank_deg"]) - 2.0 * np.array(s["cam_deg"]), nose)


def test_errors_are_records_with_key_value_and_range():
    document = tomllib.loads(appendix_text())
    document["engine"]["bore_mm"] = -3.0
    out = api.design(document)
    assert not out["ok"] and out["results"] is None
    # [engine] bore_mm is declared in 5 ... 2000 mm (specification/models.py)
    assert out["errors"] == [{"path": "engine.bore_mm", "value": "-3.0", "message": "allowed [5, 2000] mm",
                              "text": "engine.bore_mm = -3.0: allowed [5, 2000] mm"}]


def test_a_cross_check_error_is_a_record_of_its_key_and_value():
    """The records are the parts of the problem as found, not read back from its text: a cross-check's line
    "KEY = VALUE must be smaller than ..." has no ": " after the value, and parsing the text gave no key at all."""
    document = tomllib.loads(appendix_text())
    bore = document["engine"]["bore_mm"]
    document["valves"]["intake"]["throat_diameter_mm"] = bore + 10.0
    out = api.design(document)
    # the line the command line prints, written out by hand from specification/validate.py's rule
    text = f"valves.intake.throat_diameter_mm = {bore + 10.0:g} must be smaller than engine.bore_mm = {bore:g}"
    assert out["errors"] == [{"path": "valves.intake.throat_diameter_mm", "value": f"{bore + 10.0:g}",
                              "message": f"must be smaller than engine.bore_mm = {bore:g}", "text": text}]


def test_a_design_stage_error_is_a_record_of_its_key():
    """A lift beyond half the throat is refused by the law stage (design/valve.py, MAX_LIFT_TO_THROAT = 0.5), its
    problem naming the valve's key: 0.6 x the throat against the limit 0.5 x the throat, by hand."""
    document = tomllib.loads(appendix_text())
    throat = document["valves"]["intake"]["throat_diameter_mm"]
    document["valves"]["intake"]["max_lift_mm"] = 0.6 * throat
    (error,) = api.design(document)["errors"]
    assert (error["path"], error["value"]) == ("valves.intake.max_lift_mm", f"{0.6 * throat:.4g} mm")
    assert error["message"].startswith(f"allowed at most 0.5 x throat_diameter_mm = {0.5 * throat:.4g} mm")


def test_a_changed_key_that_is_no_table_is_a_record_of_the_key():
    """Spec.replace's problems name the dotted key they were given."""
    with pytest.raises(SpecError) as err:
        parse_spec(appendix_text()).replace({"engine.bore_mm.x": 1.0})
    (problem,) = api.error_records(err.value)
    assert problem["path"] == "engine.bore_mm.x" and problem["value"] is None
    assert problem["message"] == "engine.bore_mm is a value, not a table"


def test_a_changed_key_inside_an_array_is_a_record_of_the_array():
    """A dotted key through an array of tables (study --grid breathing.conditions.0.speed_rpm) names the array as
    one (fuzz6: it was called 'a value'; fails before)."""
    text = (Path(__file__).parent.parent / "examples" / "tcc3-motored.toml").read_text(encoding="utf-8")
    with pytest.raises(SpecError) as err:
        parse_spec(text).replace({"breathing.conditions.0.speed_rpm": 900.0})
    (problem,) = api.error_records(err.value)
    assert problem["path"] == "breathing.conditions.0.speed_rpm"
    assert problem["message"] == ("breathing.conditions is an array, not a table: a dotted key does not reach into "
                                  "it; set the whole array")


def test_not_a_dict_is_an_error_record():
    out = api.design("bore = 80")
    assert not out["ok"] and "not a str" in out["errors"][0]["message"]


def test_toml_text_reproduces_the_design():
    document = tomllib.loads(appendix_text())
    document["valves"]["intake"]["max_lift_mm"] = 10.5
    again = api.design(tomllib.loads(api.toml_text(document)))
    _close(again["results"], api.design(document)["results"])
    assert parse_spec(api.toml_text(document)).valves["intake"].max_lift_mm == 10.5


def test_sweep_gives_the_numbers_of_valvetrain_sweep(tmp_path):
    path = EXAMPLES / "seed000-appendix-kurz.toml"
    done = subprocess.run([sys.executable, "-m", "valvetrain", "sweep", str(path), "--out", str(tmp_path / "out")],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    batch = json.loads((tmp_path / "out" / "dynamics.json").read_text(encoding="utf-8"))
    out = api.sweep(_document(path))
    assert out["ok"]
    for name, series in out["sweeps"].items():
        rec = batch["valves"][name]
        for key in ("jump_speed_rpm", "bounce_speed_rpm"):
            assert series[key] == pytest.approx(rec[key], rel=1e-12)
        assert series["speed_rpm"] == pytest.approx(rec["per_speed"]["speed_rpm"], rel=1e-12)
        assert series["min_contact_force_N"] == pytest.approx(rec["per_speed"]["min_contact_force_N"], rel=1e-12)
        assert len(series["map_lift_error_mm"]) == len(series["speed_rpm"])
        # the contact force and the valve's acceleration over the same angles and speeds; a cam pushes, never pulls:
        # its contact force is nowhere negative, and positive somewhere at every speed
        shape = np.shape(series["map_lift_error_mm"])
        assert np.shape(series["map_contact_force_N"]) == np.shape(series["map_valve_acceleration_m_s2"]) == shape
        force = np.array(series["map_contact_force_N"], dtype=float)
        assert np.nanmin(force) >= 0.0 and np.all(np.nanmax(force, axis=1) > 0.0)


def test_a_sweep_is_stopped_by_its_progress_callback():
    class Stop(Exception):
        pass

    def progress(name, done, total):
        raise Stop

    with pytest.raises(Stop):
        api.sweep(tomllib.loads(appendix_text()), progress=progress)


def test_design_without_the_sweeps_and_with_them():
    """Issue 25: the designer's two steps.  Without the sweeps the kinematics are those of the whole design (the
    dynamics stage reads the law, never changes it) and no check of the dynamics is made; with ``sweeps`` the sweeps
    are api.sweep's, the independent route (the sweep alone, design.sweep_designs)."""
    from valvetrain.design.dynamics_checks import CHECK_CODES
    from valvetrain.specification import example_text

    document = tomllib.loads(example_text())
    document["accepted"].append({"quantity": "dynamics.jump_speed", "reason": "a test: accepted, named by its code"})
    quick = api.design(document, dynamics=False)
    whole = api.design(document, sweeps=True)
    assert quick["ok"] and whole["ok"]
    _close(quick["series"], whole["series"])
    assert not {c["code"] for c in quick["results"]["checks"]} & set(CHECK_CODES)
    assert {c["code"] for c in whole["results"]["checks"] if c["accepted"]} >= {"dynamics.jump_speed"}
    _close(whole["sweeps"], api.sweep(document)["sweeps"])
    assert "sweeps" not in api.design(document, dynamics=False)
    # a key of a [dynamics] section is validated all the same
    document["valves"]["intake"]["dynamics"]["damping_ratio"] = 5.0
    (error,) = api.design(document, dynamics=False)["errors"]
    assert error["path"] == "valves.intake.dynamics.damping_ratio"


def test_memo_designs_again_only_the_valves_whose_inputs_changed(monkeypatch):
    import valvetrain.design as design
    from valvetrain.specification import example_text, set_keys

    designed = []
    original = design.design_valve
    monkeypatch.setattr(design, "design_valve", lambda name, *a, **k: designed.append(name) or original(name, *a, **k))
    document = tomllib.loads(example_text())
    memo = {}
    api.design(document, dynamics=False, diagnose=False, memo=memo)
    assert designed == ["intake", "exhaust"]
    # the intake's lift edited: the exhaust's design is the one kept
    designed.clear()
    edited = set_keys(document, {"valves.intake.max_lift_mm": 9.5})
    out = api.design(edited, dynamics=False, diagnose=False, memo=memo)
    assert designed == ["intake"]
    # the independent route: every valve designed afresh, without the memo
    _close(out["results"], api.design(edited, dynamics=False, diagnose=False)["results"])
    # the nose lifts the valve by max_lift_mm of the specification
    assert max(out["series"]["intake"]["valve_lift_mm"]) == pytest.approx(9.5, rel=1e-9)
    # the engine's speed edited: it is an input of every valve
    designed.clear()
    api.design(set_keys(edited, {"engine.rated_speed_rpm": 6000}), dynamics=False, diagnose=False, memo=memo)
    assert designed == ["intake", "exhaust"]


@pytest.mark.parametrize("name", ["two-stroke-ports", "v8-crank"])
def test_design_without_the_sweeps_of_a_file_with_no_valves(name):
    """Fuzzer: a specification without [valves] (a two-stroke's ports, a crank alone) designed without the sweeps
    raised KeyError in the JSON entry point; its results are those of the whole design (it has no sweep to leave
    out), the independent route."""
    document = _document(EXAMPLES / f"{name}.toml")
    quick = api.design(document, dynamics=False)
    assert quick["ok"], quick["errors"]
    _close(quick["results"], api.design(document)["results"])


def test_kinematics_of_one_valve_are_the_designs_curves():
    # the designer's answer to a drag (api.kinematics: the law, flow and profile stages of the valve alone) draws
    # what the whole design of the same specification draws: every series but the spring's, the flow's figures
    from valvetrain.specification import example_text

    document = tomllib.loads(example_text())
    alone = api.kinematics(document, "intake")
    whole = api.design(document, dynamics=False, diagnose=False)
    assert alone["ok"] and alone["series"]["intake"] == {
        k: v for k, v in whole["series"]["intake"].items() if not k.startswith(("spring_", "required_"))}
    assert alone["results"]["valves"]["intake"]["flow"] == whole["results"]["valves"]["intake"]["flow"]
    assert alone["results"]["valves"]["intake"]["cam"]["camshaft_speed_rad_s"] == \
        whole["results"]["valves"]["intake"]["cam"]["camshaft_speed_rad_s"]
    # a cam the law cannot make is refused as the design refuses it; a valve the specification lacks by its name
    low = {**document, "valves": {**document["valves"], "intake": {**document["valves"]["intake"], "max_lift_mm": 0.31}}}
    assert [e["text"] for e in api.kinematics(low, "intake")["errors"]] == \
        [e["text"] for e in api.design(low, dynamics=False)["errors"]]
    assert api.kinematics(document, "inlet")["errors"][0]["text"] == "no valve 'inlet'; allowed: intake, exhaust"
