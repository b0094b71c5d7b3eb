"""Reading a specification (specification/reading.py): TOML text, a parsed document or a file; what cannot be read
or parsed is refused with the file or key it concerns."""

import re

from click.testing import CliRunner
import pytest

from valvetrain.cli import main
from valvetrain.specification import example_text

from appendix import appendix_text, appendix_with


def test_a_utf8_bom_is_accepted(tmp_path):
    f = tmp_path / "bom.toml"
    f.write_bytes(b"\xef\xbb\xbf" + appendix_text().encode("utf-8"))
    result = CliRunner().invoke(main, ["validate", str(f)])
    assert result.exit_code == 0, result.output


@pytest.mark.parametrize("command", [["run", "--out", "out"], ["tolerance", "--samples", "3", "--out", "out"],
                                     ["study", "--grid", "engine.rated_speed_rpm=6000,7000", "--out", "out"]])
def test_a_file_with_two_byte_order_marks_is_refused_by_every_command(tmp_path, monkeypatch, command):
    """fuzz10 (tools/fuzz_specs.py --seed fuzz10e): a file led by two byte-order marks, once the first was dropped in
    reading the file and the second in parsing it, passed the specification's reading, and `valvetrain tolerance`
    (and study), reading the file again with one dropped, ended in TOMLDecodeError.  One mark is dropped, by the
    reading every command shares: the file is refused alike."""
    monkeypatch.chdir(tmp_path)
    f = tmp_path / "twice.toml"
    f.write_bytes(b"\xef\xbb\xbf" * 2 + (appendix_text() + "\n[[tolerances]]\nkey = \"engine.bore_mm\"\n"
                                          "distribution = \"uniform\"\nlow = 79.9\nhigh = 80.1\n").encode("utf-8"))
    result = CliRunner().invoke(main, [command[0], str(f), *command[1:]])
    assert result.exit_code == 2, result.output
    assert result.output.startswith(f"error: {f}: not valid TOML: Invalid statement (at line 1, column 1): '\\ufeff#")
    assert not (tmp_path / "out").exists()


def test_deeply_nested_arrays_are_refused(refused):
    deep = "[" * 5000 + "]" * 5000
    assert "nested too deeply" in refused(appendix_with(("contour_points = 721", f"contour_points = 721\nx = {deep}")))


def test_a_huge_specification_is_refused_before_parsing(refused):
    """A fuzz case: 100,000 tables of deeply nested arrays (83 MB) kept tomllib busy for over a minute."""
    filler = "\n".join(f"[extra{i}]\nx = [[[1]]]" for i in range(60_000))
    out = refused(appendix_with(("contour_points = 721", f"contour_points = 721\n{filler}")))
    assert "allowed at most 1,000,000" in out


def test_a_file_reading_error_names_the_file_as_its_path(tmp_path):
    """The problem of a file that cannot be read, parsed or designed at all carries the file name as its key path (records of the
    JSON entry point); the refactoring to structured problems had left it empty.  The printed line is the one
    written by hand here."""
    from valvetrain.api import error_records
    from valvetrain.specification import SpecError, load_spec

    missing, latin, broken = tmp_path / "missing.toml", tmp_path / "latin.toml", tmp_path / "broken.toml"
    latin.write_bytes("# \xe9\n".encode("latin-1"))
    broken.write_text("[engine\n", encoding="utf-8")
    # a fuzz run (fuzz8): a document of an engine alone was 'error: (file): nothing to design: ...'
    engine = tmp_path / "engine.toml"
    engine.write_text(appendix_text().split("[valves")[0], encoding="utf-8")
    for path, line in [(missing, f"{missing}: cannot read the file: No such file or directory"),
                       (latin, f"{latin}: cannot read the file: not UTF-8 text (invalid continuation byte)"),
                       (engine, f"{engine}: nothing to design: give at least one [valves.NAME], [crank], [two_stroke] "
                                "or [breathing] section"),
                       (broken, None)]:
        with pytest.raises(SpecError) as err:
            load_spec(path)
        (record,) = error_records(err.value)
        assert record["path"] == str(path) and record["value"] is None
        assert record["text"] == (line or f"{broken}: {record['message']}")
    assert record["message"].startswith("not valid TOML: ")


@pytest.mark.parametrize("head, valves", [("", "[valves]\n"), ("valves = {}\n", "")])
def test_an_empty_valves_table_is_refused(refused, head, valves):
    """A hand test of the fuzz10 campaign: a file whose [valves] table names no valve (a student's valve tables
    left out under it) ran as a design of the crank alone and said "every allowable and physical limit is met"; it
    is refused, naming the table (a file without [valves] still designs its other sections)."""
    text = appendix_text()
    text = head + text[:text.index("[valves.intake]")] + valves + text[text.index("[gas]"):]
    assert refused(text, "run") == ("error: valves: an empty table: give each valve a [valves.NAME] table, or leave "
                                    "[valves] out for a design without valves\n")


def test_the_saved_specification_of_a_design_without_valves_reads_back():
    """spec.toml of a design without valves (examples/v8-crank.toml) is refused by no rule of the file it repeats:
    it leaves out the empty [valves] table, and reads back to the same specification."""
    from pathlib import Path

    from valvetrain.specification import load_spec, parse_spec, spec_toml

    spec = load_spec(Path(__file__).parents[2] / "examples" / "v8-crank.toml")
    text = spec_toml(spec)
    assert "[valves]" not in text
    assert parse_spec(text, source_dir=spec.source_dir) == spec


@pytest.mark.parametrize("old, new, line", [
    ("max_lift_mm = 10.0", "max_lift_mm = 10,5",
     "'max_lift_mm = 10,5'; a number's decimals follow a point, not a comma"),
    ("phi2_deg = 6.0\n", "phi2_deg = 6.0\nphi1_deg = 2.0\n", "'phi1_deg = 2.0'")])
def test_text_that_is_not_toml_is_refused_with_its_line(refused, old, new, line):
    """A fuzz10 hand test: a value with a decimal comma (max_lift_mm = 10,5) was refused as 'not valid TOML: Expected
    newline or end of document after a statement (at line 31, column 17)', the key and the value left to be found;
    the line is quoted, and a decimal comma named."""
    out = refused(appendix_with((old, new)))
    at = re.search(r"\(at line (\d+), column \d+\)", out)
    assert out.endswith(f"{at.group()}: {line}\n")
    assert appendix_with((old, new)).split("\n")[int(at.group(1)) - 1] == line.split("'")[1]


def test_parse_spec_takes_a_parsed_document():
    """parse_spec of the example's tables (as tomllib gives them) is the example; something else is a SpecError."""
    import tomllib

    import valvetrain as vt

    assert vt.parse_spec(tomllib.loads(example_text())) == vt.example_spec()
    with pytest.raises(vt.SpecError, match="TOML text or a dict of its tables, not a list"):
        vt.parse_spec([1, 2])
