#pragma once
// Writers of results (IMPR_RESU): MED (mesh + nodal, per-cell, Gauss-point and cell-node fields
// with component names, one MED time step per stored step: numdt = NUME_ORDRE, dt = INST),
// VTU/PVD (nodal and per-cell fields, binary zlib; ParaView opens them with no plugin), Gmsh .msh 2.2 with
// $NodeData/$ElementData, and FORMAT='RESULTAT' text tables.
//
// MED field names follow code_aster: the result name padded to 8 characters with '_' then the
// field name (RESU____DEPL). A component absent on some entities (Field::partial) is written
// with a MED profile holding the entities where at least one component is defined (0 for the
// undefined components of those entities).

#include "solver/database/Field.hpp"
#include "solver/database/Result.hpp"
#include "solver/io/RealEditDescriptor.hpp"
#include "solver/mesh/Mesh.hpp"

#include <array>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace stella {

// Reference coordinates of the Gauss points of a cell type for a family of `count` points
// (empty when unknown: the points are then written at the cell's reference centroid).
using GaussPointProvider = std::function<std::vector<Point3>(CellType, int count)>;

struct ResultOutput {
  std::string resultName = "RESU";     // concept name: MED field prefix, table titles
  std::vector<std::string> fields;     // NOM_CHAM; empty = every field
  std::vector<int> steps;              // NUME_ORDRE; empty = every step
  std::vector<std::string> components; // NOM_CMP filter; empty = every component
  GaussPointProvider gaussPoints;
  // GROUP_NO / GROUP_MA of FORMAT='RESULTAT': the nodes (nodal fields) and cells (per-cell and
  // per-point fields) whose rows are printed; empty = every one. The other formats write all.
  std::vector<bool> nodes;
  std::vector<bool> cells;
  // FORMAT_R of FORMAT='RESULTAT': the edit descriptor of the printed values (unset: 1PE13.6).
  std::optional<RealEditDescriptor> valueFormat;
  // VERSION_MED of FORMAT='MED': major, minor, release of the MED format written ({0, 0, 0}: the
  // library's own).
  std::array<int, 3> medVersion{0, 0, 0};
};

// The code_aster MED field name: RESU____DEPL.
std::string medFieldName(const std::string& resultName, const std::string& field);

// Writes the mesh (named `meshName`, or the mesh's name, or "MAIL") and the result's fields.
// `append`: add to an existing file that already holds the mesh (a second IMPR_RESU on unit 80).
void writeMedResult(const std::filesystem::path& file, const Mesh& mesh, const std::string& meshName,
                    const Result* result, const ResultOutput& output, bool append = false);

// One .vtu per step (<stem>_<NUME_ORDRE>.vtu beside `pvdFile`) and the .pvd collection with the
// times; nodal fields as point data, per-cell fields as cell data, Gauss-point and cell-node
// fields as cell data holding the mean of each cell's points (one array per field, its
// components as the tuple). Binary appended data compressed with zlib; NaN where a field has no
// value; DX, DY fields get DZ = 0 (3-vectors). Returns the files written.
std::vector<std::filesystem::path> writeVtuResult(const std::filesystem::path& pvdFile, const Mesh& mesh,
                                                  const Result* result, const ResultOutput& output);

// Gmsh 2.2 ASCII: the mesh then one $NodeData / $ElementData block per field and step.
void writeGmshResult(const std::filesystem::path& file, const Mesh& mesh, const Result* result,
                     const ResultOutput& output);

// FORMAT='RESULTAT': for each step and field, a table of the entities (node or cell names)
// and their component values.
std::string formatResultTables(const Mesh& mesh, const Result& result, const ResultOutput& output);

} // namespace stella
