"""Crank-mechanism stage: kinematics, gas pressure, forces and torque of one cylinder, the engine's total
torque (Power units manual (n.d.))."""

from dataclasses import dataclass
from functools import cached_property
from typing import Any

import numpy as np

from ..checks import Check, check, tally
from ..crank import dynamics, kinematics, pressure, torque
from ..locale import NoteText, cited, note
from ..specification import SpecError
from ..specification.messages import Problem, said
from ..units import MPA
from .results import quantity, record

LAMBDA_RANGE = (0.24, 0.31)
"""lambda = R / L of automotive and tractor engines (Power units manual (n.d.), eq. 1.1)."""

ROD_PIN_FRACTION_RANGE = (0.2, 0.3)
"""Share of the rod mass at the piston pin (Power units manual (n.d.), eq. 2.7)."""


@dataclass(frozen=True)
class TextbookExtremes:
    """The manual's closed forms of the piston extremes, for comparison (central mechanism)."""

    max_velocity: float = quantity("max_velocity_m_s", "m/s", "largest piston velocity, eq. (1.7)")
    max_acceleration: float = quantity("max_acceleration_m_s2", "m/s2", "largest piston acceleration, eq. (1.10)")
    min_acceleration: float = quantity("min_acceleration_m_s2", "m/s2", "smallest piston acceleration, eq. (1.11)")
    min_acceleration_angle: float = quantity("min_acceleration_crank_deg", "crank deg", "where it is smallest")
    source: str = quantity("source", label="source")


@dataclass(frozen=True)
class MassRecord:
    """The masses of the crank mechanism and their reduction to two points (Power units manual (n.d.), eqs. 2.6-2.10)."""

    piston: float = quantity("piston_kg", "kg", "piston group")
    rod: float = quantity("rod_kg", "kg", "connecting rod")
    crank: float = quantity("crank_kg", "kg", "unbalanced crank throw")
    rod_pin: float = quantity("rod_at_pin_kg", "kg", "rod mass at the piston pin")
    rod_crank: float = quantity("rod_at_crank_kg", "kg", "rod mass at the crank pin")
    reciprocating: float = quantity("reciprocating_kg", "kg", "reciprocating mass m_j")
    rotating: float = quantity("rotating_kg", "kg", "rotating mass m_R")


@dataclass(frozen=True)
class WorkRecord:
    """Indicated work of the cycle and the balance of torque and work."""

    indicated_work: float = quantity("indicated_work_J", "J", "indicated work of one cycle, closed integral p dV")
    imep: float = quantity("imep_MPa", "MPa", "indicated mean effective pressure")
    mean_torque_from_work: float = quantity("mean_torque_from_work_Nm", "N m", "mean torque of the engine from the work")
    balance: float = quantity("torque_work_balance", label="(mean torque - torque from work) / torque from work")


@dataclass(frozen=True)
class CrankSummary:
    """The crank chapter's figures (Power units manual (n.d.))."""

    bore: float = quantity("bore_mm", "mm", "bore")
    stroke: float = quantity("stroke_mm", "mm", "stroke")
    rod_length: float = quantity("rod_length_mm", "mm", "connecting-rod length")
    offset: float = quantity("offset_mm", "mm", "piston-pin offset")
    speed: float = quantity("speed_rpm", "rpm", "crank speed")
    lam: float = quantity("lambda", label="lambda = R / L")
    kinematics: str = quantity("kinematics", label="exact or approximate (the manual's series)")
    max_velocity: float = quantity("max_velocity_m_s", "m/s", "largest piston velocity")
    max_velocity_angle: float = quantity("max_velocity_crank_deg", "crank deg", "where")
    max_acceleration: float = quantity("max_acceleration_m_s2", "m/s2", "largest piston acceleration")
    max_acceleration_angle: float = quantity("max_acceleration_crank_deg", "crank deg", "where")
    min_acceleration: float = quantity("min_acceleration_m_s2", "m/s2", "smallest piston acceleration")
    min_acceleration_angle: float = quantity("min_acceleration_crank_deg", "crank deg", "where")
    textbook: TextbookExtremes = quantity("textbook", label="the manual's closed forms")
    max_rod_angle: float = quantity("max_rod_angle_deg", "deg", "largest connecting-rod angle")
    tdc: float = quantity("tdc_crank_deg", "crank deg", "top dead centre (offset mechanism)")
    bdc: float = quantity("bdc_crank_deg", "crank deg", "bottom dead centre")
    masses: MassRecord = quantity("masses", label="masses")
    centrifugal_force: float = quantity("centrifugal_force_N", "N", "centrifugal force of the rotating mass")
    max_gas_pressure: float = quantity("max_gas_pressure_MPa", "MPa", "peak cylinder pressure")
    max_gas_pressure_angle: float = quantity("max_gas_pressure_crank_deg", "crank deg", "where")
    pressure_source: str = quantity("pressure_source", label="where the cylinder pressure comes from")
    mean_torque: float = quantity("mean_torque_Nm", "N m", "mean engine torque")
    max_torque: float = quantity("max_torque_Nm", "N m", "largest engine torque")
    min_torque: float = quantity("min_torque_Nm", "N m", "smallest engine torque")
    nonuniformity: float = quantity("nonuniformity", label="(M_max - M_min) / M_mean (null: no positive mean)")
    cylinder_mean_torque: float = quantity("cylinder_mean_torque_Nm", "N m", "mean torque of one cylinder")
    torque_period: float = quantity("torque_period_deg", "crank deg", "period of the engine torque")
    even_firing: bool = quantity("even_firing", label="the cylinders fire at equal intervals")
    firing_angles: tuple[float, ...] = quantity("firing_angles_deg", "crank deg", "firing angles after cylinder 1")
    firing: str = quantity("firing", label="how the firing angles were found")
    layout: str = quantity("layout", label="inline or v")
    cylinders: int = quantity("cylinders", label="cylinders")
    strokes: int = quantity("strokes", label="strokes per cycle")
    work: WorkRecord = quantity("work", flatten=True, omit_none=True)


