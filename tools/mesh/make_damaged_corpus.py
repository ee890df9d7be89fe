#!/usr/bin/python3
"""Builds the damaged-file corpus of solver/io/tests/damaged/ from the good files in its good/
folder: at least 20 damaged, truncated, empty or garbage files per format (Gmsh .msh, ASTER .mail,
MED .med). Every one must make the readers raise a clean UserError naming the file; the test
solver/io/tests/DamagedFilesTest.cpp reads them all. Deterministic: run it again, get the same
files. Uses Debian's python3 (h5py for the MED edits).

    /usr/bin/python3 tools/mesh/make_damaged_corpus.py [corpus-dir]
"""

import os
import random
import shutil
import sys

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CORPUS = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "solver", "io", "tests", "damaged")
GOOD = os.path.join(ROOT, "solver", "io", "tests", "damaged", "good")


def write(folder, name, data):
    os.makedirs(os.path.join(CORPUS, folder), exist_ok=True)
    mode = "wb" if isinstance(data, bytes) else "w"
    with open(os.path.join(CORPUS, folder, name), mode) as f:
        f.write(data)


def read(name):
    with open(os.path.join(GOOD, name), "rb") as f:
        return f.read()


def text_of(good):
    return good.decode()


def text_damages(good, ext, folder, edits, long_line):
    """Generic damages for a text format plus format-specific `edits` (name -> text)."""
    rng = random.Random(20261122)
    write(folder, "01_empty" + ext, b"")
    write(folder, "02_blank_lines" + ext, b"\n\n   \n")
    for i, frac in enumerate((0.1, 0.3, 0.5, 0.7, 0.9)):
        write(folder, "%02d_truncated_%d%s" % (3 + i, int(frac * 100), ext), good[: int(len(good) * frac)])
    write(folder, "08_last_line_cut" + ext, good.rstrip()[:-3])
    write(folder, "09_random_bytes" + ext, bytes(rng.randrange(256) for _ in range(600)))
    write(folder, "10_nul_bytes" + ext, good[:40] + b"\0" * 64 + good[40:])
    write(folder, "11_long_line" + ext, long_line(text_of(good)).encode())
    write(folder, "12_binary_garbage_tail" + ext, good[: len(good) // 2] + bytes(range(256)) * 4)
    text = good.decode()
    for i, (name, content) in enumerate(sorted(edits(text).items())):
        write(folder, "%02d_%s%s" % (13 + i, name, ext), content)


def gmsh_edits(t):
    lines = t.splitlines(keepends=True)
    nodes = t.index("$Nodes\n")
    first_node = t.index("\n", nodes + 7) + 1  # after the count line
    node_line_end = t.index("\n", first_node)
    elems = t.index("$Elements\n")
    first_elem = t.index("\n", elems + 10) + 1
    elem_line_end = t.index("\n", first_elem)
    elem = t[first_elem:elem_line_end].split()
    return {
        "no_header": t[t.index("$EndMeshFormat\n") + 15:],
        "version_9": t.replace("2.2 0 8", "9.9 0 8", 1),
        "binary_flag": t.replace("2.2 0 8", "2.2 1 8", 1),
        "huge_node_count": t[:nodes + 7] + "999999999\n" + t[first_node:],
        "negative_node_count": t[:nodes + 7] + "-5\n" + t[first_node:],
        "node_count_too_small": t[:nodes + 7] + "3\n" + t[first_node:],
        "coordinate_text": t[:first_node] + "1 abc 0 0" + t[node_line_end:],
        "coordinate_nan": t[:first_node] + "1 nan 0 0" + t[node_line_end:],
        "coordinate_inf": t[:first_node] + "1 0 1e999 0" + t[node_line_end:],
        "duplicate_node": t[:first_node] + t[first_node:node_line_end] + "\n" + t[first_node:],
        "unknown_node_in_element": t[:first_elem] + " ".join(elem[:-1] + ["777"]) + t[elem_line_end:],
        "unknown_element_type": t[:first_elem] + " ".join(elem[:1] + ["99"] + elem[2:]) + t[elem_line_end:],
        "missing_end_nodes": t.replace("$EndNodes\n", "", 1),
        "missing_elements": t[:elems],
        "elements_before_nodes": t[:nodes] + t[elems:] + t[nodes:elems],
        "unterminated_name": t.replace('"SURFACE"', '"SURFACE', 1),
        "huge_tag_count": t[:first_elem] + " ".join(elem[:2] + ["100000"] + elem[3:]) + t[elem_line_end:],
        "element_too_few_nodes": t[:first_elem] + " ".join(elem[:-1]) + "\n$EndElements\n",
        "unknown_section_unclosed": t.replace("$Nodes\n", "$Comments\nhello\n$Nodes\n", 1).replace(
            "$Nodes", "$Nodez", 1),
    }


def gmsh41_edits(t):
    nodes = t.index("$Nodes\n")
    header_end = t.index("\n", nodes + 7)
    parts = t[nodes + 7:header_end].split()
    elems = t.index("$Elements\n")
    eheader_end = t.index("\n", elems + 10)
    eparts = t[elems + 10:eheader_end].split()
    return {
        "node_total_mismatch": t[:nodes + 7] + " ".join([parts[0], str(int(parts[1]) + 4)] + parts[2:]) +
        t[header_end:],
        "element_total_mismatch": t[:elems + 10] + " ".join([eparts[0], str(int(eparts[1]) + 1)] + eparts[2:]) +
        t[eheader_end:],
        "entities_truncated": t[: t.index("$Entities\n") + 15],
        "bad_parametric_flag": t.replace("\n1 2 0 3\n", "\n1 2 7 3\n", 1),
        "version_4_0": t.replace("4.1 0 8", "4.0 0 8", 1),
    }


def mail_edits(t):
    return {
        "no_fin": t.replace("FIN\n", ""),
        "no_finsf_in_coor": t.replace("N6 1 1\nFINSF", "N6 1 1", 1),
        "unknown_block": t.replace("TRIA3\n", "TRIANGLE3\n", 1),
        "undefined_node": t.replace("M1 N1 N2 N5", "M1 N1 N2 N99", 1),
        "duplicate_node": t.replace("N2 0.5 0\n", "N2 0.5 0\nN2 0.7 0\n", 1),
        "duplicate_cell": t.replace("M2 N1 N5 N4", "M1 N1 N5 N4", 1),
        "coordinate_text": t.replace("N3 1 0", "N3 one 0", 1),
        "coordinate_nan": t.replace("N3 1 0", "N3 nan 0", 1),
        "cell_too_few_nodes": t.replace("M1 N1 N2 N5\n", "M1 N1 N2\nFINSF\n", 1),
        "group_unknown_cell": t.replace("GROUP_MA\nSURFACE\n", "GROUP_MA\nSURFACE\n  M404\n", 1),
        "group_unknown_node": t.replace("GROUP_NO\nORIGIN\n", "GROUP_NO\nORIGIN\n  N404\n", 1),
        "no_nodes": t[: t.index("COOR_2D")] + t[t.index("FINSF", t.index("COOR_2D")) + 6:],
        "no_cells": t[: t.index("TRIA3")] + "FIN\n",
        "group_without_name": t.replace(
            "GROUP_MA\nSURFACE\n", "GROUP_MA\nFINSF\nGROUP_MA\nSURFACE\n", 1),
    }


def med_damages(folder):
    good = read("good.med")
    rng = random.Random(5)
    write(folder, "01_empty.med", b"")
    for i, frac in enumerate((0.05, 0.2, 0.4, 0.6, 0.8, 0.95, 0.99)):
        write(folder, "%02d_truncated_%d.med" % (2 + i, int(frac * 100)), good[: int(len(good) * frac)])
    write(folder, "09_text_file.med", b"COOR_3D\nN1 0 0 0\nFINSF\nFIN\n")
    write(folder, "10_random_bytes.med", bytes(rng.randrange(256) for _ in range(4096)))
    write(folder, "11_superblock_zeroed.med", b"\0" * 512 + good[512:])
    write(folder, "12_gmsh_file.med", read("good22.msh"))

    path = os.path.join(CORPUS, folder)

    def edit(name, fn):
        target = os.path.join(path, name)
        shutil.copyfile(os.path.join(GOOD, "good.med"), target)
        with h5py.File(target, "r+") as f:
            fn(f)

    def step(f):
        mesh = f["ENS_MAA"][list(f["ENS_MAA"].keys())[0]]
        return mesh[list(mesh.keys())[0]]

    def set_data(group, name, values):
        attrs = dict(group[name].attrs)
        del group[name]
        group.create_dataset(name, data=values)
        for k, v in attrs.items():
            group[name].attrs[k] = v

    def hexa(f):
        return step(f)["MAI"]["HE8"]

    with open(os.path.join(path, "13_plain_hdf5.med"), "wb"):
        pass
    with h5py.File(os.path.join(path, "13_plain_hdf5.med"), "w") as f:
        f.create_dataset("data", data=np.arange(10.0))
    edit("14_node_out_of_range.med", lambda f: set_data(hexa(f), "NOD", np.where(
        hexa(f)["NOD"][()] == 1, 999, hexa(f)["NOD"][()]).astype(hexa(f)["NOD"].dtype)))
    edit("15_node_zero.med", lambda f: set_data(hexa(f), "NOD", np.zeros_like(hexa(f)["NOD"][()])))
    edit("16_coordinate_nan.med", lambda f: set_data(step(f)["NOE"], "COO", np.full_like(
        step(f)["NOE"]["COO"][()], np.nan)))
    edit("17_connectivity_too_short.med", lambda f: set_data(hexa(f), "NOD", hexa(f)["NOD"][()][:5]))
    edit("18_coordinates_removed.med", lambda f: step(f)["NOE"].__delitem__("COO"))
    edit("19_connectivity_removed.med", lambda f: hexa(f).__delitem__("NOD"))
    edit("20_no_cells.med", lambda f: step(f).__delitem__("MAI"))
    edit("21_no_mesh.med", lambda f: f.__delitem__("ENS_MAA"))
    edit("22_count_attribute_huge.med", lambda f: hexa(f)["NOD"].attrs.__setitem__("NBR", np.int32(2000000000)))
    edit("23_coordinates_wrong_type.med", lambda f: set_data(step(f)["NOE"], "COO", np.array([b"abc"] * 36)))
    edit("24_family_names_garbage.med", lambda f: set_data(hexa(f), "NOD", np.full(
        hexa(f)["NOD"].shape, -3, dtype=hexa(f)["NOD"].dtype)))


def main():
    for folder in ("msh", "mail", "med"):
        shutil.rmtree(os.path.join(CORPUS, folder), ignore_errors=True)
    text_damages(read("good22.msh"), ".msh", "msh", gmsh_edits,
                 lambda t: t.replace("$EndMeshFormat", "9" * 20000 + "\n$EndMeshFormat", 1))
    t41 = read("good41.msh").decode()
    for i, (name, content) in enumerate(sorted(gmsh41_edits(t41).items())):
        write("msh", "%02d_v41_%s.msh" % (40 + i, name), content)
    text_damages(read("good.mail"), ".mail", "mail", mail_edits,
                 lambda t: t.replace("N1 0 0", "N1 " + "9" * 20000 + " 0", 1))
    med_damages("med")
    for folder in ("msh", "mail", "med"):
        print(folder, len(os.listdir(os.path.join(CORPUS, folder))), "files")


main()
