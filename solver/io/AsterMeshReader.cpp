// ASTER .mail reader: blocks TITRE, COOR_1D/COOR_2D/COOR_3D, one block per cell type (SEG2 ...
// HEXA27), GROUP_MA and GROUP_NO (group name as `NOM=name` on the header line or as the first
// token), each closed by FINSF; FIN ends the file; `%` starts a comment. Names may be used before
// they are defined (cells before nodes, groups before cells): they are resolved at the end.

#include "solver/io/MeshFileError.hpp"
#include "solver/io/MeshIO.hpp"
#include "solver/io/TextScanner.hpp"

#include <unordered_map>

namespace stella {

namespace {

// Names read from the file, resolved once every block is read.
struct PendingNames {
  std::string pool;
  std::vector<std::uint32_t> ends;
  std::vector<int> lines;

  void add(std::string_view n, int line) {
    pool.append(n);
    ends.push_back(static_cast<std::uint32_t>(pool.size()));
    lines.push_back(line);
  }
  std::string_view at(std::size_t i) const {
    const std::uint32_t b = i == 0 ? 0 : ends[i - 1];
    return std::string_view(pool).substr(b, ends[i] - b);
  }
};

struct PendingCell {
  CellType type;
  std::size_t firstName; // index in PendingNames
};

struct PendingGroup {
  std::string name;
  bool cells;
  std::vector<std::pair<std::string, int>> members; // name, line
};

bool isFinsf(std::string_view t) {
  return t == "FINSF";
}

std::string_view blockToken(TextScanner& s, const char* block) {
  const auto t = s.next();
  if (t.empty()) {
    s.fail("MESHFILE_2.20", {{"block", block}});
  }
  return t;
}

void readCoordinates(TextScanner& s, int dim, Mesh& mesh, std::unordered_map<std::string, NodeId>& byName) {
  const char* block = dim == 3 ? "COOR_3D" : (dim == 2 ? "COOR_2D" : "COOR_1D");
  while (s.moreOnLine()) {
    s.next(); // header options (NOM=...)
  }
  for (auto t = blockToken(s, block); !isFinsf(t); t = blockToken(s, block)) {
    std::string name(t);
    Point3 x{0.0, 0.0, 0.0};
    for (int d = 0; d < dim; ++d) {
      x[static_cast<std::size_t>(d)] = s.real("node coordinate");
    }
    if (byName.count(name) != 0) {
      s.failContent("MESHFILE_3.49", {{"name", name}});
    }
    byName.emplace(name, mesh.addNode(x, name));
  }
}

void readCells(TextScanner& s, CellType type, PendingNames& names, std::vector<PendingCell>& cells,
               std::vector<std::pair<std::string, int>>& cellNames) {
  const std::string block(name(type));
  while (s.moreOnLine()) {
    s.next();
  }
  for (auto t = blockToken(s, block.c_str()); !isFinsf(t); t = blockToken(s, block.c_str())) {
    cellNames.emplace_back(std::string(t), s.line());
    cells.push_back({type, names.lines.size()});
    for (int i = 0; i < nodeCount(type); ++i) {
      const auto n = s.expect("node name of a cell");
      if (isFinsf(n)) {
        s.fail("MESHFILE_2.21", {{"back", cellNames.back().first},
                                 {"block", block},
                                 {"node_count", std::to_string(nodeCount(type))}});
      }
      names.add(n, s.line());
    }
  }
}

PendingGroup readGroup(TextScanner& s, bool cells) {
  const char* block = cells ? "GROUP_MA" : "GROUP_NO";
  PendingGroup g{"", cells, {}};
  while (s.moreOnLine()) {
    const auto opt = s.next();
    if (opt.substr(0, 4) == "NOM=") {
      g.name = std::string(opt.substr(4));
    } else if (opt == "NOM" && s.moreOnLine()) {
      auto v = s.next();
      if (v == "=") {
        v = s.expect("group name");
      } else if (v.substr(0, 1) == "=") {
        v = v.substr(1);
      }
      g.name = std::string(v);
    } else if (g.name.empty()) {
      g.name = std::string(opt); // name on the header line
    } else {
      g.members.emplace_back(std::string(opt), s.line());
    }
  }
  for (auto t = blockToken(s, block); !isFinsf(t); t = blockToken(s, block)) {
    if (g.name.empty()) {
      g.name = std::string(t);
    } else {
      g.members.emplace_back(std::string(t), s.line());
    }
  }
  if (g.name.empty()) {
    s.fail("MESHFILE_2.22", {{"block", block}});
  }
  return g;
}

} // namespace

Mesh readAsterMesh(const std::filesystem::path& file) {
  TextScanner s(file, readWholeFile(file), '%');
  Mesh mesh;
  std::unordered_map<std::string, NodeId> nodeByName;
  PendingNames cellNodeNames;
  std::vector<PendingCell> cells;
  std::vector<std::pair<std::string, int>> cellNames;
  std::vector<PendingGroup> groups;
  int dim = 0;
  bool sawFin = false;
  for (auto t = s.next(); !t.empty(); t = s.next()) {
    if (t == "FIN") {
      sawFin = true;
      break;
    }
    if (t == "TITRE") {
      for (auto u = blockToken(s, "TITRE"); !isFinsf(u); u = blockToken(s, "TITRE")) {
      }
    } else if (t == "COOR_1D" || t == "COOR_2D" || t == "COOR_3D") {
      const int d = t[5] - '0';
      dim = std::max(dim, d);
      readCoordinates(s, d, mesh, nodeByName);
    } else if (t == "GROUP_MA" || t == "GROUP_NO") {
      groups.push_back(readGroup(s, t == "GROUP_MA"));
    } else if (const auto type = cellTypeFromName(t)) {
      readCells(s, *type, cellNodeNames, cells, cellNames);
    } else {
      s.fail("MESHFILE_2.23", {{"substr", std::string(t.substr(0, 40))}});
    }
  }
  if (!sawFin) {
    throwFileError("MESHFILE_2", file, {}, s.line());
  }
  if (mesh.nodeCount() == 0) {
    throwFileError("MESHFILE_3", file, {});
  }
  if (cells.empty()) {
    throwFileError("MESHFILE_3.2", file, {});
  }
  mesh.setDimension(dim == 3 ? 3 : 2);
  std::unordered_map<std::string, CellId> cellByName;
  mesh.reserveCells(static_cast<CellId>(cells.size()), cellNodeNames.lines.size());
  NodeId nodes[27];
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const int n = nodeCount(cells[c].type);
    for (int i = 0; i < n; ++i) {
      const std::size_t k = cells[c].firstName + static_cast<std::size_t>(i);
      const auto it = nodeByName.find(std::string(cellNodeNames.at(k)));
      if (it == nodeByName.end()) {
        throwFileError("MESHFILE_3.3", file,
                       {{"cell_names", cellNames[c].first}, {"at", std::string(cellNodeNames.at(k))}},
                       cellNodeNames.lines[k]);
      }
      nodes[i] = it->second;
    }
    if (!cellByName.emplace(cellNames[c].first, static_cast<CellId>(c)).second) {
      throwFileError("MESHFILE_3.4", file, {{"cell_names", cellNames[c].first}}, cellNames[c].second);
    }
    mesh.addCell(cells[c].type, std::span<const NodeId>(nodes, static_cast<std::size_t>(n)),
                 cellNames[c].first);
  }
  for (const auto& g : groups) {
    std::vector<std::int32_t> ids;
    ids.reserve(g.members.size());
    for (const auto& [member, line] : g.members) {
      if (g.cells) {
        const auto it = cellByName.find(member);
        if (it == cellByName.end()) {
          throwFileError("MESHFILE_3.5", file, {{"name", g.name}, {"member", member}}, line);
        }
        ids.push_back(it->second);
      } else {
        const auto it = nodeByName.find(member);
        if (it == nodeByName.end()) {
          throwFileError("MESHFILE_3.6", file, {{"name", g.name}, {"member", member}}, line);
        }
        ids.push_back(it->second);
      }
    }
    if (g.cells) {
      mesh.setCellGroup(g.name, std::move(ids));
    } else {
      mesh.setNodeGroup(g.name, std::move(ids));
    }
  }
  return mesh;
}

} // namespace stella
