"""The two-stroke port stage of a design (valvetrain.design.twostroke): a port given by its opening angle against the
series kinematics by hand, and the ports of the shipped two-stroke example against Valve-train practical works
(n.d.), work 8."""

import json
from pathlib import Path
from types import SimpleNamespace

from click.testing import CliRunner
import numpy as np
import pytest

from valvetrain.cli import main
from valvetrain.crank.kinematics import displacement
from valvetrain.design.twostroke import two_stroke_stage


def test_a_port_given_by_its_opening_angle_by_hand():
    """An exhaust port opening 60 deg before BDC, series kinematics, lambda = 30/120 = 0.25, S = 60 mm: at 120 deg from
    TDC x/R = (1 - cos 120) + lambda/4 (1 - cos 240) = 1.5 + 0.09375 = 1.59375, so sigma = 1 - x/S = 0.203125 (height
    12.1875 mm), below the recommended 0.26...0.28 (Table 8.1); fully open at BDC its area is width x height =
    30 x 12.1875 = 365.625 mm^2."""
    port = SimpleNamespace(kind="exhaust", height=None, opens_before_bdc=np.radians(60.0), width=0.030)
    ts = SimpleNamespace(speed=None, kinematics="series", step=np.radians(0.5), speed_range=None,
                         ports={"exhaust": port}, piston_height=0.05)
    eng = SimpleNamespace(bore=0.060, stroke=0.060, rod_length=0.120, rated_speed=5000 * np.pi / 30)
    result = two_stroke_stage(ts, None, eng)
    rec = result.figures.ports["exhaust"]
    assert rec.relative_height == pytest.approx(0.203125, rel=1e-12)
    assert np.degrees([rec.opens, rec.closes]) == pytest.approx([120.0, 240.0])
    assert rec.max_area == pytest.approx(365.625e-6, rel=1e-9)
    height, = [c for c in result.checks if c.code == "ports.height_to_stroke"]
    assert height.value == pytest.approx(0.203125) and (height.low, height.high) == (0.26, 0.28)


def test_two_stroke_example(tmp_path):
    path = Path(__file__).parents[2] / "examples" / "two-stroke-ports.toml"
    out = tmp_path / "ts"
    result = CliRunner().invoke(main, ["run", str(path), "--out", str(out)])
    assert result.exit_code == 0, result.output
    data = json.loads((out / "results.json").read_text())
    ports = data["two_stroke"]["ports"]
    ex = ports["exhaust"]
    # height 16.2 mm = 0.27 S, lambda = 30/120 = 0.25: opens 69.60 deg before BDC exactly (spec, work 8)
    assert ex["opens_before_bdc_deg"] == pytest.approx(69.60, abs=0.005)
    assert ex["opens_before_bdc_series_deg"] == pytest.approx(69.49, abs=0.005)
    # numerical time-area (exact kinematics) against K1 K2 / n (series kinematics): close, not equal
    assert ex["time_area_mm2_s"] == pytest.approx(ex["time_area_analytic_mm2_s"], rel=0.02)
    assert ports["transfer"]["opens_before_bdc_deg"] == pytest.approx(58.0)
    # inlet (8.4): the skirt edge (50 mm below the crown) passes the port's lower edge (73 mm) at s = 23 mm
    inlet = ports["inlet"]
    assert displacement(np.radians(inlet["closes_crank_deg"]), 0.030, 0.25) == pytest.approx(0.023, abs=1e-9)
    assert inlet["opens_crank_deg"] == pytest.approx(-inlet["closes_crank_deg"])
    for f in ("two_stroke_ports.csv", "two_stroke_time_area.csv"):
        assert (out / "tables" / f).is_file()
    assert "valves" in data and data["valves"] == {}


@pytest.mark.parametrize("change, edge", [(("lower_edge_mm = 73.0", "lower_edge_mm = 500.0"), "500"),
                                          (("lower_edge_mm = 73.0", "lower_edge_mm = 40.0"), "40"),
                                          (("piston_height_mm = 50.0", "piston_height_mm = 5.0"), "73")])
def test_an_inlet_port_the_skirt_never_passes_is_refused(refused, change, edge):
    """fuzz10 hand tests on examples/two-stroke-ports.toml: an inlet port whose lower edge the skirt never reaches
    (500 mm deep, or a piston of 5 mm) was open the whole revolution, one above the skirt at TDC (40 mm, the piston
    50 mm high) never opened: both ran without a failure.  The skirt's edge travels from piston_height_mm below the
    crown's TDC position to that plus the stroke (eq. 8.4: F = (h_in - S_p - h_p) b)."""
    text = (Path(__file__).parents[2] / "examples" / "two-stroke-ports.toml").read_text(encoding="utf-8")
    assert change[0] in text
    height = "5" if "5.0" in change[1] else "50"
    assert refused(text.replace(*change), "run") == (
        f"error: two_stroke.ports.inlet.lower_edge_mm = {edge}: allowed between piston_height_mm = {height} and "
        f"piston_height_mm + stroke = {int(height) + 60} mm, where the piston's skirt passes: else the port is never "
        "uncovered or never covered (Valve-train practical works (n.d.), eq. 8.4)\n")


def test_a_port_wider_than_the_cylinder_wall_is_refused(refused):
    """A fuzz10 hand test on examples/two-stroke-ports.toml: an exhaust port 200 mm wide in a 56 mm bore (whose wall
    is pi x 56 = 175.9 mm round) ran with a warning on width / bore."""
    text = (Path(__file__).parents[2] / "examples" / "two-stroke-ports.toml").read_text(encoding="utf-8")
    assert "width_mm = 12.3 " in text
    assert refused(text.replace("width_mm = 12.3 ", "width_mm = 200.0 "), "run") == (
        "error: two_stroke.ports.exhaust.width_mm = 200: allowed below the cylinder's circumference pi x bore = 175.9 "
        "mm (the port, or its group's summed width, is cut in the cylinder wall)\n")
