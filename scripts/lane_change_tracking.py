#!/usr/bin/python3
"""Tracking error of the driver in lane-change runs (issue 7).

Usage: /usr/bin/python3 scripts/lane_change_tracking.py DIR [DIR ...]

Reads DIR/results.csv of `flexmb run examples/truck_lane_change/truck.yaml
--out DIR` and the course from DIR/../ nothing: the course is taken from the
columns x (front-axle centre), y and centre_line_y. Prints per run:
  sec1_max   max |y - y_c| in section 1 (x < L0) [m]
  sec3_max   max |y - y_c| in section 3 (x >= L0 + L2) [m]
  overshoot  max (y - offset) beyond the new lane's centre [m] (0 if never)
  lag        x where y first reaches offset / 2, minus x where the centre
             line does (L0 + L2 / 2) [m]
  rms        RMS of y - y_c over the whole run [m]
  margin     smallest corridor margin of the four gauge points [m]
L0, L2 and the offset are read from the centre-line column (the first x
where it leaves 0, the first x where it reaches its final value).
"""
import sys

import numpy as np


def analyse(path):
    d = np.genfromtxt(path + "/results.csv", delimiter=",", names=True)
    x, y, yc = d["x"], d["y"], d["centre_line_y"]
    offset = yc[-1]
    moving = np.nonzero(np.abs(yc) > 1e-9)[0]
    l0 = x[moving[0] - 1] if len(moving) else x[-1]
    done = np.nonzero(np.abs(yc - offset) < 1e-9)[0]
    x3 = x[done[0]] if len(done) else x[-1]
    e = y - yc
    s1, s3 = x < l0, x >= x3
    half = 0.5 * offset
    i_y = np.nonzero(y >= half)[0]
    i_c = np.nonzero(yc >= half)[0]
    lag = (np.interp(half, y[i_y[0] - 1:i_y[0] + 1], x[i_y[0] - 1:i_y[0] + 1]) -
           np.interp(half, yc[i_c[0] - 1:i_c[0] + 1], x[i_c[0] - 1:i_c[0] + 1])) if len(i_y) and len(i_c) else float("nan")
    return dict(sec1_max=np.max(np.abs(e[s1])) if s1.any() else 0.0,
                sec3_max=np.max(np.abs(e[s3])) if s3.any() else 0.0,
                overshoot=max(0.0, np.max(y - offset)), lag=lag, rms=np.sqrt(np.mean(e * e)),
                margin=np.min(d["corridor_margin"][d["time"] > 0]))


def main():
    keys = ["sec1_max", "sec3_max", "overshoot", "lag", "rms", "margin"]
    print("run " + " ".join("%10s" % k for k in keys))
    for p in sys.argv[1:]:
        r = analyse(p)
        print(p + " " + " ".join("%10.3f" % r[k] for k in keys))


if __name__ == "__main__":
    main()
