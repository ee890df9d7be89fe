#pragma once
// Gmsh element types and node orderings mapped to code_aster's cell types and orderings.

#include "solver/mesh/CellType.hpp"

#include <optional>
#include <span>

namespace stella {

std::optional<CellType> cellTypeFromGmsh(int gmshType);
int gmshTypeOf(CellType t); // 0 when Gmsh has no such type (TRIA7)
// aster[j] = gmsh[perm[j]] (0-based): the Gmsh index of each code_aster node.
std::span<const int> gmshPermutation(CellType t);

} // namespace stella
