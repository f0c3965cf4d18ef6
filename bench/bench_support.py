"""What the Python bench scripts share: the repository root, running a
command, comparing two results.csv files."""

import csv
import os
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run(cmd, **kw):
    """Runs cmd (a list), raising on a non-zero exit; returns the completed
    process with its output as text."""
    return subprocess.run(cmd, check=True, capture_output=True, text=True, **kw)


def largest_difference(path_a, path_b):
    """Largest |a - b| over the rows of two results.csv files, per column
    relative to the column's range in a, over the columns whose range
    exceeds 1e-6 (smaller ranges are noise). NaN if the row counts differ."""
    with open(path_a) as fa, open(path_b) as fb:
        a, b = list(csv.DictReader(fa)), list(csv.DictReader(fb))
    if len(a) != len(b):
        return float("nan")
    worst = 0.0
    for key in a[0]:
        col_a = [float(r[key]) for r in a]
        col_b = [float(r[key]) for r in b]
        span = max(col_a) - min(col_a)
        if span > 1e-6:
            worst = max(worst, max(abs(x - y) for x, y in zip(col_a, col_b)) / span)
    return worst
