// Mortar pairing of surfaces (R-tree search + polygon clipping), against exact properties:
//   - a flat slave surface fully covered by a non-matching master surface: every slave face's
//     overlaps add up to its area (1e-12 relative), for every pair of TRIA3, TRIA6, QUAD4, QUAD8,
//     QUAD9 meshes, master facing the slave or the same way;
//   - the pairing agrees with all-pairs clipping (every master tried for every slave): the same
//     masters and the same areas, on warped (wavy) quadrangles; 2 threads give the same result;
//   - a cylinder: the overlaps of a faceted slave cylinder add up to its facets' area (exact,
//     the master surface is a graph over each slave plane), which converges to the analytic
//     area as h^2;
//   - grazing masters (edge-on, nearly edge-on, crossing), masters touching along an edge or at
//     a vertex, degenerate slaves: no NaN, no sliver, nothing where geometry says nothing;
//   - a rigid motion of both surfaces leaves every overlap unchanged (1e-12 relative).
// And the 2D counterpart (segments) on a non-matching arc.

#include "solver/contact/mortar/MortarFacePairing.hpp"
#include "solver/contact/mortar/MortarSegmentPairing.hpp"
#include "solver/contact/tests/PairingSurfaces.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

namespace stella::mortar {
namespace {

using contact::testing::surfaceGrid;
using contact::testing::SurfaceMap;

constexpr CellType kFaceTypes[] = {CellType::TRIA3, CellType::TRIA6, CellType::QUAD4, CellType::QUAD8,
                                   CellType::QUAD9};

// The faces of an nu x nv grid of `type` over [0, 1]^2 mapped by f; `flip` reverses the
// orientation (the parameters swapped).
std::vector<Face> surface(CellType type, int nu, int nv, const SurfaceMap& f, bool flip = false) {
  Mesh mesh;
  mesh.setDimension(3);
  const SurfaceMap g = flip ? SurfaceMap([&](double u, double v) { return f(v, u); }) : f;
  const auto cells = surfaceGrid(mesh, type, flip ? nv : nu, flip ? nu : nv, g);
  return meshFaces(mesh, cells, [&](NodeId n) { return mesh.point(n); });
}

// Area of a flat face's linear hull (its vertices' polygon).
double hullArea(const Face& f) {
  const int nv = f.type == CellType::TRIA3 || f.type == CellType::TRIA6 || f.type == CellType::TRIA7 ? 3 : 4;
  Point3 n{0, 0, 0};
  for (int i = 1; i + 1 < nv; ++i) {
    n = n + cross(f.nodes[static_cast<std::size_t>(i)] - f.nodes[0],
                  f.nodes[static_cast<std::size_t>(i + 1)] - f.nodes[0]);
  }
  return 0.5 * norm(n);
}

// A plane map of [0, 1]^2 onto itself moving the interior (the boundary stays straight), at
// height z.
SurfaceMap distortedSquare(double a, double z, double lo = 0.0, double hi = 1.0) {
  return [=](double u, double v) {
    const double s = std::sin(M_PI * u) * std::sin(M_PI * v);
    const double x = u + a * s * std::cos(3 * v);
    const double y = v + a * s * std::sin(2 * u);
    return Point3{lo + (hi - lo) * x, lo + (hi - lo) * y, z};
  };
}

SurfaceMap wavy(double lo, double hi, double z) {
  return [=](double u, double v) {
    const double x = lo + (hi - lo) * u;
    const double y = lo + (hi - lo) * v;
    return Point3{x, y, z + 0.04 * std::sin(5 * x) * std::cos(4 * y)};
  };
}

TEST(MortarFacePairing, FlatSurfaceFullyCoveredAddsUpToEverySlaveArea) {
  for (const CellType st : kFaceTypes) {
    for (const CellType mt : kFaceTypes) {
      for (const bool facing : {true, false}) {
        const auto slaves = surface(st, 7, 6, distortedSquare(0.08, 0.0));
        // Non-matching, overhanging by 0.1, 1e-3 above; facing: normal -z (towards the slave).
        const auto masters = surface(mt, 5, 9, distortedSquare(-0.05, 1e-3, -0.1, 1.1), facing);
        const FacePairing p = pairFaces(slaves, masters);
        ASSERT_EQ(p.slaveCount(), slaves.size());
        double total = 0;
        for (std::size_t s = 0; s < slaves.size(); ++s) {
          const double a = hullArea(slaves[s]);
          EXPECT_NEAR(p.coveredArea(s), a, 1e-12 * a) << name(st) << " on " << name(mt) << " slave " << s;
          total += p.coveredArea(s);
          for (const auto& o : p.of(s)) {
            double w = 0;
            for (const auto& q : p.pointsOf(o)) {
              w += q.weight;
            }
            EXPECT_NEAR(w, o.area, 1e-13 * a);
            EXPECT_GE(p.polygonOf(o).size(), 3u);
          }
        }
        EXPECT_NEAR(total, 1.0, 1e-12) << name(st) << " on " << name(mt);
        EXPECT_EQ(p.degenerateSlaves, 0u);
        EXPECT_EQ(p.unpairedSlaves, 0u);
      }
    }
  }
}

TEST(MortarFacePairing, AgreesWithAllPairsClippingOnWarpedSurfaces) {
  for (const CellType st : {CellType::QUAD4, CellType::TRIA6, CellType::QUAD8}) {
    const auto slaves = surface(st, 13, 11, wavy(0.0, 1.0, 0.0));
    const auto masters = surface(CellType::QUAD4, 9, 10, wavy(-0.05, 1.05, 2e-3), true);
    const FacePairing p = pairFaces(slaves, masters);
    std::vector<int> every(masters.size());
    std::iota(every.begin(), every.end(), 0);
    std::size_t overlaps = 0;
    for (std::size_t s = 0; s < slaves.size(); ++s) {
      const auto brute = intersectFaces(slaves[s], masters, every);
      const auto got = p.of(s);
      ASSERT_EQ(got.size(), brute.size()) << "slave " << s;
      for (std::size_t k = 0; k < brute.size(); ++k) {
        EXPECT_EQ(got[k].master, brute[k].master);
        EXPECT_EQ(got[k].area, brute[k].area); // the same kernel on the same pair
        EXPECT_EQ(got[k].pointCount, brute[k].points.size());
      }
      overlaps += brute.size();
    }
    EXPECT_GT(overlaps, 2 * slaves.size()); // non-matching: most slaves see several masters
    EXPECT_LT(p.candidatePairs, masters.size() * slaves.size() / 10); // and the search prunes
  }
}

TEST(MortarFacePairing, ExhaustiveSearchAndTwoThreadsGiveTheSameResult) {
  const auto slaves = surface(CellType::TRIA3, 48, 48, wavy(0.0, 1.0, 0.0)); // 4608 faces: 2 chunks
  const auto masters = surface(CellType::QUAD4, 31, 29, wavy(-0.05, 1.05, 1e-3), true);
  const FacePairing one = pairFaces(slaves, masters);
  FacePairingOptions o;
  o.threads = 2;
  const FacePairing two = pairFaces(slaves, masters, o);
  FacePairingOptions e;
  e.exhaustive = true;
  const FacePairing all = pairFaces(slaves, masters, e);
  for (const FacePairing* q : {&two, &all}) {
    ASSERT_EQ(q->offsets, one.offsets);
    ASSERT_EQ(q->overlaps.size(), one.overlaps.size());
    for (std::size_t k = 0; k < one.overlaps.size(); ++k) {
      EXPECT_EQ(q->overlaps[k].master, one.overlaps[k].master);
      EXPECT_EQ(q->overlaps[k].area, one.overlaps[k].area);
      EXPECT_EQ(q->overlaps[k].firstPoint, one.overlaps[k].firstPoint);
    }
    EXPECT_EQ(q->points.size(), one.points.size());
  }
  EXPECT_EQ(two.candidatePairs, one.candidatePairs);
}

// A quarter of a cylinder of radius r, axis y, length 1, normal outwards (flip: inwards).
SurfaceMap cylinder(double r, double t0, double t1) {
  return [=](double u, double v) {
    const double t = t0 + (t1 - t0) * u;
    return Point3{r * std::cos(t), v, r * std::sin(t)};
  };
}

TEST(MortarFacePairing, CylinderOverlapsAddUpToTheFacetsAndConvergeToTheAnalyticArea) {
  const double exact = 0.5 * M_PI; // quarter cylinder of radius 1, length 1
  for (const CellType st : {CellType::QUAD4, CellType::TRIA3, CellType::QUAD8}) {
    double previous = 0;
    for (const int n : {8, 16, 32}) {
      const auto slaves = surface(st, n, 4, cylinder(1.0, 0.0, 0.5 * M_PI));
      // The outer body's inner surface, 1e-3 away, overhanging, non-matching, facing inwards.
      const auto masters = surface(
          CellType::TRIA3, 3 * n / 2 + 1, 5,
          [](double u, double v) { return cylinder(1.001, -0.1, 0.5 * M_PI + 0.1)(u, -0.1 + 1.2 * v); },
          true);
      const FacePairing p = pairFaces(slaves, masters);
      double total = 0;
      double facets = 0;
      for (std::size_t s = 0; s < slaves.size(); ++s) {
        total += p.coveredArea(s);
        facets += hullArea(slaves[s]);
      }
      EXPECT_NEAR(total, facets, 1e-12 * facets) << name(st) << " n = " << n;
      const double error = std::abs(total - exact) / exact;
      // The facets' area: n chords 2 sin(pi / 4n) per unit length.
      EXPECT_NEAR(facets, 2 * n * std::sin(M_PI / (4 * n)), 1e-12);
      const double x = M_PI / (4 * n);
      EXPECT_LT(error, x * x / 6) << n; // 1 - sin(x)/x < x^2/6
      if (previous > 0) {
        EXPECT_NEAR(previous / error, 4.0, 0.05); // second order
      }
      previous = error;
    }
  }
}

TEST(MortarFacePairing, GrazingTouchingAndDegenerateFacesGiveNoNanAndNoSliver) {
  const auto slaves = surface(CellType::QUAD4, 4, 4, distortedSquare(0.0, 0.0)); // h = 0.25
  std::vector<Face> masters;
  const auto add = [&](const std::vector<Face>& f) { masters.insert(masters.end(), f.begin(), f.end()); };
  // Edge-on walls through the slave surface, at 1e-9 and 1e-3 rad from vertical.
  for (const double tilt : {0.0, 1e-9, 1e-3}) {
    add(surface(CellType::QUAD4, 3, 2, [=](double u, double v) {
      return Point3{0.37 + 0.2 * v * std::sin(tilt), u, -0.1 + 0.2 * v * std::cos(tilt)};
    }));
  }
  // Coplanar neighbours sharing an edge (x = 1) or only the corner (1, 1).
  add(surface(
      CellType::TRIA3, 2, 3,
      [](double u, double v) {
        return Point3{1 + u, v, 0};
      },
      true));
  add(surface(
      CellType::QUAD4, 2, 2,
      [](double u, double v) {
        return Point3{1 + u, 1 + v, 0};
      },
      true));
  const FacePairing p = pairFaces(slaves, masters);
  std::size_t overlaps = 0;
  for (std::size_t s = 0; s < slaves.size(); ++s) {
    for (const auto& o : p.of(s)) {
      ++overlaps;
      EXPECT_TRUE(std::isfinite(o.area));
      for (const auto& q : p.pointsOf(o)) {
        EXPECT_TRUE(std::isfinite(q.weight) && std::isfinite(q.slave[0]) && std::isfinite(q.master[1]));
      }
    }
  }
  // Only the wall tilted by 1e-3 (cosine 1e-3 > 1e-8) is seen, as its shadow: 0.2 sin(1e-3) wide.
  double shadow = 0;
  for (std::size_t s = 0; s < slaves.size(); ++s) {
    for (const auto& o : p.of(s)) {
      EXPECT_GE(o.master, 12);
      EXPECT_LT(o.master, 18);
      EXPECT_GT(o.area, 1e-12 * 0.25 * 0.25); // no sliver below the clipping tolerance
      shadow += o.area;
    }
  }
  EXPECT_NEAR(shadow, 0.2 * std::sin(1e-3) * 1.0, 1e-12);
  EXPECT_GT(overlaps, 0u);
  // A degenerate slave (three aligned nodes) next to real ones: no overlap, counted.
  std::vector<Face> bad = slaves;
  bad.push_back({CellType::TRIA3, {{0.1, 0.1, 0}, {0.2, 0.2, 0}, {0.3, 0.3, 0}}});
  const auto flat = surface(CellType::QUAD4, 3, 3, distortedSquare(0.0, 0.0), true);
  const FacePairing d = pairFaces(bad, flat);
  EXPECT_EQ(d.degenerateSlaves, 1u);
  EXPECT_EQ(d.unpairedSlaves, 1u);
  EXPECT_TRUE(d.of(bad.size() - 1).empty());
  EXPECT_NEAR(d.coveredArea(0), hullArea(bad[0]), 1e-15);
}

TEST(MortarFacePairing, NearlyParallelMastersCrossingTheSlavePlaneCoverIt) {
  // Master planes tilted by 1e-9 to 1e-3 rad about a line of the slave plane, crossing it at
  // x = 0.43, facing either way: each is a graph over the slave plane, so every slave face is
  // covered exactly once.
  for (const double tilt : {1e-9, 1e-6, 1e-3}) {
    for (const bool facing : {true, false}) {
      const auto slaves = surface(CellType::QUAD8, 6, 5, distortedSquare(0.1, 0.0));
      const auto masters = surface(
          CellType::TRIA3, 8, 7,
          [=](double u, double v) {
            const Point3 p = distortedSquare(-0.07, 0.0, -0.1, 1.1)(u, v);
            return Point3{0.43 + (p[0] - 0.43) * std::cos(tilt), p[1], (p[0] - 0.43) * std::sin(tilt)};
          },
          facing);
      const FacePairing p = pairFaces(slaves, masters);
      EXPECT_EQ(p.unpairedSlaves, 0u);
      for (std::size_t s = 0; s < slaves.size(); ++s) {
        EXPECT_NEAR(p.coveredArea(s), hullArea(slaves[s]), 1e-12 * hullArea(slaves[s])) << tilt;
      }
    }
  }
}

TEST(MortarFacePairing, MastersBeyondTheSearchMarginAreNotCandidates) {
  // Slave faces 0.1 wide (margin 0.025 by default), masters 0.04 above: none found, all counted
  // unpaired; with an absolute margin of 0.05, every slave face covered.
  const auto slaves = surface(CellType::QUAD4, 10, 10, distortedSquare(0.0, 0.0));
  const auto masters = surface(CellType::TRIA3, 7, 7, distortedSquare(0.0, 0.04, -0.1, 1.1), true);
  const FacePairing near = pairFaces(slaves, masters);
  EXPECT_EQ(near.overlaps.size(), 0u);
  EXPECT_EQ(near.unpairedSlaves, slaves.size());
  FacePairingOptions o;
  o.margin.absolute = 0.05;
  const FacePairing far = pairFaces(slaves, masters, o);
  EXPECT_EQ(far.unpairedSlaves, 0u);
  for (std::size_t s = 0; s < slaves.size(); ++s) {
    EXPECT_NEAR(far.coveredArea(s), 0.01, 1e-14);
  }
}

Point3 rigid(const Point3& p) { // rotation of 0.9 rad about (1, 2, 3), then a translation
  const Point3 k = (1.0 / std::sqrt(14.0)) * Point3{1, 2, 3};
  const double c = std::cos(0.9);
  const double s = std::sin(0.9);
  return c * p + s * cross(k, p) + (1 - c) * dot(k, p) * k + Point3{10, -3, 5};
}

TEST(MortarFacePairing, RigidMotionLeavesEveryOverlapUnchanged) {
  for (const CellType st : {CellType::QUAD4, CellType::TRIA6}) {
    auto slaves = surface(st, 9, 8, wavy(0.0, 1.0, 0.0));
    auto masters = surface(CellType::QUAD8, 7, 6, wavy(-0.05, 1.05, 1e-3), true);
    const FacePairing p = pairFaces(slaves, masters);
    for (auto* faces : {&slaves, &masters}) {
      for (auto& f : *faces) {
        for (auto& x : f.nodes) {
          x = rigid(x);
        }
      }
    }
    const FacePairing q = pairFaces(slaves, masters);
    ASSERT_EQ(q.offsets, p.offsets);
    for (std::size_t k = 0; k < p.overlaps.size(); ++k) {
      EXPECT_EQ(q.overlaps[k].master, p.overlaps[k].master);
      // Relative to the slave face's area (a corner overlap may be tiny).
      EXPECT_NEAR(q.overlaps[k].area, p.overlaps[k].area, 1e-12 * hullArea(slaves[0]));
    }
  }
}

// The point of a face's linear hull at parametric coordinates c (TRIA3 on (0,0),(1,0),(0,1);
// QUAD4 on [-1,1]^2).
Point3 hullPoint(const Face& f, const std::array<double, 2>& c) {
  const bool tri = f.type == CellType::TRIA3 || f.type == CellType::TRIA6;
  const double n3[3] = {1 - c[0] - c[1], c[0], c[1]};
  const double n4[4] = {0.25 * (1 - c[0]) * (1 - c[1]), 0.25 * (1 + c[0]) * (1 - c[1]),
                        0.25 * (1 + c[0]) * (1 + c[1]), 0.25 * (1 - c[0]) * (1 + c[1])};
  Point3 x{0, 0, 0};
  for (std::size_t i = 0; i < (tri ? 3u : 4u); ++i) {
    x = x + (tri ? n3[i] : n4[i]) * f.nodes[i];
  }
  return x;
}

TEST(MortarFacePairing, IntegrationPointsLieOnBothHullsOnSmallWarpedFacesFarFromTheOrigin) {
  // Faces 1e-3 wide at 100 from the origin (a coordinate's ulp is 1.4e-14): every integration
  // point's slave and master hull points lie on the slave normal through it within 1e-13 (7
  // ulps). Checked to fail with the slave normal summed from absolute positions (1e-6 off there:
  // points several 1e-12 off their line) and with a Newton on the hulls stopped at a step of
  // 1e-2 (1e-9 off: the faces are trapezoids, their bilinear map is not affine).
  const auto far = [](double z, double amplitude, double lo, double hi) {
    return [=](double u, double v) {
      const double x = lo + (hi - lo) * u;
      const double y = lo + (hi - lo) * v;
      // Trapezoids (a bilinear, not affine, map in the plane) warped out of it.
      return Point3{100 + 1e-2 * (x + 0.6 * x * y), -60 + 1e-2 * (y - 0.5 * x * y),
                    30 + z + amplitude * std::sin(900 * x) * std::cos(700 * y)};
    };
  };
  for (const CellType st : {CellType::QUAD4, CellType::TRIA3}) {
    for (const CellType mt : {CellType::QUAD4, CellType::TRIA3}) {
      const auto slaves = surface(st, 9, 8, far(0, 2e-5, 0, 1));
      const auto masters = surface(mt, 7, 6, far(1e-5, 3e-5, -0.05, 1.05), true);
      const FacePairing p = pairFaces(slaves, masters);
      std::size_t checked = 0;
      for (std::size_t s = 0; s < slaves.size(); ++s) {
        // The slave plane's normal (the Newell normal of the slave's vertices).
        const Face& f = slaves[s];
        const std::size_t nv = st == CellType::TRIA3 ? 3 : 4;
        Point3 n{0, 0, 0};
        for (std::size_t i = 0; i < nv; ++i) {
          n = n + cross(f.nodes[i] - f.nodes[0], f.nodes[(i + 1) % nv] - f.nodes[0]);
        }
        const Point3 u = (1.0 / norm(n)) * n;
        for (const auto& o : p.of(s)) {
          for (const auto& q : p.pointsOf(o)) {
            const Point3 xs = hullPoint(slaves[s], q.slave);
            const Point3 xm = hullPoint(masters[static_cast<std::size_t>(o.master)], q.master);
            for (const Point3& y : {xs, xm}) {
              const Point3 d = y - q.x;
              EXPECT_LT(norm(d - dot(d, u) * u), 1e-13); // on the normal line through x
            }
            ++checked;
          }
        }
      }
      EXPECT_GT(checked, 100u);
    }
  }
}

TEST(MortarSegmentPairing, NonMatchingArcsTileTheSlaveAndAgreeWithAllPairs) {
  const auto arc = [](double r, double a, double b, int n, CellType t) {
    std::vector<Segment> out;
    for (int i = 0; i < n; ++i) {
      const double t0 = a + (b - a) * i / n;
      const double t1 = a + (b - a) * (i + 1) / n;
      const double tm = 0.5 * (t0 + t1);
      Segment s{t, {{r * std::cos(t0), r * std::sin(t0)}, {r * std::cos(t1), r * std::sin(t1)}}};
      if (t == CellType::SEG3) {
        s.nodes.push_back({r * std::cos(tm), r * std::sin(tm)});
      }
      out.push_back(s);
    }
    return out;
  };
  for (const CellType t : {CellType::SEG2, CellType::SEG3}) {
    const auto slaves = arc(1.0, 0.3, 1.2, 17, t);
    const auto masters = arc(1.002, 1.3, 0.2, 23, CellType::SEG2); // reversed: facing the slave
    const SegmentPairing p = pairSegments(slaves, masters);
    std::vector<int> every(masters.size());
    std::iota(every.begin(), every.end(), 0);
    for (std::size_t s = 0; s < slaves.size(); ++s) {
      const auto brute = intersectSegments(slaves[s], masters, every);
      const auto got = p.of(s);
      ASSERT_EQ(got.size(), brute.size());
      double par = 0;
      for (std::size_t k = 0; k < got.size(); ++k) {
        EXPECT_EQ(got[k].master, brute[k].master);
        EXPECT_EQ(got[k].length, brute[k].length);
        par += got[k].xiMax - got[k].xiMin;
      }
      EXPECT_NEAR(par, 2.0, 1e-12); // the masters tile the slave's parameter
    }
    EXPECT_LT(p.candidatePairs, slaves.size() * masters.size() / 3);
  }
}

} // namespace
} // namespace stella::mortar
