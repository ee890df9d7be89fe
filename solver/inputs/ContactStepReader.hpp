#pragma once
// Reading the CONTACT keyword of STAT_NON_LINE (and the INTERPENETRATION event of its
// INCREMENT's LIST_INST) into the plain ContactStepInputs makeContactConstraint receives.

#include "solver/contact/ContactStepConstraint.hpp"

#include <optional>

namespace stella {

class KeywordTree;

// Nullopt when the command has no CONTACT keyword: nothing of contact is built.
std::optional<ContactStepInputs> readContactStepInputs(const KeywordTree& statNonLine);

} // namespace stella
