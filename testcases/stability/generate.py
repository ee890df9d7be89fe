#!/usr/bin/env python3
"""Writes the generated stability cases of testcases/stability/ (issue 19): one structured mesh
(Gmsh 2.2 ASCII, written here, no gmsh needed), one command file and one export per case, all
from the templates below. Run from anywhere: /usr/bin/python3 testcases/stability/generate.py
(it rewrites the files named gen_*; the hand-written cases are left alone).

Every case is a plane-strain (D_PLAN) stack of two blocks: LOW, below y = 0 (its bottom BAS held),
and UP, above, pressed on LOW by a pressure p on its top UP_TOP (or driven by imposed
displacements). With NU = 0 and DX of UP held (or frictionless sliding), the exact solution is a
uniform uniaxial state, which linear cells reproduce exactly: the closed forms below are exact
for the discrete problem too, so tolerances only cover round-off (condition number x 1e-16) or,
for penalties, nothing at all (the penetration p W / (2 E_N) of a one-cell-wide slave is in the
closed form). The reference of each case is computed here and written into its TEST_RESU."""

import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


# ---------------------------------------------------------------- meshes
class Mesh:
    def __init__(self):
        self.nodes = []  # (x, y)
        self.cells = []  # (gmsh type, physical name, node ids (1-based))
        self.names = []

    def node(self, x, y):
        self.nodes.append((x, y))
        return len(self.nodes)

    def cell(self, kind, name, ids):
        if name not in self.names:
            self.names.append(name)
        self.cells.append((kind, name, ids))

    def block(self, x0, y0, w, h, nx, ny, name, edges, split_bottom=None):
        """nx x ny QUAD4 cells; edges = names of (bottom, right, top, left) or None; split_bottom =
        (x, name_in, name_out): bottom segments right of x get name_out."""
        ids = [[self.node(x0 + w * i / nx, y0 + h * j / ny) for i in range(nx + 1)] for j in range(ny + 1)]
        for j in range(ny):
            for i in range(nx):
                self.cell(3, name, (ids[j][i], ids[j][i + 1], ids[j + 1][i + 1], ids[j + 1][i]))
        bottom, right, top, left = edges
        for i in range(nx):
            if bottom:
                label = bottom
                if split_bottom and x0 + w * (i + 0.5) / nx > split_bottom[0]:
                    label = split_bottom[1]
                self.cell(1, label, (ids[0][i], ids[0][i + 1]))
            if top:
                self.cell(1, top, (ids[ny][i + 1], ids[ny][i]))
        for j in range(ny):
            if right:
                self.cell(1, right, (ids[j][nx], ids[j + 1][nx]))
            if left:
                self.cell(1, left, (ids[j + 1][0], ids[j][0]))
        return ids

    def write(self, path):
        tag = {n: k + 1 for k, n in enumerate(self.names)}
        dim = {1: 1, 3: 2, 15: 0}
        with open(path, "w") as f:
            f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n%d\n" % len(self.names))
            for n in self.names:
                kind = next(c[0] for c in self.cells if c[1] == n)
                f.write('%d %d "%s"\n' % (dim[kind], tag[n], n))
            f.write("$EndPhysicalNames\n$Nodes\n%d\n" % len(self.nodes))
            for k, (x, y) in enumerate(self.nodes):
                f.write("%d %r %r 0\n" % (k + 1, x, y))
            f.write("$EndNodes\n$Elements\n%d\n" % len(self.cells))
            for k, (kind, name, ids) in enumerate(self.cells):
                f.write("%d %d 2 %d %d %s\n" % (k + 1, kind, tag[name], tag[name], " ".join(map(str, ids))))
            f.write("$EndElements\n")


def stack_mesh(w_low, h_low, nx_low, ny_low, w_up, h_up, nx_up, ny_up, x_up=0.0, gap=0.0, split=None,
               spring=False):
    m = Mesh()
    m.block(0.0, -h_low, w_low, h_low, nx_low, ny_low, "LOW", ("BAS", "LOW_RIGHT", "LOW_TOP", "LOW_LEFT"))
    ids = m.block(x_up, gap, w_up, h_up, nx_up, ny_up, "UP", ("UP_BOT", "UP_RIGHT", "UP_TOP", "UP_LEFT"),
                  split_bottom=(split, "UP_BOT", "UP_OUT") if split is not None else None)
    if spring:
        m.cell(15, "SPRING", (ids[ny_up][0],))
    return m


# ---------------------------------------------------------------- command files
HEAD = """DEBUT()
MA = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
MA = MODI_MAILLAGE(reuse=MA, MAILLAGE=MA, ORIE_PEAU=_F(GROUP_MA_PEAU=({skins})))
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=({model}))
M_LOW = DEFI_MATERIAU(ELAS=_F(E={e_low!r}, NU={nu_low!r}))
M_UP = DEFI_MATERIAU(ELAS=_F(E={e_up!r}, NU={nu_up!r}))
CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=(_F(GROUP_MA='LOW', MATER=M_LOW), _F(GROUP_MA='UP', MATER=M_UP)))
"""


