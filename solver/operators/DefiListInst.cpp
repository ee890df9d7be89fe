// DEFI_LIST_INST: the instants of a nonlinear analysis (METHODE='MANUEL') and the ECHEC
// actions: ERREUR with DECOUPE (SUBD_PAS, SUBD_NIVEAU, SUBD_PAS_MINI) or ARRET, and
// INTERPENETRATION with ADAPT_COEF_PENA (PENE_MAXI, COEF_MAXI) or ARRET.

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/functions/InstantList.hpp"
#include "solver/functions/RealFunction.hpp"
#include "solver/session/OperatorRegistry.hpp"

#include <cstdlib>
#include <fmt/format.h>

namespace stella {

namespace {

// What the catalogue refuses (implemente=, non_implemente=: METHODE='AUTO', SUBD_METHODE='AUTO',
// ACTION='ITER_SUPPL', the other EVENEMENT, DEFI_LIST/RESULTAT) never reaches the operator.
[[noreturn]] void notImplemented(const std::string& what) {
  STELLA_ASSERT(false, "DEFI_LIST_INST: " + what + " passed the catalogue but is not implemented");
  std::abort();
}

// Every keyword read here has a catalogue default in the branch that reads it: the validated tree
// holds it, so no fallback repeats it (tools/lint/or-fallbacks.py).
FailurePolicy readFailure(const KeywordTree& e) {
  FailurePolicy p;
  const std::string event = e.text("EVENEMENT");
  const std::string action = e.text("ACTION");
  if (event == "ERREUR") {
    p.event = FailurePolicy::Event::Error;
    if (action == "ARRET") {
      p.action = FailurePolicy::Action::Stop;
    } else if (action == "DECOUPE") {
      p.action = FailurePolicy::Action::Subdivide;
      if (e.text("SUBD_METHODE") != "MANUEL") {
        notImplemented("SUBD_METHODE='AUTO'");
      }
      p.subdivisions = static_cast<int>(e.integer("SUBD_PAS"));
      p.maxLevel = static_cast<int>(e.integer("SUBD_NIVEAU"));
      p.minStep = e.real("SUBD_PAS_MINI");
    } else {
      notImplemented("ACTION='" + action + "'");
    }
  } else if (event == "INTERPENETRATION") {
    p.event = FailurePolicy::Event::Interpenetration;
    p.maxPenetration = e.real("PENE_MAXI");
    p.action = action == "ARRET" ? FailurePolicy::Action::Stop : FailurePolicy::Action::AdaptPenalty;
    if (p.action == FailurePolicy::Action::AdaptPenalty) {
      p.maxCoefficient = e.real("COEF_MAXI"); // defined (with its default) for ADAPT_COEF_PENA only
    }
  } else {
    notImplemented("EVENEMENT='" + event + "'");
  }
  return p;
}

Value runDefiListInst(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  if (kw.text("METHODE") != "MANUEL") {
    notImplemented("METHODE='AUTO'");
  }
  auto list = std::make_shared<InstantList>();
  const KeywordTree& def = kw.occurrences("DEFI_LIST").front();
  if (def.has("VALE")) {
    list->instants = def.reals("VALE");
  } else if (def.has("LIST_INST")) {
    auto reals = conceptData<RealList>(def.conceptValue("LIST_INST"));
    STELLA_ASSERT(reals != nullptr, "LIST_INST holds no list of reals");
    list->instants = reals->values;
  } else {
    notImplemented("DEFI_LIST/RESULTAT");
  }
  for (std::size_t i = 1; i < list->instants.size(); ++i) {
    if (!(list->instants[i] > list->instants[i - 1])) {
      throw UserError(msg::make("LIST_INST_2",
                                {{"instants", list->instants[i]}, {"instants_2", list->instants[i - 1]}},
                                def.locationOf(def.has("VALE") ? "VALE" : "LIST_INST")));
    }
  }
  for (const KeywordTree& e : kw.occurrences("ECHEC")) {
    list->failures.push_back(readFailure(e));
  }
  return call.makeConcept(list);
}

} // namespace

STELLA_OPERATOR("DEFI_LIST_INST", runDefiListInst);

} // namespace stella
