"""Simulation of a hydraulic valve drive over camshaft angle: plunger chamber, pipe, actuator chamber, valve.

The method is that of Shang Hanji (1988), ch. 7; the pipe is solved by the method of characteristics of
Wylie and Streeter (1978) (:mod:`valvetrain.hydraulic_actuation.moc`) and the two chambers and the valve are
implicit (backward Euler) boundary conditions of it, solved with the end characteristic in one linear
step, so that a stiff (nearly incompressible) liquid is stable.

Pump chamber at x = 0, with fill and relief valves, leakage and a lost-motion drive's solenoid valve to its
accumulator (an orifice, open outside the solenoid's shut window, :class:`~.components.Solenoid`):

    (V_p / K) dp_0/dt = A_p dx_p/dt - A u(0) - Q_leak,p + Q_fill - Q_relief - Q_s
    Q_s = C_d A_s sign(p_0 - p_acc) sqrt(2 |p_0 - p_acc| / rho)

Actuator chamber at x = L and the valve (one degree of freedom between a rigid seat and a stiff stop), with the
hydraulic brake's force B(y) v^2 on a closing valve (:func:`~.components.brake_coefficient`, 0 without a brake):

    (V_a / K) dp_a/dt = A u(L) - A_a dy/dt - Q_leak,a
    M d2y/dt2 = (p_a - p_back) A_a - F_0 - K_s y - C dy/dt - F_gas(t) - K_stop max(y - y_stop, 0) + F_seat
                + B(y) (dy/dt)^2 [dy/dt < 0]

The solenoid's orifice makes the pump chamber's backward-Euler equation quadratic in sqrt|p_0 - p_acc|, the brake
the valve's quadratic in its new velocity: both are solved in closed form, so a large orifice or a strong brake stays
stable.

F_gas is a given force that pushes the valve towards its seat (the cylinder pressure on the valve head, less the
port's).  The seat holds y >= 0: a valve that would move into it stops there (an inelastic impact), and F_seat is
the reaction that keeps it there; the seating velocity is the valve's velocity over the last step before the seat
stops it.  The stop ends the valve's travel at y_stop: a spring of rate K_stop (the stop and the valve's stem)
that acts only beyond it.  The chamber volumes are held at their rest values (linear
compressibility).  Pressures below the vapour pressure are clamped to it (see
:mod:`valvetrain.hydraulic_actuation.moc`).
"""

from dataclasses import dataclass
import math
from typing import Optional

import numpy as np
from numba import njit

from ..dynamics.events import BOUNCE_TOLERANCE, bounce, seating
from .components import brake_coefficient
from .moc import characteristics, interior

SEATED = 1e-9
"""A valve lift below which the valve is on its seat [m] (:meth:`DriveResult.seating`): far below a time step's
travel at any landing velocity, far above the round-off the impact step leaves."""


@njit(cache=True)
def _chamber(capacity, old, source, conductances, references):
    """Backward-Euler pressure of a chamber: capacity (P - old) = source + sum g_j (p_j - P) [Pa]."""
    num = capacity * old + source
    den = capacity
    for j in range(conductances.size):
        num += conductances[j] * references[j]
        den += conductances[j]
    return num / den


@njit(cache=True)
def _orifice_chamber(capacity, old, source, conductances, references, orifice, p_r):
    """Backward-Euler pressure P of a chamber with an orifice to a reservoir at ``p_r`` besides the conductances:
    capacity (P - old) = source + sum g_j (p_j - P) - orifice sign(P - p_r) sqrt|P - p_r| [Pa].

    With den = capacity + sum g_j and D = capacity old + source + sum g_j p_j - den p_r, P = p_r + sign(D) x^2 where
    den x^2 + orifice x = |D|, x = 2 |D| / (orifice + sqrt(orifice^2 + 4 den |D|)) (the root without cancellation)."""
    linear = _chamber(capacity, old, source, conductances, references)
    if orifice == 0.0:
        return linear
    den = capacity
    for j in range(conductances.size):
        den += conductances[j]
    excess = den * (linear - p_r)
    x = 2.0 * abs(excess) / (orifice + math.sqrt(orifice * orifice + 4.0 * den * abs(excess)))
    return p_r + math.copysign(x * x, excess)


