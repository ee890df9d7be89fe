// ORIE_NORM_COQUE / ORIE_LIGNE library functions: shells and lines scrambled by reversing some
// cells come back consistent, along the requested direction at the requested node; sets that
// cannot be oriented (three faces on one edge) are refused with ORIE_1.

#include "solver/mesh/CellOrientation.hpp"
#include "interpreter/Diagnostics.hpp"
#include "solver/mesh/CellTopology.hpp"
#include "solver/mesh/GroupOperations.hpp"
#include "solver/mesh/MeshGeometry.hpp"
#include "solver/mesh/MeshTransform.hpp"
#include "solver/mesh/StructuredMesher.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

TEST(CellOrientation, FlatShellTurnsToTheRequestedSide) {
  Mesh m = buildStructuredMesh({CellType::QUAD8, {3, 2, 1}, {3, 2, 1}, {0, 0, 0}});
  const auto cells = *m.cellGroup("SURFACE");
  ASSERT_EQ(cells.size(), 6u);
  reverseCell(m, cells[0]);
  reverseCell(m, cells[3]);
  // Towards -z: the four cells still facing +z are reversed.
  auto r = orientShells(m, cells, Point3{0, 0, -1}, std::nullopt);
  EXPECT_EQ(r.reversed, 4);
  EXPECT_EQ(r.components, 1);
  for (const CellId c : cells) {
    EXPECT_NEAR(cellNormal(m, c)[2], -1.0, 1e-12) << c; // unit squares: area vector = -e_z
  }
  // Without a direction the first cell is the reference: nothing to do.
  r = orientShells(m, cells, std::nullopt, std::nullopt);
  EXPECT_EQ(r.reversed, 0);
  // Mid-edge nodes follow their edges: the reversed QUAD8 still has its mid nodes at mid-edges.
  for (const CellId c : cells) {
    const auto n = m.cellNodes(c);
    for (const auto& e : cellEdges(CellType::QUAD8)) {
      const Point3 mid =
          0.5 * (m.point(n[static_cast<std::size_t>(e.a)]) + m.point(n[static_cast<std::size_t>(e.b)]));
      EXPECT_LT(norm(m.point(n[static_cast<std::size_t>(e.mid)]) - mid), 1e-12);
    }
  }
}

TEST(CellOrientation, ClosedSkinOutwardFromOneNode) {
  Mesh m = buildStructuredMesh({CellType::HEXA8, {2, 2, 2}, {1, 1, 1}, {0, 0, 0}});
  std::vector<std::vector<CellId>> sides;
  for (const char* g : {"XMIN", "XMAX", "YMIN", "YMAX", "ZMIN", "ZMAX"}) {
    sides.push_back(*m.cellGroup(g));
  }
  const auto skin = unionOf(sides);
  ASSERT_EQ(skin.size(), 24u);
  for (std::size_t i = 0; i < skin.size(); i += 3) {
    reverseCell(m, skin[i]); // 8 faces inward
  }
  // The normal at the corner (1, 1, 1) must point along (1, 1, 1): outward everywhere.
  const auto corner =
      nodesWhere(m, [](const Point3& x) { return x[0] == 1.0 && x[1] == 1.0 && x[2] == 1.0; });
  ASSERT_EQ(corner.size(), 1u);
  const auto r = orientShells(m, skin, Point3{1, 1, 1}, corner.front());
  EXPECT_EQ(r.reversed, 8);
  EXPECT_EQ(r.components, 1);
  for (const CellId c : skin) {
    EXPECT_GT(dot(cellNormal(m, c), cellCentroid(m, c) - Point3{0.5, 0.5, 0.5}), 0.0) << m.cellName(c);
  }
}

TEST(CellOrientation, ThreeFacesOnOneEdgeAreRefused) {
  Mesh m;
  const NodeId a = m.addNode({0, 0, 0});
  const NodeId b = m.addNode({1, 0, 0});
  std::vector<CellId> fins;
  for (const Point3 tip : {Point3{0.5, 1, 0}, Point3{0.5, -1, 0}, Point3{0.5, 0, 1}}) {
    fins.push_back(m.addCell(CellType::TRIA3, std::vector<NodeId>{a, b, m.addNode(tip)}));
  }
  try {
    orientShells(m, fins, std::nullopt, std::nullopt);
    ADD_FAILURE() << "no error";
  } catch (const UserError& e) {
    EXPECT_EQ(e.first().id, "ORIE_1");
  }
  try {
    orientLines(m, fins, std::nullopt, std::nullopt);
    ADD_FAILURE() << "no error";
  } catch (const UserError& e) {
    EXPECT_EQ(e.first().id, "ORIE_2"); // not segments
  }
}

TEST(CellOrientation, LinesFollowTheTangentAtTheNode) {
  Mesh m = buildStructuredMesh({CellType::QUAD8, {3, 2, 1}, {3, 2, 1}, {0, 0, 0}});
  // The closed boundary loop (10 SEG3), scrambled.
  const auto loop =
      unionOf({*m.cellGroup("XMIN"), *m.cellGroup("XMAX"), *m.cellGroup("YMIN"), *m.cellGroup("YMAX")});
  ASSERT_EQ(loop.size(), 10u);
  for (std::size_t i = 0; i < loop.size(); i += 2) {
    reverseCell(m, loop[i]);
  }
  // Clockwise: at the origin the tangent runs along +y (up the XMIN side).
  const NodeId origin = m.nodeGroup("ORIGIN")->front();
  const auto r = orientLines(m, loop, Point3{0, 1, 0}, origin);
  EXPECT_EQ(r.components, 1);
  // Every node of the loop starts exactly one segment and ends exactly one; the loop's signed
  // area (shoelace over the segments) is -6 (clockwise 3 x 2 rectangle).
  std::map<NodeId, int> starts, ends;
  double area = 0.0;
  for (const CellId c : loop) {
    const auto n = m.cellNodes(c);
    ++starts[n[0]];
    ++ends[n[1]];
    const Point3 p = m.point(n[0]), q = m.point(n[1]), mid = m.point(n[2]);
    EXPECT_LT(norm(mid - 0.5 * (p + q)), 1e-12); // SEG3 middle node kept in the middle
    area += 0.5 * (p[0] * q[1] - q[0] * p[1]);
  }
  EXPECT_NEAR(area, -6.0, 1e-12);
  for (const auto& [n, k] : starts) {
    EXPECT_EQ(k, 1);
    EXPECT_EQ(ends[n], 1);
  }
  // The opposite tangent turns the whole loop over: all 10 reversed.
  EXPECT_EQ(orientLines(m, loop, Point3{0, -1, 0}, origin).reversed, 10);
}

} // namespace
} // namespace stella
