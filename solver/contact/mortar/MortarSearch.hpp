#pragma once
// Candidate search of mortar pairing, the same for 2D (segments) and 3D (faces): the slave and
// master cells as axis-aligned boxes (2D cells in the plane z = 0), the master boxes in the
// R-tree of MasterCellIndex (bulk-loaded, O(n log n)), one box query per slave cell. The result
// lists, for every slave cell, the masters whose boxes meet its box, in ascending order (so that
// the overlaps come out in the same order as an all-pairs loop, whatever the tree's layout).
//
// The boxes are the caller's; `slaveBox` below is the box of what the kernels use (a face's
// vertices: MortarPolygons clips the linear hulls; a segment's nodes, the SEG3 curve held by
// cellBox's scaling) inflated by a margin, absolute plus relative to the cell's size, so that
// masters across a gap, and faceted or warped surfaces that do not coincide, are found. Masters
// get a zero margin (the slave's margin covers the pair).

#include "solver/contact/MasterCellIndex.hpp"

#include <cstddef>
#include <span>
#include <vector>

namespace stella::mortar {

struct SearchMargin {
  double absolute = 0.0;  // added on every side (e.g. the largest gap to pair across)
  double relative = 0.25; // times the largest side of the cell's box
};

// Candidate masters per slave, compressed: slave s has masters[offsets[s] .. offsets[s + 1]).
struct Candidates {
  std::vector<std::size_t> offsets{0};
  std::vector<int> masters;
  std::span<const int> of(std::size_t slave) const {
    return {masters.data() + offsets[slave], offsets[slave + 1] - offsets[slave]};
  }
  std::size_t slaveCount() const { return offsets.size() - 1; }
};

// The box of a cell of `type` with nodes `points` (count of them), inflated by `margin`.
contact::Box3 slaveBox(CellType type, const Point3* points, int count, const SearchMargin& margin);

// The masters whose boxes meet each slave box: R-tree queries, or every pair tested when
// `exhaustive` (the reference of the tests and the benchmark).
Candidates findCandidates(std::span<const contact::Box3> slaves, std::span<const contact::Box3> masters,
                          bool exhaustive = false);

} // namespace stella::mortar
