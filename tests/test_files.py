"""Reading the input files (valvetrain.files): indicator diagrams (p-phi and p-V) and lift tables, their line-numbered
refusals and the values no cylinder or valve can have."""

import re

import numpy as np
import pytest

from valvetrain.crank import pressure
from valvetrain.files import (BreathingFileError, TableFileError, read_cd_table, read_indicator, read_lift_table,
                              read_valve_lift)


def test_p_phi_file_round_trip(tmp_path):
    phi = np.radians(np.arange(0.0, 720.0, 0.5))
    p = 0.1e6 + 6e6 * np.exp(-((phi - 2 * np.pi) / 0.3) ** 2)     # any diagram: a combustion peak at the firing TDC
    f = tmp_path / "ind.csv"
    f.write_text("# a comment\ncrank_deg,pressure_MPa\n" + "".join(f"{np.degrees(a):.6f},{b / 1e6:.9f}\n"
                                                                 for a, b in zip(phi, p)))
    t = read_indicator(f, 4)
    assert t.kind == "angle"
    assert np.allclose(pressure.on_grid(t.x, t.pressure, phi, 4), p, rtol=1e-8)


BAD = [
    ("crank_deg;pressure_MPa\n0;0.1\n", "ind.csv:1: header"),
    ("crank_deg,pressure_MPa\n0,0.1\n10,abc\n", "ind.csv:3: '10,abc' is not two numbers"),
    ("crank_deg,pressure_MPa\n0,0.1\n10,0.2\n5,0.3\n20,0.1\n", "ind.csv:4: crank_deg = 5 must be larger"),
    ("crank_deg,pressure_MPa\n0,0.1\n800,0.2\n", "ind.csv:3: crank_deg = 800: allowed [0, 720]"),
    ("crank_deg,pressure_MPa\n0,0.1\n10,-0.2\n", "ind.csv:3: pressure_MPa = -0.2"),
    ("crank_deg,pressure_MPa\n0,0.1\n10,0.2,3\n", "ind.csv:3: '10,0.2,3' has 3 values; allowed 2"),
    ("crank_deg,pressure_MPa\n0,0.1\n", "at least 4 data rows"),
]


@pytest.mark.parametrize("text,message", BAD)
def test_bad_files_name_the_line(tmp_path, text, message):
    f = tmp_path / "ind.csv"
    f.write_text(text)
    with pytest.raises(pressure.PressureFileError, match=message.replace("[", r"\[").replace("]", r"\]")):
        read_indicator(f, 4)


def _scaled_rows(header, rows, factor, at):
    """A file of ``rows`` with row ``at`` (0-based) multiplied by ``factor``."""
    return header + "\n" + "".join(f"{x:g},{y * factor if i == at else y:g}\n" for i, (x, y) in enumerate(rows))


INDICATOR_ROWS = [(0, 0.1), (180, 0.1), (360, 6.0), (540, 0.3), (700, 0.11)]


@pytest.mark.parametrize("header,at,factor,message", [
    # issue 21 nonsense 6: a pressure file scaled by 1e300 (p_max 6e300 MPa) was accepted
    ("crank_deg,pressure_MPa", 2, 1e300, "ind.csv:4: pressure_MPa = 6e+300: allowed [0.001, 100] (an absolute cylinder "
                                         "pressure)"),
    ("crank_deg,pressure_MPa", 2, 1e3, "ind.csv:4: pressure_MPa = 6000: allowed [0.001, 100]"),   # kPa read as MPa
    ("volume_cm3,pressure_MPa", 0, 1e300, "ind.csv:2: pressure_MPa = 1e+299: allowed [0.001, 100]"),
])
def test_pressure_values_outside_any_cylinder_are_refused(tmp_path, header, at, factor, message):
    f = tmp_path / "ind.csv"
    rows = INDICATOR_ROWS if header.startswith("crank") else [(50 + 10 * i, p) for i, (_, p) in enumerate(INDICATOR_ROWS)]
    f.write_text(_scaled_rows(header, rows, factor, at))
    with pytest.raises(pressure.PressureFileError, match=re.escape(message)):
        read_indicator(f, 4)


def test_a_volume_outside_any_cylinder_is_refused(tmp_path):
    f = tmp_path / "ind.csv"
    f.write_text("volume_cm3,pressure_MPa\n50,0.1\n500,0.2\n5e9,0.3\n60,4\n")
    with pytest.raises(pressure.PressureFileError, match=re.escape("ind.csv:4: volume_cm3 = 5e+09: allowed [0, 1e+08]")):
        read_indicator(f, 4)


@pytest.mark.parametrize("column,factor,message", [
    ("lift", 1e300, "lift.csv:{line}: lift_mm = 1e+301: allowed [-500, 500]"),
    ("lift", 1e3, "lift.csv:{line}: lift_mm = 10000: allowed [-500, 500]"),     # metres read as millimetres
    ("angle", 1e300, "lift.csv:{line}: angle_deg = 4e+302: allowed [-3600, 3600]"),
])
@pytest.mark.parametrize("comment", ["", "# a comment line keeps the file off numpy's fast path\n"])
def test_lift_table_values_outside_any_valve_are_refused(tmp_path, column, factor, message, comment):
    """Both readers of a lift table (numpy's for a plain file, the line-by-line one) name the same line."""
    rows = [(-60.0 + 10.0 * i, 10.0 * np.sin(np.pi * i / 12) ** 2) for i in range(13)]
    rows[-1] = (400.0 if column == "angle" else rows[-1][0], rows[-1][1])
    text = "".join(f"{a * (factor if column == 'angle' and i == 12 else 1):g},"
                   f"{y * (factor if column == 'lift' and i == 6 else 1):g}\n" for i, (a, y) in enumerate(rows))
    f = tmp_path / "lift.csv"
    f.write_text(comment + "angle_deg,lift_mm\n" + text)
    line = (14 if column == "angle" else 8) + (1 if comment else 0)
    with pytest.raises(TableFileError, match=re.escape(message.format(line=line))):
        read_lift_table(f)


