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
stella runs each contact case with the variants of --variants (VARIANTS below: the discrete
formulation's CONTRAINTE, GCP with RESI_ABSO 1e-8 mm for hertz2d and 1e-9 mm for block3d, 1e-8 and
1e-7 of the imposed displacements, GCP with the elastic matrix; the continuous formulation with the
contact status in the Newton loop or in a fixed-point loop); CalculiX with the contact pairs of
--ccx-types (surface to surface, node to surface). Each run's steps, Newton, contact and geometric
iterations are read from stella's message file; a Markdown table ends the output.
LAC (issue 17, doc/bench/lac-calculix.md): --variants lac,lac_scotch (block3d only: the slave
face cut by CREA_MAILLAGE/DECOUPE_LAC, one pressure per patch) against --ccx-types mortar
(CalculiX's TYPE=MORTAR); --block NB,NH changes the cubes; every CalculiX run is killed above
--ccx-memory-gib of resident memory (3 by default).
Usage: bench.py [--stella build/bin/stella] [--cases hertz2d,block3d,overhead] [--codes ccx,stella]
                [--variants contrainte,gcp,gcp_elas,continue,continue_pf,lac,lac_scotch]
                [--ccx-types s2s,n2s,mortar] [--block 23,24] [--ccx-memory-gib 3]
                [--repeats N|hertz2d:N,block3d:M] [--ccx-repeats ...] [--work /tmp/stella-ccx-bench]
Both codes run on one core (OMP_NUM_THREADS=1); times are wall-clock of the whole run (reading
the input, meshing data, solving, writing results) and the CPU time (user + sys) of the process.
"""
import argparse
import math
import os
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


# The peak resident memory (MiB) of the last run() and the resident-memory limit (GiB) of the
# CalculiX runs (--ccx-memory-gib): CalculiX 2.20's MORTAR contact on block3d grew past 21 GB of
# resident memory in its second iteration and was killed by the kernel (25 Nov 2026).
LAST_RSS_MB = [0.0]
CCX_MEMORY_GIB = [3.0]


def resident_gib(pid):
    try:
        for line in Path(f"/proc/{pid}/status").read_text().splitlines():
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 2**20
    except OSError:
        pass
    return 0.0


def run(cmd, cwd, log, memory_gib=None):
    """Runs cmd on one thread: (return code, wall s, CPU s of the process). With memory_gib, the
    process is killed (SIGKILL, return code -9) as soon as its resident memory passes it (polled
    every 0.2 s: an address-space limit would stop CalculiX at once, it reserves far more than it
    touches)."""
    env = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1")
    t0 = time.perf_counter()
    with open(log, "w") as out:
        p = subprocess.Popen(cmd, cwd=cwd, stdout=out, stderr=subprocess.STDOUT, env=env)
        while True:
            pid, status, usage = os.wait4(p.pid, os.WNOHANG if memory_gib else 0)
            if pid:
                break
            if resident_gib(p.pid) > memory_gib:
                p.kill()
                out.write(f"\nbench.py: killed, resident memory above {memory_gib} GiB\n")
            time.sleep(0.2)
        p.returncode = os.waitstatus_to_exitcode(status)
    wall = time.perf_counter() - t0
    LAST_RSS_MB[0] = usage.ru_maxrss / 1024.0
    return p.returncode, wall, usage.ru_utime + usage.ru_stime


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
CCX_TYPES = {"s2s": "SURFACE TO SURFACE", "n2s": "NODE TO SURFACE", "mortar": "MORTAR"}


def ccx_contact(slave, master, kind="s2s"):
    """CalculiX contact pair: kind 's2s' (surface-to-surface, the default of this bench) or 'n2s'
    (node-to-surface), on the same element-face surfaces. HARD: CalculiX's penalty with its
    default stiffness."""
    return f"""*SURFACE INTERACTION, NAME=SI
*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD
*CONTACT PAIR, INTERACTION=SI, TYPE={CCX_TYPES[kind]}
{slave}, {master}
"""


def ccx_hertz_body(kind="s2s"):
    """The hertz2d deck's contact, boundary conditions and step (also ccx_hertz_point.py's)."""
    return ccx_contact("CSLAVE", "CMASTER", kind) + f"""*BOUNDARY
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


def ccx_hertz(work, kind="s2s"):
    mesh = Mesh(hertz_mesh(work))
    body = ccx_hertz_body(kind)
    d = work / f"ccx_hertz2d_{kind}"
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


