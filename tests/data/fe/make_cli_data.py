#!/usr/bin/env python3
"""Writes the Nastran models of the command-line test (tests/validation/fe_cli_test.cc):

  nastran/cli_strip.bdf   free steel strip 1 m x 50 mm x 5 mm of 20 x 2 CQUAD4,
                          nu = 0 (so that it bends like an Euler-Bernoulli beam),
                          no constraints; SET1 1 (node set "SET1_1") holds the
                          three nodes of the edge x = 0 for --fix
  nastran/cli_hinge.bdf   a zero-mass mechanism: a steel CBAR clamped at node 1,
                          and a massless CBAR (rho = 0) hinged to its tip by an
                          RBE2 on translations only (123), so the massless bar
                          swings and spins freely

Usage: /usr/bin/python3 make_cli_data.py  (writes next to this script)
"""
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ next to the test data
from make_nastran_data import quad_strip  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def real(x):
    """A Nastran real: short, always with a decimal point."""
    s = "%.6g" % x
    return s if "." in s or "e" in s else s + "."


def strip():
    nx, ny = 20, 2
    lines = ["$ free strip: L = 1 m, b = 50 mm, t = 5 mm, steel with nu = 0; written by make_cli_data.py",
             "BEGIN BULK",
             "MAT1,1,2.1+11,,0.,7850.",
             "PSHELL,1,1,0.005,1,,1"]
    cards, node = quad_strip(nx, ny, 1.0, 0.05, real)
    lines += cards
    lines.append("$ the clamped edge x = 0 as a node set, for --fix SET1_1")
    lines.append("SET1,1," + ",".join(str(node(0, j)) for j in range(ny + 1)))
    lines.append("ENDDATA")
    return lines


def hinge():
    return ["$ zero-mass mechanism: massless bar 3-4 hinged (RBE2 123) to the tip of the clamped bar 1-2",
            "BEGIN BULK",
            "MAT1,1,2.1+11,,0.3,7850.",
            "MAT1,2,2.1+11,,0.3,0.",
            "PBAR,1,1,1.-4,8.3-10,8.3-10,1.4-9",
            "PBAR,2,2,1.-4,8.3-10,8.3-10,1.4-9",
            "GRID,1,,0.,0.,0.",
            "GRID,2,,0.5,0.,0.",
            "GRID,3,,0.5,0.,0.",
            "GRID,4,,1.,0.,0.",
            "CBAR,1,1,1,2,0.,0.,1.",
            "CBAR,2,2,3,4,0.,0.,1.",
            "RBE2,10,2,123,3",
            "SPC1,1,123456,1",
            "ENDDATA"]


for name, lines in (("cli_strip.bdf", strip()), ("cli_hinge.bdf", hinge())):
    with open(os.path.join(HERE, "nastran", name), "w") as f:
        f.write("\n".join(lines) + "\n")
