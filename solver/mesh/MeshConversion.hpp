#pragma once
// CREA_MAILLAGE operations as library functions; each returns a new mesh with the same names for
// the nodes and cells it keeps (new nodes get generated names) and the groups carried over.
//   LINE_QUAD  linear cells -> quadratic (SEG2->SEG3 ... HEXA8->HEXA20), mid nodes shared
//   QUAD_LINE  quadratic cells -> linear, unused nodes removed
//   HEXA20_27  HEXA20 -> HEXA27 and QUAD8 -> QUAD9; PENTA15_18: PENTA15 -> PENTA18, QUAD8 -> QUAD9
//   MODI_MAILLE QUAD8_9, TRIA6_7, SEG3_4
//   CREA_POI1  a POI1 cell on each given node
//   RESTREINT  only the given cells and the nodes they use
// New nodes are placed with the cell's own interpolation (mid-edge at the middle of straight
// edges; face and cell centres from the serendipity shape functions, so curved quadratic cells
// stay curved).

#include "solver/mesh/Mesh.hpp"

#include <string>
#include <vector>

namespace stella {

enum class CellConversion { LineToQuad, QuadToLine, Hexa20To27, Penta15To18, Quad8To9, Tria6To7, Seg3To4 };

// Converts the cells in `cells` (all cells when empty) that the conversion applies to.
Mesh convertCells(const Mesh& mesh, CellConversion conversion, const std::vector<CellId>& cells);
// Adds POI1 cells on `nodes` (named M<n>...), grouped in `groupName` when not empty.
Mesh addPointCells(const Mesh& mesh, const std::vector<NodeId>& nodes, const std::string& groupName);
// Keeps `cells` and their nodes; cell groups `keepCellGroups` and node groups `keepNodeGroups`
// are restricted to what remains (other groups are dropped).
Mesh restrictMesh(const Mesh& mesh, const std::vector<CellId>& cells,
                  const std::vector<std::string>& keepCellGroups,
                  const std::vector<std::string>& keepNodeGroups);

} // namespace stella