def ccx_block(work, nb=23, nh=24, kind="s2s"):
    mesh = Mesh(block_mesh(work, nb, nh))
    body = ccx_contact("CSLAVE", "CMASTER", kind) + f"""*BOUNDARY
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
    d = work / f"ccx_block_{nb}_{nh}_{kind}"
    d.mkdir(exist_ok=True)
    write_deck(mesh, d / "block.inp", ["BAS", "HAUT"], {"BAS": (E, NU), "HAUT": (E, NU)},
               ["SYM_X", "SYM_Y", "BAS_Z0", "HAUT_Z1", "HAUT_BAS"], {"CSLAVE": "HAUT_BAS", "CMASTER": "BAS_HAUT"},
               body)
    rc, wall, cpu = run(["ccx", "block"], d, d / "ccx.log", CCX_MEMORY_GIB[0])
    if rc != 0 or not (d / "block.dat").read_text().strip():
        return dict(rc=rc, wall=wall, cpu=cpu, rss_mb=LAST_RSS_MB[0], failed="no result (see ccx.log)")
    force = ccx_total_force(d / "block.dat")
    press = ccx_node_values(d / "block.frd", "CONTACT", 3)
    disp = ccx_node_values(d / "block.frd", "DISP", 2)
    slave = mesh.group_nodes("HAUT_BAS")
    return dict(rc=rc, wall=wall, cpu=cpu, rss_mb=LAST_RSS_MB[0], equations=ccx_equations(d / "ccx.log"),
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
CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='{FORMULATION}',{GLOBAL} ZONE=_F(GROUP_MA_MAIT='BLOC_TOP', GROUP_MA_ESCL='IND_CONT'{ALGO}))
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
CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='{FORMULATION}',{GLOBAL} ZONE=_F(GROUP_MA_MAIT='BAS_HAUT', GROUP_MA_ESCL='HAUT_BAS'{ALGO}))
RESU = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, CONTACT=CONT, EXCIT=_F(CHARGE=CL, FONC_MULT=RAMPE),
                     INCREMENT=_F(LIST_INST=L_INST){NEWTON})"""
# LAC (issue 17): the cells of the upper block under its contact face HAUT_BAS cut by
# CREA_MAILLAGE/DECOUPE_LAC (DECOUPE_HEXA='PYRA', the default: each slave QUAD4 becomes a patch of
# four triangles around a new centre node carrying the patch's LAGS_C), mortar pairing, one
# pressure per patch, the LAC defaults ALGO_RESO_GEOM = ALGO_RESO_CONT = 'NEWTON', CONTACT_INIT='OUI'.
BLOCK_LAC_COMM = """DEBUT()
M0 = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
MA = CREA_MAILLAGE(MAILLAGE=M0, DECOUPE_LAC=_F(GROUP_MA_ESCL='HAUT_BAS'))
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(GROUP_MA=('BAS', 'HAUT'), PHENOMENE='MECANIQUE', MODELISATION='3D'))
ACIER = DEFI_MATERIAU(ELAS=_F(E={E}, NU={NU}))
CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=ACIER))
CL = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='SYM_X', DX=0.0), _F(GROUP_MA='SYM_Y', DY=0.0),
                                          _F(GROUP_MA='BAS_Z0', DZ=0.0), _F(GROUP_MA='HAUT_Z1', DZ={MD})))
RAMPE = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0))
L_INST = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=1.0, NOMBRE=1))
CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE', ALGO_RESO_GEOM='NEWTON', ALGO_RESO_CONT='NEWTON',
                    ZONE=_F(GROUP_MA_MAIT='BAS_HAUT', GROUP_MA_ESCL='HAUT_BAS', ALGO_CONT='LAC',
                            APPARIEMENT='MORTAR', CONTACT_INIT='OUI'))
RESU = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, CONTACT=CONT, EXCIT=_F(CHARGE=CL, FONC_MULT=RAMPE),
                     INCREMENT=_F(LIST_INST=L_INST){NEWTON})
IMPR_RESU(FORMAT='RESULTAT', RESU=_F(RESULTAT=RESU, NOM_CHAM='DEPL', GROUP_MA='HAUT_BAS'))
FIN()
"""
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


