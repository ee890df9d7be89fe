#pragma once
// Lengths of the edges of cells, as code_aster's Mesh.getMinMaxEdgeSizes computes them: the
// straight distance between the two vertices of each edge of each cell (mid-edge nodes of
// quadratic cells do not count, point cells have no edge).

#include "solver/mesh/Mesh.hpp"

#include <span>
#include <utility>

namespace stella {

// (shortest, longest) edge of the cells; edges of zero length are not counted as shortest, and
// the shortest is 0 when no edge has a positive length.
std::pair<double, double> minMaxEdgeLengths(const Mesh& mesh, std::span<const CellId> cells);

} // namespace stella
