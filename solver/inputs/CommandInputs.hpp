#pragma once
// The inputs layer (issue 15) for the keywords MECA_STATIQUE and STAT_NON_LINE share: EXCIT (loads and
// FONC_MULT), MODELE and CHAM_MATER, SOLVEUR (the method named in the message file).

#include "catalog/KeywordTree.hpp"
#include "solver/linalg/LinearSolver.hpp"
#include "solver/model/MaterialField.hpp"
#include "solver/model/Model.hpp"
#include "solver/nonlinear/Excitation.hpp"

#include <memory>
#include <string>
#include <vector>

namespace stella {

std::vector<Excitation> readExcitations(const KeywordTree& keywords);

std::shared_ptr<const Model> readModel(const KeywordTree& keywords);

// CHAM_MATER, checked to be on the model's mesh (MATER_9 otherwise or when absent).
std::shared_ptr<const MaterialField> readMaterialField(const KeywordTree& keywords, const Model& model);

// The SOLVEUR options (METHODE, RENUM, NPREC, PCENT_PIVOT, STOP_SINGULIER); SOLVE_5 for PETSC.
linalg::SolverOptions readSolverOptions(const KeywordTree& keywords);

} // namespace stella
