// LISSAGE='OUI' with LAC in 2D: the averaged nodal normals (see LacSmoothing.hpp, LacPairing.hpp).

#include "solver/contact/lac/LacSmoothing.hpp"

#include <algorithm>
#include <cmath>

namespace stella::contact::lac {

namespace {

using mortar::Point2;
using Vec2D = mortar::kernel::Vec2<LacDual>;

// The parametric coordinates of a segment's nodes: ends, then middle.
constexpr std::array<double, 3> kNodeXi{-1.0, 1.0, 0.0};

Point2 position(const Mesh& mesh, NodeId n, const std::vector<double>& u) {
  const Point3 x = mesh.point(n);
  const auto i = static_cast<std::size_t>(n) * 3;
  return {x[0] + u[i], x[1] + u[i + 1]};
}

template <class T> mortar::kernel::Vec2<T> normalised(const mortar::kernel::Vec2<T>& v) {
  using std::sqrt;
  const T j = sqrt(mortar::kernel::dot(v, v));
  return {v[0] / j, v[1] / j};
}

} // namespace

std::map<NodeId, Point2> averagedNormals(const Mesh& mesh, const LacZoneCells& zone,
                                         const std::vector<double>& u) {
  std::map<NodeId, Point2> sums;
  for (const LacSlaveCell& sc : zone.slaves) {
    const auto nodes = mesh.cellNodes(sc.cell);
    std::vector<Point2> x;
    for (NodeId n : nodes) {
      x.push_back(position(mesh, n, u));
    }
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const Point2 n = outwardNormal<double>(mesh.cellType(sc.cell), x, sc.sign, kNodeXi[i]);
      Point2& s = sums[nodes[i]];
      s = {s[0] + n[0], s[1] + n[1]};
    }
  }
  for (auto& [node, n] : sums) {
    n = normalised(n);
  }
  return sums;
}

SlaveAdjacency slaveAdjacency(const Mesh& mesh, const LacZoneCells& zone) {
  SlaveAdjacency out;
  for (std::size_t k = 0; k < zone.slaves.size(); ++k) {
    for (NodeId n : mesh.cellNodes(zone.slaves[k].cell)) {
      out[n].push_back(k);
    }
  }
  return out;
}

SmoothedStencil smoothedStencil(const Mesh& mesh, const LacZoneCells& zone, const SlaveAdjacency& adjacency,
                                std::size_t k, const std::vector<double>& u) {
  SmoothedStencil out;
  const auto own = mesh.cellNodes(zone.slaves[k].cell);
  for (NodeId n : own) {
    for (std::size_t c : adjacency.at(n)) {
      for (NodeId m : mesh.cellNodes(zone.slaves[c].cell)) {
        if (std::find(own.begin(), own.end(), m) == own.end() &&
            std::find(out.neighbours.begin(), out.neighbours.end(), m) == out.neighbours.end()) {
          out.neighbours.push_back(m);
        }
      }
    }
  }
  const bool seed = out.neighbours.size() <= static_cast<std::size_t>(kNeighbourNodes);
  // a node as duals: seeded where it is one of the cell's own nodes or a neighbour
  const auto dualOf = [&](NodeId m) -> Vec2D {
    const Point2 x = position(mesh, m, u);
    const auto at = std::find(own.begin(), own.end(), m);
    int index = -1;
    if (at != own.end()) {
      index = 2 * static_cast<int>(at - own.begin());
    } else if (seed) {
      const auto e = std::find(out.neighbours.begin(), out.neighbours.end(), m) - out.neighbours.begin();
      index = kOverlapCoordinates + 2 * static_cast<int>(e);
    }
    return index < 0 ? Vec2D{LacDual(x[0]), LacDual(x[1])}
                     : Vec2D{LacDual::variable(x[0], index), LacDual::variable(x[1], index + 1)};
  };
  for (std::size_t i = 0; i < own.size(); ++i) {
    Vec2D sum{LacDual(0.0), LacDual(0.0)};
    for (std::size_t c : adjacency.at(own[i])) {
      const LacSlaveCell& sc = zone.slaves[c];
      const auto nodes = mesh.cellNodes(sc.cell);
      std::vector<Vec2D> x;
      for (NodeId m : nodes) {
        x.push_back(dualOf(m));
      }
      const auto local =
          static_cast<std::size_t>(std::find(nodes.begin(), nodes.end(), own[i]) - nodes.begin());
      const Vec2D n = outwardNormal<LacDual>(mesh.cellType(sc.cell), x, sc.sign, kNodeXi[local]);
      sum = {sum[0] + n[0], sum[1] + n[1]};
    }
    out.normals[i] = normalised(sum);
  }
  if (!seed) {
    out.neighbours.clear();
  }
  return out;
}

} // namespace stella::contact::lac
