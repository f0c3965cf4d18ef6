"""Results: every sensor channel as a numpy array keyed by its results.csv
column name ("time", "sensor.component"), from a Simulation or read from the
output directory of a command-line run (results.csv, summary.json)."""

import csv
import json
import os

import numpy as np


class Results:
    """Columns by name (numpy float64 arrays of equal length) and, when read
    from a run directory, its summary (dict of summary.json, else None)."""

    def __init__(self, columns, summary=None):
        self.columns = dict(columns)
        self.summary = summary

    def __getitem__(self, name):
        return self.columns[name]

    def __contains__(self, name):
        return name in self.columns

    def __iter__(self):
        return iter(self.columns)

    def __len__(self):
        return len(self.columns)

    def keys(self):
        return self.columns.keys()

    def items(self):
        return self.columns.items()

    @property
    def time(self):
        """Output times [s]."""
        return self.columns["time"]

    def sensor(self, name):
        """The columns of one sensor: component -> array."""
        prefix = name + "."
        return {k[len(prefix):]: v for k, v in self.columns.items() if k.startswith(prefix)}

    def to_pandas(self):
        """A pandas DataFrame indexed by time (needs python3-pandas)."""
        try:
            import pandas as pd
        except ImportError as e:
            raise ImportError("to_pandas() needs pandas (Debian: apt-get install python3-pandas)") from e
        return pd.DataFrame(self.columns).set_index("time")

    def __repr__(self):
        n = len(self.columns.get("time", []))
        return f"Results({len(self.columns) - 1} channels, {n} rows)"


def read_results(path):
    """Results of a run directory (results.csv and, if present, summary.json)
    or of a results.csv file."""
    path = os.fspath(path)
    csv_path = os.path.join(path, "results.csv") if os.path.isdir(path) else path
    with open(csv_path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        rows = [[float(x) for x in r] for r in reader if r]
    data = np.array(rows, dtype=np.float64).reshape(len(rows), len(header))
    columns = {name: np.ascontiguousarray(data[:, c]) for c, name in enumerate(header)}
    summary = None
    summary_path = os.path.join(os.path.dirname(csv_path), "summary.json")
    if os.path.exists(summary_path):
        with open(summary_path) as f:
            summary = json.load(f)
    return Results(columns, summary)
