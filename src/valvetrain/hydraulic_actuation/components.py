"""The parts of a hydraulic valve drive: the liquid, the pipe, the pump (plunger) chamber, the actuator
chamber and the valve, as small frozen dataclasses in SI units, with the wave speed of the liquid in an
elastic pipe.

The drive is the one of Shang Hanji (1988), ch. 7: a cam-driven plunger feeds a pipe that drives an
actuator piston on the valve.  Pressures are absolute [Pa]; forces on the valve are taken from the
pressure above the back (drain) pressure.  The liquid and pipe formulas are those of Wylie and Streeter (1978).

A lost-motion drive (the MultiAir/UniAir intake of Bernard et al. (2009)) adds a solenoid valve that bypasses the
pump chamber's oil to an accumulator, so that the valve closes before the cam does (or opens after it), and a
hydraulic brake that slows the valve in its last travel before the seat; both are orifices (Merritt (1967)).
"""

from dataclasses import dataclass
import math
from typing import Optional

import numpy as np
from numba import njit


def wave_speed(bulk_modulus, density, diameter=0.0, wall_thickness=math.inf, wall_modulus=math.inf,
               restraint=1.0) -> float:
    """Speed of a pressure wave in a liquid-filled pipe [m/s].

    Parameters
    ----------
    bulk_modulus : float
        Bulk modulus of the liquid K [Pa].
    density : float
        Density of the liquid rho [kg/m^3].
    diameter : float
        Inner diameter of the pipe d [m] (0: a rigid pipe).
    wall_thickness : float
        Wall thickness e [m] (inf: a rigid pipe).
    wall_modulus : float
        Young's modulus of the wall E [Pa] (inf: a rigid pipe).
    restraint : float
        Pipe restraint factor c1 [-] (1 for a thin-walled pipe with expansion joints).

    Returns
    -------
    float
        a [m/s].

    Notes
    -----
    a = sqrt((K / rho) / (1 + c1 K d / (E e))), the Korteweg correction for the elasticity of the wall; a
    rigid pipe gives the speed of sound in the liquid sqrt(K / rho).

    References
    ----------
    Wylie and Streeter (1978), wave speed in an elastic pipe.

    Examples
    --------
    Water (K = 2.2 GPa, rho = 1000 kg/m^3) in a rigid pipe, then in a steel pipe (E = 210 GPa) with
    d / e = 20:

    >>> round(wave_speed(2.2e9, 1000.0), 1)
    1483.2
    >>> round(wave_speed(2.2e9, 1000.0, 0.02, 0.001, 210e9), 1)
    1348.7
    """
    stiffening = restraint * bulk_modulus * diameter / (wall_modulus * wall_thickness) if diameter else 0.0
    return math.sqrt(bulk_modulus / density / (1.0 + stiffening))


def orifice_flow(area, pressure_drop, density, discharge_coefficient=0.7) -> np.ndarray:
    """Turbulent flow through a sharp-edged orifice [m^3/s], in the direction of the pressure drop.

    Parameters
    ----------
    area : float or ndarray
        Flow area of the orifice A [m^2].
    pressure_drop : float or ndarray
        Upstream less downstream pressure dp [Pa] (negative: the flow reverses).
    density : float
        rho [kg/m^3].
    discharge_coefficient : float
        C_d [-] (about 0.6-0.7 for a sharp edge).

    Returns
    -------
    float or ndarray
        Q [m^3/s].

    Notes
    -----
    Q = C_d A sign(dp) sqrt(2 |dp| / rho), Bernoulli's equation to the vena contracta.

    References
    ----------
    Merritt (1967), the orifice equation.

    Examples
    --------
    A 1 mm^2 orifice under 10 MPa of oil (870 kg/m^3), C_d = 0.7: 0.106 l/s, reversed with the drop:

    >>> round(float(orifice_flow(1e-6, 10e6, 870.0)) * 1e6, 2), round(float(orifice_flow(1e-6, -10e6, 870.0)) * 1e6, 2)
    (106.13, -106.13)
    """
    return discharge_coefficient * area * np.sign(pressure_drop) * np.sqrt(2.0 * np.abs(pressure_drop) / density)


