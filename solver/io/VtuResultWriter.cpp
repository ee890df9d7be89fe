// VTU/PVD result files (see ResultWriters.hpp): VTK XML UnstructuredGrid, every array in binary
// appended data compressed with zlib (header_type UInt64, vtkZLibDataCompressor), so that a
// million-node result is a few tens of MB that ParaView loads without parsing text.
//
// Values: a component that a field does not define on an entity (partial fields, cells without
// Gauss points, entities past the field's support) is NaN, so that ParaView shows the field's
// support instead of a false 0. Two-component displacement-like fields (DX, DY without DZ: 2D
// models) get DZ = 0, so that the array is a 3-vector that "Warp By Vector" accepts; the contact
// multipliers of DEPL (LAGS_C...) are scalar arrays of their own (DEPL_LAGS_C).

#include "solver/io/MeshFileError.hpp"
#include "solver/io/ResultSelection.hpp"
#include "solver/io/ResultWriters.hpp"
#include "solver/mesh/CellTopology.hpp"
#include "solver/mesh/MeshTransform.hpp"

#include <fmt/format.h>
#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <limits>

namespace stella {

namespace {

using detail::keptComponents;
using detail::openOutput;
using detail::selectedFields;
using detail::selectedSteps;

constexpr double notDefined = std::numeric_limits<double>::quiet_NaN();

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

// The binary blocks of the appended section and the XML that points into it.
class AppendedData {
public:
  explicit AppendedData(const std::filesystem::path& file) : file_(file) {}

