#pragma once
// `stella convert in out`: reads a mesh and writes it in another format, both chosen by the file
// extension (.med, .mail, .msh). Errors are UserError (MESHFILE_*; MESHCONV_1 for an unknown
// extension).

#include <string>

namespace stella {

void convertMesh(const std::string& in, const std::string& out);

} // namespace stella
