#!/usr/bin/env python3
"""Writes the meshes (Gmsh, blocks.geo), command files and exports of the ssnp170-like LAC patch
tests in 2D: a block UP = [0,1]x[1,2] pressed by PRES = 25 on a block LOW = [0,1]x[0,1], meshes not
matching on y = 1 (NLOW and NUP cells along x), frictionless LAC contact after
CREA_MAILLAGE/DECOUPE_LAC on the slave edge. Exact solution: sigma_yy = -25 everywhere, contact
pressure -25 (TYPE_JACOBIEN='INITIAL'), zero gap. VALE_CALC = the closed form (the computed values
differ from it by round-off, < 1e-11 relative).
"""
import os
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))
P = 25.0
E, NU = 2000.0, 0.3


def pressure(model, jacobian):
    """The contact pressure LAGS_C: -P on the initial configuration (TYPE_JACOBIEN='INITIAL'); with
    'ACTUALISE' the integrals are on the current interface, longer by the lateral strain
    eps_xx = NU P / E (C_PLAN), NU (1 + NU) P / E (D_PLAN), so LAGS_C = -P / (1 + eps_xx)."""
    if jacobian == "INITIAL":
        return -P
    eps = NU * P / E if model == "C_PLAN" else NU * (1 + NU) * P / E
    return -P / (1 + eps)

# (case, low cells, up cells, NLOW, NUP, order, slave, modelisation, TYPE_APPA, TYPE_JACOBIEN, ALGO_RESO_GEOM)
CASES = [
    ("q4_q4", "QUAD4", "QUAD4", 4, 3, 1, "UP", "D_PLAN", "RAPIDE", "INITIAL", "NEWTON"),
    ("q4_q4_swap", "QUAD4", "QUAD4", 4, 3, 1, "LOW", "D_PLAN", "RAPIDE", "INITIAL", "NEWTON"),
    ("t3_t3", "TRIA3", "TRIA3", 5, 3, 1, "UP", "D_PLAN", "RAPIDE", "INITIAL", "NEWTON"),
    ("t3_t3_swap", "TRIA3", "TRIA3", 5, 3, 1, "LOW", "D_PLAN", "RAPIDE", "INITIAL", "NEWTON"),
    ("t3_q4", "TRIA3", "QUAD4", 4, 3, 1, "UP", "D_PLAN", "ROBUSTE", "INITIAL", "NEWTON"),
    ("q4_t3_swap", "QUAD4", "TRIA3", 3, 5, 1, "LOW", "C_PLAN", "RAPIDE", "ACTUALISE", "NEWTON"),
    ("t6_t6", "TRIA6", "TRIA6", 4, 3, 2, "UP", "D_PLAN", "RAPIDE", "INITIAL", "NEWTON"),
    ("t6_t6_swap", "TRIA6", "TRIA6", 4, 3, 2, "LOW", "D_PLAN", "RAPIDE", "INITIAL", "POINT_FIXE"),
    ("q8_q8", "QUAD8", "QUAD8", 4, 3, 2, "UP", "D_PLAN", "RAPIDE", "INITIAL", "NEWTON"),
    ("q8_q8_swap", "QUAD8", "QUAD8", 3, 4, 2, "LOW", "C_PLAN", "RAPIDE", "INITIAL", "NEWTON"),
    ("q4_q4_actualise", "QUAD4", "QUAD4", 4, 3, 1, "UP", "D_PLAN", "RAPIDE", "ACTUALISE", "NEWTON"),
    ("q4_q4_axis", "QUAD4", "QUAD4", 4, 3, 1, "UP", "AXIS", "RAPIDE", "INITIAL", "NEWTON"),
    ("t6_q8_axis_swap", "TRIA6", "QUAD8", 5, 3, 2, "LOW", "AXIS", "RAPIDE", "INITIAL", "NEWTON"),
    ("t6_q8", "TRIA6", "QUAD8", 5, 3, 2, "UP", "D_PLAN", "ROBUSTE", "INITIAL", "NEWTON"),
    ("q8_t6_swap", "QUAD8", "TRIA6", 3, 4, 2, "LOW", "D_PLAN", "RAPIDE", "INITIAL", "POINT_FIXE"),
]

