"""The engine's breathing at one speed and plenum state: cycles integrated until they repeat, and what they deliver.

A cylinder (crank kinematics of :mod:`valvetrain.crank`) breathes through its intake and exhaust valves (effective
areas over the cycle, :mod:`.valves`), each through a runner (:mod:`.runners`) or straight from its plenum; the walls
take Woschni's heat (:mod:`.heat_transfer`); a fired cycle burns the trapped air's fuel on the crank chapter's Wiebe
schedule (:func:`valvetrain.crank.pressure.wiebe_fraction`).  :func:`breathe` integrates cycle after cycle
(:func:`.kernel.run_cycle`) from the plenums' state until the trapped mass, the delivered mass and the pressure at the
intake valve's closing repeat within :data:`TOLERANCE`, and returns the last cycle's figures and per-angle columns.

Angles are crank angles [rad] from the gas-exchange TDC (the timing diagram's 0), the firing TDC at 2 pi; SI units.
"""

from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from ..crank.kinematics import velocity
from ..crank.pressure import cylinder_volume, wiebe_fraction
from ..errors import InputError
from ..locale import NoteText, note
from ..results import quantity
from . import gas as gases
from . import kernel as kn
from .heat_transfer import WOSCHNI_C1, WOSCHNI_C2, wall_area
from .runners import CFL, conserved, frozen_gas, primitive

CYCLE = 4.0 * np.pi
"""Crank angle of a four-stroke cycle [rad]."""

TOLERANCE = 1e-3
"""Relative change of the trapped mass, the delivered mass and the pressure at the intake valve's closing from one
cycle to the next below which the cycles repeat (the cycle is converged)."""

MAX_CYCLES = 60
"""Cycles after which :func:`breathe` stops without convergence (and says so in the result)."""

MAX_STEP = np.radians(0.5)
"""Longest step of the integration [crank rad]: the valve events and the heat release resolved to half a degree."""

STIFFNESS_SHARE = 0.5
"""The step is at most this share of the cylinder's shortest filling time V / (A_E c) through its open valves."""

MAX_WORK = 1e8
"""Most cell-steps (:func:`work`) a design's breathing may ask for, all its conditions at their most cycles: about
half a minute of one core; a finer grid, more conditions or slower speeds are refused before they run, not left to
run for minutes."""

ADAPTATION = 1.15
"""After the first cycle the runners' step is set for this many times the fastest wave it met (|u| + c)."""

FIRED_START_TEMPERATURE = 1000.0
"""Exhaust temperature [K] of a fired engine's first cycle when the exhaust plenum's is not given: a starting value
only, the converged cycle takes the mean temperature of its own exhaust flow."""


@dataclass(frozen=True)
class Cylinder:
    """The cylinder's geometry: bore, stroke, connecting rod [m], compression ratio and piston-pin offset [m]."""

    bore: float
    stroke: float
    rod_length: float
    compression_ratio: float
    offset: float = 0.0

    @property
    def swept_volume(self) -> float:
        """V_d = pi B^2 S / 4 [m^3]."""
        return np.pi * self.bore**2 / 4.0 * self.stroke

    def volume(self, theta) -> np.ndarray:
        """Cylinder volume [m^3] at crank angles [rad] (:func:`valvetrain.crank.pressure.cylinder_volume`)."""
        radius = self.stroke / 2.0
        return cylinder_volume(theta, self.bore, radius, radius / self.rod_length, self.compression_ratio,
                               self.offset / radius)

    def volume_rate(self, theta, omega) -> np.ndarray:
        """dV/dt [m^3/s] at crank angles [rad] and crank speed omega [rad/s]: the piston area times its velocity
        (:func:`valvetrain.crank.kinematics.velocity`)."""
        radius = self.stroke / 2.0
        return np.pi * self.bore**2 / 4.0 * velocity(theta, radius, radius / self.rod_length, omega,
                                                     self.offset / radius)


