#!/usr/bin/env python3
"""Two builds of flexmb on the same example models, alternately, in one
script: Newton iterations, factorizations and the best wall time of each,
and the largest difference of the two runs' results.csv columns (relative
to the column's range). For a solver change: the baseline is the previous
build (e.g. a clean clone of main built beside this one).

  /usr/bin/python3 bench/solver_ab.py --base OLD/bin/flexmb [--new build/release/bin/flexmb] [--reps 3]

Models: the IFToMM four-bar, Bricard's mechanism and Andrews' squeezer
(examples/), and the example crane's work cycle with full Newton
(`jacobian_reuse: false`; examples/crane, boom reduced as its README says).
"""

import argparse
import json
import os
import shutil
import sys
import tempfile
import time

from bench_support import ROOT, largest_difference, run

def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--base", required=True, help="the baseline flexmb executable")
    ap.add_argument("--new", default=os.path.join(ROOT, "build", "release", "bin", "flexmb"))
    ap.add_argument("--reps", type=int, default=3)
    a = ap.parse_args()
    work = tempfile.mkdtemp(prefix="solver_ab_")
    try:
        models = [(name, os.path.join(ROOT, "examples", name, "model.yaml"))
                  for name in ("four_bar_2", "bricard", "andrews_squeezer")]
        crane = os.path.join(work, "crane")
        os.makedirs(crane)
        text = open(os.path.join(ROOT, "examples", "crane", "crane_model.yaml")).read()
        with open(os.path.join(crane, "crane.yaml"), "w") as f:
            f.write(text.replace("jacobian_reuse: true", "jacobian_reuse: false"))
        run([sys.executable, os.path.join(ROOT, "examples", "crane", "make_boom.py"), "--out",
             os.path.join(crane, "boom.bdf")])
        run([a.new, "reduce", os.path.join(crane, "boom.bdf"), "--fix", "1", "--interface", "1,2,3", "--modes", "20",
             "--deformation-stiffening", "-o", os.path.join(crane, "boom.h5")])
        models.append(("crane work cycle, full Newton", os.path.join(crane, "crane.yaml")))
        print(f"{'model':32s} {'steps':>7s} {'iterations base/new':>20s} {'wall base/new [s]':>18s} {'base/new':>8s} "
              f"{'max diff':>9s}")
        for label, model in models:
            res = {}
            for _ in range(a.reps):
                for tag, cli in (("base", a.base), ("new", a.new)):
                    out = os.path.join(work, tag)
                    t0 = time.perf_counter()
                    run([cli, "run", model, "--out", out, "--quiet"])
                    wall = time.perf_counter() - t0
                    with open(os.path.join(out, "summary.json")) as f:
                        s = json.load(f)
                    best = res.get(tag, (float("inf"),))[0]
                    res[tag] = (min(best, wall), s["steps"], s["newton_iterations"])
            diff = largest_difference(os.path.join(work, "base", "results.csv"),
                                      os.path.join(work, "new", "results.csv"))
            (wb, steps, ib), (wn, _, inew) = res["base"], res["new"]
            print(f"{label:32s} {steps:7d} {ib:>9d} / {inew:<8d} {wb:8.3f} / {wn:<7.3f} {wb / wn:8.2f} {diff:9.1e}")
        print(f"load average {os.getloadavg()[0]:.2f}")
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
