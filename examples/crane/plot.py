#!/usr/bin/python3
"""Metrics and plots of the example crane's work cycle (results.csv of
`flexmb run crane.yaml`): lift-off of the grounded load, then a 90 degree
slew with the load swinging.

Usage: /usr/bin/python3 plot.py RUN_DIR [--out DIR] [--mass 5000] [--falls 2]
       [--released-mass 2000]

Writes DIR/crane_metrics.json and the plots rope_force.png,
hook_height.png, swing.png, slewing.png, winch_and_cylinder.png,
boom_deflection.png, boom_stress.png and outriggers.png (DIR defaults to
RUN_DIR/plots).
Metrics:
- phi_2: the dynamic factor of hoisting a grounded load (EN 13001-2 /
  ISO 8686-1): the largest hoist load from the start to one second after
  lift-off over the load's weight (the hoist load is the load on the
  hook: the rope tension times the falls); the largest hoist load up to
  the slew, the winch's stop included, is reported beside it;
- lift_off_time_s: when the block leaves the ground (hook 1 mm above its
  start height);
- the largest swing of the rope from the vertical during and after the
  slew (radial: in the boom's plane; tangential: across it) and its
  residual swing after the slew stops;
- the largest slewing torque, the deflection of the boom head from its
  undeformed place (radial, lateral, vertical; the platform and the
  cylinder are rigid, so it is the boom's), and the
  largest von Mises stress of the two flange elements beyond the
  cylinder eye;
- the outrigger pads' loads: static, smallest and largest, the weakest
  pad's smallest share of the crane's weight (a pad at zero has lifted:
  the carrier rocks on three pads), and the stability margin: the
  smallest distance of the pad loads' centre of pressure from the edge of
  the support rectangle (the crane tips when it reaches the edge);
- the largest winch drum torque (the hoisting drive's reaction) and
  luffing cylinder force (the cylinder length driver's reaction);
- phi_3, when the grab lets part of the load go (the `release`
  manoeuvre; the grab's reaction, sensor `grab`, drops to zero): the
  smallest hoist load within two seconds after the release over the whole
  load's weight, beside EN 13001-2's sudden-release value 1 - 2 dm / m
  (dm the released mass, --released-mass).
"""
import argparse
import csv
import json
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

G = 9.81


def load(run_dir):
    with open(os.path.join(run_dir, "results.csv")) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def mean(values):
    return sum(values) / len(values) if values else float("nan")


def window(t, y, t0, t1):
    return [v for s, v in zip(t, y) if t0 <= s <= t1]


def swing_angles(c):
    """Radial and tangential rope angles from the vertical [deg]: the
    head-to-hook vector in the frame turned with the slewing angle."""
    rad, tan = [], []
    for k in range(len(c["time"])):
        dx = c["hook.x"][k] - c["head.x"][k]
        dy = c["hook.y"][k] - c["head.y"][k]
        dz = c["head.z"][k] - c["hook.z"][k]
        a = c["slew.value"][k]
        r = math.cos(a) * dx + math.sin(a) * dy
        s = -math.sin(a) * dx + math.cos(a) * dy
        rad.append(math.degrees(math.atan2(r, dz)))
        tan.append(math.degrees(math.atan2(s, dz)))
    return rad, tan


# the boom head sheave pin of the undeformed boom (crane.yaml: foot pin at
# x = 1 m, z = 3.2 m, 18 m luffed 40 degrees), in the slewing frame
HEAD_RADIUS = 1.0 + 18.0 * math.cos(math.radians(40.0))
HEAD_HEIGHT = 3.2 + 18.0 * math.sin(math.radians(40.0))


def head_deflection(c):
    """Deflection of the boom head from its undeformed place [m], in the
    platform's axes (sensor head_on_platform: turned with the slew and the
    carrier's tilt on its outriggers), else in the frame turned with the
    slewing angle: radial (outwards), lateral (across the boom's plane) and
    vertical. The platform and the luffing cylinder are rigid, so this is
    the boom's elastic deflection (with the local give of the foot and eye
    connections)."""
    if "head_on_platform.x" in c:
        return ([x - HEAD_RADIUS for x in c["head_on_platform.x"]], list(c["head_on_platform.y"]),
                [z - HEAD_HEIGHT for z in c["head_on_platform.z"]])
    dr, dy, dz = [], [], []
    for k in range(len(c["time"])):
        a = c["slew.value"][k]
        x, y = c["head.x"][k], c["head.y"][k]
        dr.append(math.cos(a) * x + math.sin(a) * y - HEAD_RADIUS)
        dy.append(-math.sin(a) * x + math.cos(a) * y)
        dz.append(c["head.z"][k] - HEAD_HEIGHT)
    return dr, dy, dz


def hoist_load(c, falls):
    """Load on the hook [N]: the rope tension at the winch times the falls
    (one tension along the reeved rope)."""
    return [falls * v for v in c["rope.f"]]