def iterations(mess):
    """Steps, Newton, contact and geometric iterations summed over a message file (the lines
    `stella sweep` reads too: `step k ...: converged in n iteration(s)` and `contact: g geometric
    iteration(s), c contact iteration(s)`), and the STAT_NON_LINE phase line."""
    steps = newton = contact = geom = 0
    phases = ""
    for line in Path(mess).read_text().splitlines():
        if line.startswith("   step ") and ": converged in " in line:
            steps += 1
            newton += int(line.split(": converged in ")[1].split()[0])
        elif line.startswith("   contact: ") and " geometric iteration(s)" in line:
            geom += int(line.split()[1])
            contact += int(line.split(", ")[1].split()[0])
        elif line.startswith("   phases (s): "):
            phases = line.strip()[len("phases (s): "):]
    return dict(steps=steps, newton=newton, contact_iter=contact, geom_iter=geom, phases=phases)


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


def resu_component(path, field, component):
    """The values of one component of the last `field` block of a FORMAT='RESULTAT' file, at the
    nodes where it is defined (LAGS_C: the nodes carrying a multiplier)."""
    lines = Path(path).read_text().splitlines()
    start = max(i for i, l in enumerate(lines) if f"CHAMP {field} " in l)
    i = start + 1
    while not lines[i].split() or lines[i].split()[0] != "NOEUD":
        i += 1
    names = lines[i].split()[1:]
    k = names.index(component)
    values = []
    for line in lines[i + 1:]:
        parts = line.split()
        if len(parts) != len(names) + 1:
            break
        if parts[1 + k] != "-":
            values.append(float(parts[1 + k]))
    return values


def nodal_pressure(points, rows, slave, tributary):
    names = [f"N{n + 1}" for n in slave]
    rn = np.array([rows[n]["RN"] for n in names])
    return rn / tributary


# The elastic matrix factorised once per step (NEWTON MATRICE='ELASTIQUE'): the same solution for
# these linear elastic bodies (dual contact adds nothing to the matrix), one factorisation
# instead of one per Newton iteration.
ELASTIC_MATRIX = ", NEWTON=_F(MATRICE='ELASTIQUE')"

# stella variants selectable with --variants: (FORMULATION, keywords of the ZONE, of DEFI_CONTACT,
# of STAT_NON_LINE). The continuous formulation (issue 16): augmented Lagrangian (ALGO_CONT
# 'STANDARD', COEF_CONT 100 by default), CONTACT_INIT='OUI', node integration (INTEGRATION
# 'AUTO': node-to-segment, as the discrete formulation), the contact status in the Newton loop
# (ALGO_RESO_CONT='NEWTON', the default) or in a fixed-point loop ('POINT_FIXE'); the geometry in a
# fixed-point loop (ALGO_RESO_GEOM='POINT_FIXE', the default: 'NEWTON' is refused with CONTINUE,
# CONTACT_20 "not implemented yet").
# ITER_GLOB_MAXI=30: the one-step hertz2d run needs more than the default 10 Newton iterations
# from a point contact; it is a cap, not a cost (the table gives the iterations made).
_CONT = ", ALGO_CONT='STANDARD', CONTACT_INIT='OUI'"
_ITER = ", CONVERGENCE=_F(ITER_GLOB_MAXI=30)"
VARIANTS = {
    "contrainte": ("DISCRETE", "", "", ""),
    "gcp": ("DISCRETE", ", ALGO_CONT='GCP'", None, ""),
    "gcp_elas": ("DISCRETE", ", ALGO_CONT='GCP'", None, ELASTIC_MATRIX),
    "continue": ("CONTINUE", _CONT, "", _ITER),
    "continue_pf": ("CONTINUE", _CONT, " ALGO_RESO_CONT='POINT_FIXE',", _ITER),
    # block3d only: LAC (BLOCK_LAC_COMM) with the defaults (MUMPS, RENUM='AUTO') and with MUMPS and
    # the SCOTCH nested-dissection ordering
    "lac": ("CONTINUE", "", "", ""),
    "lac_scotch": ("CONTINUE", "", "", ", SOLVEUR=_F(METHODE='MUMPS', RENUM='SCOTCH')"),
}
LAC_VARIANTS = ("lac", "lac_scotch")


