#!/usr/bin/python3
"""The example crane's boom modelled four ways (seed 003's comparison of
boom models), side by side against the full FE model:

  rigid   one rigid body with the FE model's mass, centre and inertia
  rfe     rigid finite elements: rigid segments joined by six-component
          spring-dampers (bushings) at the middles of equal primary
          segments, stiffnesses from the box section there (bending,
          torsion, axial, shear)
  cb      the floating-frame body of `flexmb reduce` (Craig-Bampton, boom.h5)
  ancf    ANCF 3D beam elements (Euler-Bernoulli, torsion), one section per
          element from the box section at the element's middle

Usage (in examples/crane, after make_boom.py and flexmb reduce, README.md):
  /usr/bin/python3 methods.py [--flexmb PATH] [--out methods] [--segments 9] [--elements 9]

For each method it writes and runs, in --out:
  1. clamped_<m>.yaml: the boom clamped at the foot pin and the cylinder eye
     (all six DOF, as the full FE model with nodes 1 and 3 fixed), no
     gravity: `flexmb modes --at initial`, the first frequencies;
  2. static_<m>.yaml, static_linear_<m>.yaml: the same clamped boom luffed
     40 degrees under its own weight and the rated load's rope forces at the
     head (two falls of 2.5 t each and the lead span towards the winch):
     `flexmb statics` at the rated load and at 1e-3 of it (scaled back: the
     linear response), the head's deflection in boom axes; pinned_<m>.yaml,
     pinned_linear_<m>.yaml: the same on the crane's pins (a revolute joint
     about the boom's y axis at the foot, a ball joint at the eye);
  3. crane_<m>.yaml: crane.yaml with this boom: `flexmb run`, the work cycle
     (lift-off, 90 degree slew), the head's deflection in the platform's axes
     and the run time.
The reference is the full FE model itself: `flexmb fe modes boom.bdf --fix
1,3`, `flexmb fe static boom.bdf --fix 1,3` and, on the pins, `--support
1:12346 --support 3:123`, with the same loads, linear and with
`--second-order` (K + K_G of the linear stresses: the P-delta reference of
the rated load; CalculiX's NLGEOM agrees, ccx_boom.py). The
results go to methods.json, methods.md (the table of the README) and
methods.png (the slewing histories).
"""
import argparse
import copy
import csv
import json
import math
import os
import subprocess
import sys
import time

import yaml

import make_boom as mb

HERE = os.path.dirname(os.path.abspath(__file__))
L = 18.0                         # boom length (make_boom.py's default)
G_SHEAR = mb.E / (2.0 * (1.0 + mb.NU))
LUFF_DEG = 40.0                  # crane.yaml's luffing angle
FOOT_W = (1.0, 0.0, 3.2)         # foot pin in world (crane.yaml)
WINCH_EXIT_W = (-2.2, 0.0, 3.92)
LOAD_MASS, FALLS, GRAVITY = 5000.0, 2, 9.81
DAMPING_RATIO = 0.01             # crane.yaml's boom: 1 % in every mode
LINEAR_SCALE = 1e-3              # load factor of the linear statics
METHODS = ("rigid", "rfe", "cb", "ancf")


# --- the box section along the boom (make_boom.py's plates, thin-walled) ---

def section(x):
    """Section properties at x [m] from the foot: A [m^2], Iy (about the
    section y axis: vertical bending), Iz (lateral bending), J (Bredt), and
    the shear areas of the webs (vertical) and flanges (lateral)."""
    h, b = mb.section(x, L)
    tf, tw = mb.T_FLANGE, mb.T_WEB
    A = 2.0 * b * tf + 2.0 * h * tw
    Iy = 2.0 * (b * tf * (h / 2.0) ** 2 + b * tf ** 3 / 12.0) + 2.0 * tw * h ** 3 / 12.0
    Iz = 2.0 * (h * tw * (b / 2.0) ** 2 + h * tw ** 3 / 12.0) + 2.0 * tf * b ** 3 / 12.0
    J = 4.0 * (b * h) ** 2 / (2.0 * b / tf + 2.0 * h / tw)
    return {"A": A, "Iy": Iy, "Iz": Iz, "J": J, "As_z": 2.0 * h * tw, "As_y": 2.0 * b * tf}


