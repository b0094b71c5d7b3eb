"""The crank chapter of a design run (valvetrain.design.crank), the two-stroke crank torque, and user pressure files
through the CLI (the two-stroke ports: tests/design/test_twostroke.py)."""

from pathlib import Path

from click.testing import CliRunner
import numpy as np
import pytest

from valvetrain.cli import main
from valvetrain.crank import pressure
from valvetrain.design import run
from valvetrain.specification import load_spec, parse_spec

from appendix import appendix_text, appendix_spec

CRANK_KEYS = ["max_velocity_m_s", "max_acceleration_m_s2", "min_acceleration_m_s2", "mean_torque_Nm",
              "max_torque_Nm", "min_torque_Nm", "nonuniformity"]


@pytest.fixture(scope="module")
def example():
    return run(appendix_spec())


def test_example_crank_chapter(example):
    c = example.to_dict()["crank"]
    for key in CRANK_KEYS:
        assert np.isfinite(c[key]), key
    # j_max = omega^2 R (1 + lambda) exactly (1.10); lambda = 38.5714 / 135
    omega, R = np.pi * 7000 / 30, 0.077142857 / 2
    assert c["max_acceleration_m_s2"] == pytest.approx(omega**2 * R * (1 + R / 0.135), rel=1e-9)
    # mean torque = i W_i / (4 pi) (spec section 5), to the 1-deg grid's accuracy
    assert abs(c["torque_work_balance"]) < 2e-4
    assert c["firing_angles_deg"] == [0.0, 540.0, 180.0, 360.0]
    assert c["torque_period_deg"] == pytest.approx(180.0)


def test_crank_tables(tmp_path):
    out = tmp_path / "d"
    assert CliRunner().invoke(main, ["run", "--out", str(out), "--figures", "all"]).exit_code == 0
    header = (out / "tables" / "crank.csv").read_text().splitlines()[0].split(",")
    for col in ["crank_deg", "s_mm", "v_m_s", "j_m_s2", "p_gas_MPa", "p_j_MPa", "p_MPa", "p_N_MPa", "p_S_MPa",
                "p_K_MPa", "p_T_MPa", "T_N", "M_cyl_Nm", "pin_radial_N", "pin_tangential_N"]:
        assert col in header
    rows = np.loadtxt(out / "tables" / "crank.csv", delimiter=",", skiprows=1)
    s_mm, p_t, t_n = (rows[:, header.index(c)] for c in ("s_mm", "p_T_MPa", "T_N"))
    # the piston travels the example's stroke, 77.142857 mm (central mechanism: s(180 deg) = 2R)
    assert s_mm.max() == pytest.approx(77.142857, rel=1e-6)
    # T = p_T x piston area (Power units manual (n.d.)), in N from MPa and mm2
    assert t_n == pytest.approx(p_t * np.pi * 80.0**2 / 4.0, rel=1e-9, abs=1e-6)
    torque_header = (out / "tables" / "engine_torque.csv").read_text().splitlines()[0].split(",")
    assert torque_header == ["crank_deg", "M_total_Nm", "M_cyl1_Nm", "M_cyl2_Nm", "M_cyl3_Nm", "M_cyl4_Nm"]
    for plot in ("crank_forces.png", "crank_torque.png", "crank_pin_polar.png"):
        assert (out / "plots" / plot).stat().st_size > 0


def _spec_with_pressure_file(tmp_path, rows, header="crank_deg,pressure_MPa"):
    (tmp_path / "ind.csv").write_text(header + "\n" + "".join(f"{a},{b}\n" for a, b in rows))
    text = appendix_text().replace('# pressure_file = "indicator.csv"', 'pressure_file = "ind.csv"')
    start, end = text.index("[crank.cycle]"), text.index("[output]")
    (tmp_path / "engine.toml").write_text(text[:start] + text[end:])
    return tmp_path / "engine.toml"


def test_user_p_phi_file_is_used(tmp_path, example):
    phi = np.arange(0.0, 720.0, 2.0)
    p = example.crank.columns.p_abs[::2] / 1e6
    spec_file = _spec_with_pressure_file(tmp_path, zip(phi, p))
    res = run(load_spec(spec_file))
    assert "p-phi diagram" in res.crank.summary["pressure_source"]
    # the same pressure on a coarser table: the mean torque agrees to the interpolation error
    assert res.crank.summary["mean_torque_Nm"] == pytest.approx(example.crank.summary["mean_torque_Nm"], rel=5e-3)


