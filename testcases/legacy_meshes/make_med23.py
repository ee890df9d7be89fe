#!/usr/bin/python3
"""Writes the MED 2.3-layout test meshes of this folder and their ASTER (.mail) twins.

Older Salome versions (MED library 2.3.x) wrote this HDF5 layout, which the MED 4 library does
not read through its family calls. The layout (MED 2.3 documentation, med_outils.h names):

  /INFOS_GENERALES            attributes MAJ, MIN, REL (file version 2.3.x)
  /ENS_MAA/<mesh>             attributes DIM (mesh dimension), ESP (space dimension),
                              TYP (0: unstructured), DES (description, 200 characters)
    NOE/COO                   coordinates, not interlaced (all x, then all y, ...);
                              attributes NBR, REP (0: cartesian), NOM, UNI (16 characters/axis)
    NOE/FAM                   family number of each node (0: none)
    NOE/NOM                   optional node names, 16-character records
    MAI/<TYP>                 one group per cell type (SE2, TR3, QU8, HE8, ...):
      NOD                     connectivity, not interlaced (node 1 of every cell, node 2 ...),
                              1-based node numbers in MED order; attribute NBR (cell count)
      FAM                     family number of each cell (negative; 0: none)
      NOM                     optional cell names, 16-character records
    FAS/FAMILLE_ZERO          attribute NUM = 0
    FAS/NOEUD/<family>        attribute NUM > 0 (node families), NUM < 0 under ELEME (cell
    FAS/ELEME/<family>        families); GRO with attribute NBR and dataset NOM: the group
                              names, 80-character records; optional ATT (NBR, IDE, VAL, DES)
(MED 3 moved the families to /FAS/<mesh>.) Names are 1-character C strings (H5T_C_S1).

Every integer is a 32-bit int (med_int of MED 2.3). The .mail twin holds the same mesh in
code_aster's node order (aster node j = MED node PERM[j], code_aster's lrmtyp tables), nodes
N1.. and cells M1.. numbered as a MED reader numbers them (cell types by increasing MED
geometry number), so both files must read to identical meshes.

Usage: make_med23.py [output directory]   (default: this script's directory)
"""

import os
import sys

import numpy as np

try:
    import h5py
except ImportError:  # make_gibi.py uses the meshes only
    h5py = None

# MED geometry number, MED 2.3 dataset name, code_aster name, node count.
TYPES = {
    "PO1": (1, "POI1", 1),
    "SE2": (102, "SEG2", 2),
    "SE3": (103, "SEG3", 3),
    "TR3": (203, "TRIA3", 3),
    "QU4": (204, "QUAD4", 4),
    "TR6": (206, "TRIA6", 6),
    "QU8": (208, "QUAD8", 8),
    "TE4": (304, "TETRA4", 4),
    "PY5": (305, "PYRAM5", 5),
    "PE6": (306, "PENTA6", 6),
    "HE8": (308, "HEXA8", 8),
    "T10": (310, "TETRA10", 10),
    "P13": (313, "PYRAM13", 13),
    "P15": (315, "PENTA15", 15),
    "H20": (320, "HEXA20", 20),
}

# aster node j = MED node PERM[j] (volumes are oriented the other way in MED).
PERM = {
    "TE4": [0, 2, 1, 3],
    "T10": [0, 2, 1, 3, 6, 5, 4, 7, 9, 8],
    "PE6": [0, 2, 1, 3, 5, 4],
    "P15": [0, 2, 1, 3, 5, 4, 8, 7, 6, 12, 14, 13, 11, 10, 9],
    "PY5": [0, 3, 2, 1, 4],
    "P13": [0, 3, 2, 1, 4, 8, 7, 6, 5, 9, 12, 11, 10],
    "HE8": [0, 3, 2, 1, 4, 7, 6, 5],
    "H20": [0, 3, 2, 1, 4, 7, 6, 5, 11, 10, 9, 8, 16, 19, 18, 17, 15, 14, 13, 12],
}