def integrate(f, a, b, n=64):
    """Gauss-Legendre (3 points) on n intervals of [a, b]."""
    g = (-math.sqrt(0.6), 0.0, math.sqrt(0.6))
    w = (5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0)
    h, s = (b - a) / n, 0.0
    for i in range(n):
        c = a + (i + 0.5) * h
        s += sum(wk * f(c + 0.5 * h * gk) for gk, wk in zip(g, w)) * 0.5 * h
    return s


def eye_offset():
    """Cylinder eye (node 3) in boom axes: below the bottom flange at x_eye."""
    h, _ = mb.section(mb.X_EYE, L)
    return (mb.X_EYE, 0.0, -h / 2.0 - mb.EYE_DROP)


def rot_y(deg):
    """Rotation matrix of roll_pitch_yaw [0, deg, 0] (about world y)."""
    a = math.radians(deg)
    return ((math.cos(a), 0.0, math.sin(a)), (0.0, 1.0, 0.0), (-math.sin(a), 0.0, math.cos(a)))


def apply(R, p):
    return tuple(sum(R[i][k] * p[k] for k in range(3)) for i in range(3))


def apply_t(R, p):
    return tuple(sum(R[k][i] * p[k] for k in range(3)) for i in range(3))


def at(origin, R, p):
    q = apply(R, p)
    return [round(origin[i] + q[i], 9) for i in range(3)]


# --- the boom four ways: bodies, extra force elements, marker names ---

def boom_rigid(origin, pitch, info):
    body = {"name": "boom", "mass": info["mass_kg"], "center_of_mass": info["center_of_mass_m"],
            "inertia": info["inertia_kg_m2"], "position": list(origin),
            "orientation": {"roll_pitch_yaw_deg": [0, pitch, 0]},
            "markers": [{"name": "foot", "orientation": {"z_axis": [0, 1, 0]}},
                        {"name": "head", "position": [L, 0, 0]},
                        {"name": "eye", "position": list(eye_offset())}]}
    return [body], [], {"foot": "boom.foot", "head": "boom.head", "eye": "boom.eye"}


def boom_cb(origin, pitch, body_file, damping):
    body = {"name": "boom", "type": "flexible", "file": body_file, "position": list(origin),
            "orientation": {"roll_pitch_yaw_deg": [0, pitch, 0]},
            "markers": [{"name": "foot", "node": 1, "orientation": {"z_axis": [0, 1, 0]}},
                        {"name": "head", "node": 2}, {"name": "eye", "node": 3}]}
    if damping:
        body["damping"] = {"ratios": [DAMPING_RATIO]}
    return [body], [], {"foot": "boom.foot", "head": "boom.head", "eye": "boom.eye"}


