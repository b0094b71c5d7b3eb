"""Valve spring characteristic and spring design (Valve-train practical works (n.d.), works 5 and 6).

SI units inside: N, m, Pa, kg, rad/s.  One module per job:

* :mod:`~valvetrain.springs.formulas`: the formulas of a helical spring (stress, Wahl and shape factors, coils and
  rate, surge frequency, fatigue safety, lengths, the stress a resonance ratio needs);
* :mod:`~valvetrain.springs.requirement`: the force line the spring must exceed, P(y) = P_min + C y (eq. 5.6),
  above K_z m_v |j_v|, the gas force and the seat load, in closed form;
* :mod:`~valvetrain.springs.candidates`: many springs designed at once with their checks (numpy arrays);
* :mod:`~valvetrain.springs.search`: the vectorised search for the lightest spring or nested pair and its
  screening bounds;
* :mod:`~valvetrain.springs.diagnosis`: why no spring passes and what would make one pass, as frozen data (the
  report words it, :mod:`valvetrain.locale.wording`).

Conical (beehive) and progressive-rate springs are not designed: the sources give no formulas for them.
"""

from .candidates import (INSTALLED_TO_LIFT_MAX, MIN_WORKING_COILS, RESONANCE_RATIO_MIN, Candidates, SpringDesign,
                         SpringMaterial, evaluate_spring, evaluate_springs, shortest_solid_length)
from .diagnosis import Conflict, Diagnosis, Remedy, StressWindow, diagnose, stress_window
from .formulas import (SHAPE_FACTOR_TABLE, active_coils, fatigue_safety, fatigue_stress_limit, length_at_pitch,
                       natural_frequency, resonance_stress, shape_factor_table, shear_stress, spring_lengths,
                       spring_rate, wahl_factor)
from .requirement import (DEFLECTION_RATIO_RANGE, DEFLECTION_RATIO_STEP, INNER_SHARE_RANGE, SEAT_ACCELERATION,
                          SPRING_RESERVE_RANGE, Characteristic, Requirement, deflection_ratios, enveloping_line,
                          enveloping_lines, gas_opening_force, required_spring_force, seat_load)
from .search import (INNER_DIAMETER_RATIO_LOW, MEAN_DIAMETER_RANGE, MEAN_DIAMETER_STEP, WIRE_RANGE_MM, WIRE_STEP_MM,
                     NoSpringFits, Search, SpringOptions, design_pair, design_spring, design_springs,
                     feasible_mean_diameters, wire_series)

__all__ = [
    "INSTALLED_TO_LIFT_MAX", "MIN_WORKING_COILS", "RESONANCE_RATIO_MIN", "Candidates", "SpringDesign",
    "SpringMaterial", "evaluate_spring", "evaluate_springs", "shortest_solid_length", "Conflict", "Diagnosis", "Remedy", "StressWindow", "diagnose", "stress_window",
    "SHAPE_FACTOR_TABLE", "active_coils", "fatigue_safety", "fatigue_stress_limit", "length_at_pitch",
    "natural_frequency", "resonance_stress", "shape_factor_table", "shear_stress", "spring_lengths", "spring_rate",
    "wahl_factor",
    "DEFLECTION_RATIO_RANGE", "DEFLECTION_RATIO_STEP", "INNER_SHARE_RANGE", "SEAT_ACCELERATION",
    "SPRING_RESERVE_RANGE", "Characteristic", "Requirement", "deflection_ratios", "enveloping_line",
    "enveloping_lines", "gas_opening_force", "required_spring_force", "seat_load", "INNER_DIAMETER_RATIO_LOW",
    "MEAN_DIAMETER_RANGE", "MEAN_DIAMETER_STEP", "WIRE_RANGE_MM", "WIRE_STEP_MM", "NoSpringFits", "Search",
    "SpringOptions", "design_pair", "design_spring", "design_springs", "feasible_mean_diameters", "wire_series",
]
