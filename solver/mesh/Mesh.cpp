// The mesh model (see Mesh.hpp).

#include "solver/mesh/Mesh.hpp"

#include "interpreter/Diagnostics.hpp"

#include <algorithm>

namespace stella {

Mesh::Mesh() {
  offsets_.push_back(0);
}

void Mesh::reserveNodes(NodeId n) {
  coordinates_.reserve(3 * static_cast<std::size_t>(n));
}

NodeId Mesh::addNode(const Point3& x) {
  coordinates_.insert(coordinates_.end(), x.begin(), x.end());
  nodeNames_.appendDefault(1);
  return nodeCount() - 1;
}

NodeId Mesh::addNode(const Point3& x, std::string_view name) {
  coordinates_.insert(coordinates_.end(), x.begin(), x.end());
  nodeNames_.append(name);
  return nodeCount() - 1;
}

Point3 Mesh::point(NodeId n) const {
  const auto i = 3 * static_cast<std::size_t>(n);
  return {coordinates_[i], coordinates_[i + 1], coordinates_[i + 2]};
}

void Mesh::setPoint(NodeId n, const Point3& x) {
  const auto i = 3 * static_cast<std::size_t>(n);
  coordinates_[i] = x[0];
  coordinates_[i + 1] = x[1];
  coordinates_[i + 2] = x[2];
}

void Mesh::reserveCells(CellId cells, std::size_t connectivity) {
  types_.reserve(static_cast<std::size_t>(cells));
  offsets_.reserve(static_cast<std::size_t>(cells) + 1);
  connectivity_.reserve(connectivity);
}

CellId Mesh::addCell(CellType type, std::span<const NodeId> nodes) {
  STELLA_ASSERT(static_cast<int>(nodes.size()) == stella::nodeCount(type),
                "node count of a " + std::string(stella::name(type)));
  types_.push_back(static_cast<std::uint8_t>(type));
  connectivity_.insert(connectivity_.end(), nodes.begin(), nodes.end());
  offsets_.push_back(connectivity_.size());
  cellNames_.appendDefault(1);
  return cellCount() - 1;
}

CellId Mesh::addCell(CellType type, std::span<const NodeId> nodes, std::string_view name) {
  STELLA_ASSERT(static_cast<int>(nodes.size()) == stella::nodeCount(type),
                "node count of a " + std::string(stella::name(type)));
  types_.push_back(static_cast<std::uint8_t>(type));
  connectivity_.insert(connectivity_.end(), nodes.begin(), nodes.end());
  offsets_.push_back(connectivity_.size());
  cellNames_.append(name);
  return cellCount() - 1;
}

std::span<const NodeId> Mesh::cellNodes(CellId c) const {
  const auto i = static_cast<std::size_t>(c);
  return {connectivity_.data() + offsets_[i], offsets_[i + 1] - offsets_[i]};
}

std::span<NodeId> Mesh::mutableCellNodes(CellId c) {
  const auto i = static_cast<std::size_t>(c);
  return {connectivity_.data() + offsets_[i], offsets_[i + 1] - offsets_[i]};
}

int Mesh::maxCellDimension() const {
  int d = 0;
  for (const auto t : types_) {
    d = std::max(d, stella::dimension(static_cast<CellType>(t)));
  }
  return d;
}

const std::vector<CellId>* Mesh::cellGroup(const std::string& name) const {
  const auto it = cellGroups_.find(name);
  return it == cellGroups_.end() ? nullptr : &it->second;
}

const std::vector<NodeId>* Mesh::nodeGroup(const std::string& name) const {
  const auto it = nodeGroups_.find(name);
  return it == nodeGroups_.end() ? nullptr : &it->second;
}

namespace {
template <class T> void sortUnique(std::vector<T>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  v.shrink_to_fit();
}
} // namespace

void Mesh::setCellGroup(const std::string& name, std::vector<CellId> cells) {
  sortUnique(cells);
  cellGroups_[name] = std::move(cells);
}

void Mesh::setNodeGroup(const std::string& name, std::vector<NodeId> nodes) {
  sortUnique(nodes);
  nodeGroups_[name] = std::move(nodes);
}

void Mesh::setOrderedNodeGroup(const std::string& name, std::vector<NodeId> nodes) {
  std::vector<NodeId> seen(nodes);
  sortUnique(seen);
  std::vector<bool> taken(seen.size(), false);
  std::vector<NodeId> out;
  for (const NodeId n : nodes) {
    const auto k = static_cast<std::size_t>(std::lower_bound(seen.begin(), seen.end(), n) - seen.begin());
    if (!taken[k]) {
      taken[k] = true;
      out.push_back(n);
    }
  }
  nodeGroups_[name] = std::move(out);
}

std::vector<NodeId> Mesh::nodesOfCells(std::span<const CellId> cells) const {
  std::vector<NodeId> nodes;
  for (const CellId c : cells) {
    const auto n = cellNodes(c);
    nodes.insert(nodes.end(), n.begin(), n.end());
  }
  sortUnique(nodes);
  return nodes;
}

std::size_t Mesh::memoryBytes(bool withGroups) const {
  std::size_t bytes = sizeof(*this) + name_.capacity() + coordinates_.capacity() * sizeof(double) +
                      offsets_.capacity() * sizeof(std::uint64_t) +
                      connectivity_.capacity() * sizeof(NodeId) + types_.capacity() +
                      nodeNames_.memoryBytes() + cellNames_.memoryBytes() - 2 * sizeof(NameTable);
  if (withGroups) {
    for (const auto& [n, g] : cellGroups_) {
      bytes += n.capacity() + g.capacity() * sizeof(CellId) + 64;
    }
    for (const auto& [n, g] : nodeGroups_) {
      bytes += n.capacity() + g.capacity() * sizeof(NodeId) + 64;
    }
  }
  return bytes;
}

} // namespace stella
