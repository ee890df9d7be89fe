// DEBUT and POURSUITE: open a session. Everything they configure in code_aster (memory, the
// database, error behaviour) has a fixed meaning in stella, so they only mark the start; the one
// setting a command file can observe, ERREUR_F='EXCEPTION' (errors of commands become exceptions
// a try/except catches), is not stella's behaviour and gets an alarm saying so.

#include "interpreter/Diagnostics.hpp"
#include "solver/session/OperatorRegistry.hpp"
#include "solver/session/Session.hpp"

namespace stella {

namespace {

void warnErrorsAreNotExceptions(OperatorCall& call) {
  for (const KeywordTree& occ : call.keywords.occurrences("ERREUR")) {
    if (occ.textOr("ERREUR_F", "ABORT") == "EXCEPTION") {
      call.session.report(
          Diagnostic::alarm("DEBUT_1",
                            "ERREUR_F='EXCEPTION' is not implemented yet: an error of a command stops the "
                            "study, an 'except' does not catch it",
                            occ.locationOf("ERREUR_F"))
              .withNote("errors of the command language (KeyError, ZeroDivisionError...) are caught as in "
                        "Python; see doc/language.md, \"Errors and try/except\""));
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
