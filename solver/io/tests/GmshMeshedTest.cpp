// Meshes made by gmsh from the .geo scripts in testcases/meshes/ load with their groups, in
// formats 2.2 and 4.1, and their quadratic cells come out in code_aster's ordering: every
// mid-edge node sits at the middle of its code_aster edge, every face-centre node at the centre
// of its face, and every volume cell has positive corner jacobians. Gmsh places the nodes, so
// this checks our Gmsh->code_aster tables against an independent program.

#include "solver/io/MeshIO.hpp"
#include "solver/io/tests/MeshTestUtil.hpp"
#include "solver/mesh/CellTopology.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <set>

namespace stella {
namespace {

std::filesystem::path meshWithGmsh(const std::string& geo, const std::string& out,
                                   const std::string& options) {
  const auto dir = testing::tempDir("gmsh");
  const auto msh = dir / out;
  const std::string cmd = "gmsh " + options + " " + STELLA_SOURCE_DIR + "/testcases/meshes/" + geo + " -o " +
                          msh.string() + " > " + (dir / "gmsh.log").string() + " 2>&1";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  return msh;
}

void expectCodeAsterOrdering(const Mesh& m, std::set<CellType>& seen) {
  for (CellId c = 0; c < m.cellCount(); ++c) {
    const CellType t = m.cellType(c);
    seen.insert(t);
    const auto nodes = m.cellNodes(c);
    const auto at = [&](int i) { return m.point(nodes[static_cast<std::size_t>(i)]); };
    for (const auto& e : cellEdges(t)) {
      if (e.mid < 0) {
        continue;
      }
      const Point3 mid = 0.5 * (at(e.a) + at(e.b));
      EXPECT_LT(norm(at(e.mid) - mid), 1e-9) << name(t) << " cell " << c << " edge " << e.a << "-" << e.b;
    }
    for (const auto& f : cellFaces(t)) {
      const int nv = vertexCount(f.type);
      if (static_cast<int>(f.nodes.size()) == 2 * nv + 1) {
        Point3 centre{0, 0, 0};
        for (int i = 0; i < nv; ++i) {
          centre = centre + (1.0 / nv) * at(f.nodes[static_cast<std::size_t>(i)]);
        }
        EXPECT_LT(norm(at(f.nodes.back()) - centre), 1e-9) << name(t) << " face centre";
      }
    }
    if (dimension(t) == 3) {
      EXPECT_GT(cellMeasure(m, c), 0.0) << name(t);
      for (const double j : cornerJacobians(m, c)) {
        EXPECT_GT(j, 0.0) << name(t);
      }
    }
  }
}

TEST(GmshMeshed, TetrahedraWithGroups22And41) {
  for (const std::string format : {"msh22", "msh41"}) {
    const Mesh m = readGmshMesh(meshWithGmsh("block_tet.geo", "bt.msh", "-3 -order 2 -format " + format));
    EXPECT_EQ(m.dimension(), 3);
    for (const char* g : {"BOTTOM", "TOP", "LEFT", "RIGHT", "BLOCK"}) {
      ASSERT_TRUE(m.hasCellGroup(g)) << g << " " << format;
      EXPECT_FALSE(m.cellGroup(g)->empty());
      EXPECT_TRUE(m.hasNodeGroup(g));
    }
    std::set<CellType> seen;
    expectCodeAsterOrdering(m, seen);
    EXPECT_TRUE(seen.count(CellType::TETRA10));
    EXPECT_TRUE(seen.count(CellType::TRIA6));
    // The volume of the block: 2 x 1 x 1.
    double v = 0;
    for (const CellId c : *m.cellGroup("BLOCK")) {
      v += cellMeasure(m, c);
    }
    EXPECT_NEAR(v, 2.0, 1e-12);
    // Every node of TOP is at z = 1.
    for (const NodeId n : *m.nodeGroup("TOP")) {
      EXPECT_DOUBLE_EQ(m.point(n)[2], 1.0);
    }
  }
}

TEST(GmshMeshed, HexahedraOfEveryOrder) {
  std::set<CellType> seen;
  for (const std::string opt : {"-3", "-3 -order 2", "-3 -order 2 -setnumber Mesh.SecondOrderIncomplete 1"}) {
    const Mesh m = readGmshMesh(meshWithGmsh("block_hex.geo", "bh.msh", opt));
    EXPECT_EQ(m.cellGroup("BLOCK")->size(), 16u);
    EXPECT_EQ(m.cellGroup("TOP")->size(), 4u);
    expectCodeAsterOrdering(m, seen);
  }
  for (const CellType t :
       {CellType::HEXA8, CellType::HEXA20, CellType::HEXA27, CellType::QUAD9, CellType::QUAD8}) {
    EXPECT_TRUE(seen.count(t)) << name(t);
  }
}

TEST(GmshMeshed, PentahedraOfEveryOrder) {
  std::set<CellType> seen;
  for (const std::string opt : {"-3", "-3 -order 2", "-3 -order 2 -setnumber Mesh.SecondOrderIncomplete 1"}) {
    const Mesh m = readGmshMesh(meshWithGmsh("wedge.geo", "w.msh", opt + " -format msh22"));
    EXPECT_FALSE(m.cellGroup("WEDGE")->empty());
    expectCodeAsterOrdering(m, seen);
  }
  for (const CellType t : {CellType::PENTA6, CellType::PENTA15, CellType::PENTA18}) {
    EXPECT_TRUE(seen.count(t)) << name(t);
  }
}

TEST(GmshMeshed, TwoBlocks2D) {
  const Mesh m = readGmshMesh(meshWithGmsh("two_blocks_2d.geo", "tb.msh", "-2 -format msh22"));
  EXPECT_EQ(m.dimension(), 2);
  EXPECT_EQ(m.cellGroup("Top_B")->size(), 12u);
  EXPECT_EQ(m.cellGroup("Bottom_C")->size(), 7u);
  EXPECT_EQ(m.cellGroup("B")->size(), 72u);
  EXPECT_EQ(m.nodeGroup("Top_B")->size(), 13u);
  for (const CellId c : *m.cellGroup("B")) {
    EXPECT_EQ(m.cellType(c), CellType::QUAD4);
    EXPECT_GT(cellNormal(m, c)[2], 0.0); // counter-clockwise
  }
}

} // namespace
} // namespace stella
