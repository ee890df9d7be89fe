// Pairing through the R-tree equals brute force (every master cell tried, the same projection
// kernel and tie rule) node by node: same paired status, same master cell, same gap to 1e-12
// relative; on random, structured (with exact ties), curved (SEG3, QUAD8, QUAD9, TRIA6) and
// nearly parallel surfaces. Also: the warm-started re-pairing equals pairing from scratch, two
// threads equal one, and the case the pre-R-tree search got wrong (the nearest projection on a
// cell none of the 16 nearest master nodes belongs to).

#include "solver/contact/ContactPairing.hpp"
#include "solver/contact/tests/PairingSurfaces.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace stella::contact {
namespace {

using testing::curve;
using testing::randomNodes;
using testing::surfaceGrid;
using testing::zoneOf;

std::vector<ContactLink> pairWith(const Mesh& mesh, const ContactZone& z, bool exhaustive, int threads = 1,
                                  const std::vector<double>* u = nullptr) {
  PairingOptions o;
  o.dimension = mesh.dimension();
  o.exhaustive = exhaustive;
  o.threads = threads;
  return pairZone(mesh, meshPositions(mesh, u), 0, z, o);
}

// Node by node: status, master cell, gap (1e-12 relative, floor 1e-12 of the length scale).
int expectSame(const std::vector<ContactLink>& a, const std::vector<ContactLink>& b, double scale) {
  EXPECT_EQ(a.size(), b.size());
  int paired = 0;
  int shown = 0;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k) {
    const bool same = a[k].slave == b[k].slave && a[k].paired == b[k].paired &&
                      a[k].masterCell == b[k].masterCell &&
                      std::abs(a[k].gap - b[k].gap) <= 1e-12 * std::max(std::abs(b[k].gap), scale);
    if (!same && shown++ < 5) {
      ADD_FAILURE() << "slave node " << a[k].slave << ": paired " << a[k].paired << "/" << b[k].paired
                    << ", master cell " << a[k].masterCell << "/" << b[k].masterCell << ", gap " << a[k].gap
                    << "/" << b[k].gap;
    }
    paired += a[k].paired ? 1 : 0;
  }
  EXPECT_EQ(shown, 0) << "links differing";
  return paired;
}

int agreement(const Mesh& mesh, double scale) {
  const ContactZone z = zoneOf("MASTER", "SLAVE");
  return expectSame(pairWith(mesh, z, false), pairWith(mesh, z, true), scale);
}

Point3 wavy(double u, double v) {
  return {u, v, 0.05 * std::sin(6.0 * u) * std::cos(5.0 * v)};
}

TEST(PairingAgreement, RandomNodesOverJitteredTriangles) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  Mesh mesh;
  mesh.setDimension(3);
  const int k = 12;
  mesh.setCellGroup("MASTER", surfaceGrid(mesh, CellType::TRIA3, k, k, [&](double u, double v) {
                      Point3 p = wavy(u, v);
                      if (u > 0.0 && u < 1.0 && v > 0.0 && v < 1.0) {
                        p[0] += jitter(rng) / k;
                        p[1] += jitter(rng) / k;
                      }
                      return p;
                    }));
  mesh.setCellGroup("SLAVE", randomNodes(mesh, 300, {-0.2, -0.2, -0.3}, {1.2, 1.2, 0.3}, rng));
  const int paired = agreement(mesh, 1.0);
  // About half of the 900 nodes lie over the master ([0, 1]^2 of the box's [-0.2, 1.2]^2), the
  // others beyond its edges by more than TOLE_PROJ_EXT, or nearer to one of them.
  EXPECT_GT(paired, 400);
  EXPECT_LT(paired, 800);
}

