#!/usr/bin/python3
"""The 10^6-DOF 3D contact study of issue 20: two HEXA8 slabs of side 10 (mm) pressed on each other.

BAS = [0,10]^2 x [-HB,0] (NB cells per side, LB layers) under HAUT = [0,10]^2 x [0,HH] (NH cells
per side, LH layers; the finer, slave face HAUT_BAS: (NH+1)^2 slave nodes), non-matching at z = 0,
mesh by ../contact-calculix/blocks3d.py. Symmetry rollers DX = 0 on x = 0, DY = 0 on y = 0, DZ = 0
on z = -HB, DZ = -D on z = HH, all by AFFE_CHAR_CINE (eliminated: no multiplier row, so the
matrix is symmetric positive definite and METHODE='PETSC' takes it). Frictionless discrete contact
(DEFI_CONTACT FORMULATION='DISCRETE', ALGO_CONT given), one step of STAT_NON_LINE.
Exact solution (uniaxial stress, linear, so in the HEXA8 space): sigma_zz = -E D / (HB + HH)
everywhere, total contact force E D / (HB + HH) x 100 on the quarter, u_z = -D HB / (HB + HH) on the
interface. With ALGO_CONT='PENALISATION' the nodal law lambda = E_N x penetration adds a compliance:
an interior slave node of tributary area a = (10/NH)^2 penetrates by about p a / E_N.

Writes the mesh, .comm and .export in WORK, runs `stella run` under /usr/bin/time -v (with
`P memory_limit` when --memory-limit is given) and prints the phase times, iterations, peak memory
and the errors against the exact values, read from the message file.

  contact1e6.py --stella build/bin/stella --work /tmp/c1e6 [--nb 99 --nh 100 --layers 16 16]
                [--algo PENALISATION --en 1e7] [--solveur "METHODE='PETSC', ..."] [--memory-limit MiB]
"""
import argparse
import pathlib
import re
import subprocess
import sys

HERE = pathlib.Path(__file__).resolve().parent
E = 210000.0
NU = 0.3

COMM = """DEBUT()
MA = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(GROUP_MA=('BAS', 'HAUT'), PHENOMENE='MECANIQUE', MODELISATION='3D'))
ACIER = DEFI_MATERIAU(ELAS=_F(E={e!r}, NU={nu!r}))
CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=ACIER))
CL = AFFE_CHAR_CINE(MODELE=MO, MECA_IMPO=(_F(GROUP_MA='SYM_X', DX=0.0), _F(GROUP_MA='SYM_Y', DY=0.0),
                                          _F(GROUP_MA='BAS_Z0', DZ=0.0), _F(GROUP_MA='HAUT_Z1', DZ={mdz!r})))
RAMPE = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0))
L_INST = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=1.0, NOMBRE=1))
CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='DISCRETE',{contact}
                    ZONE=_F(GROUP_MA_MAIT='BAS_HAUT', GROUP_MA_ESCL='HAUT_BAS', {zone}))
RESU = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, CONTACT=CONT, EXCIT=_F(CHARGE=CL, FONC_MULT=RAMPE),
                     INCREMENT=_F(LIST_INST=L_INST), SOLVEUR=_F({solveur}))
# The exact values (VALE_REFE); VALE_CALC = the exact value too: this is a measure, not a test
# (the computed value and its relative difference are printed in the message file).
TEST_RESU(RESU=(
    _F(RESULTAT=RESU, INST=1.0, NOM_CHAM='CONT_NOEU', NOM_CMP='RZ', GROUP_NO='HAUT_BAS', TYPE_TEST='SOMM',
       VALE_CALC={force!r}, TOLE_MACHINE=1.0, REFERENCE='ANALYTIQUE', VALE_REFE={force!r}, PRECISION=1.0,
       LEGENDE='force'),
    _F(RESULTAT=RESU, INST=1.0, NOM_CHAM='DEPL', NOM_CMP='DZ', GROUP_NO='HAUT_BAS', TYPE_TEST='MIN',
       VALE_CALC={uz!r}, TOLE_MACHINE=1.0, REFERENCE='ANALYTIQUE', VALE_REFE={uz!r}, PRECISION=1.0,
       LEGENDE='uz_min'),
    _F(RESULTAT=RESU, INST=1.0, NOM_CHAM='DEPL', NOM_CMP='DZ', GROUP_NO='HAUT_BAS', TYPE_TEST='MAX',
       VALE_CALC={uz!r}, TOLE_MACHINE=1.0, REFERENCE='ANALYTIQUE', VALE_REFE={uz!r}, PRECISION=1.0,
       LEGENDE='uz_max'),
    _F(RESULTAT=RESU, INST=1.0, NOM_CHAM='SIEF_ELGA', NOM_CMP='SIZZ', GROUP_MA='BAS', TYPE_TEST='MIN',
       VALE_CALC={szz!r}, TOLE_MACHINE=1.0, REFERENCE='ANALYTIQUE', VALE_REFE={szz!r}, PRECISION=1.0,
       LEGENDE='sizz_bas_min'),
    _F(RESULTAT=RESU, INST=1.0, NOM_CHAM='SIEF_ELGA', NOM_CMP='SIZZ', GROUP_MA='BAS', TYPE_TEST='MAX',
       VALE_CALC={szz!r}, TOLE_MACHINE=1.0, REFERENCE='ANALYTIQUE', VALE_REFE={szz!r}, PRECISION=1.0,
       LEGENDE='sizz_bas_max'),
    _F(RESULTAT=RESU, INST=1.0, NOM_CHAM='SIEF_ELGA', NOM_CMP='SIZZ', GROUP_MA='HAUT', TYPE_TEST='MIN',
       VALE_CALC={szz!r}, TOLE_MACHINE=1.0, REFERENCE='ANALYTIQUE', VALE_REFE={szz!r}, PRECISION=1.0,
       LEGENDE='sizz_haut_min'),
    _F(RESULTAT=RESU, INST=1.0, NOM_CHAM='SIEF_ELGA', NOM_CMP='SIZZ', GROUP_MA='HAUT', TYPE_TEST='MAX',
       VALE_CALC={szz!r}, TOLE_MACHINE=1.0, REFERENCE='ANALYTIQUE', VALE_REFE={szz!r}, PRECISION=1.0,
       LEGENDE='sizz_haut_max'),
))
FIN()
"""


