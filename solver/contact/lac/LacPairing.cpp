// Mortar pairing of LAC contact in 2D (see LacPairing.hpp).

#include "solver/contact/lac/LacPairing.hpp"

#include "solver/contact/lac/LacOverlapTerms.hpp"
#include "solver/contact/lac/LacSmoothing.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace stella::contact::lac {

namespace {

using mortar::Point2;
using mortar::Segment;
// the duals of an overlap without LISSAGE (its 12 coordinates) and with it (LacDual: the neighbours too)
using OverlapDual = mortar::ForwardDual<kOverlapCoordinates>;

Segment segmentOf(const Mesh& mesh, CellId c, const std::vector<double>* u) {
  Segment s;
  s.type = mesh.cellType(c);
  for (NodeId n : mesh.cellNodes(c)) {
    const Point3 x = mesh.point(n);
    const auto i = static_cast<std::size_t>(n) * 3;
    s.nodes.push_back(u == nullptr ? Point2{x[0], x[1]} : Point2{x[0] + (*u)[i], x[1] + (*u)[i + 1]});
  }
  return s;
}

double norm2(const Point2& a) {
  return std::sqrt(a[0] * a[0] + a[1] * a[1]);
}

// |dx/dxi| (x r in AXIS) of `s` at xi.
double measure(const Segment& s, double xi, bool axisymmetric) {
  const double j = norm2(mortar::segmentTangent(s, xi));
  return axisymmetric ? j * mortar::segmentPoint(s, xi)[0] : j;
}

// The box of the search (mortar::slaveBox: the segment in the plane z = 0) inflated by `margin`.
Box3 boxOf(const Segment& s, const mortar::SearchMargin& margin) {
  std::array<Point3, 3> p{};
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    p[i] = {s.nodes[i][0], s.nodes[i][1], 0.0};
  }
  return mortar::slaveBox(s.type, p.data(), static_cast<int>(s.nodes.size()), margin);
}

// The equations of the local coordinates of an overlap (LacOverlapTerms.hpp's layout: the slave's,
// the master's, then LISSAGE's neighbour nodes), -1 where none (a SEG2's third node, a component
// without an equation).
using LocalEquations = std::array<int, kDerivativeCoordinates>;
LocalEquations localEquations(const DofMap& dofs, std::span<const NodeId> slave,
                              std::span<const NodeId> master, std::span<const NodeId> neighbours) {
  LocalEquations e{};
  e.fill(-1);
  for (std::size_t c = 0; c < 2; ++c) {
    for (std::size_t i = 0; i < slave.size(); ++i) {
      e[2 * i + c] = dofs.dof(slave[i], static_cast<int>(c));
    }
    for (std::size_t j = 0; j < master.size(); ++j) {
      e[6 + 2 * j + c] = dofs.dof(master[j], static_cast<int>(c));
    }
    for (std::size_t j = 0; j < neighbours.size(); ++j) {
      e[kOverlapCoordinates + 2 * j + c] = dofs.dof(neighbours[j], static_cast<int>(c));
    }
  }
  return e;
}

template <class Dual> std::vector<mortar::kernel::Vec2<Dual>> seeded(const Segment& s, int first) {
  std::vector<mortar::kernel::Vec2<Dual>> out;
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    const int k = first + 2 * static_cast<int>(i);
    out.push_back({Dual::variable(s.nodes[i][0], k), Dual::variable(s.nodes[i][1], k + 1)});
  }
  return out;
}

// The sums of one patch's exact derivatives (LacPatchRow::gapDerivative...).
// (the gradient's derivative as entries: their sum is left to the assembly of the tangent)
struct DerivativeSums {
  std::map<int, double> gap;
  std::map<int, double> length;
  std::vector<LacPatchRow::Entry> gradient;
};

template <class Dual>
void addDerivatives(const OverlapTerms<Dual>& t, const LocalEquations& eq, DerivativeSums& sums) {
  for (std::size_t l = 0; l < t.gap.d.size(); ++l) {
    if (eq[l] < 0) {
      continue;
    }
    sums.gap[eq[l]] += t.gap.d[l];
    sums.length[eq[l]] += t.length.d[l];
    for (std::size_t i = 0; i < t.normal.size(); ++i) {
      if (eq[i] >= 0 && t.normal[i].d[l] != 0.0) {
        sums.gradient.push_back({eq[i], eq[l], t.normal[i].d[l]});
      }
    }
  }
}

