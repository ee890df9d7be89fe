#!/usr/bin/env bash
# Regenerates blocks.msh (Gmsh 2.2 format) from blocks.geo.
set -euo pipefail
cd "$(dirname "$0")"
gmsh blocks.geo -2 -format msh22 -o blocks.msh >/dev/null
