// Text result writers (see ResultWriters.hpp): Gmsh 2.2 node and element data, and
// FORMAT='RESULTAT' tables. VTU/PVD is in VtuResultWriter.cpp.

#include "solver/io/GmshCellTypes.hpp"
#include "solver/io/MeshFileError.hpp"
#include "solver/io/MeshIO.hpp"
#include "solver/io/ResultSelection.hpp"
#include "solver/io/ResultWriters.hpp"
#include "solver/mesh/CellTopology.hpp"
#include "solver/mesh/MeshTransform.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>

namespace stella {

namespace {

using detail::keptComponents;
using detail::selectedFields;
using detail::selectedSteps;

double valueOr0(const Field& f, std::size_t e, std::size_t c) {
  return !f.partial() || f.defined(e, c) ? f.value(e, c) : 0.0;
}

} // namespace

void writeGmshResult(const std::filesystem::path& file, const Mesh& mesh, const Result* result,
                     const ResultOutput& output) {
  writeGmshMesh(file, mesh);
  std::ofstream out(file, std::ios::app);
  if (!out) {
    throwFileError("MESHFILE_7.8", file, {});
  }
  for (const auto& name : selectedFields(result, output)) {
    for (const ResultStep* s : selectedSteps(result, output)) {
      const Field* f = s->field(name);
      if (f == nullptr || (f->support() != FieldSupport::Node && f->support() != FieldSupport::Cell)) {
        continue;
      }
      const bool nodal = f->support() == FieldSupport::Node;
      for (const auto c : keptComponents(*f, output)) {
        const std::size_t count =
            nodal ? static_cast<std::size_t>(mesh.nodeCount()) : static_cast<std::size_t>(mesh.cellCount());
        out << (nodal ? "$NodeData\n" : "$ElementData\n") << "1\n\"" << name << "_" << f->components()[c]
            << "\"\n"
            << "1\n"
            << fmt::format("{:.17g}", s->time) << "\n3\n"
            << s->number << "\n1\n"
            << count << "\n";
        for (std::size_t e = 0; e < count; ++e) {
          out << e + 1 << fmt::format(" {:.17g}\n", e < f->entityCount() ? valueOr0(*f, e, c) : 0.0);
        }
        out << (nodal ? "$EndNodeData\n" : "$EndElementData\n");
      }
    }
  }
}

std::string formatResultTables(const Mesh& mesh, const Result& result, const ResultOutput& output) {
  std::string s;
  for (const ResultStep* step : selectedSteps(&result, output)) {
    for (const auto& name : selectedFields(&result, output)) {
      const Field* f = step->field(name);
      if (f == nullptr) {
        continue;
      }
      const auto k = keptComponents(*f, output);
      const RealEditDescriptor number = output.valueFormat.value_or(RealEditDescriptor{'E', 'E', 1, 13, 6});
      s += fmt::format("\n CHAMP {} DU RESULTAT {} NUME_ORDRE {} INST {:.6E} ({})\n", name, output.resultName,
                       step->number, step->time, f->quantity());
      std::string header = f->support() == FieldSupport::Node ? " NOEUD   " : " MAILLE  ";
      if (f->support() == FieldSupport::GaussPoint || f->support() == FieldSupport::CellNode) {
        header += " POINT";
      }
      for (const auto c : k) {
        header += fmt::format(" {:>{}}", f->components()[c], number.width);
      }
      s += header + "\n";
      const auto row = [&](const std::string& label, std::size_t e) {
        std::string line = label;
        for (const auto c : k) {
          line += " " + (!f->partial() || f->defined(e, c) ? formatReal(number, f->value(e, c))
                                                           : fmt::format("{:>{}}", "-", number.width));
        }
        s += line + "\n";
      };
      const auto printed = [](const std::vector<bool>& selection, std::size_t e) {
        return selection.empty() || (e < selection.size() && selection[e]);
      };
      if (f->support() == FieldSupport::Node) {
        for (std::size_t e = 0; e < f->entityCount() && e < static_cast<std::size_t>(mesh.nodeCount()); ++e) {
          if (printed(output.nodes, e)) {
            row(fmt::format(" {:<8}", mesh.nodeName(static_cast<NodeId>(e))), e);
          }
        }
      } else if (f->support() == FieldSupport::Cell) {
        for (std::size_t e = 0; e < f->entityCount() && e < static_cast<std::size_t>(mesh.cellCount()); ++e) {
          if (printed(output.cells, e)) {
            row(fmt::format(" {:<8}", mesh.cellName(static_cast<CellId>(e))), e);
          }
        }
      } else {
        for (std::size_t c = 0; c < f->cellCount() && c < static_cast<std::size_t>(mesh.cellCount()); ++c) {
          if (!printed(output.cells, c)) {
            continue;
          }
          for (int p = 0; p < f->pointCount(c); ++p) {
            row(fmt::format(" {:<8} {:>5}", mesh.cellName(static_cast<CellId>(c)), p + 1),
                f->firstPoint(c) + static_cast<std::size_t>(p));
          }
        }
      }
    }
  }
  return s;
}

} // namespace stella
