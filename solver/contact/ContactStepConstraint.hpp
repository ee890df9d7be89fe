#pragma once
// The CONTACT keyword of STAT_NON_LINE turned into the StepConstraint the Newton driver solves
// with the mechanical equations (DEFI_CONTACT FORMULATION='DISCRETE': CONTRAINTE, GCP,
// PENALISATION, Coulomb friction, GLISSIERE, RESOLUTION='NON', the geometric loop).

#include "solver/contact/ContactDefinition.hpp"
#include "solver/functions/InstantList.hpp"
#include "solver/nonlinear/StepConstraint.hpp"

#include <memory>
#include <optional>

namespace stella {

class MechanicalSystem;

// STAT_NON_LINE's CONTACT keyword, as read by solver/inputs/ContactStepReader.
struct ContactStepInputs {
  std::shared_ptr<const contact::ContactDefinition> definition; // the concept CONTACT names
  SourceLocation at;                                            // the CONTACT keyword
  std::optional<FailurePolicy> interpenetration; // EVENEMENT='INTERPENETRATION' of INCREMENT's LIST_INST
};

// Throws UserError for a definition on another model or mesh and for what is not implemented yet
// (named). `threads` (P ncpus) pair the slave nodes in that many chunks at once.
std::unique_ptr<StepConstraint> makeContactConstraint(const ContactStepInputs& inputs,
                                                      MechanicalSystem& system, int threads = 1);

} // namespace stella
