#!/usr/bin/env bash
# Regenerates the clockwise Lame meshes (Gmsh 2.2 format) from ring_cw.geo and checks that every
# face cell is numbered clockwise.
set -euo pipefail
cd "$(dirname "$0")"
gmsh ring_cw.geo -2 -format msh22 -o ring_cw_quad8.msh >/dev/null
gmsh ring_cw.geo -2 -format msh22 -o ring_cw_tria3.msh -setnumber QUAD 0 -setnumber ORDER 1 -setnumber N 16 >/dev/null
gmsh ring_cw.geo -2 -format msh22 -o section_cw_quad8.msh -setnumber AXIS 1 >/dev/null
gmsh ring_cw.geo -2 -format msh22 -o section_cw_tria6.msh -setnumber AXIS 1 -setnumber QUAD 0 >/dev/null
python3 check_clockwise.py ring_cw_quad8.msh ring_cw_tria3.msh section_cw_quad8.msh section_cw_tria6.msh
