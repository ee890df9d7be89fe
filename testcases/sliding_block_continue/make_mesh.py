#!/usr/bin/env python3
"""Writes sliding_block_continue.msh (Gmsh 2.2 ASCII) by hand: plane strain, units mm.
Base -60 <= x <= 60, -20 <= y <= 0: 24 x 4 QUAD8 (5 mm cells), its top y = 0 the master surface
(SEG3, outward normal +y). Block -5 <= x <= 5, 0 <= y <= 10 on it: 8 x 8 QUAD4 (1.25 mm cells), its
bottom y = 0 the slave surface (SEG2, outward normal -y).
Groups: BASE, BLOC (volumes); BASE_BAS, BASE_HAUT (SEG3), BLOC_BAS, BLOC_HAUT (SEG2); node groups
MILIEU (the block's bottom node x = 0) and B_COIN (its bottom nodes x = -5 and x = 5).
Usage: /usr/bin/python3 make_mesh.py  (writes sliding_block_continue.msh next to this script)."""
from pathlib import Path

LB, HB, NBX, NBY = 60.0, 20.0, 24, 4
W, H, NX, NY = 5.0, 10.0, 8, 8


def main():
    nodes = []
    index = {}

    def node(x, y):
        key = (round(x, 9), round(y, 9))
        if key not in index:
            nodes.append((x, y))
            index[key] = len(nodes)
        return index[key]

    cells = []  # (gmsh type, physical tag, nodes)
    tags = {"BASE": (2, 1), "BLOC": (2, 2), "BASE_BAS": (1, 3), "BASE_HAUT": (1, 4), "BLOC_BAS": (1, 5),
            "BLOC_HAUT": (1, 6), "MILIEU": (0, 7), "B_COIN": (0, 8)}
    dx, dy = 2 * LB / NBX, HB / NBY
    for j in range(NBY):
        for i in range(NBX):
            x0, y0 = -LB + i * dx, -HB + j * dy
            c = [node(x0, y0), node(x0 + dx, y0), node(x0 + dx, y0 + dy), node(x0, y0 + dy)]
            m = [node(x0 + dx / 2, y0), node(x0 + dx, y0 + dy / 2), node(x0 + dx / 2, y0 + dy),
                 node(x0, y0 + dy / 2)]
            cells.append((16, 1, c + m))
    for i in range(NBX):
        x0 = -LB + i * dx
        # outward: the bottom runs +x (normal -y), the top runs -x (normal +y)
        cells.append((8, 3, [node(x0, -HB), node(x0 + dx, -HB), node(x0 + dx / 2, -HB)]))
        cells.append((8, 4, [node(x0 + dx, 0.0), node(x0, 0.0), node(x0 + dx / 2, 0.0)]))
    bx, by = 2 * W / NX, H / NY
    block = {}
    for j in range(NY + 1):
        for i in range(NX + 1):
            nodes.append((-W + i * bx, j * by))  # distinct from the base's nodes at y = 0
            block[i, j] = len(nodes)
    for j in range(NY):
        for i in range(NX):
            cells.append((3, 2, [block[i, j], block[i + 1, j], block[i + 1, j + 1], block[i, j + 1]]))
    for i in range(NX):
        cells.append((1, 5, [block[i, 0], block[i + 1, 0]]))
        cells.append((1, 6, [block[i + 1, NY], block[i, NY]]))
    cells.append((15, 7, [block[NX // 2, 0]]))
    cells.append((15, 8, [block[0, 0]]))
    cells.append((15, 8, [block[NX, 0]]))
    out = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$PhysicalNames", str(len(tags))]
    out += [f'{dim} {tag} "{name}"' for name, (dim, tag) in tags.items()]
    out += ["$EndPhysicalNames", "$Nodes", str(len(nodes))]
    out += [f"{k + 1} {x!r} {y!r} 0.0" for k, (x, y) in enumerate(nodes)]
    out += ["$EndNodes", "$Elements", str(len(cells))]
    out += [f"{k + 1} {t} 2 {p} {p} " + " ".join(map(str, ns)) for k, (t, p, ns) in enumerate(cells)]
    out += ["$EndElements", ""]
    (Path(__file__).parent / "sliding_block_continue.msh").write_text("\n".join(out))


if __name__ == "__main__":
    main()
