// Mortar geometry in 3D (see MortarPolygons.hpp).

#include "solver/contact/mortar/MortarPolygons.hpp"

#include "interpreter/Diagnostics.hpp"
#include "solver/mesh/CellTopology.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace stella::mortar {

namespace {

struct TriangleRule {
  std::vector<std::array<double, 2>> points; // on (0,0),(1,0),(0,1)
  std::vector<double> weights;               // summing to 1
};

TriangleRule triangleRule(int degree) {
  if (degree <= 1) {
    return {{{1.0 / 3, 1.0 / 3}}, {1.0}};
  }
  if (degree == 2) {
    return {{{1.0 / 6, 1.0 / 6}, {2.0 / 3, 1.0 / 6}, {1.0 / 6, 2.0 / 3}}, {1.0 / 3, 1.0 / 3, 1.0 / 3}};
  }
  if (degree == 3) {
    return {{{1.0 / 3, 1.0 / 3}, {0.2, 0.2}, {0.6, 0.2}, {0.2, 0.6}},
            {-27.0 / 48, 25.0 / 48, 25.0 / 48, 25.0 / 48}};
  }
  const double s = std::sqrt(15.0);
  const double a = (6 - s) / 21;
  const double b = (6 + s) / 21;
  const double wa = (155 - s) / 1200;
  const double wb = (155 + s) / 1200;
  return {
      {{1.0 / 3, 1.0 / 3}, {a, a}, {1 - 2 * a, a}, {a, 1 - 2 * a}, {b, b}, {1 - 2 * b, b}, {b, 1 - 2 * b}},
      {9.0 / 40, wa, wa, wa, wb, wb, wb}};
}

// The plane of the slave face: origin, unit normal, tangent basis.
struct Plane {
  Point3 origin{};
  Point3 n{};
  Point3 t1{};
  Point3 t2{};
  Point2d local(const Point3& x) const {
    const Point3 d = x - origin;
    return {dot(d, t1), dot(d, t2)};
  }
  Point3 global(const Point2d& p) const { return origin + p[0] * t1 + p[1] * t2; }
};

// Twice the vector area of the vertex polygon, from differences to the first vertex: the sum of
// cross(x_i, x_i+1) over absolute positions is the same vector but cancels 1e4 against 1e-6 for
// a face 1e-3 wide at 100 from the origin (a normal 1e-6 off: points 3e-11 off their line).
Point3 newellNormal(const Face& f) {
  const int nv = vertexCount(f.type);
  const Point3& o = f.nodes[0];
  Point3 n{0, 0, 0};
  for (int i = 1; i + 1 < nv; ++i) {
    n = n + cross(f.nodes[static_cast<std::size_t>(i)] - o, f.nodes[static_cast<std::size_t>(i + 1)] - o);
  }
  return n;
}

Plane slavePlane(const Face& s) {
  Plane p;
  const int nv = vertexCount(s.type);
  for (int i = 0; i < nv; ++i) {
    p.origin = p.origin + (1.0 / nv) * s.nodes[static_cast<std::size_t>(i)];
  }
  const Point3 n = newellNormal(s);
  p.n = (1.0 / norm(n)) * n;
  const Point3 e = std::abs(p.n[0]) < 0.9 ? Point3{1, 0, 0} : Point3{0, 1, 0};
  const Point3 t1 = cross(e, p.n);
  p.t1 = (1.0 / norm(t1)) * t1;
  p.t2 = cross(p.n, p.t1);
  return p;
}

std::vector<Point2d> projected(const Face& f, const Plane& p) {
  std::vector<Point2d> out;
  for (int i = 0; i < vertexCount(f.type); ++i) {
    out.push_back(p.local(f.nodes[static_cast<std::size_t>(i)]));
  }
  if (polygonArea(out) < 0) {
    std::reverse(out.begin(), out.end());
  }
  return out;
}

// Shape functions of a linear hull and their derivatives, in closed form (the Lagrange bases of
// fem::referenceElement: TRIA3 on (0,0),(1,0),(0,1), QUAD4 on [-1,1]^2), without the allocations
// of the generic evaluation: this runs at every integration point, twice.
void hullShape(bool triangle, double xi, double eta, double n[4], double dxi[4], double deta[4]) {
  if (triangle) {
    n[0] = 1 - xi - eta, n[1] = xi, n[2] = eta;
    dxi[0] = -1, dxi[1] = 1, dxi[2] = 0;
    deta[0] = -1, deta[1] = 0, deta[2] = 1;
    return;
  }
  const double a[4] = {-1, 1, 1, -1};
  const double b[4] = {-1, -1, 1, 1};
  for (int i = 0; i < 4; ++i) {
    n[i] = 0.25 * (1 + a[i] * xi) * (1 + b[i] * eta);
    dxi[i] = 0.25 * a[i] * (1 + b[i] * eta);
    deta[i] = 0.25 * b[i] * (1 + a[i] * xi);
  }
}

// Parametric coordinates on the linear hull of `f` of the point where the line x + s n meets it.
// Newton until the step is below 1e-15 or stops decreasing once below 1e-8: the coordinates
// are then exact to round-off, which on a face of size h at distance |x| from the origin is
// about 1e-16 |x| / h, above 1e-15 for small faces (the iteration ran its 30 steps on 40 % of
// the points of a 10^4-face pairing before).
std::array<double, 2> hullCoordinates(const Face& f, const Point3& x, const Point3& n) {
  const bool triangle = linearType(f.type) == CellType::TRIA3;
  const int nv = triangle ? 3 : 4;
  Eigen::Vector3d xi = triangle ? Eigen::Vector3d(1.0 / 3, 1.0 / 3, 0) : Eigen::Vector3d::Zero();
  double along = 0;
  double v[4], gx[4], gy[4];
  double previous = HUGE_VAL;
  for (int it = 0; it < 30; ++it) {
    hullShape(triangle, xi(0), xi(1), v, gx, gy);
    Eigen::Vector3d r = Eigen::Vector3d(along * n[0] - x[0], along * n[1] - x[1], along * n[2] - x[2]);
    Eigen::Matrix3d jac = Eigen::Matrix3d::Zero();
    for (int i = 0; i < nv; ++i) {
      const Point3& p = f.nodes[static_cast<std::size_t>(i)];
      const Eigen::Vector3d q(p[0], p[1], p[2]);
      r += v[i] * q;
      jac.col(0) += gx[i] * q;
      jac.col(1) += gy[i] * q;
    }
    jac.col(2) = Eigen::Vector3d(n[0], n[1], n[2]);
    // Cramer's rule (the columns: two tangents and the unit normal, well conditioned unless the
    // face is seen edge-on); full pivoting where the determinant vanishes next to the tangents.
    const double det = jac.determinant();
    const Eigen::Vector3d step = std::abs(det) > 1e-12 * jac.col(0).norm() * jac.col(1).norm()
                                     ? Eigen::Vector3d(jac.inverse() * r)
                                     : Eigen::Vector3d(jac.fullPivLu().solve(r));
    xi(0) -= step(0);
    xi(1) -= step(1);
    along -= step(2);
    const double size = step.head<2>().norm();
    if (size < 1e-15 || (size < 1e-8 && size >= 0.5 * previous)) {
      break;
    }
    previous = size;
  }
  return {xi(0), xi(1)};
}

double diameter(const std::vector<Point2d>& p) {
  double d = 0;
  for (const auto& a : p) {
    for (const auto& b : p) {
      d = std::max(d, std::hypot(a[0] - b[0], a[1] - b[1]));
    }
  }
  return d;
}

} // namespace

