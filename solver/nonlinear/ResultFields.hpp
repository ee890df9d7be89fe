#pragma once
// Turning solution vectors and Gauss-point states into result fields: DEPL (DX, DY[, DZ] on the
// nodes of the model; nodes outside it carry no value), SIEF_ELGA, VARI_ELGA, and the nodal
// force fields REAC_NODA / FORC_NODA from a physical-size vector.

#include "solver/assembly/DofMap.hpp"
#include "solver/database/Result.hpp"
#include "solver/nonlinear/PointState.hpp"

#include <Eigen/Dense>
#include <memory>

namespace stella {

// A nodal field of `quantity` with the model's components from a physical-size vector.
std::shared_ptr<Field> nodalField(const Model& model, const DofMap& dofs, const Eigen::VectorXd& v,
                                  const std::string& quantity);

// Stores DEPL, SIEF_ELGA and VARI_ELGA (when `withVariables`) in a step.
void storeMechanicalFields(ResultStep& step, const Model& model, const DofMap& dofs, const Eigen::VectorXd& u,
                           const PointState& state, bool withStress, bool withVariables);

// The displacement of a stored step back as a physical-size vector (for ETAT_INIT, CALC_CHAMP).
Eigen::VectorXd displacementVector(const Field& depl, const DofMap& dofs);

} // namespace stella
