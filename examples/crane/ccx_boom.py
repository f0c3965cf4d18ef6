#!/usr/bin/python3
"""The example crane's boom on its pins under the rated load, solved by
CalculiX (ccx) as an independent full FE reference, linear and
geometrically nonlinear (NLGEOM): the head's deflection and the P-delta
amplification of the part normal to the boom.

It reads boom.bdf (make_boom.py) with its own small reader of exactly the
cards make_boom.py writes (GRID, CQUAD4, PSHELL, MAT1, RBE2; anything else
is an error), writes a CalculiX deck and runs `ccx` twice on the case of
methods.py's "pinned" statics:

  the boom luffed 40 degrees (the loads given in boom axes, the FE frame:
  x from the foot to the head, z up), its own weight (*DLOAD GRAV) and the
  rated load's rope forces at the head sheave pin, node 2 (*CLOAD), both
  computed by methods.py's own functions; supported as the crane holds it:
  node 1, the foot pin, in translations and the rotations about x and z
  (a pin about the boom's y axis), node 3, the cylinder eye, in
  translations (a ball joint);
  1. `*STATIC`: linear;
  2. `*STEP, NLGEOM` + `*STATIC` in equal increments: large displacements
     and rotations, the loads dead (fixed directions in the FE frame, as
     methods.py's beam statics apply them).

The RBE2 spiders (all six components), as CalculiX can express them:

  foot (node 1) and eye (node 3): linear `*EQUATION`s u_i = u_ref + w x p_i
    (p_i from the interface node to ring node i), w the rotation vector,
    carried as the translational DOF 1-3 of a new node (ccx's own rigid
    body convention, so the foot pin fixes its components 1 and 3). Exact
    in the linear run; under NLGEOM they miss the second-order terms of a
    finite rotation, and these rings turn by 3.5e-4 and 1.1e-3 rad.
  head (node 2, the loaded one, turning by 0.018 rad): a stiff massless
    bulkhead plate across the ring (S4, BULKHEAD_STIFFNESS times the
    steel's E, BULKHEAD_THICKNESS times the flange), node 2 at its centre;
    it turns as a rigid body with its exact finite rotation. Linear: the
    same head deflection as the *RIGID BODY spiders to 2e-6; NLGEOM: the
    same as E x 100 to 1e-6.

Why not ccx's rigid constraints: `*RIGID BODY, REF NODE=, ROT NODE=` (and
`*KINEMATIC COUPLING`, tried too) on shell nodes give
the right linear answer (the check run `linear_rigid_bodies`) but under
NLGEOM ccx 2.20 cannot converge: the residual sticks at the ring node on the
shell normal through the reference node (node 1913, the head's top flange
above node 2; without the head spider, node 513 at the eye) and the
increment is cut below the minimum at 3 to 5 % of the load. Linear
*EQUATIONs at the head converge but, with the head's 0.018 rad, give a
nonlinear increment 4 % smaller than the bulkhead's (the check runs
`*_head_equation`: +2.03 % against +2.13 %); a third variant without any
head spider (the head force spread equally over the ring's 20 nodes) gives
+2.13 % as the bulkhead does.

CalculiX has no 6-DOF shell in the Debian 2.20 build: it expands each S4
into a layer of C3D8I bricks across the thickness, and where plates meet
at an angle (the box's corners) or change thickness it joins the expanded
nodes by a "knot" (a rigid body of its own). So this is the same plate
model as flexmb's CQUAD4 to discretization accuracy, not node by node.

    /usr/bin/python3 ccx_boom.py [--bdf boom.bdf] [--work ccx_boom] [--increments 10]
                                 [--head bulkhead|equation|rigid] [--others equation|rigid]
                                 [--no-checks] [--flexmb PATH]

Prints JSON: the head's displacement in boom axes [m] for both runs, the
ratio nonlinear / linear of its component normal to the boom (z), the run
times, the spiders' rotations; the check runs (linear with *RIGID BODY
spiders, linear and NLGEOM with the head's as *EQUATION) unless
--no-checks; with --flexmb also flexmb's `fe static` answer for the same
case and the linear ratio ccx / flexmb.
"""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import methods  # noqa: E402  (the loads: rope_force_W, rot_y, apply_t, GRAVITY, LUFF_DEG)

