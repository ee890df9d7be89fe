#!/usr/bin/env bash
# Regenerates the NAFEMS roller meshes (Gmsh 2.2 format) from nafems_roller.geo: in mm, and the
# same mesh in m (UNIT = 1e-3) for ../unit_scaling.
set -euo pipefail
cd "$(dirname "$0")"
gmsh nafems_roller.geo -2 -format msh22 -o nafems_roller.msh >/dev/null
gmsh nafems_roller.geo -setnumber UNIT 1e-3 -2 -format msh22 -o ../unit_scaling/nafems_roller_m.msh >/dev/null
# The finest mesh of doc/accuracy-cost/nafems_roller (H = 0.0625, 65 882 nodes) for
# nafems_roller_continue_h0625, in MED (half the size of the Gmsh file).
gmsh nafems_roller.geo -setnumber H 0.0625 -2 -format msh22 -o /tmp/nafems_roller_h0625.msh >/dev/null
../../build/bin/stella convert /tmp/nafems_roller_h0625.msh nafems_roller_h0625.med
