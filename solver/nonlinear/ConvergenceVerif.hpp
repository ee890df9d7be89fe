#pragma once
// CONVERGENCE/VERIF: how the global residual criteria the user gave combine. 'TOUT' (the
// default): every criterion given must hold; 'AU_MOINS_UN': one of them is enough. A criterion
// not given (RESI_GLOB_MAXI absent) takes no part.

#include <initializer_list>

namespace stella {

enum class CriteriaCombination { All, AtLeastOne };

struct CriterionCheck {
  bool given = false;
  bool holds = false;
};

// Whether the criteria converge; false when none is given.
inline bool criteriaHold(std::initializer_list<CriterionCheck> criteria, CriteriaCombination combination) {
  bool anyGiven = false;
  bool anyHolds = false;
  bool allHold = true;
  for (const CriterionCheck& c : criteria) {
    if (!c.given) {
      continue;
    }
    anyGiven = true;
    anyHolds = anyHolds || c.holds;
    allHold = allHold && c.holds;
  }
  if (!anyGiven) {
    return false;
  }
  return combination == CriteriaCombination::All ? allHold : anyHolds;
}

} // namespace stella
