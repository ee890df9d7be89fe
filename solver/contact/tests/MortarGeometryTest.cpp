// Mortar intersection kernels: the overlaps of all the master cells covering a slave cell add up
// to the slave cell (length, area) to 1e-12 for matching and non-matching, rotated and 1:10
// meshes; polygon clipping agrees with a brute-force intersection (vertices inside the other
// polygon and edge crossings, sorted by angle) on random polygons; integration points integrate
// linear functions exactly and carry the slave and master coordinates of their point; shared
// edges and vertices, grazing and nearly parallel masters give what geometry says.

#include "solver/contact/mortar/MortarPolygons.hpp"
#include "solver/contact/mortar/MortarSegments.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

namespace stella::mortar {
namespace {

// ---------------------------------------------------------------- 2D

Segment seg(Point2 a, Point2 b) {
  return {CellType::SEG2, {a, b}};
}

std::vector<int> all(std::size_t n) {
  std::vector<int> v(n);
  std::iota(v.begin(), v.end(), 0);
  return v;
}

Point2 rotate2(Point2 p, double angle) {
  return {std::cos(angle) * p[0] - std::sin(angle) * p[1], std::sin(angle) * p[0] + std::cos(angle) * p[1]};
}

// Masters cutting [x0, x1] at the given abscissas, reversed (they face the slave), at height gap.
std::vector<Segment> masterChain(const std::vector<double>& xs, double gap, double angle) {
  std::vector<Segment> m;
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    m.push_back(seg(rotate2({xs[i + 1], gap}, angle), rotate2({xs[i], gap}, angle)));
  }
  return m;
}

double coveredLength(const Segment& s, const std::vector<Segment>& masters, double* parametric = nullptr) {
  double total = 0;
  double par = 0;
  for (const auto& o : intersectSegments(s, masters, all(masters.size()))) {
    total += o.length;
    par += o.xiMax - o.xiMin;
  }
  if (parametric != nullptr) {
    *parametric = par;
  }
  return total;
}

TEST(MortarSegments, MastersCoveringTheSlaveAddUpToItsLength) {
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const double angle : {0.0, 0.7, 2.5}) {
    const Segment s = seg(rotate2({0, 0}, angle), rotate2({1, 0}, angle));
    // Matching, non-matching (random cuts), fine (1:10) masters.
    std::vector<std::vector<double>> chains{{0, 1}, {-0.3}, {}};
    for (int i = 0; i < 7; ++i) {
      chains[1].push_back(chains[1].back() + 0.05 + 0.2 * u(gen));
    }
    chains[1].push_back(1.3); // past the slave's end
    for (int i = 0; i <= 12; ++i) {
      chains[2].push_back(-0.05 + 0.1 * i);
    }
    for (const auto& xs : chains) {
      double par = 0;
      EXPECT_NEAR(coveredLength(s, masterChain(xs, 1e-3, angle), &par), 1.0, 1e-12);
      EXPECT_NEAR(par, 2.0, 1e-12);
    }
    // A 0.1 slave under one long master.
    const Segment small = seg(rotate2({0.4, 0}, angle), rotate2({0.5, 0}, angle));
    EXPECT_NEAR(coveredLength(small, masterChain({-1, 2}, -1e-3, angle)), 0.1, 1e-12);
  }
}