// The derivatives of one overlap: the 12 coordinates' duals, or with LISSAGE the neighbours' too.
void overlapDerivatives(const OverlapSetup& setup, const Segment& slave, const Segment& master,
                        const Segment& initial, std::span<const mortar::kernel::Vec2<LacDual>> normals,
                        const LocalEquations& eq, DerivativeSums& sums) {
  if (normals.empty()) {
    addDerivatives(overlapTerms<OverlapDual>(setup, seeded<OverlapDual>(slave, 0),
                                             seeded<OverlapDual>(master, 6), initial.nodes),
                   eq, sums);
  } else {
    addDerivatives(overlapTerms<LacDual>(setup, seeded<LacDual>(slave, 0), seeded<LacDual>(master, 6),
                                         initial.nodes, normals),
                   eq, sums);
  }
}

struct ZoneSums {
  std::vector<std::map<int, double>>& gradients;
  std::vector<SlipSums>& slips;
  std::vector<DerivativeSums>& derivatives;
};

void pairZone(const Mesh& mesh, const LacZoneCells& zone, const std::vector<double>& u, const DofMap& dofs,
              const LacPairingOptions& options, std::vector<LacPatchRow>& rows, const ZoneSums& sums) {
  std::vector<Segment> masters;
  std::vector<Box3> masterBoxes;
  for (CellId c : zone.masters) {
    masters.push_back(segmentOf(mesh, c, &u));
    masterBoxes.push_back(boxOf(masters.back(), {0.0, 0.0}));
  }
  const double moved = largestZoneDisplacement(mesh, zone, u);
  std::vector<Box3> slaveBoxes;
  for (const LacSlaveCell& sc : zone.slaves) {
    const Segment current = segmentOf(mesh, sc.cell, &u);
    const double h =
        norm2({current.nodes[1][0] - current.nodes[0][0], current.nodes[1][1] - current.nodes[0][1]});
    slaveBoxes.push_back(boxOf(current, lacMargin(h, moved)));
  }
  const mortar::Candidates candidates = lacCandidates(slaveBoxes, masterBoxes, zone.bruteForce);
  std::vector<double> gx;
  std::vector<double> gw;
  mortar::kernel::gaussLegendre(options.gaussPoints, gx, gw);
  const auto smoothed = zone.smoothing ? averagedNormals(mesh, zone, u) : std::map<NodeId, Point2>{};
  const auto adjacency =
      zone.smoothing && options.geometricTangent ? slaveAdjacency(mesh, zone) : SlaveAdjacency{};
  for (std::size_t k = 0; k < zone.slaves.size(); ++k) {
    const LacSlaveCell& sc = zone.slaves[k];
    const Segment current = segmentOf(mesh, sc.cell, &u);
    const Segment initial = segmentOf(mesh, sc.cell, nullptr);
    const auto p = static_cast<std::size_t>(sc.patch);
    LacPatchRow& row = rows[p];
    // the whole slave cell's length, with the same rule as the overlaps (exact for SEG2/SEG3)
    for (double xi : {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}) {
      const double w = xi == 0.0 ? 8.0 / 9 : 5.0 / 9;
      row.length += w * measure(zone.currentJacobian ? current : initial, xi, options.axisymmetric);
    }
    const auto slaveNodes = mesh.cellNodes(sc.cell);
    std::array<Point2, 3> normals{};
    for (std::size_t i = 0; zone.smoothing && i < slaveNodes.size(); ++i) {
      normals[i] = smoothed.at(slaveNodes[i]);
    }
    const std::span<const Point2> nodalNormals(normals.data(), zone.smoothing ? slaveNodes.size() : 0);
    const SmoothedStencil stencil = zone.smoothing && options.geometricTangent
                                        ? smoothedStencil(mesh, zone, adjacency, k, u)
                                        : SmoothedStencil{};
    const std::span<const mortar::kernel::Vec2<LacDual>> normalsDual(stencil.normals.data(),
                                                                     nodalNormals.size());
    for (const int m : candidates.of(k)) {
      const Segment& master = masters[static_cast<std::size_t>(m)];
      const OverlapSetup setup{current.type,         master.type, sc.sign, options.axisymmetric,
                               zone.currentJacobian, gx,          gw};
      const OverlapTerms<double> t =
          overlapTerms<double>(setup, current.nodes, master.nodes, initial.nodes, nodalNormals);
      if (!t.paired) {
        continue;
      }
      const auto eq = localEquations(
          dofs, slaveNodes, mesh.cellNodes(zone.masters[static_cast<std::size_t>(m)]), stencil.neighbours);
      row.pairedLength += t.length;
      row.integratedGap += t.gap;
      for (std::size_t l = 0; l < t.normal.size(); ++l) {
        if (eq[l] >= 0) {
          sums.gradients[p][eq[l]] += t.normal[l];
          sums.slips[p][0][eq[l]] += t.slip[l];
        }
      }
      if (options.geometricTangent) {
        overlapDerivatives(setup, current, master, initial, normalsDual, eq, sums.derivatives[p]);
      }
    }
  }
}

} // namespace

