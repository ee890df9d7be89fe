// MESHCHECK_1 held until the end of the study (see CoincidentNodesAlarm.hpp).

#include "solver/operators/CoincidentNodesAlarm.hpp"

#include "messages/Messages.hpp"
#include "solver/mesh/MeshCheck.hpp"

#include <algorithm>
#include <set>

namespace stella {

CoincidentNodesAlarm::CoincidentNodesAlarm(const Mesh& mesh,
                                           const std::vector<std::pair<NodeId, NodeId>>& pairs,
                                           SourceLocation at)
    : at_(std::move(at)) {
  for (const auto& [a, b] : pairs) {
    pairs_.emplace_back(mesh.nodeName(a), mesh.nodeName(b));
  }
}

std::size_t CoincidentNodesAlarm::dropContactPairs(const contact::ContactDefinition& def) {
  const Mesh& mesh = *def.mesh;
  std::vector<std::pair<std::set<NodeId>, std::set<NodeId>>> zones; // slave, master nodes
  for (const auto& zone : def.zones) {
    // The whole surfaces: nodes that SANS_GROUP_NO keeps out of the contact still touch by design.
    const auto* slaveCells = mesh.cellGroup(zone.slaveGroup);
    const auto slave = slaveCells != nullptr ? mesh.nodesOfCells(*slaveCells) : std::vector<NodeId>{};
    const auto master = mesh.nodesOfCells(contact::zoneMasterCells(mesh, zone));
    zones.emplace_back(std::set<NodeId>(slave.begin(), slave.end()),
                       std::set<NodeId>(master.begin(), master.end()));
  }
  const auto joined = [&](const std::pair<std::string, std::string>& p) {
    const auto a = mesh.findNode(p.first);
    const auto b = mesh.findNode(p.second);
    if (!a || !b) {
      return false;
    }
    return std::any_of(zones.begin(), zones.end(), [&](const auto& z) {
      return (z.first.count(*a) && z.second.count(*b)) || (z.first.count(*b) && z.second.count(*a));
    });
  };
  const auto before = pairs_.size();
  pairs_.erase(std::remove_if(pairs_.begin(), pairs_.end(), joined), pairs_.end());
  return before - pairs_.size();
}

std::vector<Diagnostic> CoincidentNodesAlarm::diagnostics() const {
  if (pairs_.empty()) {
    return {};
  }
  // The message of VERI_MAIL, on a mesh holding only the names of the nodes left.
  Mesh names;
  MeshCheckReport report;
  for (const auto& [a, b] : pairs_) {
    const NodeId na = names.addNode({0, 0, 0}, a);
    const NodeId nb = names.addNode({0, 0, 0}, b);
    report.duplicateNodes.emplace_back(na, nb);
  }
  auto ds = meshCheckDiagnostics(names, report);
  for (auto& d : ds) {
    d.location = at_;
    d.notes.push_back(msg::text("MESHCHECK_1.n_contact"));
  }
  return ds;
}

void dropPairsJoinedByContact(Session& session, const contact::ContactDefinition& def) {
  for (const auto& r : session.deferred()) {
    if (auto* alarm = dynamic_cast<CoincidentNodesAlarm*>(r.get())) {
      alarm->dropContactPairs(def);
    }
  }
}

} // namespace stella
