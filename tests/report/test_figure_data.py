"""The dynamics, grinding and hydraulic-actuation figures are their data and their drawing (report/plots.py): the data
are plain numbers and arrays, the same as results.json's, and the drawing takes them alone."""

from pathlib import Path

from matplotlib.figure import Figure
import pytest

from conftest import plain
from valvetrain.design import run
from valvetrain.report import plots
from valvetrain.report.i18n import TEXT
from valvetrain.specification import load_spec

EXAMPLES = Path(__file__).parents[2] / "examples"


def _drawn(data, draw):
    assert plain(data), draw.__name__
    assert isinstance(draw(data, TEXT["en"]), Figure)


@pytest.fixture(scope="module")
def designs():
    return {name: run(load_spec(EXAMPLES / name)) for name in
            ("pushrod-dynamics.toml", "seed000-polydyne.toml", "marine-hydraulic-exhaust.toml")}


def test_dynamics_figures(designs):
    v = designs["pushrod-dynamics.toml"].valves["intake"]
    record = v.summary["dynamics"]
    speed = plots.dynamics_speed_data(v.name, v.dynamics)
    _drawn(speed, plots.draw_dynamics_speed)
    _drawn(plots.dynamics_map_data(v.name, v.dynamics), plots.draw_dynamics_map)
    # the marked speeds are results.json's (a speed not reached is null there and no mark here)
    assert [speed["jump_rpm"], speed["bounce_rpm"]] == pytest.approx(
        [record["jump_speed_rpm"], record["bounce_speed_rpm"]], rel=1e-12, nan_ok=True)
    assert speed["rpm"] == pytest.approx(record["per_speed"]["speed_rpm"], rel=1e-12)


def test_grinding_figure(designs):
    v = designs["seed000-polydyne.toml"].valves["intake"]
    data = plots.grinding_data(v)
    _drawn(data, plots.draw_grinding)
    assert data["wheel_wear_mm"] == pytest.approx(v.summary["grinding"]["wheel_wear_mm"], rel=1e-12)


def test_hydraulic_figures(designs):
    v = designs["marine-hydraulic-exhaust.toml"].valves["exhaust"]
    record = v.summary["hydraulic"]
    data = plots.hydraulic_data(v)
    _drawn(data, plots.draw_hydraulic)
    sweep = plots.hydraulic_sweep_data(v)
    _drawn(sweep, plots.draw_hydraulic_sweep)
    assert data["stop_mm"] == pytest.approx(record["stop_mm"], rel=1e-12)
    assert sweep["simulated_rpm"] == pytest.approx(record["speed_rpm"], rel=1e-12)
