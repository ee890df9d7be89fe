#pragma once
// The methods of a mesh concept (type maillage), as code_aster's Mesh object has them:
// getNumberOfNodes, getNumberOfCells, getGroupsOfNodes, getGroupsOfCells, getCoordinates,
// getMinMaxEdgeSizes.

#include "solver/session/ConceptMethods.hpp"

#include <map>
#include <string>

namespace stella {

const std::map<std::string, ConceptMethod>& meshMethods();

} // namespace stella