TEST(MortarSegments, CurvedSlaveAndMastersTileItsParameterAndMeetItsNormals) {
  const auto arc = [](double a, double b) {
    const double m = 0.5 * (a + b);
    return Segment{CellType::SEG3,
                   {{std::cos(a), std::sin(a)}, {std::cos(b), std::sin(b)}, {std::cos(m), std::sin(m)}}};
  };
  const Segment s = arc(0.2, 0.6);
  std::vector<Segment> masters;
  const double cuts[] = {0.7, 0.52, 0.41, 0.33, 0.1};
  for (std::size_t i = 0; i + 1 < std::size(cuts); ++i) {
    Segment m = arc(cuts[i], cuts[i + 1]);
    for (auto& p : m.nodes) {
      p = {1.001 * p[0], 1.001 * p[1]};
    }
    masters.push_back(m);
  }
  double par = 0;
  const double length = coveredLength(s, masters, &par);
  EXPECT_NEAR(par, 2.0, 1e-12);
  EXPECT_NEAR(length, 0.4, 2e-4); // the SEG3 is a parabola through the arc
  for (const auto& o : intersectSegments(s, masters, all(masters.size()), {4})) {
    for (const auto& p : o.points) {
      const Point2 x = segmentPoint(s, p.slaveXi);
      const Point2 t = segmentTangent(s, p.slaveXi);
      const Point2 y = segmentPoint(masters[static_cast<std::size_t>(o.master)], p.masterXi);
      EXPECT_NEAR((y[0] - x[0]) * t[0] + (y[1] - x[1]) * t[1], 0.0, 1e-13); // on the normal
      EXPECT_LE(std::abs(p.masterXi), 1 + 1e-12);
    }
  }
}

TEST(MortarSegments, TouchingGrazingAndDistantMastersGiveNothing) {
  const Segment s = seg({0, 0}, {1, 0});
  const std::vector<Segment> masters{seg({2, 0}, {1, 0}),       // shares the end node only
                                     seg({0.5, 0.1}, {0.5, 1}), // perpendicular
                                     seg({3, 0.01}, {2, 0.01}), // beyond the end
                                     seg({1 + 1e-14, 1e-3}, {0.5, 1e-3})};
  const auto o = intersectSegments(s, masters, all(masters.size()));
  ASSERT_EQ(o.size(), 1u);
  EXPECT_EQ(o[0].master, 3);
  EXPECT_EQ(o[0].xiMax, 1.0); // snapped to the slave end
  EXPECT_NEAR(o[0].length, 0.5, 1e-12);
}

// ---------------------------------------------------------------- 3D

Face quad(Point3 a, Point3 b, Point3 c, Point3 d) {
  return {CellType::QUAD4, {a, b, c, d}};
}

Point3 rotate3(const Point3& p) { // a fixed rotation (axis (1,2,3), angle 0.9)
  const Point3 k = (1.0 / std::sqrt(14.0)) * Point3{1, 2, 3};
  const double c = std::cos(0.9);
  const double s = std::sin(0.9);
  return c * p + s * cross(k, p) + (1 - c) * dot(k, p) * k;
}