def boom_rfe(origin, pitch, n, beta):
    """n primary segments of length l; a spring-damper at each one's middle;
    n + 1 rigid elements between them (the end ones of length l/2)."""
    R = rot_y(pitch)
    l = L / n
    if abs(mb.X_EYE / l - round(mb.X_EYE / l)) > 1e-9:
        sys.exit(f"methods.py: --segments {n}: the cylinder eye (x = {mb.X_EYE} m) is not at the middle of a rigid "
                 "element (give a multiple of 9)")
    cuts = [0.0] + [(k + 0.5) * l for k in range(n)] + [L]
    rho = mb.RHO
    xe = eye_offset()
    bodies, forces, names = [], [], {}
    for j in range(n + 1):
        a, b = cuts[j], cuts[j + 1]
        mu = lambda x: rho * section(x)["A"]
        m = integrate(mu, a, b)
        xc = integrate(lambda x: mu(x) * x, a, b) / m
        Ixx = integrate(lambda x: rho * (section(x)["Iy"] + section(x)["Iz"]), a, b)
        Iyy = integrate(lambda x: rho * section(x)["Iy"] + mu(x) * (x - xc) ** 2, a, b)
        Izz = integrate(lambda x: rho * section(x)["Iz"] + mu(x) * (x - xc) ** 2, a, b)
        name = f"boom_{j}"
        markers = []
        if j > 0:
            markers.append({"name": "left"})
        if j < n:
            markers.append({"name": "right", "position": [round(b - a, 9), 0, 0]})
        if j == 0:
            markers.append({"name": "foot", "orientation": {"z_axis": [0, 1, 0]}})
            names["foot"] = f"{name}.foot"
        if a <= xe[0] < b:
            markers.append({"name": "eye", "position": [round(xe[0] - a, 9), 0, round(xe[2], 9)]})
            names["eye"] = f"{name}.eye"
        if j == n:
            markers.append({"name": "head", "position": [round(b - a, 9), 0, 0]})
            names["head"] = f"{name}.head"
        bodies.append({"name": name, "mass": round(m, 6), "center_of_mass": [round(xc - a, 9), 0, 0],
                       "inertia": [round(Ixx, 6), round(Iyy, 6), round(Izz, 6)],
                       "position": at(origin, R, (a, 0, 0)), "orientation": {"roll_pitch_yaw_deg": [0, pitch, 0]},
                       "markers": markers})
    for k in range(n):
        a, b = k * l, (k + 1) * l
        flex = lambda key, modulus: integrate(lambda x: 1.0 / (modulus * section(x)[key]), a, b)
        kt = [1.0 / flex("A", mb.E), 1.0 / flex("As_y", G_SHEAR), 1.0 / flex("As_z", G_SHEAR)]
        kr = [1.0 / flex("J", G_SHEAR), 1.0 / flex("Iy", mb.E), 1.0 / flex("Iz", mb.E)]
        forces.append({"name": f"boom_spring_{k}", "type": "bushing", "i": f"boom_{k}.right", "j": f"boom_{k + 1}.left",
                       "translational_stiffness": [float(f"{v:.6g}") for v in kt],
                       "rotational_stiffness": [float(f"{v:.6g}") for v in kr],
                       "translational_damping": [float(f"{beta * v:.6g}") for v in kt],
                       "rotational_damping": [float(f"{beta * v:.6g}") for v in kr]})
    return bodies, forces, names


def boom_ancf(origin, pitch, n, beta):
    R = rot_y(pitch)
    h = L / n
    k_eye = mb.X_EYE / h
    if abs(k_eye - round(k_eye)) > 1e-9:
        sys.exit(f"methods.py: --elements {n}: no ANCF node at the cylinder eye (x = {mb.X_EYE} m)")
    secs = []
    for i in range(n):
        s = section((i + 0.5) * h)
        secs.append({"area": float(f"{s['A']:.9g}"), "Iy": float(f"{s['Iy']:.9g}"), "Iz": float(f"{s['Iz']:.9g}"),
                     "J": float(f"{s['J']:.9g}")})
    body = {"name": "boom", "type": "ancf_beam3d", "length": L, "elements": n, "section": secs,
            "material": {"E": mb.E, "nu": mb.NU, "rho": mb.RHO}, "start": list(origin),
            "direction": [round(v, 12) for v in apply(R, (1, 0, 0))],
            "normal": [round(v, 12) for v in apply(R, (0, 0, 1))],
            "markers": [{"name": "foot", "node": 0, "orientation": {"z_axis": [0, 1, 0]}},
                        {"name": "head", "node": n},
                        {"name": "eye", "node": int(round(k_eye)), "position": [0, 0, round(eye_offset()[2], 9)]}]}
    if beta > 0.0:
        body["damping"] = float(f"{beta:.6g}")
    return [body], [], {"foot": "boom.foot", "head": "boom.head", "eye": "boom.eye"}


