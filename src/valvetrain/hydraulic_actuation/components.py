"""The parts of a hydraulic valve drive: the liquid, the pipe, the pump (plunger) chamber, the actuator
chamber and the valve, as small frozen dataclasses in SI units, with the wave speed of the liquid in an
elastic pipe.

The drive is the one of Shang Hanji (1988), ch. 7: a cam-driven plunger feeds a pipe that drives an
actuator piston on the valve.  Pressures are absolute [Pa]; forces on the valve are taken from the
pressure above the back (drain) pressure.  The liquid and pipe formulas are those of Wylie and Streeter (1978).
"""

from dataclasses import dataclass
import math


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
    """

    fluid: Fluid
    pipe: Pipe
    pump: Pump
    actuator: Actuator
    valve: Valve
    initial_pressure: float = 0.3e6
    back_pressure: float = 0.1e6

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
