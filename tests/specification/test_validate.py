"""Validation across keys (specification/validate.py): problems one field alone cannot see, the dotted keys of
Spec.replace, and run refusing a specification built around the validation."""

import pytest

from valvetrain.specification import example_text

from appendix import appendix_spec


def test_timing_of_a_table_needs_both_angles_or_none(tmp_path, refused):
    """A measured table may leave the timing to the table; one angle alone was a TypeError."""
    import shutil
    from pathlib import Path

    shutil.copytree(Path(__file__).parents[2] / "examples" / "data", tmp_path / "data")
    text = (Path(__file__).parents[2] / "examples" / "measured-lobe.toml").read_text()
    out = refused(text.replace("# max_lift_mm may be given", "opens_deg = 20.0\n# max_lift_mm may be given"))
    assert "valves.intake.opens_deg = 20 needs closes_deg too" in out


def test_model_copy_bypasses_validation_but_run_refuses_it():
    """A bore of -80 mm made with pydantic's model_copy (which validates nothing) is refused by run with the message
    a file with that bore gets (the field's bounds: [5, 2000] mm)."""
    import valvetrain as vt

    spec = vt.example_spec()
    bad = spec.model_copy(update={"engine": spec.engine.model_copy(update={"bore_mm": -80.0})})
    with pytest.raises(vt.SpecError) as err:
        vt.run(bad)
    assert err.value.problems == ["engine.bore_mm = -80.0: allowed [5, 2000] mm"]
    with pytest.raises(vt.SpecError, match="a valvetrain.specification.Spec .* or a dict of its tables is needed, "
                                           "not a str"):
        vt.run("my-engine.toml")
    with pytest.raises(vt.SpecError, match="engine.bore_mm: required key is missing"):
        vt.run({"engine": {"stroke_mm": 80.0, "rated_speed_rpm": 6000.0, "cylinders": 4, "strokes": 4},
                "crank": {}})


def test_replace_takes_the_dotted_keys_of_a_study_grid():
    """Spec.replace changes keys by the dotted paths of `study --grid`, validated: the new value is in the copy, the
    original is unchanged, and a value outside its bounds, an unknown key and a missing valve are SpecErrors."""
    import valvetrain as vt

    spec = appendix_spec()
    new = spec.replace({"engine.bore_mm": 85.0, "valves.intake.cam.shape_factor": 0.6})
    assert (new.engine.bore_mm, new.valves["intake"].cam.shape_factor) == (85.0, 0.6)
    assert spec.engine.bore_mm == 80.0 and new.engine.stroke_mm == spec.engine.stroke_mm
    for values, said in [({"engine.bore_mm": -80.0}, "engine.bore_mm = -80.0: allowed [5, 2000] mm"),
                         ({"engine.bore_mmm": 80.0}, "engine.bore_mmm: unknown key"),
                         ({"valves.exhaust.max_lift_mm": 8.0}, "valves.exhaust.max_lift_mm: the specification has no "
                                                                "valve 'exhaust' (valves: intake)"),
                         ({"valves.intake.cam": 1.0}, "valves.intake.cam: a table, not a value")]:
        with pytest.raises(vt.SpecError) as err:
            spec.replace(values)
        assert said in err.value.problems[0]


def test_a_rocker_inertia_without_its_valve_arm_is_refused(refused):
    """A rocker's moment of inertia is no mass at the valve without the arm that reduces it (J / l_v^2, eq. 5.2 of
    Valve-train practical works (n.d.)); the message names the key (checked in validate.py, where the follower is
    known: a finger's arm comes from its geometry)."""
    text = example_text()
    assert text.count("valve_arm_mm = 40.0") == 2
    out = refused("\n".join(line for line in text.split("\n") if not line.startswith("valve_arm_mm")))
    assert "valves.intake.drive.masses.rocker_inertia_kg_mm2 = 25: needs drive.valve_arm_mm" in out


def test_a_layout_without_a_lever_needs_rocker_ratio_1(refused):
    """The rocker ratio i_k = l_v / l_t is a lever's (the rocker link's, asked of the layout's links): the example's
    intake (rocker_ratio 1.6) with the direct layout, whose chain is a tappet alone, is refused naming the layout; with
    the rocker layout it is valid."""
    from valvetrain.specification.reading import parse_spec

    text = example_text()
    direct = text.replace('layout = "pushrod"           # "direct"', 'layout = "direct"           # "direct"', 1)
    assert direct != text
    assert 'valves.intake.drive.layout = "direct" needs rocker_ratio = 1 (got 1.6)' in refused(direct)
    assert parse_spec(text.replace('layout = "pushrod"           # "direct"', 'layout = "rocker"           # "direct"', 1))


def test_an_adjuster_axis_at_the_pivot_of_a_follower_without_one_is_refused():
    """A lash adjuster's axis needs a pivot the follower's geometry places (the follower's ``pivot_axis``): at the
    pivot of the example's flat follower it is refused, naming the key (no other rule refuses it: fails without)."""
    from valvetrain.specification import SpecError
    from valvetrain.specification.reading import parse_spec

    text = example_text().replace("[valves.intake.spring]", '[valves.intake.lash_adjuster]\nlocation = "pivot"\n'
                                  "axis_angle_deg = 10\n\n[valves.intake.spring]", 1)
    with pytest.raises(SpecError) as err:
        parse_spec(text)
    assert any(p.startswith("valves.intake.lash_adjuster.axis_angle_deg = 10 allowed only at the pivot of a finger")
               for p in err.value.problems)
