#!/usr/bin/env python3
"""Real-time factor of the crane slew with the ANCF hoisting rope (issue 19:
"the slewing manoeuvre, flexible boom with 20 modes, 20 rope elements, at
least 10 times faster than real time on one core"): examples/crane/
rope_methods.py's model (the 5 t load hanging, hoisted 1.05 m during the
90 degree slew, 24 s simulated) with the hanging span as an
`ancf_hoist_rope` of `--elements` elements, against the same crane with the
massless `rope` force in the same script (the baseline: what the ANCF
rope costs), and optionally against another flexmb binary on the ANCF
model (`--baseline CLI`, e.g. the build before a change), run alternately.

  /usr/bin/python3 bench/crane_rope_slew.py [--cli build/release/bin/flexmb] [--baseline OTHER] [--reps 5]

Per model and binary: the best integration time over the repetitions
(summary.json's integration_time_s: statics and the time steps, without
process start and model load) and the best wall time of `flexmb run`, the
real-time factor (24 s over the integration time), and for the baseline
binary the largest difference of any results.csv column from this build's,
relative to the column's range.
"""

import argparse
import json
import math
import os
import shutil
import sys
import tempfile
import time

import yaml

from bench_support import ROOT, largest_difference, run

sys.path.insert(0, os.path.join(ROOT, "examples", "crane"))
import rope_methods  # noqa: E402


def timed(cli, model, out):
    t0 = time.perf_counter()
    run([cli, "run", model, "--out", out, "--quiet"])
    wall = time.perf_counter() - t0
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)["integration_time_s"], wall


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--cli", default=os.path.join(ROOT, "build", "release", "bin", "flexmb"))
    ap.add_argument("--baseline", help="another flexmb binary, run alternately on the ANCF model")
    ap.add_argument("--elements", type=int, default=20)
    ap.add_argument("--reps", type=int, default=5)
    a = ap.parse_args()
    work = tempfile.mkdtemp(prefix="crane_rope_bench_")
    try:
        run([sys.executable, os.path.join(ROOT, "examples", "crane", "make_boom.py"), "--out",
             os.path.join(work, "boom.bdf")])
        run([a.cli, "reduce", os.path.join(work, "boom.bdf"), "--fix", "1", "--interface", "1,2,3", "--modes", "20",
             "--deformation-stiffening", "-o", os.path.join(work, "boom.h5")])
        head_W = [1.0 + 18.0 * math.cos(math.radians(40.0)), 0.0, 3.2 + 18.0 * math.sin(math.radians(40.0))]
        for method in ("massless", "ancf"):
            with open(os.path.join(work, method + ".yaml"), "w") as f:
                yaml.safe_dump(rope_methods.model(method, os.path.join(work, "boom.h5"), head_W, a.elements), f,
                               sort_keys=False)
        cases = [("massless rope", a.cli, "massless"), (f"ANCF rope, {a.elements} elements", a.cli, "ancf")]
        if a.baseline:
            cases.append(("ANCF rope, baseline binary", a.baseline, "ancf"))
        best = {k: (float("inf"), float("inf")) for k, _, _ in cases}
        for _ in range(a.reps):
            for label, cli, method in cases:
                integ, wall = timed(cli, os.path.join(work, method + ".yaml"), os.path.join(work, label))
                best[label] = (min(best[label][0], integ), min(best[label][1], wall))
        t_sim = 24.0
        print(f"load average {os.getloadavg()[0]:.2f}; {t_sim:g} s simulated; best of {a.reps}")
        print(f"{'model':32s} {'integration [s]':>16s} {'x real':>7s} {'wall [s]':>9s} {'/ massless':>10s}")
        base = best["massless rope"][0]
        for label, _, _ in cases:
            integ, wall = best[label]
            print(f"{label:32s} {integ:16.3f} {t_sim / integ:7.1f} {wall:9.3f} {integ / base:10.2f}")
        if a.baseline:
            diff = largest_difference(os.path.join(work, cases[1][0], "results.csv"),
                                      os.path.join(work, cases[2][0], "results.csv"))
            print(f"baseline / this build (ANCF): {best[cases[2][0]][0] / best[cases[1][0]][0]:.2f}; "
                  f"largest difference of a results column {diff:.1e} of its range")
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
