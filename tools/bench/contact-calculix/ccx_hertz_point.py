#!/usr/bin/python3
"""One CalculiX (ccx 2.20) point of the Hertz cylinder for `stella sweep` (an external series,
doc/sweep.md; used by doc/accuracy-cost/hertz_cylinder): the sweep's mesh of
testcases/hertz_cylinder/hertz_cylinder.geo, extruded into one layer of C3D8 (bench.py's hertz2d
deck: plane strain by DZ = 0, surface-to-surface HARD contact with CalculiX's default penalty,
the approach D = 1 mm imposed on IND_TOP), then the result written as `stella sweep` reads it:
    COMPUTED REFERENCE p(h) h
COMPUTED is the largest nodal contact force per unit length, CalculiX's nodal contact pressure
(CSTR) times each slave node's tributary length; REFERENCE is Hertz' p(h) h for the force CalculiX
carries (its reaction on IND_TOP), h the smallest slave edge: the quantity the stella series test.
Usage: ccx_hertz_point.py MESH.msh OUT"""
import math
import subprocess
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench import E, E_STAR, NU, R_HERTZ, ccx_hertz_body, ccx_node_values, ccx_total_force  # noqa: E402
from ccx_deck import Mesh, write_deck  # noqa: E402


def main(mesh_path, out):
    out = Path(out)
    d = out.parent / "ccx"
    d.mkdir(exist_ok=True)
    mesh = Mesh(mesh_path)
    write_deck(mesh, d / "hertz.inp", ["BLOC", "IND"], {"BLOC": (E, NU), "IND": (E, NU)},
               ["BLOC_BASE", "BLOC_AXE", "IND_AXE", "IND_TOP", "IND_CONT"],
               {"CSLAVE": "IND_CONT", "CMASTER": "BLOC_TOP"}, ccx_hertz_body("s2s"), slab=1.0)
    with open(d / "ccx.log", "w") as log:
        rc = subprocess.call(["ccx", "hertz"], cwd=d, stdout=log, stderr=subprocess.STDOUT)
    if rc != 0:
        sys.exit(f"ccx ended with {rc}: {d / 'ccx.log'}")
    total = 2.0 * abs(ccx_total_force(d / "hertz.dat")[1])  # symmetric half model, slab of thickness 1
    press = ccx_node_values(d / "hertz.frd", "CONTACT", 3)
    slave = mesh.group_nodes("IND_CONT")
    order = np.argsort(mesh.points[slave][:, 0])
    x = mesh.points[slave][order, 0]
    p = np.array([press.get(n + 1, 0.0) for n in slave[order]])
    edges = np.diff(x)
    tributary = 0.5 * (np.concatenate([[0.0], edges]) + np.concatenate([edges, [0.0]]))
    h = float(edges.min())
    a = math.sqrt(4.0 * total * R_HERTZ / (math.pi * E_STAR))
    p0 = 2.0 * total / (math.pi * a)
    reference = p0 * math.sqrt(1.0 - (h / a) ** 2) * h
    out.write_text(f"# CalculiX, total force {total:.6g} N/mm, a = {a:.6g} mm, h = {h:.6g} mm\n"
                   f"{float(np.max(p * tributary)):.10g} {reference:.10g} p(h) h\n")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
