#pragma once
// CREA_MAILLAGE/DECOUPE_LAC: cuts the cells under the slave surfaces of LAC (mortar) contact so
// that every slave cell of the original mesh becomes a patch of smaller slave cells (the cuts are
// in LacCellCuts.hpp). A cell with several slave faces is cut along each in turn (the second
// face is a face of one of the first cut's pieces).
//
// The result: the uncut cells and nodes unchanged (same names), the pieces after them in place of
// their cell (new names M<n+1>..., n the original cell count, as code_aster names them), new
// nodes named N<m+1>...; every GROUP_MA holding a cut cell holds its pieces instead; every
// GROUP_NO keeps its nodes and gains the new nodes on a slave cell whose nodes it holds all (code_aster
// keeps node groups unchanged: a GROUP_NO of a whole face would otherwise miss the new nodes of
// the face); new nodes inside the cells join no group; the patches are recorded in
// Mesh::lacPatches().
//
// Errors (UserError at `at`): CREALAC_1 a GROUP_MA_ESCL cell of the wrong dimension, CREALAC_2 a
// slave cell that is the face of no cell (MESH1_2 in code_aster) or of two (not on the boundary),
// CREALAC_3 a slave cell whose nodes differ from its cell's face (a SEG2 on a QUAD8),
// CREALAC_4 a pair of cell types DECOUPE_LAC does not cut ("not implemented yet").

#include "interpreter/SourceFile.hpp"
#include "solver/mesh/LacCellCuts.hpp"

#include <string>
#include <vector>

namespace stella {

struct LacCuttingReport {
  std::vector<int> slaveCellsPerGroup; // original slave cells of each group (code_aster MESH1_3)
  int cutCells = 0;                    // cuts made
};

Mesh cutMeshForLac(const Mesh& mesh, const std::vector<std::string>& slaveGroups, LacHexaCut mode,
                   const SourceLocation& at, LacCuttingReport* report = nullptr);

} // namespace stella