@njit(cache=True)
def _braked(stiffness, rest, brake):
    """The new velocity v of the valve's backward-Euler equation stiffness v = rest + brake v^2 [v < 0] [m/s]: the
    brake acts only on a closing valve, and the root taken is the closing one, w = -v = 2 |rest| / (stiffness +
    sqrt(stiffness^2 + 4 brake |rest|))."""
    if rest >= 0.0 or brake == 0.0:
        return rest / stiffness
    return -2.0 * -rest / (stiffness + math.sqrt(stiffness * stiffness - 4.0 * brake * rest))


@njit(cache=True)
def _valve_step(act_capacity, p_old, g, ref, act_area, vapour, stiffness, numerator, brake):
    """Backward-Euler actuator pressure and valve velocity of one step, the valve's equation written as
    v = alpha + beta p_a with alpha = numerator / stiffness, beta = A_a / stiffness, and with the brake's force
    brake v^2 on a closing valve: (p_a, v, clamped)."""
    alpha = numerator / stiffness
    g[2] = act_area * act_area / stiffness
    pa = _chamber(act_capacity, p_old, -act_area * alpha, g, ref)
    clamped = pa < vapour
    if clamped:      # the valve is pushed by the vapour pressure, not by a tension of the liquid
        pa = vapour
    v = alpha + act_area / stiffness * pa
    if brake > 0.0 and v < 0.0:     # braked closing: the chamber's pressure P = (n0 - A_a v) / d0 into the valve's
        g[2] = 0.0
        d0 = act_capacity + g[0] + g[1]
        n0 = act_capacity * p_old + g[0] * ref[0] + g[1] * ref[1]
        v = _braked(stiffness + act_area * act_area / d0, numerator + act_area * n0 / d0, brake)
        pa = (n0 - act_area * v) / d0
        clamped = pa < vapour
        if clamped:
            pa = vapour
            v = _braked(stiffness, numerator + act_area * vapour, brake)
    return pa, v, clamped


