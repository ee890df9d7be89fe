#pragma once
// The CONTACT keyword of STAT_NON_LINE turned into the StepConstraint the Newton driver solves
// with the mechanical equations (DEFI_CONTACT FORMULATION='DISCRETE': CONTRAINTE, GCP,
// PENALISATION, Coulomb friction, GLISSIERE, RESOLUTION='NON', the geometric loop).

#include "solver/nonlinear/StepConstraint.hpp"

#include <memory>

namespace stella {

class KeywordTree;
class MechanicalSystem;
struct SourceLocation;

// Null when the command has no CONTACT keyword: nothing of contact is built. Throws UserError for
// a definition on another model or mesh and for what is not implemented yet (named). `threads`
// (P ncpus) pair the slave nodes in that many chunks at once.
std::unique_ptr<StepConstraint> makeContactConstraint(const KeywordTree& statNonLine,
                                                      MechanicalSystem& system, int threads = 1);

} // namespace stella
