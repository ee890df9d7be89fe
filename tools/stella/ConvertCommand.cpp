// `stella convert IN OUT`: mesh format conversion (Debian's gmsh cannot write MED).

#include "Commands.hpp"
#include "interpreter/Diagnostics.hpp"
#include "solver/io/MeshConvert.hpp"

#include <iostream>

namespace stella::cli {

int convert(const std::string& in, const std::string& out) {
  try {
    convertMesh(in, out);
    std::cerr << "stella: wrote " << out << "\n";
    return 0;
  } catch (const UserError& e) {
    for (const auto& d : e.diagnostics()) {
      std::cerr << formatDiagnostic(d);
    }
    return exitInput;
  }
}

} // namespace stella::cli
