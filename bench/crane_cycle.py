#!/usr/bin/env python3
"""Run time of the example crane's work cycle (examples/crane/crane.yaml:
lift-off of a grounded load and a 90 degree slew, 24 s simulated) with the
elastic boom at several sizes of its modal basis, against the same cycle
with the boom reduced to its Guyan (static) modes only, in the same script:
how much the boom's modes cost, and its deformation stiffening (`reduce
--deformation-stiffening`, the example's default) against the linear body
with the same 20 normal modes.

  /usr/bin/python3 bench/crane_cycle.py [--cli build/release/bin/flexmb] [--reps 3]

Per basis: the reduction's flexible modes, the best wall time of `flexmb
run` over the repetitions (process start and model load included), the
real-time factor (simulated / wall time) and the ratio to the Guyan run.
"""

import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def run(cmd, **kw):
    return subprocess.run(cmd, check=True, capture_output=True, text=True, **kw)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--cli", default=os.path.join(ROOT, "build", "release", "bin", "flexmb"))
    ap.add_argument("--reps", type=int, default=3)
    a = ap.parse_args()
    work = tempfile.mkdtemp(prefix="crane_bench_")
    try:
        shutil.copy(os.path.join(ROOT, "examples", "crane", "crane.yaml"), work)
        run([sys.executable, os.path.join(ROOT, "examples", "crane", "make_boom.py"), "--out",
             os.path.join(work, "boom.bdf")])
        t_sim = 24.0
        rows = []
        cases = (("Guyan (static modes only)", "0", []),
                 ("20 normal modes, linear", "20", []),
                 ("20 normal modes, stiffened", "20", ["--deformation-stiffening"]),
                 ("40 normal modes, stiffened", "40", ["--deformation-stiffening"]))
        for label, modes, extra in cases:
            out = run([a.cli, "reduce", os.path.join(work, "boom.bdf"), "--fix", "1", "--interface", "1,2,3", "--modes", modes,
                       *extra, "-o", os.path.join(work, "boom.h5")]).stdout
            n = int(re.search(r"(\d+) flexible modes kept", out).group(1))
            best = float("inf")
            for _ in range(a.reps):
                t0 = time.perf_counter()
                run([a.cli, "run", os.path.join(work, "crane.yaml"), "--out", os.path.join(work, "run"), "--quiet"])
                best = min(best, time.perf_counter() - t0)
            rows.append((label, n, best))
        base = rows[0][2]
        print(f"load average {os.getloadavg()[0]:.2f}")
        print(f"{'boom basis':28s} {'modes':>5s} {'wall [s]':>9s} {'x real time':>11s} {'/ Guyan':>8s}")
        for label, n, wall in rows:
            print(f"{label:28s} {n:5d} {wall:9.3f} {t_sim / wall:11.1f} {wall / base:8.2f}")
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
