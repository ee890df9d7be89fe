// Mortar pairing of LAC in 2D (contact/lac/LacPairing): the paired lengths and integrated gaps of
// patches over non-matching master segments against hand values, the gradient against central
// differences, TYPE_APPA='RAPIDE' (R-tree candidates) against 'ROBUSTE' (every master cell).

#include "solver/contact/lac/LacPairing.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace stella::contact::lac {
namespace {

// Slave: NS SEG2 cells on y = 0 from x = 0 to 1, grouped in patches of `perPatch` cells, normal
// (ty, -tx) = (0, -1) pointing down (sign +1). Master: NM SEG2 cells on y = y0 (+ a tilt t x) from
// x = a to b, oriented right to left (normal up).
struct Interface {
  std::shared_ptr<Mesh> mesh = std::make_shared<Mesh>();
  std::shared_ptr<Model> model;
  std::unique_ptr<DofMap> dofs;
  LacZoneCells zone;

  Interface(int ns, int perPatch, int nm, double a, double b, double y0, double tilt = 0.0,
            double wave = 0.0) {
    mesh->setDimension(2);
    std::vector<NodeId> s;
    for (int i = 0; i <= ns; ++i) {
      const double x = static_cast<double>(i) / ns;
      s.push_back(mesh->addNode({x, wave * std::sin(3.0 * x), 0.0}));
    }
    std::vector<Mesh::LacPatch> patches;
    for (int i = 0; i < ns; ++i) {
      const std::array<NodeId, 2> n{s[static_cast<std::size_t>(i)], s[static_cast<std::size_t>(i + 1)]};
      const CellId c = mesh->addCell(CellType::SEG2, n);
      if (i % perPatch == 0) {
        patches.push_back({"ESCL", {}});
      }
      patches.back().cells.push_back(c);
      zone.slaves.push_back({c, static_cast<int>(patches.size()) - 1, 1.0});
    }
    mesh->setLacPatches(patches);
    std::vector<NodeId> m;
    for (int j = 0; j <= nm; ++j) {
      const double x = b - (b - a) * j / nm;
      m.push_back(mesh->addNode({x, y0 + tilt * x, 0.0}));
    }
    for (int j = 0; j < nm; ++j) {
      const std::array<NodeId, 2> n{m[static_cast<std::size_t>(j)], m[static_cast<std::size_t>(j + 1)]};
      zone.masters.push_back(mesh->addCell(CellType::SEG2, n));
    }
    zone.zone = 0;
    model = std::make_shared<Model>(mesh);
    model->components = 2;
    model->activeNodes.assign(static_cast<std::size_t>(mesh->nodeCount()), true);
    dofs = std::make_unique<DofMap>(*model);
  }

