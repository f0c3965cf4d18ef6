#!/usr/bin/python3
"""The example crane's hoisting rope two ways, on the same crane and
manoeuvre:

  massless  the `rope` force element: a tension-only elastic line from the
            boom head to the hook, free length from the hoisting speed
  ancf      an `ancf_hoist_rope` body: the hanging span as ANCF cable
            elements whose free length the `winch` driver changes, with the
            rope's mass moving between drum and span

The manoeuvre: crane.yaml's crane with its 5 t load lifted clear of the
ground on one fall (the lower part of the block and its ground contacts
left out, the upper part given the whole block's mass), hoisted at
0.3 m/s from 6 s to 10 s while the crane slews 90 degrees (crane.yaml's
slew_drive). The lead span from the winch to the boom head is left out of
both (the hanging span is what differs).

Usage (in examples/crane, after make_boom.py and flexmb reduce, README.md):
  /usr/bin/python3 rope_methods.py [--flexmb PATH] [--body boom.h5] [--out rope_methods] [--elements 10] [--animation]

Writes crane_<method>.yaml and runs it in --out, then rope_methods.json and
rope_methods.md: the largest swing of the rope from the vertical, the
largest hook force, the hook's height at the end, the boom head's largest
deflection and the run time of each. The rope weighs 1.6 kg/m against the
5 t load, so the two must agree to the rope's weight and stretch; the
ANCF rope adds the rope's own mass and its transverse waves.
"""
import argparse
import copy
import csv
import json
import math
import os
import subprocess
import time

import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
LIFT = 2.0                     # the load starts this far above its place on the ground [m]
EA = 1.7e7                     # crane.yaml's rope: 20 mm, EA = 1.7e7 N
RHO_A = 1.6                    # its mass per length [kg/m] (steel area 1.73 cm^2 and the fibre core)
MASS = 5000.0                  # the whole block
# rope hauled in [m] and its rate [m/s]: 0.3 m/s from 6 s to 10 s, 0.5 s ramps
HOIST_SPEED = "(t < 6 ? 0 : (t < 6.5 ? 0.6*(t-6) : (t < 9.5 ? 0.3 : (t < 10 ? 0.3 - 0.6*(t-9.5) : 0))))"
HOIST = "(t < 6 ? 0 : (t < 6.5 ? 0.3*(t-6)^2 : (t < 9.5 ? 0.075 + 0.3*(t-6.5) : (t < 10 ? 0.975 + 0.3*(t-9.5) - 0.3*(t-9.5)^2 : 1.05))))"


def base_model(body):
    with open(os.path.join(HERE, "crane_model.yaml")) as f:
        m = yaml.safe_load(f)
    m.pop("manoeuvres", None)
    m.pop("manoeuvre", None)
    drop_bodies = {"part", "drum"}
    m["bodies"] = [b for b in m["bodies"] if b["name"] not in drop_bodies]
    for b in m["bodies"]:
        if b["name"] == "boom":
            b["file"] = os.path.abspath(body)
        if b["name"] == "load":   # the whole block, lifted
            b["mass"] = MASS
            b["inertia"] = [MASS / 12 * (4 + 0.55 ** 2)] * 2 + [MASS / 12 * 8]
            b["position"][2] += LIFT
    m["joints"] = [j for j in m["joints"] if j["name"] not in ("winch", "grab")]
    m["drivers"] = [d for d in m["drivers"] if d["name"] != "hoist_drive"]
    m["forces"] = [f for f in m["forces"] if f["name"] != "hoist_rope" and not f["name"].startswith("ground_c")]
    m["sensors"] = [s for s in m["sensors"] if s["name"] not in ("rope", "winch_torque", "winch_exit", "grab", "part")]
    m["solver"]["t_end"] = 24.0
    return m


def hook_and_head(m, head_W):
    load = [b for b in m["bodies"] if b["name"] == "load"][0]
    hook = [load["position"][0], load["position"][1], load["position"][2] + 1.39]
    length = math.dist(head_W, hook)
    return hook, length