class Mesh:
    """Nodes, cells (MED type, MED-ordered 1-based nodes, family) and families."""

    def __init__(self, name, dim):
        self.name, self.dim = name, dim
        self.nodes, self.node_fam, self.cells = [], [], []
        self.node_names, self.cell_names = [], []  # None: the default name N<i> / M<i>
        self.families = {}  # number -> (family name, [group names])

    def node(self, x, family=0, name=None):
        self.nodes.append(tuple(float(v) for v in x))
        self.node_fam.append(family)
        self.node_names.append(name)
        return len(self.nodes)

    def cell(self, typ, nodes, family=0, name=None):
        assert len(nodes) == TYPES[typ][2], typ
        self.cells.append((typ, list(nodes), family))
        self.cell_names.append(name)

    def family(self, number, groups):
        kind = "NOEUD" if number > 0 else "ELEME"
        self.families[number] = ("FAM_%s_%d" % (kind[0], abs(number)), groups)

    def ordered_cells(self):
        """Cells as a MED reader numbers them: by MED geometry number, file order within;
        (type, nodes, family, name or None)."""
        order = sorted(range(len(self.cells)), key=lambda i: TYPES[self.cells[i][0]][0])
        return [self.cells[i] + (self.cell_names[i],) for i in order]


def put_int_attr(obj, key, value):
    obj.attrs.create(key, np.int32(value), dtype=np.int32)


def put_str_attr(obj, key, text, width):
    """A null-terminated C string attribute of `width` characters, as MED writes them."""
    tid = h5py.h5t.C_S1.copy()
    tid.set_size(width + 1)
    tid.set_strpad(h5py.h5t.STR_NULLTERM)
    attr = h5py.h5a.create(obj.id, key.encode(), tid, h5py.h5s.create(h5py.h5s.SCALAR))
    attr.write(np.array(text.ljust(width)[:width].encode() + b"\0", dtype="S%d" % (width + 1)), mtype=tid)


def put_char_dataset(group, key, text):
    """A dataset of 1-character C strings (H5T_C_S1, null-terminated, size 1), as the MED
    library writes name records; the library reads them back without conversion."""
    tid = h5py.h5t.C_S1.copy()
    tid.set_size(1)
    tid.set_strpad(h5py.h5t.STR_NULLTERM)
    space = h5py.h5s.create_simple((len(text),))
    dset = h5py.h5d.create(group.id, key.encode(), tid, space)
    dset.write(h5py.h5s.ALL, h5py.h5s.ALL, np.frombuffer(text, dtype=np.uint8), mtype=tid)


def put_names(group, names):
    """NOM: 16-character names (MED 2.3), when the mesh names these entities."""
    if all(n is None for n in names):
        return
    put_char_dataset(group, "NOM", b"".join(n.encode().ljust(16) for n in names))
    put_int_attr(group["NOM"], "NBR", len(names))


def write_med23(path, mesh, release=5):
    with h5py.File(path, "w") as f:
        info = f.create_group("INFOS_GENERALES")
        for key, value in (("MAJ", 2), ("MIN", 3), ("REL", release)):
            put_int_attr(info, key, value)
        maa = f.create_group("ENS_MAA").create_group(mesh.name)
        put_int_attr(maa, "DIM", mesh.dim)
        put_int_attr(maa, "ESP", mesh.dim)
        put_int_attr(maa, "TYP", 0)
        put_str_attr(maa, "DES", "written by make_med23.py", 200)
        noe = maa.create_group("NOE")
        coords = np.array([x[: mesh.dim] for x in mesh.nodes], dtype=np.float64)
        coo = noe.create_dataset("COO", data=coords.T.ravel())
        put_int_attr(coo, "NBR", len(mesh.nodes))
        put_int_attr(coo, "REP", 0)
        put_str_attr(coo, "NOM", "".join(a.ljust(16) for a in "XYZ"[: mesh.dim]), 16 * mesh.dim)
        put_str_attr(coo, "UNI", " " * 16 * mesh.dim, 16 * mesh.dim)
        fam = noe.create_dataset("FAM", data=np.array(mesh.node_fam, dtype=np.int32))
        put_int_attr(fam, "NBR", len(mesh.nodes))
        put_names(noe, mesh.node_names)
        mai = maa.create_group("MAI")
        for typ in TYPES:
            cells = [c for c in mesh.ordered_cells() if c[0] == typ]
            if not cells:
                continue
            g = mai.create_group(typ)
            conn = np.array([c[1] for c in cells], dtype=np.int32)
            nod = g.create_dataset("NOD", data=conn.T.ravel())
            put_int_attr(nod, "NBR", len(cells))
            fam = g.create_dataset("FAM", data=np.array([c[2] for c in cells], dtype=np.int32))
            put_int_attr(fam, "NBR", len(cells))
            put_names(g, [c[3] for c in cells])
        fas = maa.create_group("FAS")
        put_int_attr(fas.create_group("FAMILLE_ZERO"), "NUM", 0)
        for number, (fname, groups) in sorted(mesh.families.items()):
            kind = "NOEUD" if number > 0 else "ELEME"
            g = fas.require_group(kind).create_group(fname)
            put_int_attr(g, "NUM", number)
            gro = g.create_group("GRO")
            put_int_attr(gro, "NBR", len(groups))
            records = b"".join(n.encode().ljust(80) for n in groups)
            put_char_dataset(gro, "NOM", records)
            if number == 2:  # a family attribute (MED 2.3 only): must not disturb the groups
                att = g.create_group("ATT")
                put_int_attr(att, "NBR", 1)
                att.create_dataset("IDE", data=np.array([7], dtype=np.int32))
                att.create_dataset("VAL", data=np.array([42], dtype=np.int32))
                put_char_dataset(att, "DES", b"attribute of make_med23.py".ljust(200))


