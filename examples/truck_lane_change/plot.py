#!/usr/bin/python3
"""Plots of a truck lane-change run (results.csv of `flexmb run truck.yaml`).

Usage: /usr/bin/python3 plot.py RUN_DIR [RUN_DIR ...] [--out DIR]
Writes lateral_acceleration.png, steering_wheel_angle.png, roll.png,
yaw_rate.png, axle_loads.png, tire_loads.png, load_transfer.png (load-transfer
ratio per axle), roll_vs_lateral_acceleration.png and path.png; several run directories are
overlaid (e.g. rigid against elastic frame, as the seed's Figs. 9 to 14:
`plot.py RIGID_DIR ELASTIC_DIR --out PNGDIR`). Runs with the elastic frame
add frame_deflection.png (largest elastic displacement of a frame node
relative to the floating frame, and the x of that node) and frame_stress.png
(largest von Mises stress of the shell stress modes, and the x of that
element) over time.
"""
import csv
import importlib.util
import json
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def load(run_dir):
    with open(os.path.join(run_dir, "results.csv")) as f:
        rows = list(csv.DictReader(f))
    cols = {k: [float(r[k]) for r in rows] for k in rows[0]}
    label = os.path.basename(os.path.normpath(run_dir))
    try:
        with open(os.path.join(run_dir, "summary.json")) as f:
            s = json.load(f)
        label = "%s (%s frame, %.0f km/h, %s)" % (label, s["frame"], s["entry_speed_kmh"],
                                                  "passed" if s["passed"] else "failed")
    except (OSError, KeyError, ValueError):
        pass
    return label, cols


def flexmb_plot():
    """The plot helpers of the Python module (python/flexmb/plot.py), loaded
    from the source tree: they need matplotlib only, not the compiled core."""
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python", "flexmb", "plot.py")
    spec = importlib.util.spec_from_file_location("flexmb_plot", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def mark_run_up(ax, runs):
    """Dotted line where the first run's front axle reaches section 1 (x = 0):
    before it the run-up, where the start settles (not monitored)."""
    c = runs[0][1]
    t0 = next((t for t, x in zip(c["time"], c["x"]) if x >= 0.0), None)
    if t0 is not None and t0 > 0.0:
        ax.axvline(t0, color="0.5", ls=":", lw=0.8)
        ax.annotate("section 1", (t0, 1.0), xycoords=("data", "axes fraction"), xytext=(3, -10),
                    textcoords="offset points", fontsize=7, color="0.4")


def main():
    fp = flexmb_plot()
    run_dirs, out = fp.run_dir_arguments()
    runs = [load(r) for r in run_dirs]
    # per axle and per tire, as many as the (first) truck has
    columns = list(runs[0][1].keys())
    axle_loads = [k for k in columns if k.endswith("_axle_load_kN")]
    tire_loads = [k for k in columns if k.startswith("fz_") and k.endswith("_kN")]
    ltr = [k for k in columns if k.startswith("ltr_")]
    panels = [
        ("lateral_acceleration", "lateral acceleration [m/s$^2$]", ["lateral_acceleration"]),
        ("steering_wheel_angle", "steering-wheel angle [deg]", ["steering_wheel_angle_deg"]),
        ("roll", "roll angle of the frame [deg]", ["roll_deg"]),
        ("yaw_rate", "yaw rate [deg/s]", ["yaw_rate_degps"]),
        ("axle_loads", "axle load [kN]", axle_loads),
        ("tire_loads", "tire vertical load [kN] (rear: twin set)", tire_loads),
    ]
    if ltr and all(ltr[0] in c for _, c in runs):
        panels.append(("load_transfer", "load-transfer ratio [-] (1: lift-off)", ltr))
    fp.overlay(runs, panels, out_dir=out, decorate=mark_run_up)
    elastic = [(label, c) for label, c in runs if "frame_max_displacement_mm" in c]
    for name, key, pos, ylabel in [
        ("frame_deflection", "frame_max_displacement_mm", "frame_max_displacement_x",
         "max elastic displacement\nof the frame [mm]"),
        ("frame_stress", "frame_max_stress_MPa", "frame_max_stress_x", "max von Mises stress\nin the frame [MPa]"),
    ]:
        if not elastic:
            break
        fig, (ax, ax2) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
        for label, c in elastic:
            ax.plot(c["time"], c[key], label=label)
            ax2.plot(c["time"], c[pos], ".", ms=2, label=label)
        ax.set_ylabel(ylabel)
        mark_run_up(ax, elastic)
        ax2.set_ylabel("x of the maximum [m]")
        ax2.set_xlabel("time [s]")
        for a_ in (ax, ax2):
            a_.grid(True, alpha=0.3)
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(out, name + ".png"), dpi=110)
        plt.close(fig)
    # roll against lateral acceleration in the monitored part (x >= 0)
    series = []
    for label, c in runs:
        kept = [k for k, x in enumerate(c["x"]) if x >= 0.0]
        series.append(([c["lateral_acceleration"][k] for k in kept], [c["roll_deg"][k] for k in kept], label,
                       {"lw": 0.9}))
    fp.save_xy(os.path.join(out, "roll_vs_lateral_acceleration.png"), series, "lateral acceleration [m/s$^2$]",
               "roll angle of the frame [deg]", figsize=(6, 4.5))
    series = [(c["x"], c["y"], label + " front axle", {}) for label, c in runs]
    c = runs[0][1]
    series.append((c["x"], c["centre_line_y"], "course centre line", {"color": "k", "ls": "--", "lw": 0.8}))
    fp.save_xy(os.path.join(out, "path.png"), series, "x [m]", "y [m]", figsize=(9, 3))
    print("plots in %s" % out)


if __name__ == "__main__":
    main()
