#!/usr/bin/env python3
"""Run time of the example crane's work cycle (examples/crane/crane.yaml:
lift-off of a grounded load and a 90 degree slew, 24 s simulated) with the
elastic boom at several sizes of its modal basis, against the same cycle
with the boom reduced to its Guyan (static) modes only, in the same script:
how much the boom's modes cost, and its deformation stiffening (`reduce
--deformation-stiffening`, the example's default) against the linear body
with the same 20 normal modes.

  /usr/bin/python3 bench/crane_cycle.py [--cli build/release/bin/flexmb] [--reps 3]

Each basis is run twice: with the example's modified Newton (`solver:
jacobian_reuse: true`, the iteration matrix kept while the iterations
contract fast) and with full Newton (a fresh matrix every iteration, the
baseline), alternately. Per basis and solver: the reduction's flexible
modes, the best wall time of `flexmb run` over the repetitions (process
start and model load included), the real-time factor (simulated / wall
time), the ratio to the Guyan run of the same solver, and for the kept
matrix the largest difference of any results.csv column from the full
Newton run, relative to that column's range (columns whose range is below
1e-6 are noise and skipped).
"""

import argparse
import os
import re
import shutil
import sys
import tempfile
import time

from bench_support import ROOT, largest_difference, run

def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--cli", default=os.path.join(ROOT, "build", "release", "bin", "flexmb"))
    ap.add_argument("--reps", type=int, default=3)
    a = ap.parse_args()
    work = tempfile.mkdtemp(prefix="crane_bench_")
    try:
        text = open(os.path.join(ROOT, "examples", "crane", "crane_model.yaml")).read()
        if text.count("jacobian_reuse: true") != 1:
            sys.exit("crane.yaml no longer sets 'jacobian_reuse: true' once: update this bench")
        models = {"kept": text, "full": text.replace("jacobian_reuse: true", "jacobian_reuse: false")}
        for name, body in models.items():
            with open(os.path.join(work, name + ".yaml"), "w") as f:
                f.write(body)
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
            best = {"full": float("inf"), "kept": float("inf")}
            for _ in range(a.reps):
                for name in ("full", "kept"):
                    t0 = time.perf_counter()
                    run([a.cli, "run", os.path.join(work, name + ".yaml"), "--out", os.path.join(work, name), "--quiet"])
                    best[name] = min(best[name], time.perf_counter() - t0)
            diff = largest_difference(os.path.join(work, "full", "results.csv"),
                                      os.path.join(work, "kept", "results.csv"))
            rows.append((label, n, best["full"], best["kept"], diff))
        print(f"load average {os.getloadavg()[0]:.2f}")
        print(f"{'boom basis':28s} {'modes':>5s} {'full [s]':>9s} {'x real':>7s} {'/ Guyan':>8s}"
              f" {'kept [s]':>9s} {'x real':>7s} {'/ Guyan':>8s} {'full/kept':>9s} {'max diff':>9s}")
        for label, n, full, kept, diff in rows:
            print(f"{label:28s} {n:5d} {full:9.3f} {t_sim / full:7.1f} {full / rows[0][2]:8.2f}"
                  f" {kept:9.3f} {t_sim / kept:7.1f} {kept / rows[0][3]:8.2f} {full / kept:9.2f} {diff:9.1e}")
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
