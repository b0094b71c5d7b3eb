"""Crank-mechanism stage: kinematics, gas pressure, forces and torque of one cylinder, the engine's total
torque (seed 001; spec/crank-kinematics-dynamics.md)."""

from dataclasses import dataclass

import numpy as np

from ..checks import check
from ..crank import dynamics, kinematics, pressure, torque
from ..specification import SpecError, crank_geometry, si
from ..units import DEG, MM, MPA, rad_to_deg, rpm_to_rad_s

LAMBDA_RANGE = (0.24, 0.31)
"""lambda = R / L of automotive and tractor engines (seed 001, eq. 1.1)."""

ROD_PIN_FRACTION_RANGE = (0.2, 0.3)
"""Share of the rod mass at the piston pin (seed 001, eq. 2.7)."""


@dataclass
class CrankResults:
    """The crank chapter: per-angle arrays of one cylinder, the engine torque and the summary (SI)."""

    phi: np.ndarray                 # cycle angle of one cylinder [rad]
    columns: dict                   # per-angle arrays of one cylinder (SI)
    psi: np.ndarray                 # engine angle over one cycle [rad]
    cylinder_torques: np.ndarray    # (i, n) [N m]
    total_torque: np.ndarray        # (n,) [N m]
    firing: np.ndarray              # firing angles after cylinder 1 [rad]
    summary: dict
    checks: list                    # every valvetrain.checks.Check of the chapter
    pressure_source: str


def _masses(c, area, rods_per_pin):
    def mass(part):
        given = getattr(c, f"{part}_kg")
        return given if given is not None else getattr(c, f"specific_{part}_kg_m2") * area

    return dynamics.reduced_masses(mass("piston"), mass("rod"), mass("crank"), c.rod_pin_fraction, rods_per_pin)


def _gas_pressure(spec, phi, bore, radius, lam, k):
    c = spec.crank
    strokes = spec.engine.strokes
    if c.pressure_file is None:
        cy = c.cycle
        model = pressure.WiebeCycle(
            c.compression_ratio, cy.heat_input_J, cy.intake_pressure_MPa * MPA, cy.exhaust_pressure_MPa * MPA,
            cy.combustion_start_deg * DEG, cy.combustion_duration_deg * DEG, cy.wiebe_a, cy.wiebe_m, cy.gamma)
        source = (f"Wiebe cycle model: compression ratio {c.compression_ratio:g}, heat input {cy.heat_input_J:g} J, "
                  f"start {cy.combustion_start_deg:g} deg from firing TDC, duration {cy.combustion_duration_deg:g} "
                  f"deg, a = {cy.wiebe_a:g}, m = {cy.wiebe_m:g}, gamma = {cy.gamma:g}, no wall heat loss, gas "
                  f"exchange at {cy.intake_pressure_MPa:g}/{cy.exhaust_pressure_MPa:g} MPa with the valves at the "
                  "dead centres")
        return pressure.wiebe_pressure(phi, model, bore, radius, lam, strokes, k), source
    table = si(c, spec).indicator
    if table.kind == "angle":
        pressure.check_cycle(table.x, table.pressure, strokes, table.source)
        return pressure.on_grid(table.x, table.pressure, phi, strokes), f"p-phi diagram {table.source}"
    if c.compression_ratio is None:
        raise pressure.PressureFileError(f"{table.source} is a p-V diagram: crank.compression_ratio is needed to place "
                                         "it on the crank angle")
    angle, p = pressure.pv_to_angle(table.x, table.pressure, bore, radius, lam, c.compression_ratio, strokes, k,
                                    c.pv_method, table.source)
    pressure.check_cycle(angle, p, strokes, table.source)
    how = "Brix's construction" if c.pv_method == "brix" else "the exact kinematics"
    return pressure.on_grid(angle, p, phi, strokes), f"p-V diagram {table.source}, placed on the crank angle by {how}"


