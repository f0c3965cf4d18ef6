"""Models: from a model file, from YAML text, or from Python dicts with the
keys of the model file (docs/model-file.md)."""

import json

from . import _core
from .results import Results


def load(path, manoeuvre=None):
    """Loads a YAML model file, with one of its `manoeuvres` if named;
    returns a Simulation (errors as `flexmb run`)."""
    return _core.Simulation.from_file(str(path), manoeuvre or "")


def from_yaml(text, name="<string>"):
    """Loads model-file text; `name` stands for the file in error messages."""
    return _core.Simulation.from_string(text, name)


def to_yaml(model):
    """The model-file text of a dict (JSON is YAML: the same parser reads it;
    one key or list entry per line so that messages name useful lines)."""
    return json.dumps(model, indent=1)


def from_dict(model, name="<dict>"):
    """A Simulation of a model given as nested dicts and lists with the keys
    of the model file (bodies, joints, forces, sensors, solver, output, ...)."""
    return from_yaml(to_yaml(model), name)


def check(model):
    """`flexmb check` of a model file: the report text."""
    return _core.check_report(str(model))


def _results(sim):
    """The rows recorded so far as Results (copies)."""
    return Results(sim.result_arrays())


def _repr(sim):
    return f"Simulation({sim.name!r}, t = {sim.t:g} s)"


# Simulation.results(): the recorded rows as a Results object
_core.Simulation.results = _results
_core.Simulation.__repr__ = _repr
