// Gauss -> node extrapolation matrices: constants and linear functions of the reference
// coordinates are reproduced exactly at every node of every volume cell type and rule, and the
// QUAD4 / FPG4 matrix has the closed-form entries 1 + sqrt(3)/2, -1/2, 1 - sqrt(3)/2.

#include "solver/fem/GaussExtrapolation.hpp"
#include "solver/fem/ReferenceElement.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace stella::fem {
namespace {

struct Case {
  CellType type;
  IntegrationRole role;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  for (CellType t : {CellType::TRIA3, CellType::TRIA6, CellType::QUAD4, CellType::QUAD8, CellType::QUAD9}) {
    out.push_back({t, IntegrationRole::Volume});
    out.push_back({t, IntegrationRole::AxisymmetricVolume});
  }
  for (CellType t :
       {CellType::TETRA4, CellType::TETRA10, CellType::PENTA6, CellType::PENTA15, CellType::PYRAM5,
        CellType::PYRAM13, CellType::HEXA8, CellType::HEXA20, CellType::HEXA27}) {
    out.push_back({t, IntegrationRole::Volume});
  }
  return out;
}

TEST(GaussExtrapolation, ReproducesConstantsAndLinearFunctionsExactly) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(std::string(info(c.type).name));
    const Eigen::MatrixXd& g = gaussToNodeMatrix(c.type, c.role);
    const QuadratureRule& rule = rigiRule(c.type, c.role);
    const ReferenceElement& e = referenceElement(c.type);
    ASSERT_EQ(g.rows(), e.nodeCount());
    ASSERT_EQ(g.cols(), rule.size());
    // f(xi) = 2 + 3 xi - 5 eta + 7 zeta, sampled at the Gauss points.
    auto f = [](const Eigen::Vector3d& x) { return 2.0 + 3.0 * x(0) - 5.0 * x(1) + 7.0 * x(2); };
    Eigen::VectorXd atPoints(rule.size());
    for (int q = 0; q < rule.size(); ++q) {
      atPoints(q) = f(rule.points[static_cast<std::size_t>(q)]);
    }
    const Eigen::VectorXd atNodes = g * atPoints;
    for (int k = 0; k < e.nodeCount(); ++k) {
      EXPECT_NEAR(g.row(k).sum(), 1.0, 1e-12) << "node " << k; // constants
      if (rule.size() > 1) {
        EXPECT_NEAR(atNodes(k), f(e.node(k)), 1e-11) << "node " << k; // linear functions
      }
    }
  }
}

TEST(GaussExtrapolation, Quad4FourPointMatrixHasTheClosedFormEntries) {
  const Eigen::MatrixXd& g = gaussToNodeMatrix(CellType::QUAD4, IntegrationRole::Volume);
  ASSERT_EQ(g.rows(), 4);
  ASSERT_EQ(g.cols(), 4);
  const double big = 1.0 + std::sqrt(3.0) / 2.0;
  const double small = 1.0 - std::sqrt(3.0) / 2.0;
  for (int k = 0; k < 4; ++k) {
    std::vector<double> entries;
    for (int q = 0; q < 4; ++q) {
      entries.push_back(g(k, q));
    }
    std::sort(entries.begin(), entries.end());
    EXPECT_NEAR(entries[0], -0.5, 1e-12);
    EXPECT_NEAR(entries[1], -0.5, 1e-12);
    EXPECT_NEAR(entries[2], small, 1e-12);
    EXPECT_NEAR(entries[3], big, 1e-12);
  }
}

TEST(GaussExtrapolation, OnePointRuleCopiesTheValueToEveryNode) {
  const Eigen::MatrixXd& g = gaussToNodeMatrix(CellType::TRIA3, IntegrationRole::Volume);
  ASSERT_EQ(g.cols(), 1);
  EXPECT_TRUE(g.isApproxToConstant(1.0));
}

} // namespace
} // namespace stella::fem