@dataclass(frozen=True)
class CrankColumns:
    """Per-angle arrays of one cylinder over its cycle, each of the length of :attr:`CrankResults.phi` (SI; Power
    units manual (n.d.), eqs. (1.2)-(2.21)).

    Attributes
    ----------
    s, v, j : ndarray
        Piston displacement from the TDC [m], velocity [m/s], acceleration [m/s^2].
    beta : ndarray
        Connecting-rod angle [rad].
    p_abs : ndarray
        Absolute cylinder pressure [Pa].
    p_gas, p_j, p : ndarray
        Gauge gas pressure p_g - p_0, specific inertia force, total specific force on the pin axis [Pa].
    p_N, p_S, p_K, p_T : ndarray
        Specific normal (side), rod, radial and tangential forces [Pa].
    T : ndarray
        Tangential force [N].
    torque : ndarray
        Torque of the cylinder, M = T R [N m].
    pin_radial, pin_tangential : ndarray
        Crank-pin load in the crank's frame: radial (K + the rod's centrifugal force) and tangential [N].
    """

    s: np.ndarray
    v: np.ndarray
    j: np.ndarray
    beta: np.ndarray
    p_abs: np.ndarray
    p_gas: np.ndarray
    p_j: np.ndarray
    p: np.ndarray
    p_N: np.ndarray
    p_S: np.ndarray
    p_K: np.ndarray
    p_T: np.ndarray
    T: np.ndarray
    torque: np.ndarray
    pin_radial: np.ndarray
    pin_tangential: np.ndarray


@dataclass(frozen=True, repr=False)
class CrankResults:
    """The crank chapter: per-angle arrays of one cylinder, the engine torque and the summary (SI)."""

    phi: np.ndarray                 # cycle angle of one cylinder [rad]
    columns: CrankColumns           # per-angle arrays of one cylinder (SI)
    psi: np.ndarray                 # engine angle over one cycle [rad]
    cylinder_torques: np.ndarray    # (i, n) [N m]
    total_torque: np.ndarray        # (n,) [N m]
    firing: np.ndarray              # firing angles after cylinder 1 [rad]
    figures: CrankSummary
    checks: tuple[Check, ...]       # every check of the chapter
    pressure_source: str

    @cached_property
    def summary(self) -> dict[str, Any]:
        """The chapter's record in results.json (engineering units), made once: read it, don't change it."""
        return record(self.figures)

    def __repr__(self):
        f = self.figures
        return (f"CrankResults({f.cylinders} cyl. {f.layout}, mean torque {f.mean_torque:.4g} N m, peak pressure "
                f"{f.max_gas_pressure / MPA:.4g} MPa, "
                + "open failures {failure}, warnings {warning}, info {info} of {checks} checks)".format(**tally(self.checks)))


def crank_geometry(crank, engine) -> tuple[float, float, float, float]:
    """Bore, stroke, rod length [m] and speed [rad/s] of the crank mechanism: [crank]'s, else [engine]'s (SI
    views; the specification refuses values given in both that differ)."""
    def either(a, b):
        return a if a is not None else b

    return (either(crank.bore, engine.bore), either(crank.stroke, engine.stroke),
            either(crank.rod_length, engine.rod_length), either(crank.speed, engine.rated_speed))


def _masses(c, area, rods_per_pin):
    def mass(part):
        given = getattr(c, f"{part}_kg")
        return given if given is not None else getattr(c, f"specific_{part}_kg_m2") * area

    return dynamics.reduced_masses(mass("piston"), mass("rod"), mass("crank"), c.rod_pin_fraction, rods_per_pin)


