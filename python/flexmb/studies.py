"""Studies from a study file (docs/studies.md) on a Dask cluster: a local
one by default (one worker process per core), or a running cluster given by
its scheduler's address. Rows are journaled as they finish (DIR/journal.jsonl),
so an interrupted study resumes where it stopped; the table is DIR/study.csv
(and DIR/study.h5 with pandas and PyTables, which install-deps.sh installs; without them only the CSV).
"""

import csv
import fcntl
import json
import math
import os
import shutil
import sys
import time

from .study import Table
from .studyfile import StudyInputError, load_study
from .studyrun import run_one

STUDY_FIXED_COLUMNS = ("status", "message")


class StudyJournal:
    """DIR/journal.jsonl: the study's fingerprint on the first line, then one
    finished row per line, flushed and synced as each run ends."""

    def __init__(self, out_dir, fingerprint, study_file):
        self.path = os.path.join(out_dir, "journal.jsonl")
        self.rows = {}
        self.fh = open(self.path, "a+")
        try:  # one study at a time per folder: the lock ends with the process
            fcntl.flock(self.fh, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            self.fh.close()
            raise StudyInputError(
                f"{study_file}: {out_dir} is in use by another study (its journal is locked)") from None
        try:
            self._read(fingerprint, study_file)
        except BaseException:
            self.fh.close()
            raise

    def _read(self, fingerprint, study_file):
        self.fh.seek(0)
        lines = self.fh.read().split("\n")
        good = []
        try:  # a journal cut in its first line is an empty one
            head = json.loads(lines[0])
        except ValueError:
            head = None
        if head is not None:
            if head.get("fingerprint") != fingerprint:
                raise StudyInputError(
                    f"{study_file}: {self.path} is the journal of another study (or the study file, its model "
                    "or side files changed since); use another --out or delete the journal")
            good.append(lines[0])
            for line in lines[1:]:
                try:  # an interrupted write leaves a partial last line: that run is redone
                    row = json.loads(line)
                except ValueError:
                    continue
                self.rows[row["run"]] = row
                good.append(line)
        self.fh.seek(0)
        self.fh.truncate()  # rewritten without a partial line
        self.fh.write("\n".join(good or [json.dumps({"fingerprint": fingerprint, "study": study_file})]) + "\n")
        self.fh.flush()

    def add(self, row):
        self.rows[row["run"]] = row
        self.fh.write(json.dumps(row) + "\n")
        self.fh.flush()
        os.fsync(self.fh.fileno())

    def close(self):
        self.fh.close()


def _csv_value(v):
    if v is None:
        return ""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, float):
        return repr(v)
    if isinstance(v, (dict, list)):
        return json.dumps(v)
    return str(v)


