#!/usr/bin/env bash
# The mesh of petsc_contact.comm: two stacked cubes of side 10, 4^3 HEXA8 in each
# (matching nodes at z = 0, not merged), written by the contact benchmark's generator.
set -euo pipefail
cd "$(dirname "$0")"
/usr/bin/python3 ../../tools/bench/contact-calculix/blocks3d.py 4 4 blocks_4_4.msh
