#!/usr/bin/env bash
# Runs the phase timings of doc/bench/fem-performance.md: stella-bench-system (MECA_STATIQUE's
# real path) over three mesh sizes per case, MUMPS and MULT_FRONT side by side, single-threaded
# BLAS, at low priority (the machine is shared). One line of key=value per run on stdout.
#   tools/bench/fem/run-system-bench.sh BUILD_DIR/tools/bench/fem/stella-bench-system [quick|full]
set -euo pipefail
bench=${1:?path to stella-bench-system}
mode=${2:-quick}
export OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1
run() { nice -n 10 "$bench" "$@" || echo "case=$1 divisions=$2 solver=$3 FAILED"; }
if [ "$mode" = full ]; then
  hexa="20 30 45"; tetra="10 15 22"; quad="250 500 706"
else
  hexa="12 16 20"; tetra="6 8 10"; quad="100 200 400"
fi
for n in $quad; do for s in MUMPS MULT_FRONT; do run quad4 "$n" "$s"; done; done
for n in $hexa; do for s in MUMPS MULT_FRONT; do run hexa8 "$n" "$s"; done; done
for n in $tetra; do for s in MUMPS MULT_FRONT; do run tetra10 "$n" "$s"; done; done
