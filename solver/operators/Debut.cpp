// DEBUT and POURSUITE: open a session. Everything they configure in code_aster (memory, the
// database, error behaviour) has a fixed meaning in stella, so they only mark the start; the one
// setting a command file can observe, ERREUR_F='EXCEPTION' (errors of commands become exceptions
// a try/except catches), is not stella's behaviour and gets an alarm saying so.

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/session/OperatorRegistry.hpp"
#include "solver/session/Session.hpp"

namespace stella {

namespace {

void warnErrorsAreNotExceptions(OperatorCall& call) {
  for (const KeywordTree& occ : call.keywords.occurrences("ERREUR")) {
    if (occ.textOr("ERREUR_F", "ABORT") == "EXCEPTION") {
      call.session.report(msg::make("DEBUT_1", {}, occ.locationOf("ERREUR_F")));
    }
  }
}

Value runDebut(OperatorCall& call) {
  warnErrorsAreNotExceptions(call);
  call.session.message() << "  Session opened by " << call.command << "\n";
  return Value();
}

} // namespace

STELLA_OPERATOR("DEBUT", runDebut);
STELLA_OPERATOR("POURSUITE", runDebut);

} // namespace stella