@njit(cache=True)
def _drive_kernel(plunger, gas, dt, n_reaches, impedance, friction, area, vapour, p_init, p_back,
                  pump_area, pump_capacity, pump_leak, p_fill, g_fill, p_relief, g_relief,
                  act_area, act_capacity, act_leak, mass, rate, preload, damping, stop, stop_rate,
                  bypass, p_acc, brake_travel, brake_end, brake_open, brake_cd, density):
    steps = plunger.size
    p = np.full(n_reaches + 1, p_init)
    u = np.zeros(n_reaches + 1)
    out = np.zeros((steps, 8))
    flags = np.zeros((steps, 3), dtype=np.bool_)
    y = 0.0
    v = 0.0
    leaked = 0.0
    bypassed = 0.0
    g = np.empty(3)
    ref = np.empty(3)
    out[0, 0] = p_init
    out[0, 1] = p_init
    out[0, 7] = p_init
    n = n_reaches
    for k in range(1, steps):
        cp, cm = characteristics(p, u, impedance, friction)
        flags[k, 1] = interior(p, u, cp, cm, impedance, vapour)
        # pump chamber: fill valve or relief valve opened when the closed solution calls for it
        source = pump_area * (plunger[k] - plunger[k - 1]) / dt
        g[0] = area / impedance
        ref[0] = cm[0]
        g[1] = pump_leak
        ref[1] = p_back
        g[2] = 0.0
        ref[2] = 0.0
        p0 = _orifice_chamber(pump_capacity, p[0], source, g, ref, bypass[k], p_acc)
        if g_fill > 0.0 and p0 < p_fill:
            g[2] = g_fill
            ref[2] = p_fill
            p0 = _orifice_chamber(pump_capacity, p[0], source, g, ref, bypass[k], p_acc)
        elif g_relief > 0.0 and p0 > p_relief:
            g[2] = g_relief
            ref[2] = p_relief
            p0 = _orifice_chamber(pump_capacity, p[0], source, g, ref, bypass[k], p_acc)
        leaked += dt * (pump_leak * (p0 - p_back) - g[2] * (ref[2] - p0))
        bypassed += dt * bypass[k] * math.copysign(math.sqrt(abs(p0 - p_acc)), p0 - p_acc)
        if p0 < vapour:
            p0 = vapour
            flags[k, 0] = True
        p[0] = p0
        u[0] = (p0 - cm[0]) / impedance
        # actuator chamber and valve: the new valve speed is linear in the new chamber pressure
        g[0] = area / impedance
        ref[0] = cp[n]
        g[1] = act_leak
        ref[1] = p_back
        ref[2] = 0.0
        stiffness = mass / dt + rate * dt + damping
        numerator = mass * v / dt - p_back * act_area - preload - rate * y - gas[k]
        brake = brake_coefficient(y, brake_travel, brake_end, brake_open, act_area, density, brake_cd)
        pa, v_new, clamped = _valve_step(act_capacity, p[n], g, ref, act_area, vapour, stiffness, numerator, brake)
        if y + dt * v_new > stop:   # on the stop: its spring acts on the new position y + dt v
            pa, v_new, clamped = _valve_step(act_capacity, p[n], g, ref, act_area, vapour,
                                             stiffness + stop_rate * dt, numerator - stop_rate * (y - stop), brake)
        if y + dt * v_new < 0.0:
            v_new = -y / dt
            g[2] = 0.0
            pa = _chamber(act_capacity, p[n], -act_area * v_new, g, ref)
            clamped = pa < vapour
            if clamped:
                pa = vapour
        flags[k, 2] = clamped
        leaked += dt * act_leak * (pa - p_back)
        p[n] = pa
        u[n] = (cp[n] - pa) / impedance
        v = v_new
        y = y + dt * v
        stored = 0.0
        for i in range(n + 1):
            stored += (0.5 if i == 0 or i == n else 1.0) * (p[i] - p_init)
        out[k, 0] = p[0]
        out[k, 1] = p[n]
        out[k, 2] = y
        out[k, 3] = v
        out[k, 4] = leaked
        out[k, 5] = stored
        out[k, 6] = bypassed
        out[k, 7] = pa + (brake * v * v / act_area if v < 0.0 else 0.0)
    return out, flags