@njit(cache=True)
def brake_coefficient(lift, travel, end_area, open_area, piston_area, density, discharge_coefficient) -> float:
    """Coefficient B of the hydraulic brake's force B v^2 on a closing valve [N s^2/m^2].

    Parameters
    ----------
    lift : float
        Valve lift y [m].
    travel : float
        The brake's travel y_b [m]: it closes down over the valve's last y_b before the seat (0: no brake).
    end_area, open_area : float
        Flow area of the brake's orifice at the seat A_0 and from y_b up A_1 [m^2].
    piston_area : float
        The actuator (brake) piston's area A_a [m^2].
    density : float
        rho [kg/m^3].
    discharge_coefficient : float
        C_d [-].

    Returns
    -------
    float
        B [N s^2/m^2] (0 without a brake).

    Notes
    -----
    The closing valve's piston drives its oil, Q = A_a |v|, out through the brake's orifice of area
    A_b(y) = A_0 + (A_1 - A_0) min(y / y_b, 1), which the piston's tapered end closes down as the valve nears its
    seat; the orifice equation gives the pressure under the piston above the actuator chamber's,
    dp = (rho / 2) (A_a v / (C_d A_b))^2, and on the piston the force

        F = A_a dp = B v^2,    B = rho A_a^3 / (2 C_d^2 A_b(y)^2),

    which opposes the closing (the oil under the piston taken as incompressible, its volume being small).  On
    opening a check valve lets the oil past the orifice: the brake acts only on a closing valve.

    References
    ----------
    Merritt (1967), the orifice equation; Bernard et al. (2009), the hydraulic brake of the MultiAir actuator.

    Examples
    --------
    A 16 mm piston (2.01 cm^2) braked through 1 mm^2 at the seat, 10 mm^2 from 1 mm up (oil, C_d = 0.7): B at the
    seat, half-way and above the travel:

    >>> a = math.pi * 0.016**2 / 4
    >>> [round(brake_coefficient(y, 1e-3, 1e-6, 10e-6, a, 870.0, 0.7)) for y in (0.0, 0.5e-3, 2e-3)]
    [7216, 239, 72]
    """
    if travel <= 0.0:
        return 0.0
    share = min(max(lift / travel, 0.0), 1.0)
    area = end_area + (open_area - end_area) * share
    return density * piston_area**3 / (2.0 * discharge_coefficient**2 * area**2)


@dataclass(frozen=True)
class Fluid:
    """The working liquid.

    Attributes
    ----------
    density : float
        rho [kg/m^3].
    bulk_modulus : float
        K [Pa] (with the air it carries, if any).
    vapour_pressure : float
        Absolute pressure below which the liquid cavitates [Pa].
    """

    density: float = 870.0
    bulk_modulus: float = 1.5e9
    vapour_pressure: float = 2.0e3


@dataclass(frozen=True)
class Pipe:
    """The pipe between the pump and the actuator.

    Attributes
    ----------
    length, diameter : float
        L and inner diameter d [m].
    wall_thickness : float
        e [m] (inf: rigid).
    wall_modulus : float
        E [Pa] (inf: rigid).
    friction_factor : float
        Darcy friction factor lambda [-], constant (quasi-steady friction).
    reaches : int
        Number of reaches N of the characteristic grid; the time step is L / (N a).
    """

    length: float
    diameter: float
    wall_thickness: float = math.inf
    wall_modulus: float = math.inf
    friction_factor: float = 0.0
    reaches: int = 20

    @property
    def area(self) -> float:
        """Flow area pi d^2 / 4 [m^2]."""
        return math.pi * self.diameter**2 / 4.0

    def wave_speed(self, fluid) -> float:
        """Wave speed of ``fluid`` in this pipe [m/s] (:func:`wave_speed`)."""
        return wave_speed(fluid.bulk_modulus, fluid.density, self.diameter, self.wall_thickness, self.wall_modulus)


