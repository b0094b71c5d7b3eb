"""The designer's panel of variable valve actuation (web/vva.py) without a browser: a lost-motion drive's lift of
each solenoid timing and a switching finger's modes, shown where the specification has them, their keys in the
panel, redrawn after an edit."""

import math
from pathlib import Path
import tomllib

import pytest
import tomli_w

pytest.importorskip("bokeh")

from designer_page import _designer, _field  # noqa: E402

EXAMPLES = Path(__file__).parents[2] / "examples"


def _example(name, edit):
    path = EXAMPLES / name
    document = tomllib.loads(path.read_text(encoding="utf-8"))
    edit(document)
    return _designer(tomli_w.dumps(document), path.parent)


def _rows(d, item):
    data = d.vva_rows.data
    return {q: v for i, q, v in zip(data["item"], data["quantity"], data["value"], strict=True) if i == item}


def test_a_lost_motion_drive_shows_the_lift_of_each_solenoid_timing():
    # issue 42: "each in the designer where it applies"; examples/lost-motion-intake.toml with one timing and
    # without its breathing
    def one(document):
        document["valves"]["intake"]["hydraulic"]["lost_motion"]["solenoid_opens_crank_deg"] = [60.0]
        del document["breathing"]

    d = _example("lost-motion-intake.toml", one)
    assert [p.title for p in d.plot_tabs.tabs][-1] == "Lost motion, switching"
    assert d.vva.data["label"] == ["intake: full lift (solenoid valve shut)",
                                   "intake: solenoid valve opens at 60 crank deg"]
    closing = d.session.good["results"]["valves"]["intake"]["lost_motion"]["closings"][0]
    at_60 = _rows(d, "intake: solenoid valve opens at 60 crank deg")
    assert at_60["landing velocity, m/s"] == f"{closing['seating_velocity_m_s']:.4g}"
    # the lift drawn is the run's: its largest the record's largest valve lift (thinned, 32-bit: to 1e-6)
    assert max(d.vva.data["ys"][1]) == pytest.approx(closing["valve_lift_mm"], rel=1e-6)
    # its keys in the panel's group, an edit redrawn: the solenoid valve opened 30 deg later closes the valve later
    f = _field(d, "valves.intake.hydraulic.lost_motion.solenoid_opens_crank_deg")
    d.on_field(f, "value", "60.0", "90.0")
    assert d.vva.data["label"][1] == "intake: solenoid valve opens at 90 crank deg"
    later = _rows(d, "intake: solenoid valve opens at 90 crank deg")
    assert float(later["valve closes, crank deg"]) > float(at_60["valve closes, crank deg"])


def test_a_switching_finger_shows_its_modes_and_follows_an_edit():
    # examples/switching-finger.toml, the exhaust without its [switching] section and a short sweep of the arm
    def intake_only(document):
        del document["valves"]["exhaust"]["switching"]
        document["valves"]["intake"]["switching"]["speeds"] = 4

    d = _example("switching-finger.toml", intake_only)
    assert d.vva.data["label"] == ["intake: latched", "intake: unlatched"]
    assert "valves.intake.switching.inner_arm_inertia_kg_mm2" in d.widgets
    assert not any(path.startswith("valves.exhaust.switching") for path in d.widgets)
    assert _rows(d, "intake: unlatched")["valve lift unlatched, mm"] == "0"
    d.on_field(_field(d, "valves.intake.switching.inner_arm_inertia_kg_mm2"), "value", 3.6, 5.0)
    record = d.session.good["results"]["switching"]["intake"]
    # the arm's natural frequency on its spring by hand, f = sqrt(k / J) / (2 pi) (Norton (2009), a one-mass
    # oscillator) with the edited J = 5 kg mm^2 and the spring's rate from the record
    hand = math.sqrt(record["spring_rate_Nm_per_rad"] / 5.0e-6) / (2.0 * math.pi)
    shown = _rows(d, "intake: unlatched")["the arm's natural frequency on its spring, Hz"]
    assert float(shown) == pytest.approx(hand, rel=1e-3)
