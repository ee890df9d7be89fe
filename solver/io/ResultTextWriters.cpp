// Text result writers (see ResultWriters.hpp): VTU/PVD (VTK XML, ASCII), Gmsh 2.2 node and
// element data, and FORMAT='RESULTAT' tables.

#include "solver/io/GmshCellTypes.hpp"
#include "solver/io/MeshFileError.hpp"
#include "solver/io/MeshIO.hpp"
#include "solver/io/ResultWriters.hpp"
#include "solver/mesh/CellTopology.hpp"
#include "solver/mesh/MeshTransform.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>

namespace stella {

namespace {

std::vector<const ResultStep*> steps(const Result* result, const ResultOutput& out) {
  std::vector<const ResultStep*> s;
  if (result != nullptr) {
    for (const auto& step : result->steps) {
      if (out.steps.empty() ||
          std::find(out.steps.begin(), out.steps.end(), step.number) != out.steps.end()) {
        s.push_back(&step);
      }
    }
  }
  return s;
}

std::vector<std::string> fields(const Result* result, const ResultOutput& out) {
  return result == nullptr ? std::vector<std::string>{}
                           : (out.fields.empty() ? result->fieldNames() : out.fields);
}

std::vector<std::size_t> kept(const Field& f, const ResultOutput& out) {
  std::vector<std::size_t> k;
  for (std::size_t c = 0; c < f.componentCount(); ++c) {
    if (out.components.empty() ||
        std::find(out.components.begin(), out.components.end(), f.components()[c]) != out.components.end()) {
      k.push_back(c);
    }
  }
  return k;
}

double valueOr0(const Field& f, std::size_t e, std::size_t c) {
  return !f.partial() || f.defined(e, c) ? f.value(e, c) : 0.0;
}

std::ofstream openOut(const std::filesystem::path& file) {
  std::ofstream out(file);
  if (!out) {
    throwFileError("MESHFILE_7", file, "the file cannot be opened for writing");
  }
  return out;
}

// VTK cell type and the code_aster node feeding each VTK node.
struct VtkCell {
  int type;
  std::vector<int> perm; // vtk[i] = aster[perm[i]]
};

VtkCell vtkCell(CellType t) {
  std::vector<int> id(static_cast<std::size_t>(nodeCount(t)));
  for (std::size_t i = 0; i < id.size(); ++i) {
    id[i] = static_cast<int>(i);
  }
  // Quadratic hexahedra and wedges list the top edges before the vertical ones in VTK.
  const auto swapTopVertical = [](std::vector<int> p, int first, int count) {
    std::vector<int> q = p;
    for (int i = 0; i < count; ++i) {
      q[static_cast<std::size_t>(first + i)] = p[static_cast<std::size_t>(first + count + i)];
      q[static_cast<std::size_t>(first + count + i)] = p[static_cast<std::size_t>(first + i)];
    }
    return q;
  };
  // VTK wedges turn their first triangle the other way: reverse the code_aster cell first.
  const auto reversedWedge = [&]() { return orientationReversal(t); };
  switch (t) {
  case CellType::POI1:
    return {1, id};
  case CellType::SEG2:
    return {3, id};
  case CellType::SEG3:
    return {21, id};
  case CellType::SEG4:
    return {35, id};
  case CellType::TRIA3:
    return {5, id};
  case CellType::TRIA6:
    return {22, id};
  case CellType::TRIA7:
    return {34, id};
  case CellType::QUAD4:
    return {9, id};
  case CellType::QUAD8:
    return {23, id};
  case CellType::QUAD9:
    return {28, id};
  case CellType::TETRA4:
    return {10, id};
  case CellType::TETRA10:
    return {24, id};
  case CellType::PYRAM5:
    return {14, id};
  case CellType::PYRAM13:
    return {27, id};
  case CellType::HEXA8:
    return {12, id};
  case CellType::HEXA20:
    return {25, swapTopVertical(id, 12, 4)};
  case CellType::HEXA27: {
    auto p = swapTopVertical(id, 12, 4);
    const int faces[6] = {24, 22, 21, 23, 20, 25}; // VTK x-, x+, y-, y+, z-, z+
    for (int i = 0; i < 6; ++i) {
      p[static_cast<std::size_t>(20 + i)] = faces[i];
    }
    return {29, p};
  }
  case CellType::PENTA6:
    return {13, reversedWedge()};
  case CellType::PENTA15: {
    const auto r = reversedWedge();
    auto p = swapTopVertical(r, 9, 3);
    return {26, p};
  }
  case CellType::PENTA18: {
    const auto r = reversedWedge();
    auto p = swapTopVertical(r, 9, 3);
    return {32, p};
  }
  }
  return {1, id};
}

void vtuArray(std::ofstream& out, const std::string& name, const Field& f, const std::vector<std::size_t>& k,
              std::size_t count) {
  out << "        <DataArray type=\"Float64\" Name=\"" << name << "\" NumberOfComponents=\"" << k.size()
      << "\"";
  for (std::size_t i = 0; i < k.size(); ++i) {
    out << " ComponentName" << i << "=\"" << f.components()[k[i]] << "\"";
  }
  out << " format=\"ascii\">\n";
  for (std::size_t e = 0; e < count; ++e) {
    out << "          ";
    for (const auto c : k) {
      out << fmt::format("{:.17g} ", e < f.entityCount() ? valueOr0(f, e, c) : 0.0);
    }
    out << "\n";
  }
  out << "        </DataArray>\n";
}

// Gauss-point and cell-node fields as cell data: the mean of each cell's points (0 for cells
// without points), so that ParaView shows SIEF_ELGA without a plugin.
Field cellMeans(const Field& f, std::size_t cellCount) {
  Field m = Field::perCell(f.quantity(), f.components(), cellCount);
  for (std::size_t c = 0; c < cellCount && c < f.cellCount(); ++c) {
    const int n = f.pointCount(c);
    for (std::size_t k = 0; k < f.componentCount(); ++k) {
      double sum = 0.0;
      int defined = 0;
      for (int p = 0; p < n; ++p) {
        const std::size_t e = f.firstPoint(c) + static_cast<std::size_t>(p);
        if (!f.partial() || f.defined(e, k)) {
          sum += f.value(e, k);
          ++defined;
        }
      }
      m.value(c, k) = defined > 0 ? sum / defined : 0.0;
    }
  }
  return m;
}

void writeVtu(const std::filesystem::path& file, const Mesh& mesh, const ResultStep* step,
              const std::vector<std::string>& names, const ResultOutput& output) {
  auto out = openOut(file);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
         "byte_order=\"LittleEndian\">\n"
      << "  <UnstructuredGrid>\n"
      << "    <Piece NumberOfPoints=\"" << mesh.nodeCount() << "\" NumberOfCells=\"" << mesh.cellCount()
      << "\">\n";
  out << "      <PointData>\n";
  if (step != nullptr) {
    for (const auto& n : names) {
      const Field* f = step->field(n);
      if (f != nullptr && f->support() == FieldSupport::Node && !kept(*f, output).empty()) {
        vtuArray(out, n, *f, kept(*f, output), static_cast<std::size_t>(mesh.nodeCount()));
      }
    }
  }
  out << "      </PointData>\n      <CellData>\n";
  if (step != nullptr) {
    for (const auto& n : names) {
      const Field* f = step->field(n);
      if (f == nullptr || f->support() == FieldSupport::Node || kept(*f, output).empty()) {
        continue;
      }
      const auto cells = static_cast<std::size_t>(mesh.cellCount());
      if (f->support() == FieldSupport::Cell) {
        vtuArray(out, n, *f, kept(*f, output), cells);
      } else {
        vtuArray(out, n, cellMeans(*f, cells), kept(*f, output), cells);
      }
    }
  }
  out << "      </CellData>\n      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" "
         "format=\"ascii\">\n";
  for (NodeId n = 0; n < mesh.nodeCount(); ++n) {
    const auto x = mesh.point(n);
    out << fmt::format("          {:.17g} {:.17g} {:.17g}\n", x[0], x[1], x[2]);
  }
  out << "        </DataArray>\n      </Points>\n      <Cells>\n"
      << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  std::vector<int> types;
  std::vector<std::size_t> offsets;
  std::size_t offset = 0;
  for (CellId c = 0; c < mesh.cellCount(); ++c) {
    const auto vc = vtkCell(mesh.cellType(c));
    const auto nodes = mesh.cellNodes(c);
    out << "         ";
    for (const int p : vc.perm) {
      out << ' ' << nodes[static_cast<std::size_t>(p)];
    }
    out << "\n";
    offset += nodes.size();
    offsets.push_back(offset);
    types.push_back(vc.type);
  }
  out << "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (const auto o : offsets) {
    out << "          " << o << "\n";
  }
  out << "        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (const int t : types) {
    out << "          " << t << "\n";
  }
  out << "        </DataArray>\n      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  out.flush();
  if (!out) {
    throwFileError("MESHFILE_7", file, "writing failed (disk full?)");
  }
}

} // namespace

