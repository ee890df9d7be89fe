// ALGO_RESO_GEOM='NEWTON' with FROTTEMENT='COULOMB' checked by finite differences:
// (1) the Jacobian of the friction rows T_j (+t_j on the slave, -N_k(xi) t_j on the master nodes;
//     t_1 the unit tangent tau_1 / |tau_1|, t_2 = n x t_1) with respect to the positions of the slave
//     node and of the master cell's nodes (frictionRowJacobians) against the central differences of
//     the rows recomputed from a fresh orthogonal projection, on SEG2, curved SEG3, warped QUAD4,
//     TRIA3 and curved QUAD8 masters;
// (2) the tangent the constraint assembles (K_c = -d forces / du, the pairing redone inside
//     addForces, the multipliers and statuses fixed) against the central differences of its forces,
//     in 2D (curved SEG3 master, SEG2 slave cells) and 3D (warped QUAD4 master, TRIA3 slave cell):
//     sticking (ALGO_FROT='STANDARD', the first step: CONTACT_INIT='OUI' sticks) and sliding (a second
//     step after a first one accepted sliding; ALGO_FROT='STANDARD' in 2D, 'PENALISATION' in 3D: with
//     'STANDARD' in 3D the sliding multiplier is condensed (the tangent is that of the condensed
//     equations, not the forces' derivative at a fixed multiplier; ContinuousContactFriction.cpp), its
//     geometric terms are the same code). The slip is measured from a start u_start != u, so the
//     slip's own variation with the geometry (G_j = M_j^T (u - u_start)) is exercised.

#include "solver/contact/ContinuousContactConstraint.hpp"
#include "solver/contact/ContinuousGeometricTangent.hpp"
#include "solver/contact/tests/GeometricTangentAssembly.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

