#!/usr/bin/env bash
# Mesh dependence of the ssnv506-like reaction with QUAD4 AXIS cells: regenerates indentation.geo
# with each contact cell size H given (default 12 16 18 19 21 25 50), runs ssnv506.comm on it with
# stella and prints the reaction DY per radian at t = 0.2 ... 1.0 and its ratio to the reference.
# Usage: testcases/ssnv506_indentation/mesh_study.sh [STELLA] [H...]
#   STELLA defaults to build/bin/stella; outputs go to /tmp/ssnv506-mesh-study/<MODELISATION>/H<h>/.
#   MODELISATION=AXIS_SI (environment) runs the mean-dilatation cells instead of 'AXIS'.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
stella="${1:-$here/../../build/bin/stella}"
shift || true
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(12 16 18 19 21 25 50)
modelisation="${MODELISATION:-AXIS}"
work=/tmp/ssnv506-mesh-study/$modelisation
for h in "${sizes[@]}"; do
  d="$work/H$h"
  mkdir -p "$d"
  gmsh "$here/indentation.geo" -2 -setnumber H "$h" -format msh22 -o "$d/mesh.msh" >/dev/null 2>&1
  sed "s/MODELISATION='AXIS'/MODELISATION='$modelisation'/" "$here/ssnv506.comm" >"$d/study.comm"
  printf 'P testlist verification\nF comm study.comm D 1\nF msh mesh.msh D 20\nF mess study.mess R 6\nF resu study.resu R 8\n' \
    >"$d/study.export"
  (cd "$d" && "$stella" run study.export --quiet --output-dir out --work-dir out/work >stella.log 2>&1) || true
  awk -v h="$h" 'BEGIN { ref = -1.0190213e7 }
    $1 == "REACTION" && ($5 + 0 == 0.2 || $5 + 0 == 0.4 || $5 + 0 == 0.6 || $5 + 0 == 0.8 || $5 + 0 == 1.0) {
      printf "H = %-3s t = %.1f  DY = %.6e  ratio to reference %.3f\n", h, $5, $6, $6 / (ref * $5) }' \
    "$d/out/study.resu"
done
