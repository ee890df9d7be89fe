// Equivalent stresses (SIEQ) of tensors with closed-form invariants.

#include "solver/post/TensorInvariants.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

namespace stella {
namespace {

std::array<double, 17> sieq(std::vector<double> components) {
  std::array<double, 17> out{};
  equivalentStress(tensorFromComponents(components), out);
  return out;
}

TEST(TensorInvariants, UniaxialStress) {
  const auto e = sieq({100.0, 0.0, 0.0, 0.0});
  EXPECT_NEAR(e[0], 100.0, 1e-12);      // VMIS
  EXPECT_NEAR(e[1], 100.0, 1e-12);      // TRESCA
  EXPECT_NEAR(e[2], 0.0, 1e-12);        // PRIN_1
  EXPECT_NEAR(e[4], 100.0, 1e-12);      // PRIN_3
  EXPECT_NEAR(e[5], 100.0, 1e-12);      // VMIS_SG
  EXPECT_NEAR(e[12], 1.0, 1e-12);       // VECT_3_X: direction of PRIN_3 is x
  EXPECT_NEAR(e[15], 100.0, 1e-12);     // TRSIG
  EXPECT_NEAR(e[16], 1.0 / 3.0, 1e-12); // TRIAX
}

// sigma = [[50, 30, 0], [30, -20, 0], [0, 0, 10]]: VMIS = sqrt(3700 + 2700) = 80, principal
// stresses 15 -+ sqrt(2125) and 10, determinant 10 (50 (-20) - 30^2) = -19000.
TEST(TensorInvariants, GeneralPlaneTensor) {
  const double r = std::sqrt(2125.0);
  const auto e = sieq({50.0, -20.0, 10.0, 30.0, 0.0, 0.0});
  EXPECT_NEAR(e[0], 80.0, 1e-12);
  EXPECT_NEAR(e[1], 2.0 * r, 1e-12);
  EXPECT_NEAR(e[2], 15.0 - r, 1e-12);
  EXPECT_NEAR(e[3], 10.0, 1e-12);
  EXPECT_NEAR(e[4], 15.0 + r, 1e-12);
  EXPECT_NEAR(e[5], 80.0, 1e-12);
  EXPECT_NEAR(e[15], 40.0, 1e-12);
  EXPECT_NEAR(e[16], 40.0 / 3.0 / 80.0, 1e-14);
  const Eigen::Matrix3d t = tensorFromComponents(std::vector<double>{50.0, -20.0, 10.0, 30.0, 0.0, 0.0});
  EXPECT_NEAR(t.determinant(), -19000.0, 1e-9);
  // The principal directions are unit, orthogonal and diagonalise the tensor.
  const PrincipalValues p = principalValues(t);
  EXPECT_TRUE(
      (p.vectors.transpose() * t * p.vectors).isApprox(Eigen::Matrix3d(p.values.asDiagonal()), 1e-12));
}

TEST(TensorInvariants, PureShearAndCompression) {
  const double tau = 7.0;
  const auto s = sieq({0.0, 0.0, 0.0, 0.0, 0.0, tau}); // sigma_yz
  EXPECT_NEAR(s[0], std::sqrt(3.0) * tau, 1e-12);
  EXPECT_NEAR(s[1], 2.0 * tau, 1e-12);
  const auto c = sieq({-30.0, -30.0, -30.0, 0.0}); // hydrostatic: no von Mises, triaxiality 0
  EXPECT_NEAR(c[0], 0.0, 1e-12);
  EXPECT_EQ(c[16], 0.0);
  const auto u = sieq({-100.0, 0.0, 0.0, 0.0});
  EXPECT_NEAR(u[5], -100.0, 1e-12); // VMIS_SG takes the sign of the trace
}

} // namespace
} // namespace stella