def boom(method, origin, pitch, a, info, beta, dynamic):
    if method == "rigid":
        return boom_rigid(origin, pitch, info)
    if method == "rfe":
        return boom_rfe(origin, pitch, a.segments, beta if dynamic else 0.0)
    if method == "cb":
        return boom_cb(origin, pitch, os.path.relpath(a.body, a.out), dynamic)
    return boom_ancf(origin, pitch, a.elements, beta if dynamic else 0.0)


# --- the three models per method ---

def rope_force_W():
    """The rated load's rope forces on the head sheave at 40 degrees: the
    falls (FALLS T down) and the lead span (T towards the winch exit)."""
    head = at(FOOT_W, rot_y(-LUFF_DEG), (L, 0, 0))
    T = LOAD_MASS * GRAVITY / FALLS
    d = [WINCH_EXIT_W[i] - head[i] for i in range(3)]
    n = math.sqrt(sum(v * v for v in d))
    return [T * d[0] / n, 0.0, -FALLS * T + T * d[2] / n]


def clamp_model(method, a, info, static, scale=1.0, pinned=False):
    """The boom clamped at the foot and the eye (`pinned`: on the crane's
    pins instead, a revolute joint about the boom's y axis at the foot and a
    ball joint at the eye); `static`: luffed 40 degrees under `scale` times
    its weight and the rope forces, solved by statics."""
    pitch = -LUFF_DEG if static else 0.0
    origin = FOOT_W if static else (0.0, 0.0, 0.0)
    bodies, forces, names = boom(method, origin, pitch, a, info, 0.0, False)
    R = rot_y(pitch)
    ground = [{"name": "foot", "position": list(origin), "orientation": {"roll_pitch_yaw_deg": [0, pitch, 0]}},
              {"name": "eye", "position": at(origin, R, eye_offset()), "orientation": {"roll_pitch_yaw_deg": [0, pitch, 0]}}]
    if pinned:   # the foot markers' z axes along the boom's y axis (the pin)
        ground[0]["orientation"] = {"z_axis": [0, 1, 0]}
    else:        # the boom-side clamp markers in boom axes
        for b in bodies:
            for m in b["markers"]:
                if m["name"] == "foot":
                    m.pop("orientation", None)
    tag = "pinned" if pinned else ("static" if static else "clamped")
    model = {"name": f"boom_{method}_{tag}",
             "gravity": [0, 0, -GRAVITY * scale] if static else [0, 0, 0],
             "ground": {"markers": ground}, "bodies": bodies,
             "joints": [{"name": "foot_pin" if pinned else "foot_clamp", "type": "revolute" if pinned else "fixed",
                         "i": "ground.foot", "j": names["foot"]},
                        {"name": "eye_pin" if pinned else "eye_clamp", "type": "spherical" if pinned else "fixed",
                         "i": "ground.eye", "j": names["eye"]}],
             "forces": forces, "sensors": [{"name": "head", "type": "marker_position", "marker": names["head"]}]}
    if static:
        model["forces"] = forces + [{"name": "rope", "type": "point_force", "marker": names["head"],
                                     "force": [float(f"{v * scale:.12g}") for v in rope_force_W()]}]
        model["solver"] = {"analysis": "statics"}
    if not model["forces"]:
        del model["forces"]
    return model


def crane_model(method, a, info, beta):
    with open(os.path.join(HERE, "crane_model.yaml")) as f:
        crane = yaml.safe_load(f)
    i = next(k for k, b in enumerate(crane["bodies"]) if b["name"] == "boom")
    old = crane["bodies"][i]
    bodies, forces, names = boom(method, tuple(old["position"]), old["orientation"]["roll_pitch_yaw_deg"][1], a,
                                    info, beta, True)
    crane["bodies"][i:i + 1] = bodies
    crane["forces"] += forces
    rename = {f"boom.{k}": v for k, v in names.items()}

    def fix(x):
        if isinstance(x, dict):
            return {k: fix(v) for k, v in x.items()}
        if isinstance(x, list):
            return [fix(v) for v in x]
        return rename.get(x, x) if isinstance(x, str) else x
    crane["joints"] = fix(crane["joints"])
    crane["forces"] = fix(crane["forces"])
    # element stresses exist on the FE-based body only
    crane["sensors"] = [fix(s) for s in crane["sensors"] if method == "cb" or s.get("type") != "element_stress"]
    crane["name"] = f"example_crane_{method}"
    crane.pop("manoeuvres", None)
    crane.pop("manoeuvre", None)
    crane["output"] = {"interval": 0.02}
    return crane


