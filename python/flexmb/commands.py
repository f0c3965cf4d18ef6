"""The command-line workflows as functions: run a model file, FE models
(`flexmb fe ...`), reduction (`flexmb reduce`) and body files
(`flexmb body info`). Reports come back as dicts (the commands' --json)."""

import json
import os

from . import _core
from .results import read_results


def run_file(model, out_dir, t_end=None, dt=None, animation=False, manoeuvre=None):
    """`flexmb run MODEL -o OUT_DIR [--manoeuvre NAME]`: writes results.csv
    and summary.json and returns them as Results (summary in .summary).
    Raises InputError or NumericalError with the command's message if the
    run failed."""
    text, status = _core.run_file(os.fspath(model), os.fspath(out_dir), t_end, dt, animation, manoeuvre or "")
    if status != 0:
        summary = json.loads(text)
        kind = {1: _core.InputError, 2: _core.NumericalError}.get(status, _core.Error)
        raise kind(summary["message"])
    return read_results(out_dir)


def fe_modes(model, count=10, fix="", lumped=False, shift=0.0):
    """`flexmb fe modes --json`: frequencies_hz, dofs, mass_kg, ... of the
    full FE model (mesh file, FE model file or exchange-set directory)."""
    return json.loads(_core.fe_modes(os.fspath(model), count, fix, lumped, shift))


def fe_info(model):
    """`flexmb fe info --json`: counts, sets, bounding box, mass properties."""
    return json.loads(_core.fe_info(os.fspath(model)))


def fe_export(model, hb_dir, fix="", interface="", modes=10):
    """`flexmb fe export`: writes the exchange set; returns the report text."""
    return _core.fe_export(os.fspath(model), os.fspath(hb_dir), fix, interface, modes)


def reduce(model, output, interface="", modes=-1, cutoff_hz=0.0, keep=-1, fix="", rayleigh="",
           damping_ratio="", modes_file="", geometric_stiffening=False, units="SI", solid_corner_stress=False,
           deformation_stiffening=False, frame="", acceleration_modes=False):
    """`flexmb reduce --json`: Craig-Bampton reduction of a part into the body
    file `output` (.h5). interface: node ids "1,2,3" or a node set; modes:
    fixed-interface normal modes (or cutoff_hz [Hz]); keep: lowest flexible
    modes kept; rayleigh "ALPHA,BETA" or damping_ratio "Z[,Z2...]";
    solid_corner_stress: also the solids' stress modes at their corner nodes
    (`flexmb reduce --solid-corner-stress`); geometric_stiffening and
    deformation_stiffening: `--geometric-stiffening` (centrifugal) and
    `--deformation-stiffening` (the body's own deformation); frame: the
    floating frame, "mean" (also "tisserand", "buckens") or "node:ID" (or
    a node id), `--frame` (default: mean axes, or the fix nodes);
    acceleration_modes: `--acceleration-modes` (the static responses to the
    rigid-body accelerations in the basis: own weight). Returns the report
    (frame, frequencies_hz, mass_kg, timings_s, ...)."""
    if isinstance(interface, (list, tuple)):
        interface = ",".join(str(i) for i in interface)
    if isinstance(fix, (list, tuple)):
        fix = ",".join(str(i) for i in fix)
    if isinstance(frame, int) and not isinstance(frame, bool):
        frame = f"node:{frame}"
    if isinstance(rayleigh, (list, tuple)):
        rayleigh = ",".join(repr(float(x)) for x in rayleigh)
    if isinstance(damping_ratio, (list, tuple)):
        damping_ratio = ",".join(repr(float(x)) for x in damping_ratio)
    elif isinstance(damping_ratio, (int, float)):
        damping_ratio = repr(float(damping_ratio))
    return json.loads(_core.reduce(os.fspath(model), os.fspath(output), interface, modes, cutoff_hz, keep, fix,
                                   rayleigh, damping_ratio, os.fspath(modes_file), geometric_stiffening, units,
                                   solid_corner_stress, deformation_stiffening, frame, acceleration_modes))


def body_info(body):
    """`flexmb body info --json`."""
    return json.loads(_core.body_info(os.fspath(body)))


def fe_mode_shapes(model, count=10, fix="", lumped=False, shift=0.0):
    """The modes of `fe modes` with their shapes as numpy: frequencies_hz
    (count), shapes (6 rows per node: ux uy uz [m] rx ry rz [rad], M-orthonormal,
    x count), nodes (N x 3) [m], node_ids, dofs (free DOF)."""
    if isinstance(fix, (list, tuple)):
        fix = ",".join(str(i) for i in fix)
    return _core.fe_mode_shapes(os.fspath(model), count, fix, lumped, shift)
