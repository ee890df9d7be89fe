// ORIE_PEAU and VERI_NORM share one definition of "outward" (SkinOrientation.hpp): on box meshes
// of every cell type, 2D meshes with all or part of their cells clockwise and 3D meshes of
// hexahedra, tetrahedra, prisms and pyramids (linear and quadratic), boundary cells first
// mis-oriented are turned by ORIE_PEAU to the geometric outward normal of the box (the
// independent reference), corner cells included, and then all pass the VERI_NORM test. Skin
// cells bounding no volume cell are oriented from the skin cells they touch.

#include "solver/mesh/SkinOrientation.hpp"
#include "solver/fem/BoxMesh.hpp"
#include "solver/mesh/CellTopology.hpp"
#include "solver/mesh/MeshGeometry.hpp"
#include "solver/mesh/MeshTransform.hpp"
#include "solver/mesh/StructuredMesher.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

struct BoxWithSkin {
  Mesh mesh;
  std::vector<CellId> skin;
  std::vector<Point3> outward; // geometric outward normal of each skin cell
};

// A box mesh of `type` with every boundary face (edge in 2D) as a skin cell, numbered like the
// volume cell's face: outward for a positively oriented cell.
BoxWithSkin boxWithSkin(CellType type) {
  const int dim = dimension(type);
  const fem::PlainMesh p = fem::boxMesh(type, {2, 2, 2}, {1.0, 1.0, 1.0});
  BoxWithSkin b;
  b.mesh.setDimension(dim);
  for (int n = 0; n < p.nodeCount(); ++n) {
    b.mesh.addNode({p.coordinates(n, 0), p.coordinates(n, 1), dim == 3 ? p.coordinates(n, 2) : 0.0});
  }
  for (int c = 0; c < p.cellCount(); ++c) {
    const std::vector<NodeId> nodes(p.cell(c), p.cell(c) + p.nodesPerCell());
    b.mesh.addCell(type, nodes);
  }
  const CellId volumes = b.mesh.cellCount();
  for (CellId c = 0; c < volumes; ++c) {
    const std::vector<NodeId> nodes(b.mesh.cellNodes(c).begin(), b.mesh.cellNodes(c).end());
    for (const auto& f : cellFaces(type)) {
      for (int axis = 0; axis < dim; ++axis) {
        for (double side : {0.0, 1.0}) {
          bool onPlane = true;
          for (int i = 0; i < vertexCount(f.type); ++i) {
            const NodeId n = nodes[static_cast<std::size_t>(f.nodes[static_cast<std::size_t>(i)])];
            onPlane = onPlane && std::abs(b.mesh.point(n)[static_cast<std::size_t>(axis)] - side) < 1e-12;
          }
          if (!onPlane) {
            continue;
          }
          std::vector<NodeId> fn;
          for (const int i : f.nodes) {
            fn.push_back(nodes[static_cast<std::size_t>(i)]);
          }
          b.skin.push_back(b.mesh.addCell(f.type, fn));
          Point3 o{0, 0, 0};
          o[static_cast<std::size_t>(axis)] = side == 0.0 ? -1.0 : 1.0;
          b.outward.push_back(o);
        }
      }
    }
  }
  return b;
}

void expectOutward(const BoxWithSkin& b, const std::string& what) {
  const auto bounded = boundedVolumes(b.mesh, b.skin, {});
  for (std::size_t i = 0; i < b.skin.size(); ++i) {
    EXPECT_GT(dot(cellNormal(b.mesh, b.skin[i]), b.outward[i]), 0.0)
        << what << ": " << b.mesh.cellName(b.skin[i]) << " points inward";
    ASSERT_EQ(bounded[i].size(), 1u) << what;
    EXPECT_TRUE(bounded[i].front().outward) << what << ": VERI_NORM rejects " << b.mesh.cellName(b.skin[i]);
  }
}

// Reverses the volume cells c with c % step == 0 (2D: clockwise cells) and the skin cells
// i with i % 3 == 0 (mis-oriented skin), then orients the skin.
void reverseAndOrient(BoxWithSkin& b, int volumeStep) {
  if (volumeStep > 0) {
    for (CellId c = 0; c < b.skin.front(); c += volumeStep) {
      reverseCell(b.mesh, c);
    }
  }
  for (std::size_t i = 0; i < b.skin.size(); i += 3) {
    reverseCell(b.mesh, b.skin[i]);
  }
  const auto summary = orientSkin(b.mesh, b.skin, {});
  EXPECT_TRUE(summary.unanchored.empty());
}

