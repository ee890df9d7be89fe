// Projection of a point on one master cell (no allocation), and the candidate selection rule.

#include "solver/contact/CellProjection.hpp"

#include "solver/mesh/MeshGeometry.hpp"

#include <algorithm>
#include <cmath>

namespace stella::contact {

namespace {

bool isTriangle(CellType t) {
  return t == CellType::TRIA3 || t == CellType::TRIA6;
}

} // namespace

void evaluateCell(const CellNodes& cell, const std::array<double, 2>& xi, CellPoint& out) {
  surfaceShape(cell.type, xi[0], xi[1], out.shape);
  out.x = {0, 0, 0};
  out.d1 = {0, 0, 0};
  out.d2 = {0, 0, 0};
  for (std::size_t i = 0; i < static_cast<std::size_t>(cell.count); ++i) {
    const Point3& xn = cell.x[i];
    for (std::size_t a = 0; a < 3; ++a) {
      out.x[a] += out.shape.n[i] * xn[a];
      out.d1[a] += out.shape.dxi[i] * xn[a];
      out.d2[a] += out.shape.deta[i] * xn[a];
    }
  }
}

std::array<double, 2> projectPoint(const CellNodes& cell, int dim, const Point3& p) {
  std::array<double, 2> xi =
      isTriangle(cell.type) ? std::array<double, 2>{1.0 / 3.0, 1.0 / 3.0} : std::array<double, 2>{0.0, 0.0};
  CellPoint g;
  for (int it = 0; it < 50; ++it) {
    evaluateCell(cell, xi, g);
    const Point3 r = g.x - p;
    if (dim == 1) {
      const double h = dot(g.d1, g.d1);
      const double step = -dot(g.d1, r) / h;
      xi[0] += step;
      if (std::abs(step) < 1e-12) {
        break;
      }
    } else {
      const double a = dot(g.d1, g.d1);
      const double b = dot(g.d1, g.d2);
      const double c = dot(g.d2, g.d2);
      const double r1 = -dot(g.d1, r);
      const double r2 = -dot(g.d2, r);
      const double det = a * c - b * b;
      const double s1 = (c * r1 - b * r2) / det;
      const double s2 = (a * r2 - b * r1) / det;
      xi[0] += s1;
      xi[1] += s2;
      if (std::abs(s1) + std::abs(s2) < 1e-12) {
        break;
      }
    }
    // Keep far-off iterates bounded (a degenerate start must not diverge).
    xi[0] = std::clamp(xi[0], -10.0, 10.0);
    xi[1] = std::clamp(xi[1], -10.0, 10.0);
  }
  return xi;
}

double outsideDistance(CellType type, int dim, const std::array<double, 2>& xi,
                       std::array<double, 2>& clamped) {
  clamped = xi;
  if (dim == 1) {
    clamped[0] = std::clamp(xi[0], -1.0, 1.0);
    clamped[1] = 0.0;
    return std::abs(xi[0] - clamped[0]);
  }
  if (!isTriangle(type)) {
    clamped[0] = std::clamp(xi[0], -1.0, 1.0);
    clamped[1] = std::clamp(xi[1], -1.0, 1.0);
    return std::max(std::abs(xi[0] - clamped[0]), std::abs(xi[1] - clamped[1]));
  }
  // Triangle 0 <= xi, eta; xi + eta <= 1.
  double a = std::max(xi[0], 0.0);
  double b = std::max(xi[1], 0.0);
  if (a + b > 1.0) {
    const double excess = (a + b - 1.0) / 2.0;
    a -= excess;
    b -= excess;
    if (a < 0.0) {
      b = 1.0;
      a = 0.0;
    } else if (b < 0.0) {
      a = 1.0;
      b = 0.0;
    }
  }
  clamped = {a, b};
  return std::max({-xi[0], -xi[1], xi[0] + xi[1] - 1.0, 0.0});
}

Candidate projectionCandidate(const CellNodes& cell, int position, int dim, const Point3& p,
                              double extensionTolerance) {
  Candidate c;
  c.cell = position;
  const auto xi = projectPoint(cell, dim, p);
  c.outside = outsideDistance(cell.type, dim, xi, c.xi);
  CellPoint g;
  evaluateCell(cell, c.xi, g);
  c.distance = norm(g.x - p);
  // A degenerate cell (zero Jacobian) gives no projection.
  c.admissible = (extensionTolerance < 0.0 || c.outside <= extensionTolerance) && std::isfinite(c.distance);
  return c;
}

int selectCandidate(const Candidate* first, const Candidate* last, double tieTolerance) {
  double smallest = std::numeric_limits<double>::max();
  for (const Candidate* c = first; c != last; ++c) {
    if (c->admissible) {
      smallest = std::min(smallest, c->distance);
    }
  }
  int best = -1;
  for (const Candidate* c = first; c != last; ++c) {
    if (!c->admissible || c->distance > smallest + tieTolerance) {
      continue;
    }
    if (best < 0) {
      best = static_cast<int>(c - first);
      continue;
    }
    // Projections outside by round-off only count as inside.
    const double co = c->outside <= 1e-10 ? 0.0 : c->outside;
    const double bo = first[best].outside <= 1e-10 ? 0.0 : first[best].outside;
    if (co < bo || (co == bo && c->cell < first[best].cell)) {
      best = static_cast<int>(c - first);
    }
  }
  return best;
}

} // namespace stella::contact