// A grid of nx x ny master quadrangles (or triangles) over [x0, x1] x [y0, y1] at height z, with
// the interior nodes moved in the plane, facing down.
std::vector<Face> masterGrid(double x0, double x1, double y0, double y1, int nx, int ny, double z,
                             bool triangles, bool rotated, std::mt19937& gen) {
  std::uniform_real_distribution<double> jitter(-0.25, 0.25);
  std::vector<std::vector<Point3>> p(static_cast<std::size_t>(nx + 1),
                                     std::vector<Point3>(static_cast<std::size_t>(ny + 1)));
  const double hx = (x1 - x0) / nx;
  const double hy = (y1 - y0) / ny;
  for (int i = 0; i <= nx; ++i) {
    for (int j = 0; j <= ny; ++j) {
      const bool inner = i > 0 && i < nx && j > 0 && j < ny;
      Point3 x{x0 + hx * (i + (inner ? jitter(gen) : 0)), y0 + hy * (j + (inner ? jitter(gen) : 0)), z};
      p[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = rotated ? rotate3(x) : x;
    }
  }
  std::vector<Face> faces;
  for (std::size_t i = 0; i < static_cast<std::size_t>(nx); ++i) {
    for (std::size_t j = 0; j < static_cast<std::size_t>(ny); ++j) {
      const Point3 a = p[i][j], b = p[i + 1][j], c = p[i + 1][j + 1], d = p[i][j + 1];
      if (triangles) {
        faces.push_back({CellType::TRIA3, {a, c, b}});
        faces.push_back({CellType::TRIA3, {a, d, c}});
      } else {
        faces.push_back(quad(a, d, c, b));
      }
    }
  }
  return faces;
}

double coveredArea(const Face& s, const std::vector<Face>& masters, const PolygonOptions& o = {}) {
  double a = 0;
  for (const auto& r : intersectFaces(s, masters, all(masters.size()), o)) {
    a += r.area;
    double w = 0;
    for (const auto& p : r.points) {
      w += p.weight;
    }
    EXPECT_NEAR(w, r.area, 1e-13 * std::max(1.0, r.area));
  }
  return a;
}

TEST(MortarPolygons, MastersCoveringTheSlaveAddUpToItsArea) {
  std::mt19937 gen(11);
  for (const bool rotated : {false, true}) {
    const auto R = [&](Point3 p) { return rotated ? rotate3(p) : p; };
    const Face sq = quad(R({0, 0, 0}), R({1, 0, 0}), R({1, 1, 0}), R({0, 1, 0}));
    const Face tri{CellType::TRIA3, {R({0, 0, 0}), R({1, 0, 0}), R({0.3, 0.9, 0})}};
    for (const bool triangles : {false, true}) {
      // matching
      EXPECT_NEAR(coveredArea(sq, masterGrid(0, 1, 0, 1, 1, 1, 0, triangles, rotated, gen)), 1.0, 1e-12);
      // non-matching, overhanging, gap
      EXPECT_NEAR(coveredArea(sq, masterGrid(-0.2, 1.3, -0.4, 1.1, 5, 4, 1e-3, triangles, rotated, gen)), 1.0,
                  1e-12);
      EXPECT_NEAR(coveredArea(tri, masterGrid(-0.2, 1.3, -0.4, 1.1, 5, 4, -1e-3, triangles, rotated, gen)),
                  0.45, 1e-12);
      // 1:10, fine masters
      EXPECT_NEAR(coveredArea(sq, masterGrid(-0.05, 1.05, -0.05, 1.05, 11, 11, 0, triangles, rotated, gen)),
                  1.0, 1e-12);
      // 10:1, a small slave under one master
      const Face small = quad(R({0.4, 0.4, 0}), R({0.5, 0.4, 0}), R({0.5, 0.5, 0}), R({0.4, 0.5, 0}));
      EXPECT_NEAR(coveredArea(small, masterGrid(0, 1, 0, 1, 1, 1, 0, triangles, rotated, gen)), 0.01, 1e-14);
    }
  }
}

TEST(MortarPolygons, QuadraticFacesUseTheirLinearHull) {
  std::mt19937 gen(5);
  const Face q8{CellType::QUAD8,
                {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}, {1, 0, 0}, {2, 0.5, 0}, {1, 1, 0}, {0, 0.5, 0}}};
  const Face t6{CellType::TRIA6, {{0, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 0.5, 0}, {0, 0.5, 0}}};
  EXPECT_NEAR(coveredArea(q8, masterGrid(-0.1, 2.1, -0.1, 1.1, 3, 2, 0, false, false, gen)), 2.0, 1e-12);
  EXPECT_NEAR(coveredArea(t6, masterGrid(-0.1, 2.1, -0.1, 1.1, 3, 2, 0, true, false, gen)), 1.0, 1e-12);
}

