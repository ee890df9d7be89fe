// Selection of cells and nodes by groups and names, with errors that name what is missing.

#include "solver/inputs/Selection.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace stella {

namespace {

template <class Map> std::vector<std::string> keysOf(const Map& m) {
  std::vector<std::string> out;
  for (const auto& [k, v] : m) {
    out.push_back(k);
  }
  return out;
}

void sortUnique(std::vector<int>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

void subtract(std::vector<int>& from, std::vector<int> removed) {
  sortUnique(removed);
  std::vector<int> out;
  std::set_difference(from.begin(), from.end(), removed.begin(), removed.end(), std::back_inserter(out));
  from = std::move(out);
}

} // namespace

std::string listNames(const std::vector<std::string>& names, std::size_t limit) {
  if (names.empty()) {
    return "(none)";
  }
  std::vector<std::string> shown(names.begin(),
                                 names.begin() + static_cast<std::ptrdiff_t>(std::min(limit, names.size())));
  std::string text = fmt::format("{}", fmt::join(shown, ", "));
  if (names.size() > limit) {
    text += fmt::format(", ... ({} in all)", names.size());
  }
  return text;
}

const std::vector<CellId>& cellGroupOrThrow(const Mesh& mesh, const std::string& group,
                                            const KeywordTree& occurrence, const std::string& keyword) {
  const auto* cells = mesh.cellGroup(group);
  if (cells == nullptr) {
    throw UserError(msg::make("GROUP_1",
                              {{"group", group}, {"list_names", listNames(keysOf(mesh.cellGroups()))}},
                              occurrence.locationOf(keyword)));
  }
  return *cells;
}

const std::vector<NodeId>& nodeGroupOrThrow(const Mesh& mesh, const std::string& group,
                                            const KeywordTree& occurrence, const std::string& keyword) {
  const auto* nodes = mesh.nodeGroup(group);
  if (nodes == nullptr) {
    std::string note = fmt::format("its node groups are: {}", listNames(keysOf(mesh.nodeGroups())));
    if (mesh.hasCellGroup(group)) {
      note += fmt::format("; '{}' is a cell group: use GROUP_MA, or DEFI_GROUP CREA_GROUP_NO", group);
    }
    throw UserError(msg::make("GROUP_2", {{"group", group}}, occurrence.locationOf(keyword)).withNote(note));
  }
  return *nodes;
}

NodeId nodeOrThrow(const Mesh& mesh, const std::string& name, const KeywordTree& occurrence,
                   const std::string& keyword) {
  auto n = mesh.findNode(name);
  if (!n) {
    throw UserError(msg::make("GROUP_3", {{"name", name}}, occurrence.locationOf(keyword)));
  }
  return *n;
}

CellId cellOrThrow(const Mesh& mesh, const std::string& name, const KeywordTree& occurrence,
                   const std::string& keyword) {
  auto c = mesh.findCell(name);
  if (!c) {
    throw UserError(msg::make("GROUP_4", {{"name", name}}, occurrence.locationOf(keyword)));
  }
  return *c;
}

std::vector<CellId> selectCells(const Mesh& mesh, const KeywordTree& occurrence) {
  std::vector<CellId> cells;
  if (occurrence.has("TOUT")) {
    cells.resize(static_cast<std::size_t>(mesh.cellCount()));
    for (CellId c = 0; c < mesh.cellCount(); ++c) {
      cells[static_cast<std::size_t>(c)] = c;
    }
  }
  if (occurrence.has("GROUP_MA")) {
    for (const auto& g : occurrence.texts("GROUP_MA")) {
      const auto& group = cellGroupOrThrow(mesh, g, occurrence, "GROUP_MA");
      cells.insert(cells.end(), group.begin(), group.end());
    }
  }
  if (occurrence.has("MAILLE")) {
    for (const auto& name : occurrence.texts("MAILLE")) {
      cells.push_back(cellOrThrow(mesh, name, occurrence, "MAILLE"));
    }
  }
  sortUnique(cells);
  if (occurrence.has("SANS_GROUP_MA")) {
    std::vector<CellId> removed;
    for (const auto& g : occurrence.texts("SANS_GROUP_MA")) {
      const auto& group = cellGroupOrThrow(mesh, g, occurrence, "SANS_GROUP_MA");
      removed.insert(removed.end(), group.begin(), group.end());
    }
    subtract(cells, removed);
  }
  return cells;
}

std::vector<NodeId> selectNodes(const Mesh& mesh, const KeywordTree& occurrence) {
  std::vector<NodeId> nodes;
  if (occurrence.has("TOUT")) {
    nodes.resize(static_cast<std::size_t>(mesh.nodeCount()));
    for (NodeId n = 0; n < mesh.nodeCount(); ++n) {
      nodes[static_cast<std::size_t>(n)] = n;
    }
  }
  if (occurrence.has("GROUP_MA") || occurrence.has("MAILLE")) {
    KeywordTree cellsOnly;
    for (const auto& s : occurrence.simples()) {
      if (s.name == "GROUP_MA" || s.name == "MAILLE") {
        cellsOnly.addSimple(s);
      }
    }
    auto cells = selectCells(mesh, cellsOnly);
    auto n = mesh.nodesOfCells(cells);
    nodes.insert(nodes.end(), n.begin(), n.end());
  }
  if (occurrence.has("GROUP_NO")) {
    for (const auto& g : occurrence.texts("GROUP_NO")) {
      const auto& group = nodeGroupOrThrow(mesh, g, occurrence, "GROUP_NO");
      nodes.insert(nodes.end(), group.begin(), group.end());
    }
  }
  if (occurrence.has("NOEUD")) {
    for (const auto& name : occurrence.texts("NOEUD")) {
      nodes.push_back(nodeOrThrow(mesh, name, occurrence, "NOEUD"));
    }
  }
  sortUnique(nodes);
  std::vector<NodeId> removed;
  if (occurrence.has("SANS_GROUP_NO")) {
    for (const auto& g : occurrence.texts("SANS_GROUP_NO")) {
      const auto& group = nodeGroupOrThrow(mesh, g, occurrence, "SANS_GROUP_NO");
      removed.insert(removed.end(), group.begin(), group.end());
    }
  }
  if (occurrence.has("SANS_GROUP_MA")) {
    for (const auto& g : occurrence.texts("SANS_GROUP_MA")) {
      auto n = mesh.nodesOfCells(cellGroupOrThrow(mesh, g, occurrence, "SANS_GROUP_MA"));
      removed.insert(removed.end(), n.begin(), n.end());
    }
  }
  if (!removed.empty()) {
    subtract(nodes, removed);
  }
  return nodes;
}

} // namespace stella