def stella_hertz(work, stella, algo="", newton="", variant=None):
    """variant: a key of VARIANTS (FORMULATION, the ZONE's keywords, DEFI_CONTACT's, STAT_NON_LINE's);
    without it, the discrete formulation with `algo` and `newton` as before."""
    if variant in LAC_VARIANTS:
        raise SystemExit(f"--variants {variant}: LAC runs block3d only (the LAC Hertz cases are "
                         "testcases/hertz_cylinder and hertz_sphere)")
    msh = hertz_mesh(work)
    mesh = Mesh(msh)
    if variant:
        form, algo, glob, newton = VARIANTS[variant]
        glob = " RESI_ABSO=1.0e-8," if glob is None else glob
        d = work / f"stella_hertz2d_{variant}"
    else:
        form, glob = "DISCRETE", (" RESI_ABSO=1.0e-8," if algo else "")
        d = work / f"stella_hertz2d{'_gcp' if algo else ''}{'_elas' if newton else ''}"
    comm = HERTZ_COMM.format(E=E, NU=NU, MD=-D_HERTZ, ALGO=algo, GLOBAL=glob, NEWTON=newton, FORMULATION=form)
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
                solve_wall=solve_wall, **iterations(d / "case.mess"), **hertz_errors(force, x, p))


def stella_block(work, stella, nb=23, nh=24, merged=None, algo="", newton="", variant=None):
    """merged: None (contact), 'linear' (bonded, MECA_STATIQUE) or 'snl' (bonded, STAT_NON_LINE).
    variant: a key of VARIANTS, as for stella_hertz."""
    msh = block_mesh(work, nb, nh, merged is not None)
    mesh = Mesh(msh)
    form, glob = "DISCRETE", (" RESI_ABSO=1.0e-9," if algo else "")
    if variant:
        form, algo, glob, newton = VARIANTS[variant]
        glob = " RESI_ABSO=1.0e-9," if glob is None else glob
    solve = {"linear": BLOCK_LINEAR, "snl": BLOCK_SNL}.get(merged) or BLOCK_CONTACT.format(
        ALGO=algo, GLOBAL=glob, NEWTON=newton, FORMULATION=form)
    fields = "'DEPL'" if merged else "('DEPL', 'CONT_NOEU')"
    comm = BLOCK_COMM.format(E=E, NU=NU, MD=-D_BLOCK, SOLVE=solve, FIELDS=fields)
    if variant in LAC_VARIANTS:
        comm = BLOCK_LAC_COMM.format(E=E, NU=NU, MD=-D_BLOCK, NEWTON=newton)
    tag = f"stella_block_{nb}_{nh}{'_' + merged if merged else ''}{'_gcp' if algo else ''}{'_elas' if newton else ''}"
    if variant:
        tag = f"stella_block_{nb}_{nh}_{variant}"
    d = work / tag
    rc, wall, cpu = stella_run(stella, d, comm, msh)
    rss = LAST_RSS_MB[0]
    slave = mesh.group_nodes("HAUT_BAS")
    disp = read_resu_block(d / "case.resu", "DEPL")
    uz = np.array([disp[f"N{n + 1}"]["DZ"] for n in slave])
    solve_cpu, solve_wall = command_times(d / "case.mess")
    out = dict(rc=rc, wall=wall, cpu=cpu, rss_mb=rss, equations=3 * len(mesh.points), solve_cpu=solve_cpu,
               solve_wall=solve_wall)
    if merged:
        out["u_err"] = float(np.max(np.abs(uz + D_BLOCK / 2))) / (D_BLOCK / 2)
        return out
    out.update(iterations(d / "case.mess"))
    if variant in LAC_VARIANTS:
        # one pressure per patch (LAGS_C, negative in compression) on the patch's centre node; each
        # patch is one slave QUAD4 of side h: force = sum of -LAGS_C h^2
        lags = np.array(resu_component(d / "case.resu", "DEPL", "LAGS_C"))
        h = 10.0 / nh
        out["patches"] = len(lags)
        out.update(block_errors(float(np.sum(-lags)) * h * h, -lags, uz))
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


