#!/usr/bin/env bash
# Regenerates the Lame-cylinder meshes (Gmsh 2.2 format) from ring.geo.
set -euo pipefail
cd "$(dirname "$0")"
gmsh ring.geo -2 -format msh22 -o ring_quad8.msh >/dev/null
gmsh ring.geo -2 -format msh22 -o ring_tria3.msh -setnumber QUAD 0 -setnumber ORDER 1 -setnumber N 16 >/dev/null
gmsh ring.geo -2 -format msh22 -o section_quad8.msh -setnumber AXIS 1 >/dev/null