CARDS = ("GRID", "CQUAD4", "PSHELL", "MAT1", "RBE2")
BULKHEAD_STIFFNESS = 1000.0   # the head bulkhead's E over the steel's (100: the same answer to 1e-6)
BULKHEAD_THICKNESS = 5.0      # its thickness over the thickest plate's


# --- the bulk data reader (free field, as make_boom.py writes it) ---

def read_bdf(path):
    """Cards of make_boom.py: free-field lines, comma separated, '$'
    comments, continuation lines whose first field is blank or starts with
    '+'. Returns grids {id: (x, y, z)}, quads [(eid, pid, n1..n4)],
    pshells {pid: (mid, t)}, mats {mid: (E, nu, rho)}, rbe2s [(eid, gn, [nodes])]."""
    cards = []
    with open(path) as f:
        for lineno, raw in enumerate(f, 1):
            line = raw.split("$", 1)[0].rstrip()
            if not line.strip():
                continue
            head = line.strip().upper()
            if head.startswith("BEGIN BULK"):
                continue
            if head.startswith("ENDDATA"):
                break
            if "," not in line:
                sys.exit(f"ccx_boom.py: {path}:{lineno}: not a free-field card (make_boom.py writes commas): {line!r}")
            fields = [s.strip() for s in line.split(",")]
            if fields[0] == "" or fields[0].startswith("+"):
                if not cards:
                    sys.exit(f"ccx_boom.py: {path}:{lineno}: a continuation line before any card")
                cards[-1][1].extend(fields[1:])
                continue
            name = fields[0].upper().rstrip("*")
            if name not in CARDS:
                sys.exit(f"ccx_boom.py: {path}:{lineno}: card {fields[0]} is not one that make_boom.py writes "
                         f"({', '.join(CARDS)}); this reader takes no other")
            cards.append((name, fields[1:], lineno))

    def num(s, what, lineno, default=None):
        if s == "":
            if default is None:
                sys.exit(f"ccx_boom.py: {path}:{lineno}: {what} is blank")
            return default
        try:
            return float(s.replace("D", "E").replace("d", "e"))
        except ValueError:
            sys.exit(f"ccx_boom.py: {path}:{lineno}: {what}: not a number: {s!r}")

    def integer(s, what, lineno):
        try:
            return int(s)
        except ValueError:
            sys.exit(f"ccx_boom.py: {path}:{lineno}: {what}: not an integer: {s!r}")

    def only_blank(rest, what, lineno):
        if any(s for s in rest):
            sys.exit(f"ccx_boom.py: {path}:{lineno}: {what}: fields this reader does not take: {rest}")

    grids, quads, pshells, mats, rbe2s = {}, [], {}, {}, []
    for name, f, ln in cards:
        f = f + [""] * 8
        if name == "GRID":   # ID CP X1 X2 X3 CD PS SEID
            if f[1] or f[5] or f[6] or f[7]:
                sys.exit(f"ccx_boom.py: {path}:{ln}: GRID with a coordinate system, PS or SEID")
            grids[integer(f[0], "GRID ID", ln)] = tuple(num(f[k], "GRID X", ln) for k in (2, 3, 4))
        elif name == "CQUAD4":   # EID PID G1 G2 G3 G4 [THETA ZOFFS ...]
            only_blank(f[6:], "CQUAD4 THETA/ZOFFS/thicknesses", ln)
            quads.append(tuple(integer(f[k], "CQUAD4 field", ln) for k in range(6)))
        elif name == "PSHELL":   # PID MID1 T MID2 12I/T^3 MID3 TS/T NSM
            pid, mid = integer(f[0], "PSHELL PID", ln), integer(f[1], "PSHELL MID1", ln)
            t = num(f[2], "PSHELL T", ln)
            for k, what in ((3, "MID2"), (5, "MID3")):
                if f[k] and integer(f[k], what, ln) != mid:
                    sys.exit(f"ccx_boom.py: {path}:{ln}: PSHELL {what} differs from MID1 (ccx's S4 is homogeneous)")
            for k, what in ((4, "12I/T^3"), (6, "TS/T")):
                if f[k] and num(f[k], what, ln) != 1.0:
                    sys.exit(f"ccx_boom.py: {path}:{ln}: PSHELL {what} other than 1")
            if num(f[7], "NSM", ln, 0.0) != 0.0:
                sys.exit(f"ccx_boom.py: {path}:{ln}: PSHELL NSM (non-structural mass) not taken")
            only_blank(f[8:], "PSHELL Z1/Z2/MID4", ln)
            pshells[pid] = (mid, t)
        elif name == "MAT1":   # MID E G NU RHO [A TREF GE ...]
            mid, E = integer(f[0], "MAT1 MID", ln), num(f[1], "MAT1 E", ln)
            nu, rho = num(f[3], "MAT1 NU", ln), num(f[4], "MAT1 RHO", ln, 0.0)
            if f[2] and abs(num(f[2], "MAT1 G", ln) - E / (2 * (1 + nu))) > 1e-9 * E:
                sys.exit(f"ccx_boom.py: {path}:{ln}: MAT1 G other than E / 2 (1 + nu) (ccx's isotropic *ELASTIC)")
            only_blank(f[5:], "MAT1 A/TREF/GE/stress limits", ln)
            mats[mid] = (E, nu, rho)
        elif name == "RBE2":   # EID GN CM GM1 ...
            eid, gn, cm = (integer(f[k], "RBE2 field", ln) for k in range(3))
            if cm != 123456:
                sys.exit(f"ccx_boom.py: {path}:{ln}: RBE2 {eid} with CM {cm}: only 123456 (a rigid body) is written")
            rbe2s.append((eid, gn, [integer(s, "RBE2 GM", ln) for s in f[3:] if s]))
    for q in quads:
        if q[1] not in pshells:
            sys.exit(f"ccx_boom.py: {path}: CQUAD4 {q[0]}: no PSHELL {q[1]}")
        if any(n not in grids for n in q[2:]):
            sys.exit(f"ccx_boom.py: {path}: CQUAD4 {q[0]}: a GRID is missing")
    for pid, (mid, _) in pshells.items():
        if mid not in mats:
            sys.exit(f"ccx_boom.py: {path}: PSHELL {pid}: no MAT1 {mid}")
    if not quads or not rbe2s:
        sys.exit(f"ccx_boom.py: {path}: no CQUAD4 or no RBE2")
    return grids, quads, pshells, mats, rbe2s


