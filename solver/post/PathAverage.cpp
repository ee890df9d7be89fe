// PathAverage: moments of piecewise-linear values along an ordered polyline.

#include "solver/post/PathAverage.hpp"

#include "interpreter/Diagnostics.hpp"

#include <algorithm>
#include <cmath>

namespace stella {

PathMoments pathMoments(const std::vector<Point3>& points, const std::vector<double>& values) {
  STELLA_ASSERT(!points.empty() && points.size() == values.size(), "a path needs one value per node");
  std::vector<double> s(points.size(), 0.0);
  for (std::size_t i = 1; i < points.size(); ++i) {
    double d2 = 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
      d2 += (points[i][k] - points[i - 1][k]) * (points[i][k] - points[i - 1][k]);
    }
    s[i] = s[i - 1] + std::sqrt(d2);
  }
  PathMoments m;
  m.length = s.back();
  m.minimum = *std::min_element(values.begin(), values.end());
  m.maximum = *std::max_element(values.begin(), values.end());
  if (m.length <= 0.0) {
    m.moment0 = values.front();
    return m;
  }
  const double centre = 0.5 * m.length;
  double integral = 0.0;
  double first = 0.0;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const double h = s[i + 1] - s[i];
    const double fa = values[i];
    const double fb = values[i + 1];
    const double ga = s[i] - centre;
    const double gb = s[i + 1] - centre;
    integral += 0.5 * h * (fa + fb);
    first += h / 6.0 * (2.0 * fa * ga + fa * gb + fb * ga + 2.0 * fb * gb);
  }
  m.moment0 = integral / m.length;
  m.moment1 = 6.0 * first / (m.length * m.length);
  return m;
}

} // namespace stella
