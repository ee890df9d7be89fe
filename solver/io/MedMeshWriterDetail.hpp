#pragma once
// Internals shared by the MED mesh writer and the MED result writer: writing a mesh into an open
// file, and the order in which cells are written (by increasing MED geometry type), which cell
// fields must follow.

#include "solver/io/MedCommon.hpp"
#include "solver/mesh/Mesh.hpp"

#include <string>
#include <vector>

namespace stella {

void writeMedMeshInto(const MedFile& file, const Mesh& mesh, const std::string& meshName);
// order[k] = the cell written in position k.
std::vector<CellId> medWriteOrder(const Mesh& mesh);

} // namespace stella