def model(method, body, head_W, elements):
    m = base_model(body)
    hook, length = hook_and_head(m, head_W)
    # unstretched at the start, hanging taut: the statics stretches it
    if method == "massless":
        m["forces"].append({"name": "hoist_rope", "type": "rope", "i": "boom.head", "j": "load.hook",
                            "axial_stiffness": EA, "damping_time": 0.002, "free_length": length,
                            "hoist_speed": {"expression": HOIST_SPEED}})
        m["sensors"].append({"name": "hook_force", "type": "force_element", "force": "hoist_rope"})
    else:
        area = 1.73e-4
        m["bodies"].append({
            "name": "rope", "type": "ancf_hoist_rope", "free_length": length, "stored_length": 60.0,
            "elements": elements, "section": {"area": area, "inertia": 2e-9},
            "material": {"E": EA / area, "rho": RHO_A / area}, "damping": 0.002,
            "start": list(head_W), "direction": [hook[k] - head_W[k] for k in range(3)],
            "drum": {"position": [-2.2, 0, 3.6], "radius": 0.32, "inertia": 40.0},
            "markers": [{"name": "top", "end": "start"}, {"name": "hook", "end": "end"}]})
        m["joints"] += [{"name": "sheave", "type": "spherical", "i": "boom.head", "j": "rope.top"},
                        {"name": "hook", "type": "spherical", "i": "rope.hook", "j": "load.hook"}]
        m["drivers"].append({"name": "winch", "type": "winch", "rope": "rope",
                             "free_length": {"expression": "%.9g - %s" % (length, HOIST)}})
        m["sensors"].append({"name": "hook_force", "type": "joint_reaction", "joint": "hook", "frame": "world"})
    return m



def read_csv(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def metrics(r):
    n = len(r["time"])
    swing = max(math.degrees(math.atan2(math.hypot(r["hook.x"][i] - r["head.x"][i], r["hook.y"][i] - r["head.y"][i]),
                                        r["head.z"][i] - r["hook.z"][i])) for i in range(n))
    force = max(math.sqrt(r["hook_force.fx"][i] ** 2 + r["hook_force.fy"][i] ** 2 + r["hook_force.fz"][i] ** 2)
                for i in range(n))
    head = r["head_on_platform.z"]
    return {"largest_swing_deg": swing, "largest_hook_force_N": force, "hook_z_end_m": r["hook.z"][-1],
            "head_z_range_m": max(head) - min(head)}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--flexmb", default=os.path.join(HERE, "..", "..", "build", "release", "bin", "flexmb"))
    ap.add_argument("--body", default="boom.h5")
    ap.add_argument("--out", default="rope_methods")
    ap.add_argument("--elements", type=int, default=10)
    ap.add_argument("--animation", action="store_true", help="write the ANCF run's ParaView animation")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    # the boom head's sheave pin (node 2, 18 m along the boom from the foot
    # pin at (1, 0, 3.2) m, luffed 40 degrees), undeformed
    head_W = [1.0 + 18.0 * math.cos(math.radians(40.0)), 0.0, 3.2 + 18.0 * math.sin(math.radians(40.0))]
    out = {"head_W_m": head_W, "methods": {}}
    for method in ("massless", "ancf"):
        path = os.path.join(a.out, "crane_%s.yaml" % method)
        with open(path, "w") as f:
            yaml.safe_dump(model(method, a.body, head_W, a.elements), f, sort_keys=False)
        t0 = time.perf_counter()
        anim = ["--animation"] if a.animation and method == "ancf" else []
        subprocess.run([a.flexmb, "run", path, "--out", os.path.join(a.out, method), "-q"] + anim, check=True)
        wall = time.perf_counter() - t0
        res = metrics(read_csv(os.path.join(a.out, method, "results.csv")))
        res["run_time_s"] = wall
        out["methods"][method] = res
    with open(os.path.join(a.out, "rope_methods.json"), "w") as f:
        json.dump(out, f, indent=1)
    lines = ["| rope | largest swing [deg] | largest hook force [kN] | hook z at 24 s [m] | head z range [mm] | run time [s] |",
             "|---|---|---|---|---|---|"]
    for k, r in out["methods"].items():
        lines.append("| %s | %.3f | %.2f | %.4f | %.1f | %.2f |" % (k, r["largest_swing_deg"], r["largest_hook_force_N"] / 1e3,
                                                                   r["hook_z_end_m"], 1e3 * r["head_z_range_m"], r["run_time_s"]))
    with open(os.path.join(a.out, "rope_methods.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
