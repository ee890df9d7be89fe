#!/usr/bin/env python3
"""Writes sliding_block_continue_3d.msh (Gmsh 2.2 ASCII) by hand: 3D, units mm, y upwards.
Base -60 <= x, z <= 60, -20 <= y <= 0: 24 x 4 x 24 HEXA8 (5 mm cells), its top y = 0 the master
surface (QUAD4). Block -3.9 <= x, z <= 6.1, 0 <= y <= 10 on it: 8 x 8 x 8 HEXA8 (1.25 mm cells), its
bottom y = 0 the slave surface (QUAD4, 81 nodes; off the lines of the base's nodes: a slave node on an
edge between two master cells makes the geometric loop of POINT_FIXE cycle between them).
Groups: BASE, BLOC (volumes); BASE_BAS, BASE_HAUT, BLOC_BAS, BLOC_HAUT (QUAD4 faces).
Usage: /usr/bin/python3 make_mesh_3d.py  (writes sliding_block_continue_3d.msh next to this script)."""
from pathlib import Path


def grid(nodes, origin, size, counts):
    """Nodes of a structured box; returns index(i, j, k) -> 1-based node number (i: x, j: y, k: z)."""
    start = len(nodes)
    nx, ny, nz = counts
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                nodes.append(tuple(origin[a] + size[a] * (i, j, k)[a] / counts[a] for a in range(3)))
    return lambda i, j, k: start + 1 + i + (nx + 1) * (j + (ny + 1) * k)


def box(cells, n, counts, volume, bottom, top):
    nx, ny, nz = counts
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                # bottom face (y = j) then top face (y = j + 1), each counterclockwise seen from +y
                b = [n(i, j, k), n(i, j, k + 1), n(i + 1, j, k + 1), n(i + 1, j, k)]
                t = [n(i, j + 1, k), n(i, j + 1, k + 1), n(i + 1, j + 1, k + 1), n(i + 1, j + 1, k)]
                cells.append((5, volume, b + t))
    for k in range(nz):
        for i in range(nx):
            # outward: -y at the bottom, +y at the top
            cells.append((3, bottom, [n(i, 0, k), n(i + 1, 0, k), n(i + 1, 0, k + 1), n(i, 0, k + 1)]))
            cells.append((3, top, [n(i, ny, k), n(i, ny, k + 1), n(i + 1, ny, k + 1), n(i + 1, ny, k)]))


def main():
    nodes = []
    cells = []
    tags = {"BASE": (3, 1), "BLOC": (3, 2), "BASE_BAS": (2, 3), "BASE_HAUT": (2, 4), "BLOC_BAS": (2, 5),
            "BLOC_HAUT": (2, 6)}
    base = grid(nodes, (-60.0, -20.0, -60.0), (120.0, 20.0, 120.0), (24, 4, 24))
    box(cells, base, (24, 4, 24), 1, 3, 4)
    block = grid(nodes, (-3.9, 0.0, -3.9), (10.0, 10.0, 10.0), (8, 8, 8))
    box(cells, block, (8, 8, 8), 2, 5, 6)
    out = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$PhysicalNames", str(len(tags))]
    out += [f'{dim} {tag} "{name}"' for name, (dim, tag) in tags.items()]
    out += ["$EndPhysicalNames", "$Nodes", str(len(nodes))]
    out += [f"{k + 1} {x!r} {y!r} {z!r}" for k, (x, y, z) in enumerate(nodes)]
    out += ["$EndNodes", "$Elements", str(len(cells))]
    out += [f"{k + 1} {t} 2 {p} {p} " + " ".join(map(str, ns)) for k, (t, p, ns) in enumerate(cells)]
    out += ["$EndElements", ""]
    (Path(__file__).parent / "sliding_block_continue_3d.msh").write_text("\n".join(out))


if __name__ == "__main__":
    main()
