#!/usr/bin/python3
"""Writes the GIBI (Cast3M SAUVER FORMATTE) test meshes of this folder, from the meshes of
make_med23.py: gibi_plate_lin, gibi_plate_quad, gibi_block and gibi_zoo (every Cast3M element
type stella reads), each with its ASTER twin gibi_*.mail: the mesh as code_aster's PRE_GIBI
makes it (every point a node N<number>, every element a cell, named mesh objects GROUP_MA,
named points GROUP_NO of one node). Node groups of several nodes of make_med23.py's meshes
become named objects of POI1 elements (GROUP_MA), as a Cast3M user would save them.

Format (Cast3M's ASCII save file, as LIRE_MAILLAGE(FORMAT='GIBI') reads it):
  ' ENREGISTREMENT DE TYPE   4' + ' NIVEAU  15 NIVEAU ERREUR   0 DIMENSION   d' + density line
  ' ENREGISTREMENT DE TYPE   7' + three lines of Cast3M options (not read)
  ' ENREGISTREMENT DE TYPE   2' + ' PILE NUMERO   p' 'NBRE OBJETS NOMMES' I8 'NBRE OBJETS' I8,
      names FORMAT(8(1X,A8)), their object indices FORMAT(10I8), then the objects:
      pile 1 (meshes): per object  type, parts, references, nodes/element, elements  (5I8), the
        part indices (compound objects, type 0), references, colours, connectivity (10I8);
      pile 32 (nodes): the count, then the coordinate entry of each node (10I8);
      pile 33 (coordinates): the count of reals, then x y (z) density per entry (1P,3E22.14).
  ' ENREGISTREMENT DE TYPE   5' + ' LABEL AUTOMATIQUE :   1'
Element types (Cast3M number, name): 1 POI1, 2 SEG2, 3 SEG3, 4 TRI3, 6 TRI6, 8 QUA4, 10 QUA8,
14 CUB8, 15 CU20, 16 PRI6, 17 PR15, 23 TET4, 24 TE10, 25 PYR5, 26 PY13. Quadratic elements
list their nodes corner, middle, corner, ... along the edges (faces: the bottom face, the
vertical edges' middles, the top face); TET4, PRI6, PYR5 and their quadratic forms are
numbered as in MED, CUB8/CU20 as in code_aster (facts of Cast3M's format as used by the
MED/Salome GIBI converter). GIBI_PERM gives, per type, aster node j = Cast3M node GIBI_PERM[j].

Each run of consecutive cells of one type and one family becomes an unnamed or named mesh
object; a group spread over several objects becomes a named compound object; a node group of
one node a named point of pile 32. Pile 32 maps node k to coordinate entry N + 1 - k (reversed), so
that the indirection is exercised.

Usage: make_gibi.py [output directory]   (default: this script's directory)
"""

import os
import sys

import make_med23 as meshes

GIBI = {  # MED 2.3 name -> Cast3M number, name
    "PO1": (1, "POI1"), "SE2": (2, "SEG2"), "SE3": (3, "SEG3"), "TR3": (4, "TRI3"),
    "TR6": (6, "TRI6"), "QU4": (8, "QUA4"), "QU8": (10, "QUA8"), "HE8": (14, "CUB8"),
    "H20": (15, "CU20"), "PE6": (16, "PRI6"), "P15": (17, "PR15"), "TE4": (23, "TET4"),
    "T10": (24, "TE10"), "PY5": (25, "PYR5"), "P13": (26, "PY13"),
}

GIBI_PERM = {
    "SE3": [0, 2, 1],
    "TR6": [0, 2, 4, 1, 3, 5],
    "QU8": [0, 2, 4, 6, 1, 3, 5, 7],
    "H20": [0, 2, 4, 6, 12, 14, 16, 18, 1, 3, 5, 7, 8, 9, 10, 11, 13, 15, 17, 19],
    "PE6": [0, 2, 1, 3, 5, 4],
    "P15": [0, 4, 2, 9, 13, 11, 5, 3, 1, 6, 7, 8, 14, 12, 10],
    "TE4": [0, 2, 1, 3],
    "T10": [0, 4, 2, 9, 5, 3, 1, 6, 8, 7],
    "PY5": [0, 3, 2, 1, 4],
    "P13": [0, 6, 4, 2, 12, 7, 5, 3, 1, 8, 11, 10, 9],
}


def gibi_nodes(typ, med_nodes):
    """Cast3M node list of a cell given in MED order."""
    n = len(med_nodes)
    aster = [med_nodes[p] for p in meshes.PERM.get(typ, range(n))]
    gibi = [0] * n
    for j, g in enumerate(GIBI_PERM.get(typ, range(n))):
        gibi[g] = aster[j]
    return gibi


def ints(values):
    values = list(values)
    return ["".join("%8d" % v for v in values[i:i + 10]) for i in range(0, len(values), 10)]


def names(values):
    values = list(values)
    return ["".join(" %-8s" % v for v in values[i:i + 8]) for i in range(0, len(values), 8)]


def reals(values):
    return ["".join("%22.14E" % v for v in values[i:i + 3]) for i in range(0, len(values), 3)]