@dataclass(frozen=True)
class ValveFlow:
    """Effective flow areas of one side's valves over the cycle (all its valves together).

    Attributes
    ----------
    angle : ndarray
        Increasing crank angles [rad] within one cycle; the areas repeat every 4 pi.
    forward, reverse : ndarray
        Effective areas [m^2]: forward into the cylinder for the intake, out of it for the exhaust.
    """

    angle: np.ndarray
    forward: np.ndarray
    reverse: np.ndarray

    def areas(self, theta) -> tuple[np.ndarray, np.ndarray]:
        """Forward and reverse effective areas [m^2] at crank angles [rad] (linear, periodic)."""
        return (np.interp(theta, self.angle, self.forward, period=CYCLE),
                np.interp(theta, self.angle, self.reverse, period=CYCLE))


@dataclass(frozen=True)
class Runner:
    """A runner with its port: a straight pipe from the plenum to the valve.

    Attributes
    ----------
    length, diameter : float
        [m].
    cell : float
        Longest cell of the finite-volume grid [m]; at least four cells.
    friction : bool
        Wall friction of a smooth pipe.
    """

    length: float
    diameter: float
    cell: float = 0.04
    friction: bool = True

    @property
    def cells(self) -> int:
        """Number of cells."""
        return max(4, int(np.ceil(self.length / self.cell - 1e-9)))


@dataclass(frozen=True)
class Plenum:
    """A plenum's pressure [Pa] and temperature [K]; an exhaust plenum without a temperature takes the mean
    temperature of the gas that flows into it in the previous cycle."""

    pressure: float
    temperature: Optional[float] = None


@dataclass(frozen=True)
class Firing:
    """A fired cycle: the fuel, its equivalence ratio (lean or stoichiometric), the share of its heat released, and
    the Wiebe schedule of :class:`valvetrain.crank.pressure.WiebeCycle` (start and duration [rad] from the firing TDC,
    a, m)."""

    fuel: str
    equivalence_ratio: float
    start: float
    duration: float
    a: float = 6.908
    m: float = 2.0
    efficiency: float = 1.0


@dataclass(frozen=True)
class Engine:
    """What breathes: the cylinder, its valves' flow areas, runners, wall heat and firing (None: motored)."""

    cylinder: Cylinder
    intake: ValveFlow
    exhaust: ValveFlow
    intake_runner: Optional[Runner] = None
    exhaust_runner: Optional[Runner] = None
    heat_transfer: bool = True
    firing: Optional[Firing] = None
    cylinders: int = 1


@dataclass(frozen=True)
class Condition:
    """An operating condition: crank speed [rad/s], the plenums and the wall temperature [K]."""

    speed: float
    intake: Plenum
    exhaust: Plenum
    wall_temperature: float


@dataclass(frozen=True)
class BreathingColumns:
    """Per-angle arrays of the converged cycle (SI), at the integration's step nodes from 0 to 4 pi.

    Attributes
    ----------
    angle : ndarray
        Crank angle from the gas-exchange TDC [rad].
    volume, pressure, temperature, mass, burned_mass : ndarray
        The cylinder's [m^3], [Pa], [K], [kg], [kg].
    intake_flow, exhaust_flow : ndarray
        Mass flow into the cylinder through the intake valves and out through the exhaust valves [kg/s]
        (negative: back-flow).
    intake_port, exhaust_port : ndarray
        Pressure at the intake and exhaust valves' ports (the runners' last cells; the plenum's without a runner) [Pa].
    """

    angle: np.ndarray
    volume: np.ndarray
    pressure: np.ndarray
    temperature: np.ndarray
    mass: np.ndarray
    burned_mass: np.ndarray
    intake_flow: np.ndarray
    exhaust_flow: np.ndarray
    intake_port: np.ndarray
    exhaust_port: np.ndarray


