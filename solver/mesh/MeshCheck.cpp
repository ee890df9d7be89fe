// VERI_MAIL checks (see MeshCheck.hpp).

#include "solver/mesh/MeshCheck.hpp"

#include "messages/Messages.hpp"
#include "solver/mesh/CellTopology.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace stella {

namespace {

double boundingDiagonal(const Mesh& m) {
  if (m.nodeCount() == 0) {
    return 0;
  }
  Point3 lo = m.point(0);
  Point3 hi = lo;
  for (NodeId n = 1; n < m.nodeCount(); ++n) {
    const Point3 x = m.point(n);
    for (std::size_t d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], x[d]);
      hi[d] = std::max(hi[d], x[d]);
    }
  }
  return norm(hi - lo);
}

// Sort nodes by x, then compare neighbours within the tolerance window.
std::vector<std::pair<NodeId, NodeId>> duplicates(const Mesh& m, double tol) {
  std::vector<NodeId> order(static_cast<std::size_t>(m.nodeCount()));
  std::iota(order.begin(), order.end(), 0);
  const auto& x = m.coordinates();
  std::sort(order.begin(), order.end(), [&](NodeId a, NodeId b) {
    return x[3 * static_cast<std::size_t>(a)] < x[3 * static_cast<std::size_t>(b)];
  });
  std::vector<std::pair<NodeId, NodeId>> pairs;
  for (std::size_t i = 0; i < order.size(); ++i) {
    for (std::size_t j = i + 1; j < order.size(); ++j) {
      const Point3 a = m.point(order[i]);
      const Point3 b = m.point(order[j]);
      if (b[0] - a[0] > tol) {
        break;
      }
      if (norm(b - a) <= tol) {
        pairs.emplace_back(std::min(order[i], order[j]), std::max(order[i], order[j]));
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

bool degenerate(const Mesh& m, CellId c, double tol) {
  const auto nodes = m.cellNodes(c);
  std::vector<NodeId> sorted(nodes.begin(), nodes.end());
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
    return true;
  }
  for (const auto& e : cellEdges(m.cellType(c))) {
    if (norm(m.point(nodes[static_cast<std::size_t>(e.b)]) - m.point(nodes[static_cast<std::size_t>(e.a)])) <=
        tol) {
      return true;
    }
  }
  return false;
}

double longestEdge(const Mesh& m, CellId c) {
  const auto nodes = m.cellNodes(c);
  double l = 0;
  for (const auto& e : cellEdges(m.cellType(c))) {
    l = std::max(l, norm(m.point(nodes[static_cast<std::size_t>(e.b)]) -
                         m.point(nodes[static_cast<std::size_t>(e.a)])));
  }
  return l;
}

template <class Ids, class Name> std::string listNames(const Ids& ids, Name nameOf) {
  std::string s;
  std::size_t k = 0;
  for (const auto& id : ids) {
    if (k == 20) {
      s += " ... (" + std::to_string(ids.size()) + " in all)";
      break;
    }
    s += (k == 0 ? "" : ", ") + nameOf(id);
    ++k;
  }
  return s;
}

} // namespace

MeshCheckReport checkMesh(const Mesh& mesh, double flatness) {
  MeshCheckReport r;
  const double tol = 1e-10 * boundingDiagonal(mesh);
  r.duplicateNodes = duplicates(mesh, tol);
  for (CellId c = 0; c < mesh.cellCount(); ++c) {
    const CellType t = mesh.cellType(c);
    const int dim = dimension(t);
    if (dim == 0) {
      continue;
    }
    if (degenerate(mesh, c, tol)) {
      r.degenerateCells.push_back(c);
      continue;
    }
    if ((dim == 3 || (dim == 2 && mesh.dimension() == 2)) && isInverted(mesh, c)) {
      r.invertedCells.push_back(c);
      continue;
    }
    if (dim >= 2) {
      const double l = longestEdge(mesh, c);
      const double measure = std::abs(cellMeasure(mesh, c));
      if (measure < flatness * std::pow(l, dim)) {
        r.flatCells.push_back(c);
      }
    }
  }
  return r;
}

std::vector<Diagnostic> meshCheckDiagnostics(const Mesh& mesh, const MeshCheckReport& r) {
  std::vector<Diagnostic> out;
  const auto cellName = [&](CellId c) { return mesh.cellName(c); };
  if (!r.duplicateNodes.empty()) {
    const auto pairName = [&](const std::pair<NodeId, NodeId>& p) {
      return mesh.nodeName(p.first) + "=" + mesh.nodeName(p.second);
    };
    out.push_back(
        msg::make("MESHCHECK_1", {{"duplicate_nodes_count", std::to_string(r.duplicateNodes.size())},
                                  {"list_names", listNames(r.duplicateNodes, pairName)}}));
  }
  if (!r.degenerateCells.empty()) {
    out.push_back(
        msg::make("MESHCHECK_2", {{"degenerate_cells_count", std::to_string(r.degenerateCells.size())},
                                  {"list_names", listNames(r.degenerateCells, cellName)}}));
  }
  if (!r.invertedCells.empty()) {
    out.push_back(msg::make("MESHCHECK_3", {{"inverted_cells_count", std::to_string(r.invertedCells.size())},
                                            {"list_names", listNames(r.invertedCells, cellName)}}));
  }
  if (!r.flatCells.empty()) {
    out.push_back(msg::make("MESHCHECK_4", {{"flat_cells_count", std::to_string(r.flatCells.size())},
                                            {"list_names", listNames(r.flatCells, cellName)}}));
  }
  return out;
}

} // namespace stella