TEST(SkinOrientation, ClockwiseAndCounterClockwise2DMeshes) {
  for (const CellType t :
       {CellType::TRIA3, CellType::TRIA6, CellType::QUAD4, CellType::QUAD8, CellType::QUAD9}) {
    for (const int step : {0, 1, 2}) { // none, all, every other cell clockwise
      BoxWithSkin b = boxWithSkin(t);
      reverseAndOrient(b, step);
      expectOutward(b, std::string(name(t)) + " clockwise step " + std::to_string(step));
    }
  }
}

TEST(SkinOrientation, FacesOf3DCells) {
  for (const CellType t : {CellType::HEXA8, CellType::HEXA20, CellType::TETRA4, CellType::TETRA10,
                           CellType::PENTA6, CellType::PENTA15, CellType::PYRAM5, CellType::PYRAM13}) {
    BoxWithSkin b = boxWithSkin(t);
    reverseAndOrient(b, 0);
    expectOutward(b, std::string(name(t)));
  }
}

TEST(SkinOrientation, FreeSkinFollowsTheCellsItTouches2D) {
  // [0,2] x [0,1] in clockwise QUAD4; skin: the top edges, a rigid line continuing them from x = 2
  // to x = 4 (bounding nothing, half of it reversed) and a separate rigid line at y = 3.
  Mesh m = buildStructuredMesh({CellType::QUAD4, {2, 1, 1}, {2, 1, 1}, {0, 0, 0}});
  for (const CellId c : *m.cellGroup("SURFACE")) {
    reverseCell(m, c);
  }
  std::vector<CellId> skin = *m.cellGroup("YMAX");
  const NodeId corner = 5; // (2, 1): nodes are numbered x fastest
  ASSERT_EQ(m.point(corner), (Point3{2, 1, 0}));
  const NodeId e1 = m.addNode({3, 1, 0});
  const NodeId e2 = m.addNode({4, 1, 0});
  const NodeId ext1[] = {e1, corner};
  const NodeId ext2[] = {e1, e2};
  const std::vector<CellId> extension{m.addCell(CellType::SEG2, ext1), m.addCell(CellType::SEG2, ext2)};
  const NodeId f0 = m.addNode({0, 3, 0});
  const NodeId f1 = m.addNode({1, 3, 0});
  const NodeId f2 = m.addNode({2, 3, 0});
  const NodeId free1[] = {f0, f1};
  const NodeId free2[] = {f2, f1};
  const std::vector<CellId> alone{m.addCell(CellType::SEG2, free1), m.addCell(CellType::SEG2, free2)};
  skin.insert(skin.end(), extension.begin(), extension.end());
  skin.insert(skin.end(), alone.begin(), alone.end());
  const auto summary = orientSkin(m, skin, {});
  for (const CellId c : *m.cellGroup("YMAX")) {
    EXPECT_GT(cellNormal(m, c)[1], 0.0);
  }
  for (const CellId c : extension) {
    EXPECT_GT(cellNormal(m, c)[1], 0.0) << m.cellName(c);
  }
  EXPECT_GT(cellNormal(m, alone[0])[1] * cellNormal(m, alone[1])[1], 0.0); // coherent
  EXPECT_EQ(summary.unanchored, alone);
}

TEST(SkinOrientation, FreeSkinFollowsTheCellsItTouches3D) {
  // A unit cube of HEXA8; skin: its top faces and a flange of two QUAD4 at z = 1 for x in [1, 2]
  // sharing the edge x = 1 (bounding nothing), the second one reversed.
  Mesh m = buildStructuredMesh({CellType::HEXA8, {1, 1, 1}, {1, 1, 1}, {0, 0, 0}});
  std::vector<CellId> skin = *m.cellGroup("ZMAX");
  NodeId a = -1;
  NodeId b = -1;
  for (NodeId n = 0; n < m.nodeCount(); ++n) {
    if (m.point(n) == Point3{1, 0, 1}) {
      a = n;
    }
    if (m.point(n) == Point3{1, 1, 1}) {
      b = n;
    }
  }
  ASSERT_GE(a, 0);
  ASSERT_GE(b, 0);
  const NodeId c = m.addNode({1.5, 0, 1});
  const NodeId d = m.addNode({1.5, 1, 1});
  const NodeId e = m.addNode({2, 0, 1});
  const NodeId f = m.addNode({2, 1, 1});
  const NodeId q1[] = {a, b, d, c};
  const NodeId q2[] = {c, e, f, d}; // normal +z, q1's -z: incoherent
  const std::vector<CellId> flange{m.addCell(CellType::QUAD4, q1), m.addCell(CellType::QUAD4, q2)};
  skin.insert(skin.end(), flange.begin(), flange.end());
  const auto summary = orientSkin(m, skin, {});
  EXPECT_TRUE(summary.unanchored.empty());
  for (const CellId s : skin) {
    EXPECT_GT(cellNormal(m, s)[2], 0.0) << m.cellName(s);
  }
}

} // namespace
} // namespace stella
