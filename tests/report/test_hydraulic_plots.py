"""The hydraulic drive's figures (report/hydraulic_plots.py): the lost-motion closings of examples/lost-motion-intake.toml
drawn in both languages."""

from pathlib import Path

from matplotlib.figure import Figure
import numpy as np
import pytest

from valvetrain.design import run
from valvetrain.report.hydraulic_plots import lost_motion_data, lost_motion_figure
from valvetrain.report.i18n import TEXT
from valvetrain.specification import load_spec
from valvetrain.units import MM

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "lost-motion-intake.toml"


@pytest.fixture(scope="module")
def valve():
    return run(load_spec(EXAMPLE)).valves["intake"]


def test_the_lost_motion_figure_has_a_curve_a_closing(valve):
    """One run of the full lift and one a solenoid timing, each lift the stage's own response (the data are the
    records, not recomputed); an early closing never lifts the valve above the full lift (the solenoid only lets oil
    out of the pump chamber).  Drawn in English and Russian (the merge of the lost-motion figure into the split
    report/plots.py left it calling a function renamed by the split: it raised NameError)."""
    d = lost_motion_data(valve)
    lm = valve.lost_motion
    assert [at for at, _, _ in d["runs"]][1:] == pytest.approx([np.degrees(c.solenoid_opens) for c in lm.closings])
    full = d["runs"][0][1]
    assert full.max() == pytest.approx(lm.full.valve_lift.max() / MM)
    for _, lift, _ in d["runs"][1:]:
        assert lift.max() <= full.max() * (1.0 + 1e-9)
    for lang in ("en", "ru"):
        assert isinstance(lost_motion_figure(valve, TEXT[lang]), Figure)
