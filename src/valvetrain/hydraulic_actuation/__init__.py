"""Hydraulic valve actuation: a cam-driven plunger feeds a pipe that drives an actuator piston on the valve
(Shang Hanji (1988), ch. 7), the pipe solved by the method of characteristics of Wylie and Streeter (1978)."""

from .components import Actuator, Fluid, HydraulicDrive, Pipe, Pump, Valve, wave_speed
from .drive import DriveResult, SpeedSweep, simulate, speed_sweep
from .moc import PRESSURE, VELOCITY, pipe_transient

__all__ = ["Actuator", "DriveResult", "Fluid", "HydraulicDrive", "PRESSURE", "Pipe", "Pump", "SpeedSweep", "VELOCITY",
           "Valve", "pipe_transient", "simulate", "speed_sweep", "wave_speed"]
