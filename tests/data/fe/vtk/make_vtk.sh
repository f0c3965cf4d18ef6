#!/bin/sh
# Regenerates the gmsh-written legacy VTK test files (gmsh 4.8.4 was used):
# tet10.vtk (10-node tetrahedra, VTK type 24) and mixed.vtk (lines,
# triangles and tetrahedra, from ../gmsh/mixed.geo). The other .vtk files
# here are written by hand.
set -e
cd "$(dirname "$0")"
gmsh -3 tet10.geo -format vtk -o tet10.vtk > /dev/null
gmsh -3 ../gmsh/mixed.geo -format vtk -o mixed.vtk > /dev/null
