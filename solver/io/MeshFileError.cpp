// Mesh file errors and whole-file reading (see MeshFileError.hpp).

#include "solver/io/MeshFileError.hpp"

#include <fstream>
#include <sstream>

namespace stella {

void throwFileError(std::string_view key, const std::filesystem::path& file, msg::Args args, int line) {
  Diagnostic d = msg::make(key, args);
  d.message =
      line > 0 ? msg::text("MESHFILE.at_line", {{"file", file.string()}, {"line", line}, {"what", d.message}})
               : msg::text("MESHFILE.at", {{"file", file.string()}, {"what", d.message}});
  throw UserError(std::move(d.withNote(msg::text("MESHFILE.n1"))));
}

std::string readWholeFile(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    throwFileError("MESHFILE_1", file, {});
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    throwFileError("MESHFILE_1.2", file, {});
  }
  std::ostringstream s;
  s << in.rdbuf();
  std::string text = s.str();
  if (text.empty()) {
    throwFileError("MESHFILE_1.3", file, {});
  }
  return text;
}

} // namespace stella
