#pragma once
// Nodal forces of a stress field: FORC_NODA = sum over the volume cells of B^T sigma at the
// Gauss points (physical DOF vector), the internal forces in equilibrium with the loads and the
// reactions; REAC_NODA = FORC_NODA - external forces.

#include "solver/assembly/DofMap.hpp"
#include "solver/database/Field.hpp"

#include <Eigen/Dense>

namespace stella {

Eigen::VectorXd forcesFromStress(const Model& model, const DofMap& dofs, const Field& stress);

} // namespace stella