@dataclass(frozen=True)
class Pump:
    """The cam-driven plunger and its chamber.

    Attributes
    ----------
    plunger_area : float
        A_p [m^2]; the plunger lift is the cam follower lift.
    volume : float
        Chamber volume V_p at rest [m^3] (the compressed volume, held constant).
    leakage : float
        Leakage conductance of the plunger clearance [m^3/(s Pa)]: Q = leakage (p - p_back).
    fill_pressure : float
        Supply pressure behind the fill (check) valve [Pa]; it opens when the chamber pressure is below.
    fill_conductance : float
        Conductance of the open fill valve [m^3/(s Pa)] (0: no fill valve).
    relief_pressure : float
        Opening pressure of the relief valve [Pa] (inf: none).
    relief_conductance : float
        Conductance of the open relief valve [m^3/(s Pa)].
    """

    plunger_area: float
    volume: float
    leakage: float = 0.0
    fill_pressure: float = 0.0
    fill_conductance: float = 0.0
    relief_pressure: float = math.inf
    relief_conductance: float = 0.0


@dataclass(frozen=True)
class Actuator:
    """The actuator piston on the valve and its chamber.

    Attributes
    ----------
    piston_area : float
        A_a [m^2].
    volume : float
        Chamber volume V_a at rest [m^3] (held constant).
    leakage : float
        Leakage conductance of the piston clearance [m^3/(s Pa)]: Q = leakage (p - p_back).
    """

    piston_area: float
    volume: float
    leakage: float = 0.0


@dataclass(frozen=True)
class Valve:
    """The valve as one degree of freedom between a rigid seat and a stiff stop.

    Attributes
    ----------
    mass : float
        Moving mass M (valve, piston, a third of the spring) [kg].
    spring_rate : float
        K [N/m].
    preload : float
        Spring force on the seat F_0 [N].
    damping : float
        Viscous damping C [N s/m].
    stop : float
        Lift at which the valve meets its stop, the end of its stroke y_stop [m] (inf: no stop).
    stop_rate : float
        Rate of the stop K_stop [N/m]: beyond y_stop the stop pushes back with K_stop (y - y_stop).
    """

    mass: float
    spring_rate: float
    preload: float
    damping: float = 0.0
    stop: float = math.inf
    stop_rate: float = 0.0


@dataclass(frozen=True)
class Solenoid:
    """The solenoid valve of a lost-motion drive: an orifice from the pump chamber to an accumulator, shut (energised)
    between two camshaft angles and open outside them.

    Attributes
    ----------
    area : float
        Flow area of the open valve A_s [m^2].
    accumulator_pressure : float
        Absolute pressure of the accumulator (the low-pressure side, held by its spring) p_acc [Pa].
    discharge_coefficient : float
        C_d [-].
    closes : float
        Camshaft angle at which the valve starts to shut, trapping the oil [rad from the nose] (-inf: shut from the
        start).
    opens : float
        Camshaft angle at which it starts to open again, letting the oil out to the accumulator [rad from the nose]
        (inf: shut to the end: the valve follows the whole cam).
    stroke_time : float
        Time the valve takes to open or shut [s]: its flow area changes linearly over it (0: at once).

    Notes
    -----
    Open, the valve passes Q = C_d A_s sign(p - p_acc) sqrt(2 |p - p_acc| / rho) (:func:`orifice_flow`): the cam's
    plunger then pushes its oil to the accumulator instead of the actuator, and the engine's valve, no longer held,
    closes on its spring (an early closing); shut later than the cam's lift starts, the valve opens late and
    lifts less (a late opening).  Bernard et al. (2009): the MultiAir valve is normally open.
    """

    area: float
    accumulator_pressure: float
    discharge_coefficient: float = 0.7
    closes: float = -math.inf
    opens: float = math.inf
    stroke_time: float = 0.0

    def share(self, angle, cam_speed) -> np.ndarray:
        """The open share of the valve's flow area at the camshaft angles ``angle`` [rad from the nose] and the
        camshaft speed ``cam_speed`` [rad/s], 0 (shut) to 1.

        Notes
        -----
        With the stroke's angle s = omega t_s: 1 - clip((theta - closes) / s, 0, 1) + clip((theta - opens) / s, 0, 1),
        clipped to [0, 1]; with s = 0, 0 in [closes, opens) and 1 outside.

        >>> valve = Solenoid(1e-6, 0.3e6, closes=-1.0, opens=0.5, stroke_time=0.01)
        >>> valve.share(np.array([-2.0, -0.95, 0.0, 0.55, 1.0]), 10.0).round(12).tolist()
        [1.0, 0.5, 0.0, 0.5, 1.0]
        >>> from dataclasses import replace
        >>> replace(valve, stroke_time=0.0).share(np.array([-2.0, 0.0, 0.5]), 10.0).tolist()
        [1.0, 0.0, 1.0]
        """
        angle = np.asarray(angle, dtype=float)
        stroke = cam_speed * self.stroke_time
        if stroke == 0.0:
            return np.where((angle >= self.closes) & (angle < self.opens), 0.0, 1.0)
        shut = np.clip((angle - self.closes) / stroke, 0.0, 1.0)
        return np.clip(1.0 - shut + np.clip((angle - self.opens) / stroke, 0.0, 1.0), 0.0, 1.0)

    def orifice(self, density) -> float:
        """C_d A_s sqrt(2 / rho) [m^3/(s Pa^0.5)]: the open valve's flow is this times sign(dp) sqrt(|dp|)."""
        return self.discharge_coefficient * self.area * math.sqrt(2.0 / density)


