"""Bounded fields of the specification (specification/fields.py): a value outside its physical bounds is refused with
the key, the value and the range allowed."""

import pytest

from appendix import appendix_with


@pytest.mark.parametrize("old,new,message", [
    # Valve-train practical works (n.d.), work 2 recommends 0.008-0.022 mm/deg: 2e-8 would make a ramp of millions of degrees
    ("ramp_end_velocity_mm_per_deg = 0.02", "ramp_end_velocity_mm_per_deg = 2e-8",
     "valves.intake.cam.ramp_end_velocity_mm_per_deg = 2e-08: allowed [0.001, 1] mm/deg"),
    # a table step of 1e-9 deg would allocate terabytes
    ("table_step_cam_deg = 0.5", "table_step_cam_deg = 1e-9", "output.table_step_cam_deg = 1e-09: allowed [0.05, 10] deg"),
    ("bore_mm = 80.0", "bore_mm = 1e-300", "engine.bore_mm = 1e-300: allowed [5, 2000] mm"),
    ("firing_order = [1, 3, 4, 2]", "crank_throws_deg = [0.0, nan, 180.0, 0.0]",
     "engine.crank_throws_deg.1 = nan: must be a finite number"),
])
def test_values_below_physical_bounds(refused, old, new, message):
    assert message in refused(appendix_with((old, new)))
