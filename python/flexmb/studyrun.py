"""One run of a study, as a Dask worker (or the serial loop) executes it:
the flexmb command line in a scratch folder, then the outputs collected
from summary.json and results.csv. Needs no compiled core: only the
standard library, numpy and the flexmb executable.

Why a subprocess and not the Python API in the worker: a run that crashes
or hangs takes down its own process only (the worker survives, the row
says what happened, a hang ends at the study's timeout), the worker needs
the executable and no matching Python module, and each row is exactly what
`flexmb run` gives. The price is a process start per run (docs/PERFORMANCE.md).
"""

import json
import math
import os
import shutil
import subprocess
import tempfile
import time

import numpy as np


def study_cli_path(task_cli):
    """The flexmb executable on this machine: the client's if it exists here,
    else FLEXMB_CLI, else `flexmb` on PATH."""
    for path in (task_cli, os.environ.get("FLEXMB_CLI"), shutil.which("flexmb")):
        if path and os.path.exists(path):
            return path
    raise FileNotFoundError(f"no flexmb executable on this worker ({task_cli} is missing; set FLEXMB_CLI)")


def _option_args(options):
    args = []
    for k, v in options.items():
        flag = "--" + str(k).replace("_", "-")
        if v is True:
            args.append(flag)
        elif v is not False and v is not None:
            args += [flag, repr(v) if isinstance(v, float) else str(v)]
    return args


def _read_columns(path):
    with open(path) as fh:
        names = fh.readline().strip().split(",")
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return {n: data[:, i] for i, n in enumerate(names)}


def _period(t, x):
    """Mean spacing [s] of the upward crossings of the midrange of x
    (linear interpolation between samples); NaN with fewer than two."""
    mid = 0.5 * (float(np.max(x)) + float(np.min(x)))
    y = x - mid
    idx = np.nonzero((y[:-1] < 0) & (y[1:] >= 0))[0]
    if len(idx) < 2:
        return math.nan
    tc = t[idx] - y[idx] * (t[idx + 1] - t[idx]) / (y[idx + 1] - y[idx])
    return float((tc[-1] - tc[0]) / (len(tc) - 1))


def _reduce(how, t, x):
    if how == "max":
        return float(np.max(x))
    if how == "min":
        return float(np.min(x))
    if how == "mean":
        return float(np.mean(x))
    if how == "rms":
        return float(np.sqrt(np.mean(x * x)))
    if how == "abs_max":
        return float(np.max(np.abs(x)))
    if how == "first":
        return float(x[0])
    if how == "final":
        return float(x[-1])
    return _period(t, x)


def _summary_value(summary, key):
    node = summary
    for part in key.split("."):
        if not isinstance(node, dict) or part not in node:
            raise KeyError(f"summary has no '{key}'")
        node = node[part]
    return node


def collect_outputs(outputs, summary, run_dir):
    """The outputs of one run: summary.json keys and reductions of results.csv columns."""
    row, columns = {}, None
    for name, (how, what) in outputs.items():
        if how == "summary":
            row[name] = _summary_value(summary, what)
            continue
        if columns is None:
            columns = _read_columns(os.path.join(run_dir, "results.csv"))
        if what not in columns:
            raise KeyError(f"output {name}: no column '{what}' in results.csv (columns: {', '.join(columns)})")
        # the first column: time for a run, load_factor for statics
        row[name] = _reduce(how, columns.get("time", next(iter(columns.values()))), columns[what])
    return row


def _last_json(text):
    for line in reversed(text.strip().splitlines()):
        if line.startswith("{"):
            return json.loads(line)
    return {}


def run_one(task, scratch=None, keep_dir=None):
    """Runs one task of StudySpec.runs(): returns its row (run, parameter
    values, status 'ok' or 'failed', message, outputs, wall_time_s). Never
    raises for a failing run. scratch: parent of the scratch folder (None:
    the system's temporary folder); keep_dir: where the run folder is kept
    (as run_NNNN), None to delete it."""
    row = {"run": task["run"], **task["values"], "status": "failed", "message": ""}
    start = time.perf_counter()
    if keep_dir:
        os.makedirs(keep_dir, exist_ok=True)
        scratch = keep_dir
    work = tempfile.mkdtemp(prefix=f".run_{task['run']:04d}.", dir=scratch)
    try:
        model_dir = os.path.join(work, "model")
        os.mkdir(model_dir)
        model = os.path.join(model_dir, task["model_name"])
        if task["files"] is None:  # shared path: link the model folder's other entries
            for entry in os.listdir(task["model_dir"]):
                if entry != task["model_name"] and not entry.startswith("."):
                    os.symlink(os.path.join(task["model_dir"], entry), os.path.join(model_dir, entry))
        else:
            for name, data in task["files"].items():
                os.makedirs(os.path.dirname(os.path.join(model_dir, name)), exist_ok=True)
                with open(os.path.join(model_dir, name), "wb") as fh:
                    fh.write(data)
        with open(model, "w") as fh:
            fh.write(task["model_text"])
        out = os.path.join(work, "out")
        cmd = [study_cli_path(task["cli"]), *task["command"], model]
        if task["command"] == ["run"]:
            cmd += ["-o", out, "-q"]
        cmd += _option_args(task["options"])
        try:
            proc = subprocess.run(cmd, cwd=work, capture_output=True, text=True, timeout=task["timeout"])
        except subprocess.TimeoutExpired:
            row["message"] = f"timeout: the run took longer than {task['timeout']} s"
            return row
        if task["command"] == ["run"]:
            try:
                with open(os.path.join(out, "summary.json")) as fh:
                    summary = json.load(fh)
            except (OSError, ValueError):
                summary = {}
        else:
            summary = _last_json(proc.stdout)
        if proc.returncode != 0:
            msg = summary.get("message") or (proc.stderr.strip().splitlines() or [""])[-1]
            msg = msg[len("error: "):] if msg.startswith("error: ") else msg
            row["message"] = msg or f"flexmb exited with status {proc.returncode}"
            return row
        row.update(collect_outputs(task["outputs"], summary, out))
        row["status"] = "ok"
    except Exception as e:  # a row says what went wrong; the study goes on
        row["message"] = f"{type(e).__name__}: {e}"
    finally:
        # the scratch folder's name differs between attempts: messages name run_NNNN instead
        row["message"] = row["message"].replace(work, f"run_{task['run']:04d}")
        row["wall_time_s"] = time.perf_counter() - start
        if keep_dir:
            final = os.path.join(keep_dir, f"run_{task['run']:04d}")
            shutil.rmtree(final, ignore_errors=True)
            os.replace(work, final)
        else:
            shutil.rmtree(work, ignore_errors=True)
    return row