def fmt_kw(d):
    return ", ".join("%s=%r" % (k, v) for k, v in d.items())


def test_depl(group, cmp, value, tol, inst=1.0, kinds=("MIN", "MAX"), legend=""):
    """TEST_RESU of DEPL on a node group (every node has the closed-form value)."""
    out = []
    for kind in kinds:
        crit = "RELATIF" if value != 0.0 else "ABSOLU"
        out.append(
            "TEST_RESU(RESU=_F(RESULTAT=RESU, INST=%r, NOM_CHAM='DEPL', NOM_CMP='%s', GROUP_NO='%s', "
            "TYPE_TEST='%s', VALE_CALC=%r, TOLE_MACHINE=%r, CRITERE='%s', REFERENCE='ANALYTIQUE', VALE_REFE=%r, "
            "PRECISION=%r, LEGENDE=%r))" % (inst, cmp, group, kind, value, tol, crit, value, tol, legend))
    return out


def test_sum(field, group, cmp, value, tol, inst=1.0, legend="", scale=None):
    """A sum over a node group; a zero value is tested in absolute, tol x scale."""
    crit = "RELATIF" if value != 0.0 else "ABSOLU"
    if value == 0.0:
        tol = tol * scale
    extra = ", ORDRE_GRANDEUR=%r" % scale if scale and value == 0.0 else ""
    return ["TEST_RESU(RESU=_F(RESULTAT=RESU, INST=%r, NOM_CHAM='%s', NOM_CMP='%s', GROUP_NO='%s', "
            "TYPE_TEST='SOMM', VALE_CALC=%r, TOLE_MACHINE=%r, CRITERE='%s', REFERENCE='ANALYTIQUE', VALE_REFE=%r, "
            "PRECISION=%r%s, LEGENDE=%r))" % (inst, field, cmp, group, value, tol, crit, value, tol, extra, legend)]


CASES = []  # (name, comment, comm text, mesh name, README row)


def case(name, comment, mesh, comm, row):
    CASES.append((name, comment, comm, mesh, row))


def zone(algo, e_n=None, slave="'UP_BOT'", extra=None):
    z = {"GROUP_MA_MAIT": "LOW_TOP"}
    text = "_F(GROUP_MA_MAIT='LOW_TOP', GROUP_MA_ESCL=%s, ALGO_CONT='%s'" % (slave, algo)
    if e_n is not None:
        text += ", E_N=%r" % e_n
    if extra:
        text += ", " + extra
    del z
    return text + ")"


