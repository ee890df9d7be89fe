// ALGO_RESO_GEOM='NEWTON' of the continuous formulation checked by finite differences:
// (1) the second derivative of the node-to-surface gap (ContinuousGeometricTangent.hpp) against the
//     central differences of its first derivative (the pairing's row, recomputed from a fresh
//     orthogonal projection at each perturbed configuration), and that row against the differences
//     of the gap itself; on SEG2 and curved SEG3 masters (2D), warped QUAD4 and TRIA3 (3D);
// (2) the tangent the constraint assembles (K_c = -d forces / du, the pairing redone inside addForces)
//     against the central differences of its forces, on a curved SEG3 master with SEG2 slave cells and
//     on a warped QUAD4 master with a TRIA3 slave cell, PENALISATION and STANDARD (CONTACT_INIT='OUI');
//     the same comparison without the geometric term fails by orders of magnitude (the test can fail).

#include "solver/contact/ContinuousGeometricTangent.hpp"
#include "solver/assembly/DofMap.hpp"
#include "solver/contact/ContinuousContactConstraint.hpp"
#include "solver/contact/tests/ContactTestMeshes.hpp"
#include "solver/contact/tests/GeometricTangentAssembly.hpp"
#include "solver/mesh/MeshGeometry.hpp"
#include "solver/model/Model.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

namespace stella::contact {
namespace {

using namespace geometric_test;

// The gap and its gradient over (x_s, x_1..x_n) from a fresh projection (the reference).
struct GapAndRow {
  double gap = 0.0;
  Eigen::VectorXd row;
  std::array<double, 2> xi{0, 0};
};

GapAndRow gapAndRow(const CellNodes& cell, const Point3& slave) {
  const int dim = parametric(cell.type);
  GapAndRow out;
  out.xi = projectPoint(cell, dim, slave);
  CellPoint p;
  evaluateCell(cell, out.xi, p);
  const Point3 n = cellNormal(p, dim);
  out.gap = dot(slave - p.x, n);
  out.row = Eigen::VectorXd::Zero(3 * (1 + cell.count));
  for (std::size_t c = 0; c < 3; ++c) {
    out.row(static_cast<Eigen::Index>(c)) = n[c];
    for (int j = 0; j < cell.count; ++j) {
      out.row(3 * (1 + j) + static_cast<Eigen::Index>(c)) = -p.shape.n[static_cast<std::size_t>(j)] * n[c];
    }
  }
  return out;
}

TEST(ContinuousGeometricTangent, GapDerivativesMatchFiniteDifferences) {
  constexpr double h = 1e-6;
  for (const KernelCase& k : kernelCases()) {
    SCOPED_TRACE(k.name);
    const GapAndRow at = gapAndRow(k.cell, k.slave);
    const int dim = parametric(k.cell.type);
    // the projection falls inside the cell (the formula is the interior one)
    ASSERT_LE(std::abs(at.xi[0]), 1.0);
    const Eigen::MatrixXd hessian =
        gapHessian(k.cell, dim, at.xi, k.slave, Point3{at.row(0), at.row(1), at.row(2)});
    const auto size = static_cast<int>(at.row.size());
    ASSERT_EQ(hessian.rows(), size);
    Eigen::MatrixXd fd(size, size);
    double rowError = 0.0;
    for (int v = 0; v < size; ++v) {
      if (dim == 1 && v % 3 == 2) { // 2D: no z
        fd.col(v).setZero();
        continue;
      }
      const auto moved = movedBothWays(k, v, h);
      const GapAndRow plus = gapAndRow(moved[0].cell, moved[0].slave);
      const GapAndRow minus = gapAndRow(moved[1].cell, moved[1].slave);
      fd.col(v) = (plus.row - minus.row) / (2.0 * h);
      rowError = std::max(rowError, std::abs((plus.gap - minus.gap) / (2.0 * h) - at.row(v)));
    }
    if (dim == 1) { // the z rows of the 2D reference are zero too
      for (int v = 2; v < size; v += 3) {
        fd.row(v).setZero();
      }
    }
    EXPECT_LT(rowError, 1e-8);
    const double error = (hessian - fd).cwiseAbs().maxCoeff() / fd.cwiseAbs().maxCoeff();
    std::cout << fmt::format("[ gap d2g ] {}: max |d2g - FD| / max |FD| = {:.2e} (max |FD| {:.2e})\n", k.name,
                             error, fd.cwiseAbs().maxCoeff());
    EXPECT_LT(error, 1e-6);
    EXPECT_LT((hessian - hessian.transpose()).cwiseAbs().maxCoeff(), 1e-12 * hessian.cwiseAbs().maxCoeff());
  }
}

class AssembledGeometricTangent : public ::testing::TestWithParam<std::tuple<bool, ContactAlgorithm>> {};

TEST_P(AssembledGeometricTangent, MatchesFiniteDifferencesOfTheForces) {
  const auto [threeD, algorithm] = GetParam();
  Assembly newton(threeD, algorithm, true);
  Assembly fixed(threeD, algorithm, false);
  const int n = newton.dofs->physicalCount();
  // a general configuration: every node moved a little
  Eigen::VectorXd u(n);
  for (int i = 0; i < n; ++i) {
    u(i) = 0.01 * std::sin(1.7 * i + 0.3);
  }
  auto tangentOf = [&](Assembly& a) {
    ContinuousContactConstraint c(a.definition, *a.dofs, a.modelling);
    c.initialize();
    c.beginStep(u, 1.0);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
    std::vector<Eigen::Triplet<double>> t;
    c.addForces(u, f, &t);
    return dense(t, n);
  };
  const Eigen::MatrixXd k = tangentOf(newton);
  const Eigen::MatrixXd kFixed = tangentOf(fixed);
  ContinuousContactConstraint c(newton.definition, *newton.dofs, newton.modelling);
  c.initialize();
  c.beginStep(u, 1.0);
  const Eigen::MatrixXd fd = forceDifferences(c, u);
  const double scale = fd.cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 0.0);
  const double error = (k - fd).cwiseAbs().maxCoeff() / scale;
  const double errorWithout = (kFixed - fd).cwiseAbs().maxCoeff() / scale;
  std::cout << fmt::format(
      "[ assembled ] {} {}: max |K - FD| / max |FD| = {:.2e} (without the geometric term "
      "{:.2e})\n",
      threeD ? "3D QUAD4/TRIA3" : "2D SEG3/SEG2",
      algorithm == ContactAlgorithm::ContinuePenalty ? "PENALISATION" : "STANDARD", error, errorWithout);
  EXPECT_LT(error, 1e-5);
  EXPECT_GT(errorWithout, 1e-3);
  EXPECT_LT((k - k.transpose()).cwiseAbs().maxCoeff(), 1e-12 * scale); // frictionless: symmetric
}

INSTANTIATE_TEST_SUITE_P(MastersAndAlgorithms, AssembledGeometricTangent,
                         ::testing::Combine(::testing::Bool(),
                                            ::testing::Values(ContactAlgorithm::ContinuePenalty,
                                                              ContactAlgorithm::Standard)));

} // namespace
} // namespace stella::contact