@dataclass(frozen=True)
class BreathingRecord:
    """The breathing of the engine at one condition (SI; results.json in engineering units)."""

    speed: float = quantity("speed_rpm", "rpm", "crank speed")
    intake_pressure: float = quantity("intake_pressure_kPa", "kPa", "intake plenum pressure")
    intake_temperature: float = quantity("intake_temperature_K", "K", "intake plenum temperature")
    exhaust_pressure: float = quantity("exhaust_pressure_kPa", "kPa", "exhaust plenum pressure")
    wall_temperature: float = quantity("wall_temperature_K", "K", "cylinder wall temperature")
    air_mass_flow: float = quantity("air_mass_flow_g_s", "g/s", "air delivered to the engine from the intake plenum")
    volumetric_efficiency: float = quantity("volumetric_efficiency",
                                            label="air delivered per cycle over the swept volume's mass at the intake "
                                                  "plenum's density")
    trapped_mass: float = quantity("trapped_mass_mg", "mg", "mass in the cylinder at the intake valve's closing")
    residual_gas_fraction: float = quantity("residual_gas_fraction",
                                            label="share of the trapped mass that was not fresh charge: residual and "
                                                  "back-flowed gas")
    intake_backflow: float = quantity("intake_backflow_mg", "mg", "mass flowing back from the cylinder into the "
                                      "intake port per cycle")
    exhaust_backflow: float = quantity("exhaust_backflow_mg", "mg", "mass flowing back from the exhaust port into the "
                                       "cylinder per cycle")
    pmep: float = quantity("pmep_kPa", "kPa", "pumping mean effective pressure: work on the gas over the exhaust and "
                           "intake strokes per swept volume")
    imep: float = quantity("imep_kPa", "kPa", "net indicated mean effective pressure, the whole cycle")
    imep_gross: float = quantity("imep_gross_kPa", "kPa", "gross indicated mean effective pressure, compression and "
                                 "expansion")
    peak_pressure: float = quantity("peak_pressure_kPa", "kPa", "largest cylinder pressure")
    peak_pressure_angle: float = quantity("peak_pressure_crank_deg", "crank deg",
                                          "where, from the gas-exchange TDC")
    exhaust_temperature: Optional[float] = quantity("exhaust_temperature_K", "K", "mean temperature of the cylinder "
                                                    "gas leaving through the exhaust valves (weighted by its mass; "
                                                    "none where none leaves)", omit_none=True)
    wall_heat: float = quantity("wall_heat_J", "J", "heat to the walls per cycle")
    torque: Optional[float] = quantity("torque_Nm", "N m", "indicated torque of the engine (fired)", omit_none=True)
    power: Optional[float] = quantity("power_kW", "kW", "indicated power of the engine (fired)", omit_none=True)
    cycles: int = quantity("cycles", label="cycles integrated until they repeat")
    cycle_change: float = quantity("cycle_change", label="largest relative change of the trapped mass, the delivered "
                                   "mass and the pressure at the intake valve's closing in the last cycle")
    energy_balance: float = quantity("energy_balance", label="the last cycle's energy balance of cylinder and runners, "
                                     "relative to the energy that crossed it (round-off)")


@dataclass(frozen=True, repr=False)
class BreathingState:
    """The state at the end of a converged cycle, from which the next speed of a curve starts (:func:`breathe`'s
    ``start``): the cylinder's state, the runners' cells and their gases, the exhaust plenum's temperature [K] and the
    fastest wave the runners met [m/s]."""

    cylinder: np.ndarray
    intake: np.ndarray
    exhaust: np.ndarray
    gases: np.ndarray
    exhaust_temperature: float
    wave: float


@dataclass(frozen=True, repr=False)
class BreathingResult:
    """The breathing at one condition: its figures, the converged cycle's columns and its end state."""

    figures: BreathingRecord
    columns: BreathingColumns = field(repr=False)
    converged: bool = True
    state: Optional[BreathingState] = field(default=None, repr=False, compare=False)

    def __repr__(self):
        f = self.figures
        return (f"BreathingResult({f.speed * 30 / np.pi:.5g} rpm: air {f.air_mass_flow * 1e3:.4g} g/s, VE "
                f"{f.volumetric_efficiency:.4g}, peak {f.peak_pressure / 1e3:.4g} kPa, IMEP {f.imep / 1e3:.4g} kPa)")


