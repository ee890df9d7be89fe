#!/usr/bin/env python3
"""Writes the PENTA6/PENTA15/PYRAM5/PYRAM13 variants of the 3D LAC patch test (the problem, the
command file and the references of generate.py): the same blocks LOW = [0,1]^2 x [0,1] under
UP = [0,1]^2 x [1,2], NLOW and NUP cells along x and y (non-matching), 2 along z, but meshed here by
hand as Gmsh writes them (MSH 2.2, Gmsh node orderings, quadratic nodes by edge) because Gmsh
4.8 gives no prisms or pyramids for these boxes:
  PENTA (axis z): every box cell cut in two prisms by its (x, y) diagonal; their triangles lie on
    z = 1;
  PENTA (axis y): cut by the (x, z) diagonal; the faces on z = 1 are the prisms' quadrangles;
  PYRAM: every box cell cut in three pyramids whose apex is one of its corners (the corner
    (i + a, j + a, k + b) mod 2, a conforming tiling: neighbours agree on the split of the faces
    they share): b chosen so that the faces on z = 1 are triangles (apex on the face, 'tri') or
    the pyramids' quadrangular bases ('quad');
  HEXA: the box cells.
Node numberings as real meshes have them: every cell's numbering starts at a vertex that turns
with the cell's index (any rotation that keeps the orientation), and every boundary face is
written facing out of its block or into it, alternately (Gmsh's surfaces have either
orientation). Exact solution as generate.py's: SIZZ = -25, LAGS_C = PRES = -25, JEU = 0.
"""
import os

import generate

HERE = os.path.dirname(os.path.abspath(__file__))

# (case, LOW kind, UP kind, NLOW, NUP, quadratic, slave, DECOUPE_HEXA, TYPE_APPA, ALGO_RESO_GEOM)
CASES = [
    ("p6_p6", "pz", "pz", 3, 2, False, "UP", "PYRA", "RAPIDE", "NEWTON"),
    ("p6y_h8_swap", "py", "hexa", 3, 2, False, "LOW", "PYRA", "RAPIDE", "NEWTON"),
    ("py5_py5", "pyquad", "pytri", 3, 2, False, "UP", "PYRA", "RAPIDE", "NEWTON"),
    ("py5q_p6_swap", "pyquad", "pz", 2, 3, False, "LOW", "PYRA", "ROBUSTE", "POINT_FIXE"),
    ("p15_p15", "pz", "pz", 3, 2, True, "UP", "PYRA", "RAPIDE", "NEWTON"),
    ("p15y_py13_swap", "py", "pytri", 2, 3, True, "LOW", "PYRA", "RAPIDE", "NEWTON"),
    ("py13_h20_hexa", "hexa", "pytri", 3, 2, True, "UP", "HEXA", "RAPIDE", "NEWTON"),
    ("py13q_p15_swap", "pyquad", "pz", 2, 3, True, "LOW", "PYRA", "RAPIDE", "NEWTON"),
]
KIND_NAMES = {"pz": "PENTA (axis z)", "py": "PENTA (axis y)", "pyquad": "PYRAM (bases on z = 1)",
              "pytri": "PYRAM (triangles on z = 1)", "hexa": "HEXA"}

# Gmsh types and the vertex pairs of their quadratic nodes, in Gmsh's order.
LINEAR = {"tet": 4, "prism": 6, "pyr": 7, "hex": 5, "tri": 2, "quad": 3}
QUADRATIC = {"tet": 11, "prism": 18, "pyr": 19, "hex": 17, "tri": 9, "quad": 16}
EDGES = {
    "prism": [(0, 1), (0, 2), (0, 3), (1, 2), (1, 4), (2, 5), (3, 4), (3, 5), (4, 5)],
    "pyr": [(0, 1), (0, 3), (0, 4), (1, 2), (1, 4), (2, 3), (2, 4), (3, 4)],
    "hex": [(0, 1), (0, 3), (0, 4), (1, 2), (1, 5), (2, 3), (2, 6), (3, 7), (4, 5), (4, 7), (5, 6), (6, 7)],
    "tri": [(0, 1), (1, 2), (2, 0)],
    "quad": [(0, 1), (1, 2), (2, 3), (3, 0)],
}
# Faces of the volume cells (vertex indices), any orientation (fixed below).
FACES = {
    "prism": [(0, 1, 2), (3, 4, 5), (0, 1, 4, 3), (1, 2, 5, 4), (2, 0, 3, 5)],
    "pyr": [(0, 1, 2, 3), (0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)],
    "hex": [(0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)],
}


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def centroid(pts):
    return [sum(p[i] for p in pts) / len(pts) for i in range(3)]