// Brute force: vertices of each polygon inside the other and edge crossings, sorted by angle.
double bruteArea(const std::vector<Point2d>& a, const std::vector<Point2d>& b) {
  const auto inside = [](const Point2d& p, const std::vector<Point2d>& q) {
    for (std::size_t i = 0; i < q.size(); ++i) {
      const auto& u = q[i];
      const auto& v = q[(i + 1) % q.size()];
      if ((v[0] - u[0]) * (p[1] - u[1]) - (v[1] - u[1]) * (p[0] - u[0]) < 0) {
        return false;
      }
    }
    return true;
  };
  std::vector<Point2d> pts;
  for (const auto& p : a) {
    if (inside(p, b)) {
      pts.push_back(p);
    }
  }
  for (const auto& p : b) {
    if (inside(p, a)) {
      pts.push_back(p);
    }
  }
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = 0; j < b.size(); ++j) {
      const auto& p = a[i];
      const auto& p2 = a[(i + 1) % a.size()];
      const auto& q = b[j];
      const auto& q2 = b[(j + 1) % b.size()];
      const double rx = p2[0] - p[0], ry = p2[1] - p[1], sx = q2[0] - q[0], sy = q2[1] - q[1];
      const double den = rx * sy - ry * sx;
      if (den == 0) {
        continue;
      }
      const double t = ((q[0] - p[0]) * sy - (q[1] - p[1]) * sx) / den;
      const double s = ((q[0] - p[0]) * ry - (q[1] - p[1]) * rx) / den;
      if (t >= 0 && t <= 1 && s >= 0 && s <= 1) {
        pts.push_back({p[0] + t * rx, p[1] + t * ry});
      }
    }
  }
  if (pts.size() < 3) {
    return 0;
  }
  Point2d c{0, 0};
  for (const auto& p : pts) {
    c = {c[0] + p[0] / static_cast<double>(pts.size()), c[1] + p[1] / static_cast<double>(pts.size())};
  }
  std::sort(pts.begin(), pts.end(), [&](const Point2d& u, const Point2d& v) {
    return std::atan2(u[1] - c[1], u[0] - c[0]) < std::atan2(v[1] - c[1], v[0] - c[0]);
  });
  return polygonArea(pts);
}

std::vector<Point2d> randomConvex(std::mt19937& gen, int n) {
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> angles;
  for (int i = 0; i < n; ++i) {
    angles.push_back(2 * M_PI * u(gen));
  }
  std::sort(angles.begin(), angles.end());
  const double cx = u(gen), cy = u(gen), rx = 0.2 + u(gen), ry = 0.2 + u(gen);
  std::vector<Point2d> p;
  for (const double t : angles) {
    p.push_back({cx + rx * std::cos(t), cy + ry * std::sin(t)});
  }
  return p;
}

TEST(MortarPolygons, ClippingAgreesWithBruteForceOnRandomPolygons) {
  std::mt19937 gen(2026);
  int overlapping = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const auto a = randomConvex(gen, 3 + trial % 2);
    const auto b = randomConvex(gen, 3 + (trial / 2) % 2);
    if (polygonArea(a) < 1e-3 || polygonArea(b) < 1e-3) {
      continue;
    }
    const auto c = clipConvex(a, b, 1e-14);
    const double area = c.size() >= 3 ? polygonArea(c) : 0.0;
    EXPECT_NEAR(area, bruteArea(a, b), 1e-12) << "trial " << trial;
    overlapping += area > 0 ? 1 : 0;
  }
  EXPECT_GT(overlapping, 500); // the test is about overlaps
}

TEST(MortarPolygons, IntegrationPointsIntegrateLinearFunctionsAndCarryCoordinates) {
  // A slave quadrangle and a tilted, rotated master quadrangle overlapping it partly.
  const Face s = quad({0, 0, 0}, {2, 0, 0}, {2.2, 1, 0}, {0, 1.2, 0});
  const Face m = quad({0.5, -0.5, 0.3}, {0.2, 1.5, 0.2}, {3, 1.5, 0.1}, {2.6, -0.3, 0.2});
  for (const int degree : {1, 2, 3, 5}) {
    const auto r = intersectFaces(s, std::vector<Face>{m}, std::vector<int>{0}, {degree});
    ASSERT_EQ(r.size(), 1u);
    // Exact moments of the polygon (in the slave plane z = 0): the integral of x.
    double mx = 0;
    for (std::size_t i = 0; i < r[0].polygon.size(); ++i) {
      const auto& u = r[0].polygon[i];
      const auto& v = r[0].polygon[(i + 1) % r[0].polygon.size()];
      const double cr = u[0] * v[1] - v[0] * u[1];
      mx += (u[0] + v[0]) * cr / 6;
    }
    double gx = 0;
    for (const auto& p : r[0].points) {
      gx += p.weight * p.x[0];
      // The slave coordinates give the point back (flat slave); the master ones a point on the
      // master's bilinear surface straight above it.
      const double xi = p.slave[0], eta = p.slave[1];
      const double n[4] = {(1 - xi) * (1 - eta) / 4, (1 + xi) * (1 - eta) / 4, (1 + xi) * (1 + eta) / 4,
                           (1 - xi) * (1 + eta) / 4};
      Point3 xs{0, 0, 0}, xm{0, 0, 0};
      const double mn[4] = {
          (1 - p.master[0]) * (1 - p.master[1]) / 4, (1 + p.master[0]) * (1 - p.master[1]) / 4,
          (1 + p.master[0]) * (1 + p.master[1]) / 4, (1 - p.master[0]) * (1 + p.master[1]) / 4};
      for (std::size_t i = 0; i < 4; ++i) {
        xs = xs + n[i] * s.nodes[i];
        xm = xm + mn[i] * m.nodes[i];
      }
      EXPECT_NEAR(norm(xs - p.x), 0.0, 1e-13);
      EXPECT_NEAR(xm[0], p.x[0], 1e-12);
      EXPECT_NEAR(xm[1], p.x[1], 1e-12);
    }
    EXPECT_NEAR(gx, mx, 1e-13);
  }
}

