"""`flexmb study STUDY.yaml --out DIR [--workers N | --scheduler tcp://HOST:PORT] [--keep-runs]`:
the command line of flexmb.study (docs/studies.md). The flexmb executable
forwards its `study` subcommand here (python3 -m flexmb.study_cli ...)."""

import argparse
import os
import signal
import sys


def main(argv=None):
    ap = argparse.ArgumentParser(prog="flexmb study", description="run a parameter study (docs/studies.md)")
    ap.add_argument("study", help="study file (YAML)")
    ap.add_argument("-o", "--out", required=True, help="output directory: study.csv, journal.jsonl, runs/")
    where = ap.add_mutually_exclusive_group()
    where.add_argument("--workers", type=int, default=None,
                       help="worker processes of the local Dask cluster (default: one per core; 0: serial, no Dask)")
    where.add_argument("--scheduler", default=None, help="address of a running Dask scheduler, tcp://HOST:PORT")
    ap.add_argument("--keep-runs", action="store_true", help="keep each run's folder as DIR/runs/run_NNNN")
    ap.add_argument("--timeout", type=float, default=None, help="limit for the whole study [s]")
    ap.add_argument("--cli", default=None, help="the flexmb executable the runs use (default: FLEXMB_CLI, PATH)")
    ap.add_argument("-q", "--quiet", action="store_true", help="no line per run")
    args = ap.parse_args(argv)
    if args.workers is not None and args.workers < 0:
        ap.error("--workers must be 0 or more")

    def on_term(signum, frame):  # kill (SIGTERM) stops like Ctrl-C: the cluster is closed, the journal kept
        raise KeyboardInterrupt

    signal.signal(signal.SIGTERM, on_term)
    from . import _core
    from .studies import print_row, study
    from .studyfile import load_study

    try:
        total = len(load_study(args.study).rows)
        table = study(args.study, args.out, workers=args.workers, scheduler=args.scheduler, keep_runs=args.keep_runs,
                      timeout=args.timeout, cli=args.cli,
                      on_row=None if args.quiet else (lambda r: print_row(r, total)))
    except _core.Error as e:  # exit 2 for an input error, as the flexmb executable
        print(f"error: {e}", file=sys.stderr)
        return 2 if isinstance(e, _core.InputError) else 1
    except KeyboardInterrupt:
        print(f"interrupted: the finished runs are in {os.path.join(args.out, 'journal.jsonl')}; "
              "the same command resumes", file=sys.stderr)
        return 130
    except (TimeoutError, OSError, ImportError) as e:
        print(f"error: {e}", file=sys.stderr)
        return 1
    failed = sum(1 for r in table if r["status"] != "ok")
    print(f"{len(table)} runs, {failed} failed: {os.path.join(args.out, 'study.csv')}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
