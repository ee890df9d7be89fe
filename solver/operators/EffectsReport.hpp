#pragma once
// The effects report of STAT_NON_LINE (issue 19): before the first step, every effect the
// command activates and the keyword that asked for it (behaviours per group with their
// integration, contact per zone, friction, geometric loop and pairing, strains, factorisation,
// fields stored); after the last step, the time each of them cost. Nothing is listed that the
// command does not compute: without CONTACT there is no contact line but "no contact".

#include "catalog/KeywordTree.hpp"
#include "solver/assembly/MechanicalSystem.hpp"
#include "solver/nonlinear/NewtonDriver.hpp"
#include "solver/nonlinear/PhaseTimes.hpp"
#include "solver/nonlinear/StepConstraint.hpp"
#include "solver/nonlinear/TimeStepper.hpp"

#include <string>

namespace stella {

// "   effects activated (why):" and one indented line per effect.
std::string effectsReport(const KeywordTree& kw, const MechanicalSystem& system,
                          const NewtonSettings& settings, const StepConstraint* constraint,
                          const CutPolicy& cuts, bool observed);

// "   time per effect (s): ..." from the phases of the command and the driver's counts.
std::string effectCosts(const PhaseTimes& phases, const MechanicalSystem& system, const NewtonDriver& driver,
                        const StepConstraint* constraint);

} // namespace stella
