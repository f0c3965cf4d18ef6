#!/usr/bin/env python3
"""Throughput of a study (docs/studies.md) on a local Dask cluster of 1 and
2 worker processes against a serial loop of the same runs in this process
(flexmb.study with workers=0: the same run function, no Dask), and the
overhead per task. The study: the pendulum of examples/studies over N
lengths, each run `flexmb run` for t_end seconds.

  PYTHONPATH=build/release/python FLEXMB_CLI=build/release/bin/flexmb \\
    /usr/bin/python3 bench/study_scaling.py [--runs 64] [--t-end 2.0] [--workers 1,2]

Prints one line per configuration: wall time of the runs (cluster start-up
not included, printed apart), runs/s, speed-up over the serial loop.
"""

import argparse
import os
import shutil
import tempfile
import time

import flexmb


def write_study(folder, source_dir, runs, t_end):
    model = os.path.join(source_dir, "examples", "studies", "pendulum.yaml")
    values = ", ".join(repr(0.2 + 0.002 * i) for i in range(runs))  # periods 0.9 to 1.2 s
    path = os.path.join(folder, "scaling.yaml")
    with open(path, "w") as fh:
        fh.write(f"""model: {model}
options: {{t_end: {t_end}}}
parameters:
  length: {{path: "bodies[name=bob].center_of_mass[1]", scale: -1, values: [{values}]}}
outputs: {{period: period(angle.value), steps: summary.steps}}
""")
    return path


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--runs", type=int, default=64)
    ap.add_argument("--t-end", type=float, default=2.0)
    ap.add_argument("--workers", default="1,2")
    ap.add_argument("--cli", default=os.environ.get("FLEXMB_CLI"))
    args = ap.parse_args()
    source_dir = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    from distributed import Client, LocalCluster

    tmp = tempfile.mkdtemp(prefix="flexmb_study_scaling.")
    try:
        study = write_study(tmp, source_dir, args.runs, args.t_end)
        t0 = time.perf_counter()
        serial = flexmb.study(study, os.path.join(tmp, "serial"), workers=0, cli=args.cli)
        t_serial = time.perf_counter() - t0
        mean_run = sum(serial.column("wall_time_s")) / len(serial)
        print(f"{args.runs} runs of {args.t_end} s, {os.cpu_count()} cores; mean run {mean_run * 1e3:.1f} ms "
              "(on its worker: model written, flexmb process, outputs read)")
        print(f"serial loop:  {t_serial:7.2f} s  {args.runs / t_serial:6.2f} runs/s  speed-up 1.00")
        for n in (int(w) for w in args.workers.split(",")):
            t0 = time.perf_counter()
            with LocalCluster(n_workers=n, threads_per_worker=1, processes=True, dashboard_address=None,
                              silence_logs=40) as cluster, Client(cluster) as client:
                t_up = time.perf_counter() - t0
                t0 = time.perf_counter()
                table = flexmb.study(study, os.path.join(tmp, f"dask{n}"), scheduler=client, cli=args.cli)
                t_runs = time.perf_counter() - t0
            assert [repr(r["period"]) for r in table] == [repr(p) for p in serial.column("period")]
            overhead = (t_runs * n - sum(table.column("wall_time_s"))) / args.runs
            print(f"{n} worker{'s' if n > 1 else ' '}:    {t_runs:7.2f} s  {args.runs / t_runs:6.2f} runs/s  "
                  f"speed-up {t_serial / t_runs:4.2f}  (cluster start {t_up:.1f} s, "
                  f"Dask overhead per task {overhead * 1e3:.1f} ms)")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
