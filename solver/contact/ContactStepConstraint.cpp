// Building the contact constraint of STAT_NON_LINE from its CONTACT keyword.

#include "solver/contact/ContactStepConstraint.hpp"

#include "catalog/KeywordTree.hpp"
#include "interpreter/Diagnostics.hpp"

namespace stella {

std::unique_ptr<StepConstraint> makeContactConstraint(const KeywordTree& statNonLine,
                                                      MechanicalSystem& system) {
  (void)system;
  if (!statNonLine.has("CONTACT")) {
    return nullptr;
  }
  throw UserError(Diagnostic::fatal("SNL_1", "STAT_NON_LINE CONTACT is not implemented yet",
                                    statNonLine.locationOf("CONTACT")));
}

} // namespace stella