def pressed_stack(name, why, mesh, e_low, e_up, strain, h_low, h_up, w_up, algo, e_n=None, tol=1e-9,
                  contact_kw="", low_fixed=False, lengths="m", extra_zone=None, slave="'UP_BOT'",
                  test_groups=("UP_BOT", "LOW_TOP"), slave_cells=1, cine=False, continuous=False):
    """UP pressed on LOW by the imposed DY = -d of its top (d = strain x (h_low + h_up)), NU = 0,
    DX of UP held: uniform uniaxial stress s, d = s (h_low / e_low + h_up / e_up + W / (2 E_N)) (the
    last term for a penalty on a one-cell-wide UP: both slave nodes carry s W / 2)."""
    d = strain * (h_low + h_up)
    compliance = (0.0 if low_fixed else h_low / e_low) + h_up / e_up
    # penetration per unit stress: the interior slave nodes carry s W / n (n = slave_cells > 1)
    pen = w_up / (max(2, slave_cells) * e_n) if algo == "PENALISATION" else 0.0
    if continuous:  # FORMULATION='CONTINUE': LAGS_C = COEF_PENA_CONT min(gap, 0), a pressure law
        pen = 1.0 / e_n if algo == "PENALISATION" else 0.0
    s = d / (compliance + pen)
    d_low = -s * h_low / e_low if not low_fixed else 0.0
    d_upbot = d_low - s * pen
    bc_low = "_F(GROUP_MA='LOW', DX=0.0, DY=0.0)" if low_fixed else "_F(GROUP_MA='BAS', DX=0.0, DY=0.0)"
    comm = HEAD.format(skins="'LOW_TOP', 'UP_BOT'" + (", 'UP_OUT'" if "UP_OUT" in slave else ""),
                       model="_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'),",
                       e_low=e_low, nu_low=0.0, e_up=e_up, nu_up=0.0)
    if cine:  # eliminated, not dualised: 2 x 10 001 fewer Lagrange multipliers
        comm += "BC = AFFE_CHAR_CINE(MODELE=MO, MECA_IMPO=(%s, _F(GROUP_MA='UP', DX=0.0)))\n" % bc_low
    else:
        comm += "BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(%s, _F(GROUP_MA='UP', DX=0.0)))\n" % bc_low
    comm += "LOAD = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='UP_TOP', DY=%r))\n" % (-d)
    comm += "RAMP = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0))\n"
    comm += "L_INST = DEFI_LIST_REEL(VALE=(0.0, 1.0))\n"
    if continuous:
        law = ", COEF_PENA_CONT=%r" % e_n if algo == "PENALISATION" else ""
        comm += ("CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='CONTINUE'%s, ZONE=_F(GROUP_MA_MAIT='LOW_TOP', "
                 "GROUP_MA_ESCL=%s, ALGO_CONT='%s'%s, CONTACT_INIT='OUI'))\n" % (contact_kw, slave, algo, law))
    else:
        comm += "CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='DISCRETE'%s, ZONE=(%s,))\n" % (
            contact_kw, zone(algo, e_n, slave, extra_zone))
    comm += ("RESU = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, CONTACT=CONT, EXCIT=(_F(CHARGE=BC), "
             "_F(CHARGE=LOAD, FONC_MULT=RAMP)), INCREMENT=_F(LIST_INST=L_INST))\n")
    tests = []
    refs = {"UP_BOT": d_upbot, "LOW_TOP": d_low}
    for g in test_groups:
        if low_fixed and g == "LOW_TOP":
            continue
        # (many penalised slave nodes: the two end nodes carry half a node's force, penetrate half
        # as much: the interior value is the minimum)
        kinds = ("MIN",) if algo == "PENALISATION" and slave_cells > 1 and g == "UP_BOT" else ("MIN", "MAX")
        tests += test_depl(g, "DY", refs[g], tol if refs[g] != 0.0 else tol * d, kinds=kinds)
    # the master pushes the slave up with s W in total
    tests += test_sum("CONT_NOEU", "UP_BOT", "RY", s * w_up, tol)
    comm += "\n".join(tests) + "\nFIN()\n"
    law = " + W/(max(2, n) E_N), n slave cells" if pen else ""
    if continuous and pen:
        law = " + 1/COEF_PENA_CONT"
    ref = "contact resultant s W = %.6g, DY(UP_BOT) = %.6g %s (d = s (H/E per block%s))" % (
        s * w_up, d_upbot, lengths, law)
    case(name, why, mesh, comm, (why, ref, "%g relative" % tol))


def header(skins, e_low, nu_low, e_up, nu_up, modelisation="D_PLAN", springs=False):
    model = "_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='%s')," % modelisation
    if springs:
        model += " _F(GROUP_MA='SPRING', PHENOMENE='MECANIQUE', MODELISATION='2D_DIS_T'),"
    return HEAD.format(skins=skins, model=model, e_low=e_low, nu_low=nu_low, e_up=e_up, nu_up=nu_up)


def function(name, points):
    return "%s = DEFI_FONCTION(NOM_PARA='INST', VALE=(%s))\n" % (
        name, ", ".join("%r, %r" % (t, v) for t, v in points))


def interp(points, t):
    for (t0, v0), (t1, v1) in zip(points, points[1:]):
        if t0 <= t <= t1:
            return v0 + (v1 - v0) * (t - t0) / (t1 - t0)
    raise ValueError(t)


def instants(t_end, dt):
    n = int(round(t_end / dt))
    return [k * dt for k in range(n + 1)]


def snl(loads, inst, extra=""):
    return ("L_INST = DEFI_LIST_REEL(VALE=(%s))\n" % ", ".join(repr(t) for t in inst) +
            "RESU = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, CONTACT=CONT, EXCIT=(%s), "
            "INCREMENT=_F(LIST_INST=L_INST)%s)\n" % (loads, extra))


