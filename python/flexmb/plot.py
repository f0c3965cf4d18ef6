"""Plot helpers on matplotlib for results: time histories of chosen
channels and overlays of several runs (e.g. rigid against elastic frame, as
the truck demo's plots, examples/truck_lane_change/plot.py).

Runs are given as (label, columns) pairs where columns maps a column name
to a sequence (a Results, a dict of numpy arrays, or lists)."""

import os


def _plt():
    import matplotlib
    if not os.environ.get("DISPLAY") and matplotlib.get_backend().lower() not in ("agg", "pdf", "svg"):
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def save_xy(path, series, xlabel, ylabel, figsize=(7, 4.5), dpi=110):
    """One x-y figure of `series`, each (x, y, label, style) with style a dict
    of plot keywords, with grid and legend, written to `path` and closed."""
    plt = _plt()
    fig, ax = plt.subplots(figsize=figsize)
    for x, y, label, style in series:
        ax.plot(x, y, label=label, **style)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=dpi)
    plt.close(fig)


def run_dir_arguments(description=None, argv=None):
    """The command line of the example plot scripts, RUN_DIR [RUN_DIR ...]
    [--out DIR]: returns (run directories, output directory), the output
    directory (default: the first run's) created."""
    import argparse
    ap = argparse.ArgumentParser(description=description)
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--out", default=None, help="directory for the PNGs (default: the first run directory)")
    a = ap.parse_args(argv)
    out = a.out or a.runs[0]
    os.makedirs(out, exist_ok=True)
    return a.runs, out


def time_history(ax, runs, keys, xkey="time", label_keys=None):
    """Plots `keys` against `xkey` of every run into the axes `ax`; one line per
    run and key, labelled "run" (one key) or "run key" (several). label_keys
    maps a key to its label suffix (default: the key)."""
    for label, cols in runs:
        for k in keys:
            if k not in cols:
                continue
            suffix = "" if len(keys) == 1 else " " + (label_keys or {}).get(k, k)
            ax.plot(cols[xkey], cols[k], label=label + suffix)
    ax.grid(True, alpha=0.3)


def overlay(runs, panels, out_dir=None, xlabel="time [s]", xkey="time", decorate=None, dpi=110, figsize=(7, 4)):
    """One figure per panel (name, ylabel, keys) with every run overlaid;
    saved as out_dir/name.png when out_dir is given (then closed), else
    returned. decorate(ax, runs) may add marks (e.g. the run-up line).
    Returns {name: figure} for figures kept open."""
    plt = _plt()
    figures = {}
    for name, ylabel, keys in panels:
        fig, ax = plt.subplots(figsize=figsize)
        time_history(ax, runs, keys, xkey=xkey, label_keys={k: k.rsplit("_", 1)[0] for k in keys})
        if decorate:
            decorate(ax, runs)
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
        ax.legend(fontsize=7)
        fig.tight_layout()
        if out_dir:
            os.makedirs(out_dir, exist_ok=True)
            fig.savefig(os.path.join(out_dir, name + ".png"), dpi=dpi)
            plt.close(fig)
        else:
            figures[name] = fig
    return figures


def plot_results(results, keys=None, ax=None, label=""):
    """Time histories of one Results (all channels when keys is None) into
    `ax` (a new figure when None); returns the axes."""
    plt = _plt()
    if ax is None:
        _, ax = plt.subplots(figsize=(7, 4))
    keys = [k for k in results if k != "time"] if keys is None else keys
    for k in keys:
        ax.plot(results["time"], results[k], label=(label + " " + k).strip())
    ax.set_xlabel("time [s]")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
    return ax


def plot_modes(body, count=6, out=None, scale=None):
    """The first `count` mode shapes of a Body: undeformed nodes (grey) and
    nodes displaced by each mode, in the x-y and x-z views; saved to `out`
    (PNG) when given. scale: displacement factor (default: 10 % of the
    body's size over the largest modal displacement)."""
    import numpy as np
    plt = _plt()
    count = min(count, body.mode_count)
    fig, axes = plt.subplots(count, 2, figsize=(9, 1.8 * count + 0.6), squeeze=False)
    x = body.nodes
    size = float(np.ptp(x, axis=0).max()) or 1.0
    for k in range(count):
        u = body.mode_shape(k)
        s = scale if scale is not None else 0.1 * size / max(float(np.abs(u).max()), 1e-30)
        f = body.frequencies_hz[k] if k < len(body.frequencies_hz) else float("nan")
        for col, (i, j, name) in enumerate([(0, 1, "y"), (0, 2, "z")]):
            ax = axes[k][col]
            ax.plot(x[:, i], x[:, j], ".", ms=1, color="0.7")
            ax.plot(x[:, i] + s * u[:, i], x[:, j] + s * u[:, j], ".", ms=1.5)
            ax.set_ylabel(f"{name} [m]")
            ax.set_title(f"mode {k + 1}: {f:.2f} Hz", fontsize=8)
            ax.set_aspect("equal", adjustable="datalim")
    for ax in axes[-1]:
        ax.set_xlabel("x [m]")
    fig.tight_layout()
    if out:
        fig.savefig(out, dpi=110)
        plt.close(fig)
    return fig