TEST(PairingAgreement, StructuredGridsWithTiesFollowTheTieRule) {
  // Slave nodes exactly above master nodes (4 cells tie) and edge midpoints (2 cells tie).
  Mesh mesh;
  mesh.setDimension(3);
  mesh.setCellGroup("MASTER", surfaceGrid(mesh, CellType::QUAD4, 8, 8, [](double u, double v) {
                      return Point3{u, v, 0.0};
                    }));
  mesh.setCellGroup("SLAVE", surfaceGrid(mesh, CellType::QUAD4, 16, 16, [](double u, double v) {
                      return Point3{u, v, 0.05};
                    }));
  EXPECT_EQ(agreement(mesh, 1.0), 17 * 17);
  // The tie rule: of the cells holding the projection, the first of the master group.
  const auto links = pairWith(mesh, zoneOf("MASTER", "SLAVE"), false);
  const auto& master = *mesh.cellGroup("MASTER");
  for (const auto& l : links) {
    const Point3 x = mesh.point(l.slave);
    // Lowest (row, column) of the cells touching x: on a grid line, the cell before it.
    auto lowest = [](double c) {
      const double s = c * 8;
      const int i = static_cast<int>(std::floor(s + 1e-9));
      return std::abs(s - std::round(s)) < 1e-9 && i > 0 ? i - 1 : std::min(i, 7);
    };
    const int ii = lowest(x[0]);
    const int jj = lowest(x[1]);
    EXPECT_EQ(l.masterCell, master[static_cast<std::size_t>(jj * 8 + ii)]) << x[0] << " " << x[1];
    EXPECT_NEAR(l.gap, 0.05, 1e-14);
  }
}

void curvedCase(CellType type) {
  // Master: a quarter of the cylinder of radius 1 (axis y); slave: jittered grid and random
  // nodes around radius 1.05, inside and outside the master's extent.
  std::mt19937 rng(5);
  auto cylinder = [](double r) {
    return [r](double u, double v) {
      const double a = 1.5 * u;
      return Point3{r * std::cos(a), 2.0 * v, r * std::sin(a)};
    };
  };
  Mesh mesh;
  mesh.setDimension(3);
  mesh.setCellGroup("MASTER", surfaceGrid(mesh, type, 6, 5, cylinder(1.0)));
  auto slave = surfaceGrid(mesh, CellType::QUAD4, 13, 11, cylinder(1.05));
  const auto cloud = randomNodes(mesh, 100, {-0.2, -0.2, -0.2}, {1.3, 2.2, 1.3}, rng);
  slave.insert(slave.end(), cloud.begin(), cloud.end());
  mesh.setCellGroup("SLAVE", slave);
  EXPECT_GT(agreement(mesh, 1.0), 14 * 12);
}

TEST(PairingAgreement, CurvedQuad8) {
  curvedCase(CellType::QUAD8);
}

TEST(PairingAgreement, CurvedQuad9) {
  curvedCase(CellType::QUAD9);
}

TEST(PairingAgreement, CurvedTria6) {
  curvedCase(CellType::TRIA6);
}

TEST(PairingAgreement, CurvedSeg3InTwoDimensions) {
  std::mt19937 rng(3);
  auto arc = [](double r) {
    return [r](double u, double) { return Point3{r * std::cos(2.0 * u), r * std::sin(2.0 * u), 0.0}; };
  };
  Mesh mesh;
  mesh.setDimension(2);
  mesh.setCellGroup("MASTER", curve(mesh, CellType::SEG3, 10, arc(1.0)));
  auto slave = curve(mesh, CellType::SEG2, 37, arc(1.02));
  const auto cloud = randomNodes(mesh, 200, {-1.5, -1.5, 0.0}, {1.5, 1.5, 0.0}, rng, true);
  slave.insert(slave.end(), cloud.begin(), cloud.end());
  mesh.setCellGroup("SLAVE", slave);
  EXPECT_GT(agreement(mesh, 1.0), 38);
}

TEST(PairingAgreement, NearlyParallelNearlyTouchingPlanes) {
  // The slave plane 1e-9 above the master, tilted by 1e-7, on a grid 3 x finer: every slave node
  // within round-off of ties between cells.
  Mesh mesh;
  mesh.setDimension(3);
  mesh.setCellGroup("MASTER", surfaceGrid(mesh, CellType::QUAD4, 10, 10, [](double u, double v) {
                      return Point3{u, v, 0.0};
                    }));
  mesh.setCellGroup("SLAVE", surfaceGrid(mesh, CellType::QUAD4, 30, 30, [](double u, double v) {
                      return Point3{u, v, 1e-9 + 1e-7 * u};
                    }));
  EXPECT_EQ(agreement(mesh, 1.0), 31 * 31);
}