double polygonArea(const std::vector<Point2d>& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto& u = p[i];
    const auto& v = p[(i + 1) % p.size()];
    a += u[0] * v[1] - u[1] * v[0];
  }
  return 0.5 * a;
}

std::vector<Point2d> clipConvex(const std::vector<Point2d>& subject, const std::vector<Point2d>& clip,
                                double eps) {
  std::vector<Point2d> poly = subject;
  for (std::size_t e = 0; e < clip.size() && !poly.empty(); ++e) {
    const Point2d a = clip[e];
    const Point2d b = clip[(e + 1) % clip.size()];
    const double len = std::hypot(b[0] - a[0], b[1] - a[1]);
    // Signed distance to the line (a, b), positive inside (on the left); snapped to 0 within eps.
    std::vector<double> d;
    for (const auto& p : poly) {
      const double s = ((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])) / len;
      d.push_back(std::abs(s) <= eps ? 0.0 : s);
    }
    std::vector<Point2d> out;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const std::size_t j = (i + 1) % poly.size();
      if (d[i] >= 0) {
        out.push_back(poly[i]);
      }
      if ((d[i] > 0 && d[j] < 0) || (d[i] < 0 && d[j] > 0)) {
        const double t = d[i] / (d[i] - d[j]);
        out.push_back(
            {poly[i][0] + t * (poly[j][0] - poly[i][0]), poly[i][1] + t * (poly[j][1] - poly[i][1])});
      }
    }
    poly = std::move(out);
  }
  // Merge consecutive vertices closer than eps.
  std::vector<Point2d> merged;
  for (const auto& p : poly) {
    if (merged.empty() || std::hypot(p[0] - merged.back()[0], p[1] - merged.back()[1]) > eps) {
      merged.push_back(p);
    }
  }
  while (merged.size() > 1 &&
         std::hypot(merged.front()[0] - merged.back()[0], merged.front()[1] - merged.back()[1]) <= eps) {
    merged.pop_back();
  }
  return merged;
}

