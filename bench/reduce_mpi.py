#!/usr/bin/env python3
"""The distributed reduction against the serial one on a generated solid
boom (scripts/make_fe_deck.py solid-boom): wall time and peak memory
(maximum resident set) of every process, for the serial path (CHOLMOD and
block Lanczos) and `--backend petsc` on 1, 2, ... ranks of this machine.
Figures and the command in docs/PERFORMANCE.md, "Distributed reduction".

    python3 bench/reduce_mpi.py [--nx 2000 --ny 6 --nz 8] [--ranks 1,2] [--modes 20]

Each run is one process tree started here; the memory per rank is read
from /usr/bin/time (GNU time) around each rank's process.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
import time

from bench_support import ROOT

CLI = os.path.join(ROOT, "build", "release", "bin", "flexmb")
MPI_ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")


def run(cmd, work):
    """Wall time [s] and the peak resident memory [MiB] of each process."""
    t0 = time.perf_counter()
    r = subprocess.run(cmd, capture_output=True, text=True, env=MPI_ENV, cwd=work)
    wall = time.perf_counter() - t0
    if r.returncode != 0:
        sys.exit(f"failed: {' '.join(cmd)}\n{r.stderr}")
    rss = [int(m) / 1024.0 for m in re.findall(r"^MAXRSS (\d+)$", r.stderr, re.M)]
    freq = re.search(r"^\s+1\s+([0-9.e+-]+)$", r.stdout, re.M)
    return wall, rss, float(freq.group(1)) if freq else float("nan")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--nx", type=int, default=2000)
    ap.add_argument("--ny", type=int, default=6)
    ap.add_argument("--nz", type=int, default=8)
    ap.add_argument("--ranks", default="1,2")
    ap.add_argument("--modes", type=int, default=20)
    ap.add_argument("--skip-serial", action="store_true", help="only the distributed runs")
    a = ap.parse_args()
    timer = "/usr/bin/time"
    if not os.path.exists(timer):
        sys.exit("needs GNU time (/usr/bin/time, Debian package time)")
    with tempfile.TemporaryDirectory() as work:
        deck = os.path.join(work, "boom.bdf")
        subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "make_fe_deck.py"), "solid-boom", "--nx",
                        str(a.nx), "--ny", str(a.ny), "--nz", str(a.nz), "--out", deck], check=True)
        dof = 3 * (a.nx + 1) * (a.ny + 1) * (a.nz + 1)
        print(f"solid boom {a.nx} x {a.ny} x {a.nz} bricks, {dof} DOF, {a.modes} fixed-interface modes")
        base = ["reduce", deck, "--interface", "1,2", "--modes", str(a.modes), "--eigen-tolerance", "1e-10"]
        rows = []
        if not a.skip_serial:
            rows.append(("serial (CHOLMOD, block Lanczos)",
                         *run([timer, "-f", "MAXRSS %M", CLI, *base, "-o", "serial.h5"], work)))
        for n in (int(k) for k in a.ranks.split(",")):
            cmd = ["mpirun", "-np", str(n), timer, "-f", "MAXRSS %M", CLI, *base, "--backend", "petsc", "-o",
                   f"petsc{n}.h5"]
            rows.append((f"petsc, {n} rank{'s' if n > 1 else ''}", *run(cmd, work)))
        print(f"{'run':34s} {'wall [s]':>9s} {'ratio':>6s} {'max RSS per rank [MiB]':>24s} {'f1 [Hz]':>12s}")
        for name, wall, rss, f1 in rows:
            ratio = wall / rows[0][1]
            print(f"{name:34s} {wall:9.2f} {ratio:6.2f} {', '.join(f'{m:.0f}' for m in sorted(rss, reverse=True)):>24s}"
                  f" {f1:12.6f}")


if __name__ == "__main__":
    main()
