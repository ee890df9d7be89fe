#!/usr/bin/env python3
"""Mesh of the friction-ring sweep (friction_ring_axis.sweep), Gmsh 2.2 ASCII written by hand: the
AXIS meridian section of testcases/friction_ring_axis (its make_mesh.py, same groups) with cells of
size H: ring a = 1 <= r <= b = 3, 0 <= z <= 1 in (2 / H) x (1 / H) QUAD4, on a rigid base
0.5 <= r <= 3.5, -0.5 <= z <= 0 (one QUAD4) whose top edge is the master surface.
Groups: ANNEAU, SOL; ANNEAU_BAS (slave), ANNEAU_HAUT (pressed), ANNEAU_INT (r = a, driven), SOL_HAUT
(master); COIN (POI1, the ring's node (a, 0)).
Usage: /usr/bin/python3 ring_mesh.py H OUT"""
import sys

A, B, HEIGHT = 1.0, 3.0, 1.0


def main(size, path):
    nr, nz = round((B - A) / size), round(HEIGHT / size)
    nodes = [(A + (B - A) * i / nr, HEIGHT * j / nz) for j in range(nz + 1) for i in range(nr + 1)]
    base0 = len(nodes)
    nodes += [(0.5, -0.5), (3.5, -0.5), (3.5, 0.0), (0.5, 0.0)]

    def ring(i, j):
        return 1 + i + (nr + 1) * j

    def base(c):
        return base0 + 1 + c

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
    with open(path, "w") as f:
        f.write("\n".join(out))


if __name__ == "__main__":
    main(float(sys.argv[1]), sys.argv[2])
