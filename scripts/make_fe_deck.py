#!/usr/bin/env python3
"""Writes generated FE models as Nastran bulk data (free field, SI units),
for the tests and benchmarks of the reduction that need a model of a given
size (python/tests/test_reduce_petsc.py, bench/reduce_mpi.py):

  ladder      a truck-like ladder frame: two C-channel rails and flat cross
              members, CQUAD4 shells; interface nodes 1..4 at the spring
              hangers (bottom flange corners of the rails), free-free.
  solid-boom  a solid box boom of CHEXA bricks, nx x ny x nz; interface
              nodes 1 (foot) and 2 (head), each tied by an RBE2 spider to
              its end face. About 3 (nx+1)(ny+1)(nz+1) DOF.

    python3 make_fe_deck.py ladder --out frame.bdf [--nx 60]
    python3 make_fe_deck.py solid-boom --out boom.bdf [--nx 200 --ny 6 --nz 8]

Every dimension is a round assumption of a generic part, not a real one.
"""
import argparse
import os
import sys

# the free-field card writers of the example crane's boom generator
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'examples', 'crane'))
from make_boom import free, rbe2  # noqa: E402

E, NU, RHO = 2.10e11, 0.30, 7850.0


def ladder(nx):
    """Rails along x (length 6 m, track 0.86 m), C-channel 0.25 x 0.08 m,
    t = 7 mm; cross members (t = 6 mm) every nx / 6 divisions."""
    length, track, h, b = 6.0, 0.86, 0.25, 0.08
    nz, nb = 5, 2                       # divisions of the web and a flange
    lines = ['$ ladder frame (scripts/make_fe_deck.py): two C-channel rails, flat cross members',
             'BEGIN BULK', free('MAT1', 1, E, None, NU, RHO), free('PSHELL', 1, 1, 0.007, 1),
             free('PSHELL', 2, 1, 0.006, 1)]
    nid = [4]
    grid = {}

    def node(x, y, z):
        key = (round(x, 9), round(y, 9), round(z, 9))
        if key not in grid:
            nid[0] += 1
            grid[key] = nid[0]
            lines.append(free('GRID', nid[0], None, x, y, z))
        return grid[key]

    eid = [0]

    def quad(pid, a, b_, c, d):
        eid[0] += 1
        lines.append(free('CQUAD4', eid[0], pid, a, b_, c, d))

    xs = [length * i / nx for i in range(nx + 1)]
    for side in (-1.0, 1.0):
        y_web = side * track / 2
        # section points: bottom flange tip -> web bottom -> web top -> top flange tip
        prof = [(y_web - side * b * (1 - k / nb), 0.0) for k in range(nb)]
        prof += [(y_web, h * k / nz) for k in range(nz + 1)]
        prof += [(y_web - side * b * k / nb, h) for k in range(1, nb + 1)]
        for i in range(nx):
            for k in range(len(prof) - 1):
                (y0, z0), (y1, z1) = prof[k], prof[k + 1]
                quad(1, node(xs[i], y0, z0), node(xs[i + 1], y0, z0), node(xs[i + 1], y1, z1), node(xs[i], y1, z1))
    ny = 8
    for i in range(0, nx + 1, max(nx // 6, 1)):
        for j in range(ny):
            y0, y1 = -track / 2 + track * j / ny, -track / 2 + track * (j + 1) / ny
            for k in range(nz):
                z0, z1 = h * k / nz, h * (k + 1) / nz
                quad(2, node(xs[i], y0, z0), node(xs[i], y1, z0), node(xs[i], y1, z1), node(xs[i], y0, z1))
    # interface nodes 1..4: spring hangers at x = 1.0 and 4.5 m on both rails,
    # an RBE2 to the web bottom node there
    i_front, i_rear = round(1.0 / length * nx), round(4.5 / length * nx)
    gn = 0
    for i in (i_front, i_rear):
        for side in (-1.0, 1.0):
            gn += 1
            lines.append(free('GRID', gn, None, xs[i], side * track / 2, -0.05))
            eid[0] += 1
            lines += rbe2(eid[0], gn, [grid[(round(xs[i], 9), round(side * track / 2, 9), 0.0)]])
    lines.append('ENDDATA')
    return lines


def solid_boom(nx, ny, nz):
    """A 12 x 0.4 x 0.6 m steel bar of CHEXA bricks."""
    length, width, height = 12.0, 0.4, 0.6
    lines = ['$ solid boom (scripts/make_fe_deck.py): CHEXA bricks', 'BEGIN BULK',
             free('MAT1', 1, E, None, NU, RHO), free('PSOLID', 1, 1)]

    def nid(i, j, k):
        return 3 + i * (ny + 1) * (nz + 1) + j * (nz + 1) + k

    for i in range(nx + 1):
        x = length * i / nx
        for j in range(ny + 1):
            y = width * (j / ny - 0.5)
            for k in range(nz + 1):
                lines.append(free('GRID', nid(i, j, k), None, x, y, height * (k / nz - 0.5)))
    eid = 0
    for i in range(nx):
        for j in range(ny):
            for k in range(nz):
                eid += 1
                c = [nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                     nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1), nid(i, j + 1, k + 1)]
                lines.append(free('CHEXA', eid, 1, *c[:6]))
                lines.append(free('', *c[6:]))
    lines.append(free('GRID', 1, None, 0.0, 0.0, 0.0))
    lines.append(free('GRID', 2, None, length, 0.0, 0.0))
    for gn, i in ((1, 0), (2, nx)):
        eid += 1
        lines += rbe2(eid, gn, [nid(i, j, k) for j in range(ny + 1) for k in range(nz + 1)])
    lines.append('ENDDATA')
    return lines


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('model', choices=['ladder', 'solid-boom'])
    ap.add_argument('--out', required=True)
    ap.add_argument('--nx', type=int, default=None, help='divisions along the part (ladder 60, boom 200)')
    ap.add_argument('--ny', type=int, default=6)
    ap.add_argument('--nz', type=int, default=8)
    a = ap.parse_args()
    if a.model == 'ladder':
        lines = ladder(a.nx or 60)
    else:
        lines = solid_boom(a.nx or 200, a.ny, a.nz)
    with open(a.out, 'w') as f:
        f.write('\n'.join(lines) + '\n')


if __name__ == '__main__':
    main()