  std::vector<LacPatchRow> pair(const std::vector<double>& u) const {
    return pairLacPatches(*mesh, {zone}, u, *dofs, {});
  }
  std::vector<double> zero() const {
    return std::vector<double>(static_cast<std::size_t>(mesh->nodeCount()) * 3, 0.0);
  }
};

TEST(LacPairing, FullyCoveredPatchesOfANonMatchingFlatMaster) {
  const Interface f(6, 2, 5, -0.2, 1.3, -0.1); // master below, 5 cells of 0.3
  const auto rows = f.pair(f.zero());
  ASSERT_EQ(rows.size(), 3u);
  for (const auto& r : rows) {
    EXPECT_NEAR(r.length, 1.0 / 3, 1e-14);
    EXPECT_NEAR(r.pairedLength, 1.0 / 3, 1e-14);
    EXPECT_NEAR(r.integratedGap / r.pairedLength, 0.1, 1e-14); // open by 0.1 along the slave normal
    // dG/du: -w N_s n_s on the slave DOFs (n_s = (0, -1): +w N_s on DY), +w N_m n_s on the master's
    double slaveDy = 0.0;
    double masterDy = 0.0;
    for (const auto& [e, v] : r.gradient) {
      const NodeId n = f.dofs->node(e);
      if (f.dofs->component(e) == 1) {
        (n <= 6 ? slaveDy : masterDy) += v;
      } else {
        EXPECT_NEAR(v, 0.0, 1e-15);
      }
    }
    EXPECT_NEAR(slaveDy, 1.0 / 3, 1e-14);
    EXPECT_NEAR(masterDy, -1.0 / 3, 1e-14);
  }
}

TEST(LacPairing, PartlyCoveredPatchHasItsPairedLength) {
  const Interface f(6, 3, 3, 0.25, 1.75, -0.05); // the master starts at x = 0.25
  const auto rows = f.pair(f.zero());
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_NEAR(rows[0].length, 0.5, 1e-14);
  EXPECT_NEAR(rows[0].pairedLength, 0.25, 1e-14); // COEFSURF 0.5
  EXPECT_NEAR(rows[1].pairedLength, 0.5, 1e-14);
  EXPECT_NEAR(rows[0].integratedGap, 0.25 * 0.05, 1e-15);
}

TEST(LacPairing, IntegratedGapOfATiltedMasterIsExact) {
  // master y = -0.1 + 0.2 x under the whole slave: the gap along (0, -1) is 0.1 - 0.2 x
  const Interface f(4, 2, 3, -0.1, 1.2, -0.1, 0.2);
  const auto rows = f.pair(f.zero());
  ASSERT_EQ(rows.size(), 2u);
  // integral of (0.1 - 0.2 x) over [0, 0.5] and [0.5, 1]
  EXPECT_NEAR(rows[0].integratedGap, 0.05 - 0.1 * 0.25, 1e-14);
  EXPECT_NEAR(rows[1].integratedGap, 0.05 - 0.1 * 0.75, 1e-14);
}

TEST(LacPairing, GradientEqualsCentralDifferencesForNormalMotions) {
  // parallel surfaces, fully covered: normal motions move the gap linearly at first order
  const Interface f(6, 2, 5, -0.2, 1.3, -0.1);
  const auto u0 = f.zero();
  const auto rows = f.pair(u0);
  const double h = 1e-6;
  for (NodeId n = 0; n < f.mesh->nodeCount(); ++n) {
    auto up = u0;
    auto down = u0;
    up[static_cast<std::size_t>(n) * 3 + 1] += h;
    down[static_cast<std::size_t>(n) * 3 + 1] -= h;
    const auto rp = f.pair(up);
    const auto rm = f.pair(down);
    const int e = f.dofs->dof(n, 1);
    for (std::size_t p = 0; p < rows.size(); ++p) {
      double analytic = 0.0;
      for (const auto& [k, v] : rows[p].gradient) {
        analytic += k == e ? v : 0.0;
      }
      const double numeric = (rp[p].integratedGap - rm[p].integratedGap) / (2 * h);
      EXPECT_NEAR(analytic, numeric, 1e-8) << "node " << n << " patch " << p;
    }
  }
}

TEST(LacPairing, RapideEqualsRobuste) {
  Interface f(17, 3, 11, -0.3, 1.4, -0.02, 0.03, 0.01); // wavy slave, tilted master
  const auto fast = f.pair(f.zero());
  f.zone.bruteForce = true;
  const auto all = f.pair(f.zero());
  ASSERT_EQ(fast.size(), all.size());
  for (std::size_t p = 0; p < fast.size(); ++p) {
    EXPECT_GT(fast[p].pairedLength, 0.0);
    EXPECT_DOUBLE_EQ(fast[p].pairedLength, all[p].pairedLength) << p;
    EXPECT_DOUBLE_EQ(fast[p].integratedGap, all[p].integratedGap) << p;
    EXPECT_EQ(fast[p].gradient, all[p].gradient) << p;
  }
}

// The search margin (lacMargin): with no displacement, a master is a candidate across a gap up to one
// slave cell size (h = 0.25 here), not only the 0.25 h of mortar::SearchMargin's default; beyond it
// RAPIDE leaves the patches unpaired while ROBUSTE (every master, no distance limit) still pairs them.
TEST(LacPairing, RapideFindsMastersAcrossAGapUpToTheSlaveCellSize) {
  Interface within(4, 1, 3, -0.1, 1.1, -0.24); // gap 0.24 < h = 0.25
  const auto fast = within.pair(within.zero());
  within.zone.bruteForce = true;
  const auto all = within.pair(within.zero());
  for (std::size_t p = 0; p < fast.size(); ++p) {
    EXPECT_NEAR(fast[p].pairedLength, 0.25, 1e-14) << p;
    EXPECT_NEAR(fast[p].integratedGap / fast[p].pairedLength, 0.24, 1e-14) << p;
    EXPECT_DOUBLE_EQ(fast[p].integratedGap, all[p].integratedGap) << p;
  }
  Interface beyond(4, 1, 3, -0.1, 1.1, -0.26); // gap 0.26 > h
  const auto far = beyond.pair(beyond.zero());
  beyond.zone.bruteForce = true;
  const auto farAll = beyond.pair(beyond.zero());
  for (std::size_t p = 0; p < far.size(); ++p) {
    EXPECT_EQ(far[p].pairedLength, 0.0) << p;
    EXPECT_NEAR(farAll[p].pairedLength, 0.25, 1e-14) << p;
  }
}

// A slave driven 0.5 (two cell sizes) into the master body by its displacement is still paired: the
// margin adds twice the zone's largest displacement (a first Newton iterate into the other body).
TEST(LacPairing, RapideFindsADeeplyInterpenetratedSlave) {
  const Interface f(4, 1, 3, -0.1, 1.1, -0.1); // master 0.1 below the slave
  auto u = f.zero();
  for (NodeId n = 0; n <= 4; ++n) {
    u[static_cast<std::size_t>(n) * 3 + 1] = -0.6; // slave moved to y = -0.6: 0.5 inside
  }
  const auto rows = f.pair(u);
  for (const auto& r : rows) {
    EXPECT_NEAR(r.pairedLength, 0.25, 1e-14);
    EXPECT_NEAR(r.integratedGap / r.pairedLength, -0.5, 1e-14);
  }
}

// The reference tangent of a 3D patch (friction: tau_1, then tau_2 = tau_1 x n): unit, orthogonal to
// the normal, the least aligned axis made orthogonal (x first among equals): x on the faces
// z = const, so that (LAGS_F1, LAGS_F2) are along (x, y) under a body (n = -z).
TEST(LacPairing, PatchTangentIsTheLeastAlignedAxisMadeOrthogonal) {
  const auto near = [](const Point3& a, const Point3& b) {
    return std::fabs(a[0] - b[0]) < 1e-15 && std::fabs(a[1] - b[1]) < 1e-15 && std::fabs(a[2] - b[2]) < 1e-15;
  };
  EXPECT_TRUE(near(patchTangent({0, 0, -1}), {1, 0, 0}));
  EXPECT_TRUE(near(patchTangent({0, 0, 1}), {1, 0, 0}));
  EXPECT_TRUE(near(patchTangent({1, 0, 0}), {0, 1, 0}));
  const Point3 n{0, 0, -1};
  EXPECT_TRUE(near(cross(patchTangent(n), n), {0, 1, 0})); // tau_2 = y under a body
  const double k = 1.0 / std::sqrt(3.0);
  for (const Point3& m : {Point3{k, k, k}, Point3{0.6, -0.8, 0.0}, Point3{0.1, 0.2, std::sqrt(0.95)}}) {
    const Point3 t = patchTangent(m);
    EXPECT_NEAR(dot(t, t), 1.0, 1e-15);
    EXPECT_NEAR(dot(t, m), 0.0, 1e-15);
  }
  EXPECT_GT(patchTangent({0.6, -0.8, 0.0})[2], 0.99); // z, the axis the normal lies across
}

// LISSAGE='OUI': on an arc of a circle cut into uniform SEG2 or SEG3 cells (counterclockwise, so the
// normal (ty, -tx) points out of the circle), the averaged normal at every node shared by two cells is
// the circle's normal (the two cells are mirror images about the node's radius), at an end node the
// one cell's normal, at a SEG3's middle node its normal there; and smoothing a flat slave changes
// nothing (the closing-gap study with LISSAGE, LacContact.ClosingGapWithSmoothedNormals).
TEST(LacPairing, AveragedNormalsOfAFacetedCircleAreTheCircles) {
  for (const CellType type : {CellType::SEG2, CellType::SEG3}) {
    Mesh mesh;
    mesh.setDimension(2);
    LacZoneCells zone;
    zone.smoothing = true;
    const int cells = 7;
    const double step = 0.15;
    const auto at = [&](double angle) {
      return mesh.addNode({2.0 * std::cos(angle), 2.0 * std::sin(angle), 0.0});
    };
    std::vector<NodeId> ends;
    for (int i = 0; i <= cells; ++i) {
      ends.push_back(at(0.3 + step * i));
    }
    std::vector<Mesh::LacPatch> patches;
    for (int i = 0; i < cells; ++i) {
      std::vector<NodeId> n{ends[static_cast<std::size_t>(i)], ends[static_cast<std::size_t>(i + 1)]};
      if (type == CellType::SEG3) {
        n.push_back(at(0.3 + step * (i + 0.5)));
      }
      const CellId c = mesh.addCell(type, n);
      patches.push_back({"ESCL", {c}});
      zone.slaves.push_back({c, i, 1.0});
    }
    mesh.setLacPatches(patches);
    const std::vector<double> u(static_cast<std::size_t>(mesh.nodeCount()) * 3, 0.0);
    const auto normals = averagedNormals(mesh, zone, u);
    ASSERT_EQ(normals.size(), static_cast<std::size_t>(mesh.nodeCount()));
    for (int i = 1; i < cells; ++i) {
      const double angle = 0.3 + step * i;
      const auto& n = normals.at(ends[static_cast<std::size_t>(i)]);
      EXPECT_NEAR(n[0], std::cos(angle), 1e-14) << name(type) << " node " << i;
      EXPECT_NEAR(n[1], std::sin(angle), 1e-14) << name(type) << " node " << i;
    }
    // an end node: the cell's own normal, tilted from the circle's by half a cell (SEG2)
    const auto& first = normals.at(ends.front());
    const double tilt = std::atan2(first[1], first[0]) - 0.3;
    if (type == CellType::SEG2) {
      EXPECT_NEAR(tilt, step / 2, 1e-14);
    } else {
      EXPECT_GT(std::fabs(tilt), 1e-6); // the parabola's end tangent is close to, not on, the circle's
    }
  }
}

} // namespace
} // namespace stella::contact::lac