std::vector<std::filesystem::path> writeVtuResult(const std::filesystem::path& pvdFile, const Mesh& mesh,
                                                  const Result* result, const ResultOutput& output) {
  std::vector<std::filesystem::path> written;
  const auto selected = steps(result, output);
  const auto names = fields(result, output);
  // study.pvd -> study_<k>.vtu; a unit's file fort.81 -> fort.81_<k>.vtu (the batch runner copies
  // them back with the unit's result).
  const auto stem = pvdFile.extension() == ".pvd" ? pvdFile.stem().string() : pvdFile.filename().string();
  const auto dir = pvdFile.parent_path();
  std::string collection;
  if (selected.empty()) {
    const auto vtu = dir / (stem + "_mesh.vtu");
    writeVtu(vtu, mesh, nullptr, names, output);
    written.push_back(vtu);
    collection += "    <DataSet timestep=\"0\" file=\"" + vtu.filename().string() + "\"/>\n";
  }
  for (const ResultStep* s : selected) {
    const auto vtu = dir / fmt::format("{}_{}.vtu", stem, s->number);
    writeVtu(vtu, mesh, s, names, output);
    written.push_back(vtu);
    collection +=
        fmt::format("    <DataSet timestep=\"{:.17g}\" file=\"{}\"/>\n", s->time, vtu.filename().string());
  }
  auto out = openOut(pvdFile);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n"
      << collection << "  </Collection>\n</VTKFile>\n";
  written.push_back(pvdFile);
  return written;
}

