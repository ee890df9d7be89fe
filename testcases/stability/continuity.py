#!/usr/bin/env python3
"""Checks across runs of the stability cases (ctest stability.continuity, stability.units,
stability.effects, stability.messages; issue 19):

continuity  for 5 cases, one input is perturbed by 1e-6 relative (an imposed displacement, the
            friction coefficient, a Poisson ratio); every computed value of the case's TEST_RESU
            (the VALE_CALC column of its message file) must move by O(1e-6): the ratio
            |dr / r| / 1e-6 is printed and asserted <= 10 (a different active set would give a
            jump of O(1)), and at least one value must respond (ratio >= 0.1: a perturbation
            that changes nothing would test nothing).
units       the N/m, N/mm and kN/mm studies give the same dimensionless results (DY / L,
            forces / (stress unit x L)) to 1e-8.
effects     the effects report of STAT_NON_LINE (behaviours, contact zones, friction, pairing,
            factorisation, fields, time per effect) and nothing computed that was not asked (no
            contact line without CONTACT, no friction without COULOMB, no return mapping for ELAS,
            one pairing with REAC_GEOM='SANS', symmetric factorisations).
messages    the body held only by contact without springs stops with SOLVE_1 naming the free
            degree of freedom and the springs of notice 4.4.2, not with a crash.

usage: continuity.py STELLA WORKDIR {continuity|units|effects|messages}"""

import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))

# case, text to perturb in its command file, expected |dr/r| / 1e-6 bound is 10 for all
PERTURBED = [
    ("gen_penalty_1e12", "DY=-2e-05", "DY=%r" % (-2e-05 * (1 + 1e-6))),
    ("gen_friction_mu03", "COULOMB=0.3", "COULOMB=%r" % (0.3 * (1 + 1e-6))),
    ("gen_slide_off_edge", "DY=-0.01", "DY=%r" % (-0.01 * (1 + 1e-6))),
    ("gen_flip_flop", "DY=2e-05", "DY=%r" % (2e-05 * (1 + 1e-6))),
    ("gen_incompressible_si", "NU=0.4999", "NU=%r" % (0.4999 * (1 + 1e-6))),
]

VALUE_LINE = re.compile(r"^\s*(?:OK|NOOK)\s+ANALYTIQUE\s+(\S+)\s+(\S+)")