def friction_case(name, why, mesh, mu, shear_points, t_end, test_times):
    """A stiff block (E = 2.1e11) pressed by DY = -d of its top on a fixed master, then its top
    moved by DX(t); penalised normal and Coulomb friction E_N = E_T = 1e4 on n = 5 slave nodes:
    N = n E_N d; the friction force follows the 1D elastic-perfectly-plastic law of stiffness
    n E_T and limit mu N (exact at the instants, the reversals being instants)."""
    n, e_n, d, a = 5, 1.0e4, 0.01, 6.0e-3
    big_n = n * e_n * d
    comm = header("'LOW_TOP', 'UP_BOT'", 2.1e11, 0.3, 2.1e11, 0.3)
    comm += "BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='LOW', DX=0.0, DY=0.0))\n"
    comm += "PRESSE = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='UP_TOP', DY=%r))\n" % (-d)
    comm += "CISAILLE = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='UP_TOP', DX=%r))\n" % a
    comm += function("F_N", [(0.0, 0.0), (1.0, 1.0), (t_end, 1.0)])
    comm += function("F_T", shear_points)
    comm += ("CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='DISCRETE', FROTTEMENT='COULOMB', ZONE=_F("
             "GROUP_MA_MAIT='LOW_TOP', GROUP_MA_ESCL='UP_BOT', ALGO_CONT='PENALISATION', E_N=%r, "
             "ALGO_FROT='PENALISATION', E_T=%r, COULOMB=%r))\n" % (e_n, e_n, mu))
    inst = instants(t_end, 0.25)
    comm += snl("_F(CHARGE=BC), _F(CHARGE=PRESSE, FONC_MULT=F_N), _F(CHARGE=CISAILLE, FONC_MULT=F_T)", inst,
                ", CONVERGENCE=_F(ITER_GLOB_MAXI=30)")
    friction, u_prev, history = 0.0, 0.0, {}
    for t in inst:
        u = a * interp(shear_points, t)
        friction = max(-mu * big_n, min(mu * big_n, friction + n * e_n * (u - u_prev)))
        u_prev = u
        history[t] = friction if abs(friction) > 1e-9 * big_n else 0.0
    tests = []
    tol = 1e-5  # the block is 4e6 times stiffer than the n penalty springs
    for t in test_times:
        tests += test_sum("CONT_NOEU", "UP_BOT", "RY", big_n, tol, inst=t)
        tests += test_sum("CONT_NOEU", "UP_BOT", "RX", -history[t], tol, inst=t, scale=big_n)
    comm += "\n".join(tests) + "\nFIN()\n"
    ref = "N = n E_N d = %g; friction force (INST: value) %s" % (
        big_n, ", ".join("%g: %g" % (t, history[t]) for t in test_times))
    case(name, why, mesh, comm, (why, ref, "%g relative (block / penalty stiffness 4e6)" % tol))