class Block:
    """The linear cells of one block, on a grid of points (i, j, k)."""
    # offset: turns the pyramids' apexes of UP from those of LOW (x and y)

    def __init__(self, mesh, z0, n, kind, offset):
        self.mesh, self.cells = mesh, []
        nz = 2
        node = lambda i, j, k: mesh.vertex((i / n, j / n, z0 + k / nz))
        for k in range(nz):
            for j in range(n):
                for i in range(n):
                    c = {(a, b, d): node(i + a, j + b, k + d) for a in (0, 1) for b in (0, 1) for d in (0, 1)}
                    self.split(c, kind, (i, j, k), offset)

    def split(self, c, kind, ijk, offset):
        i, j, k = ijk
        if kind == "hexa":
            self.add("hex", [c[0, 0, 0], c[1, 0, 0], c[1, 1, 0], c[0, 1, 0],
                             c[0, 0, 1], c[1, 0, 1], c[1, 1, 1], c[0, 1, 1]])
        elif kind == "pz":
            for tri in (((0, 0), (1, 0), (1, 1)), ((0, 0), (1, 1), (0, 1))):
                self.add("prism", [c[a, b, 0] for a, b in tri] + [c[a, b, 1] for a, b in tri])
        elif kind == "py":
            for tri in (((0, 0), (1, 0), (1, 1)), ((0, 0), (1, 1), (0, 1))):
                self.add("prism", [c[a, 0, d] for a, d in tri] + [c[a, 1, d] for a, d in tri])
        else:
            # the apex on z = 1 (LOW: layer k = 1, its top; UP: k = 0, its bottom) for 'tri'
            apex = ((i + offset) % 2, (j + offset) % 2, (k + (kind == "pyquad")) % 2)
            for axis in range(3):
                # the face opposite the apex along `axis`, its corners in turning order
                u, v = [x for x in range(3) if x != axis]
                ring = []
                for a, b in ((0, 0), (1, 0), (1, 1), (0, 1)):
                    p = [0, 0, 0]
                    p[axis], p[u], p[v] = 1 - apex[axis], a, b
                    ring.append(tuple(p))
                self.add("pyr", [c[p] for p in ring] + [c[apex]])

    def add(self, kind, nodes):
        self.cells.append((kind, self.mesh.oriented(kind, nodes)))


class Mesh:
    def __init__(self):
        self.points, self.index = [], {}

    def vertex(self, x):
        key = tuple(round(v, 12) for v in x)
        if key not in self.index:
            self.points.append(list(x))
            self.index[key] = len(self.points)
        return self.index[key]

    def fresh(self, x):  # a node of its own (the blocks' nodes on z = 1 are not shared)
        self.points.append(list(x))
        return len(self.points)

    def x(self, n):
        return self.points[n - 1]

    def oriented(self, kind, nodes):
        x = [self.x(n) for n in nodes]
        if kind == "prism":
            vol = dot(cross(sub(x[1], x[0]), sub(x[2], x[0])), sub(centroid(x[3:]), centroid(x[:3])))
            return nodes if vol > 0 else [nodes[i] for i in (0, 2, 1, 3, 5, 4)]
        if kind == "pyr":
            vol = dot(cross(sub(x[1], x[0]), sub(x[2], x[0])), sub(x[4], centroid(x[:4])))
            return nodes if vol > 0 else [nodes[i] for i in (0, 3, 2, 1, 4)]
        vol = dot(cross(sub(x[1], x[0]), sub(x[3], x[0])), sub(x[4], x[0]))
        assert vol > 0
        return nodes


def rotated(kind, nodes, r):
    """The cell's numbering started at another vertex (same orientation)."""
    if kind == "prism":
        perms = [(0, 1, 2, 3, 4, 5), (1, 2, 0, 4, 5, 3), (5, 4, 3, 2, 1, 0)]
    elif kind == "pyr":
        perms = [(0, 1, 2, 3, 4), (1, 2, 3, 0, 4), (2, 3, 0, 1, 4), (3, 0, 1, 2, 4)]
    elif kind == "hex":
        perms = [(0, 1, 2, 3, 4, 5, 6, 7), (1, 2, 3, 0, 5, 6, 7, 4), (7, 6, 5, 4, 3, 2, 1, 0)]
    else:
        perms = [tuple(range(len(nodes)))]
    return [nodes[i] for i in perms[r % len(perms)]]