@dataclass(frozen=True)
class DriveResult:
    """The response of a hydraulic valve drive over camshaft angle (SI).

    Attributes
    ----------
    angle : ndarray
        Camshaft angle [rad from the nose of the law].
    time : ndarray
        Time from the start [s].
    plunger_lift : ndarray
        Plunger (follower) lift h [m].
    pump_pressure, actuator_pressure : ndarray
        Absolute pressures at the pump end and the actuator end of the pipe [Pa].
    valve_lift, valve_velocity : ndarray
        y [m] and dy/dt [m/s].
    rigid_lift : ndarray
        Valve lift of the rigid, incompressible drive h A_p / A_a [m].
    gas_force : ndarray
        The given force that pushes the valve towards its seat [N] (0 without one).
    leaked_volume : ndarray
        Net volume let out of the drive by the leaks and the relief valve, less the fill valve's [m^3].
    pipe_stored_volume : ndarray
        Liquid volume stored in the pipe by compression and wall expansion, against the rest state [m^3].
    cavitation_pump, cavitation_pipe, cavitation_actuator : ndarray of bool
        Where the pressure was clamped at the vapour pressure.
    wave_speed, time_step : float
        a [m/s] and dt [s].
    stop : float
        Lift at which the valve meets its stop [m] (inf: none).
    bypassed_volume : ndarray or None
        Net volume the solenoid valve has let out of the pump chamber to the accumulator [m^3] (None: no solenoid).
    solenoid_share : ndarray or None
        The open share of the solenoid valve's flow area, 0 (shut) to 1 (None: no solenoid).
    brake_pressure : ndarray
        Absolute pressure under the actuator piston [Pa]: the actuator chamber's plus the brake's B v^2 / A_a on a
        closing valve (the actuator's pressure without a brake).
    """

    angle: np.ndarray
    time: np.ndarray
    plunger_lift: np.ndarray
    pump_pressure: np.ndarray
    actuator_pressure: np.ndarray
    valve_lift: np.ndarray
    valve_velocity: np.ndarray
    rigid_lift: np.ndarray
    gas_force: np.ndarray
    leaked_volume: np.ndarray
    pipe_stored_volume: np.ndarray
    cavitation_pump: np.ndarray
    cavitation_pipe: np.ndarray
    cavitation_actuator: np.ndarray
    wave_speed: float
    time_step: float
    stop: float = math.inf
    bypassed_volume: Optional[np.ndarray] = None
    solenoid_share: Optional[np.ndarray] = None
    brake_pressure: Optional[np.ndarray] = None

    @property
    def cavitation(self) -> np.ndarray:
        """True where the pressure was at the vapour pressure anywhere in the drive."""
        return self.cavitation_pump | self.cavitation_pipe | self.cavitation_actuator

    @property
    def max_pressure(self) -> float:
        """Largest pressure at either end of the pipe [Pa]."""
        return float(max(self.pump_pressure.max(), self.actuator_pressure.max()))

    @property
    def max_pressure_angle(self) -> float:
        """Camshaft angle of :attr:`max_pressure` [rad]."""
        both = np.maximum(self.pump_pressure, self.actuator_pressure)
        return float(self.angle[np.argmax(both)])

    @property
    def lift_loss(self) -> float:
        """Largest rigid lift less the largest valve lift [m]."""
        return float(self.rigid_lift.max() - self.valve_lift.max())

    @property
    def stop_reached(self) -> bool:
        """True when the valve reached its stop (:attr:`stop`)."""
        return bool(self.valve_lift.max() >= self.stop)

    @property
    def residual_lift(self) -> float:
        """The valve's lift at the end of the record [m]: by default the revolution ends where the plunger is about
        to lift again, so a valve above its seat there has not closed before its next opening."""
        return float(self.valve_lift[-1])

    def lift_off(self) -> int:
        """Index of the first step at which the valve is off its seat (the record's length if it never is)."""
        off = np.flatnonzero(self.valve_lift > 0.0)
        return int(off[0]) if off.size else self.angle.size

    def crossings(self, lift, level) -> tuple[float, float]:
        """First rising and last falling camshaft angles [rad] where ``lift`` crosses ``level`` [m],
        linearly interpolated ((nan, nan) if it never does)."""
        above = np.flatnonzero(lift > level)
        if above.size == 0 or above[0] == 0:
            return math.nan, math.nan
        i, j = above[0], above[-1]
        rise = np.interp(level, lift[i - 1:i + 1], self.angle[i - 1:i + 1])
        if j + 1 >= lift.size:
            return float(rise), math.nan
        fall = np.interp(level, lift[j:j + 2][::-1], self.angle[j:j + 2][::-1])
        return float(rise), float(fall)

    def seating(self, tolerance=BOUNCE_TOLERANCE) -> tuple[float, float, float]:
        """The valve's first return to its seat after its largest lift, and the bounce after it.

        Parameters
        ----------
        tolerance : float
            Lift above the seat that counts as a bounce [m].

        Returns
        -------
        (float, float, float)
            Camshaft angle [rad] and the valve's velocity [m/s] at the first seating (negative: closing; both nan
            if the valve does not open or does not return within the record); the largest lift after it [m] (0
            without a bounce).

        Notes
        -----
        The seat stops the valve within a time step (an inelastic impact on a rigid seat), so the velocity at
        seating is that of the last step before it, a time step L / (N a) earlier.  A sample within
        :data:`SEATED` of the seat is on it: the impact step can leave the valve a round-off above the seat, whose
        velocity, already slowed by the seat, is not the landing's (a speed one unit in the last place different
        read 0.03 instead of 0.25 m/s).

        References
        ----------
        Shang Hanji (1988), ch. 3 (seating velocity and bounce) and ch. 7.
        """
        i, angle, _ = seating(self.angle, np.where(self.valve_lift < SEATED, 0.0, self.valve_lift),
                              self.valve_velocity)
        if i == self.angle.size:
            return math.nan, math.nan, 0.0
        return angle, float(self.valve_velocity[i - 1]), bounce(self.valve_lift, i, tolerance)[0]

    def delays(self, fraction=0.05) -> tuple[float, float]:
        """Opening and closing delays of the valve against the rigid drive [rad camshaft].

        Parameters
        ----------
        fraction : float
            The lift level of the comparison, a fraction of the largest rigid lift [-].

        Returns
        -------
        (float, float)
            Angle at which the valve passes the level on opening, less the rigid drive's; the same on
            closing (positive: the valve is late).
        """
        level = fraction * float(self.rigid_lift.max())
        open_v, close_v = self.crossings(self.valve_lift, level)
        open_r, close_r = self.crossings(self.rigid_lift, level)
        return open_v - open_r, close_v - close_r


