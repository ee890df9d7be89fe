#pragma once
// The spatial index of a contact zone's master cells: a Boost.Geometry R-tree (bulk-loaded,
// R*-tree parameters) of the cells' axis-aligned bounding boxes. One index serves both searches:
//   - node-to-surface pairing (ContactPairing): the cells whose boxes meet a cube around a slave
//     node (the box distance bounds the node-to-cell distance from below, so growing the cube
//     until it holds an admissible projection, then once more to that distance, is exact);
//   - mortar (LAC) cell-cell search: `query(box)` with a slave cell's box gives the candidate
//     master cells to intersect.
// A cell's box holds the whole cell, curved ones included (the nodes' box scaled about its
// centre by the Lebesgue bound of the interpolation, SurfaceShape.hpp), inflated by a margin the
// caller chooses (DIST_APPA, or a tolerance for the mortar search). Queries write into a
// caller-owned vector (cleared first) and do not allocate once its capacity suffices.

#include "solver/mesh/Mesh.hpp"

#include <memory>
#include <vector>

namespace stella::contact {

struct Box3 {
  Point3 lo{0, 0, 0};
  Point3 hi{0, 0, 0};
};

// Box of a cell whose node positions are `points` (count of them), holding every point of the
// cell of that type (curved cells: see above), inflated by `margin` on every side.
Box3 cellBox(CellType type, const Point3* points, int count, double margin);

// Squared Euclidean distance from x to the box (0 inside).
double squaredDistance(const Box3& box, const Point3& x);

class MasterCellIndex {
public:
  MasterCellIndex();
  ~MasterCellIndex();
  MasterCellIndex(MasterCellIndex&&) noexcept;
  MasterCellIndex& operator=(MasterCellIndex&&) noexcept;

  // Rebuilds the index over `boxes`; the value returned by queries is the box's position in it.
  void build(const std::vector<Box3>& boxes);
  std::size_t size() const;
  bool empty() const { return size() == 0; }

  // Positions of the boxes that meet `box` (unordered).
  void query(const Box3& box, std::vector<int>& out) const;
  // Positions of the boxes within `half` (L-infinity) of x: query of the cube centred at x.
  void queryAround(const Point3& x, double half, std::vector<int>& out) const;

private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

} // namespace stella::contact