def _events(flow, theta):
    """Node indices where the valve closes (open before, shut at the node) and opens (shut before, open at it)."""
    forward, reverse = flow.areas(theta)
    open_ = (forward + reverse) > 0.0
    before = np.roll(open_, 1)
    closes = np.flatnonzero(before & ~open_)
    opens = np.flatnonzero(~before & open_)
    return closes, opens


def _closed_cycle(engine, theta, steps) -> tuple[int, int]:
    """The node indices of the intake valve's closing and the exhaust valve's opening about the firing TDC (node
    ``steps // 2``): the intake's last closing before it and the exhaust's first opening after it (a valve that
    bounces off its seat closes or opens more than once a cycle).

    Raises
    ------
    BreathingError
        A valve open at the firing TDC, or one that never closes or opens.
    """
    tdc = steps // 2
    closes, opens = _events(engine.intake, theta)[0], _events(engine.exhaust, theta)[1]
    before, after = closes[closes < tdc], opens[opens > tdc]
    shut = all(sum(flow.areas(theta[tdc])) == 0.0 for flow in (engine.intake, engine.exhaust))
    if not (before.size and after.size and shut):
        shuts, opened = (note("plain", text=", ".join(f"{np.degrees(theta[i]):.4g}" for i in events)) if events.size
                         else note("breathing.never") for events in (closes, opens))
        raise BreathingError(NoteText(note("breathing.tdc_open", closes=shuts, opens=opened)))
    return int(before[-1]), int(after[0])


class BreathingError(InputError):
    """Inputs the breathing cannot integrate; the message names what and why."""


@dataclass
class _Schedule:
    """The cycle's schedule on ``steps`` steps and the parameters of :func:`.kernel.run_cycle`."""

    steps: int
    sched: np.ndarray
    par: np.ndarray
    theta: np.ndarray


def _schedule(engine, condition, steps, fuel_air, heat_per_fuel):
    theta = np.linspace(0.0, CYCLE, steps + 1)
    omega = condition.speed
    cyl = engine.cylinder
    sched = np.zeros((kn.SCHEDULE_ROWS, steps + 1))
    sched[kn.VOLUME] = cyl.volume(theta)
    sched[kn.VOLUME_RATE] = cyl.volume_rate(theta, omega)
    sched[kn.WALL_AREA] = wall_area(sched[kn.VOLUME], cyl.bore)
    sched[kn.INTAKE_IN], sched[kn.INTAKE_OUT] = engine.intake.areas(theta)
    sched[kn.EXHAUST_OUT], sched[kn.EXHAUST_IN] = engine.exhaust.areas(theta)
    exchange = sched[kn.INTAKE_IN:kn.EXHAUST_IN + 1].sum(axis=0) > 0.0
    sched[kn.C1] = np.where(exchange, WOSCHNI_C1["gas_exchange"], WOSCHNI_C1["compression"])
    ivc, evo = _closed_cycle(engine, theta, steps)
    firing = engine.firing
    if firing is None:
        sched[kn.BURN] = (theta >= np.pi * 2.0 - 1e-12).astype(float)
    else:
        start, end = 2.0 * np.pi + firing.start, 2.0 * np.pi + firing.start + firing.duration
        if not (theta[ivc] < start and end < theta[evo]) or exchange[ivc:evo].any():
            raise BreathingError(NoteText(note("breathing.combustion", start=np.degrees(start), end=np.degrees(end),
                                               closes=np.degrees(theta[ivc]), opens=np.degrees(theta[evo]))))
        x = wiebe_fraction(theta, firing, 2.0 * np.pi)
        sched[kn.BURN] = np.minimum(x / x[evo], 1.0)
        sched[kn.C2] = np.where((theta >= start) & (theta < theta[evo]), WOSCHNI_C2, 0.0)
    par = np.zeros(kn.PARAMETERS)
    par[kn.DT] = CYCLE / (steps * omega)
    par[kn.BORE] = cyl.bore
    par[kn.PISTON_SPEED] = cyl.stroke * omega / np.pi
    par[kn.SWEPT] = cyl.swept_volume
    par[kn.WALL_T] = condition.wall_temperature
    par[kn.HEAT] = 1.0 if engine.heat_transfer else 0.0
    par[kn.FUEL_AIR] = fuel_air
    par[kn.HEAT_PER_FUEL] = heat_per_fuel
    par[kn.IVC] = ivc
    par[kn.GROSS_FROM], par[kn.GROSS_TO] = steps // 4, 3 * steps // 4
    return _Schedule(steps, sched, par, theta)


