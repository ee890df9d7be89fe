// Candidate search of mortar pairing (see MortarSearch.hpp).

#include "solver/contact/mortar/MortarSearch.hpp"

#include "solver/mesh/CellTopology.hpp"

#include <algorithm>

namespace stella::mortar {

namespace {

bool meet(const contact::Box3& a, const contact::Box3& b) {
  for (std::size_t k = 0; k < 3; ++k) {
    if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) {
      return false;
    }
  }
  return true;
}

} // namespace

contact::Box3 slaveBox(CellType type, const Point3* points, int count, const SearchMargin& margin) {
  // The kernels use the vertices only (the linear hull of a face, the chord's ends and the
  // middle node of a SEG3): the box of a face is that of its vertices, not the wider box that
  // holds a curved cell (cellBox's Lebesgue scaling).
  const bool face = dimension(type) == 2;
  contact::Box3 b = face ? contact::cellBox(linearType(type), points, vertexCount(type), 0.0)
                         : contact::cellBox(type, points, count, 0.0);
  double side = 0.0;
  for (std::size_t k = 0; k < 3; ++k) {
    side = std::max(side, b.hi[k] - b.lo[k]);
  }
  const double m = margin.absolute + margin.relative * side;
  for (std::size_t k = 0; k < 3; ++k) {
    b.lo[k] -= m;
    b.hi[k] += m;
  }
  return b;
}

Candidates findCandidates(std::span<const contact::Box3> slaves, std::span<const contact::Box3> masters,
                          bool exhaustive) {
  Candidates out;
  out.offsets.reserve(slaves.size() + 1);
  std::vector<int> hits;
  if (exhaustive) {
    for (const auto& s : slaves) {
      for (std::size_t m = 0; m < masters.size(); ++m) {
        if (meet(s, masters[m])) {
          out.masters.push_back(static_cast<int>(m));
        }
      }
      out.offsets.push_back(out.masters.size());
    }
    return out;
  }
  contact::MasterCellIndex index;
  index.build(std::vector<contact::Box3>(masters.begin(), masters.end()));
  out.masters.reserve(slaves.size() * 4);
  for (const auto& s : slaves) {
    index.query(s, hits);
    std::sort(hits.begin(), hits.end());
    out.masters.insert(out.masters.end(), hits.begin(), hits.end());
    out.offsets.push_back(out.masters.size());
  }
  return out;
}

} // namespace stella::mortar