# --- the CalculiX deck ---

def lines_of(values, per_line=8):
    vals = list(values)
    return [", ".join(str(v) for v in vals[k:k + per_line]) for k in range(0, len(vals), per_line)]


def bulkhead(grids, gn, nodes, first_id, first_eid):
    """A plate across an RBE2's ring: the ring's nodes must lie in one plane
    x = const on the edges of a rectangle whose grid (the rings' distinct y
    and z) has the interface node gn at one of its points; the interior grid
    points become new nodes. Returns the new nodes [(id, x, y, z)] and the
    S4 elements [(eid, n1..n4)]."""
    x0 = grids[gn][0]
    key = lambda v: round(v, 9)
    if any(abs(grids[n][0] - x0) > 1e-9 for n in nodes):
        sys.exit(f"ccx_boom.py: the bulkhead at node {gn}: its RBE2's nodes are not in the plane x = {x0}")
    ys = sorted({key(grids[n][1]) for n in nodes})
    zs = sorted({key(grids[n][2]) for n in nodes})
    on_ring = {(key(grids[n][1]), key(grids[n][2])): n for n in nodes}
    if any(y not in (ys[0], ys[-1]) and z not in (zs[0], zs[-1]) for y, z in on_ring):
        sys.exit(f"ccx_boom.py: the bulkhead at node {gn}: its RBE2's nodes are not on a rectangle")
    centre = (key(grids[gn][1]), key(grids[gn][2]))
    if centre not in {(y, z) for y in ys for z in zs} or centre in on_ring:
        sys.exit(f"ccx_boom.py: the bulkhead at node {gn}: the node is not an inner point of the ring's grid")
    ids, new = {}, []
    for y in ys:
        for z in zs:
            if (y, z) in on_ring:
                ids[y, z] = on_ring[y, z]
            elif (y, z) == centre:
                ids[y, z] = gn
            else:
                ids[y, z] = first_id + len(new)
                new.append((ids[y, z], x0, y, z))
    elements = [(first_eid + k * (len(zs) - 1) + l, ids[ys[k], zs[l]], ids[ys[k + 1], zs[l]],
                 ids[ys[k + 1], zs[l + 1]], ids[ys[k], zs[l + 1]])
                for k in range(len(ys) - 1) for l in range(len(zs) - 1)]
    return new, elements


