"""Tables of a design in the units engineers read (tables.py), for the built-in example (pushrod drive, rocker ratio
1.6, clearance 0.25 mm, heel radius 19.75 mm, stroke 77.142857 mm, four cylinders), against relations written out by
hand: the valve lift i_k max(h - h0, 0), crank angle = 2 x camshaft angle for a four-stroke (Valve-train practical
works (n.d.), work 1), the contour's nose and heel radii, rpm = 30 omega / pi."""

import math

import numpy as np
import pytest

from valvetrain import tables
from valvetrain.design import run
from valvetrain.specification import example_spec

HEEL_MM, CLEARANCE_MM, RATIO, STROKE_MM = 19.75, 0.25, 1.6, 77.142857


@pytest.fixture(scope="module")
def results():
    return run(example_spec())


def test_the_lift_table_in_mm_and_degrees(results):
    v = results.valves["intake"]
    t = tables.lift_table_columns(v.table)
    assert list(t) == [name for name, _ in tables.LIFT_COLUMNS]
    # valve lift = i_k (h - h0) off the seat, 0 on the ramp below the clearance
    assert t["valve_lift_mm"] == pytest.approx(RATIO * np.maximum(t["tappet_lift_mm"] - CLEARANCE_MM, 0.0), abs=1e-9)
    # four-stroke: crank angle = 2 x camshaft angle, from the nose's crank angle
    nose_crank_deg = math.degrees(v.nose_crank)
    assert t["crank_deg"] == pytest.approx(2.0 * t["cam_deg"] + nose_crank_deg, abs=1e-9)
    assert t["valve_lift_mm"].max() == pytest.approx(RATIO * (t["tappet_lift_mm"].max() - CLEARANCE_MM), rel=1e-12)


def test_the_contour_s_nose_and_heel_radii(results):
    """A flat follower: the contour point of the nose lies on the nose axis at r0 + h_max, the point half a turn away
    on the heel circle r0 (the law's largest lift read from the lift table)."""
    v = results.valves["intake"]
    nose = HEEL_MM + tables.lift_table_columns(v.table)["tappet_lift_mm"].max()
    c = tables.contour_columns(v)
    assert c["radius_mm"] == pytest.approx(np.hypot(c["x_mm"], c["y_mm"]), rel=1e-12)
    assert c["radius_mm"].max() == pytest.approx(nose, abs=1e-6) and c["radius_mm"].min() == pytest.approx(HEEL_MM)
    polar = tables.polar_contour_columns(v, 1.0)
    assert polar["polar_angle_deg"][[0, -1]] == pytest.approx([-180.0, 179.0])
    assert polar["radius_mm"][polar["polar_angle_deg"] == 0.0] == pytest.approx([nose], abs=1e-6)
    assert polar["radius_mm"][0] == pytest.approx(HEEL_MM, abs=1e-9)
    cartesian = tables.cartesian_contour_columns(v, 2.0)
    assert (cartesian["x_mm"][0], cartesian["y_mm"][0]) == pytest.approx((0.0, -HEEL_MM), abs=1e-9)


def test_the_exported_lift_starts_and_ends_on_the_base_circle(results):
    v = results.valves["intake"]
    e = tables.lift_export_columns(v, 0.5)
    assert e["lift_mm"][0] == 0.0 and e["lift_mm"][-1] == 0.0
    assert np.diff(e["angle_deg"]) == pytest.approx(np.full(e["angle_deg"].size - 1, 0.5))
    # the camshaft angle from the gas-exchange TDC: the nose sits at half its crank angle
    top = np.argmax(e["lift_mm"])
    assert e["angle_deg"][top] == pytest.approx(math.degrees(v.nose_crank) / 2.0, abs=0.25)
    comments = tables.lift_export_comments(v)
    assert f"clearance_mm = {CLEARANCE_MM:g}" in comments[-1] and f"rocker_ratio = {RATIO:g}" in comments[-1]


def test_speeds_in_rpm_and_the_crank_tables(results):
    strength = results.valves["intake"].drive.strength
    s = tables.strength_speed_columns(strength)
    assert s["speed_rpm"] == pytest.approx(np.asarray(strength.per_speed.speed) * 30.0 / math.pi, rel=1e-12)
    assert s["cam_force_max_cam_deg"] == pytest.approx(np.degrees(strength.per_speed.cam_force_max_angle))
    crank = tables.crank_columns(results.crank)
    assert list(crank) == [name for name, _ in tables.CRANK_COLUMNS]
    # the piston at TDC at 0 deg and a stroke below it at BDC, 180 deg
    assert crank["s_mm"][crank["crank_deg"] == 0.0] == pytest.approx([0.0], abs=1e-9)
    assert crank["s_mm"][crank["crank_deg"] == 180.0] == pytest.approx([STROKE_MM], rel=1e-9)
    torque = tables.engine_torque_columns(results.crank)
    cylinders = [torque[f"M_cyl{i}_Nm"] for i in range(1, 5)]
    assert torque["M_total_Nm"] == pytest.approx(np.sum(cylinders, axis=0), rel=1e-9, abs=1e-9)
