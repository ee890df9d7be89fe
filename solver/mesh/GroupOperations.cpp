// DEFI_GROUP selections (see GroupOperations.hpp).

#include "solver/mesh/GroupOperations.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/mesh/CellTopology.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <numeric>

namespace stella {

std::vector<std::int32_t> unionOf(const std::vector<std::vector<std::int32_t>>& lists) {
  std::vector<std::int32_t> out;
  for (const auto& l : lists) {
    out.insert(out.end(), l.begin(), l.end());
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<std::int32_t> intersectionOf(const std::vector<std::vector<std::int32_t>>& lists) {
  if (lists.empty()) {
    return {};
  }
  std::vector<std::int32_t> out = unionOf({lists.front()});
  for (std::size_t i = 1; i < lists.size(); ++i) {
    const auto other = unionOf({lists[i]});
    std::vector<std::int32_t> next;
    std::set_intersection(out.begin(), out.end(), other.begin(), other.end(), std::back_inserter(next));
    out = std::move(next);
  }
  return out;
}

std::vector<std::int32_t> differenceOf(const std::vector<std::vector<std::int32_t>>& lists) {
  if (lists.empty()) {
    return {};
  }
  std::vector<std::int32_t> out = unionOf({lists.front()});
  const auto others = unionOf(std::vector<std::vector<std::int32_t>>(lists.begin() + 1, lists.end()));
  std::vector<std::int32_t> next;
  std::set_difference(out.begin(), out.end(), others.begin(), others.end(), std::back_inserter(next));
  return next;
}

std::vector<CellId> allCells(const Mesh& mesh) {
  std::vector<CellId> v(static_cast<std::size_t>(mesh.cellCount()));
  std::iota(v.begin(), v.end(), 0);
  return v;
}

std::vector<CellId> filterCellType(const Mesh& mesh, const std::vector<CellId>& cells,
                                   const std::string& typeMaille) {
  if (typeMaille == "TOUT") {
    return cells;
  }
  std::vector<CellId> out;
  const auto exact = cellTypeFromName(typeMaille);
  const int dim = typeMaille.size() == 2 && typeMaille[1] == 'D' ? typeMaille[0] - '0' : -1;
  for (const CellId c : cells) {
    const CellType t = mesh.cellType(c);
    if ((exact && t == *exact) || (!exact && dimension(t) == dim)) {
      out.push_back(c);
    }
  }
  return out;
}

std::vector<CellId> cellsByNodes(const Mesh& mesh, const std::vector<CellId>& cells,
                                 const std::function<bool(NodeId)>& condition, NodeCriterion criterion) {
  std::vector<CellId> out;
  for (const CellId c : cells) {
    const auto nodes = mesh.cellNodes(c);
    const std::size_t n = criterion == NodeCriterion::Vertices
                              ? static_cast<std::size_t>(vertexCount(mesh.cellType(c)))
                              : nodes.size();
    std::size_t hits = 0;
    for (std::size_t i = 0; i < n; ++i) {
      hits += condition(nodes[i]) ? 1 : 0;
    }
    const bool keep = criterion == NodeCriterion::AtLeastOne ? hits > 0
                      : criterion == NodeCriterion::Majority ? 2 * hits > n
                                                             : hits == n;
    if (keep) {
      out.push_back(c);
    }
  }
  return out;
}

Point3 nauticalDirection(const std::vector<double>& angles) {
  const double a = (angles.empty() ? 0.0 : angles[0]) * std::numbers::pi / 180.0;
  const double b = (angles.size() < 2 ? 0.0 : angles[1]) * std::numbers::pi / 180.0;
  return {std::cos(a) * std::cos(b), std::sin(a) * std::cos(b), -std::sin(b)};
}

std::vector<CellId> cellsFacing(const Mesh& mesh, const Point3& direction, double angleDegrees,
                                bool checkSign) {
  std::vector<CellId> out;
  const double dn = norm(direction);
  if (dn == 0) {
    return out;
  }
  const double cosMax = std::cos(angleDegrees * std::numbers::pi / 180.0);
  const int faceDim = mesh.dimension() == 2 ? 1 : 2;
  for (CellId c = 0; c < mesh.cellCount(); ++c) {
    if (dimension(mesh.cellType(c)) != faceDim) {
      continue;
    }
    const Point3 n = cellNormal(mesh, c);
    const double nn = norm(n);
    if (nn == 0) {
      continue;
    }
    const double cosine = dot(n, direction) / (nn * dn);
    if (cosine >= cosMax - 1e-12 || (!checkSign && -cosine >= cosMax - 1e-12)) {
      out.push_back(c);
    }
  }
  return out;
}

std::vector<NodeId> nodesOfCells(const Mesh& mesh, const std::vector<CellId>& cells,
                                 const std::string& criterion) {
  std::vector<NodeId> out;
  for (const CellId c : cells) {
    const CellType t = mesh.cellType(c);
    const auto nodes = mesh.cellNodes(c);
    const int nv = vertexCount(t);
    const int edgeEnd =
        nv +
        (cellEdges(t).empty() || cellEdges(t).front().mid < 0 ? 0 : static_cast<int>(cellEdges(t).size()));
    for (int i = 0; i < static_cast<int>(nodes.size()); ++i) {
      const bool vertex = i < nv;
      const bool mid = !vertex && i < edgeEnd;
      const bool centre = !vertex && !mid;
      if (criterion == "TOUS" || (criterion == "SOMMET" && vertex) || (criterion == "MILIEU" && mid) ||
          (criterion == "CENTRE" && centre)) {
        out.push_back(nodes[static_cast<std::size_t>(i)]);
      }
    }
  }
  return unionOf({out});
}

std::vector<NodeId> nodesWhere(const Mesh& mesh, const std::function<bool(const Point3&)>& condition) {
  std::vector<NodeId> out;
  for (NodeId n = 0; n < mesh.nodeCount(); ++n) {
    if (condition(mesh.point(n))) {
      out.push_back(n);
    }
  }
  return out;
}

double distanceToAxis(const Point3& x, const Point3& point, const Point3& direction) {
  const double dn = norm(direction);
  const Point3 r = x - point;
  return dn == 0 ? norm(r) : norm(cross(r, direction)) / dn;
}

double distanceToPlane(const Point3& x, const Point3& point, const Point3& normal) {
  const double nn = norm(normal);
  return nn == 0 ? 0.0 : std::abs(dot(x - point, normal)) / nn;
}

std::vector<NodeId> orderedChainNodes(const Mesh& mesh, const std::vector<CellId>& segments,
                                      std::optional<NodeId> origin, std::optional<NodeId> end) {
  // Adjacency between the end nodes of the segments; mid nodes are inserted between them.
  std::map<NodeId, std::vector<std::pair<NodeId, CellId>>> next;
  for (const CellId c : segments) {
    if (dimension(mesh.cellType(c)) != 1) {
      throw UserError(msg::make("DEFI_GROUP_5", {{"cell_name", mesh.cellName(c)}}));
    }
    const auto n = mesh.cellNodes(c);
    next[n[0]].emplace_back(n[1], c);
    next[n[1]].emplace_back(n[0], c);
  }
  if (next.empty()) {
    return {};
  }
  std::vector<NodeId> ends;
  for (const auto& [n, adj] : next) {
    if (adj.size() > 2) {
      throw UserError(msg::make("DEFI_GROUP_5.2", {{"node_name", mesh.nodeName(n)}}));
    }
    if (adj.size() == 1) {
      ends.push_back(n);
    }
  }
  NodeId start = ends.empty() ? next.begin()->first : ends.front();
  if (origin) {
    start = *origin;
  } else if (end && !ends.empty()) {
    start = ends.front() == *end && ends.size() > 1 ? ends[1] : ends.front();
  }
  if (next.count(start) == 0) {
    throw UserError(msg::make("DEFI_GROUP_5.3", {{"node_name", mesh.nodeName(start)}}));
  }
  std::vector<NodeId> order{start};
  std::vector<bool> used(static_cast<std::size_t>(mesh.cellCount()), false);
  NodeId at = start;
  for (std::size_t k = 0; k < segments.size(); ++k) {
    bool moved = false;
    for (const auto& [to, cell] : next[at]) {
      if (used[static_cast<std::size_t>(cell)]) {
        continue;
      }
      used[static_cast<std::size_t>(cell)] = true;
      const auto n = mesh.cellNodes(cell);
      // Interior nodes of the segment (SEG3 middle, SEG4 thirds) in the walking direction.
      if (n.size() > 2) {
        std::vector<NodeId> inner(n.begin() + 2, n.end());
        if (n[0] != at) {
          std::reverse(inner.begin(), inner.end());
        }
        order.insert(order.end(), inner.begin(), inner.end());
      }
      if (to != start || k + 1 < segments.size()) {
        order.push_back(to);
      }
      at = to;
      moved = true;
      break;
    }
    if (!moved) {
      throw UserError(msg::make("DEFI_GROUP_5.4"));
    }
  }
  return order;
}

std::vector<NodeId> nodesOnSegment(const Mesh& mesh, const std::vector<NodeId>& nodes, NodeId a, NodeId b,
                                   double precision, bool relative) {
  const Point3 pa = mesh.point(a);
  const Point3 ab = mesh.point(b) - pa;
  const double length = norm(ab);
  const double tol = relative ? precision * length : precision;
  std::vector<std::pair<double, NodeId>> found;
  for (const NodeId n : nodes) {
    const Point3 r = mesh.point(n) - pa;
    const double s = length == 0 ? 0.0 : dot(r, ab) / length;
    const double d = length == 0 ? norm(r) : norm(cross(r, ab)) / length;
    if (d <= tol && s >= -tol && s <= length + tol) {
      found.emplace_back(s, n);
    }
  }
  std::sort(found.begin(), found.end());
  std::vector<NodeId> out;
  for (const auto& [s, n] : found) {
    out.push_back(n);
  }
  return out;
}

} // namespace stella
