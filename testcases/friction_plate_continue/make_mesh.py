#!/usr/bin/env python3
"""Writes friction_plate.msh (Gmsh 2.2 ASCII) by hand, so that the node numbers the command file
uses for its periodic ties are fixed: plate node (i, j) (i = 0..NX along x, j = 0..NY along y) is
N<1 + i + (NX + 1) j>. Plate 0 <= x <= L, 0 <= y <= H (QUAD4, counter-clockwise); a rigid base
0 <= x <= L, -HB <= y <= 0 below it (one row of QUAD4, every node fixed by the command file),
its own nodes, coincident with the plate's bottom ones.
Groups: PLAQUE, SOL (surfaces); PLAQUE_BAS (slave), PLAQUE_HAUT, SOL_HAUT (master) (edges);
COIN (POI1 on the plate's bottom-right node, the periodic copy of the bottom-left one).
Usage: /usr/bin/python3 make_mesh.py  (writes friction_plate.msh next to this script)."""
from pathlib import Path

L, H, HB, NX, NY = 40.0, 10.0, 5.0, 8, 2


def main():
    nodes = []
    for j in range(NY + 1):
        for i in range(NX + 1):
            nodes.append((L * i / NX, H * j / NY))
    base0 = len(nodes)
    for j in range(2):
        for i in range(NX + 1):
            nodes.append((L * i / NX, -HB + HB * j))
    plate = lambda i, j: 1 + i + (NX + 1) * j
    base = lambda i, j: base0 + 1 + i + (NX + 1) * j
    # physical tags
    tags = {"PLAQUE": (2, 1), "SOL": (2, 2), "PLAQUE_BAS": (1, 3), "PLAQUE_HAUT": (1, 4), "SOL_HAUT": (1, 5),
            "COIN": (0, 6)}
    cells = []  # (gmsh type, physical tag, nodes)
    cells.append((15, 6, [plate(NX, 0)]))
    for i in range(NX):
        cells.append((1, 3, [plate(i, 0), plate(i + 1, 0)]))
        cells.append((1, 4, [plate(i + 1, NY), plate(i, NY)]))
        cells.append((1, 5, [base(i + 1, 1), base(i, 1)]))
    for j in range(NY):
        for i in range(NX):
            cells.append((3, 1, [plate(i, j), plate(i + 1, j), plate(i + 1, j + 1), plate(i, j + 1)]))
    for i in range(NX):
        cells.append((3, 2, [base(i, 0), base(i + 1, 0), base(i + 1, 1), base(i, 1)]))
    out = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$PhysicalNames", str(len(tags))]
    out += [f'{dim} {tag} "{name}"' for name, (dim, tag) in tags.items()]
    out += ["$EndPhysicalNames", "$Nodes", str(len(nodes))]
    out += [f"{k + 1} {x!r} {y!r} 0" for k, (x, y) in enumerate(nodes)]
    out += ["$EndNodes", "$Elements", str(len(cells))]
    out += [f"{k + 1} {t} 2 {p} {p} " + " ".join(map(str, ns)) for k, (t, p, ns) in enumerate(cells)]
    out += ["$EndElements", ""]
    (Path(__file__).parent / "friction_plate.msh").write_text("\n".join(out))


if __name__ == "__main__":
    main()