def write_deck(path, model, g_B, f_B, nlgeom, increments, spiders):
    """spiders: the kind of each RBE2 by its interface node: 'rigid'
    (*RIGID BODY), 'equation' (linear *EQUATIONs) or 'bulkhead' (a stiff
    S4 plate across the ring, BULKHEAD_STIFFNESS times the steel's E,
    BULKHEAD_THICKNESS times its thickest plate, massless)."""
    grids, quads, pshells, mats, rbe2s = model
    rot, nxt = {}, max(grids) + 1
    for _, gn, _ in rbe2s:
        if spiders[gn] != "bulkhead":
            rot[gn] = nxt
            nxt += 1
    extra_nodes, extra_elements = [], []
    for _, gn, nodes in rbe2s:
        if spiders[gn] == "bulkhead":
            new, els = bulkhead(grids, gn, nodes, nxt, max(q[0] for q in quads) + 1 + len(extra_elements))
            extra_nodes += new
            extra_elements += els
            nxt += len(new)
    out = ["** the example crane's boom (make_boom.py's boom.bdf) on its pins: ccx_boom.py",
           "*NODE, NSET=NALL"]
    out += [f"{n}, {x:.12g}, {y:.12g}, {z:.12g}" for n, (x, y, z) in sorted(grids.items())]
    out += [f"{r}, 0, 0, 0" for r in rot.values()]   # the rotation nodes: their position is not used
    out += [f"{n}, {x:.12g}, {y:.12g}, {z:.12g}" for n, x, y, z in extra_nodes]
    for pid in sorted(pshells):
        out.append(f"*ELEMENT, TYPE=S4, ELSET=P{pid}")
        out += [", ".join(str(v) for v in (q[0],) + q[2:]) for q in quads if q[1] == pid]
    if extra_elements:
        out.append("*ELEMENT, TYPE=S4, ELSET=BULKHEADS")
        out += [", ".join(str(v) for v in e) for e in extra_elements]
    out.append("*ELSET, ELSET=EALL")
    out += [f"P{pid}" for pid in sorted(pshells)] + (["BULKHEADS"] if extra_elements else [])
    for mid, (E, nu, rho) in sorted(mats.items()):
        out += [f"*MATERIAL, NAME=M{mid}", "*ELASTIC", f"{E:.12g}, {nu:.12g}", "*DENSITY", f"{rho:.12g}"]
    for pid, (mid, t) in sorted(pshells.items()):
        out += [f"*SHELL SECTION, ELSET=P{pid}, MATERIAL=M{mid}", f"{t:.12g}"]
    if extra_elements:
        E, nu = max(m[0] for m in mats.values()), min(m[1] for m in mats.values())
        out += ["*MATERIAL, NAME=BULKHEAD", "*ELASTIC", f"{BULKHEAD_STIFFNESS * E:.12g}, {nu:.12g}", "*DENSITY", "0",
                "*SHELL SECTION, ELSET=BULKHEADS, MATERIAL=BULKHEAD",
                f"{BULKHEAD_THICKNESS * max(t for _, t in pshells.values()):.12g}"]
    for eid, gn, nodes in rbe2s:
        if spiders[gn] == "rigid":
            out.append(f"*NSET, NSET=R{eid}")
            out += lines_of(nodes, 16)
            out.append(f"*RIGID BODY, NSET=R{eid}, REF NODE={gn}, ROT NODE={rot[gn]}")
        elif spiders[gn] == "equation":
            # u_i = u_ref + w x p, p = x_i - x_ref, w: the rotation node's DOF 1-3
            out.append("*EQUATION")
            r = rot[gn]
            for n in nodes:
                p = [grids[n][k] - grids[gn][k] for k in range(3)]
                for k in range(3):
                    i, j = (k + 1) % 3, (k + 2) % 3   # (w x p)_k = w_i p_j - w_j p_i
                    terms = [(n, k + 1, 1.0), (gn, k + 1, -1.0), (r, i + 1, -p[j]), (r, j + 1, p[i])]
                    terms = [t for t in terms if t[2] != 0.0]
                    out.append(str(len(terms)))
                    out.append(", ".join(f"{a}, {b}, {c:.15g}" for a, b, c in terms))
    # node 1, the foot pin: translations and the rotations about x and z
    # (its rotation node's DOF 1 and 3); node 3, the eye: translations
    out += ["*NSET, NSET=NHEAD", "2", "*BOUNDARY", "1, 1, 3", f"{rot[1]}, 1, 1", f"{rot[1]}, 3, 3", "3, 1, 3"]
    if rot:
        out += ["*NSET, NSET=NROT", ", ".join(str(r) for r in rot.values())]
    g = math.sqrt(sum(v * v for v in g_B))
    if nlgeom:
        dt = 1.0 / increments
        out += [f"*STEP, NLGEOM, INC={10 * increments}", "*STATIC", f"{dt:.12g}, 1.0, {dt * 1e-3:.12g}, {dt:.12g}"]
    else:
        out += ["*STEP", "*STATIC"]
    out += ["*DLOAD", f"EALL, GRAV, {g:.12g}, " + ", ".join(f"{v / g:.15g}" for v in g_B),
            "*CLOAD"] + [f"2, {k + 1}, {v:.12g}" for k, v in enumerate(f_B)]
    out += ["*NODE PRINT, NSET=NHEAD", "U"] + (["*NODE PRINT, NSET=NROT", "U"] if rot else []) + ["*END STEP"]
    with open(path, "w") as fh:
        fh.write("\n".join(out) + "\n")
    return rot


