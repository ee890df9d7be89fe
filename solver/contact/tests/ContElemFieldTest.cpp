// CONT_ELEM of LAC on a mesh cut by DECOUPE_LAC, filled from given patch states (no LAC
// formulation yet): every piece of a patch carries its patch's values, other cells none; the
// field goes to MED and VTU like any cell field and reads back (h5py, meshio) with its values.

#include "solver/contact/mortar/ContElemField.hpp"
#include "solver/io/ResultWriters.hpp"
#include "solver/io/tests/CommRun.hpp"
#include "solver/io/tests/MeshTestUtil.hpp"
#include "solver/mesh/LacCutting.hpp"
#include "solver/mesh/StructuredMesher.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace stella::mortar {
namespace {

struct CutCase {
  Mesh mesh;
  std::vector<LacPatchState> states;
};

// A 2 x 2 x 1 box of HEXA8 cut under ZMAX (4 patches of 4 TRIA3); patch p has the pressure
// -25 - p and the gap 1e-3 p, except the last, not paired.
CutCase cutBox() {
  CutCase c{cutMeshForLac(buildStructuredMesh({CellType::HEXA8, {2, 2, 1}, {2, 2, 1}, {0, 0, 0}}), {"ZMAX"},
                          LacHexaCut::Pyramids, {}),
            {}};
  for (std::size_t p = 0; p < c.mesh.lacPatches().size(); ++p) {
    const bool paired = p + 1 < c.mesh.lacPatches().size();
    c.states.push_back({-25.0 - static_cast<double>(p), paired ? 1e-3 * static_cast<double>(p) : NAN, paired,
                        paired ? 1.0 : 0.0});
  }
  return c;
}

TEST(ContElem, PatchValuesOnTheSlaveCellsOnly) {
  const auto c = cutBox();
  ASSERT_EQ(c.mesh.lacPatches().size(), 4u);
  const Field f = buildContElem(c.mesh, c.states);
  EXPECT_EQ(f.support(), FieldSupport::Cell);
  EXPECT_EQ(f.quantity(), "CLAC_R");
  EXPECT_EQ(f.components(), (std::vector<std::string>{"PRES", "JEU", "CONT", "COEFSURF", "PRESCOOR"}));
  std::vector<bool> onSlave(static_cast<std::size_t>(c.mesh.cellCount()), false);
  for (std::size_t p = 0; p < 4; ++p) {
    ASSERT_EQ(c.mesh.lacPatches()[p].cells.size(), 4u);
    for (const CellId cell : c.mesh.lacPatches()[p].cells) {
      const auto e = static_cast<std::size_t>(cell);
      onSlave[e] = true;
      EXPECT_EQ(f.value(e, 0), -25.0 - static_cast<double>(p));
      EXPECT_EQ(f.value(e, 1), p < 3 ? 1e-3 * static_cast<double>(p) : -1.0);
      EXPECT_EQ(f.value(e, 2), p < 3 ? 1.0 : 0.0);
      EXPECT_EQ(f.value(e, 3), p < 3 ? 1.0 : 0.0);
      EXPECT_EQ(f.value(e, 4), p < 3 ? -25.0 - static_cast<double>(p) : 0.0);
    }
  }
  for (std::size_t e = 0; e < onSlave.size(); ++e) {
    EXPECT_EQ(f.defined(e, 0), onSlave[e]) << e;
  }
}

TEST(ContElem, WrittenToMedAndVtu) {
  const auto c = cutBox();
  Result r;
  ResultStep& s = r.addStep(1.0, 1);
  s.fields["CONT_ELEM"] = std::make_shared<Field>(buildContElem(c.mesh, c.states));
  const auto dir = testing::tempDir("cont_elem");
  ResultOutput out;
  out.resultName = "RESU";
  writeMedResult(dir / "r.med", c.mesh, "MAIL", &r, out);
  writeVtuResult(dir / "r.pvd", c.mesh, &r, out);
  // MED: the field on the 16 TRIA3 slave cells only (no values on the pyramids and the other skin
  // quadrangles, where it used to be written as zeros), PRES of each.
  const char* med = R"(
import sys, numpy as np, h5py
f = h5py.File(sys.argv[1] + "/r.med", "r")
field = f["CHA/RESU____CONT_ELEM"]
names = field.attrs["NOM"].decode()
assert names.split() == ["PRES", "JEU", "CONT", "COEFSURF", "PRESCOOR"], names
step = field[list(field.keys())[0]]
assert list(step.keys()) == ["MAI.TR3"], list(step.keys())
tr3 = step["MAI.TR3"]
pfl = tr3.attrs["PFL"]
v = tr3[pfl]["CO"][()].reshape(5, -1)  # no-interlace storage: component-major
assert v.shape[1] == 16, v.shape
assert sorted(set(np.round(v[0], 12))) == [-28.0, -27.0, -26.0, -25.0], v[0]
assert sorted(v[1]).count(-1.0) == 4 and sorted(v[2]).count(1.0) == 12, v
print("OK")
)";
  EXPECT_EQ(testing::runPython(dir, med, dir.string()), 0);
  const char* vtu = R"(
import sys, numpy as np, meshio
m = meshio.read(sys.argv[1] + "/r_1.vtu")
slave = 0
for block, v in zip(m.cells, m.cell_data["CONT_ELEM"]):
    v = np.asarray(v).reshape(len(block.data), -1)
    if block.type == "triangle":
        slave += len(v)
        assert v.shape[1] == 5 and np.isfinite(v).all(), v
        assert np.allclose(v[:, 4], v[:, 0] * v[:, 3]), v
    else:
        assert np.isnan(v).all(), block.type
assert slave == 16, slave
print("OK")
)";
  EXPECT_EQ(testing::runPython(dir, vtu, dir.string()), 0);
}

} // namespace
} // namespace stella::mortar
