#pragma once
// The material state at the Gauss points of the model's volume cells: strains (engineering
// shears, the modelling's layout), stresses (SIEF_ELGA: SIXX, SIYY, SIZZ, SIXY[, SIXZ, SIYZ])
// and internal variables (VARI_ELGA: V1...).

#include "solver/database/Field.hpp"
#include "solver/model/Model.hpp"

namespace stella {

struct PointState {
  Field strain;
  Field stress;
  Field internal;
};

// Gauss points per cell of the model (0 outside volume cells).
std::vector<int> gaussPointsPerCell(const Model& model);

// A zero state with `internalVariables` components in VARI_ELGA.
PointState zeroPointState(const Model& model, int internalVariables);

// Stress component names of a model: SIXX SIYY SIZZ SIXY (2D) or + SIXZ SIYZ (3D).
std::vector<std::string> stressComponents(const Model& model);

} // namespace stella