def simulate(law, drive, cam_speed, start=None, span=2.0 * math.pi, gas_force=None) -> DriveResult:
    """Response of a hydraulic valve drive to a cam lift law at a constant camshaft speed.

    Parameters
    ----------
    law : valvetrain.laws.LiftLaw
        The plunger (follower) lift h(theta) [m] against camshaft angle [rad].
    drive : valvetrain.hydraulic_actuation.HydraulicDrive
    cam_speed : float
        Camshaft speed omega [rad/s].
    start : float, optional
        First camshaft angle [rad from the nose]; by default 0.1 rad before the law starts.
    span : float
        Camshaft angle simulated [rad] (one revolution by default).
    gas_force : callable, optional
        ``gas_force(angle)``: the force that pushes the valve towards its seat [N] at camshaft angles [rad from the
        nose] (the cylinder pressure on the valve head less the port's); none by default.

    Returns
    -------
    DriveResult
        On the characteristic grid, dt = L / (N a).

    Notes
    -----
    The equations are those of the module docstring.  The plunger speed of a step is the lift difference
    over the step, so that the displaced volume is exact; the gas force is taken at the end of the step (backward
    Euler, as the other forces).  The rigid equivalent is h A_p / A_a.

    References
    ----------
    Shang Hanji (1988), ch. 7; Wylie and Streeter (1978), method of characteristics.
    """
    fluid, pipe, pump, actuator, valve = drive.fluid, drive.pipe, drive.pump, drive.actuator, drive.valve
    a = drive.wave_speed
    dt = drive.time_step
    start = law.start - 0.1 if start is None else start
    steps = int(math.ceil(span / cam_speed / dt)) + 1
    time = np.arange(steps) * dt
    angle = start + cam_speed * time
    lift = law.lift(angle)
    gas = np.zeros(steps) if gas_force is None else np.asarray(gas_force(angle), dtype=float)
    impedance = fluid.density * a
    friction = impedance * dt * pipe.friction_factor / (2.0 * pipe.diameter)
    K = fluid.bulk_modulus
    solenoid, brake = drive.solenoid, drive.brake
    share = None if solenoid is None else solenoid.share(angle, cam_speed)
    bypass = np.zeros(steps) if solenoid is None else share * solenoid.orifice(fluid.density)
    p_acc = drive.initial_pressure if solenoid is None else solenoid.accumulator_pressure
    brake_args = (0.0, 0.0, 1.0, 1.0) if brake is None else (brake.travel, brake.end_area, brake.open_area,
                                                             brake.discharge_coefficient)
    out, flags = _drive_kernel(
        lift, gas, dt, int(pipe.reaches), impedance, friction, pipe.area, fluid.vapour_pressure,
        drive.initial_pressure, drive.back_pressure,
        pump.plunger_area, pump.volume / (K * dt), pump.leakage, pump.fill_pressure, pump.fill_conductance,
        pump.relief_pressure, pump.relief_conductance,
        actuator.piston_area, actuator.volume / (K * dt), actuator.leakage,
        valve.mass, valve.spring_rate, valve.preload, valve.damping, valve.stop, valve.stop_rate,
        bypass, p_acc, *brake_args, fluid.density)
    reach = pipe.length / pipe.reaches
    return DriveResult(
        angle=angle, time=time, plunger_lift=lift, pump_pressure=out[:, 0], actuator_pressure=out[:, 1],
        valve_lift=out[:, 2], valve_velocity=out[:, 3], rigid_lift=lift * drive.area_ratio, gas_force=gas,
        leaked_volume=out[:, 4], pipe_stored_volume=out[:, 5] * pipe.area * reach / (impedance * a),
        cavitation_pump=flags[:, 0], cavitation_pipe=flags[:, 1], cavitation_actuator=flags[:, 2],
        wave_speed=a, time_step=dt, stop=valve.stop, bypassed_volume=None if solenoid is None else out[:, 6],
        solenoid_share=share, brake_pressure=out[:, 7])


