#!/usr/bin/env python3
"""Writes friction_block_continue.msh (Gmsh 2.2 ASCII) by hand, so that the node numbers the command
files use for their periodic ties are fixed: block node (i, j, k) (i, j = 0..N along x, y; k = 0, 1
along z) is N<1 + i + (N + 1) j + (N + 1)^2 k>. Block 0 <= x, y <= L, 0 <= z <= H (N x N x 1 HEXA8);
a rigid base -1 <= x, y <= L + 1, -1 <= z <= 0 below it (one HEXA8, every node fixed by the command
files), whose top face z = 0 is the master surface.
Groups: BLOC, SOL (volumes); BLOC_BAS (slave), BLOC_HAUT, SOL_HAUT (master) (QUAD4 faces);
COPIES (POI1 on the block's bottom nodes of x = L or y = L, the periodic copies of x = 0 and y = 0).
Usage: /usr/bin/python3 make_mesh.py  (writes friction_block_continue.msh next to this script)."""
from pathlib import Path

L, H, N = 2.0, 1.0, 2


def main():
    nodes = []
    for k in range(2):
        for j in range(N + 1):
            for i in range(N + 1):
                nodes.append((L * i / N, L * j / N, H * k))
    base0 = len(nodes)
    for z in (-1.0, 0.0):
        for x, y in ((-1.0, -1.0), (L + 1, -1.0), (L + 1, L + 1), (-1.0, L + 1)):
            nodes.append((x, y, z))
    block = lambda i, j, k: 1 + i + (N + 1) * j + (N + 1) ** 2 * k
    base = lambda c, k: base0 + 1 + c + 4 * k
    tags = {"BLOC": (3, 1), "SOL": (3, 2), "BLOC_BAS": (2, 3), "BLOC_HAUT": (2, 4), "SOL_HAUT": (2, 5),
            "COPIES": (0, 6)}
    cells = []  # (gmsh type, physical tag, nodes)
    for j in range(N + 1):
        for i in range(N + 1):
            if i == N or j == N:
                cells.append((15, 6, [block(i, j, 0)]))
    for j in range(N):
        for i in range(N):
            # faces oriented outward from the block: -z at the bottom, +z at the top
            cells.append((3, 3, [block(i, j, 0), block(i, j + 1, 0), block(i + 1, j + 1, 0), block(i + 1, j, 0)]))
            cells.append((3, 4, [block(i, j, 1), block(i + 1, j, 1), block(i + 1, j + 1, 1), block(i, j + 1, 1)]))
    cells.append((3, 5, [base(0, 1), base(1, 1), base(2, 1), base(3, 1)]))
    for j in range(N):
        for i in range(N):
            cells.append((5, 1, [block(i, j, 0), block(i + 1, j, 0), block(i + 1, j + 1, 0), block(i, j + 1, 0),
                                 block(i, j, 1), block(i + 1, j, 1), block(i + 1, j + 1, 1), block(i, j + 1, 1)]))
    cells.append((5, 2, [base(c, 0) for c in range(4)] + [base(c, 1) for c in range(4)]))
    out = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$PhysicalNames", str(len(tags))]
    out += [f'{dim} {tag} "{name}"' for name, (dim, tag) in tags.items()]
    out += ["$EndPhysicalNames", "$Nodes", str(len(nodes))]
    out += [f"{k + 1} {x!r} {y!r} {z!r}" for k, (x, y, z) in enumerate(nodes)]
    out += ["$EndNodes", "$Elements", str(len(cells))]
    out += [f"{k + 1} {t} 2 {p} {p} " + " ".join(map(str, ns)) for k, (t, p, ns) in enumerate(cells)]
    out += ["$EndElements", ""]
    (Path(__file__).parent / "friction_block_continue.msh").write_text("\n".join(out))


if __name__ == "__main__":
    main()
