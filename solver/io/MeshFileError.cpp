// Mesh file errors and whole-file reading (see MeshFileError.hpp).

#include "solver/io/MeshFileError.hpp"

#include <fstream>
#include <sstream>

namespace stella {

void throwFileError(const std::string& id, const std::filesystem::path& file, const std::string& what,
                    int line) {
  std::string where = "'" + file.string() + "'";
  if (line > 0) {
    where += " line " + std::to_string(line);
  }
  throw UserError(
      Diagnostic::fatal(id, "mesh file " + where + ": " + what)
          .withNote("check that the unit points to the right file and that the FORMAT matches it"));
}

std::string readWholeFile(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    throwFileError("MESHFILE_1", file, "the file does not exist or is not a regular file");
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    throwFileError("MESHFILE_1", file, "the file cannot be opened for reading");
  }
  std::ostringstream s;
  s << in.rdbuf();
  std::string text = s.str();
  if (text.empty()) {
    throwFileError("MESHFILE_1", file, "the file is empty");
  }
  return text;
}

} // namespace stella