# --- running flexmb ---

def run(cmd, cwd):
    t0 = time.perf_counter()
    p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"methods.py: {' '.join(cmd)} failed ({p.returncode}):\n{p.stderr}")
    return p.stdout, time.perf_counter() - t0


def write(path, model):
    with open(path, "w") as f:
        f.write(f"# written by methods.py (examples/crane): {model['name']}\n")
        yaml.safe_dump(model, f, sort_keys=False, default_flow_style=None, width=120)


def read_csv(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def frequencies(out_dir):
    with open(os.path.join(out_dir, "modes.csv")) as f:
        return [float(r["frequency_hz"]) for r in csv.DictReader(f) if r["kind"] != "rigid"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--flexmb", default="flexmb", help="the flexmb program")
    ap.add_argument("--out", default="methods")
    ap.add_argument("--bdf", default="boom.bdf", help="the boom's FE model (make_boom.py)")
    ap.add_argument("--body", default="boom.h5", help="its reduced body (flexmb reduce)")
    ap.add_argument("--segments", type=int, default=9, help="RFE primary segments (the eye mid-element: a multiple of 9)")
    ap.add_argument("--elements", type=int, default=9, help="ANCF elements (a node at the eye: a multiple of 9)")
    ap.add_argument("--modes", type=int, default=4, help="frequencies compared")
    a = ap.parse_args()
    a.out, a.bdf, a.body = os.path.abspath(a.out), os.path.abspath(a.bdf), os.path.abspath(a.body)
    os.makedirs(a.out, exist_ok=True)
    fx = [a.flexmb]

    # the full FE model: clamped frequencies, linear statics, mass properties
    text, _ = run(fx + ["fe", "modes", a.bdf, "--fix", "1,3", "--count", str(a.modes), "--json"], a.out)
    full = json.loads(text)
    R = rot_y(-LUFF_DEG)
    g_B = apply_t(R, (0.0, 0.0, -GRAVITY))
    f_B = apply_t(R, rope_force_W())
    text, _ = run(fx + ["fe", "static", a.bdf, "--fix", "1,3", "--gravity", ",".join(f"{v:.12g}" for v in g_B),
                        "--force", "2:" + ",".join(f"{v:.12g}" for v in f_B), "--nodes", "2", "--json"], a.out)
    full_static = json.loads(text)["nodes"][0]["displacement_m"]
    text, _ = run(fx + ["fe", "static", a.bdf, "--fix", "1,3", "--gravity", ",".join(f"{v:.12g}" for v in g_B),
                        "--force", "2:" + ",".join(f"{v:.12g}" for v in f_B), "--nodes", "2", "--json",
                        "--second-order"], a.out)
    full_static_2nd = json.loads(text)["nodes"][0]["displacement_m"]
    pins = ["--support", "1:12346", "--support", "3:123", "--gravity", ",".join(f"{v:.12g}" for v in g_B),
            "--force", "2:" + ",".join(f"{v:.12g}" for v in f_B), "--nodes", "2", "--json"]
    text, _ = run(fx + ["fe", "static", a.bdf] + pins, a.out)
    full_pinned = json.loads(text)["nodes"][0]["displacement_m"]
    text, _ = run(fx + ["fe", "static", a.bdf] + pins + ["--second-order"], a.out)
    full_pinned_2nd = json.loads(text)["nodes"][0]["displacement_m"]
    info = json.loads(run(fx + ["body", "info", a.body, "--json"], a.out)[0])
    omega1 = 2.0 * math.pi * full["frequencies_hz"][0]
    beta = 2.0 * DAMPING_RATIO / omega1   # stiffness-proportional damping: 1 % at the first clamped mode

    result = {"full_fe": {"frequencies_hz": full["frequencies_hz"][:a.modes], "head_deflection_B_m": full_static,
                          "pinned_deflection_B_m": full_pinned,
                          "head_deflection_second_order_B_m": full_static_2nd,
                          "pinned_deflection_second_order_B_m": full_pinned_2nd,
                          "dof": full["dofs"]},
              "rope_force_W_N": rope_force_W(), "damping_time_s": beta, "methods": {}}
    for m in METHODS:
        r = {}
        write(os.path.join(a.out, f"clamped_{m}.yaml"), clamp_model(m, a, info, False))
        if m != "rigid":
            run(fx + ["modes", f"clamped_{m}.yaml", "--out", f"modes_{m}", "--at", "initial", "--count",
                      str(a.modes), "--no-animation", "--quiet"], a.out)
            r["frequencies_hz"] = frequencies(os.path.join(a.out, f"modes_{m}"))[:a.modes]
        # statics at the rated load (large rotations: the axial compression's
        # P-delta is in the beam models) and at 1e-3 of it, scaled back (the
        # linear response, as the full FE model's linear solution)
        head0 = at(FOOT_W, R, (L, 0, 0))
        for key, scale, pinned in (("head_deflection_B_m", 1.0, False), ("head_deflection_linear_B_m", LINEAR_SCALE, False),
                                   ("pinned_deflection_B_m", 1.0, True), ("pinned_deflection_linear_B_m", LINEAR_SCALE, True)):
            if m == "rigid":
                r[key] = [0.0, 0.0, 0.0]
                continue
            tag = ("pinned" if pinned else "static") + ("" if scale == 1.0 else "_linear")
            write(os.path.join(a.out, f"{tag}_{m}.yaml"), clamp_model(m, a, info, True, scale, pinned))
            run(fx + ["statics", f"{tag}_{m}.yaml", "--out", f"{tag}_{m}", "--quiet"], a.out)
            c = read_csv(os.path.join(a.out, f"{tag}_{m}", "results.csv"))
            d_W = [(c[f"head.{k}"][-1] - head0[i]) / scale for i, k in enumerate("xyz")]
            r[key] = list(apply_t(R, d_W))
        crane = crane_model(m, a, info, beta)
        write(os.path.join(a.out, f"crane_{m}.yaml"), crane)
        _, wall = run(fx + ["run", f"crane_{m}.yaml", "--out", f"crane_{m}", "--quiet"], a.out)
        with open(os.path.join(a.out, f"crane_{m}", "summary.json")) as f:
            summary = json.load(f)
        c = read_csv(os.path.join(a.out, f"crane_{m}", "results.csv"))
        r["crane"] = {"t": c["time"], "head_y_m": c["head_on_platform.y"], "head_z_m": c["head_on_platform.z"],
                      "rope_N": c["rope.f"], "wall_time_s": summary.get("wall_time_s", wall),
                      "process_time_s": wall, "status": summary.get("status")}
        r["boom_coordinates"] = {"rigid": 6, "rfe": 6 * (a.segments + 1), "cb": 6 + info["flexible_modes"],
                                 "ancf": 7 * (a.elements + 1)}[m]
        result["methods"][m] = r
        print(f"{m}: done ({wall:.2f} s for the crane run)", flush=True)
    with open(os.path.join(a.out, "methods.json"), "w") as f:
        json.dump(result, f)
    table(result, a)
    plot(result, a.out)


def drop(d):
    """Head deflection [m] normal to the boom, down positive (boom axes)."""
    return -d[2]


def second(full, key, lin):
    """The full FE model's second-order (P-delta) deflection, as table text."""
    d = drop(full[key + "_second_order_B_m"])
    return f"{d * 1e3:.1f} (second order, {100 * (d / lin - 1):+.1f} %)"


def table(res, a):
    full = res["full_fe"]
    fref = full["frequencies_hz"]
    cref, pref = drop(full["head_deflection_B_m"]), drop(full["pinned_deflection_B_m"])
    rigid_z = res["methods"]["rigid"]["crane"]["head_z_m"][0]
    lines = ["| boom model | boom coordinates | clamped frequencies [Hz] | head deflection, clamped: linear; rated load, "
             "large rotations [mm] | the same on the crane's pins [mm] | slew: largest lateral head deflection [mm] | "
             "slew: largest head sag under the rigid boom's [mm] | run time [s] |",
             "|---|---|---|---|---|---|---|---|",
             f"| full FE model (`fe modes`, `fe static`) | {full['dof']} | " + ", ".join(f"{f:.2f}" for f in fref) +
             f" | {cref * 1e3:.1f} (linear); {second(full, 'head_deflection', cref)} | "
             f"{pref * 1e3:.1f} (linear); {second(full, 'pinned_deflection', pref)} | | | |"]
    labels = {"rigid": "rigid body", "rfe": f"rigid finite elements ({a.segments} springs)",
              "cb": "floating frame, Craig-Bampton (boom.h5)", "ancf": f"ANCF 3D beam ({a.elements} elements)"}

    def pair(r, key, ref):
        lin, big = drop(r[key + "_linear_B_m"]), drop(r[key + "_B_m"])
        return f"{lin * 1e3:.1f} ({100 * (lin / ref - 1):+.1f} %); {big * 1e3:.1f} ({100 * (big / lin - 1):+.1f} % over linear)"
    for m in METHODS:
        r = res["methods"][m]
        f = r.get("frequencies_hz")
        ftxt = "none (rigid)" if f is None else ", ".join(
            f"{x:.2f} ({100 * (x / y - 1):+.1f} %)" for x, y in zip(f, fref))
        ctxt = "0" if m == "rigid" else pair(r, "head_deflection", cref)
        ptxt = "0" if m == "rigid" else pair(r, "pinned_deflection", pref)
        cr = r["crane"]
        lat = max(abs(y) for y in cr["head_y_m"])
        sag = max(rigid_z - z for z in cr["head_z_m"])
        lines.append(f"| {labels[m]} | {r['boom_coordinates']} | {ftxt} | {ctxt} | {ptxt} | {lat * 1e3:.1f} | "
                     f"{sag * 1e3:.1f} | {cr['wall_time_s']:.2f} |")
    text = "\n".join(lines) + "\n"
    with open(os.path.join(a.out, "methods.md"), "w") as f:
        f.write(text)
    print(text)


def plot(res, out):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib missing: no methods.png")
        return
    fig, ax = plt.subplots(2, 1, figsize=(8, 6.5), sharex=True)
    rigid_z = res["methods"]["rigid"]["crane"]["head_z_m"][0]
    style = {"rigid": "-", "rfe": "-", "cb": "-", "ancf": "--"}
    for m in METHODS:
        c = res["methods"][m]["crane"]
        ax[0].plot(c["t"], [1e3 * y for y in c["head_y_m"]], style[m], label=m)
        ax[1].plot(c["t"], [1e3 * (rigid_z - z) for z in c["head_z_m"]], style[m], label=m)
    ax[0].set_ylabel("head lateral [mm]\n(platform axes)")
    ax[1].set_ylabel("head sag below the\nrigid boom's head [mm]")
    ax[1].set_xlabel("time [s]")
    ax[0].set_title("Work cycle (lift-off, 90 degree slew) with four boom models")
    for x in ax:
        x.grid(True)
        x.legend(loc="best", fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "methods.png"), dpi=110)
    print("wrote", os.path.join(out, "methods.png"))


if __name__ == "__main__":
    main()
