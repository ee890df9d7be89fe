#pragma once
// STAT_NON_LINE's keywords read into the driver's settings: NEWTON, CONVERGENCE, RECH_LINEAIRE
// (NewtonSettings), INCREMENT (the instants), the ECHEC policy of a DEFI_LIST_INST (CutPolicy),
// ETAT_INIT / reuse= (the state to start from), and the keywords refused as not implemented yet
// (see StatNonLineKeywords.hpp).

#include "catalog/KeywordTree.hpp"
#include "solver/assembly/MechanicalSystem.hpp"
#include "solver/database/Result.hpp"
#include "solver/functions/InstantList.hpp"
#include "solver/nonlinear/NewtonDriver.hpp"
#include "solver/nonlinear/TimeStepper.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace stella {

// NEWTON, CONVERGENCE and RECH_LINEAIRE. PREDICTION='DEPL_CALCULE' reads NEWTON/EVOL_NOLI
// (SNL_7 when absent, or on another mesh); refusals SNL_1 name what is not implemented yet.
NewtonSettings readNewtonSettings(const KeywordTree& statNonLine, const MechanicalSystem& system);

// The instants of INCREMENT from `initialTime` (INST_INIT, NUME_INST_INIT, or by default the
// time of the initial state when one is given, else the first of the list) to INST_FIN /
// NUME_INST_FIN; `list` receives the DEFI_LIST_INST when LIST_INST is one. SNL_2 when fewer
// than two instants remain, SNL_8 for a NUME_INST_* outside the list.
std::vector<double> readInstants(const KeywordTree& increment, std::optional<double> initialTime,
                                 std::shared_ptr<const InstantList>& list);

// What to do when a step fails: the ECHEC/ERREUR occurrence of the DEFI_LIST_INST, or
// code_aster's default (cut in 4, 3 levels) for a DEFI_LIST_REEL.
CutPolicy readCutPolicy(const InstantList* list);

// The state to start from: ETAT_INIT=_F(EVOL_NOLI=..., INST= | NUME_ORDRE=) (the last stored step
// by default), else the last stored step of the reused result, else none.
struct InitialResultStep {
  std::shared_ptr<const Result> result;
  const ResultStep* step = nullptr;
};
std::optional<InitialResultStep> readInitialStep(const KeywordTree& statNonLine,
                                                 const std::shared_ptr<Result>& reused);

// The mechanical state of a stored step: DEPL, SIEF_ELGA, VARI_ELGA (zero when absent) and the
// strains of the displacement. SNL_9 when the step is on another mesh or its fields do not fit
// the model.
MechanicalState stateFromResultStep(const InitialResultStep& initial, const MechanicalSystem& system,
                                    const MechanicalState& zero, const SourceLocation& at);

} // namespace stella
