#pragma once
// DEFI_LIST_INST (type list_inst): the instants of a nonlinear analysis and what to do when a
// step fails (ECHEC): stop, or cut the step (SUBD_PAS pieces, at most SUBD_NIVEAU levels, never
// below SUBD_PAS_MINI); and, for contact, adapt the penalty on excessive interpenetration.

#include "interpreter/Value.hpp"

#include <vector>

namespace stella {

struct FailurePolicy {
  enum class Event { Error, Interpenetration };
  enum class Action { Stop, Subdivide, AdaptPenalty };
  Event event = Event::Error;
  Action action = Action::Subdivide;
  int subdivisions = 4;           // SUBD_PAS
  int maxLevel = 3;               // SUBD_NIVEAU
  double minStep = 0.0;           // SUBD_PAS_MINI
  double maxPenetration = 0;      // PENE_MAXI
  double maxCoefficient = 1.0e12; // COEF_MAXI
};

class InstantList : public ConceptData {
public:
  std::vector<double> instants;
  std::vector<FailurePolicy> failures;

  // The policy for ordinary step failures (the default when ECHEC is absent: cut in 4, 3 levels).
  FailurePolicy onError() const;
};

} // namespace stella