def write_tables(out_dir, spec, rows):
    """DIR/study.csv (every row: run, parameters, status, message, outputs,
    wall_time_s; floats in shortest round-trip form) and, with pandas and
    PyTables, DIR/study.h5 (key 'study'). Returns the paths written."""
    columns = ["run", *(p.name for p in spec.parameters), *STUDY_FIXED_COLUMNS, *spec.outputs, "wall_time_s"]
    path = os.path.join(out_dir, "study.csv")
    with open(path + ".tmp", "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(columns)
        for r in rows:
            w.writerow([_csv_value(r.get(c)) for c in columns])
    os.replace(path + ".tmp", path)
    written = [path]
    try:
        import pandas as pd
        import tables  # noqa: F401 (pandas' HDF5 writer)
    except ImportError:
        return written
    frame = pd.DataFrame([{c: r.get(c) for c in columns} for r in rows], columns=columns)
    for c in frame.columns:
        if frame[c].dtype == object:
            try:
                frame[c] = frame[c].astype(float)
            except (TypeError, ValueError):
                frame[c] = frame[c].map(_csv_value)
    h5 = os.path.join(out_dir, "study.h5")
    frame.to_hdf(h5 + ".tmp", key="study", mode="w", format="table")
    os.replace(h5 + ".tmp", h5)
    return written + [h5]


def _default_cli():
    path = os.environ.get("FLEXMB_CLI") or shutil.which("flexmb")
    if not path:
        raise FileNotFoundError("no flexmb executable: set FLEXMB_CLI or put flexmb on PATH")
    return os.path.abspath(path)


def _run_dask(client, tasks, journal, keep_dir, timeout, on_row):
    futures = {client.submit(run_one, t, None, keep_dir, key=f"flexmb-study-run-{t['run']}-{time.time_ns()}",
                             pure=False): t for t in tasks}
    pending = set(futures)
    try:
        _collect(futures, pending, journal, timeout, on_row)
    finally:
        if pending:  # interrupted or timed out: the cluster may live on, so its work is withdrawn
            client.cancel(list(pending))


def _collect(futures, pending, journal, timeout, on_row):
    from distributed import wait
    deadline = None if timeout is None else time.monotonic() + timeout
    while pending:
        left = None if deadline is None else deadline - time.monotonic()
        if left is not None and left <= 0:
            raise TimeoutError(f"study timeout: {len(pending)} of {len(futures)} runs unfinished after {timeout} s")
        done, _ = wait(pending, timeout=left, return_when="FIRST_COMPLETED")
        pending -= done
        for f in done:
            t = futures[f]
            if f.status == "finished":
                row = f.result()
            else:  # e.g. KilledWorker: the run took down workers more often than Dask allows
                exc = f.exception()
                row = {"run": t["run"], **t["values"], "status": "failed", "message": f"{type(exc).__name__}: {exc}"}
            journal.add(row)
            if on_row:
                on_row(row)


def study(study_file, out_dir, workers=None, scheduler=None, keep_runs=False, timeout=None, cli=None,
          on_row=None):
    """Runs the study file into out_dir and returns its rows as a Table (in
    run order). Runs already in out_dir/journal.jsonl are not redone.
    workers: worker processes of the local Dask cluster (default: one per
    core); 0 runs serially in this process, without Dask. scheduler: the
    address (tcp://HOST:PORT) of a running Dask scheduler, or a
    distributed.Client. keep_runs: keep each run's folder as
    out_dir/runs/run_NNNN. timeout [s]: for the whole study (TimeoutError).
    cli: the flexmb executable (default FLEXMB_CLI or PATH). on_row(row) is
    called as each run finishes."""
    spec = load_study(study_file)
    tasks = spec.runs(os.path.abspath(cli) if cli else _default_cli())
    out_dir = os.path.abspath(os.fspath(out_dir))
    os.makedirs(out_dir, exist_ok=True)
    journal = StudyJournal(out_dir, spec.fingerprint(tasks), spec.file)
    keep_dir = os.path.join(out_dir, "runs") if keep_runs else None
    todo = [t for t in tasks if t["run"] not in journal.rows]
    try:
        if todo and workers == 0 and scheduler is None:
            deadline = None if timeout is None else time.monotonic() + timeout
            for i, t in enumerate(todo):
                if deadline is not None and time.monotonic() > deadline:
                    raise TimeoutError(
                        f"study timeout: {len(todo) - i} of {len(todo)} runs unfinished after {timeout} s")
                row = run_one(t, None, keep_dir)
                journal.add(row)
                if on_row:
                    on_row(row)
        elif todo:
            _run_on_cluster(todo, journal, workers, scheduler, keep_dir, timeout, on_row)
    finally:
        journal.close()
    rows = [journal.rows[t["run"]] for t in tasks]
    write_tables(out_dir, spec, rows)
    return Table(rows)


def _run_on_cluster(todo, journal, workers, scheduler, keep_dir, timeout, on_row):
    try:
        from distributed import Client, LocalCluster
    except ImportError:
        raise ImportError("flexmb studies on a cluster need Dask (Debian's python3-distributed); "
                          "workers=0 runs them serially") from None
    connect = 60 if timeout is None else max(5, min(60, timeout))
    if scheduler is not None and not isinstance(scheduler, str):
        _run_dask(scheduler, todo, journal, keep_dir, timeout, on_row)
        return
    if scheduler is not None:
        with Client(scheduler, timeout=connect) as client:
            _run_dask(client, todo, journal, keep_dir, timeout, on_row)
        return
    import logging
    n = workers or os.cpu_count() or 1
    with LocalCluster(n_workers=min(n, len(todo)), threads_per_worker=1, processes=True, dashboard_address=None,
                      silence_logs=logging.ERROR) as cluster, Client(cluster, timeout=connect) as client:
        _run_dask(client, todo, journal, keep_dir, timeout, on_row)


def print_row(row, total, stream=sys.stdout):
    """One progress line of the command line."""
    status = row["status"] if row["status"] == "ok" else f"{row['status']}: {row['message']}"
    wall = row.get("wall_time_s")
    wall = f"{wall:.2f} s" if isinstance(wall, float) and math.isfinite(wall) else ""
    print(f"run {row['run'] + 1}/{total}: {status} {wall}", file=stream, flush=True)
