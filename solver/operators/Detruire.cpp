// DETRUIRE: destroys concepts (CONCEPT=_F(NOM=(...))). Using a destroyed concept afterwards is
// an error that names it.

#include "solver/session/OperatorRegistry.hpp"
#include "solver/session/Session.hpp"

namespace stella {

namespace {

Value runDetruire(OperatorCall& call) {
  for (const KeywordTree& occurrence : call.keywords.occurrences("CONCEPT")) {
    for (const auto& concept_ : occurrence.conceptValues("NOM")) {
      concept_->destroyed = true;
      concept_->data.reset();
      call.session.message() << "  Concept " << concept_->name << " destroyed\n";
    }
  }
  return Value();
}

} // namespace

STELLA_OPERATOR("DETRUIRE", runDetruire);

} // namespace stella
