#!/bin/sh
# A fake external program for the tiny sweep's external series (external.sweep): for D_PLAN it
# sleeps 0.2 s and writes u_r(a) = 9.5e-4 against the closed form 9.533333333333335e-4 (error
# 3.4965e-3 by hand) in the results file $2; any other model fails with exit 3.
test "$1" = D_PLAN || { echo "fake: no model $1" >&2; exit 3; }
sleep 0.2
printf '# fake external results\n9.5e-4 9.533333333333335e-4 u_r(a)\n' >"$2"
