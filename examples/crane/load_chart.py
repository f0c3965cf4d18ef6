#!/usr/bin/python3
"""The example crane's load chart check: the static equilibrium with the
rated load hanging 0.5 m above the ground at several luffing angles, as a
flexmb study (docs/studies.md) of crane.yaml's `load_chart` manoeuvre.

Usage:
  /usr/bin/python3 load_chart.py [--out load_chart_study.yaml]
  flexmb study load_chart_study.yaml --out chart      # then
  /usr/bin/python3 load_chart.py --report chart/study.csv

The first call writes the study: one run per row of the chart (luffing
angle, rated load = the load moment over the radius, capped by the
chart's largest load), each placing the boom, the luffing cylinder's two
bodies and the payload where that angle puts them (the drivers then hold
them: the cylinder's length, the rope's free length for a hook 0.5 m above
the lifting height of the ground, slewing and winch at rest). The payload
is the hook block with the upper 3000 kg (body `load`) and the lower part
(body `part`, the rest of the rated load). The report prints, per row, the
radius, the load, the boom head's deflection from its place on the
undeformed boom (self-weight and load; in the platform's axes, so the
carrier's tilt on its outriggers is not in it), the rope tension, the cylinder
force, the largest flange stress beyond the cylinder eye and the load on
the front and rear outrigger pads of one side (the boom over the front:
the crane is stable while the rear pads carry load).
"""
import argparse
import csv
import json
import math
import os
import subprocess

# crane.yaml's geometry [m] (make_boom.py for the boom)
BOOM_LENGTH = 18.0
FOOT = (1.0, 3.2)                 # foot pin (radius, height) at zero slew
EYE_BOOM = (4.0, -(0.80 - 0.35 * 4.0 / 18.0) / 2 - 0.15)   # node 3 in the boom frame (x, z)
CYL_BASE = (1.6, 2.3)             # cylinder base pin on the platform
CYL_HALF = 1.3                    # pin to the body centre of barrel and rod
WINCH_EXIT = (-2.2, 3.92)
# parts of line; the rope starts 4 cm stretched (taut: the statics needs a
# load path from the start, docs/model-file.md "rope")
FALLS, SLACK = 2, -0.04
HOOK_ABOVE_CENTRE = 1.5           # hook above the whole block's centre
BLOCK_CENTRE_ON_GROUND = 0.27475  # the whole block's centre resting on its contacts
LOAD_UP, PART_DOWN = 0.11, 0.165  # centres of `load` and `part` from the whole block's
UPPER_MASS = 3000.0               # body `load` (with the hook block)
LIFT = 0.5                        # load above the ground [m]

# the chart: luffing angles [deg]; load moment [kg m] and largest load [kg]
ANGLES = [20, 30, 40, 50, 60, 70]
LOAD_MOMENT, MAX_LOAD = 74000.0, 10000.0


def rotate(a, p):
    """Boom-frame point (x, z) at luffing angle a [rad], world (radius, height)."""
    return (FOOT[0] + p[0] * math.cos(a) - p[1] * math.sin(a), FOOT[1] + p[0] * math.sin(a) + p[1] * math.cos(a))


