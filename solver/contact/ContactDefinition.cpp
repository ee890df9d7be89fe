// The definition-time checks of DEFI_CONTACT against the mesh (groups, shared nodes, disjoint
// slave surfaces, outward normals); the keywords are read by solver/inputs/ContactReader.cpp.

#include "solver/contact/ContactDefinition.hpp"

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
    throw UserError(
        Diagnostic::fatal("CONTACT_1", fmt::format("{}: the mesh has no cell group '{}'", keyword, group), at)
            .withNote(fmt::format("its cell groups are: {}", groupList(mesh))));
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
      throw UserError(
          Diagnostic::fatal(
              "CONTACT_4",
              fmt::format("contact group '{}' holds cell {} of type {}, not a contact cell of a {}D mesh",
                          group, mesh.cellName(c), info(t).name, mesh.dimension()),
              at)
              .withNote(wanted == 1
                            ? "a 2D or axisymmetric contact surface is made of SEG2 or SEG3 edges"
                            : "a 3D contact surface is made of TRIA3, TRIA6, QUAD4, QUAD8 or QUAD9 faces"));
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
    throw UserError(
        Diagnostic::fatal(
            "CONTACT_5",
            fmt::format(
                "the normals of contact group '{}' point into the volume they bound on {} "
                "cell(s): {}{}",
                group, inward.size(),
                fmt::join(std::vector<std::string>(inward.begin(), inward.begin() + static_cast<long>(shown)),
                          ", "),
                inward.size() > shown ? " ..." : ""),
            at)
            .withNote(
                fmt::format("orient the group outward with MODI_MAILLAGE(ORIE_PEAU=_F(GROUP_MA_PEAU='{}')) "
                            "(ORIE_PEAU_2D / ORIE_PEAU_3D in older versions), or set VERI_NORM='NON'",
                            group)));
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
        throw UserError(Diagnostic::fatal("CONTACT_1",
                                          fmt::format("SANS_GROUP_NO: the mesh has no node group '{}'", g),
                                          zone.location)
                            .withNote("create it with DEFI_GROUP(CREA_GROUP_NO=...)"));
      }
    }
    checkCellDimensions(mesh, master, zone.masterGroup, zone.location);
    checkCellDimensions(mesh, slave, zone.slaveGroup, zone.location);
    const auto shared = intersection(mesh.nodesOfCells(master), zoneSlaveNodes(mesh, zone));
    if (!shared.empty()) {
      throw UserError(
          Diagnostic::fatal(
              "CONTACT_2",
              fmt::format("the master surface '{}' and the slave surface '{}' of a contact zone "
                          "share {} node(s): {}",
                          zone.masterGroup, zone.slaveGroup, shared.size(), nodeNames(mesh, shared)),
              zone.location)
              .withNote("exclude the shared nodes from the slave side with SANS_GROUP_NO (notice §2.3.4)"));
    }
    auto slaveNodes = zoneSlaveNodes(mesh, zone);
    for (std::size_t k = 0; k < slaves.size(); ++k) {
      const auto common = intersection(slaves[k], slaveNodes);
      if (!common.empty()) {
        throw UserError(
            Diagnostic::fatal(
                "CONTACT_3",
                fmt::format("the slave surfaces of zones {} ('{}') and {} ('{}') share {} node(s): {}", k + 1,
                            def.zones[k].slaveGroup, slaves.size() + 1, zone.slaveGroup, common.size(),
                            nodeNames(mesh, common)),
                zone.location)
                .withNote("slave surfaces of distinct zones must be disjoint: merge the zones or exclude the "
                          "nodes with SANS_GROUP_NO"));
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
