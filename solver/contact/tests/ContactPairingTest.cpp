// Pairing: projections, weights, normals and gaps against hand-computed geometry (flat, slanted
// and curved quadratic master cells), TOLE_PROJ_EXT, DIST_APPA, NODAL, LISSAGE.

#include "solver/contact/ContactPairing.hpp"
#include "solver/contact/tests/ContactTestMeshes.hpp"
#include "solver/fem/ReferenceElement.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace stella::contact {
namespace {

ContactZone zone(const std::string& master, const std::string& slave) {
  ContactZone z;
  z.masterGroup = master;
  z.slaveGroup = slave;
  return z;
}

std::vector<ContactLink> pair(const Mesh& mesh, const ContactZone& z, bool smoothing = false) {
  PairingOptions o;
  o.dimension = mesh.dimension();
  o.smoothing = smoothing;
  return pairZone(mesh, meshPositions(mesh, nullptr), 0, z, o);
}

TEST(ContactPairing, FlatBlocksGapsAndWeights2D) {
  // Master A_YMAX: nodes x = 0, 0.5, 1 at y = 1; slave B_YMIN: x = 0, 1/3, 2/3, 1 at y = 1.25.
  const Mesh mesh = testing::twoBlocks(CellType::QUAD4, 2, 3, 0.25);
  const auto links = pair(mesh, zone("A_YMAX", "B_YMIN"));
  ASSERT_EQ(links.size(), 4u);
  for (const auto& l : links) {
    ASSERT_TRUE(l.paired);
    EXPECT_NEAR(l.gap, 0.25, 1e-13);
    EXPECT_NEAR(l.normal[1], 1.0, 1e-13);
    EXPECT_NEAR(std::abs(l.tangent1[0]), 1.0, 1e-13);
    const Point3 x = mesh.point(l.slave);
    EXPECT_NEAR(l.projection[0], x[0], 1e-13);
    double interpolated = 0.0;
    for (std::size_t i = 0; i < l.masterNodes.size(); ++i) {
      interpolated += l.weights[i] * mesh.point(l.masterNodes[i])[0];
    }
    EXPECT_NEAR(interpolated, x[0], 1e-13);
  }
  // Slave node x = 1/3 lies on the master edge [0, 0.5]: weights 1/3 and 2/3.
  const auto& l = links[1];
  std::vector<double> w = l.weights;
  std::sort(w.begin(), w.end());
  EXPECT_NEAR(w[0], 1.0 / 3.0, 1e-13);
  EXPECT_NEAR(w[1], 2.0 / 3.0, 1e-13);
}

TEST(ContactPairing, SlantedSegmentSignedGap) {
  Mesh mesh;
  mesh.setDimension(2);
  const NodeId a = mesh.addNode({0, 0, 0});
  const NodeId b = mesh.addNode({2, 1, 0});
  const NodeId s = mesh.addNode({1, 2, 0});
  const NodeId s2 = mesh.addNode({1, 3, 0});
  mesh.setCellGroup("M", {mesh.addCell(CellType::SEG2, std::vector<NodeId>{a, b})});
  mesh.setCellGroup("S", {mesh.addCell(CellType::SEG2, std::vector<NodeId>{s, s2})});
  auto z = zone("M", "S");
  const auto links = pair(mesh, z);
  // Node s projects at t = 4/5 of the segment, (1.6, 0.8); the normal (1, -2)/sqrt5 points away
  // from s: gap -sqrt(1.8).
  const auto& l = links[0];
  ASSERT_EQ(l.slave, s);
  EXPECT_NEAR(l.projection[0], 1.6, 1e-12);
  EXPECT_NEAR(l.projection[1], 0.8, 1e-12);
  EXPECT_NEAR(l.gap, -std::sqrt(1.8), 1e-12);
  EXPECT_NEAR(l.normal[0], 1.0 / std::sqrt(5.0), 1e-12);
  EXPECT_NEAR(l.xi[0], 0.6, 1e-12);
}

// One quadratic master cell z = a x^2 + b y^2 (3D) or y = a x^2 (2D) with an affine parametric
// map; slave points at distance h along the exact normal from a surface point must have gap h
// and project on that point.
void curvedCase(CellType type) {
  const auto& ref = fem::referenceElement(type);
  const bool twoD = ref.dimension() == 1;
  const double a = 0.15;
  const double b = 0.1;
  auto surface = [&](double x, double y) {
    return twoD ? Point3{x, a * x * x, 0} : Point3{x, y, a * x * x + b * y * y};
  };
  Mesh mesh;
  mesh.setDimension(twoD ? 2 : 3);
  std::vector<NodeId> nodes;
  for (int i = 0; i < ref.nodeCount(); ++i) {
    const auto& xi = ref.node(i);
    nodes.push_back(mesh.addNode(surface(xi(0), xi(1))));
  }
  mesh.setCellGroup("M", {mesh.addCell(type, nodes)});
  const double h = 0.05;
  std::vector<std::array<double, 2>> targets =
      twoD ? std::vector<std::array<double, 2>>{{-0.5, 0}, {0.3, 0}, {0.8, 0}}
           : std::vector<std::array<double, 2>>{{0.2, 0.2}, {0.1, 0.6}, {0.5, 0.1}};
  std::vector<NodeId> slaves;
  for (const auto& t : targets) {
    const Point3 p = surface(t[0], t[1]);
    // 2D: a SEG from x = -1 to 1 has the outward normal (t_y, -t_x), pointing down.
    Point3 n = twoD ? Point3{2 * a * t[0], -1, 0} : Point3{-2 * a * t[0], -2 * b * t[1], 1};
    n = (1.0 / norm(n)) * n;
    slaves.push_back(mesh.addNode(p + h * n));
  }
  // Slave cells: points (POI1 are not contact cells; use a segment/triangle through them).
  const NodeId extra = mesh.addNode({5, 5, 5});
  if (twoD) {
    mesh.setCellGroup("S", {mesh.addCell(CellType::SEG2, std::vector<NodeId>{slaves[0], slaves[1]}),
                            mesh.addCell(CellType::SEG2, std::vector<NodeId>{slaves[1], slaves[2]})});
  } else {
    mesh.setCellGroup("S",
                      {mesh.addCell(CellType::TRIA3, std::vector<NodeId>{slaves[0], slaves[1], slaves[2]})});
  }
  (void)extra;
  auto z = zone("M", "S");
  z.extensionTolerance = 0.5;
  const auto links = pair(mesh, z);
  ASSERT_EQ(links.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    const auto& l = links[k];
    ASSERT_TRUE(l.paired) << info(type).name;
    const Point3 p = surface(targets[k][0], targets[k][1]);
    EXPECT_NEAR(l.gap, h, 1e-10) << info(type).name;
    EXPECT_NEAR(norm(l.projection - p), 0.0, 1e-10) << info(type).name;
  }
}

TEST(ContactPairing, CurvedQuadraticMasterCells) {
  for (CellType t : {CellType::SEG3, CellType::TRIA6, CellType::QUAD8, CellType::QUAD9}) {
    curvedCase(t);
  }
}

TEST(ContactPairing, ThreeDimensionalFlatFaces) {
  for (CellType t : {CellType::HEXA8, CellType::TETRA4, CellType::HEXA27}) {
    const Mesh mesh = testing::twoBlocks(t, 2, 3, 0.1);
    const auto links = pair(mesh, zone("A_ZMAX", "B_ZMIN"));
    EXPECT_EQ(links.size(), t == CellType::HEXA27 ? 49u : 16u);
    for (const auto& l : links) {
      ASSERT_TRUE(l.paired);
      EXPECT_NEAR(l.gap, 0.1, 1e-12);
      EXPECT_NEAR(l.normal[2], 1.0, 1e-12);
      EXPECT_NEAR(std::abs(dot(l.tangent1, l.tangent2)), 0.0, 1e-12);
      EXPECT_NEAR(dot(cross(l.tangent1, l.tangent2), l.normal), 1.0, 1e-12);
      double sum = 0;
      for (double w : l.weights) {
        sum += w;
      }
      EXPECT_NEAR(sum, 1.0, 1e-12);
    }
  }
}

Mesh overhangMesh(double slaveX) {
  Mesh mesh;
  mesh.setDimension(2);
  const NodeId a = mesh.addNode({1, 0, 0});
  const NodeId b = mesh.addNode({0, 0, 0});
  const NodeId s1 = mesh.addNode({slaveX, 0.1, 0});
  const NodeId s2 = mesh.addNode({slaveX - 5, 0.1, 0});
  mesh.setCellGroup("M", {mesh.addCell(CellType::SEG2, std::vector<NodeId>{a, b})});
  mesh.setCellGroup("S", {mesh.addCell(CellType::SEG2, std::vector<NodeId>{s1, s2})});
  return mesh;
}

TEST(ContactPairing, ProjectionOutsideTheCell) {
  // Master [0, 1] (normal +y); slave at x = 1.2: parametric excess 0.4.
  const Mesh mesh = overhangMesh(1.2);
  auto z = zone("M", "S");
  z.extensionTolerance = 0.5;
  auto links = pair(mesh, z);
  ASSERT_TRUE(links[0].paired);
  EXPECT_NEAR(links[0].projection[0], 1.0, 1e-13); // brought back on the cell
  z.extensionTolerance = 0.1;
  links = pair(mesh, z);
  EXPECT_FALSE(links[0].paired);
}

TEST(ContactPairing, PairingDistance) {
  const Mesh mesh = testing::twoBlocks(CellType::QUAD4, 2, 2, 0.3);
  auto z = zone("A_YMAX", "B_YMIN");
  z.pairingDistance = 0.2;
  for (const auto& l : pair(mesh, z)) {
    EXPECT_FALSE(l.paired);
  }
  z.pairingDistance = 0.4;
  for (const auto& l : pair(mesh, z)) {
    EXPECT_TRUE(l.paired);
  }
}

TEST(ContactPairing, NodalPairingUsesSlaveNormal) {
  const Mesh mesh = testing::twoBlocks(CellType::QUAD4, 2, 2, 0.1);
  auto z = zone("A_YMAX", "B_YMIN");
  z.pairing = Pairing::Nodal;
  for (const auto& l : pair(mesh, z)) {
    ASSERT_TRUE(l.paired);
    ASSERT_EQ(l.masterNodes.size(), 1u);
    EXPECT_EQ(l.weights[0], 1.0);
    EXPECT_NEAR(mesh.point(l.masterNodes[0])[0], mesh.point(l.slave)[0], 1e-14);
    EXPECT_NEAR(l.normal[1], 1.0, 1e-13); // opposite of B_YMIN's outward normal (0, -1)
    EXPECT_NEAR(l.gap, 0.1, 1e-13);
  }
}

TEST(ContactPairing, SmoothedNormalsInterpolateNodalAverages) {
  Mesh mesh;
  mesh.setDimension(2);
  const NodeId p0 = mesh.addNode({2, 1, 0});
  const NodeId p1 = mesh.addNode({1, 0, 0});
  const NodeId p2 = mesh.addNode({0, 0, 0});
  const NodeId s = mesh.addNode({0.5, 0.5, 0});
  const NodeId s2 = mesh.addNode({-3, 0.5, 0});
  mesh.setCellGroup("M", {mesh.addCell(CellType::SEG2, std::vector<NodeId>{p0, p1}),
                          mesh.addCell(CellType::SEG2, std::vector<NodeId>{p1, p2})});
  mesh.setCellGroup("S", {mesh.addCell(CellType::SEG2, std::vector<NodeId>{s, s2})});
  auto z = zone("M", "S");
  const auto plain = pair(mesh, z, false);
  EXPECT_NEAR(plain[0].normal[1], 1.0, 1e-13);
  const auto smooth = pair(mesh, z, true);
  const double r = std::sqrt(0.5);
  Point3 n1{-r, r + 1.0, 0};
  n1 = (1.0 / norm(n1)) * n1;
  Point3 expected = 0.5 * n1 + Point3{0, 0.5, 0};
  expected = (1.0 / norm(expected)) * expected;
  EXPECT_NEAR(smooth[0].normal[0], expected[0], 1e-12);
  EXPECT_NEAR(smooth[0].normal[1], expected[1], 1e-12);
}

} // namespace
} // namespace stella::contact
