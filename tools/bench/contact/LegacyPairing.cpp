// The pairing of stella before issue 23, kept for the benchmark's comparison only: nearest master
// nodes by the hand-written kd-tree (PointSearchTree), orthogonal projection on the master cells
// around the 4 (then 16) nearest nodes, shape functions through fem::ReferenceElement (allocating).

#include "tools/bench/contact/LegacyPairing.hpp"

#include "messages/Messages.hpp"
#include "solver/fem/ReferenceElement.hpp"
#include "solver/mesh/MeshGeometry.hpp"
#include "tools/bench/contact/PointSearchTree.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace stella::contact::legacy {

namespace {

Point3 normalized(const Point3& v) {
  const double n = norm(v);
  return n > 0.0 ? (1.0 / n) * v : v;
}

bool isTriangle(CellType t) {
  return t == CellType::TRIA3 || t == CellType::TRIA6;
}

// Parametric distance outside the reference cell (0 inside) and the closest inside point.
double outsideDistance(CellType t, int dim, const std::array<double, 2>& xi, std::array<double, 2>& clamped) {
  clamped = xi;
  if (dim == 1) {
    clamped[0] = std::clamp(xi[0], -1.0, 1.0);
    clamped[1] = 0.0;
    return std::abs(xi[0] - clamped[0]);
  }
  if (!isTriangle(t)) {
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

struct CellGeometry {
  Point3 x{0, 0, 0};
  Point3 d1{0, 0, 0}; // dx/dxi
  Point3 d2{0, 0, 0}; // dx/deta (3D)
  Eigen::VectorXd n;
};

CellGeometry evaluate(const Mesh& mesh, const NodePosition& position, CellId cell,
                      const std::array<double, 2>& xi) {
  const auto& ref = fem::referenceElement(mesh.cellType(cell));
  const Eigen::Vector3d p(xi[0], xi[1], 0.0);
  CellGeometry g;
  g.n = ref.values(p);
  const Eigen::MatrixXd dn = ref.gradients(p);
  const auto nodes = mesh.cellNodes(cell);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const Point3 xn = position(nodes[i]);
    const auto ii = static_cast<Eigen::Index>(i);
    g.x = g.x + g.n(ii) * xn;
    g.d1 = g.d1 + dn(ii, 0) * xn;
    if (dn.cols() > 1) {
      g.d2 = g.d2 + dn(ii, 1) * xn;
    }
  }
  return g;
}

// Outward normal of a skin cell from its parametric derivatives (consistent with cellNormal).
Point3 cellNormalAt(const CellGeometry& g, int dim) {
  if (dim == 1) {
    return normalized(Point3{g.d1[1], -g.d1[0], 0.0});
  }
  return normalized(cross(g.d1, g.d2));
}

// Unit tangents orthogonal to n: the first along the cell's first parametric direction when
// that direction is not parallel to n.
void tangents(const Point3& n, const Point3& d1, int dim, Point3& t1, Point3& t2) {
  if (dim == 1) {
    t1 = Point3{-n[1], n[0], 0.0};
    t2 = Point3{0, 0, 0};
    return;
  }
  Point3 t = d1 - dot(d1, n) * n;
  if (norm(t) < 1e-12 * std::max(norm(d1), 1.0)) {
    const Point3 e = std::abs(n[0]) < 0.9 ? Point3{1, 0, 0} : Point3{0, 1, 0};
    t = e - dot(e, n) * n;
  }
  t1 = normalized(t);
  t2 = cross(n, t1);
}

struct Surface {
  std::vector<CellId> cells;
  std::vector<NodeId> nodes; // sorted
  std::unordered_map<NodeId, std::vector<CellId>> cellsOfNode;
  std::unordered_map<NodeId, Point3> nodalNormal; // averaged unit normals (outward)
};

Surface buildSurface(const Mesh& mesh, const NodePosition& position, const std::vector<CellId>& cells,
                     int dim) {
  Surface s;
  s.cells = cells;
  s.nodes = mesh.nodesOfCells(cells);
  for (CellId c : cells) {
    const auto& ref = fem::referenceElement(mesh.cellType(c));
    const auto nodes = mesh.cellNodes(c);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      s.cellsOfNode[nodes[i]].push_back(c);
      const auto& xn = ref.node(static_cast<int>(i));
      const auto g = evaluate(mesh, position, c, {xn(0), xn(1)});
      auto& acc = s.nodalNormal[nodes[i]];
      acc = acc + cellNormalAt(g, dim);
    }
  }
  for (auto& [node, n] : s.nodalNormal) {
    n = normalized(n);
  }
  return s;
}

Point3 smoothedNormal(const Surface& s, const Mesh& mesh, CellId cell, const Eigen::VectorXd& shape) {
  Point3 n{0, 0, 0};
  const auto nodes = mesh.cellNodes(cell);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    n = n + shape(static_cast<Eigen::Index>(i)) * s.nodalNormal.at(nodes[i]);
  }
  return normalized(n);
}

Point3 chosenVector(VectorChoice choice, const std::array<double, 3>& value, const Point3& geometric,
                    const Point3& d1) {
  if (choice == VectorChoice::Fixed) {
    return normalized(Point3{value[0], value[1], value[2]});
  }
  if (choice == VectorChoice::VectY) {
    const Point3 t = normalized(d1);
    const Point3 y{value[0], value[1], value[2]};
    return normalized(y - dot(y, t) * t);
  }
  return geometric;
}

