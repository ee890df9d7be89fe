#!/usr/bin/env bash
# Regenerates the patch-test meshes (Gmsh 2.2 format) from square.geo.
set -euo pipefail
cd "$(dirname "$0")"
g() { local out=$1; shift; gmsh square.geo -format msh22 -o "$out" "$@" >/dev/null; }
g tria3.msh -2
g tria6.msh -2 -setnumber ORDER 2
g quad4.msh -2 -setnumber QUAD 1
g quad8.msh -2 -setnumber QUAD 1 -setnumber ORDER 2 -setnumber INCOMPLETE 1
g quad9.msh -2 -setnumber QUAD 1 -setnumber ORDER 2
g axis_tria6.msh -2 -setnumber ORDER 2 -setnumber X0 0.5
g axis_quad4.msh -2 -setnumber QUAD 1 -setnumber X0 0.5
g axis_quad8.msh -2 -setnumber QUAD 1 -setnumber ORDER 2 -setnumber INCOMPLETE 1 -setnumber X0 0.5
g axis_tria3.msh -2 -setnumber X0 0.5
g tetra4.msh -3 -setnumber THREED 1
g tetra10.msh -3 -setnumber THREED 1 -setnumber ORDER 2
g hexa8.msh -3 -setnumber THREED 1 -setnumber STRUCT 1 -setnumber QUAD 1
g hexa20.msh -3 -setnumber THREED 1 -setnumber STRUCT 1 -setnumber QUAD 1 -setnumber ORDER 2 -setnumber INCOMPLETE 1
g penta6.msh -3 -setnumber THREED 1 -setnumber STRUCT 1
