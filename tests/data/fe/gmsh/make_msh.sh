#!/bin/sh
# Regenerates the .msh test files from the .geo scripts with gmsh (Debian
# package gmsh, version 4.8.4 was used): each in format 4.1 and 2.2, plus one
# binary file for the "binary not supported" test.
set -e
cd "$(dirname "$0")"
for g in strip beam tet10 hex8 mixed; do
  gmsh -3 "$g.geo" -format msh41 -o "${g}_v41.msh" > /dev/null
  gmsh -3 "$g.geo" -format msh22 -o "${g}_v22.msh" > /dev/null
done
gmsh -3 beam.geo -format msh41 -bin -o beam_binary.msh > /dev/null