def metrics(c, mass, falls=2):
    t = c["time"]
    hoist = hoist_load(c, falls)
    weight = mass * G
    z0 = c["hook.z"][0]
    lift = next((s for s, z in zip(t, c["hook.z"]) if z > z0 + 1e-3), None)
    slew = [s for s, a in zip(t, c["slew.value"]) if a > 1e-6]
    slew_start = slew[0] if slew else t[-1]
    slew_end = next((s for s, a in zip(t, c["slew.value"]) if a > math.pi / 2 - 1e-6), t[-1])
    rad, tan = swing_angles(c)
    head_dr, head_dy, head_dz = head_deflection(c)
    # the head's undeformed place is that of the 40 degree boom: not
    # reported when the manoeuvre luffs (the cylinder's length changes)
    stroke = c.get("cylinder_length.value", [0.0])
    luffs = max(stroke) - min(stroke) > 1e-3
    vm = [k for k in c if k.endswith("_von_mises") and ("top_flange" in k or "bottom_flange" in k)]
    return {
        "load_weight_N": weight,
        # the peak while the load leaves the ground: up to one second (more
        # than the first bounce, 0.85 s here) after lift-off
        "phi_2": max(window(t, hoist, 0.0, (lift if lift is not None else t[-1]) + 1.0)) / weight,
        # including the stop of the winch (brake) before the slew
        "hoist_load_max_before_slew_N": max(window(t, hoist, 0.0, slew_start)),
        "lift_off_time_s": lift,
        # mean over the bouncing between lift-off and the slew: the static hoist load
        "hoist_load_mean_N": mean(window(t, hoist, (lift or 0.0) + 1.0, slew_start)),
        "rope_tension_max_N": max(c["rope.f"]),
        "winch_torque_max_Nm": max(abs(v) for v in c["winch_torque.mz"]),
        "cylinder_force_max_N": max(math.sqrt(a * a + b * b + d * d) for a, b, d in
                                    zip(c["cylinder.fx"], c["cylinder.fy"], c["cylinder.fz"])),
        "swing_radial_max_deg": max(abs(v) for v in window(t, rad, slew_start, t[-1])),
        "swing_tangential_max_deg": max(abs(v) for v in window(t, tan, slew_start, t[-1])),
        "swing_residual_deg": max(math.hypot(a, b) for a, b in zip(window(t, rad, slew_end, t[-1]),
                                                                     window(t, tan, slew_end, t[-1]))),
        "swing_max_deg": max(math.hypot(a, b) for a, b in zip(rad, tan)),
        "slewing_torque_max_Nm": max(abs(v) for v in c["slew_torque.mz"]),
        "hoist_load_max_N": max(hoist),
        "cylinder_stroke_range_m": max(stroke) - min(stroke),
        "boom_head_lateral_max_m": None if luffs else max(abs(v) for v in head_dy),
        "boom_head_vertical_range_m": None if luffs else [min(head_dz), max(head_dz)],
        "boom_head_radial_range_m": None if luffs else [min(head_dr), max(head_dr)],
        "flange_von_mises_max_Pa": max(max(c[k]) for k in vm) if vm else None,
        "slew_start_s": slew_start,
        "slew_end_s": slew_end,
    }


PADS = ("pad_fl", "pad_fr", "pad_rr", "pad_rl")
# the pads' places on the carrier (crane.yaml; x forwards, y left) [m]
PAD_XY = {"pad_fl": (2.8, 3.0), "pad_fr": (2.8, -3.0), "pad_rr": (-3.4, -3.0), "pad_rl": (-3.4, 3.0)}


def outriggers(c):
    """The outrigger pads' loads (sensors pad_*: the ground's push on each
    pad) [N]: each pad's smallest and largest load and when the smallest
    comes, and the smallest over the total (the tipping margin: the crane
    tips when a pad's load reaches zero). Empty for a crane on a fixed base."""
    if "pad_fl.fz" not in c:
        return {}
    t = c["time"]
    total = [sum(c[p + ".fz"][k] for p in PADS) for k in range(len(t))]
    # centre of pressure of the pad loads and its distance from the edge of
    # the support rectangle: the crane tips when it reaches the edge
    xs = [PAD_XY[p][0] for p in PADS]
    ys = [PAD_XY[p][1] for p in PADS]
    margin, k_m, centre = float("inf"), 0, (0.0, 0.0)
    for k in range(len(t)):
        x = sum(c[p + ".fz"][k] * PAD_XY[p][0] for p in PADS) / total[k]
        y = sum(c[p + ".fz"][k] * PAD_XY[p][1] for p in PADS) / total[k]
        d = min(max(xs) - x, x - min(xs), max(ys) - y, y - min(ys))
        if d < margin:
            margin, k_m, centre = d, k, (x, y)
    low = {p: min(range(len(t)), key=lambda k, p=p: c[p + ".fz"][k]) for p in PADS}
    weakest = min(PADS, key=lambda p: c[p + ".fz"][low[p]])
    k = low[weakest]
    return {
        "pad_load_min_N": {p: c[p + ".fz"][low[p]] for p in PADS},
        "pad_load_max_N": {p: max(c[p + ".fz"]) for p in PADS},
        "pad_load_static_N": {p: c[p + ".fz"][0] for p in PADS},
        "pad_weakest": weakest,
        "pad_weakest_time_s": t[k],
        "pad_weakest_share": c[weakest + ".fz"][k] / total[k],
        "crane_weight_on_pads_N": total[0],
        "pressure_centre_margin_min_m": margin,
        "pressure_centre_margin_time_s": t[k_m],
        "pressure_centre_at_margin_m": list(centre),
    }


