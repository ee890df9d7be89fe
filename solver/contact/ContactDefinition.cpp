// The definition-time checks of DEFI_CONTACT against the mesh (groups, shared nodes, disjoint
// slave surfaces, outward normals); the keywords are read by solver/inputs/ContactReader.cpp.

#include "solver/contact/ContactDefinition.hpp"

#include "messages/Messages.hpp"
#include "solver/mesh/SkinOrientation.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

namespace stella::contact {

namespace {

std::string groupList(const Mesh& mesh) {
  std::vector<std::string> names;
  for (const auto& [name, cells] : mesh.cellGroups()) {
    names.push_back(name);
  }
  return names.empty() ? std::string("(none)") : fmt::format("{}", fmt::join(names, ", "));
}

const std::vector<CellId>& cellGroupOrThrow(const Mesh& mesh, const std::string& group,
                                            const std::string& keyword, const SourceLocation& at) {
  const auto* cells = mesh.cellGroup(group);
  if (cells == nullptr) {
    throw UserError(msg::make("CONTACT_1",
                              {{"keyword", keyword}, {"group", group}, {"group_list", groupList(mesh)}}, at));
  }
  return *cells;
}

std::string nodeNames(const Mesh& mesh, const std::vector<NodeId>& nodes) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < nodes.size() && i < 20; ++i) {
    names.push_back(mesh.nodeName(nodes[i]));
  }
  std::string s = fmt::format("{}", fmt::join(names, ", "));
  if (nodes.size() > 20) {
    s += fmt::format(" ... ({} nodes)", nodes.size());
  }
  return s;
}

std::vector<NodeId> intersection(const std::vector<NodeId>& a, const std::vector<NodeId>& b) {
  std::vector<NodeId> out;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

void checkCellDimensions(const Mesh& mesh, const std::vector<CellId>& cells, const std::string& group,
                         const SourceLocation& at) {
  const int wanted = mesh.dimension() - 1;
  for (CellId c : cells) {
    const auto t = mesh.cellType(c);
    const bool ok = wanted == 1 ? (t == CellType::SEG2 || t == CellType::SEG3)
                                : (t == CellType::TRIA3 || t == CellType::TRIA6 || t == CellType::QUAD4 ||
                                   t == CellType::QUAD8 || t == CellType::QUAD9);
    if (!ok) {
      throw UserError(msg::make("CONTACT_4",
                                {{"group", group},
                                 {"cell_name", mesh.cellName(c)},
                                 {"name", info(t).name},
                                 {"dimension", mesh.dimension()}},
                                at)
                          .withNote(wanted == 1 ? msg::text("CONTACT_4.n1") : msg::text("CONTACT_4.n2")));
    }
  }
}

void checkNormals(const Mesh& mesh, const std::vector<CellId>& cells, const std::string& group,
                  const SourceLocation& at) {
  // The definition of "outward" ORIE_PEAU makes true (SkinOrientation.hpp). A cell bounding no
  // volume cell (rigid skin) or two (internal skin) has nothing to be checked against.
  const auto bounded = boundedVolumes(mesh, cells, {});
  std::vector<std::string> inward;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (bounded[i].size() == 1 && !bounded[i].front().outward) {
      inward.push_back(mesh.cellName(cells[i]));
    }
  }
  if (!inward.empty()) {
    const std::size_t shown = std::min<std::size_t>(inward.size(), 10);
    throw UserError(msg::make(
        "CONTACT_5",
        {{"group", group},
         {"inward_count", inward.size()},
         {"join",
          fmt::join(std::vector<std::string>(inward.begin(), inward.begin() + static_cast<long>(shown)),
                    ", ")},
         {"inward_count_2", inward.size() > shown ? " ..." : ""}},
        at));
  }
}

} // namespace

bool ContactDefinition::resolvesAny() const {
  return std::any_of(zones.begin(), zones.end(), [](const ContactZone& z) { return z.resolve; });
}

