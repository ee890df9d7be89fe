#!/usr/bin/env python3
"""Writes friction_block_continue_quadratic.msh (Gmsh 2.2 ASCII) by hand: the block of make_mesh.py
with quadratic cells, so that the node numbers of the periodic ties are fixed. Block 0 <= x, y <= L,
0 <= z <= H (N x N x 1 HEXA20); its nodes sit on the lattice of step L / (2N) along x, y and H / 2
along z, without the lattice points that are not HEXA20 nodes (face and cell centres): lattice point
(a, b, c) (a, b = 0..2N, c = 0..2) is N<1 + a + (2N + 1) b + (2N + 1)^2 c> whether or not it is a node
(the numbering has gaps). A rigid base -1 <= x, y <= L + 1, -1 <= z <= 0 below it (one HEXA20, every
node fixed by the command files), whose top face z = 0 is the master surface.
Groups: BLOC, SOL (volumes); BLOC_BAS (slave), BLOC_HAUT, SOL_HAUT (master) (QUAD8 faces);
COPIES (POI1 on the block's nodes of z < H on x = L or y = L: the periodic copies of x = 0 and y = 0).
Usage: /usr/bin/python3 make_mesh_quadratic.py (writes friction_block_continue_quadratic.msh here)."""
from pathlib import Path

L, H, N = 2.0, 1.0, 2
M = 2 * N + 1  # lattice points per row
# HEXA20: corners as HEXA8, then the 12 edges in Gmsh's order; QUAD8: corners, then edges (0 1 2 3 0)
HEXA_EDGES = [(0, 1), (0, 3), (0, 4), (1, 2), (1, 5), (2, 3), (2, 6), (3, 7), (4, 5), (4, 7), (5, 6), (6, 7)]


def lattice(a, b, c):
    return 1 + a + M * b + M * M * c


def is_node(a, b, c):
    odd = (a % 2) + (b % 2) + (c % 2)
    return odd <= 1  # corners (0 odd) and edge midpoints (1 odd)


def mid(p, q):
    return tuple((u + v) // 2 for u, v in zip(p, q))


def quad8(corners):
    return corners + [mid(corners[k], corners[(k + 1) % 4]) for k in range(4)]


def hexa20(corners):
    return corners + [mid(corners[i], corners[j]) for i, j in HEXA_EDGES]


def main():
    nodes = {}
    for c in range(3):
        for b in range(M):
            for a in range(M):
                if is_node(a, b, c):
                    nodes[lattice(a, b, c)] = (L * a / (2 * N), L * b / (2 * N), H * c / 2)
    base0 = M * M * 3
    # the base: its own lattice of 3 x 3 x 3 points over [-1, L + 1]^2 x [-1, 0]
    span = [-1.0, L / 2, L + 1.0]
    base = {}
    for c in range(3):
        for b in range(3):
            for a in range(3):
                if is_node(a, b, c):
                    base[(a, b, c)] = base0 + 1 + a + 3 * b + 9 * c
                    nodes[base[(a, b, c)]] = (span[a], span[b], -1.0 + 0.5 * c)
    tags = {"BLOC": (3, 1), "SOL": (3, 2), "BLOC_BAS": (2, 3), "BLOC_HAUT": (2, 4), "SOL_HAUT": (2, 5),
            "COPIES": (0, 6)}
    cells = []  # (gmsh type, physical tag, nodes)
    for c in range(2):
        for b in range(M):
            for a in range(M):
                if is_node(a, b, c) and (a == 2 * N or b == 2 * N):
                    cells.append((15, 6, [lattice(a, b, c)]))
    block = lambda p: lattice(*p)
    for j in range(N):
        for i in range(N):
            a, b = 2 * i, 2 * j
            # faces oriented outward from the block: -z at the bottom, +z at the top
            bottom = [(a, b, 0), (a, b + 2, 0), (a + 2, b + 2, 0), (a + 2, b, 0)]
            top = [(a, b, 2), (a + 2, b, 2), (a + 2, b + 2, 2), (a, b + 2, 2)]
            cells.append((16, 3, [block(p) for p in quad8(bottom)]))
            cells.append((16, 4, [block(p) for p in quad8(top)]))
    cells.append((16, 5, [base[p] for p in quad8([(0, 0, 2), (2, 0, 2), (2, 2, 2), (0, 2, 2)])]))
    for j in range(N):
        for i in range(N):
            a, b = 2 * i, 2 * j
            corners = [(a, b, 0), (a + 2, b, 0), (a + 2, b + 2, 0), (a, b + 2, 0),
                       (a, b, 2), (a + 2, b, 2), (a + 2, b + 2, 2), (a, b + 2, 2)]
            cells.append((17, 1, [block(p) for p in hexa20(corners)]))
    corners = [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0), (0, 0, 2), (2, 0, 2), (2, 2, 2), (0, 2, 2)]
    cells.append((17, 2, [base[p] for p in hexa20(corners)]))
    out = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$PhysicalNames", str(len(tags))]
    out += [f'{dim} {tag} "{name}"' for name, (dim, tag) in tags.items()]
    out += ["$EndPhysicalNames", "$Nodes", str(len(nodes))]
    out += [f"{k} {x!r} {y!r} {z!r}" for k, (x, y, z) in sorted(nodes.items())]
    out += ["$EndNodes", "$Elements", str(len(cells))]
    out += [f"{k + 1} {t} 2 {p} {p} " + " ".join(map(str, ns)) for k, (t, p, ns) in enumerate(cells)]
    out += ["$EndElements", ""]
    (Path(__file__).parent / "friction_block_continue_quadratic.msh").write_text("\n".join(out))


if __name__ == "__main__":
    main()