def write(path, low, up, quadratic, mesh):
    mids = {}

    def mid(a, b):
        key = (min(a, b), max(a, b))
        if key not in mids:
            mids[key] = mesh.fresh(centroid([mesh.x(a), mesh.x(b)]))
        return mids[key]

    def full(kind, nodes):
        return nodes + [mid(nodes[a], nodes[b]) for a, b in EDGES[kind]] if quadratic else nodes

    types = QUADRATIC if quadratic else LINEAR
    groups = ["LOW_X0", "LOW_Y0", "BAS", "LOW_TOP", "UP_X0", "UP_Y0", "UP_BOT", "UP_TOP", "LOW", "UP"]
    elements = []
    for name, block in (("LOW", low), ("UP", up)):
        use = {}
        for kind, nodes in block.cells:
            for f in FACES[kind]:
                use.setdefault(tuple(sorted(nodes[i] for i in f)), []).append((kind, nodes, f))
        assert all(len(v) <= 2 for v in use.values())
        faces = [v[0] for v in use.values() if len(v) == 1]
        area = 0.0
        for kind, nodes, f in faces:  # a conforming tiling of the box: its boundary is the box's
            x = [mesh.x(nodes[i]) for i in f]
            for t in range(1, len(x) - 1):
                area += 0.5 * dot(cross(sub(x[t], x[0]), sub(x[t + 1], x[0])),
                                  cross(sub(x[t], x[0]), sub(x[t + 1], x[0]))) ** 0.5
        assert abs(area - 6.0) < 1e-12, (name, area)
        faces.sort(key=lambda v: tuple(sorted(v[1][i] for i in v[2])))
        for count, (kind, nodes, f) in enumerate(faces):
            ring = [nodes[i] for i in f]
            x = [mesh.x(n) for n in ring]
            outward = dot(cross(sub(x[1], x[0]), sub(x[2], x[0])),
                          sub(centroid(x), centroid([mesh.x(n) for n in nodes])))
            if (outward > 0) != (count % 2 == 0):
                ring = [ring[0]] + ring[:0:-1]
            c = centroid(x)
            group = (name + "_X0" if abs(c[0]) < 1e-12 else name + "_Y0" if abs(c[1]) < 1e-12
                     else "BAS" if name == "LOW" and abs(c[2]) < 1e-12 else "LOW_TOP" if name == "LOW" and abs(c[2] - 1) < 1e-12
                     else "UP_BOT" if name == "UP" and abs(c[2] - 1) < 1e-12 else "UP_TOP" if name == "UP" and abs(c[2] - 2) < 1e-12
                     else None)
            if group is not None:
                fk = "tri" if len(ring) == 3 else "quad"
                elements.append((types[fk], groups.index(group) + 1, full(fk, ring)))
        for count, (kind, nodes) in enumerate(block.cells):
            elements.append((types[kind], groups.index(name) + 1, full(kind, rotated(kind, nodes, count))))
    with open(path, "w") as out:
        out.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n%d\n" % len(groups))
        for g, name in enumerate(groups):
            out.write('%d %d "%s"\n' % (3 if name in ("LOW", "UP") else 2, g + 1, name))
        out.write("$EndPhysicalNames\n$Nodes\n%d\n" % len(mesh.points))
        for n, x in enumerate(mesh.points):
            out.write("%d %r %r %r\n" % (n + 1, x[0], x[1], x[2]))
        out.write("$EndNodes\n$Elements\n%d\n" % len(elements))
        for e, (t, g, nodes) in enumerate(elements):
            out.write("%d %d 2 %d %d %s\n" % (e + 1, t, g, g, " ".join(map(str, nodes))))
        out.write("$EndElements\n")


def build(case):
    name, klow, kup, nlow, nup, quadratic = case[:6]
    low_mesh = Mesh()
    low = Block(low_mesh, 0.0, nlow, klow, 0)
    # UP's nodes follow LOW's (its nodes on z = 1 are its own: the blocks are not joined)
    up_mesh = Mesh()
    up_mesh.points = low_mesh.points
    up = Block(up_mesh, 1.0, nup, kup, 1)
    write(os.path.join(HERE, "lac3d_" + name + ".msh"), low, up, quadratic, up_mesh)


def comm(case):
    name, klow, kup, nlow, nup, quadratic, slave, cut, appa, geom = case
    text = generate.comm((name, 1, 1, nlow, nup, 2 if quadratic else 1, slave, cut, appa, geom))
    lines = text.split("\n")
    lines[0] = ("# LAC patch test (ssnp170-like, 3D), written by generate_penta_pyram.py: LOW %s %s (%d x %d"
                % (KIND_NAMES[klow], "quadratic" if quadratic else "linear", nlow, nlow))
    lines[1] = ("# cells along the interface) under UP %s (%d x %d), slave %s, DECOUPE_HEXA='%s',"
                % (KIND_NAMES[kup], nup, nup, slave, cut))
    # the faces are written facing either way: the contact faces (VERI_NORM) and the loaded one (PRES_REP)
    # turned outward as a study does
    read = lines.index("M0 = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)")
    lines.insert(read + 1, "M0 = MODI_MAILLAGE(reuse=M0, MAILLAGE=M0, ORIE_PEAU=_F(GROUP_MA_PEAU=('LOW_TOP', 'UP_BOT', 'UP_TOP')))")
    return "\n".join(lines)


def main():
    for case in CASES:
        name = "lac3d_" + case[0]
        build(case)
        open(os.path.join(HERE, name + ".comm"), "w").write(comm(case))
        open(os.path.join(HERE, name + ".export"), "w").write(
            f"P testlist verification\nF comm {name}.comm D 1\nF msh {name}.msh D 20\n"
            f"F mess {name}.mess R 6\nF resu {name}.resu R 8\nF rmed {name}.rmed R 80\n")


if __name__ == "__main__":
    main()
