#!/usr/bin/env bash
# Regenerates the NAFEMS roller meshes (Gmsh 2.2 format) from nafems_roller.geo: in mm, and the
# same mesh in m (UNIT = 1e-3) for ../unit_scaling.
set -euo pipefail
cd "$(dirname "$0")"
gmsh nafems_roller.geo -2 -format msh22 -o nafems_roller.msh >/dev/null
gmsh nafems_roller.geo -setnumber UNIT 1e-3 -2 -format msh22 -o ../unit_scaling/nafems_roller_m.msh >/dev/null
