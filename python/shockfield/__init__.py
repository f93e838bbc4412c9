"""shockfield from Python: cases, run folders and the field analysis on numpy arrays.

    import shockfield
    case = shockfield.Case.load("examples/mpm_porous_al/case.toml")
    case.set("loading.speed", 800.0)
    run = case.run(output="runs/al_800", threads=2)
    run.summary["results"], run.series["time_s"]
    shockfield.analysis.minkowski(field, count=16)

``Case`` runs the ``shockfield`` command (the same binary, so results are bitwise those of the
command line); ``Run`` reads any method's run folder; ``analysis`` calls the C++ analysis on
numpy arrays in-process (module ``shockfield._core``). Documentation: docs/python.md.
"""

from .errors import InputError, RunError, StaleViewError, StopRequested
from .box import Box
from .case import Case, shockfield_command
from .run import Run
from .simulation import Simulation
from . import analysis, sweep

__version__ = analysis.__version__
__all__ = ["Box", "Case", "Run", "Simulation", "analysis", "InputError", "RunError", "StaleViewError", "StopRequested",
           "shockfield_command", "sweep"]
