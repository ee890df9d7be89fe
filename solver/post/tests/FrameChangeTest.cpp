// Change of frame of vector and tensor components (solver/post/FrameChange) against closed
// forms: Mohr's rotation of a plane stress state, nautical angles that swap axes, VECT_X/VECT_Y
// giving the frame of the same angles, invariants of a 3D tensor, and the cylindrical frame.

#include "solver/post/FrameChange.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace stella {
namespace {

TEST(FrameChange, PlaneStressFollowsMohr) {
  const double xx = 120.0, yy = -40.0, zz = 25.0, xy = 35.0;
  for (const double alpha : {0.0, 30.0, 45.0, 100.0, -63.0}) {
    double v[4] = {xx, yy, zz, xy};
    rotateComponents(FrameQuantity::Tensor2D, nauticalRotation(alpha, 0.0, 0.0), false, v);
    const double a = 2.0 * alpha * std::numbers::pi / 180.0;
    const double mean = (xx + yy) / 2.0, half = (xx - yy) / 2.0;
    EXPECT_NEAR(v[0], mean + half * std::cos(a) + xy * std::sin(a), 1e-12) << alpha;
    EXPECT_NEAR(v[1], mean - half * std::cos(a) - xy * std::sin(a), 1e-12) << alpha;
    EXPECT_NEAR(v[2], zz, 1e-12) << alpha;
    EXPECT_NEAR(v[3], -half * std::sin(a) + xy * std::cos(a), 1e-12) << alpha;
  }
  // A vector turned with the frame: (1, 0) seen from axes at 30 degrees.
  double u[2] = {1.0, 0.0};
  rotateComponents(FrameQuantity::Vector2D, nauticalRotation(30.0, 0.0, 0.0), false, u);
  EXPECT_NEAR(u[0], std::sqrt(3.0) / 2.0, 1e-15);
  EXPECT_NEAR(u[1], -0.5, 1e-15);
}

TEST(FrameChange, NauticalAnglesSwapAxes) {
  // beta = 90: x' = -Z, y' = Y, z' = X.
  double v[3] = {1.0, 2.0, 3.0};
  rotateComponents(FrameQuantity::Vector3D, nauticalRotation(0.0, 90.0, 0.0), false, v);
  EXPECT_NEAR(v[0], -3.0, 1e-14);
  EXPECT_NEAR(v[1], 2.0, 1e-14);
  EXPECT_NEAR(v[2], 1.0, 1e-14);
  // alpha = 90 then gamma = 90: x' = Y, y' = Z, z' = X.
  double s[6] = {1.0, 2.0, 3.0, 4.0, 5.0, 6.0}; // XX YY ZZ XY XZ YZ
  rotateComponents(FrameQuantity::Tensor3D, nauticalRotation(90.0, 0.0, 90.0), false, s);
  const double expected[6] = {2.0, 3.0, 1.0, 6.0, 4.0, 5.0}; // YY ZZ XX YZ YX ZX
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(s[i], expected[i], 1e-13) << i;
  }
}

TEST(FrameChange, VectorsGiveTheFrameOfTheSameAngles) {
  const Rotation angles = nauticalRotation(30.0, -20.0, 75.0);
  // VECT_Y need not be orthogonal to VECT_X: only its part orthogonal to X counts.
  const Point3 x = angles[0];
  const Point3 y{angles[1][0] + 0.7 * x[0], angles[1][1] + 0.7 * x[1], angles[1][2] + 0.7 * x[2]};
  const auto r = rotationFromVectors({2.0 * x[0], 2.0 * x[1], 2.0 * x[2]}, y);
  ASSERT_TRUE(r.has_value());
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR((*r)[i][j], angles[i][j], 1e-14) << i << j;
    }
  }
  EXPECT_FALSE(rotationFromVectors({1, 0, 0}, {2, 0, 0}).has_value());
  EXPECT_FALSE(rotationFromVectors({0, 0, 0}, {0, 1, 0}).has_value());
}

TEST(FrameChange, TensorInvariantsAreKept) {
  const double s0[6] = {10.0, -3.0, 7.0, 2.5, -4.0, 1.5};
  double s[6];
  std::copy(s0, s0 + 6, s);
  rotateComponents(FrameQuantity::Tensor3D, nauticalRotation(17.0, 41.0, -122.0), false, s);
  const auto trace = [](const double* t) { return t[0] + t[1] + t[2]; };
  const auto squares = [](const double* t) {
    return t[0] * t[0] + t[1] * t[1] + t[2] * t[2] + 2.0 * (t[3] * t[3] + t[4] * t[4] + t[5] * t[5]);
  };
  EXPECT_NEAR(trace(s), trace(s0), 1e-12);
  EXPECT_NEAR(squares(s), squares(s0), 1e-11);
  EXPECT_GT(std::abs(s[0] - s0[0]), 1.0); // the components did change
}

TEST(FrameChange, CylindricalFrame) {
  // At (0, 2, 5) around the Z axis: e_r = Y, e_z = Z, e_theta = Z x Y = -X.
  const auto r = cylindricalRotation({0, 0, 0}, {0, 0, 1}, {0.0, 2.0, 5.0});
  ASSERT_TRUE(r.has_value());
  double v[3] = {1.0, 2.0, 3.0};
  rotateComponents(FrameQuantity::Vector3D, *r, true, v);
  EXPECT_NEAR(v[0], 2.0, 1e-15);  // v_r
  EXPECT_NEAR(v[1], 3.0, 1e-15);  // v_z
  EXPECT_NEAR(v[2], -1.0, 1e-15); // v_theta
  // Plane: a radial-hoop stress state at angle 60 degrees from ORIGINE (1, 1).
  const double t = std::numbers::pi / 3.0, rr = -100.0, tt = 166.0, zz = 20.0;
  const double c = std::cos(t), s = std::sin(t);
  double sig[4] = {rr * c * c + tt * s * s, rr * s * s + tt * c * c, zz, (rr - tt) * s * c};
  const auto p = cylindricalRotation({1, 1, 0}, {0, 0, 1}, {1.0 + 3.0 * c, 1.0 + 3.0 * s, 0.0});
  ASSERT_TRUE(p.has_value());
  rotateComponents(FrameQuantity::Tensor2D, *p, true, sig);
  EXPECT_NEAR(sig[0], rr, 1e-12);   // SIXX = sigma_rr
  EXPECT_NEAR(sig[1], zz, 1e-12);   // SIYY = sigma_zz (code_aster's (r, z, theta) frame)
  EXPECT_NEAR(sig[2], tt, 1e-12);   // SIZZ = sigma_tt
  EXPECT_NEAR(sig[3], 0.0, 1e-12);  // SIXY = sigma_rt
  double u[2] = {3.0 * c, 3.0 * s}; // radial
  rotateComponents(FrameQuantity::Vector2D, *p, true, u);
  EXPECT_NEAR(u[0], 3.0, 1e-14);
  EXPECT_NEAR(u[1], 0.0, 1e-14);
  EXPECT_FALSE(cylindricalRotation({0, 0, 0}, {0, 0, 1}, {0.0, 0.0, 4.0}).has_value()); // on the axis
}

} // namespace
} // namespace stella
