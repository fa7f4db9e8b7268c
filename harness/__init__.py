"""The servofmu co-simulation harness (importable as ``servofmu.harness``).

Runs SSP 1.0 systems of FMUs with fmpy's FMU2Slave: :func:`load_system` reads and checks a
system (archive or folder) before any FMU is instantiated, :func:`run` co-simulates it
(Gauss-Seidel or Jacobi, fixed step, SSV bindings, LinearTransformation, external signals),
:mod:`.scenarios` reproduces the papers' experiments at system level.
"""

from .errors import HarnessError, SystemError_
from .master import RunResult, run
from .signals import Constant, Cycle, PiecewiseLinear, Ramp, Steps, from_csv
from .system import System, load_system

__all__ = [
    "Constant",
    "Cycle",
    "HarnessError",
    "PiecewiseLinear",
    "Ramp",
    "RunResult",
    "Steps",
    "System",
    "SystemError_",
    "from_csv",
    "load_system",
    "run",
]
