"""Independent cross-check of the ssnv506-like indentation (testcases/ssnv506_indentation) with
CalculiX 2.20 on the SAME mesh: CAX4 elements, the same materials (sphere ELAS E = 2.1e7 unless
--sphere-e, massif E = 210000, nu = 0.3, von Mises SY = 50 without hardening), the same boundary
conditions and load ramp (sphere top arc DY = -100 t), small strain (no NLGEOM), node-to-surface
contact slave = massif top M_CONT, master = sphere arc S_CONT with a stiff linear
pressure-overclosure. Prints the reaction on the driven arc S_TOP at t = 0.2 ... 1.0, per radian
(CalculiX's CAX forces come out for the 2-degree segment it expands the section into, i.e. per
radian = F * 90 / pi: checked with --elastic against stella and the Hertz closed form, see the
testcase README).

Usage: /usr/bin/python3 ssnv506_ccx.py [--work DIR] [--elastic] [--sphere-e E] [--mesh MSH] [--times T,T...]
                                       [--contact node|surface|mortar] [--reduced] [--penalty K (N/mm^3, <= 0: HARD)]
"""

import argparse
import math
import os
import pathlib
import subprocess
import sys

import numpy as np

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from ccx_deck import FACES, Mesh  # noqa: E402

# Edges of the 2D cells (CalculiX S1, S2, ... order) and the element type for each cell type;
# quadratic cells: corner nodes then mid-side nodes, Gmsh's order is CalculiX's.
EDGES = {"quad": FACES["quad"], "quad8": [(0, 1, 4), (1, 2, 5), (2, 3, 6), (3, 0, 7)],
         "triangle": [(0, 1), (1, 2), (2, 0)], "triangle6": [(0, 1, 3), (1, 2, 4), (2, 0, 5)]}
CONTACT_TYPE = {"node": "NODE TO SURFACE", "surface": "SURFACE TO SURFACE", "mortar": "MORTAR"}
ELEMENT = {"quad": "CAX4", "quad8": "CAX8", "triangle": "CAX3", "triangle6": "CAX6"}

CASE = HERE.parents[2] / "testcases" / "ssnv506_indentation"
TIMES = (0.2, 0.4, 0.6, 0.8, 1.0)
REFERENCE = -1.0190213e7  # per radian per unit of t (the published ssnv506 table is linear in t)


def write(mesh, path, elastic, sphere_e, contact, penalty, depth, times, reduced):
    lines = ["*HEADING", "ssnv506-like indentation, written by tools/bench/contact-calculix/ssnv506_ccx.py",
             "*NODE"]
    cells = [(n, t, c) for n in ("MASSIF", "SPHERE") for t, c in mesh.groups[n] if t in EDGES]
    used = np.unique(np.concatenate([c.ravel() for _n, _t, c in cells]))
    for i in used:
        x = mesh.points[i]
        lines.append(f"{i + 1}, {x[0]:.15g}, {x[1]:.15g}, 0.")
    face_index, eid = {}, 0
    for name, t, conn_all in cells:
        lines.append(f"*ELEMENT, TYPE={ELEMENT[t]}{'R' if reduced and t.startswith('quad') else ''}, ELSET={name}")
        for conn in conn_all:
            eid += 1
            lines.append(f"{eid}, " + ", ".join(str(n + 1) for n in conn))
            for k, f in enumerate(EDGES[t]):
                face_index[tuple(sorted(conn[list(f)]))] = (eid, k + 1)
    for name in ("M_BASE", "M_AXE", "S_AXE", "S_TOP", "M_CONT"):
        nodes = mesh.group_nodes(name)
        lines.append(f"*NSET, NSET={name}")
        lines.extend(", ".join(str(n + 1) for n in nodes[i:i + 12]) for i in range(0, len(nodes), 12))
    for sname, group in (("SLAVE", "M_CONT"), ("MASTER", "S_CONT")):
        lines.append(f"*SURFACE, NAME={sname}, TYPE=ELEMENT")
        for _t, conn_all in mesh.groups[group]:
            for conn in conn_all:
                e, f = face_index[tuple(sorted(conn))]
                lines.append(f"{e}, S{f}")
    lines += ["*MATERIAL, NAME=ACIER", "*ELASTIC", f"{sphere_e:.9g}, 0.3",
              "*MATERIAL, NAME=MASSIF", "*ELASTIC", "210000., 0.3"]
    if not elastic:
        lines += ["*PLASTIC", "50., 0."]
    lines += ["*SOLID SECTION, ELSET=SPHERE, MATERIAL=ACIER", "*SOLID SECTION, ELSET=MASSIF, MATERIAL=MASSIF",
              "*SURFACE INTERACTION, NAME=SI"]
    lines += (["*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD"] if penalty <= 0 else
              ["*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR", f"{penalty:.6g}, 1e-3, 1e-3"])
    lines += [
              f"*CONTACT PAIR, INTERACTION=SI, TYPE={CONTACT_TYPE[contact]}",
              "SLAVE, MASTER",
              "*BOUNDARY", "M_BASE, 1, 2, 0.", "M_AXE, 1, 1, 0.", "S_AXE, 1, 1, 0.",
              "*AMPLITUDE, NAME=RAMPE", "0., 0., 1., 1.",
              "*TIME POINTS, NAME=TP", ", ".join(f"{t:g}" for t in times),
              "*STEP, INC=2000", "*STATIC", f"0.005, {max(times):g}, 1e-7, 0.01",
              "*BOUNDARY, AMPLITUDE=RAMPE", f"S_TOP, 2, 2, {-depth:g}",
              "*NODE PRINT, NSET=S_TOP, TOTALS=ONLY, TIME POINTS=TP", "RF",
              "*NODE PRINT, NSET=M_BASE, TOTALS=ONLY, TIME POINTS=TP", "RF",
              "*END STEP"]
    path.write_text("\n".join(lines) + "\n")


