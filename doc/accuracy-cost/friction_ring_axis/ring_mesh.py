#!/usr/bin/env python3
"""Mesh of the friction-ring sweep (friction_ring_axis.sweep), Gmsh 2.2 ASCII: the AXIS meridian
section of testcases/friction_ring_axis written by its make_mesh.py (same geometry and groups) with
cells of size H: ring a = 1 <= r <= b = 3, 0 <= z <= 1 in (2 / H) x (1 / H) QUAD4, on a rigid base
0.5 <= r <= 3.5, -0.5 <= z <= 0 (one QUAD4) whose top edge is the master surface.
Groups: ANNEAU, SOL; ANNEAU_BAS (slave), ANNEAU_HAUT (pressed), ANNEAU_INT (r = a, driven), SOL_HAUT
(master); COIN (POI1, the ring's node (a, 0)).
Usage: /usr/bin/python3 ring_mesh.py H OUT"""
import sys
from pathlib import Path

sys.dont_write_bytecode = True  # nothing written into the test case's folder
sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "testcases" / "friction_ring_axis"))
import make_mesh  # noqa: E402  (the test case's generator)


def main(size, path):
    nr = round((make_mesh.B - make_mesh.A) / size)
    nz = round(make_mesh.H / size)
    make_mesh.write(nr, nz, path)


if __name__ == "__main__":
    main(float(sys.argv[1]), sys.argv[2])
