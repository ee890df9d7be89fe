// The Coulomb law shared by the nodal and the point continuous friction (ContinuousCoulombLaw.hpp).

#include "solver/contact/ContinuousCoulombLaw.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace stella::contact {
namespace {

CoulombPoint point(double base, double limit, bool senseInStatus = false) {
  CoulombPoint p;
  p.base = {base, 0.0};
  p.rho = 100.0;
  p.limit = limit;
  p.directions = 1;
  p.senseInStatus = senseInStatus;
  return p;
}

TEST(ContinuousCoulombLaw, StickInsideTheDiscSlideOnItsBoundary) {
  const Eigen::Vector2d slip{0.01, 0.0}; // q = 2 + 100 x 0.01 = 3
  EXPECT_EQ(coulombStatus(point(2.0, 5.0), slip), 1);
  EXPECT_DOUBLE_EQ(coulombPressure(point(2.0, 5.0), 1, slip)(0), 3.0);
  EXPECT_EQ(coulombStatus(point(2.0, 2.5), slip), 2);
  EXPECT_DOUBLE_EQ(coulombPressure(point(2.0, 2.5), 2, slip)(0), 2.5); // mu t along q
  EXPECT_DOUBLE_EQ(coulombPressure(point(2.0, 2.5), 0, slip)(0), 0.0);
}

TEST(ContinuousCoulombLaw, TheSlidingSenseIsTheStatusWhenFrozen) {
  const Eigen::Vector2d back{-0.05, 0.0}; // q = -3
  EXPECT_EQ(coulombStatus(point(2.0, 1.0, true), back), 3);
  EXPECT_DOUBLE_EQ(coulombPressure(point(2.0, 1.0, true), 3, back)(0), -1.0);
  // the frozen status 2 keeps its sense whatever q says
  EXPECT_DOUBLE_EQ(coulombPressure(point(2.0, 1.0, true), 2, back)(0), 1.0);
  EXPECT_EQ(coulombStatus(point(2.0, 1.0, false), back), 2);
  EXPECT_DOUBLE_EQ(coulombPressure(point(2.0, 1.0, false), 2, back)(0), -1.0);
}

TEST(ContinuousCoulombLaw, ZeroThresholdSlidesFreelyAndExcludedDirectionsCarryNothing) {
  EXPECT_EQ(coulombStatus(point(0.0, 0.0, true), Eigen::Vector2d{-1e-18, 0.0}), 2);
  CoulombPoint none = point(2.0, 5.0);
  none.directions = 0;
  EXPECT_EQ(coulombStatus(none, Eigen::Vector2d{0.01, 0.0}), 2);
  EXPECT_TRUE(coulombIndicator(none, Eigen::Vector2d{0.01, 0.0}).isZero(0.0));
}

TEST(ContinuousCoulombLaw, ThresholdChangeOverTheLargestThreshold) {
  EXPECT_DOUBLE_EQ(frictionThresholdChange(Eigen::Vector2d{1.0, 2.0}, Eigen::Vector2d{1.5, 4.0}), 0.5);
  EXPECT_DOUBLE_EQ(frictionThresholdChange(Eigen::Vector2d{1.0, 2.0}, Eigen::Vector2d{1.0, 2.0}), 0.0);
  EXPECT_EQ(frictionThresholdChange(Eigen::Vector2d{1.0, 0.0}, Eigen::Vector2d{0.0, 0.0}),
            std::numeric_limits<double>::infinity());
}

} // namespace
} // namespace stella::contact
