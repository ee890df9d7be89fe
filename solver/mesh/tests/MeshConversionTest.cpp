// CREA_MAILLAGE operations: node counts of converted structured meshes equal those of meshes
// built directly in the target type (a conforming conversion shares its new nodes), geometry is
// preserved, and groups follow.

#include "solver/mesh/MeshConversion.hpp"
#include "solver/mesh/CellTopology.hpp"
#include "solver/mesh/MeshCheck.hpp"
#include "solver/mesh/MeshGeometry.hpp"
#include "solver/mesh/StructuredMesher.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

StructuredSpec box(CellType t) {
  return {t, {3, 2, 2}, {3, 2, 1}, {0, 0, 0}};
}

TEST(MeshConversion, LineQuadMatchesDirectQuadraticMesh) {
  for (const auto& [lin, quad] :
       {std::pair{CellType::HEXA8, CellType::HEXA20}, std::pair{CellType::TETRA4, CellType::TETRA10},
        std::pair{CellType::PENTA6, CellType::PENTA15}, std::pair{CellType::QUAD4, CellType::QUAD8}}) {
    const Mesh converted = convertCells(buildStructuredMesh(box(lin)), CellConversion::LineToQuad, {});
    const Mesh direct = buildStructuredMesh(box(quad));
    EXPECT_EQ(converted.nodeCount(), direct.nodeCount()) << name(quad);
    EXPECT_EQ(converted.cellCount(), direct.cellCount());
    EXPECT_EQ(converted.cellType(0), quad);
    EXPECT_TRUE(checkMesh(converted).clean()) << name(quad);
    EXPECT_EQ(converted.cellGroup("XMAX")->size(), direct.cellGroup("XMAX")->size());
  }
}

TEST(MeshConversion, QuadLineRemovesMidNodes) {
  const Mesh q = buildStructuredMesh(box(CellType::HEXA27));
  const Mesh l = convertCells(q, CellConversion::QuadToLine, {});
  const Mesh direct = buildStructuredMesh(box(CellType::HEXA8));
  EXPECT_EQ(l.nodeCount(), direct.nodeCount());
  EXPECT_EQ(l.cellType(0), CellType::HEXA8);
  EXPECT_EQ(l.nodeGroup("XMIN")->size(), direct.nodeGroup("XMIN")->size());
  double v = 0;
  for (const CellId c : *l.cellGroup("VOLUME")) {
    v += cellMeasure(l, c);
  }
  EXPECT_NEAR(v, 6.0, 1e-12);
}

TEST(MeshConversion, Hexa20To27AndPenta15To18AndModiMaille) {
  const Mesh h = convertCells(buildStructuredMesh(box(CellType::HEXA20)), CellConversion::Hexa20To27, {});
  EXPECT_EQ(h.nodeCount(), buildStructuredMesh(box(CellType::HEXA27)).nodeCount());
  EXPECT_EQ(h.cellType(h.cellGroup("XMAX")->front()), CellType::QUAD9);
  const Mesh p = convertCells(buildStructuredMesh(box(CellType::PENTA15)), CellConversion::Penta15To18, {});
  EXPECT_EQ(p.nodeCount(), buildStructuredMesh(box(CellType::PENTA18)).nodeCount());
  // Face centres sit at the centre of flat faces.
  for (CellId c = 0; c < h.cellCount(); ++c) {
    for (const auto& f : cellFaces(h.cellType(c))) {
      if (f.nodes.size() == 9) {
        Point3 centre{0, 0, 0};
        for (int i = 0; i < 4; ++i) {
          centre =
              centre +
              0.25 * h.point(h.cellNodes(c)[static_cast<std::size_t>(f.nodes[static_cast<std::size_t>(i)])]);
        }
        EXPECT_LT(norm(h.point(h.cellNodes(c)[static_cast<std::size_t>(f.nodes.back())]) - centre), 1e-12);
      }
    }
  }
  const Mesh q = buildStructuredMesh({CellType::QUAD8, {2, 1, 1}, {2, 1, 1}, {0, 0, 0}});
  const Mesh q9 = convertCells(q, CellConversion::Quad8To9, {});
  EXPECT_EQ(q9.nodeCount(), q.nodeCount() + 2);
  const Mesh s4 = convertCells(q, CellConversion::Seg3To4, *q.cellGroup("YMIN"));
  EXPECT_EQ(s4.cellType(s4.cellGroup("YMIN")->front()), CellType::SEG4);
  EXPECT_EQ(s4.nodeCount(), q.nodeCount() + 4); // 2 edges, 2 thirds each; the quadrangles keep the mids
}

TEST(MeshConversion, PointCellsAndRestriction) {
  const Mesh m = buildStructuredMesh(box(CellType::HEXA8));
  const Mesh p = addPointCells(m, *m.nodeGroup("ORIGIN"), "PT");
  EXPECT_EQ(p.cellCount(), m.cellCount() + 1);
  EXPECT_EQ(p.cellType(p.cellGroup("PT")->front()), CellType::POI1);
  const Mesh r = restrictMesh(m, *m.cellGroup("XMAX"), {"XMAX"}, {"XMAX"});
  EXPECT_EQ(r.cellCount(), 4);
  EXPECT_EQ(r.nodeCount(), 9);
  EXPECT_EQ(r.cellGroup("XMAX")->size(), 4u);
  EXPECT_EQ(r.nodeGroup("XMAX")->size(), 9u);
  EXPECT_FALSE(r.hasCellGroup("VOLUME"));
  // Names follow the kept entities.
  EXPECT_EQ(r.cellName(0), "M1");
}

} // namespace
} // namespace stella
