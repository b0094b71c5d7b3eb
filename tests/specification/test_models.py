"""The specification's models (specification/models.py) and what the design refuses of a model that validated: inputs
that cannot give a physically meaningful design are refused (exit 2, one message naming the key, the value and what is
allowed), never a traceback or a result that cannot be true (issue 9)."""

import re

from pydantic import ValidationError
import pytest

from valvetrain.specification import SpecError, example_spec, load_spec, parse_spec

from appendix import PATH as APPENDIX, appendix_spec, appendix_text, appendix_with


def test_the_over_speed_ratio_key_as_the_readme_states_it():
    """README, the keys' table: `[engine] over_speed_ratio`, default 1.1, allowed 1-2 (both ends allowed)."""
    assert appendix_spec().engine.over_speed_ratio == 1.1          # not in the appendix file: the default
    for value in (1.0, 2.0):
        assert appendix_spec().replace({"engine.over_speed_ratio": value}).engine.over_speed_ratio == value
    for value in (0.99, 2.01):
        with pytest.raises(SpecError, match=rf"engine.over_speed_ratio = {value}: allowed \[1, 2\]"):
            appendix_spec().replace({"engine.over_speed_ratio": value})


def test_the_engine_s_cross_checks_name_each_key_once(refused):
    """A hand test of the fuzz10 campaign: a firing order of three cylinders for four was refused as
    "engine: engine.firing_order = ...", the section named twice; each line names it once, as the other sections'."""
    out = refused(appendix_with(("firing_order = [1, 3, 4, 2]", "firing_order = [1, 2, 3]"),
                                ("rated_speed_rpm = 7000", "rated_speed_rpm = 7000\nidle_speed_rpm = 8000")), "run")
    assert out == ("error: engine: idle_speed_rpm = 8000: allowed below rated_speed_rpm = 7000; "
                   "firing_order = [1, 2, 3]: must list each cylinder 1...4 once\n")


def test_an_unknown_key_is_refused_by_its_name_and_a_section_is_frozen():
    """A misspelt key is no silent default: it is refused by its path; a validated section cannot be changed."""
    with pytest.raises(SpecError, match=r"engine.rated_speed_rmp: unknown key"):
        parse_spec(appendix_with(("rated_speed_rpm = ", "rated_speed_rmp = 1.0\nrated_speed_rpm = ")))
    with pytest.raises(ValidationError):
        appendix_spec().engine.bore_mm = 90.0


def test_a_cam_event_over_a_revolution_is_refused(refused):
    """Clearance 1.5 mm taken up at 0.002 mm/deg: the cosine ramp of Valve-train practical works (n.d.), eq. (2.1), Phi0 = pi h0 / (2 w'),
    lasts 1178 cam deg on each flank (spec/valvetrain-works-1-8.md, work 2)."""
    out = refused(appendix_with(("clearance_mm = 0.25", "clearance_mm = 1.5"),
                                ("ramp_end_velocity_mm_per_deg = 0.02", "ramp_end_velocity_mm_per_deg = 0.002")))
    assert "valves.intake.cam: the cam event lasts 2498 cam deg; allowed < 360 (a ramp of 1178 cam deg" in out


def test_a_lift_beyond_half_the_throat_is_refused(refused):
    assert "valves.intake.max_lift_mm = 400 mm: allowed at most 0.5 x throat_diameter_mm = 18.4 mm" in \
        refused(appendix_with(("max_lift_mm = 10.0", "max_lift_mm = 400.0")))


# issue 21, "The Python API validates"

@pytest.mark.parametrize("key,value,failing", [
    # issue 21 nonsense 7: the example's stroke (77.14 mm) typed in cm: S/D 0.096, c_p 1.80 m/s, lambda 0.029
    ("engine.stroke_mm", 7.7, {"stroke / bore (stroke_mm / bore_mm)", "lambda = R / L (stroke_mm / 2 / rod_length_mm)",
                               "mean piston speed (stroke_mm x rated_speed_rpm / 30000)"}),
    ("engine.rated_speed_rpm", 100.0, {"mean piston speed (stroke_mm x rated_speed_rpm / 30000)"}),  # rev/s: 0.26 m/s
])
def test_unit_slips_of_the_engine_are_failures(key, value, failing):
    """Hand calculation for the example (bore 80 mm, stroke 77.14 mm, [crank] rod 135 mm, 7000 rpm): the stroke in cm
    gives S/D = 7.7 / 80 = 0.096 < 0.278 (= (1 / 1.2) / 3, Heywood (1988)'s bore / stroke 0.8-1.2, 0.5), c_p =
    0.0077 x 7000 / 30 = 1.80 m/s < 2.67 m/s (= 8 / 3) and lambda = 3.85 / 135 = 0.029 < 0.08 (= 0.24 / 3); the speed in
    rev/s c_p = 0.07714 x 100 / 30 = 0.26 m/s.  (The bore in cm is refused already: the throat exceeds it.)  The example
    itself (S/D 0.96, c_p 18 m/s, lambda 0.29) passes all three."""
    import valvetrain as vt

    spec = appendix_spec()
    engine = {c.quantity.removeprefix("engine: "): c for c in vt.run(spec).checks if c.quantity.startswith("engine: ")}
    assert len(engine) == 3 and all(c.passed for c in engine.values())
    checks = vt.run(spec.replace({key: value})).checks
    failed = {c.quantity.removeprefix("engine: ") for c in checks
              if c.quantity.startswith("engine: ") and not c.passed}
    assert failed == failing
    assert all(c.severity == "failure" for c in checks if c.quantity.startswith("engine: "))