TEST(MortarPolygons, SharedEdgesVerticesGrazingAndNearlyParallelMasters) {
  const Face s = quad({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});
  const std::vector<Face> masters{
      quad({1, 0, 0}, {1, 1, 0}, {2, 1, 0}, {2, 0, 0}),         // 0: shares an edge, outside
      quad({1, 1, 0}, {1, 2, 0}, {2, 2, 0}, {2, 1, 0}),         // 1: shares a vertex
      quad({0.5, 0, 0}, {0.5, 1, 0}, {0.5, 1, 1}, {0.5, 0, 1}), // 2: perpendicular (grazing)
      quad({0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}),         // 3: the same face, reversed
      quad({0.2, 0.2, 1e-9}, {0.2, 0.8, 1e-9}, {0.8, 0.8, 2e-9}, {0.8, 0.2, 2e-9}), // 4: nearly parallel
      quad({1 + 1e-15, 0, 0}, {1 + 1e-15, 1, 0}, {2, 1, 0}, {2, 0, 0}),             // 5: a hair away
      quad({0.5, 0.5, 0}, {0.5 + 1e-5, 0.5, 0}, {0.5 + 1e-5, 0.5 + 1e-5, 0}, {0.5, 0.5 + 1e-5, 0}), // 6: tiny
      quad({0.5, 0.5, 0}, {0.5 + 1e-7, 0.5, 0}, {0.5 + 1e-7, 0.5 + 1e-7, 0},
           {0.5, 0.5 + 1e-7, 0}), // 7: below
                                  // 1e-12 of the slave
  };
  const auto r = intersectFaces(s, masters, all(masters.size()));
  ASSERT_EQ(r.size(), 3u);
  EXPECT_EQ(r[0].master, 3);
  EXPECT_NEAR(r[0].area, 1.0, 1e-15);
  EXPECT_EQ(r[0].polygon.size(), 4u); // no duplicate points on shared edges
  EXPECT_EQ(r[1].master, 4);
  EXPECT_NEAR(r[1].area, 0.36, 1e-15);
  EXPECT_EQ(r[2].master, 6);
  EXPECT_NEAR(r[2].area, 1e-10, 1e-20); // its corners 0.5 + 1e-5 are rounded to 1e-16
  // A master tilted by 1e-6 rad about the x axis: its shadow is its own area times the cosine.
  const double t = 1e-6;
  const Face tilted = quad({0.1, 0.1, 0}, {0.1, 0.1 + 0.5 * std::cos(t), 0.5 * std::sin(t)},
                           {0.9, 0.1 + 0.5 * std::cos(t), 0.5 * std::sin(t)}, {0.9, 0.1, 0});
  const auto rt = intersectFaces(s, std::vector<Face>{tilted}, std::vector<int>{0});
  ASSERT_EQ(rt.size(), 1u);
  EXPECT_NEAR(rt[0].area, 0.4 * std::cos(t), 1e-15);
}

} // namespace
} // namespace stella::mortar