def more_cases(mesh):
    four = "gen_stack4.msh"
    # friction mu = 0, 0.3, 1: pressed, then sheared from t = 1 to 3 (DX up to 6e-3)
    for mu, tag in ((0.0, "0"), (0.3, "03"), (1.0, "1")):
        friction_case("gen_friction_mu%s" % tag, "penalised Coulomb friction COULOMB = %g: stick, then %s" % (
            mu, "slip" if mu < 0.5 else "stick all along"), four, mu, [(0.0, 0.0), (1.0, 0.0), (3.0, 1.0)], 3.0,
            (1.0, 1.5, 2.5, 3.0))
    friction_case("gen_stick_slip_cycle", "stick-slip reversal: cyclic DX +-6e-3 (t = 1..7), COULOMB = 0.3", four,
                  0.3, [(0.0, 0.0), (1.0, 0.0), (2.0, 1.0), (4.0, -1.0), (6.0, 1.0), (7.0, 0.0)], 7.0,
                  (1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 5.0, 6.0, 6.5, 7.0))
    # flip-flop: closed, open (lift-off by +d), closed again; CONTRAINTE, deformable master
    d, e = 2.0e-5, 2.1e11
    pts = [(0.0, 0.0), (1.0, -1.0), (2.0, 1.0), (3.0, -1.0)]
    comm = header("'LOW_TOP', 'UP_BOT'", e, 0.0, e, 0.0)
    comm += "BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='BAS', DX=0.0, DY=0.0), _F(GROUP_MA='UP', DX=0.0)))\n"
    comm += "LOAD = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='UP_TOP', DY=%r))\n" % d
    comm += function("F_Y", pts)
    comm += ("CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='DISCRETE', ZONE=_F(GROUP_MA_MAIT='LOW_TOP', "
             "GROUP_MA_ESCL='UP_BOT', ALGO_CONT='CONTRAINTE'))\n")
    inst = instants(3.0, 0.5)
    comm += snl("_F(CHARGE=BC), _F(CHARGE=LOAD, FONC_MULT=F_Y)", inst)
    tests = []
    for t in inst[1:]:
        f = interp(pts, t)
        s = -f * d / (2.0 / e) if f < 0 else 0.0
        dy = -s / e if f < 0 else f * d
        tests += test_depl("UP_BOT", "DY", dy, 1e-9 if dy != 0.0 else 1e-9 * d, inst=t)
        tests += test_sum("CONT_NOEU", "UP_BOT", "RY", s, 1e-9, inst=t, scale=d * e / 2.0)
    comm += "\n".join(tests) + "\nFIN()\n"
    case("gen_flip_flop", "contact closed, touching with zero force (t = 1.5), open (lift-off), closed again",
         four, comm, ("contact closed, touching with zero force (t = 1.5), open (lift-off), closed again",
                      "closed: s = d / (H/E + H/E), DY(UP_BOT) = -s H/E; open: DY(UP_BOT) = lift, no force",
                      "1e-9 relative"))
    # grazing: UP slid by 0.1 along LOW at zero gap, no normal load (every force zero), the last
    # slave node beyond the master's edge
    for algo, extra in (("CONTRAINTE", ""), ("PENALISATION", ", E_N=1e12")):
        comm = header("'LOW_TOP', 'UP_BOT'", e, 0.0, e, 0.0)
        comm += ("BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='BAS', DX=0.0, DY=0.0), "
                 "_F(GROUP_MA='UP_TOP', DY=0.0)))\n")
        comm += "SLIDE = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='UP', DX=0.1))\n"
        comm += function("RAMP", [(0.0, 0.0), (1.0, 1.0)])
        comm += ("CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='DISCRETE', ZONE=_F(GROUP_MA_MAIT='LOW_TOP', "
                 "GROUP_MA_ESCL='UP_BOT', ALGO_CONT='%s'%s))\n" % (algo, extra))
        comm += snl("_F(CHARGE=BC), _F(CHARGE=SLIDE, FONC_MULT=RAMP)", [0.0, 0.5, 1.0],
                    ", CONVERGENCE=_F(RESI_GLOB_MAXI=1.0e-3)")
        tests = []
        for t in (0.5, 1.0):
            tests += test_depl("UP_BOT", "DY", 0.0, 1e-15, inst=t)
            tests += test_depl("UP_BOT", "DX", 0.1 * t, 1e-12, inst=t)
            tests += test_sum("CONT_NOEU", "UP_BOT", "RY", 0.0, 1e-12, inst=t, scale=1.0e6)
        comm += "\n".join(tests) + "\nFIN()\n"
        why = "grazing, %s: sliding at zero gap with zero normal force, a slave node off the master's edge" % algo
        case("gen_grazing_%s" % algo.lower(), why, four, comm,
             (why, "DY = 0, contact forces 0 (|RY| < 1e-6 N), DX = the slide", "1e-15 m, 1e-6 N absolute"))
    # sliding off the master's edge under load: stiff UP, penalties E_N = 1e4 on a fixed master
    e_n, d = 1.0e4, 0.01
    comm = header("'LOW_TOP', 'UP_BOT'", e, 0.0, e, 0.0)
    comm += "BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='LOW', DX=0.0, DY=0.0))\n"
    comm += "PRESSE = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='UP_TOP', DY=%r))\n" % (-d)
    comm += "SLIDE = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='UP', DX=0.5))\n"
    comm += function("F_N", [(0.0, 0.0), (1.0, 1.0), (2.0, 1.0)])
    comm += function("F_T", [(0.0, 0.0), (1.0, 0.0), (2.0, 1.0)])
    comm += ("CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='DISCRETE', ZONE=_F(GROUP_MA_MAIT='LOW_TOP', "
             "GROUP_MA_ESCL='UP_BOT', ALGO_CONT='PENALISATION', E_N=%r))\n" % e_n)
    comm += snl("_F(CHARGE=BC), _F(CHARGE=PRESSE, FONC_MULT=F_N), _F(CHARGE=SLIDE, FONC_MULT=F_T)",
                [0.0, 1.0, 1.25, 1.5, 1.75, 2.0])
    tests = []
    supported = {1.0: 5, 1.25: 4, 1.5: 4, 1.75: 3, 2.0: 3}
    for t, k in supported.items():
        tests += test_sum("CONT_NOEU", "UP_BOT", "RY", k * e_n * d, 1e-5, inst=t)
    comm += "\n".join(tests) + "\nFIN()\n"
    why = ("sliding off the master's edge under load (slave nodes x + s beyond x = 1 lose contact; at s = 0.25 "
           "and 0.5 one lands exactly on the master's end node)")
    case("gen_slide_off_edge", why, four, comm,
         (why, "RY sum = k E_N d, k = supported nodes: 5, 4, 4 (one on the end node), 3, 3 (one on the end node)",
          "1e-5 relative (block / penalty stiffness)"))
    # slave nodes projecting on the middle of master segments (fixed master shifted by h/2)
    mid = mesh("gen_midedge.msh", stack_mesh(1.25, 0.25, 5, 1, 1.0, 1.0, 4, 2, x_up=0.125))
    pressed_stack("gen_mid_edge", "every slave node projects on the middle of a master segment (CONTRAINTE)", mid,
                  e, e, 1e-5, 0.25, 1.0, 1.0, "CONTRAINTE", tol=1e-9, low_fixed=True)
    # non-matching meshes
    fine_slave = mesh("gen_nonmatch_10_1.msh", stack_mesh(1.0, 1.0, 4, 2, 1.0, 1.0, 40, 2))
    pressed_stack("gen_nonmatching_10_1", "non-matching 10:1: 40 slave segments on 4 deformable master segments "
                  "(nested: the slave forces spread on the master are consistent)", fine_slave, e, e, 1e-5, 1.0, 1.0,
                  1.0, "CONTRAINTE", tol=1e-9)
    coarse_slave = mesh("gen_nonmatch_1_10.msh", stack_mesh(1.0, 0.25, 40, 1, 1.0, 1.0, 4, 2))
    pressed_stack("gen_nonmatching_1_10", "non-matching 1:10: 4 slave segments on 40 master segments (fixed)",
                  coarse_slave, e, e, 1e-5, 0.25, 1.0, 1.0, "CONTRAINTE", tol=1e-9, low_fixed=True)
    # >= 10 000 contact nodes: thin strips 10 m x 0.01 m, 10 000 cells each
    many = mesh("gen_many_nodes.msh", stack_mesh(10.0, 0.01, 10000, 1, 10.0, 0.01, 10000, 1))
    # (penalised, E_N = 1e16: its compliance is 2e-9 of the strip's, the end nodes' half force
    # changes the result by less; CONTRAINTE takes minutes on the 10 001 x 10 001 Schur complement)
    pressed_stack("gen_10k_nodes", "10 001 slave nodes on 10 001 fixed master nodes (PENALISATION E_N = 1e16)",
                  many, e, e, 1e-5, 0.01, 0.01, 10.0, "PENALISATION", e_n=1e16, tol=1e-6, low_fixed=True,
                  slave_cells=10000, cine=True)
    # a body held by contact and by springs of small stiffness (notice 4.4.2), pressed by p
    sp = mesh("gen_stack4_spring.msh", stack_mesh(1.0, 1.0, 4, 2, 1.0, 1.0, 4, 2, spring=True))
    p, k = 1.0e6, 2.1e6
    for with_springs in (True, False):
        comm = header("'LOW_TOP', 'UP_BOT'", e, 0.0, e, 0.0, springs=with_springs)
        if with_springs:
            comm += "CARA = AFFE_CARA_ELEM(MODELE=MO, DISCRET_2D=_F(GROUP_MA='SPRING', CARA='K_T_D_N', VALE=(%r, %r)))\n" % (k, k)
        comm += ("BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='BAS', DX=0.0, DY=0.0), "
                 "_F(GROUP_MA='UP', DX=0.0)))\n")
        comm += "LOAD = AFFE_CHAR_MECA(MODELE=MO, PRES_REP=_F(GROUP_MA='UP_TOP', PRES=%r))\n" % p
        comm += function("RAMP", [(0.0, 0.0), (1.0, 1.0)])
        comm += ("CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='DISCRETE', ZONE=_F(GROUP_MA_MAIT='LOW_TOP', "
                 "GROUP_MA_ESCL='UP_BOT', ALGO_CONT='CONTRAINTE'))\n")
        comm += snl("_F(CHARGE=BC), _F(CHARGE=LOAD, FONC_MULT=RAMP)", [0.0, 1.0],
                    ", CARA_ELEM=CARA" if with_springs else "")
        tests = []
        if with_springs:
            # the spring (1e-5 of a node's stiffness) takes k |DY| ~ 2e6 x 1e-5 = 20 N of p W = 1e6 N:
            # the displacements move by ~2e-5 near it; the resultant is p W - k |DY(corner)|
            tests += test_depl("UP_TOP", "DY", -2.0 * p / e, 1e-4)
            tests += test_depl("UP_BOT", "DY", -p / e, 1e-4)
            tests += test_sum("CONT_NOEU", "UP_BOT", "RY", p - k * 2.0 * p / e, 1e-8)
        comm += "\n".join(tests) + "\nFIN()\n"
        if with_springs:
            why = "a body held only by contact and a spring of stiffness 1e-5 E (notice 4.4.2), pressed by p"
            case("gen_springs_held", why, sp, comm,
                 (why, "DY(UP_TOP) = -2 p H/E, contact resultant p W - k |DY(corner)|", "1e-4 relative on DY (spring force 2e-5 p W), 1e-8 on the resultant"))
        else:
            why = "the same body without springs: the discrete formulation cannot start (expected <F>_ERROR)"
            case("gen_no_springs", why, four, comm,
                 (why, "SOLVE_1 naming the free DOF and notice 4.4.2 (springs), checked by stability.messages",
                  "the message"))
    # nearly incompressible slave (NU = 0.4999, E = 1e7) with mean-dilatation D_PLAN_SI cells pressed
    # on a fixed master wider than it (its nodes expand by 1e-4 along the master, which stays flat)
    e_up, nu_up, d = 1.0e7, 0.4999, 1.0e-4
    s = d / ((1 - nu_up ** 2) / e_up)
    wide = mesh("gen_wide_master.msh", stack_mesh(1.5, 1.0, 6, 2, 1.0, 1.0, 4, 2))
    comm = header("'LOW_TOP', 'UP_BOT'", e, 0.3, e_up, nu_up, modelisation="D_PLAN_SI")
    comm += ("BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='LOW', DX=0.0, DY=0.0), "
             "_F(GROUP_MA='UP_LEFT', DX=0.0)))\n")
    comm += "LOAD = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='UP_TOP', DY=%r))\n" % (-d)
    comm += function("RAMP", [(0.0, 0.0), (1.0, 1.0)])
    comm += ("CONT = DEFI_CONTACT(MODELE=MO, FORMULATION='DISCRETE', ZONE=_F("
             "GROUP_MA_MAIT='LOW_TOP', GROUP_MA_ESCL='UP_BOT', ALGO_CONT='CONTRAINTE'))\n")
    comm += snl("_F(CHARGE=BC), _F(CHARGE=LOAD, FONC_MULT=RAMP)", [0.0, 1.0])
    tests = test_depl("UP_BOT", "DY", 0.0, 1e-9 * d)
    tests += test_depl("UP_RIGHT", "DX", nu_up * (1 + nu_up) * s / e_up, 1e-7)
    tests += test_sum("CONT_NOEU", "UP_BOT", "RY", s, 1e-7)
    comm += "\n".join(tests) + "\nFIN()\n"
    why = "nearly incompressible slave NU = 0.4999 (D_PLAN_SI), expanding by 1e-4 along a fixed master"
    case("gen_incompressible_si", why, wide, comm,
         (why, "uniaxial plane strain: s = d E / ((1 - nu^2) H), DX(UP_RIGHT) = nu (1 + nu) s W/E", "1e-7 relative"))


