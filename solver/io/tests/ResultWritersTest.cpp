// Result writers checked by an independent reader: a result with two steps (nodal DEPL, a
// per-cell field, a Gauss-point field) written as MED and VTU is read back by meshio (Debian's
// python3) and every value compared with the formula it was built from; a partial nodal field
// (CONT_NOEU on some nodes) goes out with a MED profile read back by h5py and by meshio.

#include "solver/io/ResultWriters.hpp"
#include "solver/io/MeshIO.hpp"
#include "solver/io/tests/CommRun.hpp"
#include "solver/io/tests/MeshTestUtil.hpp"
#include "solver/mesh/MeshGeometry.hpp"
#include "solver/mesh/StructuredMesher.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

namespace stella {
namespace {

// DX = x + t, DY = 2 y, DZ = 3 z t; ERRE = centroid x (per cell); SIEF_ELGA SIXX = 100 centroid
// x + point, SIYY = t, on the hexahedra (8 points each) only.
Result makeResult(const Mesh& m) {
  Result r;
  r.type = "evol_elas";
  for (const double t : {0.0, 1.0}) {
    ResultStep& s = r.addStep(t, 0);
    auto depl = std::make_shared<Field>(
        Field::nodal("DEPL_R", {"DX", "DY", "DZ"}, static_cast<std::size_t>(m.nodeCount())));
    for (NodeId n = 0; n < m.nodeCount(); ++n) {
      const auto x = m.point(n);
      depl->value(static_cast<std::size_t>(n), 0) = x[0] + t;
      depl->value(static_cast<std::size_t>(n), 1) = 2 * x[1];
      depl->value(static_cast<std::size_t>(n), 2) = 3 * x[2] * t;
    }
    s.fields["DEPL"] = depl;
    auto erre = std::make_shared<Field>(
        Field::perCell("ERRE_R", {"ERREST"}, static_cast<std::size_t>(m.cellCount())));
    std::vector<int> points;
    for (CellId c = 0; c < m.cellCount(); ++c) {
      erre->value(static_cast<std::size_t>(c), 0) = cellCentroid(m, c)[0];
      points.push_back(dimension(m.cellType(c)) == 3 ? 8 : 0);
    }
    s.fields["ERRE_ELEM"] = erre;
    auto sief = std::make_shared<Field>(
        Field::perPoint(FieldSupport::GaussPoint, "SIEF_R", {"SIXX", "SIYY"}, points));
    for (CellId c = 0; c < m.cellCount(); ++c) {
      for (int p = 0; p < points[static_cast<std::size_t>(c)]; ++p) {
        const std::size_t e = sief->firstPoint(static_cast<std::size_t>(c)) + static_cast<std::size_t>(p);
        sief->value(e, 0) = 100 * cellCentroid(m, c)[0] + p;
        sief->value(e, 1) = t;
      }
    }
    s.fields["SIEF_ELGA"] = sief;
  }
  return r;
}

using testing::runPython;

// Nodal and per-cell fields through meshio; Gauss-point values through h5py on MED's layout
// (component-major, then cell, then point: meshio 5.0 reshapes multi-point data in another
// order, so it cannot check them).
const char* const medCheck = R"(
import sys, numpy as np, meshio, h5py
m = meshio.read(sys.argv[1], file_format="med")
p = m.points
f = h5py.File(sys.argv[1], "r")
assert f["GAUSS/LOC_HEXA8_8"].attrs["NBR"] == 8
for i, t in enumerate([0.0, 1.0]):
    d = m.point_data["RESU____DEPL[%d] - %g" % (i, t)]
    assert np.allclose(d[:, 0], p[:, 0] + t), "DX"
    assert np.allclose(d[:, 1], 2 * p[:, 1]), "DY"
    assert np.allclose(d[:, 2], 3 * p[:, 2] * t), "DZ"
    erre = m.cell_data["RESU____ERRE_ELEM[%d] - %g" % (i, t)]
    block = m.cells[0]
    assert block.type == "hexahedron" and len(block.data) == 2
    centroid_x = p[block.data][:, :, 0].mean(axis=1)
    assert np.allclose(np.ravel(erre[0]), centroid_x), "ERREST"
    steps = f["CHA/RESU____SIEF_ELGA"]
    step = [steps[k] for k in steps if abs(steps[k].attrs["PDT"] - t) < 1e-12][0]
    he8 = step["MAI.HE8"]
    co = he8[he8.attrs["PFL"].decode()]["CO"][()].reshape(2, 2, 8)
    for c in range(2):
        assert np.allclose(co[0, c], 100 * centroid_x[c] + np.arange(8)), "SIXX"
        assert np.allclose(co[1, c], t), "SIYY"
print("OK")
)";

TEST(ResultWriters, MedReadByMeshio) {
  const auto dir = testing::tempDir("med_result");
  const Mesh m = testing::structuredVolume({CellType::HEXA8, {2, 1, 1}, {2, 1, 1}, {0, 0, 0}}, false);
  const Result r = makeResult(m);
  ResultOutput out;
  out.resultName = "RESU";
  writeMedResult(dir / "r.med", m, "MAIL", &r, out);
  EXPECT_EQ(runPython(dir, medCheck, (dir / "r.med").string()), 0);
  // The mesh part reads back with our own reader too.
  EXPECT_EQ(readMedMesh(dir / "r.med").cellCount(), m.cellCount());
}

TEST(ResultWriters, MedFieldSelectionAndPartialField) {
  const auto dir = testing::tempDir("med_partial");
  const Mesh m = buildStructuredMesh({CellType::QUAD4, {2, 1, 1}, {2, 1, 1}, {0, 0, 0}});
  Result r;
  ResultStep& s = r.addStep(0.5, 1);
  auto cont = std::make_shared<Field>(
      Field::nodal("INFC_R", {"CONT", "JEU"}, static_cast<std::size_t>(m.nodeCount())));
  cont->markPartial();
  for (const NodeId n : *m.nodeGroup("YMAX")) {
    cont->setDefined(static_cast<std::size_t>(n), 0);
    cont->setDefined(static_cast<std::size_t>(n), 1);
    cont->value(static_cast<std::size_t>(n), 0) = 1.0;
    cont->value(static_cast<std::size_t>(n), 1) = m.point(n)[0];
  }
  s.fields["CONT_NOEU"] = cont;
  ResultOutput out;
  out.resultName = "STAT";
  writeMedResult(dir / "p.med", m, "", &r, out);
  // Read the raw MED layout with h5py: a profile of the YMAX nodes and their values only.
  const char* script = R"(
import sys, numpy as np, h5py
f = h5py.File(sys.argv[1], "r")
step = f["CHA/STAT____CONT_NOEU"]
key = list(step.keys())[0]
assert abs(step[key].attrs["PDT"] - 0.5) < 1e-15
noe = step[key]["NOE"]
pfl = noe.attrs["PFL"].decode()
nodes = f["PROFILS"][pfl]["PFL"][()]
co = noe[pfl]["CO"][()].reshape(len(nodes), 2, order="F")
x = f["ENS_MAA/MAIL"][list(f["ENS_MAA/MAIL"].keys())[0]]["NOE/COO"][()].reshape(-1, 2, order="F")
assert list(nodes) == [4, 5, 6], nodes
assert np.allclose(co[:, 0], 1.0) and np.allclose(co[:, 1], x[nodes - 1, 0])
print("OK")
)";
  EXPECT_EQ(runPython(dir, script, (dir / "p.med").string()), 0);
  // meshio 5.0 sizes the array of a profiled nodal field by the profile's length instead of the
  // node count (an IndexError for any profile but 1..k): that one function is replaced by a
  // corrected copy sized by the node count; the rest (profile lookup, values, names) is meshio's.
  const char* meshioScript = R"(
import sys, numpy as np, h5py, meshio
import meshio.med._med as med
nodes = len(h5py.File(sys.argv[1], "r")["ENS_MAA/MAIL"]["-0000000000000000001-0000000000000000001/NOE/COO"][()]) // 2
original = med._read_nodal_data
def sized(med_data, profiles):
    pfl = med_data["NOE"].attrs["PFL"]
    if pfl.decode() == "MED_NO_PROFILE_INTERNAL":
        return original(med_data, profiles)
    index = profiles[pfl]["PFL"][()] - 1
    values = med_data["NOE"][pfl]["CO"][()].reshape(len(index), -1, order="F")
    out = np.full((nodes, values.shape[1]), np.nan)
    out[index] = values
    return out
med._read_nodal_data = sized
m = meshio.read(sys.argv[1], file_format="med")
c = m.point_data["STAT____CONT_NOEU"]  # one step: no "[i] - t" suffix
assert c.shape == (6, 2), c.shape
top = np.isclose(m.points[:, 1], 1.0)
assert list(np.nonzero(top)[0]) == [3, 4, 5]
assert np.all(np.isnan(c[~top])), c
assert np.allclose(c[top, 0], 1.0) and np.allclose(c[top, 1], m.points[top, 0]), c
print("OK")
)";
  EXPECT_EQ(runPython(dir, meshioScript, (dir / "p.med").string()), 0);
}

