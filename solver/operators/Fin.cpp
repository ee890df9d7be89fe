// FIN: reports the alarms held until the end of the study (Session::defer), then closes the
// session; the rest of the command file is ignored.

#include "solver/session/OperatorRegistry.hpp"
#include "solver/session/Session.hpp"

namespace stella {

namespace {
Value runFin(OperatorCall& call) {
  call.session.reportDeferred();
  call.session.markFinished();
  return Value();
}
} // namespace

STELLA_OPERATOR("FIN", runFin);

} // namespace stella
