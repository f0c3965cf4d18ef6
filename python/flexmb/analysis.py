"""Static equilibrium, linearized modes and state-space models of a model
(`flexmb statics`, `flexmb modes`, `flexmb linearize`) as numpy data. Each
function calls the same C++ function as the command and, given out_dir,
writes the command's files there too (docs/python.md, docs/cli.md)."""

import json
import os

import numpy as np

from . import _core
from .model import to_yaml


def _model_args(model):
    """(path or name, text) of a model given as a path or as a dict with the
    model file's keys."""
    if isinstance(model, dict):
        return "<dict>", to_yaml(model)
    return os.fspath(model), ""


def _source_args(model, at):
    """(path or name, text, at, simulation) of a model given as a path, a
    dict or a Simulation (linearized about its current state: at None or
    "current"); at None means "statics" for a path or dict."""
    if isinstance(model, _core.Simulation):
        if at not in (None, "current"):
            raise _core.InputError(f"a Simulation is linearized about its current state (at='current'), "
                                   f"not at={at!r}: pass the model file or dict for another state")
        return model.name, "", "current", model
    name, text = _model_args(model)
    return name, text, "statics" if at is None else at, None


def _out(out_dir):
    return "" if out_dir is None else os.fspath(out_dir)


def _raise_if_failed(r):
    """Raises InputError, NumericalError or Error with the command's message."""
    if r["code"] != 0:
        raise getattr(_core, r["error_kind"] or "Error", _core.Error)(r["message"])


class StaticsResult:
    """The static equilibrium of `statics()`.

    q: position coordinates at equilibrium (rigid bodies: p_WC [m], then the
    quaternion w x y z); lam: constraint multipliers; body_q(name): a body's
    entries of q; load_factor (1: the full load), iterations (Newton, all
    load steps), residual [N, N m], load_steps, cuts; table: results.csv as
    a dict of arrays (load_factor, iterations, residual, SENSOR.COMPONENT),
    one entry per load step; sensors: the sensor values at the equilibrium;
    summary: summary.json as a dict; warnings."""

    def __init__(self, r):
        self.model_name = r["model_name"]
        self.q = r["q"]
        self.lam = r["lambda"]
        self._bodies = r["bodies"]
        self.load_factor = r["load_factor"]
        self.iterations = r["iterations"]
        self.residual = r["residual"]
        self.load_steps = r["load_steps"]
        self.cuts = r["cuts"]
        self.dof = r["dof"]
        self.columns = list(r["columns"])
        self.rows = r["rows"]
        self.table = {c: self.rows[:, k] for k, c in enumerate(self.columns)}
        self.sensors = {c: float(self.rows[-1, k]) for k, c in enumerate(self.columns) if k >= 3 and len(self.rows)}
        self.summary = json.loads(r["summary_json"])
        self.warnings = list(r["warnings"])

    @property
    def bodies(self):
        """The body names (ground first)."""
        return list(self._bodies)

    def body_q(self, name):
        """The position coordinates of body `name` at equilibrium (a view of q)."""
        if name not in self._bodies:
            raise KeyError(f"no body named '{name}'")
        off, n = self._bodies[name]
        return self.q[off:off + n]

    def __repr__(self):
        return (f"StaticsResult({self.model_name!r}, load factor {self.load_factor:g}, "
                f"{self.iterations} iterations, residual {self.residual:.3g})")


class ModesResult:
    """The modes of `modes()`, rigid-body modes first, then the vibration
    modes by frequency.

    frequencies_hz (undamped |s|/2pi), damped_frequencies_hz (Im s/2pi),
    damping_ratios, eigenvalues (complex s [1/s]), kinds ("rigid",
    "oscillatory", "overdamped"...), shapes and shapes_imag (nv x modes: one
    column per mode in the velocity coordinates, largest entry 1),
    coordinates (the names of the rows), dof, rigid_modes, time [s] of the
    state; names (lane-change files: each mode's dominant motion, else
    empty); summary: summary.json as a dict; warnings."""

    def __init__(self, r):
        self.model_name = r["model_name"]
        self.frequencies_hz = r["frequencies_hz"]
        self.damped_frequencies_hz = r["damped_frequencies_hz"]
        self.damping_ratios = r["damping_ratios"]
        self.eigenvalues = r["eigenvalues"]
        self.kinds = list(r["kinds"])
        self.shapes = r["shapes"]
        self.shapes_imag = r["shapes_imag"]
        self.coordinates = list(r["coordinates"])
        self.names = list(r["names"])
        self.dof = r["dof"]
        self.rigid_modes = r["rigid_modes"]
        self.time = r["time"]
        self.summary = json.loads(r["summary_json"])
        self.warnings = list(r["warnings"])

    def __len__(self):
        return len(self.kinds)

    def __repr__(self):
        return f"ModesResult({self.model_name!r}, {len(self)} modes, {self.dof} dof)"


