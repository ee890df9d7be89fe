#!/bin/bash
# The performance campaign of doc/bench/fem-performance.md: MECA_STATIQUE through `stella run`
# (run-stella-bench.sh), MUMPS and MULT_FRONT (CHOLMOD), four sizes per case, the largest last
# (about 300 000 DOFs in 3D, 1 M in 2D), one run at a time. Appends one line per run to RESULTS.
#
#   run-stella-campaign.sh STELLA WORKDIR RESULTS [quick]
set -uo pipefail
stella=$1
work=$2
results=$3
here=$(cd "$(dirname "$0")" && pwd)
if [[ ${4:-} == quick ]]; then
  sizes=("hexa8 16 24" "tetra10 8 12" "quad4 100 200")
else
  sizes=("hexa8 16 24 32" "tetra10 8 12 16" "quad4 100 200 400" "quad4 707" "hexa8 46" "tetra10 23")
fi
for entry in "${sizes[@]}"; do
  read -r case_name ns <<< "$entry"
  for n in $ns; do
    for method in MUMPS MULT_FRONT; do
      "$here/run-stella-bench.sh" "$stella" "$case_name" "$n" "$method" "$work" >> "$results"
      tail -1 "$results"
    done
  done
done