def _steps(engine, condition, wave_speed, pipes, fresh, t_hot):
    """Steps per cycle (a multiple of 4): the runners' Courant number :data:`CFL` at ``wave_speed`` [m/s], the share
    :data:`STIFFNESS_SHARE` of the cylinder's filling time at the sound speed of air at ``t_hot`` [K], and
    :data:`MAX_STEP`."""
    omega = condition.speed
    dt = MAX_STEP / omega
    cells = [pipes[j, kn.PIPE_DX] for j in range(2) if pipes[j, kn.PIPE_PRESENT] > 0.0]
    if cells:
        dt = min(dt, CFL * min(cells) / wave_speed)
    theta = np.linspace(0.0, CYCLE, 2881)
    area = sum(np.sum(flow.areas(theta), axis=0) for flow in (engine.intake, engine.exhaust))
    sound = np.sqrt(gases.ratio_of_specific_heats(fresh, t_hot) * fresh.gas_constant * t_hot)
    volume = engine.cylinder.volume(theta)
    opened = area > 0.0
    if opened.any():
        dt = min(dt, STIFFNESS_SHARE * float(np.min(volume[opened] / (area[opened] * sound))))
    steps = int(np.ceil(CYCLE / (omega * dt)))
    return steps + (-steps) % 4


def breathe(engine, condition, tolerance=TOLERANCE, max_cycles=MAX_CYCLES, start=None) -> BreathingResult:
    """The converged breathing of ``engine`` at ``condition``.

    Parameters
    ----------
    engine : Engine
    condition : Condition
    tolerance : float
        :data:`TOLERANCE`.
    max_cycles : int
        :data:`MAX_CYCLES`.
    start : BreathingState, optional
        The end state of the same engine's converged cycle at a neighbouring speed (the previous point of a curve):
        the first cycle starts there instead of from the plenums' state at rest, and its step from the waves met
        there; the cycles repeat sooner, the result is the same within ``tolerance``.

    Returns
    -------
    BreathingResult
        ``converged`` False when the cycles did not repeat within ``max_cycles``.

    Raises
    ------
    BreathingError
        Valve events the cycle cannot hold, or a state that leaves the physical range (a negative mass).

    Notes
    -----
    Volumetric efficiency :math:`\\eta_v = m_a / (\\rho_{a,i} V_d)`, :math:`\\rho_{a,i} = p_i / (R T_i)` of the intake
    plenum; :math:`\\text{imep}_n = \\oint p\\,dV / V_d` over the cycle, :math:`\\text{imep}_g` over the compression
    and expansion strokes (180 to 540 crank deg), :math:`\\text{pmep} = \\text{imep}_g - \\text{imep}_n`; the residual
    gas fraction is the share of the trapped mass that did not enter as fresh charge in this cycle (Heywood (1988),
    chapters 2 and 6); torque :math:`T = W_n z / (4\\pi)` and power :math:`T\\omega` of the z cylinders,
    indicated (no friction).
    """
    fresh = gases.air()
    firing = engine.firing
    if firing is None:
        burned, fuel_air, heat_per_fuel = fresh, 0.0, 0.0
    else:
        burned = gases.burned_gas(firing.fuel, firing.equivalence_ratio)
        fuel_air = gases.fuel_air_ratio(firing.fuel, firing.equivalence_ratio)
        heat_per_fuel = gases.lower_heating_value(firing.fuel) * firing.efficiency
    coef = np.stack([fresh.coefficients, burned.coefficients])
    rgas = np.array([fresh.gas_constant, burned.gas_constant])
    p_i, t_i = condition.intake.pressure, condition.intake.temperature
    p_e = condition.exhaust.pressure
    given_te = condition.exhaust.temperature
    t_e = given_te if given_te is not None else (t_i if firing is None else FIRED_START_TEMPERATURE)

    def plenum_row(p0, t0, y0, g):
        return [p0, t0, y0, float(gases.enthalpy(g, t0)), float(gases.ratio_of_specific_heats(g, t0)),
                g.gas_constant]

    def runner_gas(g, t):
        return frozen_gas(g.gas_constant, float(gases.ratio_of_specific_heats(g, t)), t, float(gases.enthalpy(g, t)))

    plenums = np.array([plenum_row(p_i, t_i, 0.0, fresh), plenum_row(p_e, t_e, 1.0, burned)])
    pipes = _pipes(engine)
    gas_rows = np.array([runner_gas(fresh, t_i), runner_gas(burned, t_e)])
    queues = []
    for j, (runner, (p0, t0, y0), g) in enumerate(zip((engine.intake_runner, engine.exhaust_runner),
                                                      ((p_i, t_i, 0.0), (p_e, t_e, 1.0)), (fresh, burned),
                                                      strict=True)):
        if runner is None:
            queues.append(np.zeros((0, 4)))
            continue
        n = runner.cells
        q = np.empty((n, 4))
        for i in range(n):
            conserved(p0 / (g.gas_constant * t0), 0.0, p0, y0, gas_rows[j], q[i])
        queues.append(q)
    qi, qe = queues
    # the cylinder at the gas-exchange TDC: old gas at the exhaust plenum's state
    cyl = np.zeros(kn.CYLINDER_STATE)
    v0 = float(engine.cylinder.volume(0.0))
    m0 = p_e * v0 / (burned.gas_constant * t_e)
    cyl[kn.M], cyl[kn.U], cyl[kn.MB], cyl[kn.TG] = m0, m0 * float(gases.internal_energy(burned, t_e)), m0, t_e
    cyl[kn.P_REF], cyl[kn.V_REF], cyl[kn.T_REF], cyl[kn.G_REF] = p_i, engine.cylinder.swept_volume, t_i, 1.4

    wave, t_hot = _first_wave(engine, condition)
    warm = start is not None and start.intake.shape == qi.shape and start.exhaust.shape == qe.shape
    if warm:
        cyl[:] = start.cylinder
        for q, old, j in ((qi, start.intake, 0), (qe, start.exhaust, 1)):
            for i in range(q.shape[0]):
                conserved(*primitive(old[i], start.gases[j]), gas_rows[j], q[i])
        if given_te is None:
            t_e = start.exhaust_temperature
            plenums[1] = plenum_row(p_e, t_e, 1.0, burned)
            for i in range(qe.shape[0]):
                conserved(*primitive(qe[i], gas_rows[1]), runner_gas(burned, t_e), qe[i])
            gas_rows[1] = runner_gas(burned, t_e)
        wave = start.wave * ADAPTATION
    steps = _steps(engine, condition, wave, pipes, fresh, t_hot)
    schedules = {}
    tallies = np.zeros(kn.TALLIES)
    previous, change, cycles, converged = None, np.inf, 0, False
    while cycles < max_cycles:
        if steps not in schedules:
            schedules[steps] = _schedule(engine, condition, steps, fuel_air, heat_per_fuel)
        s = schedules[steps]
        records = np.zeros((kn.RECORDS, steps + 1))
        saved = cyl.copy(), qi.copy(), qe.copy()
        start_energy = cyl[kn.U] + _pipe_energy(qi, pipes[0]) + _pipe_energy(qe, pipes[1])
        courant = kn.run_cycle(cyl, qi, qe, s.sched, s.par, coef, rgas, plenums, pipes, gas_rows, tallies, records)
        if not np.isfinite(courant):
            raise BreathingError(NoteText(note("breathing.unphysical", speed_rpm=condition.speed * 30 / np.pi)))
        if courant > 1.0:
            cyl[:], qi[:], qe[:] = saved
            steps = int(np.ceil(steps * courant / CFL))
            steps += (-steps) % 4
            continue
        cycles += 1
        end_energy = cyl[kn.U] + _pipe_energy(qi, pipes[0]) + _pipe_energy(qe, pipes[1])
        flows = (tallies[kn.ENERGY_IN] - tallies[kn.ENERGY_OUT] - tallies[kn.WORK] - tallies[kn.WALL_HEAT]
                 + tallies[kn.COMBUSTION_HEAT])
        scale = (abs(tallies[kn.ENERGY_IN]) + abs(tallies[kn.ENERGY_OUT]) + abs(tallies[kn.WORK])
                 + abs(tallies[kn.WALL_HEAT]) + abs(tallies[kn.COMBUSTION_HEAT]))
        balance = (end_energy - start_energy - flows) / scale
        ivc = int(s.par[kn.IVC])
        now = np.array([records[kn.REC_M, ivc], tallies[kn.DELIVERED], cyl[kn.P_REF]])
        if previous is not None:
            change = float(np.max(np.abs(now - previous) / np.abs(now)))
            if change < tolerance:
                converged = True
                break
        previous = now
        # the exhaust plenum takes the mean enthalpy of what flowed into it; the exhaust runner's gas follows
        if given_te is None:
            t_new = _exhaust_temperature(tallies, gas_rows[1], pipes[1])
            if t_new is not None:
                plenums[1] = plenum_row(p_e, t_new, 1.0, burned)
                new_gas = runner_gas(burned, t_new)
                for i in range(qe.shape[0]):
                    rho, u, p, y = primitive(qe[i], gas_rows[1])
                    conserved(rho, u, p, y, new_gas, qe[i])
                gas_rows[1] = new_gas
        if cycles == 1 and courant > 0.0 and not warm:
            # the first cycle has met the fastest waves (the blowdown's): the step follows them from now on
            steps = _steps(engine, condition, _wave(courant, pipes, s) * ADAPTATION, pipes, fresh, t_hot)
    s = schedules[steps]
    state = BreathingState(cyl.copy(), qi.copy(), qe.copy(), gas_rows.copy(), float(plenums[1, kn.PLENUM_T]),
                           _wave(courant, pipes, s) if courant > 0.0 else wave)
    return _result(engine, condition, s, records, tallies, fresh, cycles, change, balance, converged, state)