def printed(dat, nset):
    """The last 'displacements (vx,vy,vz) for set NSET' block of a .dat
    (ccx prints one per increment under NLGEOM): its load factor, {node:
    [ux, uy, uz]} and the number of such blocks."""
    with open(dat) as f:
        text = f.read()
    blocks = re.findall(r"displacements \(vx,vy,vz\) for set " + nset +
                        r" and time\s+(\S+)\s*\n\s*\n((?:[ \t]*\d+(?:[ \t]+\S+){3}[ \t]*\n)+)", text)
    if not blocks:
        sys.exit(f"ccx_boom.py: no displacements of set {nset} in {dat}")
    time_, rows = blocks[-1]
    return float(time_), {int(v[0]): [float(x) for x in v[1:4]] for v in (r.split() for r in rows.strip().splitlines())}, len(blocks)


def run_ccx(ccx, work, job):
    env = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_STIFFNESS="1", CCX_NPROC_EQUATION_SOLVER="1",
               CCX_NPROC_RESULTS="1", NUMBER_OF_CPUS="1")
    t0 = time.perf_counter()
    p = subprocess.run([ccx, "-i", job], cwd=work, capture_output=True, text=True, env=env)
    wall = time.perf_counter() - t0
    with open(os.path.join(work, job + ".log"), "w") as f:
        f.write(p.stdout + p.stderr)
    if p.returncode != 0 or "*ERROR" in p.stdout:
        tail = "\n".join((p.stdout + p.stderr).splitlines()[-30:])
        sys.exit(f"ccx_boom.py: ccx -i {job} failed ({p.returncode}) in {work}:\n{tail}")
    return wall