def row(angle_deg):
    a = math.radians(angle_deg)
    eye = rotate(a, EYE_BOOM)
    head = rotate(a, (BOOM_LENGTH, 0.0))
    d = (eye[0] - CYL_BASE[0], eye[1] - CYL_BASE[1])
    length = math.hypot(*d)
    u = (d[0] / length, d[1] / length)
    cyl_pitch = -math.degrees(math.atan2(u[1], u[0]))
    radius = head[0]
    mass = min(MAX_LOAD, LOAD_MOMENT / radius)
    centre_z = BLOCK_CENTRE_ON_GROUND + LIFT
    hook_z = centre_z + HOOK_ABOVE_CENTRE
    lead = math.hypot(head[0] - WINCH_EXIT[0], head[1] - WINCH_EXIT[1])
    return {
        "cylinder_length": round(length, 6),
        "boom_pitch": -angle_deg,
        "barrel_x": round(CYL_BASE[0] + CYL_HALF * u[0], 6),
        "barrel_z": round(CYL_BASE[1] + CYL_HALF * u[1], 6),
        "barrel_pitch": round(cyl_pitch, 6),
        "rod_x": round(eye[0] - CYL_HALF * u[0], 6),
        "rod_z": round(eye[1] - CYL_HALF * u[1], 6),
        "rod_pitch": round(cyl_pitch, 6),
        "load_x": round(radius, 6),
        "load_z": round(centre_z + LOAD_UP, 6),
        "part_x": round(radius, 6),
        "part_z": round(centre_z - PART_DOWN, 6),
        "part_mass": round(mass - UPPER_MASS, 1),
        "free_length": round(lead + FALLS * (head[1] - hook_z) + SLACK, 6),
    }


PATHS = {
    "cylinder_length": "drivers[name=luffing].function",
    "boom_pitch": "bodies[name=boom].orientation.roll_pitch_yaw_deg[1]",
    "barrel_x": "bodies[name=barrel].position[0]",
    "barrel_z": "bodies[name=barrel].position[2]",
    "barrel_pitch": "bodies[name=barrel].orientation.roll_pitch_yaw_deg[1]",
    "rod_x": "bodies[name=rod].position[0]",
    "rod_z": "bodies[name=rod].position[2]",
    "rod_pitch": "bodies[name=rod].orientation.roll_pitch_yaw_deg[1]",
    "load_x": "bodies[name=load].position[0]",
    "load_z": "bodies[name=load].position[2]",
    "part_x": "bodies[name=part].position[0]",
    "part_z": "bodies[name=part].position[2]",
    "part_mass": "bodies[name=part].mass",
    "free_length": "forces[name=hoist_rope].free_length",
}

OUTPUTS = {
    "radius_m": "final(head.x)",
    "head_z_m": "final(head_on_platform.z)",
    "rope_tension_N": "final(rope.f)",
    "cylinder_x_N": "final(cylinder.fx)",
    "cylinder_z_N": "final(cylinder.fz)",
    "top_flange_von_mises_Pa": "final(top_flange.top_von_mises)",
    "bottom_flange_von_mises_Pa": "final(bottom_flange.bottom_von_mises)",
    "load_steps": "summary.load_steps",
    "pad_fl_N": "final(pad_fl.fz)",
    "pad_fr_N": "final(pad_fr.fz)",
    "pad_rr_N": "final(pad_rr.fz)",
    "pad_rl_N": "final(pad_rl.fz)",
}


def write_study(path):
    rows = [row(a) for a in ANGLES]
    lines = ["# written by load_chart.py: the crane's load chart check (statics at each luffing angle)",
             "study: crane_load_chart",
             "model: crane_model.yaml",
             "options: {manoeuvre: load_chart}",
             "files: [boom.h5]",
             "parameters:"]
    for name, p in PATHS.items():
        lines.append(f"  {name}: {{path: \"{p}\"}}")
    lines.append("table:")
    for r in rows:
        lines.append("  - {" + ", ".join(f"{k}: {v}" for k, v in r.items()) + "}")
    lines.append("outputs:")
    for name, o in OUTPUTS.items():
        lines.append(f"  {name}: {o}")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote", path, "with", len(rows), "runs")


