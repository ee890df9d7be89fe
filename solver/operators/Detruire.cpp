// DETRUIRE: destroys concepts (CONCEPT=_F(NOM=(...)), or NOM=(...) directly). Using a destroyed
// concept afterwards is an error that names it.

#include "solver/session/OperatorRegistry.hpp"
#include "solver/session/Session.hpp"

namespace stella {

namespace {

void destroy(OperatorCall& call, const KeywordTree& names) {
  for (const auto& concept_ : names.conceptValues("NOM")) {
    concept_->destroyed = true;
    concept_->data.reset();
    call.session.message() << "  Concept " << concept_->name << " destroyed\n";
  }
}

Value runDetruire(OperatorCall& call) {
  destroy(call, call.keywords);
  for (const KeywordTree& occurrence : call.keywords.occurrences("CONCEPT")) {
    destroy(call, occurrence);
  }
  return Value();
}

} // namespace

STELLA_OPERATOR("DETRUIRE", runDetruire);

} // namespace stella
