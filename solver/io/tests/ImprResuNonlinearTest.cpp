// IMPR_RESU of a STAT_NON_LINE result (evol_noli) to MED, read back by independent readers:
// meshio (DEPL, SIEF_ELGA, step times) and h5py (MED's raw layout: NUME_ORDRE, INST, Gauss-point
// values), each compared with the closed form of the problem AND with the values stella printed
// through IMPR_RESU FORMAT='RESULTAT' in the .resu file; the same result as VTU/PVD read by
// meshio. Then DEFI_GROUP INTERVALLE_VALE on the result's DX and MODI_MAILLAGE DEFORME by its
// DEPL, checked against the closed form.
//
// Problem: a 2 x 1 x 1 bar of two HEXA8, VMIS_ISOT_LINE (E = 200000, NU = 0.3, SY = 200,
// D_SIGM_EPSI = 20000), symmetry planes x = 0, y = 0, z = 0, the end x = 2 pulled so that
// eps_xx = 1e-3 f(t), f through (0, 0) (1, 1) (2, 3) (3, 2): elastic to yield at t = 1, hardening
// to sigma = 240 at t = 2, elastic unloading to sigma = 40 at t = 3. The state is uniform, so the
// element reproduces it exactly: DX = eps x, DY = (-NU sigma / E - eps_p / 2) y (plastic
// incompressibility), SIXX = sigma, the other stresses 0.

#include "solver/io/MeshIO.hpp"
#include "solver/io/tests/CommRun.hpp"
#include "solver/io/tests/MeshTestUtil.hpp"
#include "solver/mesh/StructuredMesher.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <regex>

namespace stella {
namespace {

const char* const barComm = R"py(DEBUT()
M = LIRE_MAILLAGE(UNITE=20, FORMAT='MED')
MO = AFFE_MODELE(MAILLAGE=M, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='3D'))
MAT = DEFI_MATERIAU(ELAS=_F(E=200000.0, NU=0.3), ECRO_LINE=_F(D_SIGM_EPSI=20000.0, SY=200.0))
CM = AFFE_MATERIAU(MAILLAGE=M, AFFE=_F(TOUT='OUI', MATER=MAT))
BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_NO='XMIN', DX=0.0), _F(GROUP_NO='YMIN', DY=0.0),
                                          _F(GROUP_NO='ZMIN', DZ=0.0)))
PULL = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_NO='XMAX', DX=2.0e-3))
RAMP = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0, 2.0, 3.0, 3.0, 2.0))
TIMES = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=3.0, NOMBRE=6))
RESU = STAT_NON_LINE(MODELE=MO, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=PULL, FONC_MULT=RAMP)),
                     COMPORTEMENT=_F(RELATION='VMIS_ISOT_LINE', TOUT='OUI'),
                     CONVERGENCE=_F(RESI_GLOB_RELA=1.0e-10),
                     INCREMENT=_F(LIST_INST=TIMES))
IMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(RESULTAT=RESU, NOM_CHAM=('DEPL', 'SIEF_ELGA')))
IMPR_RESU(FORMAT='RESULTAT', RESU=_F(RESULTAT=RESU, NOM_CHAM=('DEPL', 'SIEF_ELGA')))
IMPR_RESU(FORMAT='VTU', RESU=_F(RESULTAT=RESU, NOM_CHAM=('DEPL', 'SIEF_ELGA')))
M = DEFI_GROUP(reuse=M, MAILLAGE=M, CREA_GROUP_NO=_F(NOM='FAR', OPTION='INTERVALLE_VALE', RESULTAT=RESU,
               INST=2.0, NOM_CMP='DX', VALE=(2.9e-3, 1.0)))
M = MODI_MAILLAGE(reuse=M, MAILLAGE=M, DEFORME=_F(OPTION='TRAN', RESULTAT=RESU, INST=3.0))
IMPR_RESU(FORMAT='MED', UNITE=82, RESU=_F(MAILLAGE=M))
FIN()
)py";

// argv: the MED file, the .resu file. Tolerances: the closed form is met to the Newton residual
// (RESI_GLOB_RELA 1e-10 on a uniform state), so 1e-9 relative to the largest value; the RESULTAT
// tables print 7 significant digits, so 1e-6 relative to the largest value of the table.
const char* const barCheck = R"py(
import sys, re, numpy as np, meshio, h5py
med, resu = sys.argv[1], sys.argv[2]
E, NU, SY, ET = 2.0e5, 0.3, 200.0, 2.0e4
times = [0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0]
def closed(t):
    eps = 1e-3 * np.interp(t, [0, 1, 2, 3], [0, 1, 3, 2])
    if t <= 1: s = E * eps
    elif t <= 2: s = SY + ET * (eps - SY / E)
    else: s = SY + ET * (3e-3 - SY / E) - E * (3e-3 - eps)
    return eps, s, eps - s / E
assert abs(closed(2.0)[1] - 240) < 1e-9 and abs(closed(3.0)[1] - 40) < 1e-9

