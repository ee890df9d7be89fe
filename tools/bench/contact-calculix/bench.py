#!/usr/bin/python3
"""stella vs CalculiX (ccx 2.20) on the same contact meshes: end-to-end time and error against
the closed form, side by side (report: doc/bench/contact-calculix.md).

Cases:
  hertz2d  plane-strain Hertz cylinder on a flat (mesh: testcases/hertz_cylinder/hertz_cylinder.geo
           at H = 0.135, ~7 100 nodes, ~14 000 equations in stella). CalculiX has no plane-strain
           contact of its own (it expands 2D elements to 3D): it gets the same mesh extruded into
           one layer of C3D8 of thickness 1 with DZ = 0 everywhere.
  block3d  two stacked cubes, 23^3 and 24^3 HEXA8, non-matching interface (~88 000 equations):
           uniform compression, closed form sigma_zz = -E delta / 20.
  overhead block3d with matching meshes (24^3 and 24^3): the contact solve (CONTRAINTE and GCP)
           against the linear solve of the same mesh with the interface bonded (merged nodes);
           stella only.
stella runs each contact case with ALGO_CONT='CONTRAINTE' (default) and 'GCP' (RESI_ABSO 1e-8 mm
for hertz2d, 1e-9 mm for block3d: 1e-8 and 1e-7 of the imposed displacements).
Usage: bench.py [--stella build/bin/stella] [--cases hertz2d,block3d,overhead] [--codes ccx,stella]
                [--work /tmp/stella-ccx-bench]
Both codes run on one core (OMP_NUM_THREADS=1); times are wall-clock of the whole run (reading
the input, meshing data, solving, writing results) and the CPU time (user + sys) of the process.
"""
import argparse
import math
import os
import resource
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[2]
sys.path.insert(0, str(HERE))
from ccx_deck import Mesh, write_deck  # noqa: E402

E, NU = 210000.0, 0.3
E_STAR = E / (2.0 * (1.0 - NU * NU))
R_HERTZ, D_HERTZ = 50.0, 1.0  # indenter radius, imposed approach of the cut (mm)
D_BLOCK = 0.02  # block3d: imposed shortening of the 20 mm stack


def run(cmd, cwd, log):
    env = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    with open(log, "w") as out:
        rc = subprocess.call(cmd, cwd=cwd, stdout=out, stderr=subprocess.STDOUT, env=env)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return rc, wall, cpu


# ---------------------------------------------------------------- meshes
def hertz_mesh(work):
    msh = work / "hertz2d.msh"
    if not msh.exists():
        subprocess.check_call(["gmsh", str(ROOT / "testcases/hertz_cylinder/hertz_cylinder.geo"), "-2",
                               "-setnumber", "H", "0.135", "-format", "msh22", "-o", str(msh)],
                              stdout=subprocess.DEVNULL)
    return msh


def block_mesh(work, nb, nh, merged=False):
    msh = work / f"blocks_{nb}_{nh}{'_merged' if merged else ''}.msh"
    if not msh.exists():
        subprocess.check_call([sys.executable, str(HERE / "blocks3d.py"), str(nb), str(nh), str(msh)]
                              + (["merged"] if merged else []))
    return msh


# ---------------------------------------------------------------- CalculiX side
def ccx_contact(slave, master):
    return f"""*SURFACE INTERACTION, NAME=SI
*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD
*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE
{slave}, {master}
"""


