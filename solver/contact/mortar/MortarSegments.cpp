// Mortar geometry in 2D (see MortarSegments.hpp).

#include "solver/contact/mortar/MortarSegments.hpp"

#include "interpreter/Diagnostics.hpp"

#include <algorithm>
#include <cmath>

namespace stella::mortar {

namespace {

struct Shape {
  std::array<double, 3> n{};
  std::array<double, 3> d{};
};

Shape shape(CellType t, double xi) {
  if (t == CellType::SEG2) {
    return {{0.5 * (1 - xi), 0.5 * (1 + xi), 0}, {-0.5, 0.5, 0}};
  }
  return {{-0.5 * xi * (1 - xi), 0.5 * xi * (1 + xi), 1 - xi * xi}, {xi - 0.5, xi + 0.5, -2 * xi}};
}

double cross(const Point2& a, const Point2& b) {
  return a[0] * b[1] - a[1] * b[0];
}
double dot(const Point2& a, const Point2& b) {
  return a[0] * b[0] + a[1] * b[1];
}
Point2 minus(const Point2& a, const Point2& b) {
  return {a[0] - b[0], a[1] - b[1]};
}

// The slave coordinate whose normal line passes through p: (p - x(xi)) . t(xi) = 0.
double projectOnNormalLines(const Segment& s, const Point2& p) {
  const Point2 a = s.nodes[0];
  const Point2 b = s.nodes[1];
  const Point2 ab = minus(b, a);
  double xi = 2 * dot(minus(p, a), ab) / dot(ab, ab) - 1; // exact for a straight segment
  if (s.type == CellType::SEG2) {
    return xi;
  }
  for (int it = 0; it < 30; ++it) {
    const Point2 r = minus(p, segmentPoint(s, xi));
    const Point2 t = segmentTangent(s, xi);
    const Point2 tt = {2 * (s.nodes[0][0] + s.nodes[1][0] - 2 * s.nodes[2][0]) * 0.5,
                       2 * (s.nodes[0][1] + s.nodes[1][1] - 2 * s.nodes[2][1]) * 0.5};
    const double f = dot(r, t);
    const double df = -dot(t, t) + dot(r, tt);
    const double step = f / df;
    xi -= step;
    if (std::abs(step) < 1e-15) {
      break;
    }
  }
  return xi;
}

// The master coordinate where the line through x along n meets the master.
double projectAlong(const Segment& m, const Point2& x, const Point2& n) {
  double xi = 0;
  for (int it = 0; it < 30; ++it) {
    const double g = cross(minus(segmentPoint(m, xi), x), n);
    const double dg = cross(segmentTangent(m, xi), n);
    if (dg == 0) {
      break;
    }
    const double step = g / dg;
    xi -= step;
    if (std::abs(step) < 1e-15) {
      break;
    }
  }
  return xi;
}

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

} // namespace

Point2 segmentPoint(const Segment& s, double xi) {
  const Shape f = shape(s.type, xi);
  Point2 x{0, 0};
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    x[0] += f.n[i] * s.nodes[i][0];
    x[1] += f.n[i] * s.nodes[i][1];
  }
  return x;
}

Point2 segmentTangent(const Segment& s, double xi) {
  const Shape f = shape(s.type, xi);
  Point2 t{0, 0};
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    t[0] += f.d[i] * s.nodes[i][0];
    t[1] += f.d[i] * s.nodes[i][1];
  }
  return t;
}

std::vector<SegmentOverlap> intersectSegments(const Segment& slave, std::span<const Segment> masters,
                                              std::span<const int> candidates,
                                              const SegmentOptions& options) {
  STELLA_ASSERT(slave.nodes.size() == (slave.type == CellType::SEG2 ? 2u : 3u), "mortar slave segment");
  std::vector<double> gx;
  std::vector<double> gw;
  gaussLegendre(options.gaussPoints, gx, gw);
  const double eps = 2 * options.minLength;
  const Point2 slaveChord = minus(slave.nodes[1], slave.nodes[0]);
  std::vector<SegmentOverlap> out;
  for (const int k : candidates) {
    const Segment& m = masters[static_cast<std::size_t>(k)];
    const Point2 chord = minus(m.nodes[1], m.nodes[0]);
    const double cosine =
        std::abs(dot(chord, slaveChord)) / std::sqrt(dot(chord, chord) * dot(slaveChord, slaveChord));
    if (!(cosine >= options.grazingCosine)) {
      continue; // master seen edge-on (or degenerate)
    }
    double a = projectOnNormalLines(slave, m.nodes[0]);
    double b = projectOnNormalLines(slave, m.nodes[1]);
    if (a > b) {
      std::swap(a, b);
    }
    a = std::abs(a + 1) <= eps ? -1.0 : std::max(a, -1.0);
    b = std::abs(b - 1) <= eps ? 1.0 : std::min(b, 1.0);
    if (!(b - a > eps)) {
      continue;
    }
    SegmentOverlap o{k, a, b, 0.0, {}};
    for (std::size_t g = 0; g < gx.size(); ++g) {
      const double xi = 0.5 * (a + b) + 0.5 * (b - a) * gx[g];
      const Point2 t = segmentTangent(slave, xi);
      const double jac = std::sqrt(dot(t, t));
      const Point2 n = {t[1] / jac, -t[0] / jac};
      const double w = gw[g] * 0.5 * (b - a) * jac;
      o.points.push_back({xi, projectAlong(m, segmentPoint(slave, xi), n), w});
      o.length += w;
    }
    out.push_back(std::move(o));
  }
  return out;
}

} // namespace stella::mortar