QUAD = {"QUAD4": 1, "QUAD8": 1, "TRIA3": 0, "TRIA6": 0}


def mesh(name, low, up, nlow, nup, order, gap=0.0):
    args = ["gmsh", os.path.join(HERE, "blocks.geo"), "-2", "-format", "msh22", "-o",
            os.path.join(HERE, name + ".msh"), "-setnumber", "NLOW", str(nlow), "-setnumber", "NUP", str(nup),
            "-setnumber", "QLOW", str(QUAD[low]), "-setnumber", "QUP", str(QUAD[up]),
            "-setnumber", "ORDER", str(order), "-setnumber", "INCOMPLETE", "1", "-setnumber", "GAP", repr(gap)]
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)


def comm(case, calc):
    name, low, up, nlow, nup, order, slave, model, appa, jac, geom = case
    master = "LOW" if slave == "UP" else "UP"
    edge = {"UP": "UP_BOT", "LOW": "LOW_TOP"}
    c = calc or {}
    lam = pressure(model, jac)

    def test(field, cmp, kind, refe, crit, prec, legend):
        value = c.get((field, cmp, kind), refe)
        group = "GROUP_MA='%s', " % edge[slave] if field == "CONT_ELEM" else ""
        return (f"    _F(RESULTAT=RESU, INST=1.0, NOM_CHAM='{field}', NOM_CMP='{cmp}', TYPE_TEST='{kind}', {group}\n"
                f"       VALE_CALC={value!r}, VALE_REFE={refe!r}, REFERENCE='ANALYTIQUE', CRITERE='{crit}',\n"
                f"       PRECISION={prec!r}, LEGENDE='{legend}'),\n")
    lines = [
        f"# LAC patch test (ssnp170-like, 2D), written by generate.py: {low} (LOW, {nlow} cells along the\n"
        f"# interface) under {up} (UP, {nup} cells), slave {slave}, {model}, TYPE_APPA='{appa}',\n"
        f"# TYPE_JACOBIEN='{jac}', ALGO_RESO_GEOM='{geom}'. Exact: SIYY = -25, LAGS_C = PRES = {lam!r}, JEU = 0.\n",
        "DEBUT()\n",
        "M0 = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)\n",
        f"MA = CREA_MAILLAGE(MAILLAGE=M0, DECOUPE_LAC=_F(GROUP_MA_ESCL='{edge[slave]}'))\n",
        f"MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='{model}'))\n",
        "MAT = DEFI_MATERIAU(ELAS=_F(E=2000.0, NU=0.3))\n",
        "CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=MAT))\n",
        "CH = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='BAS', DY=0.0), _F(GROUP_MA=('LOW_LEFT', 'UP_LEFT'), DX=0.0)),\n",
        f"                    PRES_REP=_F(GROUP_MA='UP_TOP', PRES={P!r}))\n",
        "RAMPE = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0))\n",
        "L_INST = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=1.0, NOMBRE=1))\n",
        f"CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE', ALGO_RESO_GEOM='{geom}', ALGO_RESO_CONT='NEWTON',\n",
        f"                    ZONE=_F(ALGO_CONT='LAC', APPARIEMENT='MORTAR', GROUP_MA_MAIT='{edge[master]}',\n",
        f"                            GROUP_MA_ESCL='{edge[slave]}', CONTACT_INIT='OUI', TYPE_APPA='{appa}',\n",
        f"                            TYPE_JACOBIEN='{jac}'))\n",
        "RESU = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, CONTACT=CONT, EXCIT=_F(CHARGE=CH, FONC_MULT=RAMPE),\n",
        "                     INCREMENT=_F(LIST_INST=L_INST))\n",
        "RESU = CALC_CHAMP(reuse=RESU, RESULTAT=RESU, CONTRAINTE='SIEF_NOEU')\n",
        "TEST_RESU(RESU=(\n",
        test("SIEF_NOEU", "SIYY", "MIN", -P, "RELATIF", 1e-3, "SIYY min = -25"),
        test("SIEF_NOEU", "SIYY", "MAX", -P, "RELATIF", 1e-3, "SIYY max = -25"),
        test("DEPL", "LAGS_C", "MIN", lam, "RELATIF", 1e-3, "LAGS_C min"),
        test("DEPL", "LAGS_C", "MAX", lam, "RELATIF", 1e-3, "LAGS_C max"),
        test("CONT_ELEM", "PRES", "MIN", lam, "RELATIF", 1e-3, "PRES min"),
        test("CONT_ELEM", "PRES", "MAX", lam, "RELATIF", 1e-3, "PRES max"),
        test("CONT_ELEM", "JEU", "MIN", 0.0, "ABSOLU", 1e-3, "JEU min = 0"),
        test("CONT_ELEM", "JEU", "MAX", 0.0, "ABSOLU", 1e-3, "JEU max = 0"),
        test("CONT_ELEM", "CONT", "MIN", 1.0, "ABSOLU", 0.0, "every patch in contact"),
        test("CONT_ELEM", "COEFSURF", "MIN", 1.0, "RELATIF", 1e-10, "every patch fully paired"),
        "))\n",
        "IMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(RESULTAT=RESU, NOM_CHAM=('DEPL', 'SIEF_NOEU', 'CONT_ELEM')))\n",
        "IMPR_RESU(FORMAT='VTU', UNITE=81, RESU=_F(RESULTAT=RESU, NOM_CHAM=('DEPL', 'SIEF_NOEU', 'CONT_ELEM')))\n",
        "FIN()\n",
    ]
    return "".join(lines)


