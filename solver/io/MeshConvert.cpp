// Mesh conversion between the formats stella reads and writes (see MeshConvert.hpp).

#include "solver/io/MeshConvert.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/io/MeshIO.hpp"

namespace stella {

namespace {

MeshFormat formatOf(const std::string& file) {
  const auto f = meshFormatFromExtension(file);
  if (!f) {
    throw UserError(msg::make("MESHCONV_1", {{"file", file}}));
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
