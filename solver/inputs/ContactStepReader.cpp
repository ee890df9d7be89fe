// Reading STAT_NON_LINE's CONTACT keyword: the contact definition it names, where it is, and the
// INTERPENETRATION event of the LIST_INST of INCREMENT.

#include "solver/inputs/ContactStepReader.hpp"

#include "catalog/KeywordTree.hpp"
#include "interpreter/Diagnostics.hpp"
#include "solver/database/ConceptStore.hpp"

namespace stella {

namespace {

std::optional<FailurePolicy> interpenetrationPolicy(const KeywordTree& kw) {
  if (!kw.has("INCREMENT")) {
    return std::nullopt;
  }
  auto list = conceptData<InstantList>(kw.occurrences("INCREMENT").front().conceptValue("LIST_INST"));
  if (list == nullptr) {
    return std::nullopt;
  }
  for (const FailurePolicy& p : list->failures) {
    if (p.event == FailurePolicy::Event::Interpenetration) {
      return p;
    }
  }
  return std::nullopt;
}

} // namespace

std::optional<ContactStepInputs> readContactStepInputs(const KeywordTree& statNonLine) {
  if (!statNonLine.has("CONTACT")) {
    return std::nullopt;
  }
  ContactStepInputs in;
  in.at = statNonLine.locationOf("CONTACT");
  in.definition = conceptData<contact::ContactDefinition>(statNonLine.conceptValue("CONTACT"));
  STELLA_ASSERT(in.definition != nullptr, "CONTACT holds no contact definition");
  in.interpenetration = interpenetrationPolicy(statNonLine);
  return in;
}

} // namespace stella