def run(stella, workdir, name, comm_text=None, tag=""):
    """Runs testcases/stability/<name>.export (or its command file replaced by comm_text); returns
    the computed values of its TEST_RESU, in order, and the message file's text."""
    out = os.path.join(workdir, name + tag)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    export = os.path.join(HERE, name + ".export")
    if comm_text is not None:
        for line in open(export):
            if line.startswith("F msh"):
                mesh = line.split()[2]
        shutil.copy(os.path.join(HERE, mesh), out)
        with open(os.path.join(out, name + ".comm"), "w") as f:
            f.write(comm_text)
        with open(os.path.join(out, name + ".export"), "w") as f:
            f.write(open(export).read())
        export = os.path.join(out, name + ".export")
    subprocess.run([stella, "run", export, "--quiet", "--work-dir", os.path.join(out, "work"), "--output-dir", out],
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
    mess = open(os.path.join(out, name + ".mess")).read()
    values = [float(m.group(2)) for m in map(VALUE_LINE.match, mess.splitlines()) if m]
    return values, mess


def continuity(stella, workdir):
    failures = 0
    for name, old, new in PERTURBED:
        text = open(os.path.join(HERE, name + ".comm")).read()
        if text.count(old) != 1:
            print("%s: '%s' is not found once in the command file" % (name, old))
            failures += 1
            continue
        base, _ = run(stella, workdir, name)
        moved, _ = run(stella, workdir, name, text.replace(old, new), ".perturbed")
        if not base or len(base) != len(moved):
            print("%s: %d values, %d perturbed" % (name, len(base), len(moved)))
            failures += 1
            continue
        scale = max(abs(v) for v in base)
        ratios = [abs(b - m) / max(abs(b), 1e-9 * scale) / 1e-6 for b, m in zip(base, moved)]
        worst = max(ratios)
        ok = worst <= 10.0 and worst >= 0.1
        print("%s: %s -> %s: max |dr/r| / 1e-6 = %.3f over %d values %s" % (name, old, new, worst, len(base),
                                                                             "OK" if ok else "FAILED"))
        failures += 0 if ok else 1
    return failures


def units(stella, workdir):
    # (case, length unit in m, stress unit in Pa): the discrete penalised series, then the continuous
    # formulation with its default COEF_CONT
    failures = unit_series(stella, workdir, [("gen_units_n_m", 1.0, 1.0), ("gen_units_n_mm", 1e-3, 1e6),
                                             ("gen_units_kn_mm", 1e-3, 1e9)])
    return failures + unit_series(stella, workdir, [("gen_continue_units_n_m", 1.0, 1.0),
                                                    ("gen_continue_units_n_mm", 1e-3, 1e6)])


def unit_series(stella, workdir, systems):
    results = []
    for name, length, stress in systems:
        values, mess = run(stella, workdir, name)
        # the tests are DY (MIN, MAX) of UP_BOT and LOW_TOP, then the contact resultant
        dimensionless = [v * length / 1.0 for v in values[:-1]] + [values[-1] * stress * length]
        results.append((name, dimensionless))
    failures = 0
    ref = results[0][1]
    for name, dims in results[1:]:
        worst = max(abs(a - b) / abs(a) for a, b in zip(ref, dims))
        ok = len(dims) == len(ref) == 5 and worst <= 1e-8
        print("%s vs %s: largest relative difference of the dimensionless results %.2e %s" % (
            name, results[0][0], worst, "OK" if ok else "FAILED"))
        failures += 0 if ok else 1
    return failures


def effects(stella, workdir):
    """The effects report of STAT_NON_LINE, and that nothing is computed that was not asked."""
    def variant(name, old, new):
        text = open(os.path.join(HERE, name + ".comm")).read()
        assert text.count(old) == 1, (name, old)
        return text.replace(old, new)

    checks = [
        # (what, case, command file text or None, lines wanted, lines refused)
        ("frictionless Lagrange contact", "gen_ratio_1e6_contrainte", None,
         ["effects activated [why]:", "linear elasticity, no return mapping",
          "zone 1: GROUP_MA_ESCL='UP_BOT' on GROUP_MA_MAIT='LOW_TOP', ALGO_CONT='CONTRAINTE'",
          "no friction (FROTTEMENT='SANS')", "factorisation symmetric", "time per effect (s):", "0 unsymmetric)",
          "fields stored at each archived step: DEPL, SIEF_ELGA, VARI_ELGA, CONT_NOEU"],
         ["Coulomb friction", "return mapping at each"]),
        ("no CONTACT: no contact structure", "gen_ratio_1e6_contrainte",
         variant("gen_ratio_1e6_contrainte", "CONTACT=CONT, ", ""),
         ["no contact: no pairing, no contact structure, no friction [CONTACT absent]", "0 unsymmetric)"],
         ["pairing(s)", ", contact ", "CONT_NOEU ["]),
        ("REAC_GEOM='SANS': paired once", "gen_incompressible_si",
         variant("gen_incompressible_si", "FORMULATION='DISCRETE', ", "FORMULATION='DISCRETE', REAC_GEOM='SANS', "),
         ["no geometric update (REAC_GEOM='SANS': paired once)", "(1 pairing(s))"], []),
        # COEF_MATR_FROT = 0 leaves the sliding links' tangent out only while RESI_GLOB_RELA >= 1e-3
        # and the statuses change: a sticking block (COULOMB = 1) never needs it.
        ("Coulomb friction that sticks, COEF_MATR_FROT = 0: symmetric", "gen_friction_mu1", None,
         ["Coulomb friction COULOMB=1 E_T=10000", "0 unsymmetric)"], []),
        ("Coulomb slip with COEF_MATR_FROT = 1: unsymmetric while sliding", "gen_friction_mu03",
         variant("gen_friction_mu03", "COULOMB=0.3", "COULOMB=0.3, COEF_MATR_FROT=1.0"),
         ["COEF_MATR_FROT=1", "time per effect (s):"], ["0 unsymmetric)"]),
        ("VMIS_ISOT_LINE: return mapping", "gen_ratio_1e6_contrainte",
         variant("gen_ratio_1e6_contrainte", "INCREMENT=_F(LIST_INST=L_INST)",
                 "INCREMENT=_F(LIST_INST=L_INST), COMPORTEMENT=_F(GROUP_MA='UP', RELATION='VMIS_ISOT_LINE')").replace(
             "M_UP = DEFI_MATERIAU(ELAS=_F(E=210000.0, NU=0.0))",
             "M_UP = DEFI_MATERIAU(ELAS=_F(E=210000.0, NU=0.0), ECRO_LINE=_F(D_SIGM_EPSI=1000.0, SY=1.0e6))"),
         ["behaviour VMIS_ISOT_LINE on GROUP_MA=(UP) (8 cell(s)): return mapping at each Gauss point",
          "behaviour ELAS on the 8 other volume cell(s)", "behaviours (ELAS, VMIS_ISOT_LINE) with assembly"], []),
    ]
    failures = far_zone(stella, workdir)
    for what, name, text, wanted, refused in checks:
        _, mess = run(stella, workdir, name, text, ".effects" if text else "")
        missing = [w for w in wanted if w not in mess]
        present = [r for r in refused if r in mess]
        ok = not missing and not present
        print("%s (%s): %s" % (what, name, "OK" if ok else "missing %s, present %s" % (missing, present)))
        failures += 0 if ok else 1
    return failures


FAR_STUDY = """DEBUT()
MA = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
MA = MODI_MAILLAGE(reuse=MA, MAILLAGE=MA, ORIE_PEAU=_F(GROUP_MA_PEAU=('LOW_TOP', 'UP_BOT')))
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))
ACIER = DEFI_MATERIAU(ELAS=_F(E=2.1e11, NU=0.3))
CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=ACIER))
BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='BAS', DY=0.0), _F(GROUP_MA='LOW_LEFT', DX=0.0),
                                         _F(GROUP_MA='UP', DX=0.0, DY=0.0)))
LOAD = AFFE_CHAR_MECA(MODELE=MO, PRES_REP=_F(GROUP_MA='LOW_TOP', PRES=1.0e6))
RAMP = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0))
L_INST = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=1.0, NOMBRE=5))
{contact}RESU = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, {snl}EXCIT=(_F(CHARGE=BC), _F(CHARGE=LOAD, FONC_MULT=RAMP)),
                     INCREMENT=_F(LIST_INST=L_INST))
TEST_RESU(RESU=_F(RESULTAT=RESU, INST=1.0, NOM_CHAM='DEPL', NOM_CMP='DY', GROUP_NO='LOW_TOP', TYPE_TEST='MIN',
                  VALE_CALC=-4.333333333333e-06, TOLE_MACHINE=1.0, REFERENCE='ANALYTIQUE',
                  VALE_REFE=-4.333333333333e-06, PRECISION=1.0e-9, LEGENDE='(1 - nu^2) p H / E'))
FIN()
"""


def far_zone(stella, workdir):
    """An unused contact zone (the bodies 0.5 m apart, every gap far larger than the motion):
    the same factorisations as without CONTACT and one pairing per step (no geometric loop: it
    used to pair twice and factorise twice per step)."""
    sys.path.insert(0, HERE)
    from generate import stack_mesh
    out = os.path.join(workdir, "far_zone")
    os.makedirs(out, exist_ok=True)
    stack_mesh(1.0, 1.0, 4, 2, 1.0, 0.2, 4, 1, gap=0.5).write(os.path.join(out, "far.msh"))
    zone = ("CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='DISCRETE', ZONE=_F(GROUP_MA_MAIT='LOW_TOP', "
            "GROUP_MA_ESCL='UP_BOT', ALGO_CONT='CONTRAINTE'))\n")
    counts = {}
    for tag, contact, snl in (("without", "", ""), ("with", zone, "CONTACT=CONT, ")):
        comm = os.path.join(out, tag + ".comm")
        with open(comm, "w") as f:
            f.write(FAR_STUDY.format(contact=contact, snl=snl))
        subprocess.run([stella, "run", comm, "--unit", "20=" + os.path.join(out, "far.msh")],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
        mess = open(os.path.join(out, tag + ".mess")).read()
        m = re.search(r"factorisation [0-9.]+ \((\d+) symmetric, (\d+) unsymmetric\)", mess)
        p = re.search(r"\((\d+) pairing\(s\)\)", mess)
        counts[tag] = (m and int(m.group(1)), p and int(p.group(1)), "DIAGNOSTIC JOB : OK" in mess)
    ok = counts["without"][2] and counts["with"][2] and counts["with"][0] == counts["without"][0] and \
        counts["with"][1] == 6
    print("unused contact zone far away: %d factorisations without CONTACT, %s with, %s pairing(s) (5 steps) %s" % (
        counts["without"][0] or -1, counts["with"][0], counts["with"][1], "OK" if ok else "FAILED"))
    return 0 if ok else 1


def messages(stella, workdir):
    _, mess = run(stella, workdir, "gen_no_springs")
    wanted = ["<F> <SOLVE_1>", "component DY is free", "springs", "4.4.2", "DIAGNOSTIC JOB : OK"]
    missing = [w for w in wanted if w not in mess]
    print("gen_no_springs: message %s" % ("OK" if not missing else "lacks %s" % missing))
    return len(missing)


if __name__ == "__main__":
    stella, workdir, what = sys.argv[1:4]
    os.makedirs(workdir, exist_ok=True)
    failed = {"continuity": continuity, "units": units, "messages": messages, "effects": effects}[what](stella, workdir)
    sys.exit(1 if failed else 0)