class StateSpace:
    """The state-space model x' = A x + B u, y = C x + D u of `linearize()`.

    A, B, C, D: numpy arrays; states (names: "dx COORDINATE" increments,
    then "v COORDINATE" rates, then "driver NAME.position" and "driver NAME.velocity" of driver inputs),
    inputs ("FORCE.fx", ..., "SPRING.tension", "DRIVER.acceleration"),
    outputs ("SENSOR.COMPONENT", deviations from output_values, their values
    at the state); time [s] of the state; summary; warnings."""

    def __init__(self, r):
        self.A, self.B, self.C, self.D = r["A"], r["B"], r["C"], r["D"]
        self.states = list(r["states"])
        self.inputs = list(r["inputs"])
        self.outputs = list(r["outputs"])
        self.output_values = r["output_values"]
        self.time = r["time"]
        self.summary = json.loads(r["summary_json"])
        self.warnings = list(r["warnings"])

    def __repr__(self):
        return f"StateSpace({len(self.states)} states, {len(self.inputs)} inputs, {len(self.outputs)} outputs)"


def statics(model, out_dir=None, time=0.0, animation=False, manoeuvre=None):
    """`flexmb statics`: the static equilibrium of `model` (a model file's
    path or a dict with its keys) under gravity and the loads at `time` [s],
    with load stepping; `manoeuvre`: the entry of the file's `manoeuvres`
    to apply (None: the file's own choice), as `--manoeuvre`. out_dir: also
    write results.csv, summary.json (and with animation, anim.pvd) there as
    the command does. Raises InputError or NumericalError (no equilibrium:
    naming the body or joint and the load factor reached) with the
    command's message."""
    name, text = _model_args(model)
    r = _core.statics(name, text, _out(out_dir), float(time), animation, manoeuvre or "")
    _raise_if_failed(r)
    return StaticsResult(r)


def modes(model, at=None, count=10, time=0.0, out_dir=None, animation=True, frames=24, amplitude=0.1,
          frame=None):
    """`flexmb modes`: the modes of `model` (path, dict or Simulation)
    linearized about the state `at`: "statics" (the default for a path or
    dict: the static equilibrium at `time`), "initial" (the consistent
    initial state at `time`), "time" (a dynamic run to `time` [s]) or, for a
    Simulation, "current" (its state now, e.g. after run() or step(), with
    the inputs as set); all rigid-body modes and the `count` lowest
    vibration modes. out_dir: also write modes.csv, modes.json, summary.json
    and (animation) mode_<k>/anim.pvd there as the command does. A
    lane-change file (examples/truck_lane_change/truck.yaml): the truck
    standing on its tires, frame "rigid" or "elastic" (None: the file's),
    and `names` the modes' dominant motions ("bounce", "pitch", "front axle
    hop", ...)."""
    name, text, at, sim = _source_args(model, at)
    r = _core.modes(name, text, _out(out_dir), at, float(time), int(count), animation, int(frames),
                    float(amplitude), frame or "", sim)
    _raise_if_failed(r)
    return ModesResult(r)


def linearize(model, inputs, outputs=(), at=None, time=0.0, out_dir=None):
    """`flexmb linearize`: the state-space model of `model` (path, dict or
    Simulation) about the state `at` ("statics", "initial", "time" or, for a
    Simulation, "current", as in modes());
    inputs: force element names (point_force: 3 world force components [N],
    point_torque: 3 moments [N m], spring_damper: its extra tension [N],
    joint_motor: its torque [N m] or force [N]) and motion drivers (their
    acceleration [m/s^2 or rad/s^2]; their position and velocity are then
    appended to the states, docs/cli.md "Drivers as inputs");
    outputs: sensor names (empty: all sensors). out_dir: also write A.mtx,
    B.mtx, C.mtx, D.mtx, statespace.json and summary.json there."""
    if isinstance(inputs, str):
        inputs = [inputs]
    if isinstance(outputs, str):
        outputs = [outputs]
    name, text, at, sim = _source_args(model, at)
    r = _core.linearize(name, text, _out(out_dir), list(inputs), list(outputs), at, float(time), sim)
    _raise_if_failed(r)
    return StateSpace(r)


def read_mtx(path):
    """A dense Matrix Market "array" file (as `flexmb linearize` writes) as a
    numpy array."""
    with open(path) as f:
        header = f.readline()
        if "array" not in header:
            raise ValueError(f"{path}: not a dense Matrix Market array file")
        line = f.readline()
        while line.startswith("%"):
            line = f.readline()
        rows, cols = (int(x) for x in line.split())
        values = np.array([float(x) for x in f.read().split()])
    return values.reshape(cols, rows).T.copy()
