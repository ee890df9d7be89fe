#!/usr/bin/env bash
# Regenerates the Hertz mesh (Gmsh 2.2 format) from hertz_cylinder.geo; ../hertz_sphere uses it too.
set -euo pipefail
cd "$(dirname "$0")"
gmsh hertz_cylinder.geo -2 -format msh22 -o hertz_quad4.msh >/dev/null
