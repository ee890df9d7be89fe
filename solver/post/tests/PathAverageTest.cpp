// Moments along a path (POST_RELEVE_T MOYENNE): exact for values linear in the abscissa, on
// unevenly spaced and non-straight paths; a quadratic against its closed-form mean.

#include "solver/post/PathAverage.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace stella {
namespace {

TEST(PathAverage, LinearValuesOnAnUnevenPath) {
  // Nodes at s = 0, 0.1, 0.5, 2 along a broken line (total length 2): f = 3 + 4 s.
  const std::vector<Point3> points{{0, 0, 0}, {0.1, 0, 0}, {0.5, 0, 0}, {0.5, 1.5, 0}};
  const std::vector<double> s{0.0, 0.1, 0.5, 2.0};
  std::vector<double> f;
  for (double x : s) {
    f.push_back(3.0 + 4.0 * x);
  }
  const PathMoments m = pathMoments(points, f);
  EXPECT_NEAR(m.length, 2.0, 1e-15);
  EXPECT_NEAR(m.moment0, 3.0 + 4.0 * 1.0, 1e-14); // value at mid-length
  EXPECT_NEAR(m.moment1, 4.0 * 1.0, 1e-14);       // half the rise over the path
  EXPECT_EQ(m.minimum, 3.0);
  EXPECT_EQ(m.maximum, 11.0);
}

TEST(PathAverage, QuadraticConvergesToItsMean) {
  // f = s^2 on [0, 1]: mean 1/3; trapezoidal error h^2 / 6 on a uniform path.
  const int n = 100;
  std::vector<Point3> points;
  std::vector<double> f;
  for (int i = 0; i <= n; ++i) {
    const double s = static_cast<double>(i) / n;
    points.push_back({0.0, 0.0, s});
    f.push_back(s * s);
  }
  const PathMoments m = pathMoments(points, f);
  const double h = 1.0 / n;
  EXPECT_NEAR(m.moment0, 1.0 / 3.0 + h * h / 6.0, 1e-14);
  // Linearised part of s^2 on [0, 1]: (6/L^2) int s^2 (s - 1/2) ds = 6 (1/4 - 1/6) = 1/2.
  EXPECT_NEAR(m.moment1, 0.5, 1e-4);
}

TEST(PathAverage, SingleNode) {
  const PathMoments m = pathMoments({{1, 2, 3}}, {5.0});
  EXPECT_EQ(m.moment0, 5.0);
  EXPECT_EQ(m.moment1, 0.0);
}

} // namespace
} // namespace stella
