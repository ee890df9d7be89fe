#!/usr/bin/env bash
# The 3D Lame slab (HEXA20, N = 6) from ../lame_cylinder/ring3d.geo, Gmsh 2.2 format.
set -euo pipefail
cd "$(dirname "$0")"
gmsh -3 ../lame_cylinder/ring3d.geo -format msh22 -setnumber N 6 -setnumber ORDER 2 -o ring3d_hexa20.msh >/dev/null