def write_all():
    for f in os.listdir(HERE):
        if f.startswith("gen_"):
            os.remove(os.path.join(HERE, f))
    meshes = {}

    def mesh(name, m):
        meshes[name] = m
        return name

    # 1 stiffness ratios (soft slave UP on stiff master LOW, then a nearly rigid indenter)
    four = mesh("gen_stack4.msh", stack_mesh(1.0, 1.0, 4, 2, 1.0, 1.0, 4, 2))
    one = mesh("gen_stack1.msh", stack_mesh(0.1, 1.0, 1, 4, 0.1, 1.0, 1, 4))
    for ratio, tag in ((1e6, "1e6"), (1e9, "1e9")):
        e_soft = 2.1e11 / ratio
        p = 1e-4
        for algo in ("CONTRAINTE", "GCP"):
            pressed_stack("gen_ratio_%s_%s" % (tag, algo.lower()),
                          "stiffness ratio %s: a soft slave (E = %.3g) on a steel master, %s" % (tag, e_soft, algo),
                          four, 2.1e11, e_soft, p, 1.0, 1.0, 1.0, algo, tol=1e-6 if ratio > 1e6 else 1e-8,
                          contact_kw=", RESI_ABSO=%r" % (1e-12 * 2 * p) if algo == "GCP" else "")
        pressed_stack("gen_indenter_%s" % tag,
                      "nearly rigid indenter: a steel slave on a master %s times softer, CONTRAINTE" % tag,
                      four, e_soft, 2.1e11, p, 1.0, 1.0, 1.0, "CONTRAINTE", tol=1e-6 if ratio > 1e6 else 1e-8)
    # 2 penalties E_N 1e6..1e18 on one-cell-wide blocks (node stiffness E W / H ~ 2e10 N/m)
    for k in range(6, 19, 2):
        e_n = 10.0 ** k
        pressed_stack("gen_penalty_1e%02d" % k,
                      "PENALISATION E_N = 1e%d (node stiffness 2e10 N/m: ratio %.0e)" % (k, e_n / 2.1e10), one,
                      2.1e11, 2.1e11, 1e-5, 1.0, 1.0, 0.1, "PENALISATION", e_n=e_n, tol=1e-6)
    # 3 unit scaling: the same penalised study in N/m, N/mm and kN/mm (per unit thickness in D_PLAN a
    # nodal force is force / length, so E_N is force / length^2, scaled like E; E_N such that the
    # penetration is 5 % of the compression)
    for tag, length, force in (("n_m", 1.0, 1.0), ("n_mm", 1e3, 1.0), ("kn_mm", 1e3, 1e-3)):
        stress = force / length ** 2
        m = mesh("gen_units_%s.msh" % tag, stack_mesh(0.1 * length, length, 1, 4, 0.1 * length, length, 1, 4))
        pressed_stack("gen_units_%s" % tag, "unit scaling (%s): E, d, E_N and lengths scaled" % {"n_m": "N/m", "n_mm": "N/mm", "kn_mm": "kN/mm"}[tag],
                      m, 2.1e11 * stress, 2.1e11 * stress, 1e-5, length, length, 0.1 * length,
                      "PENALISATION", e_n=2.1e11 * stress, tol=1e-8, lengths=tag.split("_")[1])
    more_cases(mesh)
    # 4 the continuous formulation (LAGS_C unknowns): the same stacks with the augmented Lagrangian
    # (exact: the result must not depend on COEF_CONT nor on the units) and with its penalty law
    for ratio, tag in ((1e6, "1e6"), (1e9, "1e9")):
        e_soft = 2.1e11 / ratio
        pressed_stack("gen_continue_ratio_%s" % tag,
                      "stiffness ratio %s, FORMULATION='CONTINUE' STANDARD (augmented Lagrangian)" % tag,
                      four, 2.1e11, e_soft, 1e-4, 1.0, 1.0, 1.0, "STANDARD", tol=1e-6 if ratio > 1e6 else 1e-8,
                      continuous=True)
    for k in (8, 12, 16):
        rho = 10.0 ** k
        pressed_stack("gen_continue_penalty_1e%02d" % k,
                      "FORMULATION='CONTINUE' PENALISATION COEF_PENA_CONT = 1e%d (E = 2.1e11: ratio %.0e)"
                      % (k, rho / 2.1e11), one, 2.1e11, 2.1e11, 1e-5, 1.0, 1.0, 0.1, "PENALISATION", e_n=rho,
                      tol=1e-6, continuous=True)
    for tag, length, force in (("n_m", 1.0, 1.0), ("n_mm", 1e3, 1.0)):
        stress = force / length ** 2
        m = mesh("gen_units_%s.msh" % tag, stack_mesh(0.1 * length, length, 1, 4, 0.1 * length, length, 1, 4))
        pressed_stack("gen_continue_units_%s" % tag,
                      "unit scaling (%s), FORMULATION='CONTINUE' with the default COEF_CONT"
                      % {"n_m": "N/m", "n_mm": "N/mm"}[tag], m, 2.1e11 * stress, 2.1e11 * stress, 1e-5, length,
                      length, 0.1 * length, "STANDARD", tol=1e-8, lengths=tag.split("_")[1], continuous=True)
    for name, m in meshes.items():
        m.write(os.path.join(HERE, name))
    rows = []
    for name, why, comm, m, row in CASES:
        with open(os.path.join(HERE, name + ".comm"), "w") as f:
            f.write("# Generated by generate.py (do not edit): %s\n" % why)
            f.write(comm)
        with open(os.path.join(HERE, name + ".export"), "w") as f:
            if name == "gen_no_springs":
                f.write("P expected_diag <F>_ERROR\n")
            f.write("P testlist verification stability\nF comm %s.comm D 1\nF msh %s D 20\n"
                    "F mess %s.mess R 6\nF resu %s.resu R 8\n" % (name, m, name, name))
        rows.append((name,) + row)
    return rows


