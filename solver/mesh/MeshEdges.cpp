#include "MeshEdges.hpp"

#include "solver/mesh/CellTopology.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stella {

std::pair<double, double> minMaxEdgeLengths(const Mesh& mesh, std::span<const CellId> cells) {
  double shortest = std::numeric_limits<double>::infinity();
  double longest = 0.0;
  for (CellId c : cells) {
    if (shapeOf(mesh.cellType(c)) == CellShape::Point) {
      continue;
    }
    const auto nodes = mesh.cellNodes(c);
    for (const CellEdge& e : cellEdges(mesh.cellType(c))) {
      const Point3 a = mesh.point(nodes[static_cast<std::size_t>(e.a)]);
      const Point3 b = mesh.point(nodes[static_cast<std::size_t>(e.b)]);
      const double length = std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
      longest = std::max(longest, length);
      if (length > 0.0) {
        shortest = std::min(shortest, length);
      }
    }
  }
  return {std::isinf(shortest) ? 0.0 : shortest, longest};
}

} // namespace stella
