// The pairing's closed-form shape functions against fem::ReferenceElement, the Lebesgue bounds
// of the cell boxes against sampling, and the R-tree box query against a linear scan.

#include "solver/contact/MasterCellIndex.hpp"
#include "solver/contact/SurfaceShape.hpp"
#include "solver/fem/ReferenceElement.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace stella::contact {
namespace {

const CellType surfaceTypes[] = {CellType::SEG2,  CellType::SEG3,  CellType::TRIA3, CellType::TRIA6,
                                 CellType::QUAD4, CellType::QUAD8, CellType::QUAD9};

TEST(SurfaceShape, EqualsTheReferenceElements) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  for (CellType t : surfaceTypes) {
    const auto& ref = fem::referenceElement(t);
    for (int k = 0; k < 50; ++k) {
      const double xi = u(rng);
      const double eta = ref.dimension() == 1 ? 0.0 : u(rng);
      SurfaceShapeValues s;
      surfaceShape(t, xi, eta, s);
      const Eigen::Vector3d p(xi, eta, 0.0);
      const Eigen::VectorXd n = ref.values(p);
      const Eigen::MatrixXd d = ref.gradients(p);
      ASSERT_EQ(s.count, ref.nodeCount()) << name(t);
      for (int i = 0; i < s.count; ++i) {
        const auto si = static_cast<std::size_t>(i);
        EXPECT_NEAR(s.n[si], n(i), 1e-13) << name(t) << " N" << i;
        EXPECT_NEAR(s.dxi[si], d(i, 0), 1e-13) << name(t) << " dN" << i << "/dxi";
        EXPECT_NEAR(s.deta[si], ref.dimension() > 1 ? d(i, 1) : 0.0, 1e-13)
            << name(t) << " dN" << i << "/deta";
      }
    }
  }
}

TEST(SurfaceShape, LebesgueBoundHoldsOnTheReferenceCell) {
  for (CellType t : surfaceTypes) {
    const bool triangle = t == CellType::TRIA3 || t == CellType::TRIA6;
    const bool segment = t == CellType::SEG2 || t == CellType::SEG3;
    double worst = 0.0;
    const int m = 200;
    for (int i = 0; i <= m; ++i) {
      for (int j = 0; j <= (segment ? 0 : m); ++j) {
        const double a = triangle ? static_cast<double>(i) / m : -1.0 + 2.0 * i / m;
        const double b = triangle ? static_cast<double>(j) / m : -1.0 + 2.0 * j / m;
        if (triangle && a + b > 1.0) {
          continue;
        }
        SurfaceShapeValues s;
        surfaceShape(t, a, b, s);
        double sum = 0.0;
        for (int k = 0; k < s.count; ++k) {
          sum += std::abs(s.n[static_cast<std::size_t>(k)]);
        }
        worst = std::max(worst, sum);
      }
    }
    EXPECT_LE(worst, lebesgueBound(t) + 1e-12) << name(t);
    EXPECT_GE(worst, lebesgueBound(t) - 1e-3) << name(t) << ": the bound is the maximum";
  }
}

TEST(MasterCellIndex, BoxQueryEqualsLinearScan) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Box3> boxes(3000);
  for (auto& b : boxes) {
    for (std::size_t a = 0; a < 3; ++a) {
      b.lo[a] = u(rng);
      b.hi[a] = b.lo[a] + 0.03 * u(rng);
    }
  }
  MasterCellIndex index;
  index.build(boxes);
  ASSERT_EQ(index.size(), boxes.size());
  std::vector<int> found;
  for (int q = 0; q < 200; ++q) {
    Box3 query;
    for (std::size_t a = 0; a < 3; ++a) {
      query.lo[a] = u(rng);
      query.hi[a] = query.lo[a] + 0.1 * u(rng);
    }
    index.query(query, found);
    std::sort(found.begin(), found.end());
    std::vector<int> expected;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      bool meets = true;
      for (std::size_t a = 0; a < 3; ++a) {
        meets = meets && boxes[i].lo[a] <= query.hi[a] && query.lo[a] <= boxes[i].hi[a];
      }
      if (meets) {
        expected.push_back(static_cast<int>(i));
      }
    }
    EXPECT_EQ(found, expected);
  }
}

TEST(MasterCellIndex, CurvedCellInsideItsBox) {
  // A SEG3 whose middle node is off the chord: the curve bulges beyond the nodes' box.
  const Point3 pts[3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}; // x(0.5) = 1.125 > 1
  const Box3 b = cellBox(CellType::SEG3, pts, 3, 0.0);
  for (int k = 0; k <= 100; ++k) {
    const double xi = -1.0 + 0.02 * k;
    SurfaceShapeValues s;
    surfaceShape(CellType::SEG3, xi, 0.0, s);
    for (std::size_t a = 0; a < 3; ++a) {
      const double x = s.n[0] * pts[0][a] + s.n[1] * pts[1][a] + s.n[2] * pts[2][a];
      EXPECT_GE(x, b.lo[a] - 1e-15);
      EXPECT_LE(x, b.hi[a] + 1e-15);
    }
  }
}

} // namespace
} // namespace stella::contact