def _wave(courant, pipes, schedule):
    """The fastest wave [m/s] of a cycle whose largest Courant number was ``courant``."""
    cell = min(pipes[j, kn.PIPE_DX] for j in range(2) if pipes[j, kn.PIPE_PRESENT] > 0.0)
    return courant * cell / schedule.par[kn.DT]


def _pipes(engine):
    """The runners' rows of :func:`.kernel.run_cycle`: cell length, diameter, area, friction, present."""
    pipes = np.zeros((2, 5))
    for j, runner in enumerate((engine.intake_runner, engine.exhaust_runner)):
        if runner is not None:
            n = runner.cells
            pipes[j] = [runner.length / n, runner.diameter, np.pi * runner.diameter**2 / 4.0, float(runner.friction),
                        1.0]
    return pipes


def _first_wave(engine, condition):
    """The first cycle's estimate of the fastest wave in the runners [m/s] and the hot temperature [K] of the
    cylinder's filling time: 1.3 times the sound speed of the burned gas at 1.5 times the hotter plenum (a fired
    engine's exhaust at :data:`FIRED_START_TEMPERATURE` when its plenum's is not given)."""
    t_i, t_e = condition.intake.temperature, condition.exhaust.temperature
    if t_e is None:
        t_e = t_i if engine.firing is None else FIRED_START_TEMPERATURE
    burned = gases.air() if engine.firing is None else gases.burned_gas(engine.firing.fuel,
                                                                         engine.firing.equivalence_ratio)
    t_hot = max(t_i, t_e) * 1.5
    return 1.3 * float(np.sqrt(gases.ratio_of_specific_heats(burned, t_hot) * burned.gas_constant * t_hot)), t_hot


