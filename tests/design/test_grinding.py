"""The [valves.NAME.grinding] section: specification, the grinding stage, results.json, the files and the report."""

import csv
import json
from pathlib import Path
import re

import ezdxf
import jsonschema
import numpy as np
import pytest

from valvetrain.design import results_schema, run
from valvetrain.export import results_json, write_outputs
from valvetrain.specification import SpecError, parse_spec

from appendix import appendix_text

SECTION = "wheel_radius_mm = 300.0\nmaster_follower_radius_mm = 20.0\nbar_ratio = 2.0\n"


def with_section(grinding):
    """The built-in example's text (a flat-follower Kurz cam) with a [valves.intake.grinding] section."""
    return appendix_text().replace("[valves.intake.parts]", f"[valves.intake.grinding]\n{grinding}\n[valves.intake.parts]")


def problems(grinding):
    with pytest.raises(SpecError) as err:
        parse_spec(with_section(grinding))
    return err.value.problems


def test_no_section_no_grinding(tmp_path):
    results = run(parse_spec(appendix_text()))
    assert all("grinding" not in v for v in json.loads(results_json(results))["valves"].values())
    write_outputs(results, tmp_path / "out")
    assert not list((tmp_path / "out").rglob("*master*")) and not list((tmp_path / "out").rglob("*wear_error*"))


def test_a_flat_follower_cam_gets_a_master_and_no_wear_error(tmp_path):
    results = run(parse_spec(with_section(SECTION)))
    data = json.loads(results_json(results))
    jsonschema.validate(data, results_schema())
    g = data["valves"]["intake"]["grinding"]
    assert g["grindable"] and g["master_makeable"] and g["master_convex"]
    assert g["wheel_centre_min_radius_mm"] == pytest.approx(results.valves["intake"].heel_radius * 1e3 + 300.0)
    assert g["master_base_radius_mm"] == pytest.approx(2.0 * g["wheel_centre_min_radius_mm"] - 20.0)
    assert g["master_follower_lift_mm"] == pytest.approx(2.0 * (g["wheel_centre_max_radius_mm"]
                                                               - g["wheel_centre_min_radius_mm"]))
    assert g["max_wear_lift_error_mm"] < 1e-9 and g["max_wear_lift_error_first_order_mm"] == 0.0
    assert g["wheel_wear_mm"] == 0.5 and g["wear_table"] == "tables/intake_wear_error.csv"
    # the wear table's angles: the law's start and every 0.5 cam deg after it (written out in degrees), to the round-off
    # of one angle (1e-13 deg), not arange's step summed over the table (2e-12 deg)
    law, angle = results.valves["intake"].law, np.degrees(results.valves["intake"].grinding.wear.cam_angle)
    assert np.abs(angle - (np.degrees(law.start) + 0.5 * np.arange(angle.size))).max() < 1e-13
    out = write_outputs(results, tmp_path / "out")
    for f in ("contour/intake_master.csv", "contour/intake_master_cartesian.csv", "contour/intake_master.dxf",
              "tables/intake_wear_error.csv", "plots/intake_grinding.png"):
        assert (out / f).is_file(), f
    msp = ezdxf.readfile(out / "contour/intake_master.dxf").modelspace()
    (profile,) = msp.query('LWPOLYLINE[layer=="MASTER_PROFILE"]')
    points = np.array([p[:2] for p in profile.get_points()])
    assert profile.closed and np.min(np.hypot(*points.T)) == pytest.approx(g["master_base_radius_mm"], rel=1e-9)
    assert np.max(np.hypot(*points.T)) == pytest.approx(g["master_base_radius_mm"] + g["master_follower_lift_mm"],
                                                        rel=1e-6)
    (heel,) = msp.query('CIRCLE[layer=="MASTER_BASE_CIRCLE"]')
    assert heel.dxf.radius == pytest.approx(g["master_base_radius_mm"])
    rows = list(csv.DictReader(line for line in open(out / "contour/intake_master.csv") if not line.startswith("#")))
    assert len(rows) == 1440 and float(rows[720]["spindle_deg"]) == 0.0   # every 0.25 deg (export_step_deg)
    # at the nose the master follower is at its full lift, and so is the surface grinder's flat face
    assert float(rows[720]["master_follower_lift_mm"]) == pytest.approx(g["master_follower_lift_mm"], rel=1e-9)
    assert float(rows[720]["master_flat_lift_mm"]) == pytest.approx(g["master_follower_lift_mm"], rel=1e-6)
    wear = list(csv.DictReader(open(out / "tables/intake_wear_error.csv")))
    assert list(wear[0]) == ["cam_deg", "lift_mm", "worn_lift_mm", "error_mm", "error_first_order_mm",
                             "phase_shift_deg"]
    html = (out / "report.html").read_text()
    assert "Cam grinding: master cam and wheel wear" in html and re.search(r"\[\d+, ch\. 6\]", html)   # numbered
    assert "contour/intake_master.dxf" in html


def test_the_russian_report_has_the_grinding_chapter(tmp_path):
    out = write_outputs(run(parse_spec(with_section(SECTION))), tmp_path / "out", lang="ru")
    html = (out / "report.html").read_text()
    assert "Шлифование кулачка: копир и износ шлифовального круга" in html