# The RESULTAT tables: (field, NUME_ORDRE) -> (INST, rows of numbers after the entity name).
tables, cur = {}, None
for line in open(resu):
    m = re.match(r" CHAMP (\S+) DU RESULTAT RESU NUME_ORDRE (\d+) INST (\S+)", line)
    if m:
        cur = (m.group(1), int(m.group(2)))
        tables[cur] = (float(m.group(3)), [])
    elif not line.strip():
        cur = None
    elif cur and not line.startswith((" NOEUD", " MAILLE")):
        tables[cur][1].append([float(v) for v in line.split()[1:]])
assert sorted(k[1] for k in tables if k[0] == "DEPL") == list(range(7)), tables.keys()

mesh = meshio.read(med, file_format="med")
p = mesh.points
steps = {}
for key in mesh.point_data:
    m = re.match(r"RESU____DEPL\[(\d+)\] - (\S+)", key)
    if m: steps[int(m.group(1))] = (float(m.group(2)), key)
assert sorted(steps) == list(range(7)), mesh.point_data.keys()
worst_closed = worst_table = 0.0
for i, t in enumerate(times):
    eps, s, ep = closed(t)
    assert abs(steps[i][0] - t) < 1e-12 and abs(tables[("DEPL", i)][0] - t) < 1e-12, (i, steps[i][0])
    d = mesh.point_data[steps[i][1]]
    lateral = -NU * s / E - ep / 2
    ref = np.column_stack([eps * p[:, 0], lateral * p[:, 1], lateral * p[:, 2]])
    scale = max(abs(ref).max(), 1e-3)
    worst_closed = max(worst_closed, abs(d - ref).max() / scale)
    worst_table = max(worst_table, abs(d - np.array(tables[("DEPL", i)][1])).max() / scale)
    sief = [v for k, v in mesh.cell_data.items() if k.startswith("RESU____SIEF_ELGA[%d] -" % i)]
    assert len(sief) == 1, mesh.cell_data.keys()
    v = sief[0][0]  # the HEXA8 block: cells x points x components (uniform field: any point order)
    assert v.shape == (2, 8, 6), v.shape
    sref = np.zeros(6); sref[0] = s
    worst_closed = max(worst_closed, abs(v - sref).max() / 240.0)
    rows = np.array(tables[("SIEF_ELGA", i)][1])[:, 1:]  # drop the point number
    assert rows.shape == (16, 6), rows.shape
    worst_table = max(worst_table, abs(rows - v.reshape(16, 6)).max() / 240.0)

#h5py : MED's own layout. Every step of both fields: NUME_ORDRE as numdt, INST as PDT.
f = h5py.File(med, "r")
for name in ("RESU____DEPL", "RESU____SIEF_ELGA"):
    g = f["CHA/" + name]
    found = sorted((g[k].attrs["NDT"], g[k].attrs["PDT"]) for k in g)
    assert [n for n, _ in found] == list(range(7)), found
    assert np.allclose([t for _, t in found], times, rtol=0, atol=1e-14), found
g = f["CHA/RESU____SIEF_ELGA"]
names = g.attrs["NOM"].decode()
comps = [names[16 * k:16 * k + 16].strip() for k in range(g.attrs["NCO"])]
assert comps == ["SIXX", "SIYY", "SIZZ", "SIXY", "SIXZ", "SIYZ"], comps
for k in g:
    t = g[k].attrs["PDT"]
    he8 = g[k]["MAI.HE8"]
    co = he8[he8.attrs["PFL"].decode()]["CO"][()].reshape(6, 2, 8)
    s = closed(t)[1]
    assert abs(co[0] - s).max() <= 1e-9 * 240 and abs(co[1:]).max() <= 1e-9 * 240, (t, co[:, 0, 0])
print("closed form %.2e table %.2e" % (worst_closed, worst_table))
assert worst_closed < 1e-9, worst_closed
assert worst_table < 1e-6, worst_table
print("OK")
)py";

// argv: the .pvd (unit 81 in the work directory; the .vtu files beside it). The collection lists
// every step with its time; meshio reads each .vtu: DEPL as point data, SIEF_ELGA as cell data
// (the mean of the cell's Gauss points).
const char* const vtuCheck = R"py(
import sys, os, numpy as np, meshio, xml.etree.ElementTree as ET
E, NU, SY, HARD = 2.0e5, 0.3, 200.0, 2.0e4
def closed(t):
    eps = 1e-3 * np.interp(t, [0, 1, 2, 3], [0, 1, 3, 2])
    if t <= 1: s = E * eps
    elif t <= 2: s = SY + HARD * (eps - SY / E)
    else: s = SY + HARD * (3e-3 - SY / E) - E * (3e-3 - eps)
    return eps, s, eps - s / E
