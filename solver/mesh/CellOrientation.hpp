#pragma once
// MODI_MAILLAGE/ORIE_NORM_COQUE and ORIE_LIGNE: consistent orientation of connected shell cells
// (faces) and of chains of line cells (segments).
//
// Two faces sharing an edge agree when they run along it in opposite directions; two segments
// sharing a node agree when one ends where the other starts. Each connected set of cells is
// oriented like its reference cell. Without a direction the reference is the set's first cell in
// the list, kept as it is. With a direction (VECT_NORM / VECT_TANG) the reference is the cell
// whose normal (tangent) is most nearly parallel to it, among the cells holding `node`
// (GROUP_NO) when the set holds that node, else among all; it is turned so that its normal
// (tangent) has a positive component along the direction.
// Throws UserError ORIE_1 when a set cannot be oriented (three cells on one edge or node, a
// Moebius band), ORIE_2 for a cell of the wrong dimension.

#include "solver/mesh/Mesh.hpp"

#include <optional>
#include <vector>

namespace stella {

struct OrientationSummary {
  int reversed = 0;   // cells whose node order was reversed
  int components = 0; // connected sets of cells
};

OrientationSummary orientShells(Mesh& mesh, const std::vector<CellId>& faces,
                                const std::optional<Point3>& direction, std::optional<NodeId> node);
OrientationSummary orientLines(Mesh& mesh, const std::vector<CellId>& segments,
                               const std::optional<Point3>& direction, std::optional<NodeId> node);

// Orients every cell of `cells` (faces or segments) whose `fixed` flag is false like the fixed
// cells of its connected set (faces through shared edges, segments through shared nodes; a cell
// takes its orientation from the first oriented neighbour reaching it); fixed cells stay as they
// are. A set without a fixed cell is made coherent with its first cell, and its cells are
// appended to `unanchored`. Returns the cells reversed and the number of sets.
OrientationSummary propagateOrientation(Mesh& mesh, const std::vector<CellId>& cells,
                                        const std::vector<bool>& fixed, std::vector<CellId>& unanchored);

} // namespace stella
