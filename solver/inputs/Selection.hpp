#pragma once
// The cells and nodes a factor keyword occurrence designates (TOUT, GROUP_MA, MAILLE, GROUP_NO,
// NOEUD, SANS_GROUP_MA, SANS_GROUP_NO), with user errors naming the group or name that the mesh
// does not have and listing the ones it has.

#include "catalog/KeywordTree.hpp"
#include "solver/mesh/Mesh.hpp"

#include <string>
#include <vector>

namespace stella {

// Cells of TOUT / GROUP_MA / MAILLE (sorted, unique), minus SANS_GROUP_MA.
std::vector<CellId> selectCells(const Mesh& mesh, const KeywordTree& occurrence);

// Nodes of TOUT / GROUP_MA / MAILLE / GROUP_NO / NOEUD (sorted, unique), minus SANS_GROUP_NO and
// the nodes of SANS_GROUP_MA.
std::vector<NodeId> selectNodes(const Mesh& mesh, const KeywordTree& occurrence);

// The cells of one group, or UserError GROUP_1 naming it (keyword gives the location).
const std::vector<CellId>& cellGroupOrThrow(const Mesh& mesh, const std::string& group,
                                            const KeywordTree& occurrence, const std::string& keyword);
const std::vector<NodeId>& nodeGroupOrThrow(const Mesh& mesh, const std::string& group,
                                            const KeywordTree& occurrence, const std::string& keyword);
NodeId nodeOrThrow(const Mesh& mesh, const std::string& name, const KeywordTree& occurrence,
                   const std::string& keyword);
// The cell named `name`, or UserError GROUP_4 (keyword gives the location).
CellId cellOrThrow(const Mesh& mesh, const std::string& name, const KeywordTree& occurrence,
                   const std::string& keyword);

// "A, B, C" (at most `limit` names, then "...").
std::string listNames(const std::vector<std::string>& names, std::size_t limit = 12);

} // namespace stella
