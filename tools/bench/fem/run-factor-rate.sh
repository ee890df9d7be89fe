#!/usr/bin/env bash
# The measurement of doc/bench/factor-rate.md in one run: dgemm's rate at 1 and 2 BLAS threads,
# then CHOLMOD (MULT_FRONT) and MUMPS factorisations of the clamped HEXA8 cube at the sizes of
# doc/bench/fem-performance.md that factorise in under a minute (N = 16, 24, 32), each at 1 and
# 2 threads back to back; the load average before and after (the machine is shared).
#   tools/bench/fem/run-factor-rate.sh BUILD_DIR/tools/bench/fem/stella-bench-factor-rate [CHOLMOD_RENUM MUMPS_RENUM]
set -euo pipefail
bench=${1:?path to stella-bench-factor-rate}
cholmod=${2:-METIS}
mumps=${3:-AUTO}
unset OPENBLAS_NUM_THREADS STELLA_BLAS_THREADS
export OMP_NUM_THREADS=1
echo "load_before=\"$(cut -d' ' -f1-3 /proc/loadavg)\" date=$(date -u +%FT%TZ)"
"$bench" --threads 1,2 --dgemm 2000 --cholmod "$cholmod" --mumps "$mumps" 16 24 32
echo "load_after=\"$(cut -d' ' -f1-3 /proc/loadavg)\""
