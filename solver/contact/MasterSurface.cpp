// Contact surface topology in flat arrays, node positions, boxes, index and nodal normals.

#include "solver/contact/MasterSurface.hpp"

#include "solver/fem/ReferenceElement.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <algorithm>
#include <cmath>

namespace stella::contact {

namespace {

Point3 normalized(const Point3& v) {
  const double n = norm(v);
  return n > 0.0 ? (1.0 / n) * v : v;
}

// Compressed rows from (row, value) pairs counted then filled.
template <class RowOf>
void compress(int rows, std::size_t entries, RowOf&& rowOf, std::vector<int>& start,
              std::vector<int>& values) {
  start.assign(static_cast<std::size_t>(rows) + 1, 0);
  for (std::size_t e = 0; e < entries; ++e) {
    ++start[static_cast<std::size_t>(rowOf(e).first) + 1];
  }
  for (std::size_t r = 0; r < static_cast<std::size_t>(rows); ++r) {
    start[r + 1] += start[r];
  }
  values.assign(entries, 0);
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (std::size_t e = 0; e < entries; ++e) {
    const auto [row, value] = rowOf(e);
    values[static_cast<std::size_t>(fill[static_cast<std::size_t>(row)]++)] = value;
  }
}

} // namespace

Point3 cellNormalAt(const CellPoint& g, int dim) {
  if (dim == 1) {
    return normalized(Point3{g.d1[1], -g.d1[0], 0.0});
  }
  return normalized(cross(g.d1, g.d2));
}

MasterSurface::MasterSurface(const Mesh& mesh, const std::vector<CellId>& cells, int dim)
    : dim_(dim), cells_(cells) {
  nodes_ = mesh.nodesOfCells(cells_);
  types_.reserve(cells_.size());
  cellStart_.reserve(cells_.size() + 1);
  cellStart_.push_back(0);
  for (CellId c : cells_) {
    types_.push_back(mesh.cellType(c));
    for (NodeId n : mesh.cellNodes(c)) {
      cellNode_.push_back(local(n));
    }
    cellStart_.push_back(static_cast<int>(cellNode_.size()));
  }
  // Cells of each node (ascending positions).
  std::vector<std::pair<int, int>> pairs;
  pairs.reserve(cellNode_.size());
  for (int c = 0; c < cellCount(); ++c) {
    for (int n : cellNodes(c)) {
      pairs.emplace_back(n, c);
    }
  }
  compress(
      nodeCount(), pairs.size(), [&](std::size_t e) { return pairs[e]; }, nodeStart_, nodeCell_);
  // Neighbours: the cells of the cell's nodes, sorted and unique.
  neighbourStart_.reserve(cells_.size() + 1);
  neighbourStart_.push_back(0);
  std::vector<int> around;
  for (int c = 0; c < cellCount(); ++c) {
    around.clear();
    for (int n : cellNodes(c)) {
      const auto cs = cellsOfNode(n);
      around.insert(around.end(), cs.begin(), cs.end());
    }
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    neighbour_.insert(neighbour_.end(), around.begin(), around.end());
    neighbourStart_.push_back(static_cast<int>(neighbour_.size()));
  }
  positions_.resize(nodes_.size());
}

std::span<const int> MasterSurface::cellNodes(int position) const {
  const auto p = static_cast<std::size_t>(position);
  return {cellNode_.data() + cellStart_[p], static_cast<std::size_t>(cellStart_[p + 1] - cellStart_[p])};
}

std::span<const int> MasterSurface::neighbours(int position) const {
  const auto p = static_cast<std::size_t>(position);
  return {neighbour_.data() + neighbourStart_[p],
          static_cast<std::size_t>(neighbourStart_[p + 1] - neighbourStart_[p])};
}

std::span<const int> MasterSurface::cellsOfNode(int local) const {
  const auto p = static_cast<std::size_t>(local);
  return {nodeCell_.data() + nodeStart_[p], static_cast<std::size_t>(nodeStart_[p + 1] - nodeStart_[p])};
}

int MasterSurface::local(NodeId n) const {
  const auto it = std::lower_bound(nodes_.begin(), nodes_.end(), n);
  return it != nodes_.end() && *it == n ? static_cast<int>(it - nodes_.begin()) : -1;
}

void MasterSurface::gather(int position, CellNodes& out) const {
  out.type = types_[static_cast<std::size_t>(position)];
  const auto nodes = cellNodes(position);
  out.count = static_cast<int>(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    out.x[i] = positions_[static_cast<std::size_t>(nodes[i])];
  }
}

void MasterSurface::update(const NodePosition& position, bool withIndex, double margin, bool withNormals) {
  Point3 lo{0, 0, 0};
  Point3 hi{0, 0, 0};
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    positions_[i] = position(nodes_[i]);
    for (std::size_t a = 0; a < 3; ++a) {
      lo[a] = i == 0 ? positions_[i][a] : std::min(lo[a], positions_[i][a]);
      hi[a] = i == 0 ? positions_[i][a] : std::max(hi[a], positions_[i][a]);
    }
  }
  double largest = 0.0;
  for (std::size_t a = 0; a < 3; ++a) {
    largest = std::max({largest, std::abs(lo[a]), std::abs(hi[a])});
  }
  lengthScale_ = norm(hi - lo) + largest;
  if (lengthScale_ == 0.0) {
    lengthScale_ = 1.0;
  }
  CellNodes cn;
  if (withIndex) {
    boxes_.resize(cells_.size());
    double sum = 0.0;
    for (int c = 0; c < cellCount(); ++c) {
      gather(c, cn);
      boxes_[static_cast<std::size_t>(c)] = cellBox(cn.type, cn.x.data(), cn.count, margin);
      sum += 0.5 * norm(boxes_[static_cast<std::size_t>(c)].hi - boxes_[static_cast<std::size_t>(c)].lo);
    }
    meanCellSize_ = cells_.empty() ? 0.0 : sum / static_cast<double>(cells_.size());
    index_.build(boxes_);
  }
  if (withNormals) {
    normals_.assign(nodes_.size(), Point3{0, 0, 0});
    CellPoint g;
    for (int c = 0; c < cellCount(); ++c) {
      gather(c, cn);
      const auto& ref = fem::referenceElement(cn.type);
      const auto nodes = cellNodes(c);
      for (std::size_t i = 0; i < nodes.size(); ++i) {
        const auto& xn = ref.node(static_cast<int>(i));
        evaluateCell(cn, {xn(0), xn(1)}, g);
        auto& acc = normals_[static_cast<std::size_t>(nodes[i])];
        acc = acc + cellNormalAt(g, dim_);
      }
    }
    for (auto& n : normals_) {
      n = normalized(n);
    }
  }
}

} // namespace stella::contact
