#!/usr/bin/env python3
"""Writes friction_ring_axis.msh (Gmsh 2.2 ASCII) by hand: an AXIS meridian section (x = r, y = z).
Ring a = 1 <= r <= b = 3, 0 <= z <= H = 1 (NR x NZ QUAD4, counter-clockwise); a rigid base
0.5 <= r <= 3.5, -0.5 <= z <= 0 below it (one QUAD4, every node fixed by the command file), whose
top edge z = 0 is the master surface.
Groups: ANNEAU, SOL (surfaces); ANNEAU_BAS (slave), ANNEAU_HAUT (pressed), ANNEAU_INT (r = a,
driven), SOL_HAUT (master) (edges); COIN (POI1 on the ring's node (a, 0), driven and excluded from
the slave nodes).
Usage: /usr/bin/python3 make_mesh.py  (writes friction_ring_axis.msh next to this script). The
accuracy-cost page doc/accuracy-cost/friction_ring_axis writes its finer meshes with write()."""
from pathlib import Path

A, B, H, NR, NZ = 1.0, 3.0, 1.0, 4, 2


def write(nr, nz, path):
    """The mesh with nr x nz QUAD4 in the ring, written to path."""
    nodes = []
    for j in range(nz + 1):
        for i in range(nr + 1):
            nodes.append((A + (B - A) * i / nr, H * j / nz))
    base0 = len(nodes)
    nodes += [(0.5, -0.5), (3.5, -0.5), (3.5, 0.0), (0.5, 0.0)]
    ring = lambda i, j: 1 + i + (nr + 1) * j
    base = lambda c: base0 + 1 + c
    tags = {"ANNEAU": (2, 1), "SOL": (2, 2), "ANNEAU_BAS": (1, 3), "ANNEAU_HAUT": (1, 4), "ANNEAU_INT": (1, 5),
            "SOL_HAUT": (1, 6), "COIN": (0, 7)}
    cells = [(15, 7, [ring(0, 0)])]
    for i in range(nr):
        cells.append((1, 3, [ring(i, 0), ring(i + 1, 0)]))
        cells.append((1, 4, [ring(i + 1, nz), ring(i, nz)]))
    for j in range(nz):
        cells.append((1, 5, [ring(0, j + 1), ring(0, j)]))
    cells.append((1, 6, [base(2), base(3)]))
    for j in range(nz):
        for i in range(nr):
            cells.append((3, 1, [ring(i, j), ring(i + 1, j), ring(i + 1, j + 1), ring(i, j + 1)]))
    cells.append((3, 2, [base(0), base(1), base(2), base(3)]))
    out = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$PhysicalNames", str(len(tags))]
    out += [f'{dim} {tag} "{name}"' for name, (dim, tag) in tags.items()]
    out += ["$EndPhysicalNames", "$Nodes", str(len(nodes))]
    out += [f"{k + 1} {x!r} {y!r} 0" for k, (x, y) in enumerate(nodes)]
    out += ["$EndNodes", "$Elements", str(len(cells))]
    out += [f"{k + 1} {t} 2 {p} {p} " + " ".join(map(str, ns)) for k, (t, p, ns) in enumerate(cells)]
    out += ["$EndElements", ""]
    Path(path).write_text("\n".join(out))


def main():
    write(NR, NZ, Path(__file__).parent / "friction_ring_axis.msh")


if __name__ == "__main__":
    main()
