// stella-mesh: writes a structured rectangle or box mesh (solver/mesh/StructuredMesher.hpp) in
// MED, ASTER or Gmsh format, chosen by the output extension. Reproducible: the same arguments
// always give the same file.
//   stella-mesh --type HEXA8 --div 4 4 8 --size 1 1 2 -o block.med
//   stella-mesh --type QUAD8 --div 10 2 --size 5 1 --origin 0 -1 -o beam.mail

#include "interpreter/Diagnostics.hpp"
#include "solver/io/MeshIO.hpp"
#include "solver/mesh/StructuredMesher.hpp"

#include <CLI/CLI.hpp>

#include <iostream>

int main(int argc, char** argv) {
  CLI::App app{"stella-mesh: structured meshes of rectangles and boxes"};
  std::string type = "QUAD4";
  std::vector<int> div{1, 1, 1};
  std::vector<double> size{1.0, 1.0, 1.0};
  std::vector<double> origin{0.0, 0.0, 0.0};
  std::string output;
  std::string meshName = "MAIL";
  app.add_option("--type", type,
                 "cell type: QUAD4 QUAD8 QUAD9 TRIA3 TRIA6 HEXA8 HEXA20 HEXA27 TETRA4 TETRA10 "
                 "PENTA6 PENTA15 PENTA18");
  app.add_option("--div", div, "divisions along x, y (and z)")->expected(2, 3);
  app.add_option("--size", size, "lengths along x, y (and z)")->expected(2, 3);
  app.add_option("--origin", origin, "corner with the smallest coordinates")->expected(2, 3);
  app.add_option("--name", meshName, "mesh name in MED files");
  app.add_option("-o,--output", output, "output file (.med, .mail or .msh)")->required();
  CLI11_PARSE(app, argc, argv);
  try {
    const auto t = stella::cellTypeFromName(type);
    if (!t) {
      std::cerr << "stella-mesh: unknown cell type " << type << "\n";
      return 2;
    }
    stella::StructuredSpec spec;
    spec.type = *t;
    for (std::size_t d = 0; d < 3; ++d) {
      spec.divisions[d] = d < div.size() ? div[d] : 1;
      spec.lengths[d] = d < size.size() ? size[d] : 1.0;
      spec.origin[d] = d < origin.size() ? origin[d] : 0.0;
    }
    stella::Mesh mesh = stella::buildStructuredMesh(spec);
    mesh.setName(meshName);
    const auto format = stella::meshFormatFromExtension(output);
    if (!format) {
      std::cerr << "stella-mesh: use a .med, .mail or .msh output file\n";
      return 2;
    }
    stella::writeMesh(output, mesh, *format);
    std::cout << output << ": " << mesh.nodeCount() << " nodes, " << mesh.cellCount() << " cells\n";
  } catch (const stella::UserError& e) {
    std::cerr << "stella-mesh: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