def write_mail(path, mesh):
    def node_name(i):
        return mesh.node_names[i] or "N%d" % (i + 1)

    out = ["TITRE", " MED 2.3 test mesh %s (make_med23.py)" % mesh.name, "FINSF", "%"]
    out.append("COOR_%dD" % mesh.dim)
    for i, x in enumerate(mesh.nodes):
        out.append("%s %s" % (node_name(i), " ".join(repr(v) for v in x[: mesh.dim])))
    out += ["FINSF", "%"]
    cells = mesh.ordered_cells()
    cell_groups, node_groups = {}, {}
    previous = None
    for i, (typ, nodes, family, name) in enumerate(cells):
        if typ != previous:
            if previous is not None:
                out += ["FINSF", "%"]
            out.append(TYPES[typ][1])
            previous = typ
        perm = PERM.get(typ, range(len(nodes)))
        out.append("%s %s" % (name or "M%d" % (i + 1), " ".join(node_name(nodes[p] - 1) for p in perm)))
        for g in mesh.families.get(family, ("", []))[1] if family else []:
            cell_groups.setdefault(g, []).append(name or "M%d" % (i + 1))
    out += ["FINSF", "%"]
    for i, family in enumerate(mesh.node_fam):
        for g in mesh.families.get(family, ("", []))[1] if family else []:
            node_groups.setdefault(g, []).append(node_name(i))
    for block, groups in (("GROUP_MA", cell_groups), ("GROUP_NO", node_groups)):
        for g in sorted(groups):
            out += [block, g] + ["  " + m for m in groups[g]] + ["FINSF", "%"]
    out.append("FIN")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def plate_2d(quadratic):
    """[0,2]x[0,2]: two quadrangles (x < 1) and four triangles (x > 1), edges on y = 0 and
    y = 2. Cell groups SURF+GAUCHE (quadrangles), SURF+DROITE (triangles), BAS, HAUT; node
    groups N_BAS (y = 0), N_COIN (the origin, whose family carries both) and N_HAUT (y = 2)."""
    m = Mesh("PLAQ2D", 2)
    step = 0.5 if quadratic else 1.0
    n = int(round(2 / step)) + 1
    ids = {}
    for j in range(n):
        for i in range(n):
            if quadratic and i == 1 and j % 2 == 1:
                continue  # the centre of a QUAD8 is no node of the mesh
            fam = 2 if (i, j) == (0, 0) else (1 if j == 0 else (3 if j == n - 1 else 0))
            ids[i, j] = m.node((i * step, j * step), fam)
    k = 2 if quadratic else 1  # grid steps per cell side

    def p(i, j):
        return ids[i * k, j * k] if not quadratic else ids[i, j]

    m.family(1, ["N_BAS"])
    m.family(2, ["N_BAS", "N_COIN"])
    m.family(3, ["N_HAUT"])
    m.family(-1, ["SURF", "GAUCHE"])
    m.family(-2, ["SURF", "DROITE"])
    m.family(-3, ["BAS"])
    m.family(-4, ["HAUT"])
    for j in range(2):
        if quadratic:
            a, b = 2 * 0, 2 * j
            q = [ids[a, b], ids[a + 2, b], ids[a + 2, b + 2], ids[a, b + 2],
                 ids[a + 1, b], ids[a + 2, b + 1], ids[a + 1, b + 2], ids[a, b + 1]]
            m.cell("QU8", q, -1)
            a = 2
            t1 = [ids[a, b], ids[a + 2, b], ids[a + 2, b + 2],
                  ids[a + 1, b], ids[a + 2, b + 1], ids[a + 1, b + 1]]
            t2 = [ids[a, b], ids[a + 2, b + 2], ids[a, b + 2],
                  ids[a + 1, b + 1], ids[a + 1, b + 2], ids[a, b + 1]]
            m.cell("TR6", t1, -2)
            m.cell("TR6", t2, -2)
        else:
            m.cell("QU4", [p(0, j), p(1, j), p(1, j + 1), p(0, j + 1)], -1)
            m.cell("TR3", [p(1, j), p(2, j), p(2, j + 1)], -2)
            m.cell("TR3", [p(1, j), p(2, j + 1), p(1, j + 1)], -2)
    for i in range(2):
        if quadratic:
            m.cell("SE3", [ids[2 * i, 0], ids[2 * i + 2, 0], ids[2 * i + 1, 0]], -3)
            m.cell("SE3", [ids[2 * i + 2, 4], ids[2 * i, 4], ids[2 * i + 1, 4]], -4)
        else:
            m.cell("SE2", [p(i, 0), p(i + 1, 0)], -3)
            m.cell("SE2", [p(i + 1, 2), p(i, 2)], -4)
    return m