def ccx_hertz(work):
    mesh = Mesh(hertz_mesh(work))
    body = ccx_contact("CSLAVE", "CMASTER") + f"""*BOUNDARY
NALL, 3, 3, 0.
BLOC_BASE, 2, 2, 0.
BLOC_AXE, 1, 1, 0.
IND_AXE, 1, 1, 0.
*STEP
*STATIC
1., 1.
*BOUNDARY
IND_TOP, 2, 2, {-D_HERTZ}
*NODE PRINT, NSET=IND_TOP, TOTALS=ONLY
RF
*CONTACT FILE
CSTR
*END STEP
"""
    d = work / "ccx_hertz2d"
    d.mkdir(exist_ok=True)
    write_deck(mesh, d / "hertz.inp", ["BLOC", "IND"], {"BLOC": (E, NU), "IND": (E, NU)},
               ["BLOC_BASE", "BLOC_AXE", "IND_AXE", "IND_TOP", "IND_CONT"],
               {"CSLAVE": "IND_CONT", "CMASTER": "BLOC_TOP"}, body, slab=1.0)
    rc, wall, cpu = run(["ccx", "hertz"], d, d / "ccx.log")
    force = ccx_total_force(d / "hertz.dat")  # slab of thickness 1: per unit length, half model
    press = ccx_node_values(d / "hertz.frd", "CONTACT", 3)
    off = len(mesh.points)
    slave = mesh.group_nodes("IND_CONT")
    x = mesh.points[slave][:, 0]
    p = np.array([press.get(n + 1, 0.0) for n in slave])
    return dict(rc=rc, wall=wall, cpu=cpu, equations=ccx_equations(d / "ccx.log"), nodes=2 * len(
        np.unique(np.concatenate([c.ravel() for _n, _t, c in mesh.volume_cells(["BLOC", "IND"])]))), off=off,
        **hertz_errors(abs(force[1]), x, p))


def ccx_block(work, nb=23, nh=24):
    mesh = Mesh(block_mesh(work, nb, nh))
    body = ccx_contact("CSLAVE", "CMASTER") + f"""*BOUNDARY
SYM_X, 1, 1, 0.
SYM_Y, 2, 2, 0.
BAS_Z0, 3, 3, 0.
*STEP
*STATIC
1., 1.
*BOUNDARY
HAUT_Z1, 3, 3, {-D_BLOCK}
*NODE PRINT, NSET=HAUT_Z1, TOTALS=ONLY
RF
*NODE FILE
U
*CONTACT FILE
CSTR
*END STEP
"""
    d = work / f"ccx_block_{nb}_{nh}"
    d.mkdir(exist_ok=True)
    write_deck(mesh, d / "block.inp", ["BAS", "HAUT"], {"BAS": (E, NU), "HAUT": (E, NU)},
               ["SYM_X", "SYM_Y", "BAS_Z0", "HAUT_Z1", "HAUT_BAS"], {"CSLAVE": "HAUT_BAS", "CMASTER": "BAS_HAUT"},
               body)
    rc, wall, cpu = run(["ccx", "block"], d, d / "ccx.log")
    force = ccx_total_force(d / "block.dat")
    press = ccx_node_values(d / "block.frd", "CONTACT", 3)
    disp = ccx_node_values(d / "block.frd", "DISP", 2)
    slave = mesh.group_nodes("HAUT_BAS")
    return dict(rc=rc, wall=wall, cpu=cpu, equations=ccx_equations(d / "ccx.log"),
                **block_errors(abs(force[2]), np.array([press.get(n + 1, 0.0) for n in slave]),
                               np.array([disp.get(n + 1, 0.0) for n in slave])))


def ccx_total_force(dat):
    lines = open(dat).read().splitlines()
    k = max(i for i, l in enumerate(lines) if "total force" in l)
    return [float(v) for v in lines[k + 2].split()]


def ccx_equations(log):
    lines = open(log).read().splitlines()
    for i, line in enumerate(lines):
        if "number of equations" in line:
            return int(lines[i + 1].split()[0])
    return None


def ccx_node_values(frd, block, column):
    """{node: value} of component `column` (0-based) of the last `block` block of a .frd file."""
    values, inside = {}, False
    for line in open(frd):
        if line.startswith(" -4"):
            inside = line.split()[1] == block
            if inside:
                values = {}
            continue
        if inside and line.startswith(" -3"):
            inside = False
        elif inside and line.startswith(" -1"):
            values[int(line[3:13])] = float(line[13 + 12 * column:25 + 12 * column])
    return values


