#!/usr/bin/env bash
# The mesh of petsc_contact.comm: two stacked cubes of side 10, 4^3 HEXA8 in each
# (matching nodes at z = 0, not merged), written by the contact benchmark's generator.
set -euo pipefail
cd "$(dirname "$0")"
/usr/bin/python3 ../../tools/bench/contact-calculix/blocks3d.py 4 4 blocks_4_4.msh
# The mesh of petsc_contact_slabs.comm: the 10^6-DOF contact study of tools/bench/contact-1e6
# at 12 615 DOFs: slabs 10 x 10 x 1.6, 19^2 x 4 HEXA8 under 20^2 x 4 (non-matching, 441 slave nodes).
/usr/bin/python3 ../../tools/bench/contact-calculix/blocks3d.py 19 20 slabs_19_20.msh --layers 4 4 --heights 1.6 1.6