def export(name):
    return (f"P testlist verification\nF comm {name}.comm D 1\nF msh {name}.msh D 20\n"
            f"F mess {name}.mess R 6\nF resu {name}.resu R 8\nF rmed {name}.rmed R 80\nF pvd {name}.pvd R 81\n")


# The closing gap: UP lifted by G0, its top moved down by t D (DDL_IMPO, D_PLAN, QUAD4 4 / TRIA3 3,
# slave UP, CONTACT_INIT='NON', ALGO_RESO_GEOM='POINT_FIXE'). At t = 0.25 the gap is open: UP
# translates (no stress), JEU = G0 - t D, CONT = 0, PRES = 0; at t = 1 it is closed and both blocks
# (height 1 each) share the compression D - G0: sigma_yy = -E (D - G0) / (2 (1 - NU^2)) = -25.
G0 = 0.01
D = G0 + 2 * (1 - NU * NU) * P / E


def closing_comm(calc_gap):
    def test(field, cmp, kind, inst, refe, crit, prec, legend):
        group = "GROUP_MA='UP_BOT', " if field == "CONT_ELEM" else ""
        return (f"    _F(RESULTAT=RESU, INST={inst!r}, NOM_CHAM='{field}', NOM_CMP='{cmp}', TYPE_TEST='{kind}', {group}\n"
                f"       VALE_CALC={refe!r}, VALE_REFE={refe!r}, REFERENCE='ANALYTIQUE', CRITERE='{crit}',\n"
                f"       PRECISION={prec!r}, LEGENDE='{legend}'),\n")
    open_gap = G0 - 0.25 * D
    return "".join([
        "# LAC contact closing a gap, written by generate.py: UP (TRIA3, 3 cells) lifted by G0 = 0.01 above LOW\n",
        "# (QUAD4, 4 cells), its top moved down by t D; CONTACT_INIT='NON', statuses found by the Newton iterations.\n",
        f"# t = 0.25: open, JEU = G0 - t D = {open_gap!r}, PRES = 0, CONT = 0; t = 1: SIYY = LAGS_C = -25.\n",
        "DEBUT()\n",
        "M0 = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)\n",
        "MA = CREA_MAILLAGE(MAILLAGE=M0, DECOUPE_LAC=_F(GROUP_MA_ESCL='UP_BOT'))\n",
        "MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))\n",
        "MAT = DEFI_MATERIAU(ELAS=_F(E=2000.0, NU=0.3))\n",
        "CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=MAT))\n",
        "FIX = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='BAS', DY=0.0), _F(GROUP_MA=('LOW_LEFT', 'UP_LEFT'), DX=0.0)))\n",
        f"PUSH = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='UP_TOP', DY={-D!r}))\n",
        "RAMPE = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0))\n",
        "L_INST = DEFI_LIST_REEL(VALE=(0.0, 0.25, 1.0))\n",
        "CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE', ALGO_RESO_GEOM='POINT_FIXE', ALGO_RESO_CONT='NEWTON',\n",
        "                    ZONE=_F(ALGO_CONT='LAC', GROUP_MA_MAIT='LOW_TOP', GROUP_MA_ESCL='UP_BOT', CONTACT_INIT='NON'))\n",
        "RESU = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, CONTACT=CONT, EXCIT=(_F(CHARGE=FIX), _F(CHARGE=PUSH, FONC_MULT=RAMPE)),\n",
        "                     INCREMENT=_F(LIST_INST=L_INST),\n",
        "                     # the open step has no reaction (UP translates): an absolute criterion\n",
        "                     CONVERGENCE=_F(RESI_GLOB_MAXI=1.0e-8))\n",
        "RESU = CALC_CHAMP(reuse=RESU, RESULTAT=RESU, CONTRAINTE='SIEF_NOEU')\n",
        "TEST_RESU(RESU=(\n",
        test("CONT_ELEM", "JEU", "MIN", 0.25, open_gap, "RELATIF", 1e-6, "open gap min"),
        test("CONT_ELEM", "JEU", "MAX", 0.25, open_gap, "RELATIF", 1e-6, "open gap max"),
        test("CONT_ELEM", "CONT", "MAX", 0.25, 0.0, "ABSOLU", 0.0, "no patch in contact"),
        test("CONT_ELEM", "PRES", "MIN", 0.25, 0.0, "ABSOLU", 0.0, "no pressure"),
        test("SIEF_NOEU", "SIYY", "MIN", 1.0, -P, "RELATIF", 1e-3, "SIYY min = -25"),
        test("SIEF_NOEU", "SIYY", "MAX", 1.0, -P, "RELATIF", 1e-3, "SIYY max = -25"),
        test("DEPL", "LAGS_C", "MIN", 1.0, -P, "RELATIF", 1e-3, "LAGS_C min = -25"),
        test("DEPL", "LAGS_C", "MAX", 1.0, -P, "RELATIF", 1e-3, "LAGS_C max = -25"),
        test("CONT_ELEM", "JEU", "MIN", 1.0, 0.0, "ABSOLU", 1e-3, "closed"),
        test("CONT_ELEM", "CONT", "MIN", 1.0, 1.0, "ABSOLU", 0.0, "every patch in contact"),
        "))\n",
        "FIN()\n",
    ])


def main():
    mesh("lac_closing_gap", "QUAD4", "TRIA3", 4, 3, 1, G0)
    open(os.path.join(HERE, "lac_closing_gap.comm"), "w").write(closing_comm(None))
    open(os.path.join(HERE, "lac_closing_gap.export"), "w").write(
        "P testlist verification\nF comm lac_closing_gap.comm D 1\nF msh lac_closing_gap.msh D 20\n"
        "F mess lac_closing_gap.mess R 6\nF resu lac_closing_gap.resu R 8\n")
    for case in CASES:
        name = "lac_" + case[0]
        mesh(name, *case[1:6])
        open(os.path.join(HERE, name + ".comm"), "w").write(comm(case, None))
        open(os.path.join(HERE, name + ".export"), "w").write(export(name))


if __name__ == "__main__":
    main()
