#pragma once
// Reading and writing meshes: Gmsh .msh (2.2 and 4.1, ASCII or binary), ASTER .mail, MED
// (libmedC, MED 3/4 and 2.3 layouts); reading only: GIBI (Cast3M SAUVER FORMATTE, .mgib).
// Every reader returns a Mesh in code_aster's node orderings, or throws UserError (MESHFILE_*,
// see MeshFileError.hpp) naming the file and the problem; readers never crash on damaged files.
//
// Groups: Gmsh physical groups become cell groups named by their physical name ("GM<tag>"
// without a name) and node groups of the same name (the nodes of those cells); MED families
// become cell and node groups; .mail GROUP_MA/GROUP_NO blocks become groups; named GIBI mesh objects
// become GROUP_MA, named GIBI points GROUP_NO of one node (see GibiReader.cpp).

#include "solver/mesh/Mesh.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace stella {

enum class MeshFormat { Med, Aster, Gmsh, Gibi };

// By extension: .med/.rmed/.mmed -> Med, .mail/.mai -> Aster, .msh -> Gmsh, .mgib -> Gibi.
std::optional<MeshFormat> meshFormatFromExtension(const std::filesystem::path& file);

Mesh readGmshMesh(const std::filesystem::path& file);
Mesh readAsterMesh(const std::filesystem::path& file);
Mesh readGibiMesh(const std::filesystem::path& file);
// `meshName` empty: the first mesh of the file (as LIRE_MAILLAGE without NOM_MED).
Mesh readMedMesh(const std::filesystem::path& file, const std::string& meshName = "");
// Names of the meshes in a MED file, in file order.
std::vector<std::string> medMeshNames(const std::filesystem::path& file);
Mesh readMesh(const std::filesystem::path& file, MeshFormat format, const std::string& medMeshName = "");

// Writers. MED: the mesh named `meshName` (mesh.name() or "MAIL" when empty) with node and cell
// names and the groups as families; `append` adds the mesh to an existing file.
void writeMedMesh(const std::filesystem::path& file, const Mesh& mesh, const std::string& meshName = "",
                  bool append = false);
// ASTER .mail: coordinates with 17 significant digits (readAsterMesh gives back the same doubles),
// one cell block per run of cells of one type, then the groups; `title` fills the TITRE block.
void writeAsterMesh(const std::filesystem::path& file, const Mesh& mesh,
                    const std::vector<std::string>& title = {"written by stella"});
// Gmsh 2.2 ASCII; each cell group becomes a physical group (a cell in several groups is written
// once per group with the same element tag, which readGmshMesh merges back into one cell).
void writeGmshMesh(const std::filesystem::path& file, const Mesh& mesh);
// GIBI: MESHFILE_5 (writing GIBI is not implemented yet).
void writeMesh(const std::filesystem::path& file, const Mesh& mesh, MeshFormat format);

} // namespace stella
