#pragma once
// A contact surface as the pairing uses it: its cells (in the group's order: "positions"), its
// nodes numbered locally, the cells around each node and the neighbours of each cell (cells
// sharing a node), in flat arrays built once; the current node positions and, on demand, the
// cells' boxes with their spatial index and the averaged nodal normals (LISSAGE, slave normals).

#include "solver/contact/CellProjection.hpp"
#include "solver/contact/ContactPairing.hpp"
#include "solver/contact/MasterCellIndex.hpp"

#include <vector>

namespace stella::contact {

class MasterSurface {
public:
  MasterSurface() = default;
  // `cells` must be SEG2/SEG3 (dim 1) or TRIA3/TRIA6/QUAD4/QUAD8/QUAD9 (dim 2) cells.
  MasterSurface(const Mesh& mesh, const std::vector<CellId>& cells, int dim);

  int cellCount() const { return static_cast<int>(cells_.size()); }
  int nodeCount() const { return static_cast<int>(nodes_.size()); }
  CellId cell(int position) const { return cells_[static_cast<std::size_t>(position)]; }
  NodeId node(int local) const { return nodes_[static_cast<std::size_t>(local)]; }
  // Local node numbers of a cell, in its connectivity order.
  std::span<const int> cellNodes(int position) const;
  // Positions of the cells sharing a node with this one (itself included).
  std::span<const int> neighbours(int position) const;
  // Positions of the cells around a local node.
  std::span<const int> cellsOfNode(int local) const;
  // Local number of a mesh node, -1 when not on the surface.
  int local(NodeId n) const;

  // Reads the node positions (every call), then, when asked, the boxes and index (inflated by
  // `margin`) and the averaged unit nodal normals.
  void update(const NodePosition& position, bool withIndex, double margin, bool withNormals);
  const Point3& position(int local) const { return positions_[static_cast<std::size_t>(local)]; }
  void gather(int position, CellNodes& out) const;
  const MasterCellIndex& index() const { return index_; }
  const Box3& box(int position) const { return boxes_[static_cast<std::size_t>(position)]; }
  const Point3& nodalNormal(int local) const { return normals_[static_cast<std::size_t>(local)]; }
  // A length of the surface (its box's diagonal plus its largest coordinate): the scale of the
  // tie tolerance.
  double lengthScale() const { return lengthScale_; }
  // Mean half-diagonal of the cells' boxes: the first search radius.
  double meanCellSize() const { return meanCellSize_; }

private:
  int dim_ = 2;
  std::vector<CellId> cells_;
  std::vector<CellType> types_;
  std::vector<NodeId> nodes_; // sorted
  std::vector<int> cellStart_, cellNode_;
  std::vector<int> nodeStart_, nodeCell_;
  std::vector<int> neighbourStart_, neighbour_;
  std::vector<Point3> positions_;
  std::vector<Box3> boxes_;
  std::vector<Point3> normals_;
  MasterCellIndex index_;
  double lengthScale_ = 1.0;
  double meanCellSize_ = 0.0;
};

// Outward unit normal of a skin cell from its parametric derivatives.
Point3 cellNormalAt(const CellPoint& g, int dim);

} // namespace stella::contact
