#pragma once
// Dualised conditions that impose the same DOF more than once: a node in two groups that both
// get DX = 0, a DDL_IMPO repeated by a FACE_IMPO, or two loads of EXCIT blocking the same face.
// code_aster accepts such studies; with one Lagrange multiplier per condition the saddle system
// would be singular. Single-DOF relations (c u = v) that repeat an earlier one on the same node
// and component are dropped when they impose the same value at every instant (both 0, or the
// same value in the same load or under the same FONC_MULT); two conditions that impose
// different values are refused (LOAD_11) naming the node, the component and both conditions.
// A DOF eliminated by AFFE_CHAR_CINE (MECA_IMPO) wins over a dualised condition on it, under the
// same rule. Relations over several DOFs (LIAISON_DDL with several terms, LIAISON_UNIF, LIAISON_SOLIDE) are
// kept as they are.

#include "interpreter/SourceFile.hpp"
#include "solver/model/KinematicLoad.hpp"
#include "solver/model/MechanicalLoad.hpp"

#include <memory>
#include <string>
#include <vector>

namespace stella {

// One load of EXCIT, in the order of EXCIT.
struct ExcitedLoad {
  std::shared_ptr<const MechanicalLoad> load;     // or null
  std::shared_ptr<const KinematicLoad> kinematic; // or null
  const void* multiplier = nullptr;               // identity of FONC_MULT (null: constant 1)
  std::string name;                               // the load concept's name, for messages
  SourceLocation location;                        // of CHARGE= in EXCIT
};

// The loads to use, one per entry: the entry's own load when none of its relations repeats an
// earlier one, else a copy without the repeated single-DOF relations. `dropped` (if given)
// receives the number of relations dropped. Throws UserError LOAD_11 on a conflict.
std::vector<std::shared_ptr<const MechanicalLoad>>
mergeRepeatedConditions(const std::vector<ExcitedLoad>& loads, int* dropped = nullptr);

} // namespace stella