def full_fe_drop(angle_deg, mass, flexmb, bdf, second_order=False):
    """The head's drop [m] in the full FE model's linear (or, with
    `second_order`, second-order: `--second-order`) static solution
    (`flexmb fe static`), supported as the crane holds the boom: the foot
    pin (node 1: translations and the rotations about x and z) and the
    cylinder eye on a rigid cylinder (node 3: translations); loaded by its
    weight and the rope at the head sheave (the falls straight down, the
    lead span towards the winch exit), all in the boom's axes."""
    a = math.radians(angle_deg)
    c, s = math.cos(a), math.sin(a)
    to_boom = lambda x, z: (x * c + z * s, -x * s + z * c)   # world (x, z) -> boom (x, z)
    head = rotate(a, (BOOM_LENGTH, 0.0))
    T = mass * 9.81 / FALLS
    d = (WINCH_EXIT[0] - head[0], WINCH_EXIT[1] - head[1])
    n = math.hypot(*d)
    f = to_boom(T * d[0] / n, -FALLS * T + T * d[1] / n)
    g = to_boom(0.0, -9.81)
    out = subprocess.run([flexmb, "fe", "static", bdf, "--support", "1:12346", "--support", "3:123",
                          "--gravity", f"{g[0]:.12g},0,{g[1]:.12g}", "--force", f"2:{f[0]:.12g},0,{f[1]:.12g}",
                          "--nodes", "2", "--json"] + (["--second-order"] if second_order else []),
                         capture_output=True, text=True, check=True).stdout
    u = json.loads(out)["nodes"][0]["displacement_m"]
    return -(u[0] * s + u[2] * c)   # world z of the boom-axes displacement, down positive


def fe_column(drop, fe_drop, fe_drop_2nd):
    """The full FE model's linear and second-order head drops [mm] and the
    run's difference from the second-order one."""
    return f" {fe_drop * 1e3:.1f}; {fe_drop_2nd * 1e3:.1f} (run {100 * (drop / fe_drop_2nd - 1):+.1f} %) |"


def report(csv_path, flexmb=None, bdf=None):
    with open(csv_path) as f:
        rows = list(csv.DictReader(f))
    fe = flexmb is not None and bdf is not None
    print("| luffing angle [deg] | radius [m] | rated load [kg] | head deflection down [mm] | rope tension [kN] | cylinder force [kN] | flange von Mises [MPa] | front pads [kN] | rear pads [kN] | status |"
          + (" full FE, linear; second order: head deflection down [mm] |" if fe else ""))
    print("|---|---|---|---|---|---|---|---|---|---|" + ("---|" if fe else ""))
    for r in rows:
        a = -float(r["boom_pitch"])
        head_z = rotate(math.radians(a), (BOOM_LENGTH, 0.0))[1]
        ok = r.get("status") == "ok"
        def num(k, s=1.0):
            return float(r[k]) * s if ok and r.get(k) not in (None, "") else float("nan")
        mass = UPPER_MASS + float(r["part_mass"])
        vm = max(num("top_flange_von_mises_Pa", 1e-6), num("bottom_flange_von_mises_Pa", 1e-6))
        print(f"| {a:.0f} | {num('radius_m'):.2f} | {mass:.0f} | {(head_z - num('head_z_m')) * 1e3:.0f} | "
              f"{num('rope_tension_N', 1e-3):.1f} | {math.hypot(num('cylinder_x_N'), num('cylinder_z_N')) * 1e-3:.0f} | "
              f"{vm:.0f} | {num('pad_fl_N', 1e-3):.0f} | {num('pad_rl_N', 1e-3):.0f} | {r.get('status')} |"
              + (fe_column(head_z - num('head_z_m'), full_fe_drop(a, mass, flexmb, bdf),
                           full_fe_drop(a, mass, flexmb, bdf, True)) if fe else ""))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default="load_chart_study.yaml")
    ap.add_argument("--report", default=None, help="study.csv of the study: print the chart")
    ap.add_argument("--fe", default=None, help="with --report: the boom's FE model (boom.bdf): add the full FE "
                    "model's linear and second-order static head deflections (flexmb fe static) to each row")
    ap.add_argument("--flexmb", default="flexmb", help="the flexmb program (for --fe)")
    a = ap.parse_args()
    if a.report:
        report(a.report, a.flexmb if a.fe else None, a.fe)
    else:
        write_study(a.out)


if __name__ == "__main__":
    main()