def gibi_variant(mesh):
    """The mesh as code_aster reads it from GIBI: node groups of one node stay (named points);
    larger node groups become groups of POI1 cells (named mesh objects of points)."""
    m = meshes.Mesh(mesh.name, mesh.dim)
    node_groups = [mesh.families.get(f, ("", []))[1] if f else [] for f in mesh.node_fam]
    size = {}
    for groups in node_groups:
        for g in groups:
            size[g] = size.get(g, 0) + 1
    point_families, cell_families = {}, {}
    next_cell_family = min([0] + list(mesh.families)) - 1
    poi1 = []
    for x, groups in zip(mesh.nodes, node_groups):
        single = tuple(g for g in groups if size[g] == 1)
        multi = tuple(g for g in groups if size[g] > 1)
        if single and single not in point_families:
            point_families[single] = len(point_families) + 1
            m.family(point_families[single], list(single))
        node = m.node(x, point_families.get(single, 0))
        if multi:
            if multi not in cell_families:
                cell_families[multi] = next_cell_family
                m.family(next_cell_family, list(multi))
                next_cell_family -= 1
            poi1.append((node, cell_families[multi]))
    for number, family in mesh.families.items():
        if number < 0:
            m.families[number] = family
    for typ, nodes, family in mesh.cells:
        m.cell(typ, nodes, family)
    for node, family in poi1:
        m.cell("PO1", [node], family)
    return m


def objects_of(mesh):
    """(objects, named, points): objects as (type number, parts, nodes per element, elements);
    named maps a cell group to an object index (1-based), points a node group to its node."""
    objects, runs = [], []
    for typ, nodes, family, _ in mesh.ordered_cells():
        if runs and runs[-1][0] == typ and runs[-1][1] == family:
            runs[-1][2].append(gibi_nodes(typ, nodes))
        else:
            runs.append((typ, family, [gibi_nodes(typ, nodes)]))
    groups = {}
    for typ, family, cells in runs:
        objects.append((GIBI[typ][0], [], len(cells[0]), cells))
        for g in (mesh.families.get(family, ("", []))[1] if family else []):
            groups.setdefault(g, []).append(len(objects))
    named = {}
    for g, parts in sorted(groups.items()):
        if len(parts) == 1:
            named[g] = parts[0]
        else:
            objects.append((0, parts, 0, []))
            named[g] = len(objects)
    points = {}
    for i, family in enumerate(mesh.node_fam):
        for g in (mesh.families.get(family, ("", []))[1] if family else []):
            assert g not in points, "a GIBI node group is one named point"
            points[g] = i + 1
    return objects, named, points


def write_gibi(path, mesh):
    dim = mesh.dim
    out = [" ENREGISTREMENT DE TYPE   4",
           " NIVEAU  15 NIVEAU ERREUR   0 DIMENSION   %d" % dim,
           " DENSITE  0.00000E+00",
           " ENREGISTREMENT DE TYPE   7",
           " NOMBRE INFO CASTEM2000   8",
           " IFOUR  -1 NIFOUR   0 IFOMOD  -1 IECHO   1 IIMPI   0 IOSPI   0 ISOTYP   1",
           " NSDPGE     0"]
    objects, named, points = objects_of(mesh)
    out.append(" ENREGISTREMENT DE TYPE   2")
    out.append(" PILE NUMERO   1NBRE OBJETS NOMMES%8dNBRE OBJETS%8d" % (len(named), len(objects)))
    out += names(named.keys())
    out += ints(named.values())
    for number, parts, per, cells in objects:
        out += ints([number, len(parts), 0, per, len(cells)])
        out += ints(parts)
        out += ints([0] * len(cells))  # colours
        out += ints(n for cell in cells for n in cell)
    count = len(mesh.nodes)
    out.append(" ENREGISTREMENT DE TYPE   2")
    out.append(" PILE NUMERO  32NBRE OBJETS NOMMES%8dNBRE OBJETS%8d" % (len(points), count))
    out += names(points.keys())
    out += ints(points.values())
    out += ints([count])
    out += ints(count - k for k in range(count))
    out.append(" ENREGISTREMENT DE TYPE   2")
    out.append(" PILE NUMERO  33NBRE OBJETS NOMMES%8dNBRE OBJETS%8d" % (0, 1))
    values = []
    for entry in range(count):
        x = mesh.nodes[count - 1 - entry]
        values += list(x[:dim]) + [0.0]
    out += ints([len(values)])
    out += reals(values)
    out += [" ENREGISTREMENT DE TYPE   5", "LABEL AUTOMATIQUE :   1"]
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    for stem, mesh in (("gibi_plate_lin", meshes.plate_2d(False)), ("gibi_plate_quad", meshes.plate_2d(True)),
                       ("gibi_block", meshes.block_3d()), ("gibi_zoo", meshes.zoo())):
        variant = gibi_variant(mesh)
        write_gibi(os.path.join(out, stem + ".mgib"), variant)
        meshes.write_mail(os.path.join(out, stem + ".mail"), variant)


if __name__ == "__main__":
    main()
