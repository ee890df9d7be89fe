#!/usr/bin/python3
"""Writes the 3D block-on-block benchmark mesh (Gmsh 2.2 ASCII): two stacked cubes of side 10 (mm),
BAS = [0,10]^2 x [-10,0] with NB HEXA8 per side and HAUT = [0,10]^2 x [0,10] with NH per side
(non-matching at z = 0 when NB != NH). With a 4th argument "merged" (NB = NH), the cubes share
their interface nodes: the bonded model of the contact-overhead measure. Groups (cells and nodes): BAS, HAUT (volumes); QUAD4 faces BAS_Z0
(z = -10), BAS_HAUT (z = 0, master), HAUT_BAS (z = 0, slave), HAUT_Z1 (z = 10), SYM_X (x = 0 of
both), SYM_Y (y = 0 of both). Usage: blocks3d.py NB NH OUT.msh [merged]"""
import sys


def main():
    nb, nh, out = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
    merged = len(sys.argv) > 4 and sys.argv[4] == "merged"
    if merged and nb != nh:
        sys.exit("merged needs NB = NH")
    nodes, cells = [], []  # cells: (gmsh type, physical tag, node tags)
    names = {1: (3, "BAS"), 2: (3, "HAUT"), 3: (2, "BAS_Z0"), 4: (2, "BAS_HAUT"), 5: (2, "HAUT_BAS"),
             6: (2, "HAUT_Z1"), 7: (2, "SYM_X"), 8: (2, "SYM_Y")}

    def cube(n, z0, vol, bottom, top, shared=False):
        # shared: the first layer of nodes is the previous cube's last layer
        base = len(nodes) + 1 - ((n + 1) ** 2 if shared else 0)
        h = 10.0 / n

        def tag(i, j, k):
            return base + i + (n + 1) * (j + (n + 1) * k)

        for k in range(1 if shared else 0, n + 1):
            for j in range(n + 1):
                for i in range(n + 1):
                    nodes.append((i * h, j * h, z0 + k * h))
        for k in range(n):
            for j in range(n):
                for i in range(n):
                    c = [tag(i, j, k), tag(i + 1, j, k), tag(i + 1, j + 1, k), tag(i, j + 1, k)]
                    cells.append((5, vol, c + [t + (n + 1) ** 2 for t in c]))
        for j in range(n):
            for i in range(n):  # faces oriented outward
                cells.append((3, bottom, [tag(i, j, 0), tag(i, j + 1, 0), tag(i + 1, j + 1, 0), tag(i + 1, j, 0)]))
                cells.append((3, top, [tag(i, j, n), tag(i + 1, j, n), tag(i + 1, j + 1, n), tag(i, j + 1, n)]))
        for k in range(n):
            for j in range(n):
                cells.append((3, 7, [tag(0, j, k), tag(0, j, k + 1), tag(0, j + 1, k + 1), tag(0, j + 1, k)]))
            for i in range(n):
                cells.append((3, 8, [tag(i, 0, k), tag(i + 1, 0, k), tag(i + 1, 0, k + 1), tag(i, 0, k + 1)]))

    cube(nb, -10.0, 1, 3, 4)
    cube(nh, 0.0, 2, 5, 6, merged)
    with open(out, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n%d\n" % len(names))
        for t, (d, name) in names.items():
            f.write(f'{d} {t} "{name}"\n')
        f.write("$EndPhysicalNames\n$Nodes\n%d\n" % len(nodes))
        for i, (x, y, z) in enumerate(nodes):
            f.write(f"{i + 1} {x:.15g} {y:.15g} {z:.15g}\n")
        f.write("$EndNodes\n$Elements\n%d\n" % len(cells))
        for i, (t, phys, c) in enumerate(cells):
            f.write(f"{i + 1} {t} 2 {phys} {phys} " + " ".join(map(str, c)) + "\n")
        f.write("$EndElements\n")


if __name__ == "__main__":
    main()
