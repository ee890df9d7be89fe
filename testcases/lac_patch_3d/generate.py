#!/usr/bin/env python3
"""Writes the meshes (Gmsh, blocks3d.geo), command files and exports of the ssnp170-like LAC patch
tests in 3D: a block UP = [0,1]^2 x [1,2] pressed by PRES = 25 on a block LOW = [0,1]^2 x [0,1],
meshes not matching on z = 1 (NLOW and NUP cells along x and y), symmetry conditions on x = 0 and
y = 0, DZ = 0 under LOW, frictionless LAC contact after CREA_MAILLAGE/DECOUPE_LAC on the slave face.
Exact solution: sigma_zz = -25 everywhere (uniaxial), contact pressure -25, zero gap. VALE_CALC =
the closed form (the computed values differ from it by round-off).
"""
import os
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))
P = 25.0

# (case, LOW hexahedra?, UP hexahedra?, NLOW, NUP, order, slave, DECOUPE_HEXA, TYPE_APPA, ALGO_RESO_GEOM)
CASES = [
    ("h8_h8", 1, 1, 3, 2, 1, "UP", "PYRA", "RAPIDE", "NEWTON"),
    ("h8_h8_swap", 1, 1, 3, 2, 1, "LOW", "PYRA", "RAPIDE", "NEWTON"),
    ("h8_h8_hexa", 1, 1, 3, 2, 1, "UP", "HEXA", "RAPIDE", "NEWTON"),
    ("t4_t4", 0, 0, 3, 2, 1, "UP", "PYRA", "RAPIDE", "NEWTON"),
    ("t4_h8_swap", 0, 1, 2, 3, 1, "LOW", "PYRA", "ROBUSTE", "POINT_FIXE"),
    ("h20_h20", 1, 1, 3, 2, 2, "UP", "PYRA", "RAPIDE", "NEWTON"),
    ("t10_t10_swap", 0, 0, 2, 3, 2, "LOW", "PYRA", "RAPIDE", "NEWTON"),
    ("h20_t10", 1, 0, 3, 2, 2, "UP", "HEXA", "RAPIDE", "NEWTON"),
    ("h8_t4", 1, 0, 3, 2, 1, "UP", "PYRA", "RAPIDE", "NEWTON"),
    ("h20_h20_swap", 1, 1, 2, 3, 2, "LOW", "PYRA", "RAPIDE", "NEWTON"),
    ("h27_h27", 1, 1, 3, 2, 3, "UP", "PYRA", "RAPIDE", "NEWTON"),
    ("h27_t10_swap", 1, 0, 2, 3, 3, "LOW", "PYRA", "ROBUSTE", "NEWTON"),
    ("h8_h8_actualise", 1, 1, 3, 2, 1, "UP", "PYRA", "RAPIDE", "NEWTON"),
]
# _actualise: TYPE_JACOBIEN='ACTUALISE', the integrals on the current interface, whose area grew by
# (1 + eps_xx)^2 with eps_xx = NU P / E (uniaxial stress): LAGS_C = PRES = -P / (1 + NU P / E)^2.
E, NU = 2000.0, 0.3
# order 3 above: quadratic with the complete Lagrange cells (HEXA27: QUAD9 faces, not cut by
# DECOUPE_LAC, each its own patch); order 2: the serendipity ones (HEXA20, TETRA10).


# Computed values that differ from the closed form by more than the non-regression tolerance
# (1e-6 relative): the HEXA cut makes trapezoidal QUAD4 slave faces, whose shape functions are not
# polynomials of the position, so the degree-5 triangle rule integrates them to 2e-6 relative.
CALC = {
    "h8_h8_hexa": {("SIEF_NOEU", "SIZZ", "MIN"): -25.000057639837234,
                   ("SIEF_NOEU", "SIZZ", "MAX"): -24.999942714719918},
}


def mesh(name, hlow, hup, nlow, nup, order):
    subprocess.run(["gmsh", os.path.join(HERE, "blocks3d.geo"), "-3", "-format", "msh22", "-o",
                    os.path.join(HERE, name + ".msh"), "-setnumber", "NLOW", str(nlow), "-setnumber", "NUP",
                    str(nup), "-setnumber", "HLOW", str(hlow), "-setnumber", "HUP", str(hup), "-setnumber",
                    "ORDER", str(min(order, 2)), "-setnumber", "INCOMPLETE", "0" if order == 3 else "1"], check=True, stdout=subprocess.DEVNULL)


