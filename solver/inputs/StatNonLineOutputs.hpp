#pragma once
// The inputs half of the outputs of STAT_NON_LINE during the run: OBSERVATION (the result's
// 'OBSERVATION' table), SUIVI_DDL (columns of the convergence table), MESURE (the 'STAT' table of
// time measures) and AFFICHAGE (where the convergence tables go). The numerics in
// solver/nonlinear/ receive the plain structs built here.

#include "solver/nonlinear/ConvergenceTableOutput.hpp"
#include "solver/nonlinear/DofMonitor.hpp"
#include "solver/nonlinear/FieldExtraction.hpp"
#include "solver/nonlinear/Observation.hpp"
#include "solver/nonlinear/StepMeasures.hpp"

#include <memory>
#include <string>

namespace stella {

class KeywordTree;

// One OBSERVATION or SUIVI_DDL occurrence (`keyword` names it in the messages).
FieldExtraction readFieldExtraction(const KeywordTree& occurrence, const Mesh& mesh,
                                    const std::string& keyword);

// The occurrences of OBSERVATION (none: empty()); SNL_21 at PAS_OBSE below 1.
Observations readObservations(const KeywordTree& statNonLine, const Mesh& mesh);

// The occurrences of SUIVI_DDL; null without any.
std::unique_ptr<DofMonitor> readDofMonitor(const KeywordTree& statNonLine, const MechanicalSystem& system);

// MESURE (absent: nothing wanted).
StepMeasures readStepMeasures(const KeywordTree& statNonLine);

// AFFICHAGE (absent: every step, the message file only).
ConvergenceDisplay readConvergenceDisplay(const KeywordTree& statNonLine);

} // namespace stella