TEST(ResultWriters, VtuReadByMeshio) {
  const auto dir = testing::tempDir("vtu_result");
  const Mesh m = buildStructuredMesh({CellType::HEXA20, {2, 1, 1}, {2, 1, 1}, {0, 0, 0}});
  const Result r = makeResult(m);
  const auto files = writeVtuResult(dir / "r.pvd", m, &r, {});
  ASSERT_EQ(files.size(), 3u);
  const char* script = R"(
import sys, numpy as np, meshio
m = meshio.read(sys.argv[1])
p = m.points
d = m.point_data["DEPL"]
assert np.allclose(d[:, 0], p[:, 0] + 1.0) and np.allclose(d[:, 2], 3 * p[:, 2])
for block, e in zip(m.cells, m.cell_data["ERRE_ELEM"]):
    assert np.allclose(np.ravel(e), p[block.data][:, :8 if block.type == "hexahedron20" else 4, 0].mean(axis=1)), block.type
    if block.type == "hexahedron20":
        # VTK order: mid nodes 8-11 bottom, 12-15 top, 16-19 vertical.
        x = p[block.data]
        assert np.allclose(x[:, 12], (x[:, 4] + x[:, 5]) / 2) and np.allclose(x[:, 16], (x[:, 0] + x[:, 4]) / 2)
print("OK")
)";
  EXPECT_EQ(runPython(dir, script, (dir / "r_1.vtu").string()), 0);
}

