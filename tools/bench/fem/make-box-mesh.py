#!/usr/bin/python3
"""Structured meshes of the unit cube / unit square for the performance runs of MECA_STATIQUE
(doc/bench/fem-performance.md), written in Gmsh's ASCII format 2.2 (LIRE_MAILLAGE FORMAT='GMSH').

    make-box-mesh.py CASE N OUT.msh
      CASE  hexa8    N^3 hexahedra                      3 (N+1)^3 DOFs
            tetra10  N^3 cubes cut into 6 tetrahedra    3 (2N+1)^3 DOFs
            quad4    N^2 quadrangles (plane strain)     2 (N+1)^2 DOFs
            quad8    N^2 eight-node quadrangles         2 ((2N+1)^2 - N^2) DOFs

Groups (physical tags): 1 VOLUME (the cells), 2 XMIN (skin cells on x = 0), 3 XMAX (x = 1).
"""

import itertools
import sys


def write(path, nodes, blocks):
    """nodes: list of coordinate triples; blocks: list of (gmsh type, physical tag, [node lists])."""
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n")
        f.write("$PhysicalNames\n3\n")
        dim = 3 if blocks[0][0] in (5, 11) else 2
        f.write(f'{dim} 1 "VOLUME"\n{dim - 1} 2 "XMIN"\n{dim - 1} 3 "XMAX"\n$EndPhysicalNames\n')
        f.write(f"$Nodes\n{len(nodes)}\n")
        f.write("".join(f"{i + 1} {x:.12g} {y:.12g} {z:.12g}\n" for i, (x, y, z) in enumerate(nodes)))
        f.write("$EndNodes\n")
        count = sum(len(cells) for _, _, cells in blocks)
        f.write(f"$Elements\n{count}\n")
        number = 0
        out = []
        for gtype, tag, cells in blocks:
            for cell in cells:
                number += 1
                out.append(f"{number} {gtype} 2 {tag} {tag} " + " ".join(str(n + 1) for n in cell) + "\n")
        f.write("".join(out))
        f.write("$EndElements\n")


def hexa8(n):
    m = n + 1
    idx = lambda i, j, k: (k * m + j) * m + i
    nodes = [(i / n, j / n, k / n) for k in range(m) for j in range(m) for i in range(m)]
    cells = []
    for k, j, i in itertools.product(range(n), repeat=3):
        cells.append([idx(i, j, k), idx(i + 1, j, k), idx(i + 1, j + 1, k), idx(i, j + 1, k),
                      idx(i, j, k + 1), idx(i + 1, j, k + 1), idx(i + 1, j + 1, k + 1), idx(i, j + 1, k + 1)])
    xmin = [[idx(0, j, k), idx(0, j, k + 1), idx(0, j + 1, k + 1), idx(0, j + 1, k)]
            for k in range(n) for j in range(n)]
    xmax = [[idx(n, j, k), idx(n, j + 1, k), idx(n, j + 1, k + 1), idx(n, j, k + 1)]
            for k in range(n) for j in range(n)]
    return nodes, [(5, 1, cells), (3, 2, xmin), (3, 3, xmax)]


def kuhn_tetrahedra():
    """The 6 tetrahedra of the unit cube sharing the diagonal (0,0,0)-(1,1,1), positively oriented,
    as corner offsets."""
    tets = []
    for p in itertools.permutations(range(3)):
        a = [0, 0, 0]
        path = [tuple(a)]
        for axis in p:
            a[axis] = 1
            path.append(tuple(a))
        v = [[path[q][c] - path[0][c] for c in range(3)] for q in (1, 2, 3)]
        det = (v[0][0] * (v[1][1] * v[2][2] - v[1][2] * v[2][1]) - v[0][1] * (v[1][0] * v[2][2] - v[1][2] * v[2][0])
               + v[0][2] * (v[1][0] * v[2][1] - v[1][1] * v[2][0]))
        if det < 0:
            path[1], path[2] = path[2], path[1]
        tets.append(path)
    return tets


def tetra10(n):
    m = 2 * n + 1  # the grid of vertices and mid-edge nodes
    idx = lambda i, j, k: (k * m + j) * m + i
    nodes = [(i / (2 * n), j / (2 * n), k / (2 * n)) for k in range(m) for j in range(m) for i in range(m)]
    # Gmsh TETRA10: vertices, then edges 01, 12, 20, 30, 32, 31
    edges = [(0, 1), (1, 2), (2, 0), (3, 0), (3, 2), (3, 1)]
    cells, xmin, xmax = [], [], []
    templates = kuhn_tetrahedra()
    for k, j, i in itertools.product(range(n), repeat=3):
        for t in templates:
            v = [(2 * (i + a), 2 * (j + b), 2 * (k + c)) for a, b, c in t]
            mids = [tuple((v[p][d] + v[q][d]) // 2 for d in range(3)) for p, q in edges]
            cells.append([idx(*x) for x in v + mids])
            for face in ((0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)):
                for x0, group in ((0, xmin), (2 * n, xmax)):
                    if all(v[q][0] == x0 for q in face):
                        a, b, c = (v[q] for q in face)
                        mid = lambda p, q: tuple((p[d] + q[d]) // 2 for d in range(3))
                        group.append([idx(*x) for x in (a, b, c, mid(a, b), mid(b, c), mid(c, a))])
    return nodes, [(11, 1, cells), (9, 2, xmin), (9, 3, xmax)]


def quad(n, quadratic):
    if not quadratic:
        m = n + 1
        idx = lambda i, j: j * m + i
        nodes = [(i / n, j / n, 0.0) for j in range(m) for i in range(m)]
        cells = [[idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)] for j in range(n) for i in range(n)]
        xmin = [[idx(0, j + 1), idx(0, j)] for j in range(n)]
        xmax = [[idx(n, j), idx(n, j + 1)] for j in range(n)]
        return nodes, [(3, 1, cells), (1, 2, xmin), (1, 3, xmax)]
    m = 2 * n + 1  # no node at the cell centres
    number = {}
    nodes = []
    for j in range(m):
        for i in range(m):
            if i % 2 == 1 and j % 2 == 1:
                continue
            number[(i, j)] = len(nodes)
            nodes.append((i / (2 * n), j / (2 * n), 0.0))
    idx = lambda i, j: number[(i, j)]
    cells = []
    for j in range(n):
        for i in range(n):
            a, b = 2 * i, 2 * j
            cells.append([idx(a, b), idx(a + 2, b), idx(a + 2, b + 2), idx(a, b + 2),
                          idx(a + 1, b), idx(a + 2, b + 1), idx(a + 1, b + 2), idx(a, b + 1)])
    xmin = [[idx(0, 2 * j + 2), idx(0, 2 * j), idx(0, 2 * j + 1)] for j in range(n)]
    xmax = [[idx(2 * n, 2 * j), idx(2 * n, 2 * j + 2), idx(2 * n, 2 * j + 1)] for j in range(n)]
    return nodes, [(16, 1, cells), (8, 2, xmin), (8, 3, xmax)]


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    case, n, path = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    if case == "hexa8":
        nodes, blocks = hexa8(n)
    elif case == "tetra10":
        nodes, blocks = tetra10(n)
    elif case in ("quad4", "quad8"):
        nodes, blocks = quad(n, case == "quad8")
    else:
        sys.exit(f"unknown case {case}")
    write(path, nodes, blocks)


if __name__ == "__main__":
    main()
