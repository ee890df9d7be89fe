// MODI_MAILLAGE operations: rigid motions against closed forms, orientation reversal keeps
// geometry and flips the sign, ORIE_PEAU makes every skin normal point out of the body.

#include "solver/mesh/MeshTransform.hpp"
#include "interpreter/Diagnostics.hpp"
#include "solver/mesh/CellTopology.hpp"
#include "solver/mesh/MeshGeometry.hpp"
#include "solver/mesh/StructuredMesher.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

TEST(MeshTransform, RigidMotionsAndScaling) {
  Mesh m = buildStructuredMesh({CellType::HEXA8, {1, 1, 1}, {1, 1, 1}, {0, 0, 0}});
  translateMesh(m, {1, 2, 3});
  EXPECT_EQ(m.point(0), (Point3{1, 2, 3}));
  // A quarter turn about z through (1, 2, 3): (2, 2, 3) -> (1, 3, 3).
  rotateMesh(m, {1, 2, 3}, {0, 0, 1}, 90.0);
  const Point3 p = m.point(1);
  EXPECT_NEAR(p[0], 1.0, 1e-15);
  EXPECT_NEAR(p[1], 3.0, 1e-15);
  scaleMesh(m, 2.0);
  EXPECT_NEAR(cellMeasure(m, 0), 8.0, 1e-12);
}

TEST(MeshTransform, ReversalFlipsEveryType) {
  for (const auto& info : cellTypeTable) {
    if (info.dimension == 0) {
      continue;
    }
    const auto perm = orientationReversal(info.type);
    std::vector<int> sorted = perm;
    std::sort(sorted.begin(), sorted.end());
    for (int i = 0; i < info.nodeCount; ++i) {
      ASSERT_EQ(sorted[static_cast<std::size_t>(i)], i) << info.name << " is not a permutation";
    }
    // Mid nodes still sit at the middle of their (new) edges.
    const auto x = referenceCoordinates(info.type);
    std::vector<std::array<double, 3>> y(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      y[i] = x[static_cast<std::size_t>(perm[i])];
    }
    for (const auto& e : cellEdges(info.type)) {
      if (e.mid >= 0) {
        for (int d = 0; d < 3; ++d) {
          EXPECT_DOUBLE_EQ(y[e.mid][d], 0.5 * (y[e.a][d] + y[e.b][d])) << info.name;
        }
      }
    }
    if (info.dimension == 3) {
      Mesh m;
      std::vector<NodeId> nodes;
      for (const auto& p : x) {
        nodes.push_back(m.addNode(p));
      }
      m.addCell(info.type, nodes);
      const double v = cellMeasure(m, 0);
      reverseCell(m, 0);
      EXPECT_NEAR(cellMeasure(m, 0), -v, 1e-12) << info.name;
    }
  }
}

TEST(MeshTransform, MirrorKeepsPositiveCellsAndOutwardSkins) {
  Mesh m = buildStructuredMesh({CellType::HEXA20, {2, 1, 1}, {2, 1, 1}, {0, 0, 0}});
  const Point3 axis1{0, 1, 0};
  const Point3 axis2{0, 0, 1};
  mirrorMesh(m, {0, 0, 0}, axis1, &axis2); // x -> -x
  for (const CellId c : *m.cellGroup("VOLUME")) {
    EXPECT_GT(cellMeasure(m, c), 0.0);
  }
  // XMAX (now at x = -2) still points away from the body: -x.
  for (const CellId c : *m.cellGroup("XMAX")) {
    EXPECT_LT(cellNormal(m, c)[0], 0.0);
  }
}

TEST(MeshTransform, OrientSkin3DAnd2D) {
  Mesh m = buildStructuredMesh({CellType::HEXA27, {2, 2, 1}, {1, 1, 1}, {0, 0, 0}});
  const auto top = *m.cellGroup("ZMAX");
  reverseCell(m, top[0]);
  reverseCell(m, top[2]);
  EXPECT_EQ(orientSkin(m, top, {}).reversed, 2);
  for (const CellId c : top) {
    EXPECT_GT(cellNormal(m, c)[2], 0.0);
  }
  EXPECT_EQ(orientSkin(m, top, {}).reversed, 0);

  Mesh q = buildStructuredMesh({CellType::QUAD8, {2, 2, 1}, {1, 1, 1}, {0, 0, 0}});
  const auto left = *q.cellGroup("XMIN");
  reverseCell(q, left[1]);
  EXPECT_EQ(orientSkin(q, left, {}).reversed, 1);
  for (const CellId c : left) {
    EXPECT_LT(cellNormal(q, c)[0], 0.0);
  }
}

TEST(MeshTransform, InternalSkinNeedsASide) {
  Mesh m = buildStructuredMesh({CellType::QUAD4, {2, 1, 1}, {2, 1, 1}, {0, 0, 0}});
  // The internal edge x = 1 between the two quads.
  const NodeId a = 1;
  const NodeId b = 4;
  const NodeId e[] = {b, a};
  const CellId mid = m.addCell(CellType::SEG2, e);
  EXPECT_THROW(orientSkin(m, {mid}, {}), UserError);
  // Oriented out of the left quad: normal +x.
  orientSkin(m, {mid}, {0});
  EXPECT_GT(cellNormal(m, mid)[0], 0.0);
  orientSkin(m, {mid}, {1});
  EXPECT_LT(cellNormal(m, mid)[0], 0.0);
}

} // namespace
} // namespace stella