std::vector<PolygonOverlap> intersectFaces(const Face& slave, std::span<const Face> masters,
                                           std::span<const int> candidates, const PolygonOptions& options) {
  STELLA_ASSERT(dimension(slave.type) == 2 && static_cast<int>(slave.nodes.size()) == nodeCount(slave.type),
                "mortar slave face");
  const Plane plane = slavePlane(slave);
  const auto slavePolygon = projected(slave, plane);
  const double h = diameter(slavePolygon);
  const double eps = options.relativeTolerance * h;
  const TriangleRule rule = triangleRule(options.degree);
  std::vector<PolygonOverlap> out;
  for (const int k : candidates) {
    const Face& m = masters[static_cast<std::size_t>(k)];
    const Point3 nm = newellNormal(m);
    const double nmNorm = norm(nm);
    if (!(nmNorm > 0) || !(std::abs(dot(nm, plane.n)) >= options.grazingCosine * nmNorm)) {
      continue; // degenerate or seen edge-on
    }
    const auto poly = clipConvex(projected(m, plane), slavePolygon, eps);
    if (poly.size() < 3) {
      continue;
    }
    const double area = polygonArea(poly);
    if (!(area > eps * h)) {
      continue;
    }
    PolygonOverlap o{k, area, {}, {}};
    Point2d c{0, 0};
    for (const auto& p : poly) {
      o.polygon.push_back(plane.global(p));
      c = {c[0] + p[0] / static_cast<double>(poly.size()), c[1] + p[1] / static_cast<double>(poly.size())};
    }
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Point2d& a = poly[i];
      const Point2d& b = poly[(i + 1) % poly.size()];
      const double tri = polygonArea({c, a, b});
      if (!(tri > 0)) {
        continue; // a zero-area triangle of collinear merged vertices
      }
      for (std::size_t g = 0; g < rule.weights.size(); ++g) {
        const double u = rule.points[g][0];
        const double v = rule.points[g][1];
        const Point2d p{c[0] + u * (a[0] - c[0]) + v * (b[0] - c[0]),
                        c[1] + u * (a[1] - c[1]) + v * (b[1] - c[1])};
        const Point3 x = plane.global(p);
        o.points.push_back(
            {hullCoordinates(slave, x, plane.n), hullCoordinates(m, x, plane.n), x, rule.weights[g] * tri});
      }
    }
    out.push_back(std::move(o));
  }
  return out;
}

} // namespace stella::mortar
