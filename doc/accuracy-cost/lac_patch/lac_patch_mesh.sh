#!/bin/sh
# Mesh of one point of the LAC patch-test sweep (lac_patch.sweep): the two blocks of
# testcases/lac_patch_2d/blocks.geo (DIM = 2) or testcases/lac_patch_3d/blocks3d.geo (DIM = 3), with
# NLOW and NUP cells along the interface divided by H (H = 1, 1/2, 1/4: the test case's mesh refined).
# Usage: lac_patch_mesh.sh DIM QLOW QUP NLOW NUP ORDER H OUT  (ORDER 3: complete quadratic cells)
set -e
R=$(awk "BEGIN { print int(1 / $7 + 0.5) }")
DIM=$1 QLOW=$2 QUP=$3 NLOW=$(( $4 * R )) NUP=$(( $5 * R )) ORDER=$6 OUT=$8
INCOMPLETE=1
if [ "$ORDER" = 3 ]; then ORDER=2; INCOMPLETE=0; fi
if [ "$DIM" = 2 ]; then
  exec gmsh ../../../testcases/lac_patch_2d/blocks.geo -2 -format msh22 -setnumber NLOW $NLOW -setnumber NUP $NUP \
    -setnumber QLOW $QLOW -setnumber QUP $QUP -setnumber ORDER $ORDER -setnumber INCOMPLETE $INCOMPLETE -o "$OUT"
fi
exec gmsh ../../../testcases/lac_patch_3d/blocks3d.geo -3 -format msh22 -setnumber NLOW $NLOW -setnumber NUP $NUP \
  -setnumber HLOW $QLOW -setnumber HUP $QUP -setnumber ORDER $ORDER -setnumber INCOMPLETE $INCOMPLETE -o "$OUT"