def measured(run_dir, name):
    """(largest error of the case's ANALYTIQUE tests, iterations per step) from its message file in
    run_dir/<name>/ (ctest writes them to build/testcases/stability/)."""
    import re
    try:
        mess = open(os.path.join(run_dir, name, name + ".mess")).read()
    except OSError:
        return "not run", ""
    errors = []
    for line in mess.splitlines():
        m = re.match(r"^\s*(OK|NOOK)\s+ANALYTIQUE\s+(\S+)\s+(\S+)", line)
        if m:
            refe, calc = float(m.group(2)), float(m.group(3))
            errors.append((abs(calc - refe) / abs(refe), "rel") if refe != 0.0 else (abs(calc), "abs"))
    its = re.findall(r"converged in (\d+) iteration", mess)
    if not errors:
        return "no test (message checked)", ""
    rel = [e for e, kind in errors if kind == "rel"]
    text = "%d tests OK, largest error %.1e relative" % (len(errors), max(rel)) if rel else "%d tests OK" % len(errors)
    if any(kind == "abs" for _, kind in errors):
        text += ", zero values within %.1e" % max(e for e, kind in errors if kind == "abs")
    steps = len(its)
    return text, "%d step(s): %s" % (steps, ", ".join(its)) if steps <= 6 else "%d steps, at most %s" % (
        steps, max(map(int, its)))


if __name__ == "__main__":
    import sys
    rows = write_all()
    if len(sys.argv) > 2 and sys.argv[1] == "--table":
        print("| case | what makes it hard | reference | tolerance | result | iterations |")
        print("|---|---|---|---|---|---|")
        for name, why, ref, tol in rows:
            result, its = measured(sys.argv[2], name)
            print("| `%s` | %s | %s | %s | %s | %s |" % (name, why, ref, tol, result, its))