def work(engine, condition, max_cycles=MAX_CYCLES) -> float:
    """The cell-steps :func:`breathe` may take at ``condition``: the first cycle's steps times the runners' cells and
    the cylinder (counted as eight cells), times ``max_cycles``; :data:`MAX_WORK` bounds a design's sum."""
    pipes = _pipes(engine)
    wave, t_hot = _first_wave(engine, condition)
    cells = sum(r.cells for r in (engine.intake_runner, engine.exhaust_runner) if r is not None)
    return float(_steps(engine, condition, wave, pipes, gases.air(), t_hot) * (cells + 8) * max_cycles)


def _pipe_energy(q, pipe):
    """Total energy in a runner's cells [J]."""
    return float(q[:, 2].sum() * pipe[kn.PIPE_DX] * pipe[kn.PIPE_AREA]) if q.size else 0.0


def _exhaust_temperature(tallies, runner_gas, pipe):
    """The mean temperature of the gas that flowed into the exhaust plenum in the last cycle [K], None if none did (or
    its mean enthalpy is below the runner gas's zero: a cycle far from repeating, whose plenum keeps its temperature)."""
    mass = tallies[kn.TO_EXHAUST]
    if mass <= 0.0:
        return None
    if pipe[kn.PIPE_PRESENT] > 0.0:
        gamma, r, e0 = runner_gas[:3]
        t = float((tallies[kn.ENERGY_OUT] / mass - e0) / (gamma * r / (gamma - 1.0)))
    else:
        t = float(tallies[kn.EXHAUST_TEMPERATURE] / tallies[kn.EXHAUST_FORWARD])
    return t if np.isfinite(t) and t > 0.0 else None