def test_user_p_v_file_is_used(tmp_path, example):
    c = example.crank
    v = pressure.cylinder_volume(c.phi, 0.08, 0.077142857 / 2, 0.077142857 / 2 / 0.135, 10.0)
    spec_file = _spec_with_pressure_file(tmp_path, zip(v * 1e6, c.columns.p_abs / 1e6), "volume_cm3,pressure_MPa")
    res = run(load_spec(spec_file))
    assert "p-V diagram" in res.crank.summary["pressure_source"]
    assert res.crank.summary["indicated_work_J"] == pytest.approx(c.summary["indicated_work_J"], rel=5e-3)


def test_bad_pressure_file_is_refused_with_its_line(tmp_path):
    spec_file = _spec_with_pressure_file(tmp_path, [(0, 0.1), (10, 0.2), ("x", 0.3), (30, 0.1)])
    out = tmp_path / "out"
    result = CliRunner().invoke(main, ["run", str(spec_file), "--out", str(out)])
    assert result.exit_code == 2
    assert "crank.pressure_file:" in result.output and "ind.csv:4:" in result.output
    assert not out.exists()


def test_missing_pressure_source_is_refused(refused):
    text = appendix_text()
    start, end = text.index("[crank.cycle]"), text.index("[output]")
    assert "give pressure_file" in refused(text[:start] + text[end:])


def test_v8_example():
    res = run(load_spec(__import__("pathlib").Path(__file__).parents[2] / "examples" / "v8-crank.toml"))
    c = res.crank.summary
    assert c["even_firing"] is True
    assert c["torque_period_deg"] == pytest.approx(90.0)
    # V engine, two rods per pin: m_R = m_k + 2 m_sh.k (2.10)
    m = c["masses"]
    assert m["rotating_kg"] == pytest.approx(m["crank_kg"] + 2 * m["rod_at_crank_kg"])
    assert abs(c["torque_work_balance"]) < 2e-4


def test_two_stroke_crank_torque(tmp_path):
    """A two-cylinder two-stroke: cycle 360 deg, even firing every 180 deg (theta = 180 tau / i, eq. 2.22)."""
    text = "\n".join([
        '[engine]', 'bore_mm = 56.0', 'stroke_mm = 60.0', 'rated_speed_rpm = 6000', 'cylinders = 2', 'strokes = 2',
        '[crank]', 'rod_length_mm = 120.0', 'compression_ratio = 8.0', 'piston_kg = 0.2', 'rod_kg = 0.15',
        'crank_kg = 0.1', '[crank.cycle]', 'heat_input_J = 250.0', ''])
    f = tmp_path / "ts.toml"
    f.write_text(text)
    c = run(load_spec(f)).crank
    assert c.phi[-1] == pytest.approx(np.radians(359.0))
    assert c.summary["torque_period_deg"] == pytest.approx(180.0)
    assert c.summary["firing_angles_deg"] == [0.0, 180.0]
    assert abs(c.summary["torque_work_balance"]) < 2e-4


UNITS = ("_deg", "_mm", "_mm2", "_mm2_s", "_m_s", "_m_s2", "_m_s3", "_MPa", "_N", "_Nm", "_rpm")

UNITLESS = ("epsilon", "bounce_count", "jump", "revolutions")
"""The columns of a number without a unit, of the dynamics sweep: the ratio M omega^2 / (c + K), two counts and a
flag ("segment" and "load" are the two text columns)."""


def test_every_table_names_its_unit(tmp_path):
    """Issue 10: every CSV table of the output folder is in mm, deg, MPa and N (m/s, m/s2 for speeds and
    accelerations, as the lift table) and names the unit of each column in its header."""
    out = tmp_path / "d"
    assert CliRunner().invoke(main, ["run", "--out", str(out)]).exit_code == 0
    files = sorted((out / "tables").glob("*.csv")) + sorted((out / "contour").glob("*.csv"))
    assert len(files) >= 6
    for f in files:
        header = next(line for line in f.read_text().splitlines() if not line.startswith("#")).split(",")
        for col in header:
            assert col in ("segment", "load") or col.endswith(UNITS) or col in UNITLESS, (f.name, col)
        assert not any(col.endswith(("_m", "_kN")) for col in header), f.name