namespace stella::contact {
namespace {

using namespace geometric_test;

// The friction rows over (x_s, x_1..x_n) from a fresh projection (the reference), the pairing's
// tangents: 2D t_1 = (-n_y, n_x); 3D t_1 = tau_1 - (tau_1 . n) n normalised, t_2 = n x t_1.
std::array<Eigen::VectorXd, 2> frictionRows(const CellNodes& cell, const Point3& slave) {
  const int dim = parametric(cell.type);
  const std::array<double, 2> xi = projectPoint(cell, dim, slave);
  CellPoint p;
  evaluateCell(cell, xi, p);
  const Point3 n = cellNormal(p, dim);
  std::array<Point3, 2> t{Point3{-n[1], n[0], 0.0}, Point3{0, 0, 0}};
  if (dim == 2) {
    const Point3 d = p.d1 - dot(p.d1, n) * n;
    t[0] = (1.0 / norm(d)) * d;
    t[1] = cross(n, t[0]);
  }
  std::array<Eigen::VectorXd, 2> rows;
  for (std::size_t j = 0; j < 2; ++j) {
    rows[j] = Eigen::VectorXd::Zero(3 * (1 + cell.count));
    for (std::size_t c = 0; c < 3; ++c) {
      rows[j](static_cast<Eigen::Index>(c)) = t[j][c];
      for (int k = 0; k < cell.count; ++k) {
        rows[j](3 * (1 + k) + static_cast<Eigen::Index>(c)) =
            -p.shape.n[static_cast<std::size_t>(k)] * t[j][c];
      }
    }
  }
  return rows;
}

TEST(ContinuousGeometricFriction, FrictionRowJacobiansMatchFiniteDifferences) {
  constexpr double h = 1e-6;
  for (const KernelCase& k : kernelCases()) {
    SCOPED_TRACE(k.name);
    const int dim = parametric(k.cell.type);
    const std::array<double, 2> xi = projectPoint(k.cell, dim, k.slave);
    CellPoint p;
    evaluateCell(k.cell, xi, p);
    const Point3 n = cellNormal(p, dim);
    const auto at = frictionRows(k.cell, k.slave);
    const Point3 t1{at[0](0), at[0](1), at[0](2)};
    const auto m = frictionRowJacobians(k.cell, dim, xi, k.slave, n, t1);
    const auto size = static_cast<int>(at[0].size());
    for (std::size_t j = 0; j < (dim == 1 ? 1U : 2U); ++j) {
      Eigen::MatrixXd fd(size, size);
      for (int v = 0; v < size; ++v) {
        const auto moved = movedBothWays(k, v, h);
        fd.col(v) = (frictionRows(moved[0].cell, moved[0].slave)[j] -
                     frictionRows(moved[1].cell, moved[1].slave)[j]) /
                    (2.0 * h);
      }
      Eigen::MatrixXd mj = m[j];
      if (dim == 1) { // 2D: the z components (rows and columns) are not DOFs
        for (int v = 2; v < size; v += 3) {
          fd.row(v).setZero();
          fd.col(v).setZero();
          mj.row(v).setZero();
          mj.col(v).setZero();
        }
      }
      const double error = (mj - fd).cwiseAbs().maxCoeff() / fd.cwiseAbs().maxCoeff();
      std::cout << fmt::format("[ friction dT ] {} t{}: max |M - FD| / max |FD| = {:.2e} (max |FD| {:.2e})\n",
                               k.name, j + 1, error, fd.cwiseAbs().maxCoeff());
      EXPECT_LT(error, 1e-6);
    }
  }
}

enum class FrictionState { Stick, Slide };

struct FrictionCase {
  bool threeD;
  FrictionState state;
  bool penalisedFriction; // ALGO_FROT='PENALISATION' (else STANDARD)
};

std::string caseName(const FrictionCase& c) {
  return fmt::format("{} {} {}", c.threeD ? "3D QUAD4/TRIA3" : "2D SEG3/SEG2",
                     c.state == FrictionState::Stick ? "stick" : "slide",
                     c.penalisedFriction ? "PENALISATION" : "STANDARD");
}

class AssembledFrictionTangent : public ::testing::TestWithParam<FrictionCase> {};

TEST_P(AssembledFrictionTangent, MatchesFiniteDifferencesOfTheForces) {
  const FrictionCase fc = GetParam();
  SCOPED_TRACE(caseName(fc));
  Assembly a(fc.threeD, ContactAlgorithm::Standard, true);
  a.definition->settings.friction = true;
  a.definition->settings.geometricResidual = 1e30; // the test's first step is accepted where it stands
  ContactZone& zone = a.definition->zones[0];
  zone.coulomb = 0.3;
  zone.continuous.initialThreshold = 1.0; // LAGS_C = -1 on the nodes in contact: threshold 0.3
  zone.continuous.frictionPenalised = fc.penalisedFriction;
  zone.continuous.frictionPenalty = 1.0e3;
  zone.continuous.frictionAugmentation = 1.0e3;
  const int n = a.dofs->physicalCount();
  Eigen::VectorXd u0 = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd u1(n);
  Eigen::VectorXd u2(n);
  for (int i = 0; i < n; ++i) {
    u1(i) = 0.004 * std::sin(1.7 * i + 0.3);
    u2(i) = u1(i) + 0.003 * std::cos(2.3 * i + 0.1);
  }
  ContinuousContactConstraint c(a.definition, *a.dofs, a.modelling);
  c.initialize();
  c.beginStep(u0, 1.0);
  Eigen::VectorXd at = u1;
  if (fc.state == FrictionState::Slide) {
    // a first step accepted at u1: the slip rho_t |s| (about 4) exceeds mu |LAGS_C| = 0.3, the nodes
    // in contact slide; the second step starts there sliding, LAGS_F on the threshold
    Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
    bool accepted = false;
    for (int i = 0; i < 3 && !accepted; ++i) {
      c.addForces(u1, f, nullptr);
      accepted = c.acceptConvergence(u1);
    }
    ASSERT_TRUE(accepted);
    int sliding = 0;
    for (const LinkState& s : c.states()) {
      sliding += s.status == LinkStatus::Sliding ? 1 : 0;
    }
    ASSERT_GE(sliding, 2);
    c.beginStep(u1, 2.0);
    at = u2;
  }
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  std::vector<Eigen::Triplet<double>> t;
  c.addForces(at, f, &t);
  const Eigen::MatrixXd k = dense(t, n);
  EXPECT_FALSE(c.symmetric());
  const Eigen::MatrixXd fd = forceDifferences(c, at);
  const double scale = fd.cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 0.0);
  const double error = (k - fd).cwiseAbs().maxCoeff() / scale;
  const double asymmetry = (fd - fd.transpose()).cwiseAbs().maxCoeff() / scale;
  std::cout << fmt::format(
      "[ assembled friction ] {}: max |K - FD| / max |FD| = {:.2e} (FD's asymmetry {:.2e})\n", caseName(fc),
      error, asymmetry);
  EXPECT_LT(error, 1e-5);
  EXPECT_GT(asymmetry, 1e-4); // the friction makes it unsymmetric: the comparison sees both halves
}

INSTANTIATE_TEST_SUITE_P(StickAndSlip, AssembledFrictionTangent,
                         ::testing::Values(FrictionCase{false, FrictionState::Stick, false},
                                           FrictionCase{false, FrictionState::Slide, false},
                                           FrictionCase{false, FrictionState::Slide, true},
                                           FrictionCase{true, FrictionState::Stick, false},
                                           FrictionCase{true, FrictionState::Slide, true}),
                         [](const ::testing::TestParamInfo<FrictionCase>& p) {
                           const FrictionCase& c = p.param;
                           return fmt::format("{}_{}_{}", c.threeD ? "ThreeD" : "TwoD",
                                              c.state == FrictionState::Stick ? "Stick" : "Slide",
                                              c.penalisedFriction ? "Penalisation" : "Standard");
                         });

} // namespace
} // namespace stella::contact
