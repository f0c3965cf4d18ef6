#!/usr/bin/python3
"""A truck lane-change speed study: the lane change of
examples/truck_lane_change/truck.yaml at several speeds, rigid and elastic
frame, run in parallel processes (flexmb.run_study); a table of the metrics
and overlays of the rigid and elastic runs.

Usage: PYTHONPATH=build/release/python /usr/bin/python3 examples/python/truck_speed_study.py [OUT_DIR] [SPEEDS]
SPEEDS: comma-separated km/h (default 40,50,60). Writes OUT_DIR/study.csv,
OUT_DIR/<frame>_<speed>/ (results.csv, summary.json) and the PNGs in OUT_DIR/plots."""
import csv
import os
import sys

import flexmb
import flexmb.plot

HERE = os.path.dirname(os.path.abspath(__file__))
TRUCK = os.path.join(HERE, "..", "truck_lane_change", "truck.yaml")
out_dir = sys.argv[1] if len(sys.argv) > 1 else "out/python/truck_study"
speeds = [float(s) for s in (sys.argv[2] if len(sys.argv) > 2 else "40,50,60").split(",")]


def lane_change(variant):
    """One variant: a lane change; returns the metrics of the table."""
    run_dir = os.path.join(out_dir, "%s_%g" % (variant["frame"], variant["speed_kmh"]))
    r = flexmb.lane_change(TRUCK, speed_kmh=variant["speed_kmh"], frame=variant["frame"], out_dir=run_dir)
    return {k: r.metrics.get(k) for k in ("passed", "max_lateral_acceleration", "max_roll_deg",
                                       "min_corridor_margin", "max_frame_stress_MPa", "wall_time_s")}


if __name__ == "__main__":
    variants = [{"frame": f, "speed_kmh": v} for v in speeds for f in ("rigid", "elastic")]
    table = flexmb.run_study(lane_change, variants)
    os.makedirs(out_dir, exist_ok=True)
    with open(os.path.join(out_dir, "study.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=[k for k in table[0] if k != "traceback"], extrasaction="ignore")
        w.writeheader()
        w.writerows(table)
    for row in table:
        print(row.get("error") or row)
    # rigid against elastic at the highest speed, as the demo's plots
    v = max(speeds)
    runs = []
    for frame in ("rigid", "elastic"):
        res = flexmb.read_results(os.path.join(out_dir, "%s_%g" % (frame, v)))
        runs.append(("%s frame, %g km/h" % (frame, v), res))
    flexmb.plot.overlay(runs, [
        ("lateral_acceleration", "lateral acceleration [m/s$^2$]", ["lateral_acceleration"]),
        ("roll", "roll angle of the frame [deg]", ["roll_deg"]),
        ("axle_loads", "axle load [kN]", ["front_axle_load_kN", "rear_axle_load_kN"]),
    ], out_dir=os.path.join(out_dir, "plots"))
    print("table:", os.path.join(out_dir, "study.csv"), "plots:", os.path.join(out_dir, "plots"))