def arguments():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--stella", default="build/bin/stella")
    p.add_argument("--work", default="/tmp/contact-1e6")
    p.add_argument("--nb", type=int, default=99)
    p.add_argument("--nh", type=int, default=100)
    p.add_argument("--layers", type=int, nargs=2, default=(16, 16))
    p.add_argument("--heights", type=float, nargs=2, default=(1.6, 1.6))
    p.add_argument("--d", type=float, default=0.0032, help="imposed displacement of the top")
    p.add_argument("--algo", default="PENALISATION", help="ALGO_CONT")
    p.add_argument("--en", type=float, default=1.0e7, help="E_N (PENALISATION)")
    p.add_argument("--zone", default="", help="more ZONE keywords")
    p.add_argument("--contact", default="", help="more DEFI_CONTACT keywords, e.g. RESI_ABSO=1e-9 for GCP")
    p.add_argument("--solveur", default="METHODE='PETSC', ALGORITHME='CG', PRE_COND='GAMG', RESI_RELA=1.0e-8")
    p.add_argument("--memory-limit", type=int, help="MiB, written as P memory_limit")
    p.add_argument("--label", default=None)
    return p.parse_args()


def write_study(a, study, mesh):
    h = a.heights[0] + a.heights[1]
    zone = f"ALGO_CONT='{a.algo}'"
    if a.algo == "PENALISATION":
        zone += f", E_N={a.en!r}"
    if a.zone:
        zone += ", " + a.zone
    values = dict(contact=' ' + a.contact + ',' if a.contact else '', e=E, nu=NU, mdz=-a.d, zone=zone, solveur=a.solveur, force=E * a.d / h * 100.0,
                  uz=-a.d * a.heights[0] / h, szz=-E * a.d / h)
    study.with_suffix(".comm").write_text(COMM.format(**values))
    export = [f"P testlist bench", f"F comm {study.name}.comm D 1", f"F msh {mesh.name} D 20",
              f"F mess {study.name}.mess R 6"]
    if a.memory_limit:
        export.append(f"P memory_limit {a.memory_limit}")
    study.with_suffix(".export").write_text("\n".join(export) + "\n")


def report(a, study):
    mess = study.with_suffix(".mess").read_text(errors="replace")
    timing = study.with_suffix(".time").read_text()
    out = {}
    for key, pattern in [("wall", r"Elapsed \(wall clock\) time.*: (\S+)"),
                         ("max_rss_kb", r"Maximum resident set size \(kbytes\): (\d+)"),
                         ("user", r"User time \(seconds\): (\S+)"), ("sys", r"System time \(seconds\): (\S+)")]:
        m = re.search(pattern, timing)
        out[key] = m.group(1) if m else "?"
    for line in mess.splitlines():
        for key in ("equations:", "time per effect", "linear solver:", "iterative solver:", "peak memory:",
                    "solver summary", "Newton", "contact iterations", "pairing"):
            if key in line and len(out.get("lines", [])) < 40:
                out.setdefault("lines", []).append(line.strip())
    for cmd in ("LIRE_MAILLAGE", "AFFE_MODELE", "DEFI_CONTACT", "STAT_NON_LINE", "TEST_RESU"):
        m = re.search(rf"^\s*\d+\s+{cmd}\s.*$", mess, re.M)
        if m:
            out.setdefault("commands", []).append(m.group(0).strip())
    print(f"study={study.name} wall={out['wall']} cpu_s={float(out['user']) + float(out['sys']):.1f} "
          f"max_rss_mb={int(out['max_rss_kb']) / 1024:.0f}" if out['user'] != "?" else f"study={study.name}")
    for line in out.get("lines", []) + out.get("commands", []):
        print("  " + line)
    # TEST_RESU lines: the computed values against the exact ones
    for m in re.finditer(r"^.*(force|uz_min|uz_max|sizz_\w+).*$", mess, re.M):
        print("  " + m.group(0).strip())


def main():
    a = arguments()
    work = pathlib.Path(a.work)
    work.mkdir(parents=True, exist_ok=True)
    geometry = f"blocks_{a.nb}_{a.nh}_{a.layers[0]}_{a.layers[1]}_{a.heights[0]:g}_{a.heights[1]:g}"
    mesh = work / f"{geometry}.msh"
    if not mesh.exists():
        subprocess.check_call([sys.executable, str(HERE.parent / "contact-calculix" / "blocks3d.py"), str(a.nb),
                               str(a.nh), str(mesh), "--layers", *map(str, a.layers), "--heights",
                               *map(str, a.heights)])
    study = work / (a.label or f"{geometry}_{a.algo}")
    write_study(a, study, mesh)
    with open(study.with_suffix(".out"), "w") as log:
        subprocess.call(["/usr/bin/time", "-v", "-o", str(study.with_suffix(".time")), a.stella, "run",
                         str(study.with_suffix(".export")), "--work-dir", str(study) + ".work", "--output-dir",
                         str(work)], stdout=log, stderr=subprocess.STDOUT)
    report(a, study)


if __name__ == "__main__":
    main()
