#pragma once
// One EXCIT occurrence: a mechanical load (dualised) or a kinematic load (eliminated), scaled by
// FONC_MULT(INST) when given (TYPE_CHARGE='FIXE_CSTE').

#include "solver/functions/RealFunction.hpp"
#include "solver/model/KinematicLoad.hpp"
#include "solver/model/MechanicalLoad.hpp"

#include <memory>

namespace stella {

struct Excitation {
  std::shared_ptr<const MechanicalLoad> load;     // or null
  std::shared_ptr<const KinematicLoad> kinematic; // or null
  std::shared_ptr<const RealFunction> multiplier; // FONC_MULT, or null for 1
  double factor(double time) const { return multiplier ? (*multiplier)(time) : 1.0; }
};

} // namespace stella