def totals(dat):
    """[(time, fy of the S_TOP total, fy of the M_BASE total)] from the .dat file."""
    out, lines = [], open(dat).read().splitlines()
    block = []
    for i, line in enumerate(lines):
        if "total force" in line:
            t = float(line.split("time")[-1])
            block.append((t, float(lines[i + 2].split()[1])))
    for k in range(0, len(block) - 1, 2):
        out.append((block[k][0], block[k][1], block[k + 1][1]))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--work", default="/tmp/ssnv506-ccx")
    ap.add_argument("--elastic", action="store_true", help="elastic massif, depth 2 mm (Hertz check)")
    ap.add_argument("--sphere-e", type=float, default=2.1e7)
    ap.add_argument("--mesh", default=str(CASE / "indentation_quad4.msh"))
    ap.add_argument("--reduced", action="store_true", help="CAX4R/CAX8R (reduced integration)")
    ap.add_argument("--contact", default="node", choices=tuple(CONTACT_TYPE))
    ap.add_argument("--penalty", type=float, default=1e6, help="N/mm^3; <= 0: HARD")
    ap.add_argument("--times", default=None,
                    help="output instants, comma-separated; the run stops at the last (default 0.2,...,1)")
    a = ap.parse_args()
    work = pathlib.Path(a.work)
    work.mkdir(parents=True, exist_ok=True)
    depth = 2.0 if a.elastic else 100.0
    times = (1.0,) if a.elastic else (tuple(float(t) for t in a.times.split(",")) if a.times else TIMES)
    write(Mesh(a.mesh), work / "ssnv506.inp", a.elastic, a.sphere_e, a.contact, a.penalty, depth, times,
          a.reduced)
    with open(work / "ccx.log", "w") as log:
        rc = subprocess.call(["ccx", "ssnv506"], cwd=work, stdout=log, stderr=subprocess.STDOUT,
                             env=dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_EQUATION_SOLVER="1"))
    print(f"ccx exit {rc}; deck and log in {work}")
    for t, top, base in totals(work / "ssnv506.dat"):
        line = f"t = {t:5.3f}  S_TOP Fy = {top:.6e}  M_BASE Fy = {base:.6e}  per radian = {top * 90 / math.pi:.6e}"
        if a.elastic:
            estar = 1.0 / ((1 - 0.3**2) / 210000.0 + (1 - 0.3**2) / a.sphere_e)
            hertz = -4.0 / 3.0 * estar * math.sqrt(500.0) * (depth * t) ** 1.5
            line += f"  Hertz per radian {hertz / (2 * math.pi):.6e}"
        else:
            line += f"  reference per radian {REFERENCE * t:.6e}"
        print(line)


if __name__ == "__main__":
    main()
