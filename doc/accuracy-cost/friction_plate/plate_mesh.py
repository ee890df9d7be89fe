#!/usr/bin/env python3
"""Mesh of the friction-plate sweep (doc/accuracy-cost/friction_plate/README.md), Gmsh 2.2 ASCII:
the model of testcases/friction_plate with square cells of side H. Plate 0 <= x <= 40,
0 <= y <= 10 (NX = 40/H by NY = 10/H QUAD4), a rigid base below it (one row of QUAD4, its own
nodes, coincident with the plate's bottom ones). Plate node (i, j) is N<1 + i + (NX + 1) j>: the
command file ties the nodes of x = 0 and x = 40 row by row with these numbers.
Groups: PLAQUE, SOL; PLAQUE_BAS (slave), PLAQUE_HAUT (driven), SOL_HAUT (master); COIN (POI1,
the bottom-right plate node, the periodic copy of the bottom-left one).
Usage: /usr/bin/python3 plate_mesh.py H OUT.msh"""
import sys

L, HEIGHT, HB = 40.0, 10.0, 5.0


def mesh(h):
    nx, ny = round(L / h), round(HEIGHT / h)
    nodes = [(L * i / nx, HEIGHT * j / ny) for j in range(ny + 1) for i in range(nx + 1)]
    base0 = len(nodes)
    nodes += [(L * i / nx, -HB + HB * j) for j in range(2) for i in range(nx + 1)]
    plate = lambda i, j: 1 + i + (nx + 1) * j
    base = lambda i, j: base0 + 1 + i + (nx + 1) * j
    names = {"PLAQUE": (2, 1), "SOL": (2, 2), "PLAQUE_BAS": (1, 3), "PLAQUE_HAUT": (1, 4), "SOL_HAUT": (1, 5),
             "COIN": (0, 6)}
    cells = [(15, 6, [plate(nx, 0)])]
    for i in range(nx):
        cells += [(1, 3, [plate(i, 0), plate(i + 1, 0)]), (1, 4, [plate(i + 1, ny), plate(i, ny)]),
                  (1, 5, [base(i + 1, 1), base(i, 1)])]
    cells += [(3, 1, [plate(i, j), plate(i + 1, j), plate(i + 1, j + 1), plate(i, j + 1)])
              for j in range(ny) for i in range(nx)]
    cells += [(3, 2, [base(i, 0), base(i + 1, 0), base(i + 1, 1), base(i, 1)]) for i in range(nx)]
    out = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$PhysicalNames", str(len(names))]
    out += [f'{dim} {tag} "{name}"' for name, (dim, tag) in names.items()]
    out += ["$EndPhysicalNames", "$Nodes", str(len(nodes))]
    out += [f"{k + 1} {x!r} {y!r} 0" for k, (x, y) in enumerate(nodes)]
    out += ["$EndNodes", "$Elements", str(len(cells))]
    out += [f"{k + 1} {t} 2 {p} {p} " + " ".join(map(str, ns)) for k, (t, p, ns) in enumerate(cells)]
    return "\n".join(out + ["$EndElements", ""])


if __name__ == "__main__":
    with open(sys.argv[2], "w") as f:
        f.write(mesh(float(sys.argv[1])))