def test_a_roller_cam_with_a_concave_flank_refuses_a_larger_wheel(tmp_path):
    """The roller exhaust of the polydyne example has concave flanks of 72 mm: a 300 mm wheel cannot grind them; the
    run says so as a failure check and writes no master and no wear table; a 60 mm wheel grinds it."""
    text = (Path(__file__).parents[2] / "examples" / "seed000-polydyne.toml").read_text()
    assert "wheel_radius_mm = 60.0" in text
    results = run(parse_spec(text.replace("wheel_radius_mm = 60.0", "wheel_radius_mm = 300.0")))
    v = results.valves["exhaust"]
    g = json.loads(results_json(results))["valves"]["exhaust"]["grinding"]
    assert not g["grindable"] and not g["master_makeable"] and g["max_wear_lift_error_mm"] is None
    # the example's valve-piston gap (0.70 mm against 2.54 mm) is a failure of its own since issue 24
    failing = [c for c in v.warnings if c.severity == "failure" and "valve-piston clearance" not in c.quantity]
    assert [c.quantity for c in failing] == ["exhaust: cam concave radius |rho| against the grinding wheel radius"]
    assert failing[0].value == pytest.approx(-g["cam_min_concave_radius_mm"] * 1e-3)
    out = write_outputs(results, tmp_path / "out")
    assert not (out / "contour/exhaust_master.dxf").exists() and not (out / "tables/exhaust_wear_error.csv").exists()
    assert (out / "contour/intake_master.dxf").exists()

    data = json.loads(results_json(run(parse_spec(text))))["valves"]
    # the flat-follower intake is ground with infeed: the base circle kept, a lift error of a fraction of a micrometre
    intake = data["intake"]["grinding"]
    assert intake["wear_compensation"] == "infeed" and 1e-5 < intake["max_wear_lift_error_mm"] < 1e-3
    assert intake["max_wear_lift_error_first_order_mm"] == pytest.approx(intake["max_wear_lift_error_mm"], rel=0.01)
    good = data["exhaust"]["grinding"]
    assert good["grindable"] and good["master_makeable"] and not good["master_convex"]
    assert good["master_flat_lift_max_mm"] is None   # a concave master cannot be made on a surface grinder
    # a roller follower sees w (sec beta - 1): some tens of micrometres for a 1 mm wear at 21 deg
    assert 0.02 < good["max_wear_lift_error_mm"] < 0.1
    assert good["max_wear_lift_error_first_order_mm"] == pytest.approx(good["max_wear_lift_error_mm"], rel=0.1)


@pytest.mark.parametrize("text, words", [
    ("wheel_radius_mm = 0.0\nmaster_follower_radius_mm = 20.0", ["wheel_radius_mm", "allowed [5, 1000] mm"]),
    ("wheel_radius_mm = 300.0\nmaster_follower_radius_mm = -1.0", ["master_follower_radius_mm", "allowed [1, 1000]"]),
    (SECTION + "bar_ratio = 0.0", ["bar_ratio", "allowed [0.1, 10]"]),
    (SECTION + "wheel_wear_mm = -0.1", ["wheel_wear_mm", "allowed [0, 50] mm"]),
    ("wheel_radius_mm = 10.0\nmaster_follower_radius_mm = 20.0\nwheel_wear_mm = 10.0",
     ["wheel_wear_mm = 10", "wheel_radius_mm = 10", "allowed [0, wheel radius)"]),
    ("master_follower_radius_mm = 20.0", ["wheel_radius_mm"]),
    (SECTION + "wheel_speed = 30.0", ["wheel_speed"]),
    (SECTION + 'wear_compensation = "reset"', ["wear_compensation", "'none'", "'infeed'"]),
])
def test_bad_values_are_refused_with_the_key_and_the_range(text, words):
    if "bar_ratio = 2.0\nbar_ratio" in text:
        text = text.replace("bar_ratio = 2.0\n", "", 1)
    found = "; ".join(problems(text))
    assert "grinding" in found
    for w in words:
        assert w in found, found


def test_a_master_without_a_heel_circle_is_refused():
    """The default master heel radius i (heel + R_w) - r_m must be positive: the run names the key and the limit."""
    text = with_section("wheel_radius_mm = 5.0\nmaster_follower_radius_mm = 10.0\nbar_ratio = 0.1\n")
    with pytest.raises(SpecError) as err:
        run(parse_spec(text))
    found = "; ".join(err.value.problems)
    assert "valves.intake.grinding.master_follower_radius_mm = 10" in found
    assert "allowed master_follower_radius_mm <" in found and "master_base_radius_mm" in found
    # the record of the JSON entry point names the key too (fuzzer: its path was empty)
    (problem,) = err.value.problems
    assert (problem.path, problem.value) == ("valves.intake.grinding.master_follower_radius_mm", "10")
    # with a heel radius of its own the master exists
    run(parse_spec(text.replace("bar_ratio = 0.1\n", "bar_ratio = 0.1\nmaster_base_radius_mm = 30.0\n")))