void writeGmshResult(const std::filesystem::path& file, const Mesh& mesh, const Result* result,
                     const ResultOutput& output) {
  writeGmshMesh(file, mesh);
  std::ofstream out(file, std::ios::app);
  if (!out) {
    throwFileError("MESHFILE_7", file, "the file cannot be opened for writing");
  }
  for (const auto& name : fields(result, output)) {
    for (const ResultStep* s : steps(result, output)) {
      const Field* f = s->field(name);
      if (f == nullptr || (f->support() != FieldSupport::Node && f->support() != FieldSupport::Cell)) {
        continue;
      }
      const bool nodal = f->support() == FieldSupport::Node;
      for (const auto c : kept(*f, output)) {
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
  for (const ResultStep* step : steps(&result, output)) {
    for (const auto& name : fields(&result, output)) {
      const Field* f = step->field(name);
      if (f == nullptr) {
        continue;
      }
      const auto k = kept(*f, output);
      s += fmt::format("\n CHAMP {} DU RESULTAT {} NUME_ORDRE {} INST {:.6E} ({})\n", name, output.resultName,
                       step->number, step->time, f->quantity());
      std::string header = f->support() == FieldSupport::Node ? " NOEUD   " : " MAILLE  ";
      if (f->support() == FieldSupport::GaussPoint || f->support() == FieldSupport::CellNode) {
        header += " POINT";
      }
      for (const auto c : k) {
        header += fmt::format(" {:>13}", f->components()[c]);
      }
      s += header + "\n";
      const auto row = [&](const std::string& label, std::size_t e) {
        std::string line = label;
        for (const auto c : k) {
          line += !f->partial() || f->defined(e, c) ? fmt::format(" {:13.6E}", f->value(e, c))
                                                    : fmt::format(" {:>13}", "-");
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