def _firing(eng):
    order = eng.firing_order or list(range(1, eng.cylinders + 1))
    if eng.firing_angles_deg is not None:
        return np.asarray(eng.firing_angles_deg) * DEG, "given firing angles"
    if eng.crank_throws_deg is not None:
        banks = eng.banks or [0] * (eng.cylinders // 2) + [1] * (eng.cylinders - eng.cylinders // 2)
        axes = [b * eng.bank_angle_deg * DEG if eng.layout == "v" else 0.0 for b in banks]
        return torque.layout_firing(order, np.asarray(eng.crank_throws_deg) * DEG, axes, eng.strokes), \
            "from the crank throws and cylinder axes"
    return torque.even_firing(order, eng.strokes), f"even firing, order {'-'.join(map(str, order))}"


def crank_stage(spec):
    """Run the crank chapter of a specification with a [crank] section; returns :class:`CrankResults`."""
    c, eng = spec.crank, spec.engine
    bore_mm, stroke_mm, rod_mm, speed = crank_geometry(spec)
    bore, radius, rod = bore_mm * MM, stroke_mm * MM / 2.0, rod_mm * MM
    lam, k = radius / rod, c.offset_mm * MM / radius
    omega = rpm_to_rad_s(speed)
    exact = c.kinematics == "exact"
    strokes = eng.strokes
    n = int(round(180.0 * strokes / c.step_deg))
    phi = np.arange(n) * (c.step_deg * DEG)
    area = np.pi * bore**2 / 4.0

    try:
        p_abs, source = _gas_pressure(spec, phi, bore, radius, lam, k)
    except pressure.PressureFileError as exc:
        raise SpecError([f"crank.pressure_file: {exc}"]) from None
    masses = _masses(c, area, 2 if eng.layout == "v" else 1)
    forces = dynamics.cylinder_dynamics(phi, p_abs, c.ambient_pressure_MPa * MPA, bore, radius, lam, omega, masses,
                                        k, exact)
    s = kinematics.displacement(phi, radius, lam, k, exact)
    v = kinematics.velocity(phi, radius, lam, omega, k, exact)
    j = kinematics.acceleration(phi, radius, lam, omega, k, exact)
    beta = kinematics.rod_angle(phi, lam, k)
    columns = {"s": s, "v": v, "j": j, "beta": beta, "p_abs": p_abs, **forces}

    firing, firing_how = _firing(eng)
    each, total = torque.engine_torque(phi, (phi, forces["torque"]), firing, strokes)
    even = torque.is_even(firing, strokes)
    period = torque.firing_interval(strokes, eng.cylinders) if even else np.pi * strokes
    in_period = phi < period - 1e-12
    stats = torque.torque_statistics(total[in_period])

    volume = pressure.cylinder_volume(phi, bore, radius, lam, c.compression_ratio, k, exact) \
        if c.compression_ratio is not None else None
    work = pressure.indicated_work(phi, p_abs, volume) if volume is not None else None
    ext = kinematics.extremes(radius, lam, omega, k, exact)
    book = kinematics.textbook_extremes(radius, lam, omega)
    tdc, bdc = kinematics.dead_centres(lam, k)
    summary = {
        "bore_mm": bore_mm, "stroke_mm": stroke_mm, "rod_length_mm": rod_mm, "offset_mm": c.offset_mm,
        "speed_rpm": speed, "lambda": lam, "kinematics": c.kinematics,
        "max_velocity_m_s": ext["v_max"], "max_velocity_crank_deg": rad_to_deg(ext["v_max_angle"]),
        "max_acceleration_m_s2": ext["j_max"], "max_acceleration_crank_deg": rad_to_deg(ext["j_max_angle"]),
        "min_acceleration_m_s2": ext["j_min"], "min_acceleration_crank_deg": rad_to_deg(ext["j_min_angle"]),
        "textbook": {"max_velocity_m_s": book["v_max"], "max_acceleration_m_s2": book["j_max"],
                     "min_acceleration_m_s2": book["j_min"], "min_acceleration_crank_deg": rad_to_deg(book["j_min_angle"]),
                     "source": "seed 001, eqs. (1.7), (1.10), (1.11) (central mechanism)"},
        "max_rod_angle_deg": rad_to_deg(float(np.max(np.abs(beta)))),
        "tdc_crank_deg": rad_to_deg(tdc), "bdc_crank_deg": rad_to_deg(bdc),
        "masses": {"piston_kg": masses.piston, "rod_kg": masses.rod, "crank_kg": masses.crank,
                   "rod_at_pin_kg": masses.rod_pin, "rod_at_crank_kg": masses.rod_crank,
                   "reciprocating_kg": masses.reciprocating, "rotating_kg": masses.rotating},
        "centrifugal_force_N": dynamics.centrifugal_force(masses.rotating, radius, omega),
        "max_gas_pressure_MPa": float(np.max(p_abs)) / MPA,
        "max_gas_pressure_crank_deg": rad_to_deg(phi[int(np.argmax(p_abs))]),
        "pressure_source": source,
        "mean_torque_Nm": stats["mean"], "max_torque_Nm": stats["max"], "min_torque_Nm": stats["min"],
        "nonuniformity": stats["nonuniformity"],
        "cylinder_mean_torque_Nm": float(np.mean(forces["torque"])),
        "torque_period_deg": rad_to_deg(period), "even_firing": even,
        "firing_angles_deg": [rad_to_deg(a) for a in firing], "firing": firing_how,
        "layout": eng.layout, "cylinders": eng.cylinders, "strokes": strokes,
    }
    if work is not None:
        from_work = eng.cylinders * work / (np.pi * strokes)
        summary.update(indicated_work_J=work, imep_MPa=work / (area * 2.0 * radius) / MPA,
                       mean_torque_from_work_Nm=from_work,
                       torque_work_balance=(stats["mean"] - from_work) / from_work if from_work else None)
    found = [check("crank lambda = R/L", lam, *LAMBDA_RANGE, source="seed 001, eq. (1.1)"),
             check("rod mass share at the piston pin", c.rod_pin_fraction, *ROD_PIN_FRACTION_RANGE,
                   source="seed 001, eq. (2.7)")]
    return CrankResults(phi, columns, phi, each, total, firing, summary, found, source)
