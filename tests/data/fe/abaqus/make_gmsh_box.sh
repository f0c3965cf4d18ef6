#!/bin/sh
# Regenerates gmsh_box.inp (an Abaqus deck written by gmsh) from gmsh_box.geo.
set -e
cd "$(dirname "$0")"
gmsh -3 gmsh_box.geo -format inp -o gmsh_box.inp > /dev/null
