// DEFI_GROUP selections on structured meshes whose answers are known by construction.

#include "solver/mesh/GroupOperations.hpp"
#include "interpreter/Diagnostics.hpp"
#include "solver/mesh/MeshGeometry.hpp"
#include "solver/mesh/StructuredMesher.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

namespace stella {
namespace {

// 4 x 2 QUAD4 on [0,4] x [0,2]: nodes 5 x 3, node (i, j) = i + 5 j.
Mesh plate() {
  return buildStructuredMesh({CellType::QUAD4, {4, 2, 1}, {4, 2, 1}, {0, 0, 0}});
}

TEST(GroupOperations, SetOperations) {
  EXPECT_EQ(unionOf({{3, 1}, {2, 3}}), (std::vector<std::int32_t>{1, 2, 3}));
  EXPECT_EQ(intersectionOf({{1, 2, 3}, {3, 2, 9}, {2, 3}}), (std::vector<std::int32_t>{2, 3}));
  EXPECT_EQ(differenceOf({{1, 2, 3, 4}, {2}, {4}}), (std::vector<std::int32_t>{1, 3}));
}

TEST(GroupOperations, TypeFilterAndFacing) {
  const Mesh m = plate();
  EXPECT_EQ(filterCellType(m, allCells(m), "2D").size(), 8u);
  EXPECT_EQ(filterCellType(m, allCells(m), "SEG2").size(), 12u);
  // Edges whose outward normal is +y: the top edge (4 segments), not the bottom one.
  const auto top = cellsFacing(m, {0, 1, 0}, 0.5, true);
  EXPECT_EQ(top, *m.cellGroup("YMAX"));
  EXPECT_EQ(cellsFacing(m, {0, 1, 0}, 0.5, false).size(), 8u);
  EXPECT_NEAR(nauticalDirection({90.0})[1], 1.0, 1e-15);
}

TEST(GroupOperations, SphereBandAndSupport) {
  const Mesh m = plate();
  const auto quads = *m.cellGroup("SURFACE");
  // Sphere of radius 0.5 around (2, 1): only the node (2, 1) is inside; 4 quads touch it.
  const Point3 c{2, 1, 0};
  EXPECT_EQ(cellsByNodes(
                m, quads, [&](NodeId n) { return norm(m.point(n) - c) <= 0.5; }, NodeCriterion::AtLeastOne)
                .size(),
            4u);
  // Band |x - 0.5| <= 0.6 holds the nodes x = 0 and x = 1: exactly the first column of quads.
  const auto band = cellsByNodes(
      m, quads,
      [&](NodeId n) {
        return distanceToPlane(m.point(n), {0.5, 0, 0}, {1, 0, 0}) <= 0.6;
      },
      NodeCriterion::All);
  EXPECT_EQ(band.size(), 2u);
  // APPUI SOMMET on the nodes of XMIN: the XMIN edges only (quads have two nodes off it).
  const auto xmin = *m.nodeGroup("XMIN");
  const auto support = cellsByNodes(
      m, allCells(m), [&](NodeId n) { return std::binary_search(xmin.begin(), xmin.end(), n); },
      NodeCriterion::Vertices);
  EXPECT_EQ(support, *m.cellGroup("XMIN"));
}

TEST(GroupOperations, NodesByCriterion) {
  const Mesh q = buildStructuredMesh({CellType::QUAD9, {1, 1, 1}, {1, 1, 1}, {0, 0, 0}});
  const std::vector<CellId> cell{0};
  EXPECT_EQ(nodesOfCells(q, cell, "SOMMET").size(), 4u);
  EXPECT_EQ(nodesOfCells(q, cell, "MILIEU").size(), 4u);
  EXPECT_EQ(nodesOfCells(q, cell, "CENTRE"), (std::vector<NodeId>{4}));
  EXPECT_EQ(nodesOfCells(q, cell, "TOUS").size(), 9u);
}

TEST(GroupOperations, OrderedNodes) {
  const Mesh m = plate();
  // The top edge from its right end: x = 4, 3, 2, 1, 0 at y = 2.
  const NodeId right = 14;
  const auto ordered = orderedChainNodes(m, *m.cellGroup("YMAX"), right, std::nullopt);
  EXPECT_EQ(ordered, (std::vector<NodeId>{14, 13, 12, 11, 10}));
  // A chain of SEG3 keeps its mid nodes in walking order.
  const Mesh q = buildStructuredMesh({CellType::QUAD8, {2, 1, 1}, {2, 1, 1}, {0, 0, 0}});
  const auto line = orderedChainNodes(q, *q.cellGroup("YMIN"), std::nullopt, std::nullopt);
  ASSERT_EQ(line.size(), 5u);
  for (std::size_t i = 1; i < line.size(); ++i) {
    EXPECT_NEAR(std::abs(q.point(line[i])[0] - q.point(line[i - 1])[0]), 0.5, 1e-14);
  }
  // Nodes on the diagonal segment (0,0)-(4,2): (0,0), (2,1), (4,2).
  std::vector<NodeId> all(15);
  std::iota(all.begin(), all.end(), 0);
  EXPECT_EQ(nodesOnSegment(m, all, 0, 14, 1e-9, false), (std::vector<NodeId>{0, 7, 14}));
  EXPECT_THROW(orderedChainNodes(m, *m.cellGroup("SURFACE"), std::nullopt, std::nullopt), UserError);
}

TEST(GroupOperations, OrderedGroupKeepsOrder) {
  Mesh m = plate();
  m.setOrderedNodeGroup("LINE", {3, 1, 3, 2});
  EXPECT_EQ(*m.nodeGroup("LINE"), (std::vector<NodeId>{3, 1, 2}));
}

} // namespace
} // namespace stella
