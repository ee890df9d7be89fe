#!/usr/bin/env bash
# Runs the phase timings of doc/bench/linalg.md: stella-bench-fem over mesh sizes and solvers,
# single-threaded BLAS, one line of key=value per run on stdout.
#   tools/bench/fem/run-linalg-bench.sh BUILD_DIR/stella-bench-fem [quick|full]
set -euo pipefail
bench=${1:?path to stella-bench-fem}
mode=${2:-quick}
export OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1
run() { "$bench" "$@"; }
if [ "$mode" = full ]; then
  hexa="8 12 16 20 45"; tetra="4 6 8 22"; quad="100 200 400 706"
else
  hexa="8 12 16 20"; tetra="4 6 8"; quad="100 200 400"
fi
for n in $hexa; do for s in MUMPS MULT_FRONT; do run hexa8 "$n" "$s"; done; done
for n in $tetra; do for s in MUMPS MULT_FRONT; do run tetra10 "$n" "$s"; done; done
for n in $quad; do for s in MUMPS MULT_FRONT; do run quad4 "$n" "$s"; done; done
run hexa8 12 MUMPS lagrange
run hexa8 12 MULT_FRONT lagrange
run hexa8 12 GCPC