TEST(PairingAgreement, NearestProjectionOnACellFarFromTheNearestNodes) {
  // One large master cell 0.5 below the slave nodes, and a finely meshed patch of the same
  // master surface 2.5 above them: the 16 nearest master nodes are all on the patch, the nearest
  // projection is on the large cell. The pairing before the R-tree (cells around the 4, then 16
  // nearest master nodes) paired these nodes with the patch at distance 2.5.
  Mesh mesh;
  mesh.setDimension(3);
  auto master = surfaceGrid(mesh, CellType::QUAD4, 1, 1, [](double u, double v) {
    return Point3{-10.0 + 20.0 * u, -10.0 + 20.0 * v, 0.0};
  });
  const CellId large = master.front();
  const auto patch = surfaceGrid(mesh, CellType::QUAD4, 6, 6, [](double u, double v) {
    return Point3{-0.5 + u, 0.5 - v, 3.0}; // facing down, towards the slave
  });
  master.insert(master.end(), patch.begin(), patch.end());
  mesh.setCellGroup("MASTER", master);
  mesh.setCellGroup("SLAVE", surfaceGrid(mesh, CellType::QUAD4, 3, 3, [](double u, double v) {
                      return Point3{-0.3 + 0.6 * u, -0.3 + 0.6 * v, 0.5};
                    }));
  EXPECT_EQ(agreement(mesh, 1.0), 16);
  for (const auto& l : pairWith(mesh, zoneOf("MASTER", "SLAVE"), false)) {
    EXPECT_EQ(l.masterCell, large);
    EXPECT_NEAR(l.gap, 0.5, 1e-14);
  }
}

TEST(PairingAgreement, WarmRepairingEqualsPairingFromScratch) {
  Mesh mesh;
  mesh.setDimension(3);
  mesh.setCellGroup("MASTER", surfaceGrid(mesh, CellType::QUAD4, 16, 16, wavy));
  mesh.setCellGroup("SLAVE", surfaceGrid(mesh, CellType::QUAD4, 20, 20, [](double u, double v) {
                      return Point3{0.05 + 0.9 * u, 0.05 + 0.9 * v, 0.08};
                    }));
  const ContactZone z = zoneOf("MASTER", "SLAVE");
  PairingOptions o;
  ZonePairing pairing(mesh, 0, z, o);
  pairing.pair(meshPositions(mesh, nullptr));
  // A small displacement (the geometric loop), then a slip of 2.5 master cells.
  for (double slip : {0.001, 2.5 / 16}) {
    std::vector<double> u(static_cast<std::size_t>(mesh.nodeCount()) * 3, 0.0);
    for (NodeId n = 0; n < mesh.nodeCount(); ++n) {
      const Point3 x = mesh.point(n);
      const bool slave = x[2] > 0.07;
      u[static_cast<std::size_t>(n) * 3] = slave ? slip : 0.0;
      u[static_cast<std::size_t>(n) * 3 + 2] = slave ? -0.01 : 0.002 * x[0];
    }
    const auto& warm = pairing.pair(meshPositions(mesh, &u));
    expectSame(warm, pairWith(mesh, z, true, 1, &u), 1.0);
    if (slip < 0.01) {
      EXPECT_LT(pairing.searchedNodes(), 21 * 21 / 2); // most nodes stayed with their cells
    }
  }
}

TEST(PairingAgreement, TwoThreadsEqualOne) {
  Mesh mesh;
  mesh.setDimension(3);
  mesh.setCellGroup("MASTER", surfaceGrid(mesh, CellType::QUAD4, 24, 24, wavy));
  mesh.setCellGroup("SLAVE", surfaceGrid(mesh, CellType::QUAD4, 99, 99, [](double u, double v) {
                      return Point3{u, v, 0.06};
                    }));
  const ContactZone z = zoneOf("MASTER", "SLAVE");
  const auto one = pairWith(mesh, z, false, 1);
  const auto two = pairWith(mesh, z, false, 2);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t k = 0; k < one.size(); ++k) {
    ASSERT_EQ(one[k].masterCell, two[k].masterCell);
    ASSERT_EQ(one[k].xi, two[k].xi);
    ASSERT_EQ(one[k].gap, two[k].gap); // bitwise: the same kernel on the same data
  }
}

} // namespace
} // namespace stella::contact
