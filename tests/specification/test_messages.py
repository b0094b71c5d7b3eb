"""Messages of a refused specification (specification/messages.py): the key, the value shown cut, what is allowed."""

from appendix import appendix_cam, appendix_with


def test_echoed_values_are_cut(refused):
    out = refused(appendix_with(("contour_points = 721", "contour_points = 721\nx = " + "[" * 200 + "]" * 200)))
    line = next(ln for ln in out.splitlines() if "output.x" in ln)
    assert len(line) < 200


def test_a_missing_law_lists_the_laws(refused):
    out = refused(appendix_with(('law = "kurz"', "")))
    assert "valves.intake.cam.law: required key is missing; allowed 'kurz', 'polydyne', 'polynomial'" in out
    assert "discriminator" not in out


def test_a_long_file_name_is_cut_in_the_message(tmp_path, refused):
    """A 5000-character table_file name (the fuzzer's) is shown cut, not echoed whole."""
    import shutil
    from pathlib import Path

    shutil.copytree(Path(__file__).parents[2] / "examples" / "data", tmp_path / "data")
    text = (Path(__file__).parents[2] / "examples" / "measured-lobe.toml").read_text()
    out = refused(text.replace('"data/measured-intake-lobe.csv"', '"' + "x" * 5000 + '.csv"'))
    line = next(ln for ln in out.splitlines() if "table_file" in ln)
    assert "cannot read the file" in line and len(line) < 300


def test_a_long_spring_material_is_cut_in_the_message(refused):
    """A 5000-character material name (found by the fuzzer) is shown cut, with the grades allowed."""
    out = refused(appendix_with(('material = "VDSiCr"', 'material = "' + "x" * 5000 + '"')))
    line = next(ln for ln in out.splitlines() if "material" in ln)
    assert "VDSiCr" in line and len(line) < 300


def test_many_combined_ratios_are_refused_with_a_short_message(refused):
    """100,000 ratio entries (found by the fuzzer) are refused by their count, not echoed."""
    cam = ('[valves.intake.cam]\nlaw = "combined"\nramp_end_velocity_mm_per_deg = 0.02\n'
           'segments = [{shape = "half_sine", length_deg = 25.0}, {shape = "quarter_sine", length_deg = 8.0}, '
           '{shape = "parabola_to_nose", length_deg = 38.0}]\n'
           'ratios = [' + ", ".join(["{segment = 20, value = 0.625}"] * 100_000) + "]\n")
    out = refused(appendix_with((appendix_cam(), cam + "\n")))
    assert "ratios" in out and max(len(ln) for ln in out.splitlines()) < 300