def block_3d():
    """Two unit HEXA8 stacked along z on [0,1]x[0,1]x[0,2], QUAD4 faces on z = 0 (BAS) and z = 2
    (HAUT), both faces oriented outward; cell groups VOLU, BAS, HAUT, SURF_EXT (a family with
    BAS and SURF_EXT), node groups N_BAS, N_O (origin), N_X (x-axis node, y = z = 0), N_HAUT.
    Nodes and cells are named (NO1..., HEXA1, HEXA2, FACE_BAS, FACE_HAU: NOM datasets in MED)."""
    m = Mesh("BLOC3D", 3)
    ids = {}
    for k in range(3):
        for j in range(2):
            for i in range(2):
                if k == 0:
                    fam = {(0, 0): 2, (1, 0): 3}.get((i, j), 1)
                else:
                    fam = 4 if k == 2 else 0
                ids[i, j, k] = m.node((i, j, k), fam, "NO%d" % (len(m.nodes) + 1))
    m.family(1, ["N_BAS"])
    m.family(2, ["N_BAS", "N_O"])
    m.family(3, ["N_BAS", "N_X"])
    m.family(4, ["N_HAUT"])
    m.family(-1, ["VOLU"])
    m.family(-2, ["BAS", "SURF_EXT"])
    m.family(-3, ["HAUT", "SURF_EXT"])
    for k in range(2):
        # MED HE8: bottom face clockwise seen from outside... MED orders the bottom face so
        # that its normal points into the cell (opposite to code_aster), see PERM.
        aster = [ids[0, 0, k], ids[1, 0, k], ids[1, 1, k], ids[0, 1, k],
                 ids[0, 0, k + 1], ids[1, 0, k + 1], ids[1, 1, k + 1], ids[0, 1, k + 1]]
        med = [0] * 8
        for j, pj in enumerate(PERM["HE8"]):
            med[pj] = aster[j]
        m.cell("HE8", med, -1, "HEXA%d" % (k + 1))
    m.cell("QU4", [ids[0, 0, 0], ids[0, 1, 0], ids[1, 1, 0], ids[1, 0, 0]], -2, "FACE_BAS")
    m.cell("QU4", [ids[0, 0, 2], ids[1, 0, 2], ids[1, 1, 2], ids[0, 1, 2]], -3, "FACE_HAU")
    return m


def zoo(types=tuple(TYPES)):
    """One cell of every type in `types` on its own nodes (reading test only, not a geometry);
    each cell type in its own family with groups ALL and the type name; node group FIRST (the
    nodes of the first cell)."""
    m = Mesh("ZOO", 3)
    for n, typ in enumerate(types):
        count = TYPES[typ][2]
        nodes = [m.node((3.0 * n + 0.1 * a, 0.2 * (a % 3), 0.3 * (a % 5)), 1 if n == 0 else 0)
                 for a in range(count)]
        m.family(-(n + 1), ["ALL", TYPES[typ][1]])
        m.cell(typ, nodes, -(n + 1))
        if typ in ("SE2", "HE8"):  # two cells of a type: the not-interlaced connectivity
            nodes = [m.node((3.0 * n + 0.1 * a, 1.0 + 0.2 * (a % 3), 0.3 * (a % 5)))
                     for a in range(count)]
            m.cell(typ, nodes, -(n + 1))
    m.family(1, ["FIRST"])
    return m


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    for stem, mesh in (("med23_plate_lin", plate_2d(False)), ("med23_plate_quad", plate_2d(True)),
                       ("med23_block", block_3d()), ("med23_zoo", zoo())):
        write_med23(os.path.join(out, stem + ".med"), mesh)
        write_mail(os.path.join(out, stem + ".mail"), mesh)


if __name__ == "__main__":
    main()