def valve_timing(valves) -> dict[str, float]:
    """The gas-exchange angles of the Wiebe model from the designed valves [rad, crank angle from the gas-exchange
    TDC]: ``intake_opens``/``intake_closes`` of the intake valves (the earliest opening, the latest closing),
    ``exhaust_opens``/``exhaust_closes`` of the exhaust valves; a kind without valves is left out."""
    out = {}
    for kind in ("intake", "exhaust"):
        these = [v for v in valves.values() if v.kind == kind]
        if these:
            out[f"{kind}_opens"] = min(v.cam.valve_opens for v in these)
            out[f"{kind}_closes"] = max(v.cam.valve_closes for v in these)
    return out


def wiebe_timing(timing) -> tuple[dict[str, float], tuple]:
    """Keyword arguments of :class:`~valvetrain.crank.pressure.WiebeCycle` from :func:`valve_timing` (angles
    moved to the model's frames: the closed cycle's from the firing TDC, the overlap's from the gas-exchange TDC),
    and the words of the pressure source naming them (a note, :func:`valvetrain.locale.note`; empty without them)."""
    two_pi, four_pi = 2.0 * np.pi, 4.0 * np.pi
    kw, valves = {}, ()
    if "intake_closes" in timing:
        kw["intake_closes"] = np.mod(timing["intake_closes"], four_pi) - two_pi
        kw["intake_opens"] = np.mod(timing["intake_opens"] + two_pi, four_pi) - two_pi
        valves += note("crank.intake_valve", opens_deg=np.degrees(timing["intake_opens"]),
                     closes_deg=np.degrees(timing["intake_closes"]))
    if "exhaust_opens" in timing:
        kw["exhaust_opens"] = np.mod(timing["exhaust_opens"], four_pi) - two_pi
        kw["exhaust_closes"] = np.mod(timing["exhaust_closes"] + two_pi, four_pi) - two_pi
        valves += note("crank.exhaust_valve", opens_deg=np.degrees(np.mod(timing["exhaust_opens"], four_pi)),
                     closes_deg=np.degrees(timing["exhaust_closes"]))
    return kw, note("crank.valve_timing", valves=valves) if valves else ()


def _gas_pressure(c, strokes, phi, bore, radius, lam, k, timing=None):
    """Cylinder pressure on the grid from the indicator diagram or the Wiebe model, and its description."""
    if c.indicator is None:
        cy = c.cycle
        kw, where = wiebe_timing(timing or {}) if strokes == 4 else ({}, ())
        model = pressure.WiebeCycle(c.compression_ratio, cy.heat_input_J, cy.intake_pressure, cy.exhaust_pressure,
                                    cy.combustion_start, cy.combustion_duration, cy.wiebe_a, cy.wiebe_m, cy.gamma,
                                    **kw)
        if strokes == 4:
            try:
                pressure.check_timing(model)
            except ValueError as exc:
                raise SpecError([Problem("crank.cycle", said(exc))]) from None
            valves = note("crank.wiebe_valves", blowdown_deg=pressure.BLOWDOWN_DEG,
                          where=where or note("crank.valves_at_dead_centres"))
        else:
            valves = note("crank.ports_at_dead_centres")
        source = NoteText(note("crank.wiebe", compression_ratio=c.compression_ratio, heat_J=cy.heat_input_J,
                               start_deg=np.degrees(cy.combustion_start),
                               duration_deg=np.degrees(cy.combustion_duration), a=cy.wiebe_a, m=cy.wiebe_m,
                               gamma=cy.gamma, intake_MPa=cy.intake_pressure / MPA,
                               exhaust_MPa=cy.exhaust_pressure / MPA, valves=valves))
        return pressure.wiebe_pressure(phi, model, bore, radius, lam, strokes, k), source
    table = c.indicator
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