def release(c, mass, released_mass, falls):
    """phi_3 of a sudden release (EN 13001-2, beta_3 = 1): the release time
    (the grab's reaction falls to zero), the released mass's share of the
    load and the smallest hoist load after it over the load's weight."""
    if "grab.fx" not in c:
        return {}
    t = c["time"]
    grab = [math.sqrt(a * a + b * b + d * d) for a, b, d in zip(c["grab.fx"], c["grab.fy"], c["grab.fz"])]
    k = next((i for i in range(1, len(t)) if grab[i] == 0.0 and grab[i - 1] > 0.0), None)
    if k is None:
        return {}
    hoist = hoist_load(c, falls)
    share = released_mass / mass
    return {
        "release_time_s": t[k],
        "released_share": share,
        "phi_3": min(window(t, hoist, t[k], t[k] + 2.0)) / (mass * G),
        "phi_3_en13001_sudden": 1.0 - 2.0 * share,
    }


def plot(out, name, t, series, ylabel, title):
    fig, ax = plt.subplots(figsize=(8, 4.5))
    for label, y in series:
        ax.plot(t, y, label=label)
    ax.set_xlabel("time [s]")
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    if len(series) > 1:
        ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, name), dpi=110)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("run_dir")
    ap.add_argument("--out", default=None)
    ap.add_argument("--mass", type=float, default=5000.0, help="payload with hook block [kg]")
    ap.add_argument("--falls", type=int, default=2, help="parts of line the hook block hangs on")
    ap.add_argument("--released-mass", type=float, default=2000.0,
                    help="part of the payload the grab lets go in the release manoeuvre [kg]")
    a = ap.parse_args()
    out = a.out or os.path.join(a.run_dir, "plots")
    os.makedirs(out, exist_ok=True)
    c = load(a.run_dir)
    m = metrics(c, a.mass, a.falls)
    m.update(release(c, a.mass, a.released_mass, a.falls))
    m.update(outriggers(c))
    with open(os.path.join(out, "crane_metrics.json"), "w") as f:
        json.dump(m, f, indent=2)
    print(json.dumps(m, indent=2))
    t = c["time"]
    plot(out, "rope_force.png", t, [("hoist load (on the hook)", [v / 1e3 for v in hoist_load(c, a.falls)]),
                                    ("load weight", [m["load_weight_N"] / 1e3] * len(t))],
         "force [kN]", "Hoist load: lift-off (phi_2 = %.3f) and slewing" % m["phi_2"])
    plot(out, "hook_height.png", t, [("hook", c["hook.z"])], "height [m]", "Hook height")
    rad, tan = swing_angles(c)
    plot(out, "swing.png", t, [("radial (in the boom plane)", rad), ("tangential (across)", tan)],
         "rope angle from vertical [deg]", "Load swing")
    plot(out, "slewing.png", t, [("slewing angle [deg]", [math.degrees(v) for v in c["slew.value"]]),
                                 ("slewing torque [kN m]", [v / 1e3 for v in c["slew_torque.mz"]])],
         "", "Slewing drive")
    plot(out, "winch_and_cylinder.png", t,
         [("winch drum torque [kN m]", [v / 1e3 for v in c["winch_torque.mz"]]),
          ("luffing cylinder force [10 kN]", [math.sqrt(a * a + b * b + d * d) / 1e4 for a, b, d in
                                              zip(c["cylinder.fx"], c["cylinder.fy"], c["cylinder.fz"])])],
         "", "Hoisting winch and luffing cylinder")
    dr, dy, dz = head_deflection(c)
    plot(out, "boom_deflection.png", t,
         [("vertical", [v * 1e3 for v in dz]), ("lateral", [v * 1e3 for v in dy]),
          ("radial", [v * 1e3 for v in dr])],
         "deflection [mm]", "Boom head from its undeformed place (platform axes)")
    if "pad_fl.fz" in c:
        plot(out, "outriggers.png", t, [(p, [v / 1e3 for v in c[p + ".fz"]]) for p in PADS],
             "pad load [kN]", "Outrigger pad loads (tipping when one reaches zero)")
    vm = [k for k in c if k.endswith("_von_mises") and ("top_flange" in k or "bottom_flange" in k)]
    plot(out, "boom_stress.png", t, [(k, [v / 1e6 for v in c[k]]) for k in vm], "von Mises [MPa]",
         "Boom flanges beyond the cylinder eye")
    print("plots in", out)


if __name__ == "__main__":
    main()