  // Adds `bytes` zlib-compressed in blocks; returns the DataArray's offset attribute.
  std::size_t add(const void* bytes, std::size_t size) {
    const std::size_t offset = data_.size();
    const std::size_t blocks = (size + blockSize - 1) / blockSize;
    std::vector<std::uint64_t> header{blocks, blockSize, size % blockSize};
    std::vector<unsigned char> compressed;
    const auto* in = static_cast<const unsigned char*>(bytes);
    for (std::size_t b = 0; b < blocks; ++b) {
      const std::size_t length = std::min(blockSize, size - b * blockSize);
      uLongf out = compressBound(static_cast<uLong>(length));
      const std::size_t at = compressed.size();
      compressed.resize(at + out);
      if (compress2(compressed.data() + at, &out, in + b * blockSize, static_cast<uLong>(length), 6) !=
          Z_OK) {
        throwFileError("MESHFILE_7.4", file_, {});
      }
      compressed.resize(at + out);
      header.push_back(out);
    }
    append(header.data(), header.size() * sizeof(std::uint64_t));
    append(compressed.data(), compressed.size());
    return offset;
  }
  const std::vector<char>& bytes() const { return data_; }

private:
  static constexpr std::size_t blockSize = std::size_t{1} << 20;
  void append(const void* p, std::size_t n) {
    const auto* c = static_cast<const char*>(p);
    data_.insert(data_.end(), c, c + n);
  }
  std::filesystem::path file_;
  std::vector<char> data_;
};

// The components written for a field: the kept ones, and DZ = 0 after DX, DY when the field has
// no DZ (a 2D displacement or force: a 3-vector for VTK).
// Contact multipliers of DEPL (LAGS_C, LAGS_F1, LAGS_F2: FORMULATION='CONTINUE') are written
// as scalar arrays of their own (DEPL_LAGS_C), not as components of the displacement vector.
struct VtuComponents {
  std::vector<std::size_t> kept;
  bool addZ = false;
  std::vector<std::size_t> multipliers;
};

VtuComponents vtuComponents(const Field& f, const ResultOutput& out) {
  VtuComponents v{{}, false, {}};
  std::vector<std::string> names;
  for (const auto c : keptComponents(f, out)) {
    if (f.components()[c].rfind("LAGS_", 0) == 0) {
      v.multipliers.push_back(c);
      continue;
    }
    v.kept.push_back(c);
    names.push_back(f.components()[c]);
  }
  v.addZ = names == std::vector<std::string>{"DX", "DY"};
  return v;
}

std::string dataArray(AppendedData& data, const std::string& name, const std::vector<std::string>& components,
                      const std::vector<double>& values) {
  std::string xml = fmt::format("        <DataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"{}\"",
                                name, components.size());
  for (std::size_t i = 0; i < components.size(); ++i) {
    xml += fmt::format(" ComponentName{}=\"{}\"", i, components[i]);
  }
  const std::size_t offset = data.add(values.data(), values.size() * sizeof(double));
  return xml + fmt::format(" format=\"appended\" offset=\"{}\"/>\n", offset);
}

// One array of `count` tuples: the field's value where it is defined, NaN elsewhere.
std::string fieldArray(AppendedData& data, const std::string& name, const Field& f, const VtuComponents& k,
                       std::size_t count) {
  std::vector<std::string> components;
  for (const auto c : k.kept) {
    components.push_back(f.components()[c]);
  }
  if (k.addZ) {
    components.emplace_back("DZ");
  }
  std::vector<double> values;
  values.reserve(count * components.size());
  for (std::size_t e = 0; e < count; ++e) {
    for (const auto c : k.kept) {
      values.push_back(e < f.entityCount() && (!f.partial() || f.defined(e, c)) ? f.value(e, c) : notDefined);
    }
    if (k.addZ) {
      values.push_back(e < f.entityCount() ? 0.0 : notDefined);
    }
  }
  return dataArray(data, name, components, values);
}

// Gauss-point and cell-node fields as cell data: the mean of each cell's defined points, NaN for
// cells without any (skin cells of SIEF_ELGA), so that ParaView shows SIEF_ELGA without a plugin.
Field cellMeans(const Field& f, std::size_t cellCount) {
  Field m = Field::perCell(f.quantity(), f.components(), cellCount);
  for (std::size_t c = 0; c < cellCount; ++c) {
    const int n = c < f.cellCount() ? f.pointCount(c) : 0;
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
      m.value(c, k) = defined > 0 ? sum / defined : notDefined;
    }
  }
  return m;
}

std::string pointData(AppendedData& data, const Mesh& mesh, const ResultStep* step,
                      const std::vector<std::string>& names, const ResultOutput& output) {
  std::string xml = "      <PointData>\n";
  for (const auto& n : step != nullptr ? names : std::vector<std::string>{}) {
    const Field* f = step->field(n);
    if (f != nullptr && f->support() == FieldSupport::Node && !keptComponents(*f, output).empty()) {
      const VtuComponents k = vtuComponents(*f, output);
      const auto count = static_cast<std::size_t>(mesh.nodeCount());
      if (!k.kept.empty()) {
        xml += fieldArray(data, n, *f, k, count);
      }
      for (const auto c : k.multipliers) {
        xml += fieldArray(data, n + "_" + f->components()[c], *f, VtuComponents{{c}, false, {}}, count);
      }
    }
  }
  return xml + "      </PointData>\n";
}

std::string cellData(AppendedData& data, const Mesh& mesh, const ResultStep* step,
                     const std::vector<std::string>& names, const ResultOutput& output) {
  std::string xml = "      <CellData>\n";
  const auto cells = static_cast<std::size_t>(mesh.cellCount());
  for (const auto& n : step != nullptr ? names : std::vector<std::string>{}) {
    const Field* f = step->field(n);
    if (f == nullptr || f->support() == FieldSupport::Node || keptComponents(*f, output).empty()) {
      continue;
    }
    const auto k = vtuComponents(*f, output);
    xml += f->support() == FieldSupport::Cell ? fieldArray(data, n, *f, k, cells)
                                              : fieldArray(data, n, cellMeans(*f, cells), k, cells);
  }
  return xml + "      </CellData>\n";
}

std::string geometry(AppendedData& data, const Mesh& mesh) {
  std::vector<double> points;
  points.reserve(static_cast<std::size_t>(mesh.nodeCount()) * 3);
  for (NodeId n = 0; n < mesh.nodeCount(); ++n) {
    const auto x = mesh.point(n);
    points.insert(points.end(), {x[0], x[1], x[2]});
  }
  std::vector<std::int64_t> connectivity;
  std::vector<std::int64_t> offsets;
  std::vector<std::uint8_t> types;
  for (CellId c = 0; c < mesh.cellCount(); ++c) {
    const auto vc = vtkCell(mesh.cellType(c));
    const auto nodes = mesh.cellNodes(c);
    for (const int p : vc.perm) {
      connectivity.push_back(nodes[static_cast<std::size_t>(p)]);
    }
    offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
    types.push_back(static_cast<std::uint8_t>(vc.type));
  }
  const auto array = [&](const char* type, const char* name, const void* p, std::size_t bytes,
                         const char* extra) {
    return fmt::format("        <DataArray type=\"{}\"{}{} format=\"appended\" offset=\"{}\"/>\n", type,
                       name[0] != '\0' ? fmt::format(" Name=\"{}\"", name) : std::string(), extra,
                       data.add(p, bytes));
  };
  return "      <Points>\n" +
         array("Float64", "", points.data(), points.size() * sizeof(double), " NumberOfComponents=\"3\"") +
         "      </Points>\n      <Cells>\n" +
         array("Int64", "connectivity", connectivity.data(), connectivity.size() * sizeof(std::int64_t), "") +
         array("Int64", "offsets", offsets.data(), offsets.size() * sizeof(std::int64_t), "") +
         array("UInt8", "types", types.data(), types.size(), "") + "      </Cells>\n";
}

void writeVtu(const std::filesystem::path& file, const Mesh& mesh, const ResultStep* step,
              const std::vector<std::string>& names, const ResultOutput& output) {
  AppendedData data(file);
  const std::string pieces = pointData(data, mesh, step, names, output) +
                             cellData(data, mesh, step, names, output) + geometry(data, mesh);
  auto out = openOutput(file, std::ios::out | std::ios::binary);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
         "byte_order=\"LittleEndian\" header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\">\n"
      << "  <UnstructuredGrid>\n"
      << "    <Piece NumberOfPoints=\"" << mesh.nodeCount() << "\" NumberOfCells=\"" << mesh.cellCount()
      << "\">\n"
      << pieces << "    </Piece>\n  </UnstructuredGrid>\n  <AppendedData encoding=\"raw\">\n   _";
  out.write(data.bytes().data(), static_cast<std::streamsize>(data.bytes().size()));
  out << "\n  </AppendedData>\n</VTKFile>\n";
  out.flush();
  if (!out) {
    throwFileError("MESHFILE_7.5", file, {});
  }
}

} // namespace

std::vector<std::filesystem::path> writeVtuResult(const std::filesystem::path& pvdFile, const Mesh& mesh,
                                                  const Result* result, const ResultOutput& output) {
  std::vector<std::filesystem::path> written;
  const auto selected = selectedSteps(result, output);
  const auto names = selectedFields(result, output);
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
  auto out = openOutput(pvdFile);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n"
      << collection << "  </Collection>\n</VTKFile>\n";
  written.push_back(pvdFile);
  return written;
}

} // namespace stella
