"""flexmb from Python: build, run, reduce and post-process with numpy.

The compiled core (flexmb._core) holds the engine; this package adds the
pure-Python helpers: models from dicts, results as numpy arrays, FE and body
files, the truck lane change, parameter studies (in processes, or from a
study file on a Dask cluster), static equilibrium, linearized modes and
state-space models, and plots. See docs/python.md.
"""

from ._core import Error, InputError, NumericalError, Input, Simulation
from .model import load, from_dict, from_yaml, check
from .results import Results, read_results
from .commands import run_file, fe_modes, fe_mode_shapes, fe_info, fe_export, reduce, body_info
from .bodies import Body, read_body
from .vehicle import LaneChangeResult, driver_sensitivity, lane_change, max_pass_speed, truck_handling
from .study import run_study, Table
from .studyfile import load_study
from .studies import study
from .analysis import StaticsResult, ModesResult, StateSpace, statics, modes, linearize, read_mtx

__all__ = [
    "Error", "InputError", "NumericalError", "Input", "Simulation",
    "load", "from_dict", "from_yaml", "check",
    "Results", "read_results",
    "run_file", "fe_modes", "fe_mode_shapes", "fe_info", "fe_export", "reduce", "body_info",
    "Body", "read_body",
    "LaneChangeResult", "driver_sensitivity", "lane_change", "max_pass_speed", "truck_handling",
    "run_study", "Table", "load_study", "study",
    "StaticsResult", "ModesResult", "StateSpace", "statics", "modes", "linearize", "read_mtx",
]