# ---------------------------------------------------------------- stella side
HERTZ_COMM = """DEBUT()
MA = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
MA = MODI_MAILLAGE(reuse=MA, MAILLAGE=MA, ORIE_PEAU=_F(GROUP_MA_PEAU=('IND_CONT', 'BLOC_TOP')))
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(GROUP_MA=('IND', 'BLOC'), PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))
ACIER = DEFI_MATERIAU(ELAS=_F(E={E}, NU={NU}))
CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=ACIER))
CL = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='BLOC_BASE', DY=0.0), _F(GROUP_MA=('BLOC_AXE', 'IND_AXE'), DX=0.0),
                                          _F(GROUP_MA='IND_TOP', DY={MD})))
RAMPE = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0))
L_INST = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=1.0, NOMBRE=1))
CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='DISCRETE',{GLOBAL} ZONE=_F(GROUP_MA_MAIT='BLOC_TOP', GROUP_MA_ESCL='IND_CONT'{ALGO}))
RESU = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, CONTACT=CONT, EXCIT=_F(CHARGE=CL, FONC_MULT=RAMPE),
                     INCREMENT=_F(LIST_INST=L_INST){NEWTON})
IMPR_RESU(FORMAT='RESULTAT', RESU=_F(RESULTAT=RESU, NOM_CHAM='CONT_NOEU', INST=1.0, GROUP_NO='IND_CONT'))
FIN()
"""

BLOCK_COMM = """DEBUT()
MA = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(GROUP_MA=('BAS', 'HAUT'), PHENOMENE='MECANIQUE', MODELISATION='3D'))
ACIER = DEFI_MATERIAU(ELAS=_F(E={E}, NU={NU}))
CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=ACIER))
CL = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='SYM_X', DX=0.0), _F(GROUP_MA='SYM_Y', DY=0.0),
                                          _F(GROUP_MA='BAS_Z0', DZ=0.0), _F(GROUP_MA='HAUT_Z1', DZ={MD})))
{SOLVE}
IMPR_RESU(FORMAT='RESULTAT', RESU=_F(RESULTAT=RESU, NOM_CHAM={FIELDS}, GROUP_NO='HAUT_BAS'))
FIN()
"""
BLOCK_CONTACT = """RAMPE = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0))
L_INST = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=1.0, NOMBRE=1))
CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='DISCRETE',{GLOBAL} ZONE=_F(GROUP_MA_MAIT='BAS_HAUT', GROUP_MA_ESCL='HAUT_BAS'{ALGO}))
RESU = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, CONTACT=CONT, EXCIT=_F(CHARGE=CL, FONC_MULT=RAMPE),
                     INCREMENT=_F(LIST_INST=L_INST){NEWTON})"""
BLOCK_LINEAR = "RESU = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CM, EXCIT=_F(CHARGE=CL))"
BLOCK_SNL = """RAMPE = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0))
L_INST = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=1.0, NOMBRE=1))
RESU = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=_F(CHARGE=CL, FONC_MULT=RAMPE), INCREMENT=_F(LIST_INST=L_INST))"""


def stella_run(stella, d, comm, msh):
    d.mkdir(exist_ok=True)
    (d / "case.comm").write_text(comm)
    (d / "case.export").write_text(f"P testlist bench\nF comm case.comm D 1\nF msh {msh} D 20\n"
                                   "F mess case.mess R 6\nF resu case.resu R 8\n")
    rc, wall, cpu = run([stella, "run", "case.export", "--quiet", "--work-dir", str(d / "work"),
                         "--output-dir", str(d)], d, d / "stella.log")
    return rc, wall, cpu


def command_times(mess, names=("STAT_NON_LINE", "MECA_STATIQUE")):
    """(cpu, elapsed) seconds of the first command among `names` in a message file."""
    current = None
    for line in Path(mess).read_text().splitlines():
        words = line.split()
        if line.lstrip().startswith("# Command #") and len(words) > 3:
            current = words[3]
        elif line.lstrip().startswith("# End of command") and current in names:
            return float(words[words.index("cpu:") + 1]), float(words[words.index("elapsed:") + 1])
    return None, None


