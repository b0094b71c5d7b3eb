"""Gas exchange: the breathing of the engine's cylinders through the designed valves.

One physical domain a module: gas properties from Cantera's species data (:mod:`.gas`), compressible flow through a
restriction (:mod:`.orifice`), the valves' effective areas from lift and C_D(L/D) (:mod:`.valves`), wall heat transfer
(:mod:`.heat_transfer`), the runners' one-dimensional gas dynamics (:mod:`.runners`), the compiled cycle of the
cylinder, valves, runners and plenums (:mod:`.kernel`) and the cycles converged at one speed (:mod:`.cycle`).
"""

from .cycle import (BreathingColumns, BreathingError, BreathingRecord, BreathingResult, Condition, Cylinder, Engine,
                    Firing, Plenum, Runner, ValveFlow, breathe)
from .valves import CdTable, CdTableError

__all__ = ["BreathingColumns", "BreathingError", "BreathingRecord", "BreathingResult", "CdTable", "CdTableError",
           "Condition", "Cylinder", "Engine", "Firing", "Plenum", "Runner", "ValveFlow", "breathe"]
