// VERI_MAIL: a clean structured mesh has no finding; planted duplicates, a degenerate, an
// inverted and a flat cell are each found and named; a clockwise 2D face is not inverted.

#include "solver/mesh/MeshCheck.hpp"
#include "solver/mesh/StructuredMesher.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

TEST(MeshCheck, CleanMeshesHaveNoFinding) {
  for (const CellType t : {CellType::HEXA20, CellType::TETRA4, CellType::QUAD4, CellType::TRIA6}) {
    const Mesh m = buildStructuredMesh({t, {2, 2, 2}, {1, 2, 3}, {0, 0, 0}});
    EXPECT_TRUE(checkMesh(m).clean()) << name(t);
  }
}

TEST(MeshCheck, FindsEveryKindOfProblem) {
  Mesh m = buildStructuredMesh({CellType::HEXA8, {2, 1, 1}, {2, 1, 1}, {0, 0, 0}});
  // Inverted: swap top and bottom of the first hexahedron.
  auto h = m.mutableCellNodes(0);
  for (int i = 0; i < 4; ++i) {
    std::swap(h[static_cast<std::size_t>(i)], h[static_cast<std::size_t>(i + 4)]);
  }
  // Degenerate: a quadrangle with a repeated node.
  const NodeId q[] = {0, 1, 1, 3};
  const CellId deg = m.addCell(CellType::QUAD4, q);
  // Duplicate node, and a flat triangle (height 1e-5 for a base of 1).
  const NodeId dup = m.addNode(m.point(2));
  const NodeId a = m.addNode({5, 0, 0});
  const NodeId b = m.addNode({6, 0, 0});
  const NodeId c = m.addNode({5.5, 1e-5, 0});
  const NodeId tri[] = {a, b, c};
  const CellId flat = m.addCell(CellType::TRIA3, tri);
  const auto r = checkMesh(m);
  ASSERT_EQ(r.duplicateNodes.size(), 1u);
  EXPECT_EQ(r.duplicateNodes[0], (std::pair<NodeId, NodeId>{2, dup}));
  EXPECT_EQ(r.degenerateCells, std::vector<CellId>{deg});
  EXPECT_EQ(r.invertedCells, std::vector<CellId>{0});
  EXPECT_EQ(r.flatCells, std::vector<CellId>{flat});
  const auto d = meshCheckDiagnostics(m, r);
  ASSERT_EQ(d.size(), 4u);
  EXPECT_EQ(d[0].id, "MESHCHECK_1");
  EXPECT_NE(d[0].message.find("N3=N" + std::to_string(dup + 1)), std::string::npos) << d[0].message;
  EXPECT_NE(d[2].message.find("M1"), std::string::npos);
  EXPECT_EQ(d[3].severity, Severity::Alarm);
  // A looser APLAT accepts the flat triangle.
  EXPECT_TRUE(checkMesh(m, 1e-6).flatCells.empty());
}

// A clockwise face of a 2D mesh (as Salome writes them) is accepted, as in code_aster; a folded
// (bow-tie) face, whose corner jacobians change sign, is inverted.
TEST(MeshCheck, ClockwiseFaceOfA2DMeshIsAcceptedAFoldedOneIsInverted) {
  Mesh m = buildStructuredMesh({CellType::QUAD4, {2, 1, 1}, {2, 1, 1}, {0, 0, 0}});
  auto n = m.mutableCellNodes(0);
  std::swap(n[1], n[3]); // clockwise
  EXPECT_TRUE(checkMesh(m).invertedCells.empty());
  auto f = m.mutableCellNodes(1);
  std::swap(f[2], f[3]); // folded
  EXPECT_EQ(checkMesh(m).invertedCells, std::vector<CellId>{1});
}

} // namespace
} // namespace stella
