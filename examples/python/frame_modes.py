#!/usr/bin/python3
"""A ladder frame (two C-channel rails, four tube cross members; CBAR beams)
written as a Nastran bulk-data file, reduced by Craig-Bampton with interface
nodes at the four spring hangers, and its modes plotted.

Usage: PYTHONPATH=build/release/python /usr/bin/python3 examples/python/frame_modes.py [OUT_DIR]
Writes OUT_DIR/frame.bdf, frame.h5 and frame_modes.png."""
import os
import sys

import numpy as np

import flexmb
import flexmb.plot

out_dir = sys.argv[1] if len(sys.argv) > 1 else "out/python"
os.makedirs(out_dir, exist_ok=True)

length, half_track, n = 6.0, 0.45, 24  # rail length [m], half the rail spacing [m], elements per rail
xs = np.linspace(0.0, length, n + 1)
cross_at = [0, 8, 16, 24]              # rail stations with a cross member
lines = ["BEGIN BULK", "MAT1,1,2.1+11,,0.3,7850.",
         # rail: C 250 x 80 x 7 (A [m^2], I1, I2 [m^4], J [m^4]); cross member: tube
         "PBAR,1,1,4.2-3,3.5-5,2.6-6,7.0-8", "PBAR,2,1,1.5-3,2.0-6,2.0-6,4.0-6"]
grid = {}
gid = 1
for side, y in enumerate([-half_track, half_track]):
    for k, x in enumerate(xs):
        grid[(side, k)] = gid
        lines.append(f"GRID,{gid},,{x:.4f},{y:.4f},0.")
        gid += 1
eid = 1
for side in (0, 1):
    for k in range(n):
        lines.append(f"CBAR,{eid},1,{grid[(side, k)]},{grid[(side, k + 1)]},0.,0.,1.")
        eid += 1
for k in cross_at:
    lines.append(f"CBAR,{eid},2,{grid[(0, k)]},{grid[(1, k)]},0.,0.,1.")
    eid += 1
lines.append("ENDDATA")
bdf = os.path.join(out_dir, "frame.bdf")
with open(bdf, "w") as f:
    f.write("\n".join(lines) + "\n")

print("fe info:", {k: v for k, v in flexmb.fe_info(bdf).items() if k in ("nodes", "elements", "mass_kg")})
full = flexmb.fe_modes(bdf, count=12)
print("full model, free-free [Hz]:", np.round(full["frequencies_hz"], 2))

hangers = [grid[(0, 2)], grid[(1, 2)], grid[(0, 22)], grid[(1, 22)]]
rep = flexmb.reduce(bdf, os.path.join(out_dir, "frame.h5"), interface=hangers, modes=12, damping_ratio=0.02)
print("reduced body, flexible [Hz]:", np.round(rep["frequencies_hz"], 2))

body = flexmb.Body(os.path.join(out_dir, "frame.h5"))
print(body, "mass %.1f kg, centre of mass" % body.total_mass, np.round(body.center_of_mass, 3))
flexmb.plot.plot_modes(body, count=6, out=os.path.join(out_dir, "frame_modes.png"))
print("plot:", os.path.join(out_dir, "frame_modes.png"))
