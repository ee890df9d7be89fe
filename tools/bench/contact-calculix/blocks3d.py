#!/usr/bin/python3
"""Writes the 3D block-on-block benchmark mesh (Gmsh 2.2 ASCII): two stacked blocks of side 10 (mm),
BAS = [0,10]^2 x [-HB,0] with NB HEXA8 per side and HAUT = [0,10]^2 x [0,HH] with NH per side
(non-matching at z = 0 when NB != NH). By default cubes (HB = HH = 10, NB resp. NH layers);
--layers LB LH and --heights HB HH make slabs (the 10^6-DOF study of tools/bench/contact-1e6:
10 000 slave nodes need 100 x 100 nodes on the slave face). With "merged" (NB = NH, the same
layers and heights), the blocks share their interface nodes: the bonded model of the
contact-overhead measure. Groups (cells and nodes): BAS, HAUT (volumes); QUAD4 faces BAS_Z0
(z = -HB), BAS_HAUT (z = 0, master), HAUT_BAS (z = 0, slave), HAUT_Z1 (z = HH), SYM_X (x = 0 of
both), SYM_Y (y = 0 of both).
Usage: blocks3d.py NB NH OUT.msh [merged] [--layers LB LH] [--heights HB HH]"""
import argparse


def arguments():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("nb", type=int)
    p.add_argument("nh", type=int)
    p.add_argument("out")
    p.add_argument("merged", nargs="?", choices=["merged"])
    p.add_argument("--layers", type=int, nargs=2, metavar=("LB", "LH"))
    p.add_argument("--heights", type=float, nargs=2, metavar=("HB", "HH"), default=(10.0, 10.0))
    a = p.parse_args()
    if a.layers is None:
        a.layers = (a.nb, a.nh)
    if a.merged and (a.nb != a.nh or a.layers[0] != a.layers[1] or a.heights[0] != a.heights[1]):
        p.error("merged needs NB = NH and equal layers and heights")
    return a


def main():
    a = arguments()
    nodes, cells = [], []  # cells: (gmsh type, physical tag, node tags)
    names = {1: (3, "BAS"), 2: (3, "HAUT"), 3: (2, "BAS_Z0"), 4: (2, "BAS_HAUT"), 5: (2, "HAUT_BAS"),
             6: (2, "HAUT_Z1"), 7: (2, "SYM_X"), 8: (2, "SYM_Y")}

    def block(n, layers, z0, height, vol, bottom, top, shared=False):
        # shared: the first layer of nodes is the previous block's last layer
        base = len(nodes) + 1 - ((n + 1) ** 2 if shared else 0)
        h = 10.0 / n
        hz = height / layers

        def tag(i, j, k):
            return base + i + (n + 1) * (j + (n + 1) * k)

        for k in range(1 if shared else 0, layers + 1):
            for j in range(n + 1):
                for i in range(n + 1):
                    nodes.append((i * h, j * h, z0 + k * hz))
        for k in range(layers):
            for j in range(n):
                for i in range(n):
                    c = [tag(i, j, k), tag(i + 1, j, k), tag(i + 1, j + 1, k), tag(i, j + 1, k)]
                    cells.append((5, vol, c + [t + (n + 1) ** 2 for t in c]))
        for j in range(n):
            for i in range(n):  # faces oriented outward
                cells.append((3, bottom, [tag(i, j, 0), tag(i, j + 1, 0), tag(i + 1, j + 1, 0), tag(i + 1, j, 0)]))
                cells.append((3, top, [tag(i, j, layers), tag(i + 1, j, layers), tag(i + 1, j + 1, layers),
                                       tag(i, j + 1, layers)]))
        for k in range(layers):
            for j in range(n):
                cells.append((3, 7, [tag(0, j, k), tag(0, j, k + 1), tag(0, j + 1, k + 1), tag(0, j + 1, k)]))
            for i in range(n):
                cells.append((3, 8, [tag(i, 0, k), tag(i + 1, 0, k), tag(i + 1, 0, k + 1), tag(i, 0, k + 1)]))

    block(a.nb, a.layers[0], -a.heights[0], a.heights[0], 1, 3, 4)
    block(a.nh, a.layers[1], 0.0, a.heights[1], 2, 5, 6, a.merged is not None)
    with open(a.out, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n%d\n" % len(names))
        for t, (d, name) in names.items():
            f.write(f'{d} {t} "{name}"\n')
        f.write("$EndPhysicalNames\n$Nodes\n%d\n" % len(nodes))
        f.writelines(f"{i + 1} {x:.15g} {y:.15g} {z:.15g}\n" for i, (x, y, z) in enumerate(nodes))
        f.write("$EndNodes\n$Elements\n%d\n" % len(cells))
        f.writelines(f"{i + 1} {t} 2 {phys} {phys} " + " ".join(map(str, c)) + "\n"
                     for i, (t, phys, c) in enumerate(cells))
        f.write("$EndElements\n")


if __name__ == "__main__":
    main()
