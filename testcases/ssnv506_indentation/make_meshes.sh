#!/usr/bin/env bash
# Regenerates the ssnv506-like meshes (Gmsh 2.2 format) from indentation.geo.
set -euo pipefail
cd "$(dirname "$0")"
gmsh indentation.geo -2 -format msh22 -o indentation_quad4.msh >/dev/null
gmsh indentation.geo -2 -setnumber H 25 -format msh22 -o indentation_h25.msh >/dev/null # ssnv506_h25_calculix
gmsh indentation.geo -3 -setnumber H 25 -setnumber SECTOR 6 -format msh22 -o sector_3d.msh >/dev/null 2>&1 # Gmsh warns about degenerate hexahedra on the axis