// VTU of a 2D result: DEPL (DX, DY) as a 3-vector with DZ = 0 (what ParaView's Warp By Vector
// needs), a partial nodal field NaN on the nodes where it is not defined (not 0), SIEF_ELGA NaN on
// the skin cells that have no Gauss points, and every array binary, appended and zlib-compressed
// (read back by meshio, which decodes the blocks independently of stella).
TEST(ResultWriters, VtuTwoDimensionalVectorsNanAndCompressedBinary) {
  const auto dir = testing::tempDir("vtu_2d");
  const Mesh m = buildStructuredMesh({CellType::QUAD4, {2, 1, 1}, {2, 1, 1}, {0, 0, 0}});
  Result r;
  ResultStep& s = r.addStep(1.5, 3);
  const auto nodes = static_cast<std::size_t>(m.nodeCount());
  auto depl = std::make_shared<Field>(Field::nodal("DEPL_R", {"DX", "DY"}, nodes));
  auto cont = std::make_shared<Field>(Field::nodal("NEUT_R", {"CONT"}, nodes));
  cont->markPartial();
  for (std::size_t n = 0; n < nodes; ++n) {
    const auto x = m.point(static_cast<NodeId>(n));
    depl->value(n, 0) = x[0];
    depl->value(n, 1) = -x[1];
    if (x[0] == 0.0) {
      cont->value(n, 0) = 1.0;
      cont->setDefined(n, 0);
    }
  }
  s.fields["DEPL"] = depl;
  s.fields["CONT_NOEU"] = cont;
  std::vector<int> points;
  for (CellId c = 0; c < m.cellCount(); ++c) {
    points.push_back(m.cellType(c) == CellType::QUAD4 ? 4 : 0);
  }
  auto sief = std::make_shared<Field>(Field::perPoint(FieldSupport::GaussPoint, "SIEF_R", {"SIXX"}, points));
  for (CellId c = 0; c < m.cellCount(); ++c) {
    for (int p = 0; p < points[static_cast<std::size_t>(c)]; ++p) {
      sief->value(sief->firstPoint(static_cast<std::size_t>(c)) + static_cast<std::size_t>(p), 0) =
          10.0 * c + p;
    }
  }
  s.fields["SIEF_ELGA"] = sief;
  writeVtuResult(dir / "r.pvd", m, &r, {});
  const char* script = R"(
import sys, numpy as np, meshio, xml.etree.ElementTree as ET
pvd = ET.parse(sys.argv[1] + "/r.pvd").getroot().find("Collection").findall("DataSet")
assert [(float(d.get("timestep")), d.get("file")) for d in pvd] == [(1.5, "r_3.vtu")], pvd
vtu = sys.argv[1] + "/r_3.vtu"
raw = open(vtu, "rb").read()
assert b'format="ascii"' not in raw and b'format="appended"' in raw, "appended binary"
assert b'compressor="vtkZLibDataCompressor"' in raw and b'<AppendedData encoding="raw">' in raw
assert b'ComponentName2="DZ"' in raw
m = meshio.read(vtu)
p = m.points
d = m.point_data["DEPL"]
assert d.shape == (len(p), 3), d.shape
assert np.array_equal(d[:, 0], p[:, 0]) and np.array_equal(d[:, 1], -p[:, 1]) and not d[:, 2].any(), d
c = m.point_data["CONT_NOEU"].ravel()
on = p[:, 0] == 0.0
assert on.sum() == 2 and np.array_equal(c[on], [1.0, 1.0]) and np.isnan(c[~on]).all(), c
quads = 0
for block, v in zip(m.cells, m.cell_data["SIEF_ELGA"]):
    v = np.ravel(v)
    if block.type == "quad":
        quads += len(v)
        assert np.isfinite(v).all() and np.allclose(v % 10, 1.5), v  # mean of 10 c + (0, 1, 2, 3)
    else:
        assert np.isnan(v).all(), (block.type, v)
assert quads == 2, quads
print("OK")
)";
  EXPECT_EQ(runPython(dir, script, dir.string()), 0);
}

