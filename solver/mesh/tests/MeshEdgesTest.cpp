// minMaxEdgeLengths (code_aster's getMinMaxEdgeSizes) on cells whose edges are known by
// construction: straight vertex-to-vertex lengths, mid-edge nodes ignored, zero-length edges not
// counted as shortest, point cells without edges.

#include "solver/mesh/MeshEdges.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <vector>

namespace stella {
namespace {

std::vector<CellId> all(const Mesh& m) {
  std::vector<CellId> cells;
  for (CellId c = 0; c < m.cellCount(); ++c) {
    cells.push_back(c);
  }
  return cells;
}

TEST(MeshEdges, RectangleAndRightTriangle) {
  Mesh m;
  for (const Point3& p : {Point3{0, 0, 0}, Point3{2, 0, 0}, Point3{2, 0.5, 0}, Point3{0, 0.5, 0}}) {
    m.addNode(p);
  }
  const NodeId quad[] = {0, 1, 2, 3};
  m.addCell(CellType::QUAD4, quad);
  auto [shortest, longest] = minMaxEdgeLengths(m, all(m));
  EXPECT_DOUBLE_EQ(shortest, 0.5);
  EXPECT_DOUBLE_EQ(longest, 2.0);

  Mesh t;
  for (const Point3& p : {Point3{0, 0, 0}, Point3{3, 0, 0}, Point3{0, 4, 0}}) {
    t.addNode(p);
  }
  const NodeId tria[] = {0, 1, 2};
  t.addCell(CellType::TRIA3, tria);
  std::tie(shortest, longest) = minMaxEdgeLengths(t, all(t));
  EXPECT_DOUBLE_EQ(shortest, 3.0);
  EXPECT_DOUBLE_EQ(longest, 5.0); // the hypotenuse
}

// A 1 x 2 x 3 box: its 12 edges only (the face and body diagonals are not edges).
TEST(MeshEdges, HexahedronEdgesNotDiagonals) {
  Mesh m;
  const double x[] = {0, 1, 1, 0};
  const double y[] = {0, 0, 2, 2};
  for (double z : {0.0, 3.0}) {
    for (int i = 0; i < 4; ++i) {
      m.addNode({x[i], y[i], z});
    }
  }
  const NodeId hexa[] = {0, 1, 2, 3, 4, 5, 6, 7};
  m.addCell(CellType::HEXA8, hexa);
  const auto [shortest, longest] = minMaxEdgeLengths(m, all(m));
  EXPECT_DOUBLE_EQ(shortest, 1.0);
  EXPECT_DOUBLE_EQ(longest, 3.0);
}

// A QUAD8 whose mid-edge nodes are pushed off the straight edges: the lengths are still the
// vertex-to-vertex ones (1 and 1); a TETRA4 of unit legs: 1 and sqrt(2).
TEST(MeshEdges, QuadraticMidNodesIgnoredAndTetrahedron) {
  Mesh m;
  for (const Point3& p :
       {Point3{0, 0, 0}, Point3{1, 0, 0}, Point3{1, 1, 0}, Point3{0, 1, 0}, Point3{0.5, -0.3, 0},
        Point3{1.3, 0.5, 0}, Point3{0.5, 1.3, 0}, Point3{-0.3, 0.5, 0}}) {
    m.addNode(p);
  }
  const NodeId quad8[] = {0, 1, 2, 3, 4, 5, 6, 7};
  m.addCell(CellType::QUAD8, quad8);
  auto [shortest, longest] = minMaxEdgeLengths(m, all(m));
  EXPECT_DOUBLE_EQ(shortest, 1.0);
  EXPECT_DOUBLE_EQ(longest, 1.0);

  Mesh t;
  for (const Point3& p : {Point3{0, 0, 0}, Point3{1, 0, 0}, Point3{0, 1, 0}, Point3{0, 0, 1}}) {
    t.addNode(p);
  }
  const NodeId tetra[] = {0, 1, 2, 3};
  t.addCell(CellType::TETRA4, tetra);
  std::tie(shortest, longest) = minMaxEdgeLengths(t, all(t));
  EXPECT_DOUBLE_EQ(shortest, 1.0);
  EXPECT_DOUBLE_EQ(longest, std::sqrt(2.0));
}

// A segment of zero length (two nodes at one place) is not the shortest edge; point cells have
// no edge: only POI1 cells give (0, 0).
TEST(MeshEdges, ZeroLengthEdgesAndPointCells) {
  Mesh m;
  for (const Point3& p : {Point3{0, 0, 0}, Point3{0, 0, 0}, Point3{0.25, 0, 0}}) {
    m.addNode(p);
  }
  const NodeId zero[] = {0, 1};
  const NodeId quarter[] = {1, 2};
  const NodeId point[] = {2};
  m.addCell(CellType::SEG2, zero);
  m.addCell(CellType::SEG2, quarter);
  m.addCell(CellType::POI1, point);
  auto [shortest, longest] = minMaxEdgeLengths(m, all(m));
  EXPECT_DOUBLE_EQ(shortest, 0.25);
  EXPECT_DOUBLE_EQ(longest, 0.25);
  const std::vector<CellId> points = {2};
  std::tie(shortest, longest) = minMaxEdgeLengths(m, points);
  EXPECT_EQ(shortest, 0.0);
  EXPECT_EQ(longest, 0.0);
}

} // namespace
} // namespace stella
