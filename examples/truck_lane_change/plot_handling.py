#!/usr/bin/python3
"""Plots of a handling test (`flexmb truck handling ... --out RUN_DIR`).

Usage: /usr/bin/python3 plot_handling.py RUN_DIR [RUN_DIR ...] [--out DIR]
step-steer: step_response.png (steering-wheel angle, yaw rate, lateral
acceleration and roll over time); sine-steer: sine_response.png (the same)
and frequency_response.png (gain and phase lag of the yaw rate and lateral
acceleration against frequency, one point per run, beside the single-track
model's); constant-steer: understeer.png (steering
angle less the kinematic angle L / R, at the steering wheel and at the road
wheels, against lateral acceleration, with the single-track line) and
roll_gradient.png (roll and side slip against lateral acceleration).
Several runs of one test are overlaid (e.g. rigid against elastic frame).
"""
import csv
import json
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from plot import flexmb_plot  # noqa: E402  (plot.py beside this script)


def load(run):
    with open(os.path.join(run, "results.csv")) as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(run, "summary.json")) as f:
        summary = json.load(f)
    label = "%s (%s frame)" % (os.path.basename(os.path.normpath(run)), summary["frame"])
    # constant steer: the quasi-steady states only (the speed rising)
    t0 = summary.get("quasi_steady_from", 0.0)
    rows = [r for r in rows if float(r["time"]) >= t0]
    return label, {k: [float(r[k]) for r in rows] for k in rows[0]}, summary


def step_steer(runs, out, name="step_response.png"):
    fig, axes = plt.subplots(4, 1, figsize=(7, 9), sharex=True)
    keys = [("steering_wheel_angle_deg", "steering wheel [deg]"), ("yaw_rate_degps", "yaw rate [deg/s]"),
            ("lateral_acceleration", "lateral acc. [m/s$^2$]"), ("roll_deg", "roll [deg]")]
    for label, c, _ in runs:
        for ax, (key, _) in zip(axes, keys):
            ax.plot(c["time"], c[key], label=label)
    for ax, (_, ylabel) in zip(axes, keys):
        ax.set_ylabel(ylabel)
        ax.grid(True, alpha=0.3)
    axes[-1].set_xlabel("time [s]")
    axes[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, name), dpi=110)
    plt.close(fig)


def sine_steer(runs, out):
    step_steer(runs, out, "sine_response.png")
    pts = sorted((s["frequency_hz"], s) for _, _, s in runs)
    f = [p[0] for p in pts]
    fig, axes = plt.subplots(2, 2, figsize=(9, 6), sharex=True)
    for col, (key, unit) in enumerate((("yaw_rate", "1/s"), ("lateral_acceleration", "m/s$^2$"))):
        for row, (metric, ylabel) in enumerate((("_gain", "gain [%s per rad]" % unit),
                                                ("_phase_lag_deg", "phase lag [deg]"))):
            ax = axes[row][col]
            ax.plot(f, [p[1][key + metric] for p in pts], "o-", label="truck")
            ax.plot(f, [p[1]["single_track_" + key + metric] for p in pts], "s--", label="single-track model")
            ax.set_ylabel(ylabel)
            ax.grid(True, alpha=0.3)
        axes[0][col].set_title(key.replace("_", " "))
        axes[1][col].set_xlabel("frequency [Hz]")
    axes[0][0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "frequency_response.png"), dpi=110)
    plt.close(fig)


def constant_steer(runs, out, g=9.81):
    series = []
    for label, c, s in runs:
        ay = c["lateral_acceleration"]
        kin = [s["wheelbase"] * k for k in c["curvature"]]
        sw = [math.degrees(math.radians(d) / s["steering_ratio"] - x) for d, x in zip(c["steering_wheel_angle_deg"], kin)]
        rw = [math.degrees(math.radians(d) - x) for d, x in zip(c["road_wheel_angle_deg"], kin)]
        k = s["single_track_understeer_gradient_deg_per_g"]
        series += [(ay, sw, label + ", steering wheel / ratio", {"lw": 0.9}),
                   (ay, rw, label + ", road wheels", {"lw": 0.9, "ls": "--"}),
                   ([0, max(ay)], [0, k * max(ay) / g], "single-track slope %.2f deg/g" % k,
                    {"color": "k", "ls": ":", "lw": 0.8})]
    fp = flexmb_plot()
    fp.save_xy(os.path.join(out, "understeer.png"), series, "lateral acceleration [m/s$^2$]",
               "steer angle - L / R [deg]")
    series = []
    for label, c, _ in runs:
        series += [(c["lateral_acceleration"], c["roll_deg"], label + ", roll", {}),
                   (c["lateral_acceleration"], c["sideslip_deg"], label + ", side slip", {"ls": "--"})]
    fp.save_xy(os.path.join(out, "roll_gradient.png"), series, "lateral acceleration [m/s$^2$]", "angle [deg]")


def main():
    run_dirs, out = flexmb_plot().run_dir_arguments()
    runs = [load(r) for r in run_dirs]
    tests = {s["test"] for _, _, s in runs}
    if len(tests) != 1:
        raise SystemExit("runs of different tests: %s" % ", ".join(sorted(tests)))
    plot = {"step-steer": step_steer, "sine-steer": sine_steer, "constant-steer": constant_steer}.get(tests.pop())
    if plot is None:
        raise SystemExit("no plots for this test (step-steer, sine-steer, constant-steer)")
    plot(runs, out)
    print("plots in %s" % out)


if __name__ == "__main__":
    main()