def read_resu_block(path, field):
    """Last `field` block of a FORMAT='RESULTAT' file: {node name: {component: value}}."""
    lines = Path(path).read_text().splitlines()
    start = max(i for i, l in enumerate(lines) if f"CHAMP {field} " in l)
    i = start + 1
    while not lines[i].split() or lines[i].split()[0] != "NOEUD":
        i += 1
    names = lines[i].split()[1:]
    rows = {}
    for line in lines[i + 1:]:
        parts = line.split()
        if len(parts) != len(names) + 1:
            break
        if all(v == "-" for v in parts[1:]):
            continue  # a node outside the partial field
        rows[parts[0]] = {n: (float(v) if v != "-" else 0.0) for n, v in zip(names, parts[1:])}
    return rows


def nodal_pressure(points, rows, slave, tributary):
    names = [f"N{n + 1}" for n in slave]
    rn = np.array([rows[n]["RN"] for n in names])
    return rn / tributary


# The elastic matrix factorised once per step (NEWTON MATRICE='ELASTIQUE'): the same solution for
# these linear elastic bodies (dual contact adds nothing to the matrix), one factorisation
# instead of one per Newton iteration.
ELASTIC_MATRIX = ", NEWTON=_F(MATRICE='ELASTIQUE')"


def stella_hertz(work, stella, algo="", newton=""):
    msh = hertz_mesh(work)
    mesh = Mesh(msh)
    d = work / f"stella_hertz2d{'_gcp' if algo else ''}{'_elas' if newton else ''}"
    comm = HERTZ_COMM.format(E=E, NU=NU, MD=-D_HERTZ, ALGO=algo, GLOBAL=(" RESI_ABSO=1.0e-8," if algo else ""),
                             NEWTON=newton)
    rc, wall, cpu = stella_run(stella, d, comm, msh)
    rows = read_resu_block(d / "case.resu", "CONT_NOEU")
    slave = mesh.group_nodes("IND_CONT")
    x = mesh.points[slave][:, 0]
    order = np.argsort(x)
    slave, x = slave[order], x[order]
    xy = mesh.points[slave][:, :2]
    seg = np.linalg.norm(np.diff(xy, axis=0), axis=1)
    trib = np.zeros(len(slave))
    trib[:-1] += seg / 2
    trib[1:] += seg / 2
    p = nodal_pressure(mesh.points, rows, slave, trib)
    force = sum(abs(rows[f"N{n + 1}"]["RNY"]) for n in slave)
    used = np.unique(np.concatenate([c.ravel() for _n, _t, c in mesh.volume_cells(["BLOC", "IND"])]))
    solve_cpu, solve_wall = command_times(d / "case.mess")
    return dict(rc=rc, wall=wall, cpu=cpu, equations=2 * len(used), nodes=len(used), solve_cpu=solve_cpu,
                solve_wall=solve_wall, **hertz_errors(force, x, p))


def stella_block(work, stella, nb=23, nh=24, merged=None, algo="", newton=""):
    """merged: None (contact), 'linear' (bonded, MECA_STATIQUE) or 'snl' (bonded, STAT_NON_LINE)."""
    msh = block_mesh(work, nb, nh, merged is not None)
    mesh = Mesh(msh)
    solve = {"linear": BLOCK_LINEAR, "snl": BLOCK_SNL}.get(merged) or BLOCK_CONTACT.format(
        ALGO=algo, GLOBAL=(" RESI_ABSO=1.0e-9," if algo else ""), NEWTON=newton)
    fields = "'DEPL'" if merged else "('DEPL', 'CONT_NOEU')"
    tag = f"stella_block_{nb}_{nh}{'_' + merged if merged else ''}{'_gcp' if algo else ''}{'_elas' if newton else ''}"
    d = work / tag
    rc, wall, cpu = stella_run(stella, d, BLOCK_COMM.format(E=E, NU=NU, MD=-D_BLOCK, SOLVE=solve, FIELDS=fields), msh)
    slave = mesh.group_nodes("HAUT_BAS")
    disp = read_resu_block(d / "case.resu", "DEPL")
    uz = np.array([disp[f"N{n + 1}"]["DZ"] for n in slave])
    solve_cpu, solve_wall = command_times(d / "case.mess")
    out = dict(rc=rc, wall=wall, cpu=cpu, equations=3 * len(mesh.points), solve_cpu=solve_cpu,
               solve_wall=solve_wall)
    if merged:
        out["u_err"] = float(np.max(np.abs(uz + D_BLOCK / 2))) / (D_BLOCK / 2)
        return out
    rows = read_resu_block(d / "case.resu", "CONT_NOEU")
    h = 10.0 / nh
    xy = mesh.points[slave][:, :2]
    edge = (np.isclose(xy, 0.0) | np.isclose(xy, 10.0)).sum(axis=1)
    area = h * h / 2.0 ** edge
    press = np.array([rows[f"N{n + 1}"]["RN"] for n in slave]) / area
    force = sum(rows[f"N{n + 1}"]["RN"] for n in slave)
    out.update(block_errors(force, press, uz))
    return out