@dataclass(frozen=True)
class Brake:
    """The hydraulic brake of the actuator piston: its orifice closes down over the valve's last travel before the
    seat (:func:`brake_coefficient`).

    Attributes
    ----------
    travel : float
        y_b [m].
    end_area, open_area : float
        A_0 at the seat and A_1 from y_b up [m^2].
    discharge_coefficient : float
        C_d [-].
    """

    travel: float
    end_area: float
    open_area: float
    discharge_coefficient: float = 0.7

    def coefficient(self, lift, piston_area, density) -> float:
        """B at the valve lift ``lift`` [m] of a piston of ``piston_area`` [m^2] in a liquid of ``density``
        [kg/m^3] (:func:`brake_coefficient`) [N s^2/m^2]."""
        return brake_coefficient(lift, self.travel, self.end_area, self.open_area, piston_area, density,
                                 self.discharge_coefficient)


@dataclass(frozen=True)
class HydraulicDrive:
    """The whole drive.

    Attributes
    ----------
    fluid : Fluid
    pipe : Pipe
    pump : Pump
    actuator : Actuator
    valve : Valve
    initial_pressure : float
        Absolute pressure of the liquid at rest, everywhere [Pa].
    back_pressure : float
        Absolute pressure of the drain, under the actuator piston and behind the leaks [Pa].
    solenoid : Solenoid, optional
        The lost-motion drive's solenoid valve from the pump chamber to the accumulator (None: none).
    brake : Brake, optional
        The actuator's hydraulic brake (None: none).
    """

    fluid: Fluid
    pipe: Pipe
    pump: Pump
    actuator: Actuator
    valve: Valve
    initial_pressure: float = 0.3e6
    back_pressure: float = 0.1e6
    solenoid: Optional[Solenoid] = None
    brake: Optional[Brake] = None

    @property
    def area_ratio(self) -> float:
        """A_p / A_a [-]: the valve lift of a rigid, incompressible drive per unit plunger lift."""
        return self.pump.plunger_area / self.actuator.piston_area

    @property
    def wave_speed(self) -> float:
        """Wave speed a in the pipe [m/s]."""
        return self.pipe.wave_speed(self.fluid)

    @property
    def time_step(self) -> float:
        """Time step of the characteristic grid L / (N a) [s]."""
        return self.pipe.length / (self.pipe.reaches * self.wave_speed)
