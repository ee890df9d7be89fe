// Mortar pairing of LAC contact in 2D (see LacPairing.hpp).

#include "solver/contact/lac/LacPairing.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace stella::contact::lac {

namespace {

using mortar::Point2;
using mortar::Segment;

// Shape functions of SEG2 / SEG3 (ends, then middle) at xi.
std::array<double, 3> shape(CellType t, double xi) {
  if (t == CellType::SEG2) {
    return {0.5 * (1 - xi), 0.5 * (1 + xi), 0.0};
  }
  return {-0.5 * xi * (1 - xi), 0.5 * xi * (1 + xi), 1 - xi * xi};
}

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

void addGradient(std::map<int, double>& g, const DofMap& dofs, NodeId n, const Point2& v, double f) {
  for (int c = 0; c < 2; ++c) {
    const int e = dofs.dof(n, c);
    if (e >= 0) {
      g[e] += f * v[static_cast<std::size_t>(c)];
    }
  }
}

void pairZone(const Mesh& mesh, const LacZoneCells& zone, const std::vector<double>& u, const DofMap& dofs,
              const LacPairingOptions& options, std::vector<LacPatchRow>& rows,
              std::vector<std::map<int, double>>& gradients, std::vector<SlipSums>& slips) {
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
  mortar::SegmentOptions segmentOptions;
  segmentOptions.gaussPoints = options.gaussPoints;
  for (std::size_t k = 0; k < zone.slaves.size(); ++k) {
    const LacSlaveCell& sc = zone.slaves[k];
    const Segment current = segmentOf(mesh, sc.cell, &u);
    const Segment initial = segmentOf(mesh, sc.cell, nullptr);
    const Segment& jacobianOn = zone.currentJacobian ? current : initial;
    LacPatchRow& row = rows[static_cast<std::size_t>(sc.patch)];
    // the whole slave cell's length, with the same rule as the overlaps (exact for SEG2/SEG3)
    for (double xi : {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}) {
      const double w = xi == 0.0 ? 8.0 / 9 : 5.0 / 9;
      row.length += w * measure(jacobianOn, xi, options.axisymmetric);
    }
    const auto overlaps = mortar::intersectSegments(current, masters, candidates.of(k), segmentOptions);
    const auto slaveNodes = mesh.cellNodes(sc.cell);
    for (const auto& o : overlaps) {
      const Segment& m = masters[static_cast<std::size_t>(o.master)];
      const auto masterNodes = mesh.cellNodes(zone.masters[static_cast<std::size_t>(o.master)]);
      for (const auto& q : o.points) {
        const Point2 t = mortar::segmentTangent(current, q.slaveXi);
        const double jt = norm2(t);
        const Point2 n = {sc.sign * t[1] / jt, -sc.sign * t[0] / jt};
        const Point2 xs = mortar::segmentPoint(current, q.slaveXi);
        const Point2 xm = mortar::segmentPoint(m, q.masterXi);
        const double gap = n[0] * (xm[0] - xs[0]) + n[1] * (xm[1] - xs[1]);
        // q.weight = Gauss weight x |dx/dxi| (current): take the configuration's measure instead
        const double w = q.weight / jt * measure(jacobianOn, q.slaveXi, options.axisymmetric);
        row.pairedLength += w;
        row.integratedGap += w * gap;
        auto& grad = gradients[static_cast<std::size_t>(sc.patch)];
        auto& slip = slips[static_cast<std::size_t>(sc.patch)][0];
        const Point2 tau = {-n[1], n[0]};
        const auto ns = shape(current.type, q.slaveXi);
        for (std::size_t i = 0; i < slaveNodes.size(); ++i) {
          addGradient(grad, dofs, slaveNodes[i], n, -w * ns[i]);
          addGradient(slip, dofs, slaveNodes[i], tau, w * ns[i]);
        }
        const auto nm = shape(m.type, q.masterXi);
        for (std::size_t j = 0; j < masterNodes.size(); ++j) {
          addGradient(grad, dofs, masterNodes[j], n, w * nm[j]);
          addGradient(slip, dofs, masterNodes[j], tau, -w * nm[j]);
        }
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
  std::size_t directions = 1;
  for (const auto& zone : zones) {
    const bool faces = !zone.slaves.empty() && mesh.cellType(zone.slaves.front().cell) != CellType::SEG2 &&
                       mesh.cellType(zone.slaves.front().cell) != CellType::SEG3;
    if (faces) {
      directions = 2;
      pairZone3d(mesh, zone, displacement, dofs, rows, gradients, slips);
    } else {
      pairZone(mesh, zone, displacement, dofs, options, rows, gradients, slips);
    }
  }
  for (std::size_t p = 0; p < rows.size(); ++p) {
    rows[p].gradient.assign(gradients[p].begin(), gradients[p].end());
    rows[p].slipGradients.resize(directions);
    for (std::size_t a = 0; a < directions; ++a) {
      rows[p].slipGradients[a].assign(slips[p][a].begin(), slips[p][a].end());
    }
  }
  return rows;
}

} // namespace stella::contact::lac
