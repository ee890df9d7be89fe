// Structured meshes: counts, total measure, positive cells, outward boundary groups, and a
// conforming mesh (every interior face shared by exactly two cells).

#include "solver/mesh/StructuredMesher.hpp"
#include "interpreter/Diagnostics.hpp"
#include "solver/mesh/CellTopology.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

namespace stella {
namespace {

TEST(StructuredMesher, EveryBoxTypeIsConformingAndPositive) {
  for (const CellType t : {CellType::HEXA8, CellType::HEXA20, CellType::HEXA27, CellType::TETRA4,
                           CellType::TETRA10, CellType::PENTA6, CellType::PENTA15, CellType::PENTA18}) {
    StructuredSpec s{t, {3, 2, 2}, {3.0, 1.0, 2.0}, {1.0, 0.0, 0.0}};
    const Mesh m = buildStructuredMesh(s);
    double volume = 0;
    std::map<std::vector<NodeId>, int> faces;
    for (const CellId c : *m.cellGroup("VOLUME")) {
      volume += cellMeasure(m, c);
      for (const double j : cornerJacobians(m, c)) {
        EXPECT_GT(j, 0.0) << name(t);
      }
      for (const auto& f : cellFaces(t)) {
        std::vector<NodeId> key;
        for (const int i : f.nodes) {
          key.push_back(m.cellNodes(c)[static_cast<std::size_t>(i)]);
        }
        std::sort(key.begin(), key.end());
        ++faces[key];
      }
    }
    EXPECT_NEAR(volume, 6.0, 1e-12) << name(t);
    std::size_t boundary = 0;
    for (const auto& [k, n] : faces) {
      EXPECT_LE(n, 2) << name(t);
      boundary += n == 1 ? 1 : 0;
    }
    std::size_t grouped = 0;
    for (const char* g : {"XMIN", "XMAX", "YMIN", "YMAX", "ZMIN", "ZMAX"}) {
      ASSERT_TRUE(m.hasCellGroup(g)) << g;
      grouped += m.cellGroup(g)->size();
    }
    EXPECT_EQ(boundary, grouped) << name(t);
    // XMAX faces point to +x, with total area 1 x 2.
    Point3 area{0, 0, 0};
    for (const CellId c : *m.cellGroup("XMAX")) {
      area = area + cellNormal(m, c);
    }
    EXPECT_NEAR(area[0], 2.0, 1e-12) << name(t);
    EXPECT_EQ(m.point(0), (Point3{1.0, 0.0, 0.0}));
  }
}

TEST(StructuredMesher, RectangleCountsAndEdges) {
  const Mesh q = buildStructuredMesh({CellType::QUAD8, {4, 2, 1}, {2.0, 1.0, 1.0}, {0, 0, 0}});
  EXPECT_EQ(q.dimension(), 2);
  EXPECT_EQ(q.cellGroup("SURFACE")->size(), 8u);
  EXPECT_EQ(q.nodeCount(), 9 * 5 - 8); // lattice minus quad centres
  EXPECT_EQ(q.cellGroup("YMAX")->size(), 4u);
  EXPECT_EQ(q.cellType(q.cellGroup("YMAX")->front()), CellType::SEG3);
  EXPECT_EQ(q.nodeGroup("YMAX")->size(), 9u);
  // The top edges' outward normals point to +y.
  for (const CellId c : *q.cellGroup("YMAX")) {
    EXPECT_GT(cellNormal(q, c)[1], 0.0);
  }
  const Mesh t = buildStructuredMesh({CellType::TRIA3, {2, 2, 1}, {1.0, 1.0, 1.0}, {0, 0, 0}});
  EXPECT_EQ(t.cellGroup("SURFACE")->size(), 8u);
  double area = 0;
  for (const CellId c : *t.cellGroup("SURFACE")) {
    area += cellMeasure(t, c);
    EXPECT_GT(cellNormal(t, c)[2], 0.0);
  }
  EXPECT_NEAR(area, 1.0, 1e-14);
}

TEST(StructuredMesher, RefusesWhatItCannotBuild) {
  EXPECT_THROW(buildStructuredMesh({CellType::PYRAM5, {1, 1, 1}, {1, 1, 1}, {0, 0, 0}}), UserError);
  EXPECT_THROW(buildStructuredMesh({CellType::QUAD4, {0, 1, 1}, {1, 1, 1}, {0, 0, 0}}), UserError);
}

} // namespace
} // namespace stella