def loads_B():
    """methods.py's pinned statics at 40 degrees: gravity and the head's rope
    force in boom axes."""
    R = methods.rot_y(-methods.LUFF_DEG)
    return list(methods.apply_t(R, (0.0, 0.0, -methods.GRAVITY))), list(methods.apply_t(R, methods.rope_force_W()))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bdf", default="boom.bdf", help="the boom's FE model (make_boom.py)")
    ap.add_argument("--work", default="ccx_boom", help="folder for the decks and ccx's files")
    ap.add_argument("--ccx", default="ccx", help="the CalculiX program")
    ap.add_argument("--increments", type=int, default=10, help="equal load increments of the NLGEOM step")
    ap.add_argument("--head", choices=("bulkhead", "equation", "rigid"), default="bulkhead",
                    help="the head's RBE2 (node 2) in both runs")
    ap.add_argument("--others", choices=("equation", "rigid"), default="equation",
                    help="the foot's and the eye's RBE2s (nodes 1, 3) in both runs")
    ap.add_argument("--no-checks", action="store_true",
                    help="leave out the check runs (linear with *RIGID BODY spiders; NLGEOM with the head's as *EQUATION)")
    ap.add_argument("--flexmb", help="also run `flexmb fe static` on the same case and compare")
    a = ap.parse_args()
    if shutil.which(a.ccx) is None:
        sys.exit(f"ccx_boom.py: {a.ccx} not found (Debian: calculix-ccx)")
    model = read_bdf(a.bdf)
    if sorted(gn for _, gn, _ in model[4]) != [1, 2, 3]:
        sys.exit(f"ccx_boom.py: {a.bdf}: the RBE2s must have the interface nodes 1, 2, 3 (make_boom.py)")
    g_B, f_B = loads_B()
    os.makedirs(a.work, exist_ok=True)
    main_spiders = {1: a.others, 2: a.head, 3: a.others}
    res = {"bdf": os.path.abspath(a.bdf), "gravity_B_m_s2": g_B, "head_force_B_N": f_B,
           "nodes": len(model[0]), "cquad4": len(model[1]), "rbe2": len(model[4]), "spiders": main_spiders}
    runs = [("linear", False, main_spiders), ("nlgeom", True, main_spiders)]
    if not a.no_checks:
        runs += [("linear_rigid_bodies", False, {1: "rigid", 2: "rigid", 3: "rigid"}),
                 ("linear_head_equation", False, {1: a.others, 2: "equation", 3: a.others}),
                 ("nlgeom_head_equation", True, {1: a.others, 2: "equation", 3: a.others})]
    for job, nl, spiders in runs:
        rot = write_deck(os.path.join(a.work, job + ".inp"), model, g_B, f_B, nl, a.increments, spiders)
        wall = run_ccx(a.ccx, a.work, job)
        dat = os.path.join(a.work, job + ".dat")
        t, head, n = printed(dat, "NHEAD")
        if abs(t - 1.0) > 1e-9:
            sys.exit(f"ccx_boom.py: the {job} step ended at load factor {t}, not 1")
        r = {"head_displacement_B_m": head[2], "wall_s": round(wall, 2)}
        if rot:
            _, w, _ = printed(dat, "NROT")
            r["spider_rotations_rad"] = {str(gn): w[rn] for gn, rn in rot.items()}
        if nl:
            r["increments"] = n
        res[job] = r
    normal = lambda job: res[job]["head_displacement_B_m"][2]
    res["nlgeom_over_linear_normal"] = normal("nlgeom") / normal("linear")
    if not a.no_checks:
        res["head_equation_nlgeom_over_linear_normal"] = normal("nlgeom_head_equation") / normal("linear_head_equation")
        res["linear_over_rigid_bodies_normal"] = normal("linear") / normal("linear_rigid_bodies")
    if a.flexmb:
        # flexmb's full FE model, linear and second order (K + K_G)
        for key, extra in (("flexmb_fe_static", []), ("flexmb_fe_static_second_order", ["--second-order"])):
            p = subprocess.run([a.flexmb, "fe", "static", a.bdf, "--support", "1:12346", "--support", "3:123",
                                "--gravity", ",".join(f"{v:.12g}" for v in g_B),
                                "--force", "2:" + ",".join(f"{v:.12g}" for v in f_B), "--nodes", "2", "--json",
                                *extra], capture_output=True, text=True)
            if p.returncode != 0:
                sys.exit(f"ccx_boom.py: flexmb fe static {' '.join(extra)} failed ({p.returncode}):\n{p.stderr}")
            node = json.loads(p.stdout)["nodes"][0]
            res[key] = {"head_displacement_B_m": node["displacement_m"], "head_rotation_B_rad": node["rotation_rad"]}
        res["ccx_linear_over_flexmb_normal"] = normal("linear") / res["flexmb_fe_static"]["head_displacement_B_m"][2]
        res["flexmb_second_order_over_linear_normal"] = (res["flexmb_fe_static_second_order"]["head_displacement_B_m"][2]
                                                         / res["flexmb_fe_static"]["head_displacement_B_m"][2])
    print(json.dumps(res, indent=1))


if __name__ == "__main__":
    main()