@pytest.mark.parametrize("row, values", [("-70,0;0,0000", 3), ("-70,0\t0,0000", 3), ("-70,5,1,25", 4)])
def test_a_decimal_comma_is_named_as_such(tmp_path, row, values):
    """A hand test of the fuzz10 campaign: a lift table written with commas as decimal separators (a spreadsheet's
    export in a language that writes 1,5) was refused as 'expected 2 values, found 3', naming neither the row nor
    what the file should hold; the message echoes the row and says the separators."""
    f = tmp_path / "lift.csv"
    f.write_text(f"angle_deg,lift_mm\n{row}\n", encoding="utf-8")
    with pytest.raises(TableFileError) as err:
        read_lift_table(f)
    assert str(err.value) == (f"{f}:2: {row!r} has {values} values; allowed 2 (angle_deg,lift_mm), separated by "
                              "commas, with a point as the decimal separator")


def test_a_byte_order_mark_is_dropped(tmp_path):
    """A hand test of the fuzz10 campaign: a lift table saved as a spreadsheet's "CSV UTF-8" (a UTF-8 byte-order
    mark first) was refused as "header '\\ufeffangle_deg,lift_mm'"; it reads as the same file without the mark, a
    lift table (numpy's reader) and an indicator diagram (the line-by-line one) alike."""
    lift = "angle_deg,lift_mm\n" + "".join(f"{a},{10.0 * np.sin(np.pi * i / 12) ** 2:.6f}\n"
                                           for i, a in enumerate(range(-60, 70, 10)))
    indicator = "crank_deg,pressure_MPa\n" + "".join(f"{a},{p}\n" for a, p in INDICATOR_ROWS)

    def columns(read, f):
        table = read(f)
        return [np.asarray(c).tolist() for c in (table if isinstance(table, tuple) else (table.x, table.pressure))]

    for text, read in [(lift, read_lift_table), (indicator, lambda f: read_indicator(f, 4))]:
        plain, marked = tmp_path / "plain.csv", tmp_path / "marked.csv"
        plain.write_text(text, encoding="utf-8")
        marked.write_bytes(b"\xef\xbb\xbf" + text.encode("utf-8"))
        assert columns(read, marked) == columns(read, plain)


def test_valve_lift_and_cd_files(tmp_path):
    """The breathing's files: a lift in crank deg from the gas-exchange TDC and a C_D table of one or two columns;
    what cannot be used is refused naming the line and the key that names the file."""
    lift = tmp_path / "lift.csv"
    lift.write_text("# measured\ncrank_deg,lift_mm\n-20,0\n0,1.5\n100,8\n240,0\n", encoding="utf-8")
    angles, lifts = read_valve_lift(lift)
    assert list(angles) == [-20, 0, 100, 240] and lifts[2] == 8.0
    cd = tmp_path / "cd.csv"
    cd.write_text("l_over_d,cd\n0,0\n0.1,0.4\n0.3,0.7\n", encoding="utf-8")
    x, forward, reverse = read_cd_table(cd)
    assert list(forward) == list(reverse) == [0.0, 0.4, 0.7]
    for path, text, key, message in [
            (lift, "crank_deg,lift_mm\n0,0\n10,1\n10,2\n30,0\n", "lift_file", r"lift.csv:4: crank_deg = 10 must be "
             "larger than the previous 10"),
            (lift, "crank_deg,lift_mm\n0,0\n10,-1\n20,2\n30,0\n", "lift_file", r"lift.csv:3: lift_mm = -1: allowed"),
            (lift, "crank_deg,lift_mm\n0,0\n300,1\n600,2\n720,0\n", "lift_file", r"span 720 crank deg"),
            (cd, "l_over_d,cd_forward,cd_reverse\n0,0,0\n0.1,0.4\n", "cd_file",
             r"cd.csv:3: '0.1,0.4' has 2 values; allowed 3"),
            (cd, "l_over_d,cd\n0,0\n0.1,1.2\n", "cd_file", r"row 2: forward C_D = 1.2; allowed 0 to 1")]:
        path.write_text(text, encoding="utf-8")
        with pytest.raises(BreathingFileError, match=message) as caught:
            (read_valve_lift if key == "lift_file" else read_cd_table)(path)
        assert caught.value.key == key


def test_a_file_that_never_ends_is_refused(monkeypatch):
    """A fuzz run (fuzz8): cam.table_file = "/dev/zero" (or FILE /dev/zero) read until the machine's memory ran out,
    a MemoryError traceback; reading stops after MAX_FILE_CHARACTERS (made small here) and names the file."""
    from valvetrain import files
    from valvetrain.specification import SpecError, load_spec

    monkeypatch.setattr(files, "MAX_FILE_CHARACTERS", 1000)
    with pytest.raises(TableFileError, match=r"^/dev/zero: cannot read the file: over 1,000 characters, more than a "
                                             r"specification or a table holds$"):
        read_lift_table("/dev/zero")
    with pytest.raises(SpecError) as err:
        load_spec("/dev/zero")
    assert err.value.problems == ["/dev/zero: cannot read the file: over 1,000 characters, more than a specification "
                                  "or a table holds"]