# ---------------------------------------------------------------- errors against the closed forms
def hertz_errors(half_force, x, p):
    total = 2.0 * half_force  # symmetric half model
    a = math.sqrt(4.0 * total * R_HERTZ / (math.pi * E_STAR))
    p0 = 2.0 * total / (math.pi * a)
    order = np.argsort(x)
    x, p = x[order], p[order]
    active = np.nonzero(p > 0)[0]
    last = active.max()
    a_fe = 0.5 * (x[last] + x[min(last + 1, len(x) - 1)])  # the contact edge lies between them
    h = x[min(last + 1, len(x) - 1)] - x[last]
    return dict(force=total, a=a, p0=p0, p0_fe=float(p[0]), p0_err=(p[0] - p0) / p0, a_fe=a_fe,
                a_err_elements=(a_fe - a) / h)


def block_errors(force, press, uz):
    f_exact = E * D_BLOCK / 20.0 * 100.0
    p_exact = E * D_BLOCK / 20.0
    return dict(force=force, f_err=(force - f_exact) / f_exact,
                p_err=float(np.max(np.abs(press - p_exact))) / p_exact,
                u_err=float(np.max(np.abs(uz + D_BLOCK / 2))) / (D_BLOCK / 2))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--stella", default=str(ROOT / "build/bin/stella"))
    ap.add_argument("--cases", default="hertz2d,block3d,overhead")
    ap.add_argument("--codes", default="ccx,stella")
    ap.add_argument("--work", default="/tmp/stella-ccx-bench")
    args = ap.parse_args()
    work = Path(args.work)
    work.mkdir(parents=True, exist_ok=True)
    cases, codes = args.cases.split(","), args.codes.split(",")
    stella = str(Path(args.stella).resolve())
    results = {}
    if "hertz2d" in cases:
        if "ccx" in codes:
            results["ccx hertz2d"] = ccx_hertz(work)
        if "stella" in codes:
            results["stella hertz2d"] = stella_hertz(work, stella)
            results["stella hertz2d GCP"] = stella_hertz(work, stella, algo=", ALGO_CONT='GCP'")
            results["stella hertz2d GCP, MATRICE='ELASTIQUE'"] = stella_hertz(work, stella, algo=", ALGO_CONT='GCP'",
                                                                             newton=ELASTIC_MATRIX)
    if "block3d" in cases:
        if "ccx" in codes:
            results["ccx block3d"] = ccx_block(work)
        if "stella" in codes:
            results["stella block3d"] = stella_block(work, stella)
            results["stella block3d GCP"] = stella_block(work, stella, algo=", ALGO_CONT='GCP'")
            results["stella block3d GCP, MATRICE='ELASTIQUE'"] = stella_block(work, stella, algo=", ALGO_CONT='GCP'",
                                                                             newton=ELASTIC_MATRIX)
    if "overhead" in cases:
        results["stella block 24/24 contact"] = stella_block(work, stella, 24, 24)
        results["stella block 24/24 contact GCP"] = stella_block(work, stella, 24, 24, algo=", ALGO_CONT='GCP'")
        results["stella block 24/24 bonded, MECA_STATIQUE"] = stella_block(work, stella, 24, 24, merged="linear")
        results["stella block 24/24 bonded, STAT_NON_LINE"] = stella_block(work, stella, 24, 24, merged="snl")
    for name, r in results.items():
        print(name, {k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})


if __name__ == "__main__":
    main()
