#!/usr/bin/env python3
"""Writes the command files and exports of the DECOUPE_LAC patch tests: the meshes of
../patch_tests cut by CREA_MAILLAGE/DECOUPE_LAC under two loaded sides (cells at the corner are cut
twice), then the constant-stress patch test of ../patch_tests on the cut mesh, with the
closed-form values as references."""

E, NU = 200000.0, 0.3
P, Q, S = 100.0, 40.0, -30.0  # target stresses (sigma_xx, sigma_yy, sigma_zz in 3D)

# (case, modelisation, meshes, slave groups, DECOUPE_HEXA)
CASES = [
    ("decoupe_lac_2d", "D_PLAN", ["tria3", "tria6", "quad4", "quad8"], ("RIGHT", "TOP"), None),
    ("decoupe_lac_3d", "3D", ["tetra4", "tetra10", "hexa8", "hexa20", "penta6"], ("X1", "Z1"), "PYRA"),
    ("decoupe_lac_3d_hexa", "3D", ["hexa8", "hexa20"], ("X1", "Z1", "Y0"), "HEXA"),
]


def expected(model):
    if model == "D_PLAN":
        exx = ((1 - NU * NU) * P - NU * (1 + NU) * Q) / E
        eyy = ((1 - NU * NU) * Q - NU * (1 + NU) * P) / E
        return [("SIXX", P), ("SIYY", Q), ("SIZZ", NU * (P + Q)), ("SIXY", 0.0)], [("DX", "MAX", exx), ("DY", "MAX", eyy)]
    exx = (P - NU * (Q + S)) / E
    eyy = (Q - NU * (P + S)) / E
    ezz = (S - NU * (P + Q)) / E
    return ([("SIXX", P), ("SIYY", Q), ("SIZZ", S), ("SIXY", 0.0), ("SIXZ", 0.0), ("SIYZ", 0.0)],
            [("DX", "MAX", exx), ("DY", "MAX", eyy), ("DZ", "MIN", ezz)])


def loads(model, i):
    if model == "3D":
        return (f"CH{i} = AFFE_CHAR_MECA(MODELE=MO{i},\n"
                f"    DDL_IMPO=(_F(GROUP_MA='X0', DX=0.0), _F(GROUP_MA='Y0', DY=0.0), _F(GROUP_MA='Z0', DZ=0.0)),\n"
                f"    FORCE_FACE=(_F(GROUP_MA='X1', FX={P!r}), _F(GROUP_MA='Y1', FY={Q!r}), _F(GROUP_MA='Z1', FZ={S!r})))\n")
    return (f"CH{i} = AFFE_CHAR_MECA(MODELE=MO{i},\n"
            f"    DDL_IMPO=(_F(GROUP_MA='LEFT', DX=0.0), _F(GROUP_MA='BOTTOM', DY=0.0)),\n"
            f"    PRES_REP=(_F(GROUP_MA='RIGHT', PRES={-P!r}), _F(GROUP_MA='TOP', PRES={-Q!r})))\n")


def test_line(result, field, cmp, kind, value):
    if value == 0.0:
        return (f"    _F(RESULTAT={result}, NUME_ORDRE=1, NOM_CHAM='{field}', NOM_CMP='{cmp}', TYPE_TEST='{kind}',\n"
                f"       VALE_CALC=0.0, ORDRE_GRANDEUR={P!r}, CRITERE='ABSOLU', TOLE_MACHINE=1.0e-8,\n"
                f"       REFERENCE='ANALYTIQUE', VALE_REFE=0.0, PRECISION=1.0e-8),\n")
    return (f"    _F(RESULTAT={result}, NUME_ORDRE=1, NOM_CHAM='{field}', NOM_CMP='{cmp}', TYPE_TEST='{kind}',\n"
            f"       VALE_CALC={value!r}, TOLE_MACHINE=1.0e-10,\n"
            f"       REFERENCE='ANALYTIQUE', VALE_REFE={value!r}, PRECISION=1.0e-10),\n")


def comm(model, meshes, slaves, hexa):
    stresses, displacements = expected(model)
    groups = "(" + ", ".join(f"'{g}'" for g in slaves) + ")"
    cut = f"GROUP_MA_ESCL={groups}" + (f", DECOUPE_HEXA='{hexa}'" if hexa else "")
    out = [f"# DECOUPE_LAC then the constant-stress patch test, MODELISATION='{model}', written by generate.py.\n",
           "DEBUT()\n",
           f"STEEL = DEFI_MATERIAU(ELAS=_F(E={E!r}, NU={NU!r}))\n"]
    for i, mesh in enumerate(meshes, start=1):
        out.append(f"\n# {mesh}\n")
        out.append(f"M0{i} = LIRE_MAILLAGE(FORMAT='GMSH', UNITE={19 + i})\n")
        out.append(f"M{i} = CREA_MAILLAGE(MAILLAGE=M0{i}, DECOUPE_LAC=_F({cut}))\n")
        out.append(f"MO{i} = AFFE_MODELE(MAILLAGE=M{i}, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='{model}'))\n")
        out.append(f"CM{i} = AFFE_MATERIAU(MAILLAGE=M{i}, AFFE=_F(TOUT='OUI', MATER=STEEL))\n")
        out.append(loads(model, i))
        out.append(f"R{i} = MECA_STATIQUE(MODELE=MO{i}, CHAM_MATER=CM{i}, EXCIT=_F(CHARGE=CH{i}))\n")
        out.append("TEST_RESU(RESU=(\n")
        for cmp, value in stresses:
            for kind in ("MIN", "MAX"):
                out.append(test_line(f"R{i}", "SIEF_ELGA", cmp, kind, value))
        for cmp, kind, value in displacements:
            if kind == "MAX" and value < 0:
                kind = "MIN"
            out.append(test_line(f"R{i}", "DEPL", cmp, kind, value))
        out.append("))\n")
    out.append("\nFIN()\n")
    return "".join(out)


def export(name, meshes):
    lines = ["P testlist verification\n", f"F comm {name}.comm D 1\n"]
    for i, mesh in enumerate(meshes, start=1):
        lines.append(f"F msh ../patch_tests/{mesh}.msh D {19 + i}\n")
    lines.append(f"F mess {name}.mess R 6\n")
    lines.append(f"F resu {name}.resu R 8\n")
    return "".join(lines)


for name, model, meshes, slaves, hexa in CASES:
    with open(f"{name}.comm", "w") as f:
        f.write(comm(model, meshes, slaves, hexa))
    with open(f"{name}.export", "w") as f:
        f.write(export(name, meshes))