def comm(case):
    name, hlow, hup, nlow, nup, order, slave, cut, appa, geom = case
    master = "LOW" if slave == "UP" else "UP"
    face = {"UP": "UP_BOT", "LOW": "LOW_TOP"}
    actualise = name.endswith("_actualise")
    lam = -P / (1 + NU * P / E) ** 2 if actualise else -P
    jacobian = ", TYPE_JACOBIEN='ACTUALISE'" if actualise else ""

    def test(field, cmp, kind, refe, crit, prec, legend):
        group = "GROUP_MA='%s', " % face[slave] if field == "CONT_ELEM" else ""
        calc = CALC.get(name, {}).get((field, cmp, kind), refe)
        return (f"    _F(RESULTAT=RESU, INST=1.0, NOM_CHAM='{field}', NOM_CMP='{cmp}', TYPE_TEST='{kind}', {group}\n"
                f"       VALE_CALC={calc!r}, VALE_REFE={refe!r}, REFERENCE='ANALYTIQUE', CRITERE='{crit}',\n"
                f"       PRECISION={prec!r}, LEGENDE='{legend}'),\n")
    return "".join([
        f"# LAC patch test (ssnp170-like, 3D), written by generate.py: LOW {'HEXA' if hlow else 'TETRA'} order {order} ({nlow} x {nlow}\n",
        f"# cells along the interface) under UP {'HEXA' if hup else 'TETRA'} ({nup} x {nup}), slave {slave}, DECOUPE_HEXA='{cut}',\n",
        f"# TYPE_APPA='{appa}', ALGO_RESO_GEOM='{geom}'{jacobian}. Exact: SIZZ = -25, LAGS_C = PRES = {lam!r}, JEU = 0.\n",
        "DEBUT()\n",
        "M0 = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)\n",
        f"MA = CREA_MAILLAGE(MAILLAGE=M0, DECOUPE_LAC=_F(GROUP_MA_ESCL='{face[slave]}', DECOUPE_HEXA='{cut}'))\n",
        "MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='3D'))\n",
        "MAT = DEFI_MATERIAU(ELAS=_F(E=2000.0, NU=0.3))\n",
        "CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=MAT))\n",
        "CH = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='BAS', DZ=0.0), _F(GROUP_MA=('LOW_X0', 'UP_X0'), DX=0.0),\n",
        "                                        _F(GROUP_MA=('LOW_Y0', 'UP_Y0'), DY=0.0)),\n",
        f"                    PRES_REP=_F(GROUP_MA='UP_TOP', PRES={P!r}))\n",
        "RAMPE = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0))\n",
        "L_INST = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=1.0, NOMBRE=1))\n",
        f"CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE', ALGO_RESO_GEOM='{geom}', ALGO_RESO_CONT='NEWTON',\n",
        f"                    ZONE=_F(ALGO_CONT='LAC', APPARIEMENT='MORTAR', GROUP_MA_MAIT='{face[master]}',\n",
        f"                            GROUP_MA_ESCL='{face[slave]}', CONTACT_INIT='OUI', TYPE_APPA='{appa}'{jacobian}))\n",
        "RESU = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, CONTACT=CONT, EXCIT=_F(CHARGE=CH, FONC_MULT=RAMPE),\n",
        "                     INCREMENT=_F(LIST_INST=L_INST))\n",
        "RESU = CALC_CHAMP(reuse=RESU, RESULTAT=RESU, CONTRAINTE='SIEF_NOEU')\n",
        "TEST_RESU(RESU=(\n",
        test("SIEF_NOEU", "SIZZ", "MIN", -P, "RELATIF", 1e-3, "SIZZ min = -25"),
        test("SIEF_NOEU", "SIZZ", "MAX", -P, "RELATIF", 1e-3, "SIZZ max = -25"),
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
        "FIN()\n",
    ])


def main():
    for case in CASES:
        name = "lac3d_" + case[0]
        mesh(name, *case[1:6])
        open(os.path.join(HERE, name + ".comm"), "w").write(comm(case))
        open(os.path.join(HERE, name + ".export"), "w").write(
            f"P testlist verification\nF comm {name}.comm D 1\nF msh {name}.msh D 20\n"
            f"F mess {name}.mess R 6\nF resu {name}.resu R 8\nF rmed {name}.rmed R 80\n")


if __name__ == "__main__":
    main()