def _wiebe(**timing):
    """The example's Wiebe cycle (compression ratio 10, 950 J, 80 x 77.142857 mm, rod 135 mm) with valve angles."""
    cycle = pressure.WiebeCycle(10.0, 950.0, **timing)
    return lambda deg: pressure.wiebe_pressure(np.radians(deg), cycle, 0.08, 0.0385714285, 0.0385714285 / 0.135, 4)


def test_the_wiebe_pressure_is_continuous():
    """Issue 10: no step anywhere in the cycle, with the valves at the dead centres and at the example's timing
    (intake -26...258, exhaust 474...-10 crank deg from the gas-exchange TDC): refining the grid tenfold divides the
    largest change between neighbouring points by ten (a step would keep it), and no change exceeds 0.2 MPa per
    degree (the combustion's steepest rise is 0.18 MPa per degree)."""
    timed = dict(intake_closes=np.radians(258.0 - 360.0), intake_opens=np.radians(-26.0),
                 exhaust_opens=np.radians(474.0 - 360.0), exhaust_closes=np.radians(10.0))
    for p in (_wiebe(), _wiebe(**timed)):
        coarse, fine = (np.abs(np.diff(p(np.arange(0.0, 720.0001, step)))).max() for step in (0.1, 0.01))
        assert fine < 0.12 * coarse
        assert coarse < 0.2e6 * 0.1


def test_the_blowdown_follows_the_exhaust_opening():
    """Issue 10: the pressure leaves the closed cycle's expansion at the exhaust opening: opening at 500 instead of
    540 crank deg, it equals the other's pressure up to 500 and lies below it from there, and reaches the exhaust
    pressure 40 deg earlier (at the end of the 60 deg blowdown)."""
    early, late = _wiebe(exhaust_opens=np.radians(140.0)), _wiebe()
    before = np.arange(400.0, 500.0, 1.0)
    assert early(before) == pytest.approx(late(before), rel=1e-12)
    assert np.all(early(np.arange(502.0, 600.0, 2.0)) < late(np.arange(502.0, 600.0, 2.0)))
    assert early(np.array([560.0, 600.0])) == pytest.approx([0.11e6, 0.11e6])
    assert late(np.array([560.0]))[0] > 0.2e6


def test_the_example_cycle_uses_its_valve_timing():
    """The built-in example's pressure: the intake pressure up to the intake valve's closing at 258 crank deg
    (compression starts there, not at BDC), and the source names the timing."""
    crank = run(appendix_spec()).crank
    p = crank.columns.p_abs
    deg = np.degrees(crank.phi)
    assert np.all(p[(deg > 30.0) & (deg <= 257.0)] == 0.09e6)
    assert p[deg == 270.0][0] > 0.1e6
    assert "compression from the intake valve's closing" in crank.pressure_source
    assert "intake valve -26...258" in crank.pressure_source


def test_a_cycle_that_absorbs_work_is_a_warning():
    """The V8 example with almost no heat (0.01 J) and a 10 MPa exhaust stroke against a 0.09 MPa intake is a pump:
    its mean torque is negative and the check, the mean torque over the largest torque, says so (a warning: a motored
    engine is legal input).  Hand estimate:
    the pumping loop alone, -(p_e - p_i) V_h i / (4 pi) = -(10 - 0.09) MPa x 571.7 cm3 x 8 / (4 pi) = -3607 N m,
    ignoring the compression-expansion loop and the pressure's transitions at the dead centres (found -3390 N m); the
    example's own cycle delivers work and passes."""
    text = (Path(__file__).parents[2] / "examples" / "v8-crank.toml").read_text(encoding="utf-8")
    pump = text.replace("heat_input_J = 1400.0", "heat_input_J = 0.01\nexhaust_pressure_MPa = 10.0")
    displaced = np.pi / 4 * 0.092**2 * 0.086
    for spec, passed in ((text, True), (pump, False)):
        design = run(parse_spec(spec))
        found = [c for c in design.checks if c.code == "crank.mean_torque"]
        assert len(found) == 1 and found[0].severity == "warning" and found[0].passed is passed
        assert -1.0 <= found[0].value <= 1.0, "a share of the largest torque"
    assert design.crank.figures.mean_torque == pytest.approx(-(10 - 0.09) * 1e6 * displaced * 8 / (4 * np.pi), rel=0.1)
