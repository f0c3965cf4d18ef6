"""Parameter studies: a list of variants run in parallel processes, their
results collected into one table.

A study is a picklable function `task(variant) -> dict` and a list of
variants (e.g. dicts of parameters). run_study hands the tasks to an
executor with the concurrent.futures interface (submit -> future with
result()); by default a ProcessPoolExecutor on this machine. Any executor
with that interface fits, e.g. dask.distributed's Client (its submit
returns futures with result()), so a cluster can take the same tasks later.
"""

import concurrent.futures
import os
import traceback


def _guarded(task, variant):
    try:
        row = task(variant)
        return dict(row) if row is not None else {}
    except Exception as e:  # a failed variant is a row with its error
        return {"error": f"{type(e).__name__}: {e}", "traceback": traceback.format_exc()}


class Table(list):
    """Rows (dicts) of a study, one per variant, variant keys first."""

    def column(self, key):
        """The values of one key (None where a row lacks it)."""
        return [r.get(key) for r in self]

    def to_pandas(self):
        """A pandas DataFrame (needs python3-pandas)."""
        import pandas as pd
        return pd.DataFrame(list(self))


def run_study(task, variants, executor=None, max_workers=None):
    """Runs task(variant) for every variant and returns a Table: each row the
    variant (if a dict) merged with what the task returned, in the order of
    `variants`. A variant that raises gives a row with 'error'.
    executor: None for a ProcessPoolExecutor(max_workers, default os.cpu_count()),
    'serial' to run in this process, or any object with submit(fn, *args)."""
    variants = list(variants)
    if executor == "serial":
        outs = [_guarded(task, v) for v in variants]
    else:
        own = executor is None
        if own:
            executor = concurrent.futures.ProcessPoolExecutor(max_workers=max_workers or os.cpu_count())
        try:
            futures = [executor.submit(_guarded, task, v) for v in variants]
            outs = [f.result() for f in futures]
        finally:
            if own:
                executor.shutdown()
    table = Table()
    for v, out in zip(variants, outs):
        row = dict(v) if isinstance(v, dict) else {"variant": v}
        row.update(out)
        table.append(row)
    return table