pvd = sys.argv[1]
sets = ET.parse(pvd).getroot().find("Collection").findall("DataSet")
times = [float(d.get("timestep")) for d in sets]
assert np.allclose(times, [0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0], rtol=0, atol=1e-15), times
worst = 0.0
for d, t in zip(sets, times):
    m = meshio.read(os.path.join(os.path.dirname(pvd), d.get("file")))
    eps, s, ep = closed(t)
    lateral = -NU * s / E - ep / 2
    p = m.points
    ref = np.column_stack([eps * p[:, 0], lateral * p[:, 1], lateral * p[:, 2]])
    worst = max(worst, abs(m.point_data["DEPL"] - ref).max() / max(abs(ref).max(), 1e-3))
    sief = m.cell_data["SIEF_ELGA"][0]
    assert sief.shape == (2, 6), sief.shape
    sref = np.zeros(6); sref[0] = s
    worst = max(worst, abs(sief - sref).max() / 240.0)
print("worst %.2e" % worst)
assert worst < 1e-9, worst
print("OK")
)py";

TEST(ImprResuNonlinear, MedOfStatNonLineReadByMeshioAndH5py) {
  const auto dir = testing::tempDir("impr_snl");
  writeMedMesh(dir / "bar.med", testing::structuredVolume({CellType::HEXA8, {2, 1, 1}, {2, 1, 1}, {0, 0, 0}}),
               "BAR");
  // unit 80 comes back to its --unit path; unit 82 (the deformed mesh, read back from the work
  // directory) is written back to deformed.med
  const auto r = testing::runComm(dir, "bar", barComm,
                                  {{20, dir / "bar.med"}, {80, dir / "out.med"}, {82, dir / "deformed.med"}});
  ASSERT_EQ(r.diagnostic, JobDiagnostic::Ok) << r.message;
  EXPECT_EQ(testing::runPython(dir, barCheck, (dir / "out.med").string() + " " + (dir / "bar.resu").string()),
            0);
  // FORMAT='VTU' (catalogue extension, default unit 81): the .pvd copied back as bar.pvd with its
  // .vtu files renamed bar_<k>.vtu beside it and named so in the collection.
  EXPECT_TRUE(std::filesystem::exists(dir / "bar_6.vtu"));
  EXPECT_EQ(testing::runPython(dir, vtuCheck, (dir / "bar.pvd").string()), 0);
  // INTERVALLE_VALE: DX = 3e-3 x at t = 2, so DX in [2.9e-3, 1] keeps the 8 nodes at x = 1, 2.
  EXPECT_NE(r.message.find("group of nodes FAR (8 nodes)"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("DEFORME: 12 nodes moved by DEPL of RESU at NUME_ORDRE 6"), std::string::npos)
      << r.message;
  // DEFORME at t = 3 (eps = 2e-3, sigma = 40, eps_p = 1.8e-3): x (1 + eps), y and z (1 + lateral).
  const Mesh before = readMedMesh(dir / "bar.med");
  const Mesh after = readMedMesh(dir / "bar.work" / "fort.82");
  ASSERT_EQ(after.nodeCount(), before.nodeCount());
  const double eps = 2e-3;
  const double lateral = -0.3 * 40.0 / 2e5 - (eps - 40.0 / 2e5) / 2;
  for (NodeId n = 0; n < before.nodeCount(); ++n) {
    const Point3 x = before.point(n);
    const Point3 y = after.point(n);
    EXPECT_NEAR(y[0], x[0] * (1 + eps), 1e-12) << n;
    EXPECT_NEAR(y[1], x[1] * (1 + lateral), 1e-12) << n;
    EXPECT_NEAR(y[2], x[2] * (1 + lateral), 1e-12) << n;
  }
}

// The convergence table's WHERE (MAXI) column names the degree of freedom of the largest residual
// whole: with 10-character node names ("node BARNODE001, component DX", 29 characters) it was cut
// at 23 characters ("node BARNODE001, compon").
TEST(ImprResuNonlinear, ConvergenceTableShowsWholeNodeNames) {
  const auto dir = testing::tempDir("impr_snl_names");
  const Mesh plain = testing::structuredVolume({CellType::HEXA8, {2, 1, 1}, {2, 1, 1}, {0, 0, 0}});
  Mesh named;
  for (NodeId n = 0; n < plain.nodeCount(); ++n) {
    named.addNode(plain.point(n), fmt::format("BARNODE{:03d}", n + 1));
  }
  for (CellId c = 0; c < plain.cellCount(); ++c) {
    named.addCell(plain.cellType(c), plain.cellNodes(c));
  }
  for (const auto& [name, nodes] : plain.nodeGroups()) {
    named.setNodeGroup(name, nodes);
  }
  writeAsterMesh(dir / "bar.mail", named, {"bar with long node names"});
  std::string comm = barComm;
  comm.replace(comm.find("FORMAT='MED')"), 13, "FORMAT='ASTER')");
  comm = comm.substr(0, comm.find("IMPR_RESU(")) + "FIN()\n";
  const auto r = testing::runComm(dir, "bar", comm, {{20, dir / "bar.mail"}});
  ASSERT_EQ(r.diagnostic, JobDiagnostic::Ok) << r.message;
  const std::regex whole(R"(\| node BARNODE\d{3}, component D[XYZ] +\|)");
  EXPECT_TRUE(std::regex_search(r.message, whole)) << r.message;
  EXPECT_EQ(r.message.find("BARNODE001, compon |"), std::string::npos);
}

} // namespace
} // namespace stella