struct Candidate {
  CellId cell = -1;
  std::array<double, 2> xi{0, 0};
  double distance = std::numeric_limits<double>::max();
};

std::vector<NodeId> searchNodes(const PointSearchTree& tree, const std::vector<NodeId>& masterNodes,
                                const Point3& x, int k) {
  std::vector<NodeId> out;
  for (int i : tree.nearest(x, k)) {
    out.push_back(masterNodes[static_cast<std::size_t>(i)]);
  }
  return out;
}

} // namespace

static std::array<double, 2> projectOnCell(const Mesh& mesh, const NodePosition& position, CellId cell,
                                           const Point3& x) {
  const CellType t = mesh.cellType(cell);
  const int dim = info(t).dimension;
  std::array<double, 2> xi =
      isTriangle(t) ? std::array<double, 2>{1.0 / 3.0, 1.0 / 3.0} : std::array<double, 2>{0.0, 0.0};
  for (int it = 0; it < 50; ++it) {
    const auto g = evaluate(mesh, position, cell, xi);
    const Point3 r = g.x - x;
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

std::vector<ContactLink> pairZone(const Mesh& mesh, const NodePosition& position, int zoneIndex,
                                  const ContactZone& zone, const PairingOptions& options) {
  if (zone.projection == Projection::Fixed) {
    throw UserError(msg::make("CONTACT_10", {}, zone.location));
  }
  const int dim = options.dimension - 1;
  const Surface master = buildSurface(mesh, position, zoneMasterCells(mesh, zone), dim);
  const auto* slaveCells = mesh.cellGroup(zone.slaveGroup);
  const Surface slave = buildSurface(mesh, position, slaveCells ? *slaveCells : std::vector<CellId>{}, dim);
  std::vector<Point3> masterPoints;
  masterPoints.reserve(master.nodes.size());
  for (NodeId n : master.nodes) {
    masterPoints.push_back(position(n));
  }
  const PointSearchTree tree(std::move(masterPoints));
  const bool slaveNormalNeeded = zone.normal != NormalChoice::Master || zone.pairing == Pairing::Nodal;

  std::vector<ContactLink> links;
  for (NodeId s : zoneSlaveNodes(mesh, zone)) {
    ContactLink link;
    link.zone = zoneIndex;
    link.slave = s;
    const Point3 x = position(s);
    Point3 slaveNormal{0, 0, 0};
    if (slaveNormalNeeded) {
      slaveNormal = slave.nodalNormal.count(s) ? slave.nodalNormal.at(s) : Point3{0, 0, 0};
      slaveNormal = chosenVector(zone.slaveVector, zone.slaveVectorValue, slaveNormal,
                                 Point3{-slaveNormal[1], slaveNormal[0], 0});
    }
    if (tree.empty()) {
      links.push_back(link);
      continue;
    }
    Point3 masterNormal{0, 0, 0};
    Point3 d1{0, 0, 0};
    if (zone.pairing == Pairing::Nodal) {
      const NodeId m = searchNodes(tree, master.nodes, x, 1).front();
      link.masterNodes = {m};
      link.weights = {1.0};
      link.projection = position(m);
      masterNormal = -1.0 * slaveNormal;
      d1 = Point3{-masterNormal[1], masterNormal[0], 0.0};
      link.paired = true;
    } else {
      Candidate best;
      for (int k : {4, 16}) {
        for (NodeId m : searchNodes(tree, master.nodes, x, k)) {
          for (CellId c : master.cellsOfNode.at(m)) {
            const auto xi = projectOnCell(mesh, position, c, x);
            std::array<double, 2> clamped{};
            const double out = outsideDistance(mesh.cellType(c), dim, xi, clamped);
            if (zone.extensionTolerance >= 0.0 && out > zone.extensionTolerance) {
              continue;
            }
            const double d = norm(evaluate(mesh, position, c, clamped).x - x);
            if (d < best.distance) {
              best = {c, clamped, d};
            }
          }
        }
        if (best.cell >= 0) {
          break;
        }
      }
      if (best.cell < 0) {
        links.push_back(link);
        continue;
      }
      const auto g = evaluate(mesh, position, best.cell, best.xi);
      link.masterCell = best.cell;
      link.xi = best.xi;
      const auto nodes = mesh.cellNodes(best.cell);
      link.masterNodes.assign(nodes.begin(), nodes.end());
      link.weights.assign(g.n.data(), g.n.data() + g.n.size());
      link.projection = g.x;
      d1 = g.d1;
      masterNormal = options.smoothing ? smoothedNormal(master, mesh, best.cell, g.n) : cellNormalAt(g, dim);
      masterNormal = chosenVector(zone.masterVector, zone.masterVectorValue, masterNormal, g.d1);
      link.paired = true;
    }
    Point3 n = masterNormal;
    if (zone.normal == NormalChoice::Slave) {
      n = -1.0 * slaveNormal;
    } else if (zone.normal == NormalChoice::MasterSlave) {
      n = normalized(masterNormal - slaveNormal);
    }
    link.normal = n;
    tangents(n, d1, dim, link.tangent1, link.tangent2);
    link.gap = dot(x - link.projection, n);
    if (zone.pairingDistance > 0.0 && norm(x - link.projection) > zone.pairingDistance) {
      link.paired = false;
    }
    links.push_back(std::move(link));
  }
  return links;
}

} // namespace stella::contact::legacy