std::string algorithmName(ContactAlgorithm a) {
  switch (a) {
  case ContactAlgorithm::Constraint:
    return "CONTRAINTE";
  case ContactAlgorithm::Gcp:
    return "GCP";
  case ContactAlgorithm::Penalty:
  case ContactAlgorithm::ContinuePenalty:
    return "PENALISATION";
  case ContactAlgorithm::Standard:
    return "STANDARD";
  case ContactAlgorithm::Lac:
    return "LAC";
  }
  return "?";
}

std::vector<NodeId> zoneSlaveNodes(const Mesh& mesh, const ContactZone& zone) {
  const auto* cells = mesh.cellGroup(zone.slaveGroup);
  if (cells == nullptr) {
    return {};
  }
  std::vector<NodeId> nodes = mesh.nodesOfCells(*cells);
  std::vector<NodeId> excluded;
  for (const auto& g : zone.excludedNodeGroups) {
    if (const auto* ns = mesh.nodeGroup(g)) {
      excluded.insert(excluded.end(), ns->begin(), ns->end());
    }
  }
  for (const auto& g : zone.excludedCellGroups) {
    if (const auto* cs = mesh.cellGroup(g)) {
      const auto ns = mesh.nodesOfCells(*cs);
      excluded.insert(excluded.end(), ns.begin(), ns.end());
    }
  }
  std::sort(excluded.begin(), excluded.end());
  std::vector<NodeId> out;
  std::set_difference(nodes.begin(), nodes.end(), excluded.begin(), excluded.end(), std::back_inserter(out));
  return out;
}

std::vector<CellId> zoneMasterCells(const Mesh& mesh, const ContactZone& zone) {
  const auto* cells = mesh.cellGroup(zone.masterGroup);
  return cells == nullptr ? std::vector<CellId>{} : *cells;
}

void checkContactDefinition(const ContactDefinition& def) {
  const Mesh& mesh = *def.mesh;
  if (def.settings.formulation == Formulation::LiaisonUnil) {
    return; // no surfaces
  }
  std::vector<std::vector<NodeId>> slaves;
  for (const ContactZone& zone : def.zones) {
    const auto& master = cellGroupOrThrow(mesh, zone.masterGroup, "GROUP_MA_MAIT", zone.location);
    const auto& slave = cellGroupOrThrow(mesh, zone.slaveGroup, "GROUP_MA_ESCL", zone.location);
    for (const auto& g : zone.excludedCellGroups) {
      cellGroupOrThrow(mesh, g, "SANS_GROUP_MA", zone.location);
    }
    for (const auto& g : zone.excludedNodeGroups) {
      if (!mesh.hasNodeGroup(g)) {
        throw UserError(msg::make("CONTACT_1.2", {{"g", g}}, zone.location));
      }
    }
    checkCellDimensions(mesh, master, zone.masterGroup, zone.location);
    checkCellDimensions(mesh, slave, zone.slaveGroup, zone.location);
    const auto shared = intersection(mesh.nodesOfCells(master), zoneSlaveNodes(mesh, zone));
    if (!shared.empty()) {
      throw UserError(msg::make("CONTACT_2",
                                {{"master_group", zone.masterGroup},
                                 {"slave_group", zone.slaveGroup},
                                 {"shared_count", shared.size()},
                                 {"node_names", nodeNames(mesh, shared)}},
                                zone.location));
    }
    auto slaveNodes = zoneSlaveNodes(mesh, zone);
    for (std::size_t k = 0; k < slaves.size(); ++k) {
      const auto common = intersection(slaves[k], slaveNodes);
      if (!common.empty()) {
        throw UserError(msg::make("CONTACT_3",
                                  {{"k", k + 1},
                                   {"slave_group", def.zones[k].slaveGroup},
                                   {"slaves_count", slaves.size() + 1},
                                   {"slave_group_2", zone.slaveGroup},
                                   {"common_count", common.size()},
                                   {"node_names", nodeNames(mesh, common)}},
                                  zone.location));
      }
    }
    slaves.push_back(std::move(slaveNodes));
    if (def.settings.checkNormals) {
      checkNormals(mesh, master, zone.masterGroup, zone.location);
      checkNormals(mesh, slave, zone.slaveGroup, zone.location);
    }
  }
}

} // namespace stella::contact
