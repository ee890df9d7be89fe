#pragma once
// Errors about mesh and result files: every one is a UserError that names the file and says
// what is wrong (and the line for text formats). The texts are in messages/mesh.msg. Message ids:
//   MESHFILE_1  the file cannot be opened, or is empty
//   MESHFILE_2  syntax error in a text format (line given)
//   MESHFILE_3  inconsistent content (unknown node, bad count, non-finite coordinate...)
//   MESHFILE_4  the MED/HDF5 library refused the file or an operation on it
//   MESHFILE_5  a feature of the format that is not implemented yet
//   MESHFILE_6  the mesh named by NOM_MED is not in the file
//   MESHFILE_7  the file cannot be written

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"

#include <filesystem>
#include <string>

namespace stella {

// Throws catalogue entry `key` (MESHFILE_n) formatted with `args`, its text prefixed with the
// file (and the line when > 0), followed by the advice to check the unit and the FORMAT.
[[noreturn]] void throwFileError(std::string_view key, const std::filesystem::path& file, msg::Args args = {},
                                 int line = 0);

// The whole content of a file; MESHFILE_1 when it cannot be read.
std::string readWholeFile(const std::filesystem::path& file);

} // namespace stella
