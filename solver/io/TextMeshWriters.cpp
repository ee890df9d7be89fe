// Text mesh writers: ASTER .mail and Gmsh .msh 2.2 ASCII, and the dispatch by format.

#include "solver/io/GmshCellTypes.hpp"
#include "solver/io/MeshFileError.hpp"
#include "solver/io/MeshIO.hpp"

#include <fmt/format.h>

#include <fstream>

namespace stella {

namespace {

std::ofstream openForWriting(const std::filesystem::path& file) {
  std::ofstream out(file);
  if (!out) {
    throwFileError("MESHFILE_7.8", file, {});
  }
  return out;
}

void finish(std::ofstream& out, const std::filesystem::path& file) {
  out.flush();
  if (!out) {
    throwFileError("MESHFILE_7.5", file, {});
  }
}

} // namespace

void writeAsterMesh(const std::filesystem::path& file, const Mesh& mesh,
                    const std::vector<std::string>& title) {
  auto out = openForWriting(file);
  out << "TITRE\n";
  for (const auto& line : title) {
    out << ' ' << line << '\n';
  }
  out << "FINSF\n%\n";
  const bool d2 = mesh.dimension() == 2;
  out << (d2 ? "COOR_2D\n" : "COOR_3D\n");
  for (NodeId n = 0; n < mesh.nodeCount(); ++n) {
    const auto x = mesh.point(n);
    if (d2) {
      out << fmt::format("{} {:.17g} {:.17g}\n", mesh.nodeName(n), x[0], x[1]);
    } else {
      out << fmt::format("{} {:.17g} {:.17g} {:.17g}\n", mesh.nodeName(n), x[0], x[1], x[2]);
    }
  }
  out << "FINSF\n%\n";
  // One block per run of cells of the same type, keeping the cell order.
  CellId c = 0;
  while (c < mesh.cellCount()) {
    const CellType t = mesh.cellType(c);
    out << name(t) << "\n";
    for (; c < mesh.cellCount() && mesh.cellType(c) == t; ++c) {
      out << mesh.cellName(c);
      for (const NodeId n : mesh.cellNodes(c)) {
        out << ' ' << mesh.nodeName(n);
      }
      out << '\n';
    }
    out << "FINSF\n%\n";
  }
  for (const auto& [g, cells] : mesh.cellGroups()) {
    out << "GROUP_MA\n" << g << "\n";
    for (const CellId k : cells) {
      out << "  " << mesh.cellName(k) << "\n";
    }
    out << "FINSF\n%\n";
  }
  for (const auto& [g, nodes] : mesh.nodeGroups()) {
    out << "GROUP_NO\n" << g << "\n";
    for (const NodeId k : nodes) {
      out << "  " << mesh.nodeName(k) << "\n";
    }
    out << "FINSF\n%\n";
  }
  out << "FIN\n";
  finish(out, file);
}

void writeGmshMesh(const std::filesystem::path& file, const Mesh& mesh) {
  auto out = openForWriting(file);
  out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
  // Physical groups: one tag per cell group, in name order, named in every dimension where the
  // group has cells (a Gmsh physical group has one dimension). Empty groups cannot be written.
  std::vector<std::vector<int>> groupsOfCell(static_cast<std::size_t>(mesh.cellCount()));
  std::vector<std::string> names;
  int tag = 0;
  for (const auto& [g, cells] : mesh.cellGroups()) {
    ++tag;
    bool dims[4] = {false, false, false, false};
    for (const CellId k : cells) {
      dims[dimension(mesh.cellType(k))] = true;
      groupsOfCell[static_cast<std::size_t>(k)].push_back(tag);
    }
    for (int d = 0; d < 4; ++d) {
      if (dims[d]) {
        names.push_back(std::to_string(d) + " " + std::to_string(tag) + " \"" + g + "\"");
      }
    }
  }
  if (!names.empty()) {
    out << "$PhysicalNames\n" << names.size() << "\n";
    for (const auto& n : names) {
      out << n << "\n";
    }
    out << "$EndPhysicalNames\n";
  }
  out << "$Nodes\n" << mesh.nodeCount() << "\n";
  for (NodeId n = 0; n < mesh.nodeCount(); ++n) {
    const auto x = mesh.point(n);
    out << fmt::format("{} {:.17g} {:.17g} {:.17g}\n", n + 1, x[0], x[1], x[2]);
  }
  out << "$EndNodes\n";
  std::size_t elements = 0;
  for (const auto& g : groupsOfCell) {
    elements += std::max<std::size_t>(1, g.size());
  }
  out << "$Elements\n" << elements << "\n";
  for (CellId c = 0; c < mesh.cellCount(); ++c) {
    const CellType t = mesh.cellType(c);
    const int gt = gmshTypeOf(t);
    if (gt == 0) {
      throwFileError("MESHFILE_5.6", file, {{"name", std::string(name(t))}, {"cell_name", mesh.cellName(c)}});
    }
    const auto nodes = mesh.cellNodes(c);
    const auto perm = gmshPermutation(t);
    std::vector<NodeId> gmshNodes(nodes.size());
    for (std::size_t j = 0; j < nodes.size(); ++j) {
      gmshNodes[static_cast<std::size_t>(perm[j])] = nodes[j];
    }
    auto groups = groupsOfCell[static_cast<std::size_t>(c)];
    if (groups.empty()) {
      groups.push_back(0);
    }
    for (const int p : groups) {
      out << c + 1 << ' ' << gt << " 2 " << p << ' ' << (p == 0 ? 1 : p);
      for (const NodeId n : gmshNodes) {
        out << ' ' << n + 1;
      }
      out << '\n';
    }
  }
  out << "$EndElements\n";
  finish(out, file);
}

std::optional<MeshFormat> meshFormatFromExtension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  for (char& ch : ext) {
    ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  }
  if (ext == ".med" || ext == ".rmed" || ext == ".mmed") {
    return MeshFormat::Med;
  }
  if (ext == ".mail" || ext == ".mai") {
    return MeshFormat::Aster;
  }
  if (ext == ".msh") {
    return MeshFormat::Gmsh;
  }
  if (ext == ".mgib") {
    return MeshFormat::Gibi;
  }
  return std::nullopt;
}

Mesh readMesh(const std::filesystem::path& file, MeshFormat format, const std::string& medMeshName) {
  switch (format) {
  case MeshFormat::Med:
    return readMedMesh(file, medMeshName);
  case MeshFormat::Aster:
    return readAsterMesh(file);
  case MeshFormat::Gmsh:
    return readGmshMesh(file);
  case MeshFormat::Gibi:
    return readGibiMesh(file);
  }
  return {};
}

void writeMesh(const std::filesystem::path& file, const Mesh& mesh, MeshFormat format) {
  switch (format) {
  case MeshFormat::Med:
    writeMedMesh(file, mesh);
    return;
  case MeshFormat::Aster:
    writeAsterMesh(file, mesh);
    return;
  case MeshFormat::Gmsh:
    writeGmshMesh(file, mesh);
    return;
  case MeshFormat::Gibi:
    throwFileError("MESHFILE_5.7", file, {});
  }
}

} // namespace stella