double largestZoneDisplacement(const Mesh& mesh, const LacZoneCells& zone, const std::vector<double>& u) {
  double largest = 0.0;
  const auto visit = [&](CellId c) {
    for (NodeId n : mesh.cellNodes(c)) {
      const auto i = static_cast<std::size_t>(n) * 3;
      largest = std::max(largest, std::sqrt(u[i] * u[i] + u[i + 1] * u[i + 1] + u[i + 2] * u[i + 2]));
    }
  };
  for (const LacSlaveCell& sc : zone.slaves) {
    visit(sc.cell);
  }
  for (CellId c : zone.masters) {
    visit(c);
  }
  return largest;
}

mortar::Candidates lacCandidates(std::span<const Box3> slaves, std::span<const Box3> masters,
                                 bool bruteForce) {
  if (!bruteForce) {
    return mortar::findCandidates(slaves, masters);
  }
  mortar::Candidates all;
  all.offsets.reserve(slaves.size() + 1);
  all.masters.reserve(slaves.size() * masters.size());
  for (std::size_t s = 0; s < slaves.size(); ++s) {
    for (std::size_t m = 0; m < masters.size(); ++m) {
      all.masters.push_back(static_cast<int>(m));
    }
    all.offsets.push_back(all.masters.size());
  }
  return all;
}

std::vector<LacPatchRow> pairLacPatches(const Mesh& mesh, const std::vector<LacZoneCells>& zones,
                                        const std::vector<double>& displacement, const DofMap& dofs,
                                        const LacPairingOptions& options) {
  std::vector<LacPatchRow> rows(mesh.lacPatches().size());
  std::vector<std::map<int, double>> gradients(rows.size());
  std::vector<SlipSums> slips(rows.size());
  std::vector<DerivativeSums> derivatives(options.geometricTangent ? rows.size() : 0);
  std::size_t directions = 1;
  for (const auto& zone : zones) {
    const bool faces = !zone.slaves.empty() && mesh.cellType(zone.slaves.front().cell) != CellType::SEG2 &&
                       mesh.cellType(zone.slaves.front().cell) != CellType::SEG3;
    if (faces) {
      directions = 2;
      pairZone3d(mesh, zone, displacement, dofs, rows, gradients, slips);
    } else {
      pairZone(mesh, zone, displacement, dofs, options, rows, {gradients, slips, derivatives});
    }
  }
  for (std::size_t p = 0; p < rows.size(); ++p) {
    rows[p].gradient.assign(gradients[p].begin(), gradients[p].end());
    rows[p].slipGradients.resize(directions);
    for (std::size_t a = 0; a < directions; ++a) {
      rows[p].slipGradients[a].assign(slips[p][a].begin(), slips[p][a].end());
    }
    if (options.geometricTangent) {
      const DerivativeSums& d = derivatives[p];
      rows[p].gapDerivative.assign(d.gap.begin(), d.gap.end());
      rows[p].lengthDerivative.assign(d.length.begin(), d.length.end());
      rows[p].gradientDerivative = d.gradient;
    }
  }
  return rows;
}

} // namespace stella::contact::lac