def firing_angles(eng) -> tuple[np.ndarray, str]:
    """Firing angles of the cylinders after cylinder 1 [rad] (SI view of [engine]) and how they were found: given,
    from the crank throws and cylinder axes, or even firing in the firing order."""
    order = eng.firing_order or tuple(range(1, eng.cylinders + 1))
    if eng.firing_angles is not None:
        return np.asarray(eng.firing_angles), "given firing angles"
    if eng.crank_throws is not None:
        banks = eng.banks or [0] * (eng.cylinders // 2) + [1] * (eng.cylinders - eng.cylinders // 2)
        axes = [b * eng.bank_angle if eng.layout == "v" else 0.0 for b in banks]
        return torque.layout_firing(list(order), np.asarray(eng.crank_throws), axes, eng.strokes), \
            NoteText(note("crank.firing_from_throws"))
    return torque.even_firing(list(order), eng.strokes), NoteText(note("crank.firing_even",
                                                                        order="-".join(map(str, order))))


def crank_stage(c, eng, timing=None, cylinder=None) -> CrankResults:
    """Run the crank chapter: ``c`` and ``eng`` are the SI views of [crank] and [engine], ``timing`` the valves'
    angles for the Wiebe model (:func:`valve_timing`), ``cylinder`` the breathing's cylinder pressure over the cycle
    (a :class:`~valvetrain.design.hydraulic_actuation.CylinderPressure`), which replaces the indicator diagram and the
    Wiebe model when given; returns :class:`CrankResults`."""
    bore, stroke, rod, omega = crank_geometry(c, eng)
    radius = stroke / 2.0
    lam, k = radius / rod, c.offset / radius
    exact = c.kinematics == "exact"
    strokes = eng.strokes
    n = int(round(np.pi * strokes / c.step))
    phi = np.arange(n) * c.step
    area = np.pi * bore**2 / 4.0

    if cylinder is not None:
        p_abs = np.interp(phi, cylinder.angle, cylinder.pressure, period=pressure.cycle_length(strokes))
        source = cylinder.source
    else:
        try:
            p_abs, source = _gas_pressure(c, strokes, phi, bore, radius, lam, k, timing)
        except pressure.PressureFileError as exc:
            raise SpecError([Problem("crank.pressure_file", said(exc))]) from None
    masses = _masses(c, area, 2 if eng.layout == "v" else 1)
    forces = dynamics.cylinder_dynamics(phi, p_abs, c.ambient_pressure, bore, radius, lam, omega, masses, k, exact)
    beta = kinematics.rod_angle(phi, lam, k)
    columns = CrankColumns(s=kinematics.displacement(phi, radius, lam, k, exact),
                           v=kinematics.velocity(phi, radius, lam, omega, k, exact),
                           j=kinematics.acceleration(phi, radius, lam, omega, k, exact), beta=beta, p_abs=p_abs,
                           **forces)

    firing, firing_how = firing_angles(eng)
    each, total = torque.engine_torque(phi, (phi, forces["torque"]), firing, strokes)
    even = torque.is_even(firing, strokes)
    period = torque.firing_interval(strokes, eng.cylinders) if even else np.pi * strokes
    stats = torque.torque_statistics(total[phi < period - 1e-12])

    work = None
    if c.compression_ratio is not None:
        volume = pressure.cylinder_volume(phi, bore, radius, lam, c.compression_ratio, k, exact)
        w = pressure.indicated_work(phi, p_abs, volume)
        from_work = eng.cylinders * w / (np.pi * strokes)
        work = WorkRecord(w, w / (area * stroke), from_work,
                          (stats["mean"] - from_work) / from_work if from_work else None)
    ext = kinematics.extremes(radius, lam, omega, k, exact)
    book = kinematics.textbook_extremes(radius, lam, omega)
    tdc, bdc = kinematics.dead_centres(lam, k)
    figures = CrankSummary(
        bore, stroke, rod, c.offset, omega, lam, c.kinematics, ext["v_max"], ext["v_max_angle"], ext["j_max"],
        ext["j_max_angle"], ext["j_min"], ext["j_min_angle"],
        TextbookExtremes(book["v_max"], book["j_max"], book["j_min"], book["j_min_angle"],
                         cited(note("source.central_mechanism",
                                    work="Power units manual (n.d.), eqs. (1.7), (1.10), (1.11)"))),
        float(np.max(np.abs(beta))), tdc, bdc,
        MassRecord(masses.piston, masses.rod, masses.crank, masses.rod_pin, masses.rod_crank, masses.reciprocating,
                   masses.rotating),
        dynamics.centrifugal_force(masses.rotating, radius, omega), float(np.max(p_abs)),
        float(phi[int(np.argmax(p_abs))]), source, stats["mean"], stats["max"], stats["min"], stats["nonuniformity"],
        float(np.mean(forces["torque"])), period, even, tuple(float(a) for a in firing), firing_how, eng.layout,
        eng.cylinders, strokes, work)
    found = [check("crank.rod_ratio", lam, *LAMBDA_RANGE, source="Power units manual (n.d.), eq. (1.1)"),
             check("crank.rod_pin_share", c.rod_pin_fraction, *ROD_PIN_FRACTION_RANGE,
                   source="Power units manual (n.d.), eq. (2.7)"),
             check("crank.mean_torque", stats["mean_share"], low=0.0, strict_low=True,
                   source=cited(note("source.motored", work="Kolchin and Demidov (1980)")))]
    return CrankResults(phi, columns, phi, each, total, firing, figures, tuple(found), source)
