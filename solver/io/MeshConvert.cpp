// Mesh conversion between the formats stella reads and writes (see MeshConvert.hpp).

#include "solver/io/MeshConvert.hpp"

#include "interpreter/Diagnostics.hpp"
#include "solver/io/MeshIO.hpp"

namespace stella {

namespace {

MeshFormat formatOf(const std::string& file) {
  const auto f = meshFormatFromExtension(file);
  if (!f) {
    throw UserError(
        Diagnostic::fatal("MESHCONV_1", "cannot tell the mesh format of '" + file + "' from its extension")
            .withNote("use .med (MED), .mail (ASTER) or .msh (Gmsh)"));
  }
  return *f;
}

} // namespace

void convertMesh(const std::string& in, const std::string& out) {
  const MeshFormat from = formatOf(in);
  const MeshFormat to = formatOf(out);
  Mesh mesh = readMesh(in, from);
  if (mesh.name().empty()) {
    mesh.setName("MAIL");
  }
  writeMesh(out, mesh, to);
}

} // namespace stella
