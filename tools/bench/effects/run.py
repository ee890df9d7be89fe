#!/usr/bin/env python3
"""What an unused or inactive effect costs in STAT_NON_LINE (issue 19; report doc/bench/effects.md).

Four pairs of studies differ by one effect that changes nothing in the result:
  far-zone   the same elastic study with an unused DEFI_CONTACT zone (the bodies 0.5 m apart)
  vmis       VMIS_ISOT_LINE below yield (SY = 1e30) vs ELAS
  mu0        penalised Coulomb friction with COULOMB = 0 vs FROTTEMENT='SANS' (contact active)
  reac-geom  REAC_GEOM='AUTOMATIQUE' vs 'SANS' on a small-displacement contact study
Each study runs RUNS times (default 7, at least 5), the two of a pair alternating, in one
process after the other on this machine; the time is STAT_NON_LINE's own (the message file's
"Time per command"), the ratio is median(variant) / median(base).

usage: tools/bench/effects/run.py [build/bin/stella] [RUNS] [cells per side]"""

import os
import re
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
sys.path.insert(0, os.path.join(ROOT, "testcases", "stability"))
from generate import stack_mesh  # noqa: E402  (the structured two-block meshes of the stability cases)

HEAD = """DEBUT()
MA = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
MA = MODI_MAILLAGE(reuse=MA, MAILLAGE=MA, ORIE_PEAU=_F(GROUP_MA_PEAU=('LOW_TOP', 'UP_BOT')))
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))
ACIER = DEFI_MATERIAU(ELAS=_F(E=2.1e11, NU=0.3), ECRO_LINE=_F(D_SIGM_EPSI=2.0e9, SY=1.0e30))
CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=ACIER))
RAMP = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0))
L_INST = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=1.0, NOMBRE=5))
"""

# The elastic study: LOW held at its bottom and pressed on its top; UP held apart, 0.5 m above.
APART = HEAD + """BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='BAS', DX=0.0, DY=0.0), _F(GROUP_MA='UP', DX=0.0, DY=0.0)))
LOAD = AFFE_CHAR_MECA(MODELE=MO, PRES_REP=_F(GROUP_MA='LOW_TOP', PRES=1.0e6))
{contact}RESU = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, {snl}EXCIT=(_F(CHARGE=BC), _F(CHARGE=LOAD, FONC_MULT=RAMP)),
                     INCREMENT=_F(LIST_INST=L_INST){behaviour})
FIN()
"""
FAR_ZONE = ("CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='DISCRETE', ZONE=_F(GROUP_MA_MAIT='LOW_TOP', "
            "GROUP_MA_ESCL='UP_BOT', ALGO_CONT='CONTRAINTE'))\n")

# The contact study: UP pressed on LOW by the imposed DY of its top (small displacements).
PRESSED = HEAD + """BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='BAS', DX=0.0, DY=0.0), _F(GROUP_MA='UP_TOP', DX=0.0)))
LOAD = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='UP_TOP', DY=-1.0e-5))
CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='DISCRETE'{options}, ZONE=_F(GROUP_MA_MAIT='LOW_TOP', GROUP_MA_ESCL='UP_BOT',
                    ALGO_CONT='PENALISATION', E_N=1.0e14{zone}))
RESU = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, CONTACT=CONT, EXCIT=(_F(CHARGE=BC), _F(CHARGE=LOAD, FONC_MULT=RAMP)),
                     INCREMENT=_F(LIST_INST=L_INST))
FIN()
"""
FRICTION = ", ALGO_FROT='PENALISATION', E_T=1.0e14, COULOMB=0.0"

PAIRS = [
    ("far-zone", "an unused DEFI_CONTACT zone far away (0.5 m apart)", "apart",
     APART.format(contact="", snl="", behaviour=""),
     APART.format(contact=FAR_ZONE, snl="CONTACT=CONT, ", behaviour="")),
    ("vmis", "VMIS_ISOT_LINE below yield vs ELAS", "apart",
     APART.format(contact="", snl="", behaviour=""),
     APART.format(contact="", snl="", behaviour=", COMPORTEMENT=_F(RELATION='VMIS_ISOT_LINE')")),
    ("mu0", "Coulomb friction COULOMB = 0 vs no friction (contact active)", "pressed",
     PRESSED.format(options="", zone=""),
     PRESSED.format(options=", FROTTEMENT='COULOMB'", zone=FRICTION)),
    ("reac-geom", "REAC_GEOM='AUTOMATIQUE' vs 'SANS' (small displacements)", "pressed",
     PRESSED.format(options=", REAC_GEOM='SANS'", zone=""),
     PRESSED.format(options="", zone="")),
]

TIME = re.compile(r"^\s*\d+\s+STAT_NON_LINE\s+\S+\s+([0-9.]+)", re.M)
EFFECT = re.compile(r"time per effect \(s\): (.*)")


def main():
    stella = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "bin", "stella")
    runs = max(5, int(sys.argv[2]) if len(sys.argv) > 2 else 7)
    n = int(sys.argv[3]) if len(sys.argv) > 3 else 60
    work = tempfile.mkdtemp(prefix="stella-bench-effects-")
    meshes = {"apart": stack_mesh(1.0, 1.0, n, n, 1.0, 0.2, n, max(1, n // 5), gap=0.5),
              "pressed": stack_mesh(1.0, 1.0, n, n, 1.0, 0.2, n, max(1, n // 5))}
    for name, m in meshes.items():
        m.write(os.path.join(work, name + ".msh"))

    def run(tag, text, mesh):
        comm = os.path.join(work, tag + ".comm")
        with open(comm, "w") as f:
            f.write(text)
        subprocess.run([stella, "run", comm, "--unit", "20=" + os.path.join(work, mesh + ".msh")],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
        mess = open(os.path.join(work, tag + ".mess")).read()
        if "DIAGNOSTIC JOB : OK" not in mess:
            sys.exit("%s did not end OK: see %s" % (tag, os.path.join(work, tag + ".mess")))
        return float(TIME.search(mess).group(1)), EFFECT.search(mess).group(1)

    print("stella STAT_NON_LINE, %d x %d + %d x %d QUAD4 (D_PLAN), 5 steps, %d runs each, medians" % (
        n, n, n, max(1, n // 5), runs))
    print("| pair | base (s) | with the effect (s) | ratio | time per effect of one run (with the effect) |")
    print("|---|---|---|---|---|")
    for tag, what, mesh, base, variant in PAIRS:
        times = {"base": [], "variant": []}
        effects = ""
        for _ in range(runs):
            times["base"].append(run(tag + "_base", base, mesh)[0])
            t, effects = run(tag + "_variant", variant, mesh)
            times["variant"].append(t)
        b, v = statistics.median(times["base"]), statistics.median(times["variant"])
        print("| %s: %s | %.3f | %.3f | %.3f | %s |" % (tag, what, b, v, v / b, effects))


if __name__ == "__main__":
    main()