@pytest.mark.parametrize("value", [-1.0, 50.5])
def test_a_margin_outside_its_range_is_refused(value):
    text = appendix_text().replace("min_margin_percent = 0.0 ", f"min_margin_percent = {value} ")
    with pytest.raises(SpecError, match=r"min_margin_percent = .*: allowed \[0, 50\] %"):
        parse_spec(text)


@pytest.mark.parametrize("value", [5e-324, 1e-300, 9.9e-5])
def test_a_film_parameter_limit_of_almost_nothing_is_refused(refused, value):
    """Fuzz (fuzz11): [lubrication] min_film_parameter, then (0, 10], took 5e-324, and the check's margin, the film
    parameter over it, was inf in results.json; now at least 1e-4 (Lubrication's docstring: a film of a tenth of an
    atom for the default finishes), which tests/design/test_lubrication.py runs with."""
    out = refused(appendix_text() + f"\n[valves.intake.lubrication]\nmin_film_parameter = {value!r}\n", "run")
    assert out == f"error: valves.intake.lubrication.min_film_parameter = {value!r}: allowed [0.0001, 10]\n"


@pytest.mark.parametrize("key,value,allowed", [
    ("tappet_kg", 5e-324, "allowed 0 (none) or [0.0001, 20] kg"),
    ("pushrod_kg", 1e-300, "allowed 0 (none) or [0.0001, 20] kg"),
    ("cotters_kg", 9e-5, "allowed 0 (none) or [0.0001, 5] kg"),
    ("rocker_inertia_kg_mm2", 1e-300, "allowed 0 (none) or [0.01, 1e+07] kg·mm²"),
    ("bridge_kg", 5e-324, "allowed [0.0001, 20] kg"),
])
def test_a_part_mass_of_almost_nothing_is_refused(key, value, allowed):
    """Fuzz (fuzz11): the built-in example's multi-mass train with a tappet or pushrod of 5e-324 kg, a rocker of
    1e-300 kg mm2 or a valve bridge of 5e-324 kg (its bound then (0, 20]) overflowed the highest natural frequency,
    a traceback; a part's mass is now 0 (no such part) or at least LEAST_PART_MASS_KG = 1e-4 kg, a rocker's inertia
    at least 0.01 kg mm2 (models.py), and the bounds themselves are taken."""
    spec = example_spec()
    with pytest.raises(SpecError, match=rf"^valves.intake.drive.masses.{key} = {value!r}: {re.escape(allowed)}$"):
        spec.replace({f"valves.intake.drive.masses.{key}": value})
    least = 0.01 if key == "rocker_inertia_kg_mm2" else 1e-4
    assert getattr(spec.replace({f"valves.intake.drive.masses.{key}": least}).valves["intake"].drive.masses,
                   key) == least


MARINE = APPENDIX.parent / "marine-hydraulic-exhaust.toml"


@pytest.mark.parametrize("key,value,allowed", [
    ("valves.intake.dynamics.spring_mass_kg", 0.0, "allowed [0.0001, 5] kg"),
    ("valves.intake.dynamics.spring_mass_kg", 5e-324, "allowed [0.0001, 5] kg"),
    ("valves.intake.spring.min_frequency_difference", 5e-324, "allowed 0 (the check switched off) or [0.01, 1]"),
    ("valves.exhaust.hydraulic.vapour_pressure_MPa", 5e-324,
     "allowed 0 (cavitation at absolute zero) or [1e-06, 1] MPa"),
])
def test_a_limit_or_coil_mass_of_almost_nothing_is_refused(key, value, allowed):
    """Fuzz (fuzz11), keys with a closed lower bound of zero: a coil mass of 0 kg in the built-in example's multi-mass
    train divided by zero (a traceback) and one of 5e-324 kg overflowed; a nested pair's min_frequency_difference or a
    vapour pressure of 5e-324 put their check's margin, relative to it, at inf in results.json.  Now a coil mass is
    at least LEAST_PART_MASS_KG, the two limits 0 (their meaning kept) or at least 0.01 and 1e-6 MPa (models.py)."""
    spec = load_spec(MARINE) if "hydraulic" in key else example_spec()
    with pytest.raises(SpecError, match=rf"^{re.escape(key)} = {value!r}: {re.escape(allowed)}$"):
        spec.replace({key: value})


def test_a_problem_of_a_section_is_said_in_every_language():
    """Issue 41: a section's problems (specification/models.py validators) are notes of the catalogue (spec.*), its
    English the line the file's reader and the command line print, its Russian the designer's: idle_speed_rpm 9000
    above the built-in's rated 7000 rpm, both problems of [engine] in one line."""
    from valvetrain.locale import note_text
    from valvetrain.specification import example_text

    text = example_text().replace("rated_speed_rpm = 7000", "rated_speed_rpm = 7000\nidle_speed_rpm = 9000", 1)
    text = text.replace("firing_order = [1, 3, 4, 2]", "firing_order = [1, 1, 3, 4]", 1)
    with pytest.raises(SpecError) as err:
        parse_spec(text)
    (problem,) = err.value.problems
    assert problem.message == ("idle_speed_rpm = 9000: allowed below rated_speed_rpm = 7000; firing_order = [1, 1, 3, "
                               "4]: must list each cylinder 1...4 once")
    assert note_text(problem.message.parts, "ru") == (
        "idle_speed_rpm = 9000: допускается ниже rated_speed_rpm = 7000; firing_order = [1, 1, 3, 4]: каждый цилиндр "
        "1...4 должен быть назван один раз")