def repeated(n, fn, *a, **k):
    """fn run n times; the result of the run of median CPU time, with the CPU times of all runs."""
    runs = sorted((fn(*a, **k) for _ in range(n)), key=lambda r: r["cpu"])
    out = dict(runs[len(runs) // 2])
    out["cpu_runs"] = " ".join(f"{r['cpu']:.3g}" for r in runs)
    return out


def summary(results):
    """Markdown table: CPU (median), ratio CalculiX / stella per case, iterations and errors."""
    print("\n| case | run | CPU s (median; all runs) | CalculiX s2s CPU / this | steps | Newton | contact it. "
          "| geom. it. | errors |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name, r in results.items():
        case = "hertz2d" if "hertz2d" in name else "block3d" if "block3d" in name else "overhead"
        ref = results.get(f"ccx {case} s2s")
        ratio = f"{ref['cpu'] / r['cpu']:.2f}" if ref and r.get("cpu") else ""
        errs = ", ".join(f"{k} {r[k]:+.3g}" for k in ("p0_err", "a_err_elements", "f_err", "p_err", "u_err") if k in r)
        print(f"| {case} | {name} | {r['cpu']:.3g} ({r.get('cpu_runs', '')}) | {ratio} | {r.get('steps', '')} "
              f"| {r.get('newton', '')} | {r.get('contact_iter', '')} | {r.get('geom_iter', '')} | {errs} |")


def per_case(text):
    """'3' (every case) or 'hertz2d:3,block3d:1' -> {case: runs}."""
    if ":" not in text:
        return {c: int(text) for c in ("hertz2d", "block3d")}
    return {c: int(v) for c, v in (x.split(":") for x in text.split(","))}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--stella", default=str(ROOT / "build/bin/stella"))
    ap.add_argument("--cases", default="hertz2d,block3d,overhead")
    ap.add_argument("--codes", default="ccx,stella")
    ap.add_argument("--variants", default="contrainte,gcp,gcp_elas",
                    help="stella runs of hertz2d and block3d, keys of VARIANTS: " + ",".join(VARIANTS))
    ap.add_argument("--ccx-types", default="s2s", help="CalculiX contact pairs: s2s (surface to surface), n2s "
                    "(node to surface)")
    ap.add_argument("--repeats", default="1", help="runs of each stella point, one value or one per case "
                    "(hertz2d:3,block3d:1); the median CPU time is reported")
    ap.add_argument("--ccx-repeats", default="1", help="runs of each CalculiX point, one value or one per case "
                    "(hertz2d:3,block3d:1)")
    ap.add_argument("--work", default="/tmp/stella-ccx-bench")
    ap.add_argument("--block", default="23,24", help="block3d: cells per side of the lower (master) and "
                    "upper (slave) cubes")
    ap.add_argument("--ccx-memory-gib", type=float, default=3.0, help="resident-memory limit of each CalculiX "
                    "run (GiB; 0: none): killed above it")
    args = ap.parse_args()
    work = Path(args.work)
    work.mkdir(parents=True, exist_ok=True)
    cases, codes = args.cases.split(","), args.codes.split(",")
    variants, kinds = args.variants.split(","), args.ccx_types.split(",")
    stella_n, ccx_n = per_case(args.repeats), per_case(args.ccx_repeats)
    stella = str(Path(args.stella).resolve())
    results = {}

    def report(name, r):
        results[name] = r
        print(name, {k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()}, flush=True)

    CCX_MEMORY_GIB[0] = args.ccx_memory_gib
    nb, nh = (int(v) for v in args.block.split(","))
    sizes = {"hertz2d": {}, "block3d": dict(nb=nb, nh=nh)}
    for case, ccx_fn, stella_fn in (("hertz2d", ccx_hertz, stella_hertz), ("block3d", ccx_block, stella_block)):
        if case not in cases:
            continue
        if "ccx" in codes:
            for kind in kinds:
                report(f"ccx {case} {kind}", repeated(ccx_n.get(case, 1), ccx_fn, work, kind=kind, **sizes[case]))
        if "stella" in codes:
            for v in variants:
                report(f"stella {case} {v}", repeated(stella_n.get(case, 1), stella_fn, work, stella, variant=v,
                                                      **sizes[case]))
    if "overhead" in cases:
        report("stella block 24/24 contact", stella_block(work, stella, 24, 24))
        report("stella block 24/24 contact GCP", stella_block(work, stella, 24, 24, algo=", ALGO_CONT='GCP'"))
        report("stella block 24/24 bonded, MECA_STATIQUE", stella_block(work, stella, 24, 24, merged="linear"))
        report("stella block 24/24 bonded, STAT_NON_LINE", stella_block(work, stella, 24, 24, merged="snl"))
    summary(results)


if __name__ == "__main__":
    main()