@dataclass(frozen=True)
class SpeedSweep:
    """The drive's response at several camshaft speeds (SI), one entry per speed.

    Attributes
    ----------
    cam_speed : ndarray
        Camshaft speed omega [rad/s].
    max_pressure : ndarray
        Largest pressure at either end of the pipe [Pa].
    valve_lift, lift_loss : ndarray
        Largest valve lift and the rigid drive's largest lift less it [m].
    opening_delay, closing_delay : ndarray
        Delays against the rigid drive at ``fraction`` of its largest lift [rad camshaft] (nan: never reached).
    cavitation : ndarray of bool
        The pressure fell to the vapour pressure somewhere during the revolution.
    seating_velocity, bounce : ndarray
        The valve's velocity at its first seating [m/s] (nan: it does not return) and its largest lift after it
        [m] (:meth:`DriveResult.seating`).
    residual_lift : ndarray
        The valve's lift at the end of the revolution [m] (:attr:`DriveResult.residual_lift`).
    stop_reached : ndarray of bool
        The valve reached its stop (:attr:`DriveResult.stop_reached`).
    """

    cam_speed: np.ndarray
    max_pressure: np.ndarray
    valve_lift: np.ndarray
    lift_loss: np.ndarray
    opening_delay: np.ndarray
    closing_delay: np.ndarray
    cavitation: np.ndarray
    seating_velocity: np.ndarray
    bounce: np.ndarray
    residual_lift: np.ndarray
    stop_reached: np.ndarray


def speed_sweep(law, drive, cam_speeds, fraction=0.05, **kwargs) -> SpeedSweep:
    """One revolution of the drive (:func:`simulate`) at each camshaft speed of ``cam_speeds`` [rad/s].

    ``fraction`` is the lift level of the delays (:meth:`DriveResult.delays`); ``kwargs`` go to :func:`simulate`.

    References
    ----------
    Shang Hanji (1988), ch. 7.
    """
    speeds = np.asarray(cam_speeds, dtype=float)
    rows = []
    for omega in speeds:
        r = simulate(law, drive, float(omega), **kwargs)
        _, seat_velocity, height = r.seating()
        rows.append((r.max_pressure, float(r.valve_lift.max()), r.lift_loss, *r.delays(fraction),
                     bool(r.cavitation.any()), seat_velocity, height, r.residual_lift, r.stop_reached))
    cols = [np.array(c, dtype=float) for c in zip(*rows, strict=True)] if rows else [np.zeros(0)] * 10
    return SpeedSweep(speeds, *cols[:5], cols[5].astype(bool), *cols[6:9], cols[9].astype(bool))
