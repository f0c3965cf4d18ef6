#!/usr/bin/env python3
"""Writes the FE model of the example crane's boom as Nastran bulk data
(boom.bdf), as a user's FE package would: a welded box-section luffing boom
of steel plates (CQUAD4 shells, PSHELL, MAT1), tapering from the foot to the
head, with three interface nodes tied to the shell by RBE2 spiders:

  node 1  foot pin centre        (x = 0, on the boom axis)
  node 2  head sheave pin centre (x = L, on the boom axis)
  node 3  luffing cylinder eye   (x = x_eye, below the bottom flange; its
          spider ties the whole section there, as a bulkhead would)

Boom frame: x along the boom from the foot to the head, y to the left, z up
(the boom lies horizontal in its FE frame; the model file turns it to its
luffing angle). SI units (m, kg, s, N, Pa). Every dimension is an assumption
of the example (examples/crane/README.md, "Parameters").

    python3 make_boom.py [--out boom.bdf] [--length 18] [--nx 90]
"""
import argparse

# section and plates [m]; steel S690 (E, nu, rho)
H_FOOT, H_HEAD = 0.80, 0.45      # section height at foot and head
B_FOOT, B_HEAD = 0.50, 0.35      # section width at foot and head
T_FLANGE, T_WEB = 0.010, 0.006   # plate thicknesses
E, NU, RHO = 2.10e11, 0.30, 7850.0
X_EYE = 4.0                      # cylinder eye position along the boom
EYE_DROP = 0.15                  # eye centre below the bottom flange
N_FLANGE, N_WEB = 4, 6           # divisions across a flange and a web


def section(x, length):
    s = x / length
    return H_FOOT + (H_HEAD - H_FOOT) * s, B_FOOT + (B_HEAD - B_FOOT) * s


def ring_points(h, b):
    """Points around the box section, counter-clockwise seen from the head,
    starting at the bottom right corner; each with its plate ('web' or
    'flange') to the next point."""
    pts = []
    corners = [(-b / 2, -h / 2), (b / 2, -h / 2), (b / 2, h / 2), (-b / 2, h / 2)]
    # bottom flange (y from -b/2 to b/2), right web, top flange, left web
    sides = [(corners[0], corners[1], N_FLANGE, 'flange'), (corners[1], corners[2], N_WEB, 'web'),
             (corners[2], corners[3], N_FLANGE, 'flange'), (corners[3], corners[0], N_WEB, 'web')]
    for (y0, z0), (y1, z1), n, kind in sides:
        for k in range(n):
            t = k / n
            pts.append((y0 + (y1 - y0) * t, z0 + (z1 - z0) * t, kind))
    return pts


def free(*fields):
    return ','.join('' if f is None else (f'{f:.9g}' if isinstance(f, float) else str(f)) for f in fields)


def rbe2(eid, gn, nodes):
    """RBE2 over `nodes` in free field with continuation lines of 8 fields."""
    lines = [free('RBE2', eid, gn, 123456, *nodes[:5])]
    rest = nodes[5:]
    while rest:
        lines.append(free('', *rest[:8]))
        rest = rest[8:]
    return lines


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--out', default='boom.bdf')
    ap.add_argument('--length', type=float, default=18.0, help='boom length, foot pin to head sheave pin [m]')
    ap.add_argument('--nx', type=int, default=90, help='shell elements along the boom')
    a = ap.parse_args()
    L, nx = a.length, a.nx
    out = ['$ example crane boom: welded box section, CQUAD4 shells (examples/crane/make_boom.py)',
           f'$ length {L} m, section {H_FOOT}x{B_FOOT} m at the foot to {H_HEAD}x{B_HEAD} m at the head',
           '$ interface nodes: 1 foot pin, 2 head sheave pin, 3 luffing cylinder eye',
           'BEGIN BULK',
           free('MAT1', 1, E, None, NU, RHO),
           free('PSHELL', 1, 1, T_FLANGE, 1, None, 1),
           free('PSHELL', 2, 1, T_WEB, 1, None, 1)]
    n_around = 2 * (N_FLANGE + N_WEB)
    first = 101  # shell node ids: 101 + i * n_around + k
    kinds = []
    for i in range(nx + 1):
        x = L * i / nx
        h, b = section(x, L)
        pts = ring_points(h, b)
        kinds = [p[2] for p in pts]
        for k, (y, z, _) in enumerate(pts):
            out.append(free('GRID', first + i * n_around + k, None, x, y, z))
    out.append(free('GRID', 1, None, 0.0, 0.0, 0.0))
    out.append(free('GRID', 2, None, L, 0.0, 0.0))
    h_eye, _ = section(X_EYE, L)
    out.append(free('GRID', 3, None, X_EYE, 0.0, -h_eye / 2 - EYE_DROP))
    eid = 1
    for i in range(nx):
        for k in range(n_around):
            n1 = first + i * n_around + k
            n2 = first + i * n_around + (k + 1) % n_around
            pid = 1 if kinds[k] == 'flange' else 2
            out.append(free('CQUAD4', eid, pid, n1, n2, n2 + n_around, n1 + n_around))
            eid += 1
    ring = lambda i: [first + i * n_around + k for k in range(n_around)]
    out += rbe2(10001, 1, ring(0))
    out += rbe2(10002, 2, ring(nx))
    # the eye: on lugs at a bulkhead, idealized as a rigid ring of the
    # section nearest x_eye (tying it to the bottom flange alone bends the
    # 10 mm plate locally by centimetres under the cylinder force)
    out += rbe2(10003, 3, ring(round(X_EYE / L * nx)))
    out.append('ENDDATA')
    with open(a.out, 'w') as f:
        f.write('\n'.join(out) + '\n')
    print(f'{a.out}: {(nx + 1) * n_around + 3} nodes, {nx * n_around} CQUAD4, 3 RBE2; interface nodes 1,2,3')


if __name__ == '__main__':
    main()
