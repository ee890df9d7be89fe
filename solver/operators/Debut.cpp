// DEBUT and POURSUITE: open a session. Everything they configure in code_aster (memory, the
// database, error behaviour) has a fixed meaning in stella, so they only mark the start.

#include "solver/session/OperatorRegistry.hpp"
#include "solver/session/Session.hpp"

namespace stella {

namespace {
Value runDebut(OperatorCall& call) {
  call.session.message() << "  Session opened by " << call.command << "\n";
  return Value();
}
} // namespace

STELLA_OPERATOR("DEBUT", runDebut);
STELLA_OPERATOR("POURSUITE", runDebut);

} // namespace stella