// DEPL with the contact multiplier LAGS_C of FORMULATION='CONTINUE' (defined on the slave nodes
// only): the displacement stays a 3-vector (DX, DY, DZ = 0), LAGS_C goes to a scalar array
// DEPL_LAGS_C, NaN off the slave nodes (it used to be the third component of the vector, which
// Warp By Vector took for DZ).
TEST(ResultWriters, VtuContactMultiplierIsNotPartOfTheDisplacementVector) {
  const auto dir = testing::tempDir("vtu_lags_c");
  const Mesh m = buildStructuredMesh({CellType::QUAD4, {2, 1, 1}, {2, 1, 1}, {0, 0, 0}});
  Result r;
  ResultStep& s = r.addStep(1.0, 1);
  const auto nodes = static_cast<std::size_t>(m.nodeCount());
  auto depl = std::make_shared<Field>(Field::nodal("DEPL_R", {"DX", "DY", "LAGS_C"}, nodes));
  depl->markPartial();
  for (std::size_t n = 0; n < nodes; ++n) {
    const auto x = m.point(static_cast<NodeId>(n));
    depl->value(n, 0) = x[0];
    depl->value(n, 1) = -x[1];
    depl->setDefined(n, 0);
    depl->setDefined(n, 1);
    if (x[1] == 0.0) {
      depl->value(n, 2) = -100.0 - x[0];
      depl->setDefined(n, 2);
    }
  }
  s.fields["DEPL"] = depl;
  writeVtuResult(dir / "r.pvd", m, &r, {});
  const char* script = R"(
import sys, numpy as np, meshio
m = meshio.read(sys.argv[1] + "/r_1.vtu")
p = m.points
d = m.point_data["DEPL"]
assert d.shape == (len(p), 3), d.shape
assert np.array_equal(d[:, 0], p[:, 0]) and np.array_equal(d[:, 1], -p[:, 1]) and not d[:, 2].any(), d
c = m.point_data["DEPL_LAGS_C"].ravel()
on = p[:, 1] == 0.0
assert on.sum() == 3 and np.array_equal(c[on], -100.0 - p[on, 0]) and np.isnan(c[~on]).all(), c
print("OK")
)";
  EXPECT_EQ(runPython(dir, script, dir.string()), 0);
}

TEST(ResultWriters, ResultTablesAndGmsh) {
  const auto dir = testing::tempDir("text_result");
  const Mesh m = buildStructuredMesh({CellType::QUAD4, {1, 1, 1}, {1, 1, 1}, {0, 0, 0}});
  Result r;
  ResultStep& s = r.addStep(2.0, 1);
  auto depl = std::make_shared<Field>(Field::nodal("DEPL_R", {"DX", "DY"}, 4));
  depl->value(3, 1) = -0.25;
  s.fields["DEPL"] = depl;
  ResultOutput out;
  out.resultName = "RES";
  out.components = {"DY"};
  const std::string t = formatResultTables(m, r, out);
  EXPECT_NE(t.find("CHAMP DEPL DU RESULTAT RES NUME_ORDRE 1 INST 2.000000E+00"), std::string::npos) << t;
  EXPECT_NE(t.find(" N4       -2.500000E-01"), std::string::npos) << t;
  EXPECT_EQ(t.find("DX"), std::string::npos);
  writeGmshResult(dir / "r.msh", m, &r, out);
  const char* script = R"(
import sys, meshio
m = meshio.read(sys.argv[1])
assert abs(m.point_data["DEPL_DY"][3] + 0.25) < 1e-15
print("OK")
)";
  EXPECT_EQ(runPython(dir, script, (dir / "r.msh").string()), 0);
}

} // namespace
} // namespace stella
