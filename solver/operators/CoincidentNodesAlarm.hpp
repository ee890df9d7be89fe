#pragma once
// MESHCHECK_1 (nodes at the same position), held until the end of the study: LIRE_MAILLAGE's
// VERI_MAIL finds the pairs, DEFI_CONTACT drops those its zones join (one node on a slave
// surface, the other on the master surface of the same zone: bodies meshed touching), and the
// pairs left are reported at FIN, located at LIRE_MAILLAGE. The alarm is deferred rather than
// filtered at LIRE_MAILLAGE because the contact zones are defined later in the file, on a model.
//
// Pairs are kept by node name, so that a mesh re-made by DEFI_GROUP(reuse=...) or MODI_MAILLAGE
// still matches them.

#include "solver/contact/ContactDefinition.hpp"
#include "solver/session/Session.hpp"

#include <string>
#include <utility>
#include <vector>

namespace stella {

class CoincidentNodesAlarm : public DeferredReport {
public:
  CoincidentNodesAlarm(const Mesh& mesh, const std::vector<std::pair<NodeId, NodeId>>& pairs,
                       SourceLocation at);
  // Drops the pairs that a zone of `def` joins; returns how many.
  std::size_t dropContactPairs(const contact::ContactDefinition& def);
  std::vector<Diagnostic> diagnostics() const override;

private:
  std::vector<std::pair<std::string, std::string>> pairs_;
  SourceLocation at_;
};

// Every CoincidentNodesAlarm the session holds drops the pairs `def` joins.
void dropPairsJoinedByContact(Session& session, const contact::ContactDefinition& def);

} // namespace stella
