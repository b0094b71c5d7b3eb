"""Hydraulic valve actuation: a cam-driven plunger feeds a pipe that drives an actuator piston on the valve
(Shang Hanji (1988), ch. 7), the pipe solved by the method of characteristics of Wylie and Streeter (1978); a
lost-motion drive's solenoid valve to an accumulator and hydraulic brake (Bernard et al. (2009))."""

from .components import (Actuator, Brake, Fluid, HydraulicDrive, Pipe, Pump, Solenoid, Valve, brake_coefficient,
                         orifice_flow, wave_speed)
from .drive import DriveResult, SpeedSweep, simulate, speed_sweep
from .moc import PRESSURE, VELOCITY, pipe_transient

__all__ = ["Actuator", "Brake", "DriveResult", "Fluid", "HydraulicDrive", "PRESSURE", "Pipe", "Pump", "Solenoid",
           "SpeedSweep", "VELOCITY", "Valve", "brake_coefficient", "orifice_flow", "pipe_transient", "simulate",
           "speed_sweep", "wave_speed"]
