#pragma once
// VERI_MAIL checks of LIRE_MAILLAGE: duplicate nodes (same position), degenerate cells (a node
// repeated or an edge of zero length), inverted cells (a negative corner jacobian of a volume
// cell; a face of a 2D mesh whose corner jacobians change sign, i.e. a folded face: a clockwise
// face is accepted, as in code_aster), flat cells (APLAT: measure / longest edge^dim below
// the threshold). Reported as alarms naming the nodes and cells:
//   MESHCHECK_1 duplicate nodes, MESHCHECK_2 degenerate cells, MESHCHECK_3 inverted cells,
//   MESHCHECK_4 flat cells.

#include "interpreter/Diagnostics.hpp"
#include "solver/mesh/Mesh.hpp"

#include <utility>
#include <vector>

namespace stella {

struct MeshCheckReport {
  std::vector<std::pair<NodeId, NodeId>> duplicateNodes;
  std::vector<CellId> degenerateCells;
  std::vector<CellId> invertedCells;
  std::vector<CellId> flatCells;
  bool clean() const {
    return duplicateNodes.empty() && degenerateCells.empty() && invertedCells.empty() && flatCells.empty();
  }
};

// `flatness` is VERI_MAIL/APLAT (code_aster default 1e-3). Nodes closer than 1e-10 times the
// bounding-box diagonal count as duplicates.
MeshCheckReport checkMesh(const Mesh& mesh, double flatness = 1e-3);
// One alarm per kind of problem found, naming up to 20 entities each.
std::vector<Diagnostic> meshCheckDiagnostics(const Mesh& mesh, const MeshCheckReport& report);

} // namespace stella