def _peak(theta, p):
    """The largest pressure and its angle, refined by the parabola through the largest node and its neighbours."""
    k = int(np.argmax(p[:-1]))
    a, b, c = p[k - 1], p[k], p[(k + 1) % (p.size - 1)]
    den = a - 2.0 * b + c
    shift = 0.5 * (a - c) / den if den < 0.0 else 0.0
    step = theta[1] - theta[0]
    return float(b - 0.25 * (a - c) * shift), float(theta[k] + shift * step)


def _result(engine, condition, s, records, tallies, fresh, cycles, change, balance, converged, state):
    cyl = engine.cylinder
    vd = cyl.swept_volume
    omega = condition.speed
    p_i, t_i = condition.intake.pressure, condition.intake.temperature
    rho_i = p_i / (fresh.gas_constant * t_i)
    delivered = tallies[kn.DELIVERED]
    ivc = int(s.par[kn.IVC])
    trapped = records[kn.REC_M, ivc]
    residual = records[kn.REC_MB, ivc] / trapped
    work, gross = tallies[kn.WORK], tallies[kn.GROSS_WORK]
    peak, peak_angle = _peak(s.theta, records[kn.REC_P])
    fired = engine.firing is not None
    torque = work * engine.cylinders / CYCLE if fired else None
    out = tallies[kn.EXHAUST_FORWARD]
    exhaust_t = tallies[kn.EXHAUST_TEMPERATURE] / out if out > 0.0 else None
    figures = BreathingRecord(
        omega, p_i, t_i, condition.exhaust.pressure, condition.wall_temperature,
        delivered * engine.cylinders * omega / CYCLE, delivered / (rho_i * vd), trapped, residual,
        tallies[kn.INTAKE_BACK], tallies[kn.EXHAUST_BACK], (gross - work) / vd, work / vd, gross / vd, peak, peak_angle,
        exhaust_t, tallies[kn.WALL_HEAT], torque, torque * omega if fired else None, cycles, change, balance)
    columns = BreathingColumns(s.theta, s.sched[kn.VOLUME], records[kn.REC_P], records[kn.REC_T], records[kn.REC_M],
                               records[kn.REC_MB], records[kn.REC_INTAKE], records[kn.REC_EXHAUST],
                               records[kn.REC_INTAKE_PORT], records[kn.REC_EXHAUST_PORT])
    return BreathingResult(figures, columns, converged, state)

