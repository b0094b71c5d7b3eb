"""The pivot ball of a stud-mounted rocker (valvetrain.links.rocker_pivot): the fulcrum load of a lever of the first
kind and the ball's contact stress in its seat against a hand calculation of Valve-train practical works (n.d.),
eqs. (7.11)/(7.14), silent for a rocker on a shaft; in a design of the appendix example (a pushrod layout)."""

from types import SimpleNamespace

import pytest

from valvetrain.links import RockerPivot
from valvetrain.links.rocker_pivot import fulcrum_load
from valvetrain.report.names import translate
from valvetrain.specification import SpecError

from appendix import appendix_design
from link_loads import loads


def parts(ball=0.008, seat=0.0085):
    return SimpleNamespace(rocker_pivot_ball_radius=ball, rocker_pivot_seat_radius=seat)


def test_the_fulcrum_carries_both_arms_forces():
    """R = P_T + P_v with P_v = P_T / i_k (the moments about the fulcrum balance): 1000 + 625 N at i_k = 1.6."""
    assert fulcrum_load(1000.0, 1.6) == pytest.approx(1000.0 + 1000.0 * 1.0 / 1.6, rel=1e-15)


def test_the_ball_s_contact_stress_by_hand():
    """sigma = 0.388 (R E^2 (1/r_1 - 1/r_2)^2)^(1/3) with R = 1625 N, E = 2.1e5 MPa, r_1 = 8 mm, r_2 = 8.5 mm:
    (1/8 - 1/8.5) mm^-1 = 7.353 m^-1, so sigma = 609.4 MPa (hand calculation), within 2000 MPa."""
    made, notes = loads(parts(), cam_force=1000.0, rocker_ratio=1.6)
    (c,) = RockerPivot().checks(made)
    assert c.code == "strength.rocker_pivot_stress" and c.value == pytest.approx(609.40e6, rel=1e-4)
    assert c.high == 2000e6 and c.passed and notes == []


def test_a_rocker_on_a_shaft_has_no_pivot_ball_and_half_a_pivot_is_named():
    assert RockerPivot().checks(loads(parts(None, None))[0]) == []
    made, notes = loads(parts(seat=None))
    assert RockerPivot().checks(made) == [] and notes == ["rocker_pivot_stress: not checked"]


def test_the_pushrod_train_checks_its_pivot_ball_and_refuses_a_seat_no_larger():
    """The appendix example (tappet, pushrod, rocker) with a pivot ball: the check in the design's strength record
    under the largest cam force (its own record) and the rocker ratio 1.6 of the example; a seat no larger than the
    ball is refused naming both keys.  A finger's section given to its flat follower is a warning of the results
    naming the key and the layout (no part reads it: it was ignored without a word).  A valve bridge (its span and
    section given) joins the chain: its bending check under twice the valve force at mid-span, M = 2 F_v l / 4 on
    W = b h^2 / 6 (Shigley (2011), Table A-9; valvetrain.links.bridge)."""
    design = appendix_design(valves__intake__parts__rocker_pivot_ball_radius_mm=8.0,
                             valves__intake__parts__rocker_pivot_seat_radius_mm=8.5,
                             valves__intake__parts__finger_section_width_mm=6.0,
                             valves__intake__parts__bridge_span_mm=40.0, valves__intake__parts__bridge_width_mm=14.0,
                             valves__intake__parts__bridge_height_mm=12.0)
    (unused,) = [w for w in design.to_dict()["warnings"] if w["code"] == "parts.unused_key"]
    assert unused["params"] == {"key": "finger_section_width_mm", "layout": "pushrod"}
    assert unused["severity"] == "warning" and unused["quantity"] == ("intake: parts of the pushrod layout that read "
                                                                      "[parts] finger_section_width_mm")
    strength = design.valves["intake"].drive.strength
    (bridge,) = [c for c in strength.checks if c.code == "strength.bridge_bending"]
    assert bridge.value == pytest.approx(2.0 * strength.valve_force_max * 0.040 / 4.0 / (0.014 * 0.012**2 / 6.0),
                                         rel=1e-9)
    (c,) = [c for c in strength.checks if c.code == "strength.rocker_pivot_stress"]
    expected = 0.388 * (fulcrum_load(strength.cam_force_max, 1.6) * 2.1e11**2 * (1 / 0.008 - 1 / 0.0085)**2)**(1 / 3)
    assert c.value == pytest.approx(expected, rel=1e-9)
    with pytest.raises(SpecError, match="rocker_pivot_seat_radius_mm = 8 must exceed rocker_pivot_ball_radius_mm = 8"):
        appendix_design(valves__intake__parts__rocker_pivot_ball_radius_mm=8.0,
                        valves__intake__parts__rocker_pivot_seat_radius_mm=8.0)


def test_a_seat_that_conforms_to_the_ball_has_no_stress_from_the_formula():
    """A seat of 8.0001 mm on the 8 mm ball: the formula gives 2.17 MPa under R = 1625 N, which Hertz's contact could
    carry only over a circle of radius a = sqrt(3 R / (2 pi sigma)) = 18.9 mm (its mean pressure R / (pi a^2) is 2/3
    of the peak; hand calculation), wider than the ball: the stress cannot be evaluated (a failure, the reason named)
    instead of a pass (before: 2.17 MPa against 2000 MPa, passed)."""
    made, _ = loads(parts(seat=0.0080001), cam_force=1000.0, rocker_ratio=1.6)
    (c,) = RockerPivot().checks(made)
    assert not c.evaluated and not c.passed and c.severity == "failure"
    assert c.unevaluated == ("the socket conforms to the ball: Hertz's contact circle of 18.9 mm radius would be "
                             "wider than the ball of 8 mm radius")
    assert translate(c.unevaluated, "ru") == ("опора прилегает к шару: круг контакта по Герцу радиусом 18,9 мм был бы "
                                              "шире шара радиусом 8 мм")
