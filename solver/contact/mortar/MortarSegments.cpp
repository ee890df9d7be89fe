// Mortar geometry in 2D (see MortarSegments.hpp).

#include "solver/contact/mortar/MortarSegments.hpp"

#include "solver/contact/mortar/MortarSegmentKernel.hpp"

#include "interpreter/Diagnostics.hpp"

#include <algorithm>
#include <cmath>

namespace stella::mortar {

namespace kernel {

void gaussLegendre(int n, std::vector<double>& x, std::vector<double>& w) {
  switch (n) {
  case 1:
    x = {0};
    w = {2};
    break;
  case 2:
    x = {-1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};
    w = {1, 1};
    break;
  case 3:
    x = {-std::sqrt(0.6), 0, std::sqrt(0.6)};
    w = {5.0 / 9, 8.0 / 9, 5.0 / 9};
    break;
  default: {
    const double a = std::sqrt(3.0 / 7 - 2.0 / 7 * std::sqrt(1.2));
    const double b = std::sqrt(3.0 / 7 + 2.0 / 7 * std::sqrt(1.2));
    const double wa = (18 + std::sqrt(30.0)) / 36;
    const double wb = (18 - std::sqrt(30.0)) / 36;
    x = {-b, -a, a, b};
    w = {wb, wa, wa, wb};
  }
  }
}

} // namespace kernel

Point2 segmentPoint(const Segment& s, double xi) {
  return kernel::point<double>(s.type, s.nodes, xi);
}

Point2 segmentTangent(const Segment& s, double xi) {
  return kernel::tangent<double>(s.type, s.nodes, xi);
}

std::vector<SegmentOverlap> intersectSegments(const Segment& slave, std::span<const Segment> masters,
                                              std::span<const int> candidates,
                                              const SegmentOptions& options) {
  STELLA_ASSERT(slave.nodes.size() == (slave.type == CellType::SEG2 ? 2u : 3u), "mortar slave segment");
  std::vector<double> gx;
  std::vector<double> gw;
  kernel::gaussLegendre(options.gaussPoints, gx, gw);
  std::vector<SegmentOverlap> out;
  for (const int k : candidates) {
    const Segment& m = masters[static_cast<std::size_t>(k)];
    double a = 0.0;
    double b = 0.0;
    if (!kernel::coveredInterval<double>(slave.type, slave.nodes, m.type, m.nodes, options.minLength,
                                         options.grazingCosine, a, b)) {
      continue;
    }
    SegmentOverlap o{k, a, b, 0.0, {}};
    for (std::size_t g = 0; g < gx.size(); ++g) {
      const double xi = 0.5 * (a + b) + 0.5 * (b - a) * gx[g];
      const Point2 t = segmentTangent(slave, xi);
      const double jac = std::sqrt(kernel::dot(t, t));
      const Point2 n = {t[1] / jac, -t[0] / jac};
      const double w = gw[g] * 0.5 * (b - a) * jac;
      o.points.push_back({xi, kernel::projectAlong<double>(m.type, m.nodes, segmentPoint(slave, xi), n), w});
      o.length += w;
    }
    out.push_back(std::move(o));
  }
  return out;
}

} // namespace stella::mortar
